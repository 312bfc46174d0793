// SPDX-License-Identifier: GPL-3.0-or-later
// The blend Theta_3 of docs/formulation.md 8(r) (blend_theta3, pressure_kinks.hpp), along which the variable exponent
// of 8(z) rises and falls across the five zones' stick zones: against the quadrature of its derivative
// (16/(5 pi)) (1 - t^2)^(5/2), and against Theta of 8(g) less sqrt(1 - t^2) blend_kinks (the two blends' difference,
// whose own check by quadrature is tests/test_rough_blend_s20.cpp's).
#include <cmath>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/problems/pressure_kinks.hpp"

namespace {
struct workspace {
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(2000);
    ~workspace() { gsl_integration_workspace_free(w); }
};
}  // namespace

TEST(BlendTheta3, IsTheIntegralOfItsDerivative) {
    gsl_set_error_handler_off();
    workspace ws;
    gsl_function d{[](double t, void*) { return 16.0 / (5.0 * M_PI) * std::pow(1.0 - t * t, 2.5); }, nullptr};
    for (const double t : {-1.0, -0.9, -0.3, 0.0, 0.2, 0.77, 1.0}) {
        double value = 0.0, error = 0.0;
        if (t > -1.0) {
            ASSERT_EQ(gsl_integration_qags(&d, -1.0, t, 1e-15, 1e-13, 2000, ws.w, &value, &error), GSL_SUCCESS);
        }
        EXPECT_NEAR(roughroll::blend_theta3(t), value, 1e-14) << t;
    }
}

// Theta(t) = 1/2 + (arcsin t + t sqrt(1 - t^2))/pi (8(g)), and Theta - Theta_3 = sqrt(1 - t^2) blend_kinks(t) (8(r)):
// the two functions that split Theta between the pressure's kinks and the right side agree to rounding.
TEST(BlendTheta3, IsThetaLessTheBlendsKinks) {
    for (const double t : {-1.0, -0.999, -0.6, -0.1, 0.0, 0.35, 0.8, 0.9999, 1.0}) {
        const double root = std::sqrt((1.0 - t) * (1.0 + t));
        const double theta = 0.5 + M_1_PI * (std::asin(t) + t * root);
        EXPECT_NEAR(roughroll::blend_theta3(t), theta - root * roughroll::blend_kinks(t), 4e-16) << t;
    }
}
