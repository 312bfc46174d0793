// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 23, 2: Bentall and Johnson's braked pair near gross sliding (data/aluminium-on-steel.toml,
// Johnson's level, f = 0.05) at Q = -0.049999 (Q/f = -0.99998), three zones with a stick zone of
// half-length 0.023. The start's levels 64, 128, 256 at the default n = 128 differ by -5.3e-11 and
// -4.1e-10: the rounding of the entry condition psi(-1), which grows like n^2 and moves the start by
// rho/|b_0| = 814 times it (docs/formulation.md 8(m)); the point had been refused as not converging
// visibly. The zone-end floor entry_ends_floor takes that rounding in: the point is answered, and
// its estimates bound the distance from two other routes, each within its own estimate.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"

using namespace roughroll;

namespace {

constexpr double braked = -0.049999;

struct routed {
    tangential_solution solution;
    error_estimate estimate;
};

// The scene's point at n (its default method, extrapolated) with its estimate; a refusal fails.
std::optional<routed> at(int n, double Q) {
    scene s = read_scene(ROUGHROLL_DATA "/aluminium-on-steel.toml");
    if (n > 0) override_solver(s, n, std::nullopt);
    try {
        const scene_point p = solve_point(s, Q);
        if (!p.estimate) {
            ADD_FAILURE() << "n = " << n << ": no estimate";
            return std::nullopt;
        }
        return routed{p.solution, *p.estimate};
    } catch (const resolution_error& e) {
        ADD_FAILURE() << "n = " << n << " refused: " << e.what();
        return std::nullopt;
    }
}

}  // namespace

// Refused on today's main at the default n = 128; answered now, with bounds that hold against the
// n = 32 point (least rounding: the data b p + f G are analytic on the stick zone, so the smooth
// pair converges spectrally, 8(k), and only rounding separates the levels) and against n = 512
// (whose own rounding is 16 times n = 128's: each bound must cover the distance less the other's).
TEST(DissimilarNearSliding, BrakedPairAnsweredAtTheDefaultNWithBoundsThatHold) {
    const auto p = at(0, braked);
    ASSERT_TRUE(p.has_value());
    const tangential_solution& s = p->solution;
    ASSERT_FALSE(s.five);
    ASSERT_TRUE(s.checks.hold());
    EXPECT_GT(s.start, -1.0);
    EXPECT_LT(s.rho(), 0.03);  // the stick zone near gross sliding
    const auto coarse = at(32, braked), fine = at(512, braked);
    ASSERT_TRUE(coarse && fine);
    std::printf("n = 128: start %.15f +- %.2e, c0 %.15f +- %.2e, xi %.16f +- %.2e\n", s.start, p->estimate.start,
                s.c0, p->estimate.c0, s.xi, p->estimate.xi);
    for (const routed* r : {&*coarse, &*fine}) {
        std::printf("  against start %.15f (+- %.2e) c0 %.15f (+- %.2e) xi %.16f: %.2e %.2e %.2e\n", r->solution.start,
                    r->estimate.start, r->solution.c0, r->estimate.c0, r->solution.xi,
                    std::fabs(s.start - r->solution.start), std::fabs(s.c0 - r->solution.c0),
                    std::fabs(s.xi - r->solution.xi));
        // |error of n = 128| >= |distance| - (the other route's bound): within n = 128's bound.
        EXPECT_LE(std::fabs(s.start - r->solution.start) - r->estimate.start, p->estimate.start);
        EXPECT_LE(std::fabs(s.c0 - r->solution.c0) - r->estimate.c0, p->estimate.c0);
        EXPECT_LE(std::fabs(s.xi - r->solution.xi) - r->estimate.xi, p->estimate.xi);
    }
    // The n = 32 route's rounding is 16 times below n = 128's: its distance alone stays within.
    EXPECT_LE(std::fabs(s.start - coarse->solution.start), p->estimate.start);
    EXPECT_LE(std::fabs(s.c0 - coarse->solution.c0), p->estimate.c0);
}

// The floor reads rounding as rounding, not divergence: on the braked point's zone (rho = 0.0228,
// b_0 = -2.8e-5, terms 0.29) at levels 64, 128, 256 it is 1.7e-9, above the levels' -5.3e-11,
// -4.1e-10 (refused with the floor of before, 2e-11); levels that move by 1e-6 and 1e-5 (a
// structure that does not converge) are still refused, and on a zone away from sliding (rho = 0.5,
// b_0 = -0.015, about the braked pair at Q/f = -0.75) the floor is 7e-11.
TEST(DissimilarNearSliding, FloorTakesRoundingNotDivergence) {
    const double rho = 0.022758, b0 = -2.797e-5, terms = 0.0969213 + 0.1438337 + 0.05;
    const double floor = entry_ends_floor(256, terms, rho, b0);
    EXPECT_GT(floor, 1e-9);
    EXPECT_LT(floor, 3e-9);
    const double start = -0.3396594114;
    const three_levels noise{start, start - 5.34e-11, start - 5.34e-11 - 4.08e-10};
    EXPECT_FALSE(bound_error(noise, 4, reported_value{1, false}, 2.0 * zone_end_resolution).resolved)
        << "the refusal before";
    const error_bound b = bound_error(noise, 4, reported_value{1, false}, 2.0 * zone_end_resolution + floor);
    EXPECT_TRUE(b.resolved);
    EXPECT_GE(b.value, 4.6e-10);
    const three_levels diverging{start, start + 1e-6, start - 1e-5};
    EXPECT_FALSE(bound_error(diverging, 4, reported_value{1, false}, 2.0 * zone_end_resolution + floor).resolved);
    EXPECT_LT(entry_ends_floor(256, terms, 0.5, -0.015), 1e-10);
    EXPECT_EQ(entry_ends_floor(256, terms, 0.5, 0.0), 0.0);  // no zone's b_0: no floor, not infinity
}
