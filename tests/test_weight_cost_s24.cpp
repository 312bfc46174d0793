// SPDX-License-Identifier: GPL-3.0-or-later
// What session 24 keeps between the blends of one wired pressure (docs/formulation.md 8(z), "Wired"; pressure_kinks'
// piece tables, its rules, the second table built at need and the memo of p) gives the values made afresh, bit for bit:
// 1. W (kinks_blend) of a blend made after others, whose pieces between the kinks' ends come from the kept tables, against
//    the same blend of a fresh copy of the pressure that made no blend before, at points across [s, 1]: in the pieces,
//    next to the cuts (near_part) and within a thousandth of a node's weight of a node of the first table (the second
//    table, built at its first such point);
// 2. the zone load of a blend whose stick zone is the kinks' own (its piece [s, c] kept by an earlier blend) against
//    QAGS of p Theta, an independent route (as tests/test_exact_weight_s23.cpp's 4, there on pieces not kept).
// Can fail (mutations of pressure_kinks.cpp, session 24): with the kept pieces' blend factor left out (tabulate's H),
// 2 fails (zone load +1.3e-2 off QAGS); with the kept tables keyed without their table (0: M points, 1: M + 1), the
// second table's points in 1 fail against QUADPACK.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

#include "hilbert_on_pieces.hpp"

using namespace roughroll;

namespace {
const double beta_d = 0.1438337435056057;  // aluminium on steel (the JSON's beta_d)
// Free rolling's zone ends at f = 0.05 (the default point's, session 23; tests/test_exact_weight_s23.cpp).
const std::array<double, 4> ends{-0.6847168688940107, 0.4863688037786901, 0.8347229913922383, 0.9192781716024576};
constexpr double f = 0.05;

std::shared_ptr<pressure_kinks> wired(int n) {
    auto p = std::make_shared<pressure_kinks>();
    p->set_weight(-beta_d * f);
    p->set_variable(n, beta_d, 1.0, f, ends,
                    {[](double t) { return 0.03 * (0.4 + 0.3 * t + 0.1 * std::cos(2.0 * t)); },
                     [](double t) { return 0.02 * (0.2 - 0.5 * t + 0.1 * std::exp(t)); }});
    p->solve_variable();
    return p;
}

// Points of [s, 1) for W: every piece's inside, next to each cut (within 1e-6 and 1e-9: near_part), and the two points
// of the M-point rule's nodes nearest the middle of each piece moved by 1e-7 of their weight (the second table).
std::vector<double> points(double s, double c) {
    std::vector<double> r;
    std::vector<double> cuts{s, c, 1.0};
    for (const double e : ends)
        if (e > s) cuts.push_back(e);
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = cuts[i], e = cuts[i + 1];
        for (const double u : {0.1, 0.37, 0.5, 0.81}) r.push_back(a + u * (e - a));
        for (const double d : {1e-6, 1e-9}) {
            r.push_back(a + d * (e - a));
            r.push_back(e - d * (e - a));
        }
    }
    r.erase(std::remove_if(r.begin(), r.end(), [](double x) { return !(x < 1.0 - 1e-8); }), r.end());
    return r;
}

// The M-point rule's node j on [a, e] in the cos map (pressure_kinks.cpp's cos_map_node) and its weight.
std::array<double, 2> node(const gauss_legendre& rule, std::size_t j, double a, double e) {
    const double half = 0.5 * (e - a);
    const double u = M_PI_2 * (rule.nodes[j] + 1.0), sh = std::sin(0.5 * u), ch = std::cos(0.5 * u);
    return {u < M_PI_2 ? a + 2.0 * half * sh * sh : e - 2.0 * half * ch * ch,
            rule.weights[j] * M_PI_2 * half * std::sin(u)};
}

double blend_of(double eta, double s, double c) {
    if (eta <= s) return 0.0;
    if (eta >= c) return 1.0;
    const double t = std::clamp((eta - s) / (0.5 * (c - s)) - 1.0, -1.0, 1.0);
    return 0.5 + M_1_PI * (std::asin(t) + t * std::sqrt((1.0 - t) * (1.0 + t)));
}
}  // namespace

// 1. A blend after others (kept pieces, the rules, the memo of p) against a fresh pressure's, bit for bit.
TEST(WeightCostS24, KeptTablesGiveTheFreshBlendsValues) {
    constexpr int n = 64;
    const auto kept = wired(n);
    const auto fresh = wired(n);
    // Blends of both stick zones at ends Newton's steps might ask, then the one compared.
    for (const double d : {3e-3, -2e-3, 1e-4}) {
        ASSERT_TRUE(kept->blend(ends[0] + d, ends[1] - d));
        ASSERT_TRUE(kept->blend(ends[2] - d, ends[3] + d));
    }
    const double s = ends[2] + 2e-4, c = ends[3] - 1e-4;
    const auto a = kept->blend(s, c), b = fresh->blend(s, c);
    ASSERT_TRUE(a && b);
    std::vector<double> r = points(s, c);
    // The second table's points: next to nodes of the first (M = 10 sqrt(n) + 48 points off the stick zones, M + n on
    // the pieces inside them: pressure_kinks::blend).
    const int m = static_cast<int>(std::ceil(10.0 * std::sqrt(double(n)))) + 48;
    const gauss_legendre off(m), on(m + n);
    std::vector<double> near_nodes;
    for (const auto& [rule, lo, hi] : {std::tuple<const gauss_legendre&, double, double>{off, ends[3], 1.0},
                                       std::tuple<const gauss_legendre&, double, double>{on, c, ends[3]}})
        for (const std::size_t j : {rule.nodes.size() / 2, rule.nodes.size() / 3}) {
            const auto x = node(rule, j, lo, hi);
            near_nodes.push_back(x[0] + 1e-7 * x[1]);
        }
    r.insert(r.end(), near_nodes.begin(), near_nodes.end());
    // There also against QUADPACK's H[p H] (the fresh blend keeps its pieces too: a wrong second table would be wrong in
    // both; the first table's node 1e-7 of its weight from r loses about 1e-10 to cancellation).
    gsl_set_error_handler_off();
    for (const double x : near_nodes) {
        const std::function<double(double)> g = [&](double eta) { return (*kept)(eta) * blend_of(eta, s, c); };
        const double reference = hilbert_on_pieces::hilbert(g, x, {s, c, ends[0], ends[1], ends[2], ends[3]});
        const std::optional<double> w = (*a)(x, blend_of(x, s, c));
        ASSERT_TRUE(w);
        EXPECT_NEAR(*w, reference, 1e-12) << x;
        std::printf("r %.17g: W %.17g, QUADPACK %+.2e\n", x, *w, *w - reference);
    }
    int compared = 0;
    for (const double x : r) {
        const double h = blend_of(x, s, c);
        const std::optional<double> wa = (*a)(x, h), wb = (*b)(x, h);
        ASSERT_EQ(wa.has_value(), wb.has_value()) << x;
        if (!wa) continue;
        EXPECT_EQ(*wa, *wb) << x;  // bit for bit
        ++compared;
    }
    EXPECT_EQ(compared, 27);  // 8 in each of the 3 pieces, 4 by nodes, less one within 1e-8 of the edge
    ASSERT_TRUE(a->zone_load() && b->zone_load());
    EXPECT_EQ(*a->zone_load(), *b->zone_load());
    std::printf("W compared at %d points, bit for bit; zone load %.17g\n", compared, *a->zone_load());
}

// 2. The zone load of a blend on the kinks' own second stick zone (all its pieces kept) against QAGS of p Theta.
TEST(WeightCostS24, ZoneLoadFromKeptPiecesAgainstQuadpack) {
    gsl_set_error_handler_off();
    const auto p = wired(128);
    ASSERT_TRUE(p->blend(ends[2] - 1e-3, ends[3] + 1e-3));  // keeps the piece [s2, c2] (the kinks' zone)
    const double s = ends[2], c = ends[3];
    const auto b = p->blend(s, c);
    ASSERT_TRUE(b);
    const std::optional<double> zone = b->zone_load();
    ASSERT_TRUE(zone);
    const std::function<double(double)> g = [&](double x) { return (*p)(x) * blend_of(x, s, c); };
    const auto [total, estimate] = hilbert_on_pieces::integral_graded(g, s, c, 512);
    std::printf("zone load %.17g, QAGS %.17g (its estimate %.1e): %+.2e\n", *zone, total, estimate, *zone - total);
    EXPECT_NEAR(*zone, total, 1e-13 + estimate);
}
