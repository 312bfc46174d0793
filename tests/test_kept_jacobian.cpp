// SPDX-License-Identifier: GPL-3.0-or-later
// A Jacobian kept between the solves of a sequence (damped_newton.hpp, newton_jacobian; full coupling's alternation,
// docs/formulation.md 8(e), "The Jacobian kept between steps"): on a sequence of systems whose root moves a little
// from one to the next, the roots are those of the differenced Newton (to the tolerance, against their closed form),
// at fewer residuals; a kept Jacobian that is wrong (its steps do not contract) is differenced afresh and the root is
// still found; a solve without a root hands no Jacobian on.
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/numerics/damped_newton.hpp"
#include "newton_steps.hpp"

using namespace roughroll;

namespace {
// The system of DampedNewton.ThreeUnknownsAgainstTheClosedForm (root (1, 1, 1)) in x - t, with terms of order t that
// vanish at that root and change the Jacobian: the root is (1 + t, 1 + t, 1 + t) for every t, the slopes move with t.
newton_problem moving(double t, int& calls) {
    newton_problem p;
    p.residual = [t, &calls](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        ++calls;
        const double a = x[0] - t, b = x[1] - t, c = x[2] - t;
        return std::vector<double>{a * a + b + c - 3.0 + 0.1 * t * (a - 1.0),
                                   a + b * b - c - 1.0 + 0.2 * t * (b - 1.0) * c,
                                   std::exp(c - 1.0) - a * b - 0.1 * t * (c - 1.0)};
    };
    return with_steps(p);
}

constexpr double tolerance = 1e-11;
}  // namespace

TEST(KeptJacobian, SameRootsAsDifferencedNewtonAtFewerResiduals) {
    // The alternation's pattern: each solve starts at the last root, the system moved by a small step in t.
    newton_jacobian kept;
    int with_kept = 0, without = 0;
    std::vector<double> from_kept = {1.3, 0.8, 1.2}, from_plain = from_kept;
    for (int step = 0; step < 8; ++step) {
        const double t = 1e-3 * (1.0 - std::pow(0.1, step));  // roots moving less and less, as the alternation's ends
        const auto a = damped_newton(moving(t, with_kept), from_kept, {40, tolerance, 1e-6}, &kept).root;
        const auto b = damped_newton(moving(t, without), from_plain, {40, tolerance, 1e-6}).root;
        ASSERT_TRUE(a);
        ASSERT_TRUE(b);
        // (1 + t, 1 + t, 1 + t) is the root (the perturbations vanish there); the last step was below the tolerance,
        // with a Jacobian whose steps contract, so the root is within it.
        for (std::size_t j = 0; j < 3; ++j) {
            EXPECT_NEAR(a->x[j], 1.0 + t, tolerance) << "step " << step;
            EXPECT_NEAR(b->x[j], 1.0 + t, tolerance) << "step " << step;
        }
        EXPECT_FALSE(kept.J.empty());
        from_kept = a->x;
        from_plain = b->x;
    }
    EXPECT_EQ(kept.residuals, with_kept);
    EXPECT_LT(3 * with_kept, 2 * without) << "kept " << with_kept << " against " << without;
    // Only the first solve differenced (its start has no Jacobian); every later one began from the kept one.
    EXPECT_LE(kept.differenced, 2);
}

TEST(KeptJacobian, AWrongOneIsDifferencedAfresh) {
    // A kept Jacobian of the opposite sign: its first step goes away from the root (|F| grows), so it is not taken,
    // the Jacobian is differenced at x and Newton goes on from there to the root.
    int calls = 0;
    newton_jacobian kept;
    kept.J = {{-2.0, -1.0, -1.0}, {-1.0, -2.0, 1.0}, {1.0, 1.0, -1.0}};
    const auto root = damped_newton(moving(0.0, calls), {1.1, 0.95, 1.05}, {40, tolerance, 1e-6}, &kept).root;
    ASSERT_TRUE(root);
    for (const double v : root->x) EXPECT_NEAR(v, 1.0, tolerance);
    EXPECT_GE(kept.differenced, 1);
}

TEST(KeptJacobian, NoRootHandsNoJacobianOn) {
    // x^2 + 1 = 0 has no real root: every step of Newton (or of a secant) in x is at least (x^2 + 1)/|J|, never below
    // the tolerance, until the iterations are spent; the kept Jacobian is dropped, not handed to the next solve.
    int calls = 0;
    newton_problem none = moving(0.0, calls);
    none.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{x[0] * x[0] + 1.0, x[1] - 1.0};
    };
    newton_jacobian kept;
    kept.J = {{1.0, 0.0}, {0.0, 1.0}};
    EXPECT_FALSE(damped_newton(none, {0.5, 0.5}, {40, tolerance, 1e-6}, &kept).root);
    EXPECT_TRUE(kept.J.empty());
}

TEST(KeptJacobian, AnOverscaledOneIsNotARoot) {
    // A kept Jacobian s times the true one (s = 1e9, 1e12): its step is s times too short, below the tolerance from the
    // first iteration, while |F| stays as it was. The start is no root: the Jacobian is differenced and the root found.
    for (const double scale : {1e9, 1e12}) {
        int calls = 0;
        newton_problem linear = moving(0.0, calls);
        linear.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
            return std::vector<double>{x[0] - 1.0, x[1] - 2.0};
        };
        newton_jacobian kept;
        kept.J = {{scale, 0.0}, {0.0, scale}};
        const auto root = damped_newton(linear, {1.001, 2.001}, {40, tolerance, 1e-6}, &kept).root;
        ASSERT_TRUE(root) << "scale " << scale;
        EXPECT_NEAR(root->x[0], 1.0, tolerance) << "scale " << scale;
        EXPECT_NEAR(root->x[1], 2.0, tolerance) << "scale " << scale;
        EXPECT_GE(kept.differenced, 1) << "scale " << scale;
    }
}
