// SPDX-License-Identifier: GPL-3.0-or-later
// Gauss-Chebyshev rule (4.6)-(4.7) and the U-series tools built on it.
#include <cmath>
#include <vector>

#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "tolerance.hpp"

using namespace roughroll;

TEST(GaussChebyshev, NodesWeightsAndCollocationPoints) {
    const gauss_chebyshev rule(7);
    ASSERT_EQ(rule.nodes.size(), 7u);
    ASSERT_EQ(rule.collocation.size(), 8u);
    double sum = 0.0;
    for (int k = 0; k < 7; ++k) {
        EXPECT_NEAR(rule.nodes[k], std::cos((k + 1) * M_PI / 8), tol::few_roundings);
        sum += rule.weights[k];
    }
    EXPECT_NEAR(sum, M_PI / 2, tol::short_sum);  // int sqrt(1 - x^2) dx
    for (int m = 0; m < 8; ++m)
        EXPECT_NEAR(std::cos(8 * std::acos(rule.collocation[m])), 0.0, tol::short_sum);  // T_{n+1}
}

TEST(GaussChebyshev, RejectsNOutsideRange) {
    EXPECT_THROW(gauss_chebyshev(min_nodes - 1), input_error);
    EXPECT_THROW(gauss_chebyshev(max_nodes + 1), input_error);
    EXPECT_NO_THROW(gauss_chebyshev{min_nodes});
}

TEST(GaussChebyshev, ExactToDegreeTwoNMinusOne) {
    const int n = 6;
    const gauss_chebyshev rule(n);
    // int x^{2j} sqrt(1 - x^2) dx = pi (2j)! / (2^{2j+1} j! (j+1)!)
    for (int j = 0; 2 * j <= 2 * n - 1; ++j) {
        double q = 0.0;
        for (int k = 0; k < n; ++k) q += rule.weights[k] * std::pow(rule.nodes[k], 2 * j);
        const double exact =
            M_PI * std::tgamma(2 * j + 1) / (std::pow(2.0, 2 * j + 1) * std::tgamma(j + 1) * std::tgamma(j + 2));
        EXPECT_NEAR(q, exact, tol::short_sum) << "degree " << 2 * j;
    }
}

TEST(USeries, InterpolatesAPolynomialExactly) {
    const gauss_chebyshev rule(9);
    auto poly = [](double x) { return 1.0 - 2.0 * x + 3.0 * x * x * x - 0.5 * std::pow(x, 8); };
    std::vector<double> values;
    for (double x : rule.nodes) values.push_back(poly(x));
    const auto b = u_coefficients(rule, values);
    for (double x : {-1.0, -0.3, 0.0, 0.77, 1.0}) EXPECT_NEAR(u_series(b, x), poly(x), tol::interpolation);
}

// The batched Cauchy transform (the slip-velocity checks, tangential_solver::check) gives each
// point's scalar value bit for bit: points outside (-1, 1) on both sides, at +-1, a block with a
// point inside (the scalar route), a partial last block; and the closed form for phi = 1.
TEST(USeries, BatchedCauchyTransformEqualsTheScalarOne) {
    std::vector<double> b;
    for (int j = 0; j < 129; ++j) b.push_back(std::sin(0.7 * j + 0.3) / (1.0 + j));
    std::vector<double> x;
    for (int i = 0; i < 200; ++i) x.push_back(1.0 + 3.0 * std::pow(std::sin(M_PI * (i + 0.5) / 400), 2));  // (1, 4]
    x.insert(x.end(), {-1.0, 1.0, -1.5, -40.0, 1.0 + 1e-15, 0.3, 2.0, -0.99, 7.0, 1.25, -2.0});
    std::vector<double> out(x.size());
    cauchy_u_series(b, x.data(), out.data(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(out[i], cauchy_u_series(b, x[i])) << "x = " << x[i];
    const std::vector<double> one{1.0};
    cauchy_u_series(one, x.data(), out.data(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (std::fabs(x[i]) > 1.0) {
            EXPECT_NEAR(out[i], -(x[i] - std::copysign(std::sqrt(x[i] * x[i] - 1.0), x[i])), tol::few_roundings)
                << "x = " << x[i];
        }
    }
}

TEST(USeries, CauchyTransformInsideAndOutside) {
    // phi = 1: (1/pi) int sqrt(1-t^2)/(t - x) dt = -x inside, -(x - sgn x sqrt(x^2-1)) outside.
    const std::vector<double> one{1.0};
    EXPECT_NEAR(cauchy_u_series(one, 0.4), -0.4, tol::few_roundings);
    EXPECT_NEAR(cauchy_u_series(one, 2.0), -(2.0 - std::sqrt(3.0)), tol::few_roundings);
    EXPECT_NEAR(cauchy_u_series(one, -3.0), -(-3.0 + std::sqrt(8.0)), tol::few_roundings);
    // U_2 inside: -T_3(x).
    const std::vector<double> u2{0.0, 0.0, 1.0};
    const double x = 0.3;
    EXPECT_NEAR(cauchy_u_series(u2, x), -(4 * x * x * x - 3 * x), tol::few_roundings);
}

TEST(USeries, ExactTrailingZerosChangeNoBit) {
    // Clenshaw skips a series' exact trailing zeros (a Hertz pressure is one term of n): the
    // values are those of the series without them, bit for bit, scalar and batched, at points
    // of either sign (where 2x * 0 is -0).
    const std::vector<double> short_b{0.3, -1.2, 0.5};
    std::vector<double> long_b = short_b;
    long_b.resize(40, 0.0);
    std::vector<double> x, out(9);
    for (int i = 0; i < 9; ++i) x.push_back(std::cos(0.37 * i));
    u_series(long_b, x.data(), out.data(), x.size());
    for (int i = 0; i < 9; ++i) {
        EXPECT_EQ(u_series(long_b, x[i]), u_series(short_b, x[i]));
        EXPECT_EQ(out[i], u_series(short_b, x[i]));
    }
    EXPECT_EQ(u_series(std::vector<double>(5, 0.0), 0.4), 0.0);
}

TEST(HertzSolution, IsOneTermExactly) {
    // The smooth normal problem's pressure (2/pi) sqrt(1 - r^2): b_0 = 2/pi and every other b_j
    // exactly 0 (from the node values, u_coefficients left rounding of up to 1.6e-15 in each b_j
    // at n = 128, summed by every evaluation of p).
    for (int n : {8, 32, 128}) {
        const normal_solution h = hertz_solution(n, method::product);
        ASSERT_EQ(h.b.size(), static_cast<std::size_t>(n));
        EXPECT_EQ(h.b[0], M_2_PI);
        for (int j = 1; j < n; ++j) EXPECT_EQ(h.b[j], 0.0) << "n = " << n << ", j = " << j;
        for (double r : {-0.9, 0.0, 0.3, 0.99}) EXPECT_EQ(h.pressure(r), M_2_PI * std::sqrt(1.0 - r * r)) << r;
    }
}
