// SPDX-License-Identifier: GPL-3.0-or-later
// chebyshev_projection (docs/formulation.md 8(e), "The coupled right side") against an independent
// route: each coefficient by GSL's adaptive QAGP in t = acos r with the kinks as break points,
// for a function with square-root kinks inside and square-root ends; a polynomial is reproduced.
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/numerics/chebyshev_projection.hpp"
#include "../validation/chebyshev_by_qagp.hpp"
#include "tolerance.hpp"

using namespace roughroll;

// p1-like: sqrt(1 - r^2) at the ends, square-root kinks at -0.4 and 0.55 (sorted, increasing).
TEST(ChebyshevProjection, KinkedFunctionAgainstAdaptiveQuadrature) {
    const std::vector<double> kinks{-0.4, 0.55};
    const std::function<double(double)> g = [](double r) {
        double v = std::sqrt(1.0 - r * r) * (1.0 + 0.3 * r);
        if (r > -0.4 && r < 0.55) v -= 0.7 * std::sqrt((r + 0.4) * (0.55 - r));
        return v;
    };
    const int N = 40;
    const std::vector<double> c = chebyshev_projection(g, kinks, N);
    ASSERT_EQ(c.size(), static_cast<std::size_t>(N) + 1);
    for (int j = 0; j <= N; ++j)
        EXPECT_NEAR(c[j], chebyshev_coefficient_by_qagp(g, kinks, j, 1e-13), tol::against_adaptive) << j;
    // The series at an inner point between the kinks converges like N^-3/2 (a square-root kink's
    // coefficients fall like j^-3/2 ... ^-5/2): four times N, at least 4 times smaller.
    const double e40 = std::fabs(chebyshev_sum(c, 0.0) - g(0.0));
    const double e160 = std::fabs(chebyshev_sum(chebyshev_projection(g, kinks, 160), 0.0) - g(0.0));
    EXPECT_LT(e160, 0.25 * e40) << e40 << " " << e160;
}

// A polynomial of degree <= N is its own projection (coefficients to rounding), kinks or not.
TEST(ChebyshevProjection, PolynomialIsReproduced) {
    const std::vector<double> want{0.3, -1.2, 0.5, 0.0, 2.0, -0.25};
    const std::function<double(double)> g = [&](double r) { return chebyshev_sum(want, r); };
    for (const std::vector<double>& kinks : {std::vector<double>{}, std::vector<double>{-0.9, 0.1, 0.7}}) {
        const std::vector<double> c = chebyshev_projection(g, kinks, 12);
        for (int j = 0; j <= 12; ++j) EXPECT_NEAR(c[j], j < 6 ? want[j] : 0.0, tol::short_sum) << j;
    }
    EXPECT_DOUBLE_EQ(chebyshev_sum(want, 1.0), 0.3 - 1.2 + 0.5 + 2.0 - 0.25);
    EXPECT_DOUBLE_EQ(chebyshev_sum(want, -1.0), 0.3 + 1.2 + 0.5 + 2.0 + 0.25);
}
