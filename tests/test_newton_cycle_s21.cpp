// SPDX-License-Identifier: GPL-3.0-or-later
// damped_newton's stop in a two-step cycle (numerics/damped_newton.cpp; docs/formulation.md 8(x), "The slow
// refusal"): a residual with a jump at its root holds Newton between two points, each full step taking x back to
// where it was two iterates before; where the caller gives F's rounding, two such returns within it end the search
// with no root, instead of after every iteration (five residuals each at n = 1000 of the five zones: 120 s CPU).
// Neither a contracting Newton nor a smooth unstable cycle that Newton leaves (arctan near 1.3917) is stopped.
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/numerics/damped_newton.hpp"
#include "newton_steps.hpp"

using namespace roughroll;

namespace {
// F(x) = x + c sign(x): a jump of 2c at the root 0 (as the five zones' entry condition across s2, 8(x)). Newton
// from 0.5 goes to -c, then c, -c, ...: each step 2c, each return exact.
newton_problem jump(double c, int& calls) {
    newton_problem p;
    p.residual = [c, &calls](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        ++calls;
        return std::vector<double>{x[0] + (x[0] < 0.0 ? -c : c)};
    };
    return with_steps(p);
}
}  // namespace

TEST(NewtonCycle, AJumpAtTheRootEndsTheSearchAtOnce) {
    int calls = 0;
    newton_problem p = jump(1e-3, calls);
    p.rounding = [](const std::vector<double>&) { return 1e-9; };  // F's rounding, far below the steps 2e-3
    const newton_result r = damped_newton(p, {0.5}, {40, 1e-12, 1e-6});
    EXPECT_EQ(r.stop, newton_stop::no_root);
    EXPECT_FALSE(r.root);
    // Steps 0.5 -> -c -> c (no return yet) -> -c -> c (two returns): four iterations of two residuals (the difference
    // and the step) after the first. Without the stop: 40 iterations, 81 residuals.
    EXPECT_LE(calls, 10);
}

TEST(NewtonCycle, NoCycleReadWithoutTheRoundingOfF) {
    // The same jump, no rounding given: the iterations run out as before (no scale to call the returns exact by).
    int calls = 0;
    const newton_result r = damped_newton(jump(1e-3, calls), {0.5}, {40, 1e-12, 1e-6});
    EXPECT_EQ(r.stop, newton_stop::no_root);
    EXPECT_GT(calls, 40);
}

TEST(NewtonCycle, ASmoothCycleNewtonLeavesIsNotStopped) {
    // arctan(x) = 0 from 1.39 and 1.391: Newton's iterates come back within 0.4 % and 0.16 % of their steps to
    // where they were two before (the unstable cycle at +-1.3917), then leave it and converge to 0 at iterations 10
    // and 11. F's rounding 1e-14 lies far below those returns (0.01 and more): no stop.
    for (const double x0 : {1.39, 1.391}) {
        newton_problem p;
        p.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
            return std::vector<double>{std::atan(x[0])};
        };
        p = with_steps(p);
        p.rounding = [](const std::vector<double>&) { return 1e-14; };
        const newton_result r = damped_newton(p, {x0}, {40, 1e-12, 1e-6});
        ASSERT_EQ(r.stop, newton_stop::root) << x0;
        EXPECT_NEAR(r.root->x[0], 0.0, 1e-12) << x0;
    }
}
