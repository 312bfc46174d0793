// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_solver.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/gross_sliding.hpp"
#include "roughroll/problems/zone_family.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {
constexpr int newton_iterations = 40;
// Below this 1 - |Q|/f the search starts from the operator's model zone near gross sliding (7(e), 7(g)).
constexpr double near_sliding = 1e-4;
}  // namespace

zone_solver::zone_solver(stick_zone_operator op) : op_(std::move(op)) {}

double zone_solver::entry_coefficient(const tangential_solution& s) {
    return s.psi_b.empty() ? 0.0 : u_series(s.psi_b, -1.0);  // psi(-1) = sum_j b_j U_j(-1)
}

tangential_solution zone_solver::gross_sliding() {
    // w = G: xi = -f min G (docs/formulation.md 7(d)).
    return roughroll::gross_sliding(op_.f, op_.f, op_.G_sampled, op_.G);
}

zone_newton_from zone_solver::newton(double magnitude) {
    // Newton on F = (log(-rho int q / (f - |Q|)), E) in the zone's midpoint m and u = log rho
    // (docs/formulation.md 7(e), 7(g); zone_ends_newton): the load's component is relative, so it
    // keeps its digits as the zone collapses at gross sliding (rho -> 0, f - |Q| -> 0), and close to
    // linear in u (rho int q ~ -kappa rho^k), so Newton converges from a zone far off in size. Empty
    // when it does not converge: the caller falls back to Brent.
    return [this, magnitude](double start, double end) {
        return zone_ends_newton(op_.solve, op_.newton_entry, op_.f - magnitude, start, end, newton_iterations,
                                op_.method.newton_tolerance);
    };
}

tangential_solution zone_solver::general(double magnitude, std::optional<zone_guess> guess,
                                         std::optional<double> single_end) {
    const double f = op_.f;
    // Q(start, c0) falls from f (no stick zone, c0 = start) as the zone grows (7(c)), in the gap form
    // rho int q + (f - |Q|): Q - |Q| without the O(f) sum that cancels (7(d)): f - |Q| is exact
    // (Sterbenz, |Q| >= f/2 where it matters) and rho int q keeps its relative digits, where
    // f + rho int q rounds to ulp(f) (at |Q|/f = 1 - 1e-15 six ulps: the ends found from Q itself
    // were noise, 7(e)).
    std::optional<double> last_end = single_end;
    const zone_family zones{[&](double start) {
                                const auto c = stick_zone_end(
                                    [&](double c0) {
                                        if (c0 <= start) return f - magnitude;
                                        return op_.load_integral(op_.solve(start, c0)) + (f - magnitude);
                                    },
                                    start, op_.method.chained_ends ? last_end : std::nullopt);
                                if (c) last_end = c;
                                return c;
                            },
                            op_.solve, op_.entry};
    // The paper's zone first: if E <= 0 at start = -1 it is the answer (7(b), 7(g)).
    std::optional<double> edge_end = single_end;
    if (!edge_end && op_.method.edge_zone_required) {
        edge_end = zones.end(-1.0);
        if (!edge_end) {
            std::ostringstream msg;
            msg.precision(17);
            msg << op_.method.name << ": no stick zone from the leading edge carries |Q|/f = " << magnitude / f;
            throw numerical_error(msg.str());
        }
    }
    double at_edge_entry = std::numeric_limits<double>::quiet_NaN();  // unknown: the scan decides
    if (edge_end) {
        tangential_solution at_edge = op_.solve(-1.0, *edge_end);
        at_edge_entry = op_.entry(at_edge);
        if (at_edge_entry <= 0.0) return at_edge;
    }
    // r*, where G is least: the stick zone straddles it and collapses onto it at gross sliding (7(d)).
    std::optional<double> point;
    const auto least_point = [&] {
        if (!point) point = gross_sliding().c0();
        return *point;
    };
    // Near gross sliding: from the operator's model zone at r*, before the coarse level's guess,
    // which rounding makes no better.
    if (f - magnitude <= near_sliding * f)
        if (auto s = op_.near_sliding(magnitude, least_point(), newton(magnitude))) return *s;
    // Newton from the coarse level's zone when extrapolating.
    if (guess && guess->start > -1.0)
        if (auto s = newton(magnitude)(guess->start, guess->c0)) return *s;
    // Else bracket the entry condition along the family of zones [s, c(s)] that carry |Q|
    // (7(e), zone_family.hpp): the starts towards the trailing edge (or r*) until E changes sign.
    const double top = op_.method.scan_to_least_point ? least_point() : 1.0;
    std::vector<double> starts;
    for (int k = 1; k <= op_.method.scan; ++k)
        if (const double start = -1.0 + (top + 1.0) * k / op_.method.scan; start < 1.0) starts.push_back(start);
    return first_bracket_zone(zones, scan_starts(zones, {{-1.0, edge_end.value_or(-1.0), at_edge_entry}}, starts, true),
                              newton(magnitude), op_.method.refusal);
}

tangential_solution zone_solver::solve(double Q, bool force_general, std::optional<zone_guess> guess) {
    const double magnitude = load_magnitude(Q, op_.f);
    const std::optional<tangential_solution> single = op_.paper_zone(Q, force_general && magnitude != 0.0);
    if (single && (magnitude == 0.0 || (!force_general && single->checks.hold()))) return *single;
    const std::optional<double> single_end = single ? std::optional<double>(single->c0()) : std::nullopt;
    check_load_resolvable(magnitude, op_.f);
    const auto search = [&](std::optional<zone_guess> g) {
        return searched_point(magnitude == op_.f ? gross_sliding() : general(magnitude, g, single_end), Q, op_.method.name,
                              op_.check);
    };
    tangential_solution s = search(guess);
    // Newton from a guess may find another zone that solves both conditions but not the
    // inequalities (seen near s = 0.97 while it wandered): then search without the guess.
    if (guess && !s.checks.hold()) s = search(std::nullopt);
    return s;
}

}  // namespace roughroll
