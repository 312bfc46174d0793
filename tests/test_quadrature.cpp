// SPDX-License-Identifier: GPL-3.0-or-later
// Gauss-Chebyshev rule (4.6)-(4.7) and the U-series tools built on it.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/cauchy_u_table.hpp"
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
// point inside (the scalar route), blocks inside, a partial last block; and the closed form for phi = 1.
TEST(USeries, BatchedCauchyTransformEqualsTheScalarOne) {
    std::vector<double> b;
    for (int j = 0; j < 129; ++j) b.push_back(std::sin(0.7 * j + 0.3) / (1.0 + j));
    std::vector<double> x;
    for (int i = 0; i < 200; ++i) x.push_back(1.0 + 3.0 * std::pow(std::sin(M_PI * (i + 0.5) / 400), 2));  // (1, 4]
    x.insert(x.end(), {-1.0, 1.0, -1.5, -40.0, 1.0 + 1e-15, 0.3, 2.0, -0.99, 7.0, 1.25, -2.0});
    for (int i = 0; i < 27; ++i) x.push_back(std::cos(M_PI * (i + 0.5) / 27));  // blocks inside (-1, 1)
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

namespace {
// cauchy_u_series in long double from the double x: the reference the table and the series are held to.
long double cauchy_reference(const std::vector<double>& b, double x) {
    long double sum = 0.0L;
    const long double X = x;
    if (std::fabs(x) < 1.0) {
        long double t_prev = 1.0L, t = X;
        for (double bj : b) {
            sum += bj * t;
            const long double next = 2.0L * X * t - t_prev;
            t_prev = t;
            t = next;
        }
    } else {
        const long double z = 1.0L / (X + std::copysign(std::sqrt(X * X - 1.0L), X));  // no cancellation at large |x|
        long double zp = z;
        for (double bj : b) {
            sum += bj * zp;
            zp *= z;
        }
    }
    return -sum;
}
}  // namespace

TEST(CauchyUTable, AgreesWithTheSeriesWithinItsBound) {
    // The tabulated c(x) = cauchy_u_series(b, x) (p_q^0's factor at full coupling) against the series summed in
    // long double, for coefficients like a stick zone's g (falling algebraically, alternating) and n from just above
    // a panel's 25 terms to 1000, at points uniform in phi inside, uniform in w = acosh |x| outside on both sides,
    // beyond the outer panels, and next to x = +-1 on both sides. The table may differ by its bound (at most eps B)
    // and the rounding of an acos or acosh, a 25-term Clenshaw and the conditioning of c at x (|c'(x)| eps |x|,
    // measured here by a difference); a panel misplaced, a side swapped or a bound too small shows as far more.
    for (int n : {26, 64, 128, 300, 1000}) {
        std::vector<double> b(n);
        double l1 = 0.0;
        for (int j = 0; j < n; ++j) {
            b[j] = (j % 2 == 0 ? 0.4 : -0.7) / std::pow(1.0 + j, 1.5) + 1e-5 * std::cos(3.0 * j);
            l1 += std::fabs(b[j]);
        }
        const cauchy_u_table table(b);
        EXPECT_LE(table.error_bound(), GSL_DBL_EPSILON * l1) << "n = " << n;
        std::vector<double> x;
        for (int i = 1; i < 2000; ++i) x.push_back(std::cos(M_PI * i / 2000.0 + 1e-4 * std::sin(7.0 * i)));
        for (int i = 0; i <= 2000; ++i) {
            const double w = 4.0 * i / 2000.0 + 1e-4 * std::sin(5.0 * i);
            x.insert(x.end(), {std::cosh(w), -std::cosh(w)});
        }
        for (double d : {1e-3, 1e-8, 1e-13, 1e-16}) x.insert(x.end(), {1.0 - d, -1.0 + d, 1.0 + 2.0 * d, -1.0 - 2.0 * d});
        x.insert(x.end(), {1.0, -1.0, 30.0, -1e3, 1e8});
        double worst = 0.0;
        for (const double xi : x) {
            const long double ref = cauchy_reference(b, xi);
            const double step = 64.0 * GSL_DBL_EPSILON * std::fabs(xi);
            const double x_up = std::fabs(xi) < 1.0 && xi + step >= 1.0 ? xi - step : xi + step;
            const double slope = std::fabs(static_cast<double>((cauchy_reference(b, x_up) - ref) / (x_up - xi)));
            const double allowed = table.error_bound() + 32.0 * GSL_DBL_EPSILON * (l1 + slope * std::fabs(xi));
            const double error = std::fabs(static_cast<double>(table(xi) - ref));
            EXPECT_LE(error, allowed) << "n = " << n << ", x = " << xi;
            worst = std::max(worst, error / allowed);
        }
        EXPECT_GT(worst, 0.0);
        EXPECT_GT(table.inner_panels(), 0);
        EXPECT_GT(table.outer_panels(), 0);
    }
    EXPECT_THROW(cauchy_u_table(std::vector<double>{}), numerical_error);
    EXPECT_THROW(cauchy_u_table(std::vector<double>{1.0, NAN}), numerical_error);
}

TEST(CauchyUTable, OuterBoundHoldsOnCoarsePanels) {
    // outer_bound against the measured error of the outer panels where it is far above rounding: the table's
    // construction cannot be made coarse, so the panels' interpolant is rebuilt here from the same nodes, for a
    // series with all |b_j| equal (the largest c for its B). A bound without the growth e^(n (x - h)) fails here.
    const int n = 128;
    std::vector<double> b(n);
    double l1 = 0.0;
    for (int j = 0; j < n; ++j) {
        b[j] = j % 3 == 1 ? -1.0 : 1.0;
        l1 += 1.0;
    }
    const auto c = [&b](double w) {
        const double z = std::exp(-w);
        double zp = z, sum = 0.0;
        for (double bj : b) {
            sum += bj * zp;
            zp *= z;
        }
        return -sum;
    };
    const std::vector<double> to_c = theta_panels::values_to_coefficients();
    const int size = theta_panels::degree + 1;
    for (double length : {0.35, 0.25, 0.18}) {
        const double bound = cauchy_u_table::outer_bound(n, length) * l1;
        double worst = 0.0;
        std::vector<double> coefficients(size);
        for (int k = 0; k < size; ++k) {
            coefficients[k] = 0.0;
            for (int i = 0; i < size; ++i) coefficients[k] += to_c[k * size + i] * c(0.5 * length * (theta_panels::lobatto(i) + 1.0));
        }
        for (int i = 0; i <= 1000; ++i) {
            const double s = -1.0 + 2.0 * i / 1000.0;
            double value = 0.0;
            for (int k = 0; k < size; ++k) value += coefficients[k] * std::cos(k * std::acos(s));
            worst = std::max(worst, std::fabs(value - c(0.5 * length * (s + 1.0))));
        }
        EXPECT_LE(worst, bound + n * GSL_DBL_EPSILON * l1) << "panel length " << length;
        EXPECT_GT(worst, 1e-30);
    }
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
