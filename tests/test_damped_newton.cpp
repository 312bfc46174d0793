// SPDX-License-Identifier: GPL-3.0-or-later
// The damped Newton of the zone ends (numerics/damped_newton.hpp): a root in three unknowns
// against its closed form, the damping that keeps the iterate inside its domain, and the empty
// answers (singular Jacobian, residual undefined at the start, no convergence); the stop at F's
// rounding where it lies above the tolerance, no stop there while Newton still contracts, nor where
// that rounding passes its cap (far from the root), where it says so, and the zone search's refusal there.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/damped_newton.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_newton.hpp"
#include "newton_steps.hpp"
#include "rounding_jitter.hpp"

using namespace roughroll;

TEST(DampedNewton, ThreeUnknownsAgainstTheClosedForm) {
    // x^2 + y + z = 3, x + y^2 - z = 1, exp(z - 1) - x y = 0 has the root (1, 1, 1).
    newton_problem p;
    p.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{x[0] * x[0] + x[1] + x[2] - 3.0, x[0] + x[1] * x[1] - x[2] - 1.0,
                                   std::exp(x[2] - 1.0) - x[0] * x[1]};
    };
    const auto root = damped_newton(with_steps(p), {1.3, 0.8, 1.2}, {40, 1e-12, 1e-6}).root;
    ASSERT_TRUE(root);
    for (double v : root->x) EXPECT_NEAR(v, 1.0, 1e-10);
    EXPECT_LE(root->iterations, 10);
}

TEST(DampedNewton, StepsHalvedToStayInside) {
    // log(x) = 0 from x = 3: the full step 3 - 3 log 3 < 0 leaves x > 0 and is halved; root x = 1.
    newton_problem p;
    p.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{std::log(x[0])};
    };
    p.inside = [](const std::vector<double>& x) { return x[0] > 0.0; };
    const auto root = damped_newton(with_steps(p), {3.0}, {40, 1e-12, 1e-6}).root;
    ASSERT_TRUE(root);
    EXPECT_NEAR(root->x[0], 1.0, 1e-12);
}

TEST(DampedNewton, EmptyWhenItCannotConverge) {
    newton_problem singular;  // F does not depend on y: the Jacobian is singular
    singular.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{x[0] - 1.0, 2.0 * x[0] - 3.0};
    };
    EXPECT_EQ(damped_newton(with_steps(singular), {0.0, 0.0}, {40, 1e-12, 1e-6}).stop, newton_stop::no_root);

    newton_problem undefined;  // F undefined at the start
    undefined.residual = [](const std::vector<double>&) -> std::optional<std::vector<double>> { return std::nullopt; };
    EXPECT_EQ(damped_newton(with_steps(undefined), {0.0}, {40, 1e-12, 1e-6}).stop, newton_stop::no_root);

    newton_problem no_root;  // x^2 + 1 = 0: the iterates wander and the iterations run out
    no_root.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{x[0] * x[0] + 1.0};
    };
    EXPECT_EQ(damped_newton(with_steps(no_root), {0.5}, {40, 1e-12, 1e-6}).stop, newton_stop::no_root);
}

namespace {
// (x - 1, y - 2) with a rounding of size a: the root (1, 2), whose Newton steps are the rounding's once it is reached.
newton_problem rounded_linear(double a) {
    newton_problem p;
    p.residual = [a](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{x[0] - 1.0 + jitter(x[0] + x[1], a), x[1] - 2.0 + jitter(x[0] - x[1], a)};
    };
    return with_steps(p);
}
}  // namespace

TEST(DampedNewton, StopsAtTheRoundingOfF) {
    // A rounding of 3e-10 at the zone ends' tolerance 1e-11: the steps stay near 3e-10 and the iterations run out (the
    // five zones' Newton at n >= 384 before the stop, docs/formulation.md 8(q)); told the rounding's size, 4e-9 (eps/rcond
    // of the five zones' systems at n = 1000, whose floor steps are 0.004 to 0.17 of it), Newton stops at the second
    // step within it that does not contract, within the rounding of the root.
    newton_problem p = rounded_linear(3e-10);
    EXPECT_EQ(damped_newton(p, {1.5, 1.5}, {40, 1e-11, 1e-6}).stop, newton_stop::no_root);
    p.rounding = [](const std::vector<double>&) { return 4e-9; };
    const newton_result result = damped_newton(p, {1.5, 1.5}, {40, 1e-11, 1e-6});
    EXPECT_EQ(result.stop, newton_stop::root);
    const auto& root = result.root;
    ASSERT_TRUE(root);
    EXPECT_NEAR(root->x[0], 1.0, 6e-10);
    EXPECT_NEAR(root->x[1], 2.0, 6e-10);
    EXPECT_LE(root->iterations, 10);
}

TEST(DampedNewton, NoRoundingStopBeyondItsCap) {
    // An ill-conditioned F (rcond 2e-13): a rounding of 1e-4, of which it is told, 1e-3 = eps/rcond (the differences
    // of the Jacobian 0.1 long, so that the rounding leaves it 1e-3 off). Two steps within that rounding, the second
    // not contracting, come at about 1e-4 from the root: a stop there would be a root 1e7 tolerances off, reported as
    // converged. Above rounding_cap tolerances the rounding stop is none: no root, but the limit of F's rounding, said
    // as such (its caller advises what lowers that rounding), at once (the old code spent all 40 iterations and
    // reported only "no root", which its callers read as a search another n may succeed in).
    newton_problem p = rounded_linear(1e-4);
    p.difference_step = [](const std::vector<double>&, std::size_t) { return -0.1; };
    p.rounding = [](const std::vector<double>&) { return 1e-3; };
    int calls = 0;
    const auto counted = p.residual;
    p.residual = [&](const std::vector<double>& x) {
        ++calls;
        return counted(x);
    };
    const newton_result limited = damped_newton(p, {1.5, 1.5}, {40, 1e-11, 1e-6});
    EXPECT_FALSE(limited.root);
    EXPECT_EQ(limited.stop, newton_stop::rounding_limit);
    EXPECT_EQ(limited.rounding, 1e-3);
    EXPECT_LT(calls, 3 * 10);  // stopped within 10 iterations of 3 residuals each
    // Far from any root: x^3 - 2x + 2 from x = 0 cycles between 0 and 1 (Newton's 2-cycle, its root -1.769), full steps
    // of size 1 that do not contract; told of a rounding of 10, the stop would report 0 or 1 as the root.
    newton_problem cycle;
    cycle.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{x[0] * x[0] * x[0] - 2.0 * x[0] + 2.0};
    };
    cycle = with_steps(cycle);
    cycle.rounding = [](const std::vector<double>&) { return 10.0; };
    const newton_result cycled = damped_newton(cycle, {0.0}, {40, 1e-11, 1e-6});
    EXPECT_FALSE(cycled.root);
    EXPECT_EQ(cycled.stop, newton_stop::rounding_limit);
}

TEST(DampedNewton, NoStopAtTheRoundingWhileNewtonContracts) {
    // The smooth problem above told of a rounding far larger than its own: its steps contract (quadratically), so
    // Newton goes on to the tolerance and the root is as exact as without it.
    newton_problem p;
    p.residual = [](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        return std::vector<double>{x[0] * x[0] + x[1] + x[2] - 3.0, x[0] + x[1] * x[1] - x[2] - 1.0,
                                   std::exp(x[2] - 1.0) - x[0] * x[1]};
    };
    p = with_steps(p);
    const auto plain = damped_newton(p, {1.3, 0.8, 1.2}, {40, 1e-12, 1e-6}).root;
    p.rounding = [](const std::vector<double>&) { return 1e-2; };
    const auto told = damped_newton(p, {1.3, 0.8, 1.2}, {40, 1e-12, 1e-6}).root;
    ASSERT_TRUE(plain && told);
    EXPECT_EQ(told->iterations, plain->iterations);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(told->x[i], plain->x[i]);
}

// The zone ends' Newton (ends_newton, problems/zone_newton.hpp) on a synthetic zone family whose systems have rcond
// 1e-9 (eps/rcond 2.2e-7 of the half-width, 2.2e4 of the ends' tolerance 1e-11; the real zone systems reach 4e-9 at
// n = 1000): the load's gap and the entry condition are linear in the ends with a rounding of 1e-8. Newton stops at
// that rounding beyond its cap: no root from this start (the search's other routes go on), the limit noted for the
// search's refusal, which says what lowers it, not "another n". Before, the stop was an empty result like any
// non-convergence, which the callers worded as "another n (at most 1000) may find them", where a larger n rounds worse.
TEST(ZoneEndsNewton, RoundingBeyondItsCapNotedWithWhatLowersIt) {
    const double f = 0.3, Q = 0.1;
    const auto family = [&](double rcond) {
        return [f, rcond](const std::vector<stick_span>& z) -> std::optional<tangential_solution> {
            // Q(s, c) = f (1 - (c - s)) + rounding, entry E = s + 0.5 + rounding: the root s = -0.5, c = 1/6 + 1/2.
            const double s = z[0].start, c = z[0].end;
            const double load = f * (1.0 - (c - s)) + f * jitter(s + c, 1e-8);
            tangential_solution t = zone_solution(f, s, c, 0.0, load, {s + 0.5 + jitter(s - c, 1e-8)}, rcond);
            return t;
        };
    };
    const auto entry = [](const tangential_solution& t) { return t.psi_b[0]; };
    const std::vector<stick_span> from{{-0.45, 0.7, 0.0}};
    // Well conditioned (rcond 1e-3: a rounding of 2.2e-13, below the tolerance): no stop at the rounding, and the
    // jitter of 1e-8 leaves Newton without a root: empty, for the caller's other starts, and no limit noted.
    rounding_limits plain;
    EXPECT_FALSE(ends_newton<tangential_solution>(family(1e-3), entry, Q, f, from, false, 40, 1e-11, plain));
    EXPECT_FALSE(plain.met());
    rounding_limits met;
    EXPECT_FALSE(ends_newton<tangential_solution>(family(1e-9), entry, Q, f, from, false, 40, 1e-11, met));
    ASSERT_TRUE(met.met());
    const std::string what = met.refusal();
    EXPECT_NE(what.find("give a smaller n"), std::string::npos) << what;
    EXPECT_NE(what.find("(2.22e-07 of the half-width) passes 1000 times their tolerance 1e-11"), std::string::npos)
        << what;
    EXPECT_EQ(what.find("another n"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
}
