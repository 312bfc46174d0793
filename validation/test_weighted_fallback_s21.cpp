// SPDX-License-Identifier: GPL-3.0-or-later
// The fallback of five zones on the pressure's weight (docs/formulation.md 8(x), "The fallback"): an alternation on the
// weight w_N that loses its five zones is solved again on the old path (square-root weight, the plateau of 8(p)).
// Free rolling of the pair at f = 0.2, n = 1000 (product): the weighted alternation's step 2 holds its five-zone Newton
// in a two-step cycle (a jump of the second entry condition between two points 2.4e-8 apart, 8(x) "The slow refusal")
// and loses them; without the fallback the point is refused ("the five zones ... are not found again", measured with
// the CLI before this change, 5574d83: `point <full> --Q 0 --friction 0.2 --n 1000 --method product`, rc 2). With it, the point is
// the old path's, answered with its checks holding, and it agrees with the weighted path's point at n = 512 (its own
// levels 128, 256 on the weight) within the sum of both estimates: two pressures, one problem.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

using namespace roughroll;

TEST(WeightedFallback, FreeRollingAtTwoTenthsAtThousandNodesTakesTheOldPath) {
    const double f = 0.2;
    const dissimilar pair{beta_al_st, coupling_level::full};
    contact fallback(roughness{}, f, solver_options{1000, method::product}, pair);
    const tangential_solution s = fallback.point(0.0);
    ASSERT_TRUE(s.checks.hold());
    ASSERT_EQ(s.layout.stick_zones(), 2u);
    // The old path's pressure: kinks on the square-root weight (the weighted path sets w_N's exponent, 8(x)).
    ASSERT_TRUE(fallback.normal().kinks);
    EXPECT_FALSE(fallback.normal().kinks->weighted());
    const std::optional<error_estimate> e = fallback.estimate(s);
    ASSERT_TRUE(e);

    contact weighted(roughroll::roughness{}, f, solver_options{512, method::product}, pair);
    const tangential_solution w = weighted.point(0.0);
    ASSERT_TRUE(w.checks.hold());
    ASSERT_EQ(w.layout.stick_zones(), 2u);
    ASSERT_TRUE(weighted.normal().kinks);
    EXPECT_TRUE(weighted.normal().kinks->weighted());
    const std::optional<error_estimate> v = weighted.estimate(w);
    ASSERT_TRUE(v);

    // The estimate report gives c0's and the stick start's; the second zone's ends take the larger of both (as
    // test_five_zones_weighted_s20's reference does).
    const double ends = std::max(e->c0, e->start) + std::max(v->c0, v->start);
    const struct {
        const char* name;
        double a, b, bound;
    } rows[] = {
        {"c0", s.c0(), w.c0(), e->c0 + v->c0},
        {"stick start", s.start(), w.start(), e->start + v->start},
        {"second start", s.start2(), w.start2(), ends},
        {"second end", s.end2(), w.end2(), ends},
        {"xi", s.xi, w.xi, e->xi + v->xi},
        {"P_H/P2", fallback.normal().lambda, weighted.normal().lambda, e->lambda + v->lambda},
    };
    for (const auto& row : rows) {
        std::printf("  %-12s n = 1000 (old path) - n = 512 (weighted) %.3g, estimates' sum %.3g\n", row.name,
                    std::fabs(row.a - row.b), row.bound);
        EXPECT_LE(std::fabs(row.a - row.b), row.bound) << row.name;
    }
}
