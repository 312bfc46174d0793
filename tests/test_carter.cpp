// SPDX-License-Identifier: GPL-3.0-or-later
// Carter's closed form, as written in the literature: xi1 = (f a/R)(1 - sqrt(1 - Q/f)),
// in the paper's units xi = (2f/pi)(1 - sqrt(1 - Q/f)) and (1 + c0)/2 = sqrt(1 - Q/f).
#include <cmath>

#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/model/carter.hpp"
#include "tolerance.hpp"

using namespace roughroll;

TEST(Carter, EndsOfTheCurve) {
    EXPECT_DOUBLE_EQ(carter(0.0, 0.3).c0, 1.0);
    EXPECT_DOUBLE_EQ(carter(0.0, 0.3).xi, 0.0);
    EXPECT_DOUBLE_EQ(carter(0.3, 0.3).c0, -1.0);
    EXPECT_DOUBLE_EQ(carter(0.3, 0.3).xi, M_2_PI * 0.3);
}

TEST(Carter, MidpointAndMirror) {
    const auto p = carter(0.15, 0.3);
    EXPECT_NEAR(p.c0, 2.0 * std::sqrt(0.5) - 1.0, tol::few_roundings);
    EXPECT_NEAR(p.xi, M_2_PI * 0.3 * (1.0 - std::sqrt(0.5)), tol::few_roundings);
    const auto m = carter(-0.15, 0.3);
    EXPECT_EQ(m.c0, p.c0);
    EXPECT_EQ(m.xi, -p.xi);
}

TEST(Carter, NoCancellationForSmallLoads) {
    // 1 - sqrt(1 - x) = x/2 + x^2/8 + ...: the closed form keeps full relative accuracy.
    const double x = 1e-12;
    EXPECT_NEAR(carter(x, 1.0).xi / (M_2_PI * (x / 2 + x * x / 8)), 1.0, tol::few_roundings);
}
