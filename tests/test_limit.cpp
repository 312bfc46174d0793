// SPDX-License-Identifier: GPL-3.0-or-later
// Unit tests of the one-parameter limit's pieces (src/problems/one_parameter.cpp): the compliances
// 2T/A^2, the symmetry of the normal solution, and p' from the normal equation against a
// difference quotient of the pressure series.
#include <cmath>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/one_parameter.hpp"
#include "tolerance.hpp"

using namespace roughroll;

TEST(Limit, CompliancesSumOverCylinders) {
    roughness r;
    r.cylinder1.normal = {2.0, 2.0};      // 2*2/4 = 1
    r.cylinder2.normal = {0.5, 10.0};     // 1/100
    r.cylinder1.tangential = {0.0, 0.0};  // absent
    r.cylinder2.tangential = {3.0, 3.0};  // 6/9
    const compliances eps = one_parameter_compliances(r);
    EXPECT_DOUBLE_EQ(eps.normal, 1.01);
    EXPECT_DOUBLE_EQ(eps.tangential, 2.0 / 3.0);
    r.cylinder1.tangential = {1.0, 0.0};
    EXPECT_THROW(one_parameter_compliances(r), input_error);
    r.cylinder1.tangential = {-1.0, 1.0};
    EXPECT_THROW(one_parameter_compliances(r), input_error);
}

TEST(Limit, NormalSolutionIsEvenAndCarriesTheLoad) {
    const normal_solution s = one_parameter_normal(0.3, 64);
    EXPECT_EQ(s.how, method::one_parameter);
    EXPECT_NEAR(s.b[0] * M_PI_2, 1.0, tol::few_roundings);
    for (std::size_t j = 1; j < s.b.size(); j += 2) EXPECT_NEAR(s.b[j], 0.0, tol::short_sum) << j;  // p even
    EXPECT_NEAR(s.pressure(0.4), s.pressure(-0.4), tol::short_sum);
    EXPECT_EQ(s.pressure(1.0), 0.0);
    EXPECT_THROW(one_parameter_normal(-1.0, 64), input_error);
    EXPECT_THROW(one_parameter_normal(0.1, 1), input_error);
}

TEST(Limit, PressureSlopeFromTheEquationMatchesTheSeries) {
    one_parameter_solver s(compliances{0.1, 0.3}, 0.3, 128);
    const double h = 1e-5;
    for (double r : {-0.9, -0.5, 0.0, 0.3, 0.8}) {
        const double difference = (s.normal().pressure(r + h) - s.normal().pressure(r - h)) / (2 * h);
        EXPECT_NEAR(s.pressure_slope(r), difference, 1e-4) << r;
        EXPECT_NEAR(s.G(r), M_2_PI * s.normal().lambda * r + 0.2 * s.pressure_slope(r), tol::short_sum) << r;
    }
    EXPECT_TRUE(std::isfinite(s.pressure_slope(-1.0)));
    EXPECT_GT(s.pressure_slope(-1.0), 0.0);  // the pressure rises from the leading edge
}

TEST(Limit, MethodName) {
    EXPECT_EQ(method_from_string(to_string(method::one_parameter)), method::one_parameter);
    EXPECT_GT(default_nodes(method::one_parameter), 0);
}
