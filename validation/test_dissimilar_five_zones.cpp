// Five zones of dissimilar rollers (docs/formulation.md 8(g), 8(j)): slip-, stick, slip+, stick,
// slip- (beta_D > 0), by the product's two-zone collocation and Newton in the four ends, against
// the independent grid route (no structure assumed), free rolling and Bentall and Johnson's
// driven case Q/f = +0.75 at f = 0.05, aluminium on steel.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "test_zones_low_order.hpp"

using namespace roughroll;

namespace {
// Dundurs' beta_D of aluminium (roller 1) on steel, 8(a).
const double beta_al_st = [] {
    const double C = 0.69 / 23.0 + 0.72 / 82.0;
    return (0.38 / 23.0 - 0.44 / 82.0) / (2.0 * C);
}();

// The ends of the two stick zones of a grid solution with five runs (slip-, stick, slip+, stick, slip-).
std::vector<double> grid_ends(const validation::grid_solution& g) {
    const auto runs = g.runs();
    if (runs.size() != 5) return {};
    return {runs[1].from, runs[1].to, runs[3].from, runs[3].to};
}
}  // namespace

TEST(DissimilarFiveZones, Explore) {
    const double f = 0.05;
    for (double Q_over_f : {0.0, 0.25, 0.5, 0.75}) {
        const normal_solution hertz = hertz_solution(32, method::product);
        tangential_solver t(hertz, kernel{}, kernel{}, f, false);
        dissimilar_zones d(t, kernel{}, beta_al_st);
        const auto g = validation::solve_on_grid(hertz, kernel{}, f, Q_over_f * f, 200, 0, beta_al_st);
        std::vector<double> ends = grid_ends(g);
        std::printf("Q/f %.2f grid xi %.8f runs %zu\n", Q_over_f, g.xi, g.runs().size());
        for (const auto& r : g.runs()) std::printf("   [%.3f, %.3f] %d\n", r.from, r.to, r.state);
        if (ends.empty()) {
            const auto runs = g.runs();
            ends = {runs[1].from, runs[1].to, 0.99, 0.995};
        }
        const auto s = d.five_zones(Q_over_f * f, ends);
        if (!s) {
            std::printf("  no convergence\n");
            continue;
        }
        std::printf("  product: [%.9f, %.9f] [%.9f, %.9f] xi %.10f Q %.3e it %d sweeps %d stick %.3e slip %.3e\n", s->s1,
                    s->c1, s->s2, s->c2, s->xi, s->Q - Q_over_f * f, s->iterations, s->sweeps, s->checks.stick_margin,
                    s->checks.slip_margin);
    }
}
