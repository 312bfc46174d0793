// SPDX-License-Identifier: GPL-3.0-or-later
// A Chebyshev coefficient of a function with kinks, by GSL's adaptive QAGP: the reference the
// projections of numerics/chebyshev_projection and the full coupling's pressure are checked
// against (a route that shares nothing with them but the definition).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

// int_0^pi F(t) dt by GSL's adaptive QAGP, with break points at acos of the kinks inside (-1, 1) (any order) and at
// the extra points in t: the route of the references below, in t = acos r so that the edges' square roots are smooth.
// GSL_EROUND (the requested 1e-13 at the rounding of the sum) is accepted when QAGP's own error estimate is below
// `accepted_error`.
inline double integral_in_theta_by_qagp(const std::function<double(double)>& F, const std::vector<double>& kinks,
                                        std::vector<double> pts, double accepted_error) {
    gsl_function G{[](double t, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(t); },
                   const_cast<std::function<double(double)>*>(&F)};
    pts.push_back(0.0);
    pts.push_back(M_PI);
    for (double r : kinks)
        if (r > -1.0 && r < 1.0) pts.push_back(std::acos(r));
    std::sort(pts.begin(), pts.end());
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(4000);
    double result = 0.0, error = 0.0;
    const int status = gsl_integration_qagp(&G, pts.data(), pts.size(), 1e-13, 0.0, 4000, w, &result, &error);
    gsl_integration_workspace_free(w);
    EXPECT_TRUE(status == GSL_SUCCESS || (status == GSL_EROUND && error < accepted_error)) << error;
    return result;
}

// (2 - delta_j0)/pi int_0^pi g(cos t) cos(j t) dt, with break points at acos of the kinks.
inline double chebyshev_coefficient_by_qagp(const std::function<double(double)>& g, const std::vector<double>& kinks,
                                            int j, double accepted_error) {
    const double result = integral_in_theta_by_qagp([&](double t) { return g(std::cos(t)) * std::cos(j * t); }, kinks,
                                                    {}, accepted_error);
    return (j == 0 ? 1.0 : 2.0) / M_PI * result;
}
