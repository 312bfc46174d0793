// SPDX-License-Identifier: GPL-3.0-or-later
// The smooth-cylinder limit: the numerical scheme itself (not the closed-form path)
// reproduces Carter's xi = (2f/pi)(1 - sqrt(1 - Q/f)), (1 + c0)/2 = sqrt(1 - Q/f) to 1e-12,
// for both methods, several n, and Q/f from 1e-6 to 1 - 1e-6 (and the mirror Q < 0).
#include <cmath>

#include <gtest/gtest.h>

#include "roughroll/model/carter.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/tangential_solver.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {
const double ratios[] = {1e-6, 1e-3, 0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 0.999, 1.0 - 1e-6};
}

class SmoothLimit : public ::testing::TestWithParam<std::tuple<method, int>> {};

TEST_P(SmoothLimit, SchemeEqualsCarter) {
    const auto [how, n] = GetParam();
    const double f = 0.3;
    const normal_solution normal = normal_solver(n, how).solve(kernel{});  // solved, not closed form
    EXPECT_NEAR(normal.lambda, 1.0, tol::dense_solve);
    tangential_solver solver(normal, kernel{}, kernel{}, f, /*closed_form=*/false);
    for (double ratio : ratios) {
        for (double sign : {1.0, -1.0}) {
            const double Q = sign * ratio * f;
            const tangential_solution s = solver.solve(Q);
            const carter_point c = carter(Q, f);
            EXPECT_GT(s.iterations, 0);
            EXPECT_NEAR(s.xi, c.xi, tol::two_routes) << "Q/f = " << Q / f;
            EXPECT_NEAR(0.5 * (1.0 + s.c0()), 0.5 * (1.0 + c.c0), tol::two_routes) << "Q/f = " << Q / f;
            EXPECT_TRUE(s.checks.hold()) << "Q/f = " << Q / f;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(MethodsAndN, SmoothLimit,
                         ::testing::Combine(::testing::Values(method::paper, method::product),
                                            ::testing::Values(4, 20, 100)));

TEST(SmoothLimit, ClosedFormPathSolvesNothing) {
    contact c(roughness{}, 0.3, solver_options{});
    EXPECT_EQ(c.normal().lambda, 1.0);
    const auto s = c.point(0.1);
    EXPECT_EQ(s.iterations, 0);  // no root search
    EXPECT_NEAR(s.xi, carter(0.1, 0.3).xi, tol::few_roundings);
    EXPECT_TRUE(s.checks.hold());
}
