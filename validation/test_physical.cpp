// SPDX-License-Identifier: GPL-3.0-or-later
// Physical claims of the paper and of docs/formulation.md (2(c), 2(h)), on every solution:
// P_H/P2 > 1 (roughness adds compliance, E2), creep above Carter's (Sec. 4), the
// inequalities (3.3)-(3.4), and the special loads Q = 0, |Q| = f, Q < 0.
#include <cmath>

#include <gtest/gtest.h>

#include "roughroll/model/carter.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/base/error.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {
roughness rough(double T, double A) {
    roughness r;
    r.cylinder1.tangential = r.cylinder1.normal = {T, A};
    return r;
}
}  // namespace

class Physical : public ::testing::TestWithParam<std::tuple<double, double, method>> {};

TEST_P(Physical, LoadRatioCreepAndInequalities) {
    const auto [T, A, how] = GetParam();
    const double f = 0.3;
    contact c(rough(T, A), f, solver_options{64, how});
    EXPECT_GT(c.normal().lambda, 1.0);
    for (double ratio : {0.001, 0.1, 0.5, 0.9, 0.99, 1.0}) {
        const auto s = c.point(ratio * f);
        EXPECT_GT(s.xi, carter(ratio * f, f).xi) << "Q/f = " << ratio;
        EXPECT_TRUE(s.checks.hold()) << "Q/f = " << ratio << " margins " << s.checks.pressure_margin << " "
                                     << s.checks.stick_margin << " " << s.checks.slip_margin;
    }
}

INSTANTIATE_TEST_SUITE_P(Fig2AndBeyond, Physical,
                         ::testing::Combine(::testing::Values(0.5, 1.0, 2.0), ::testing::Values(0.0, 0.5, 1.0, 5.0),
                                            ::testing::Values(method::paper, method::product)));

TEST(SpecialLoads, ZeroLoadNeedsNoSolve) {
    contact c(rough(0.5, 0.5), 0.3, solver_options{40, method::paper});
    const auto s = c.point(0.0);
    EXPECT_EQ(s.xi, 0.0);
    EXPECT_EQ(s.c0(), 1.0);
    EXPECT_EQ(s.iterations, 0);
    EXPECT_TRUE(s.checks.hold());
    EXPECT_NEAR(tangential_of(c).traction(s, 0.3), 0.0, tol::few_roundings);  // full stick, p1 = 0
}

TEST(SpecialLoads, GrossSlidingOnset) {
    contact c(rough(0.5, 0.5), 0.3, solver_options{40, method::paper});
    const auto s = c.point(0.3);
    EXPECT_EQ(s.c0(), -1.0);
    EXPECT_EQ(s.iterations, 0);
    // Equal kernels: xi = -f G(-1) = (2/pi) lambda f.
    EXPECT_NEAR(s.xi, M_2_PI * c.normal().lambda * 0.3, tol::few_roundings);
    // The limit is continuous: Q just below f gives nearly the same creep.
    EXPECT_NEAR(c.point(0.3 * (1 - 1e-10)).xi, s.xi, 1e-5);
    EXPECT_THROW(c.point(0.3 * (1 + 1e-12)), input_error);
}

TEST(SpecialLoads, NegativeLoadIsTheMirror) {
    roughness r = rough(0.5, 0.5);
    r.cylinder2.tangential = {0.7, 2.0};  // unequal kernels: the mirror must still hold exactly
    contact c(r, 0.3, solver_options{40, method::paper});
    const auto plus = c.point(0.12), minus = c.point(-0.12);
    EXPECT_EQ(minus.c0(), plus.c0());
    EXPECT_EQ(minus.xi, -plus.xi);
    for (double x : {-0.9, 0.0, 0.6}) EXPECT_EQ(tangential_of(c).traction(minus, x), -tangential_of(c).traction(plus, x));
    EXPECT_TRUE(minus.checks.hold());
}

TEST(SpecialLoads, RejectsNonFiniteAndSlidingLoads) {
    contact c(rough(0.5, 0.5), 0.3, solver_options{20, method::paper});
    EXPECT_THROW(c.point(std::nan("")), input_error);
    EXPECT_THROW(c.point(INFINITY), input_error);
    EXPECT_THROW(c.point(-0.31), input_error);
}

TEST(Fig2Claim, CreepIncreasesWithTAndDecreasesWithA) {
    // Paper, Fig. 2: rough creep above Carter's, growing with T (2a) and falling with A (2b).
    const double f = 0.3;
    for (double ratio : {0.05, 0.3, 0.6, 0.9, 0.999, 1.0}) {
        const double Q = ratio * f;
        double previous = carter(Q, f).xi;
        for (double T : {0.5, 1.0}) {
            contact c(rough(T, 0.5), f, solver_options{64, method::product});
            const double xi = c.point(Q).xi;
            EXPECT_GT(xi, previous) << "Fig. 2a, T = " << T << ", Q/f = " << ratio;
            previous = xi;
        }
        previous = INFINITY;
        for (double A : {0.0, 0.5, 1.0}) {
            contact c(rough(0.5, A), f, solver_options{64, method::product});
            const double xi = c.point(Q).xi;
            EXPECT_LT(xi, previous) << "Fig. 2b, A = " << A << ", Q/f = " << ratio;
            EXPECT_GT(xi, carter(Q, f).xi);
            previous = xi;
        }
    }
}
