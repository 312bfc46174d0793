// SPDX-License-Identifier: GPL-3.0-or-later
// Session 18's cheaper full coupling (docs/formulation.md 8(e), "The stop from the contraction" and "The root before
// the last step"), on closed forms:
//   - the alternation's stop (coupling_settled) on a linear fixed-point map x <- kappa x + c, whose fixed point
//     c/(1 - kappa) is known: the contraction's bound stops no later than the plain rule (a step before it where the
//     last change allows), within the tolerance of the fixed point; the largest ratio is read, not the
//     last; changes that grow (kappa >= 1, where the bound's factor kappa/(1 - kappa) turns negative) or fall
//     slowly are left to the plain rule; from a coarser level's start the first change (the levels' difference)
//     gives no ratio;
//   - damped Newton with a kept Jacobian returns the iterate before a step that the last step's contraction shows to
//     be within the tolerance, without the residual there; where that contraction leaves more than the tolerance
//     (rho/(1 - rho) of it) it takes the step, so the root stays within the tolerance.
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/numerics/damped_newton.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "newton_steps.hpp"
#include "rounding_jitter.hpp"

using namespace roughroll;

namespace {
// The steps of x <- kappa x + c from x0 until `stop` says settled: the changes and the last iterate.
struct fixed_point_run {
    std::vector<double> changes;
    double x;
};
template <class Stop>
fixed_point_run iterate(double kappa, double c, double x0, Stop stop) {
    fixed_point_run run{{}, x0};
    for (int k = 0; k < 60; ++k) {
        const double next = kappa * run.x + c;
        run.changes.push_back(std::fabs(next - run.x));
        run.x = next;
        if (stop(run.changes)) break;
    }
    return run;
}
}  // namespace

TEST(CouplingStop, TheContractionsBoundStopsAStepEarlierWithinTheTolerance) {
    // The alternation's measured contractions (0.01 .. 0.07, 8(e)) from a start 1e-3 away, at the values' tolerance.
    const double tolerance = 1e-12;
    for (const double kappa : {0.01, 0.02, 0.03, 0.05, 0.07, 0.1, 0.3}) {
        SCOPED_TRACE(kappa);
        const double c = 0.25, fixed = c / (1.0 - kappa);
        const auto plain = iterate(kappa, c, fixed + 1e-3, [&](const std::vector<double>& d) { return d.back() <= tolerance; });
        const auto bound = iterate(kappa, c, fixed + 1e-3,
                                   [&](const std::vector<double>& d) { return coupling_settled(d, 0, tolerance); });
        // A step earlier where the last plain step's change lies below the tolerance by less than
        // (1 - kappa)/(4 kappa) (from this start at 0.01 and 0.02), else as many steps; never more.
        if (kappa < 0.025)
            EXPECT_EQ(bound.changes.size() + 1, plain.changes.size());
        else
            EXPECT_EQ(bound.changes.size(), plain.changes.size());
        EXPECT_LE(std::fabs(bound.x - fixed), tolerance * (1.0 + 1e-3));
        EXPECT_LE(std::fabs(plain.x - bound.x), 2.0 * tolerance);
    }
}

TEST(CouplingStop, ChangesThatDoNotContractAreLeftToThePlainRule) {
    const double tolerance = 1e-12;
    // Growing changes: kappa = 2 makes kappa/(1 - kappa) = -2, a "bound" below every tolerance; not settled.
    EXPECT_FALSE(coupling_settled({1e-9, 2e-9}, 0, tolerance));
    EXPECT_FALSE(coupling_settled({1e-9, 1e-9}, 0, tolerance));  // kappa = 1: no contraction shown
    // A slow contraction, kappa = 0.6: only the plain rule, once the last change is within the tolerance.
    EXPECT_FALSE(coupling_settled({2e-12, 1.2e-12}, 0, tolerance));
    EXPECT_TRUE(coupling_settled({1.6e-12, 0.96e-12}, 0, tolerance));
    // One change: no ratio yet.
    EXPECT_FALSE(coupling_settled({2e-12}, 0, tolerance));
    EXPECT_TRUE(coupling_settled({0.5e-12}, 0, tolerance));
    // kappa = 0.004: the bound 4e-3/0.996 x 2e-11 = 8.0e-14 settles a change of 20 tolerances; at kappa = 0.01 the
    // bound 5.1e-13 of a change 5e-11 is within the tolerance but not within its quarter.
    EXPECT_TRUE(coupling_settled({5e-9, 2e-11}, 0, tolerance));
    EXPECT_FALSE(coupling_settled({5e-9, 5e-11}, 0, tolerance));
    // From a coarser level's start the first change is the levels' difference: its ratio is not read.
    EXPECT_FALSE(coupling_settled({5e-9, 2e-11}, 1, tolerance));
    EXPECT_TRUE(coupling_settled({1e-6, 5e-9, 2e-11}, 1, tolerance));
    // The largest of the level's own ratios, not the last (session 18 review): changes 1.4e-5, 1e-6, 9e-9 at the ends'
    // tolerance 1e-10 fall by 0.071 then 0.009; read from the last ratio alone the bound 8.2e-11 would settle a point
    // that a constant of 0.07 leaves 6.8e-10 (6.8 tolerances) from its fixed point.
    EXPECT_FALSE(coupling_settled({1.4e-5, 1e-6, 9e-9}, 0, 1e-10));
    EXPECT_FALSE(coupling_settled({1e-6, 9e-9}, 0, 1e-10));  // one ratio of 0.009: 8.2e-11 is not within 2.5e-11
    EXPECT_TRUE(coupling_settled({1e-6, 9e-9, 1.6e-10}, 0, 1e-10));  // 0.018: 2.9e-12
    // A previous change of zero (gross sliding's ends) gives no ratio.
    EXPECT_FALSE(coupling_settled({0.0, 5e-11}, 0, tolerance));
}

namespace {
// F(x) = x - 1 in one unknown, its residuals counted; a kept Jacobian `slope` makes every step (1/slope) of Newton's.
newton_problem linear(int& calls) {
    newton_problem p;
    p.residual = [&calls](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        ++calls;
        return std::vector<double>{x[0] - 1.0};
    };
    return with_steps(p);
}
}  // namespace

TEST(RootBeforeTheLastStep, AnExactKeptJacobianNeedsNoResidualAtTheRootAgain) {
    // x0 = 3 with the exact Jacobian kept: the first step lands on the root, x = 1 (F = 0 exactly); the next step is 0,
    // which contracts (rho = 0) within the tolerance, so x is the root and F is not asked there a third time.
    int calls = 0;
    newton_jacobian kept;
    kept.J = {{1.0}};
    const auto root = damped_newton(linear(calls), {3.0}, {40, 1e-11, 1e-6}, &kept).root;
    ASSERT_TRUE(root);
    EXPECT_EQ(root->x[0], 1.0);
    EXPECT_EQ(calls, 2);
    EXPECT_EQ(kept.residuals, 2);
    EXPECT_EQ(kept.differenced, 0);
    EXPECT_FALSE(kept.J.empty());
}

TEST(RootBeforeTheLastStep, ASlowerContractionTakesTheStep) {
    // A kept Jacobian 1/0.6 of the true slope: each step is 0.6 of Newton's, the error contracts by rho = 0.4 (|F|
    // more than halved: the steps are taken), and the steps are shorter than the difference step (no Broyden update).
    // From 1 + 1e-10 the errors are 4e-11, 1.6e-11, 6.4e-12: the step 9.6e-12 from 1 + 1.6e-11 is below the
    // tolerance 1e-11, but the iterate before it is 1.6e-11 away, which the bound 9.6e-12/(1 - 0.4) = 1.6e-11 shows:
    // the step is taken, and the root returned is 6.4e-12 from 1, within the tolerance.
    int calls = 0;
    newton_jacobian kept;
    kept.J = {{1.0 / 0.6}};
    const auto root = damped_newton(linear(calls), {1.0 + 1e-10}, {40, 1e-11, 1e-6}, &kept).root;
    ASSERT_TRUE(root);
    EXPECT_LE(std::fabs(root->x[0] - 1.0), 1e-11);
    EXPECT_NEAR(root->x[0], 1.0 + 6.4e-12, 1e-15);
    EXPECT_EQ(kept.differenced, 0);
}

namespace {
// (x - 1, y - 2) with a rounding of size a (rounding_jitter.hpp), told to Newton as `rounding`: the five zones' ends
// at large n, where eps/rcond of their systems lies above the tolerance (docs/formulation.md 8(q)).
newton_problem rounded_linear(double a, double told, int& calls) {
    newton_problem p;
    p.residual = [a, &calls](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        ++calls;
        return std::vector<double>{x[0] - 1.0 + jitter(x[0] + x[1], a), x[1] - 2.0 + jitter(x[0] - x[1], a)};
    };
    p.rounding = [told](const std::vector<double>&) { return told; };
    return with_steps(p);
}
}  // namespace

TEST(RootBeforeTheLastStep, AtTheRoundingOfFTheIterateBeforeTheStep) {
    // The exact Jacobian kept: the first step lands within the rounding 3e-10 of the root; the next step, of that
    // rounding's size, contracts by 1e-9 and lies within F's rounding 4e-9, so x is the root to that rounding (the
    // resolution reported), without the two steps within the rounding that the rounding stop waits for.
    int calls = 0;
    newton_jacobian kept;
    kept.J = {{1.0, 0.0}, {0.0, 1.0}};
    const newton_result result = damped_newton(rounded_linear(3e-10, 4e-9, calls), {1.5, 1.5}, {40, 1e-11, 1e-6}, &kept);
    ASSERT_EQ(result.stop, newton_stop::root);
    ASSERT_TRUE(result.root);
    EXPECT_NEAR(result.root->x[0], 1.0, 6e-10);
    EXPECT_NEAR(result.root->x[1], 2.0, 6e-10);
    EXPECT_EQ(result.root->resolution, 4e-9);
    EXPECT_EQ(calls, 2);
    // Beyond the cap (rounding_cap tolerances) no root is taken before a step: the rounding limit is the stop's to tell.
    int beyond = 0;
    newton_jacobian kept_beyond;
    kept_beyond.J = {{1.0, 0.0}, {0.0, 1.0}};
    const newton_result limit =
        damped_newton(rounded_linear(3e-10, 2e-8, beyond), {1.5, 1.5}, {40, 1e-11, 1e-6}, &kept_beyond);
    EXPECT_NE(limit.stop, newton_stop::root);
}
