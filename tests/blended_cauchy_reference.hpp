// SPDX-License-Identifier: GPL-3.0-or-later
// The reference of W's Cauchy part for the blended stick zone (test_blended_cauchy, test_kinks_blend_s18): GSL's
// adaptive quadrature of its definition (docs/formulation.md 8(g), 8(o)), independent of blended_cauchy and kinks_blend.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

// The blend Theta of 8(g) on the zone [s, c]: 0 before it, 1 after it.
inline double theta_blend(double eta, double s, double c) {
    if (eta <= s) return 0.0;
    if (eta >= c) return 1.0;
    const double t = std::clamp((eta - s) / (0.5 * (c - s)) - 1.0, -1.0, 1.0);
    return 0.5 + M_1_PI * (std::asin(t) + t * std::sqrt(1.0 - t * t));
}

// (1/pi) PV int_s^1 p H/(eta - r) as (1/pi) [int_s^1 (g(eta) - g(r))/(eta - r) d eta + g(r) log((1 - r)/(r - s))],
// g = p H (g(r) = 0 for r outside (s, 1)), the bounded integrand by QAGS on the pieces between s, c, r, 1 and
// `cuts` (the kinks' ends), each in u = sqrt(1 - eta) (the square root of p at eta = 1 made analytic).
// `phi`(eta) = p/sqrt(1 - eta^2). QAGS's own error estimate is accepted up to `accepted` where it reports no success
// (GSL's round-off on an integrand oscillating with 1000 terms reaches 1.6e-13).
inline double blended_reference(const std::function<double(double)>& phi, double s, double c, double r,
                                const std::vector<double>& cuts = {}, double accepted = 1e-13) {
    const std::function<double(double)> g = [&](double eta) {
        return std::sqrt((1.0 - eta) * (1.0 + eta)) * phi(eta) * theta_blend(eta, s, c);
    };
    const bool inside = r > s && r < 1.0;
    const double gr = inside ? g(r) : 0.0;
    // In u, 1 - eta = u^2 exactly: p = u sqrt(2 - u^2) phi(1 - u^2), eta - r = (1 - r) - u^2, d eta = -2 u du.
    const std::function<double(double)> h_u = [&](double u) {
        const double eta = 1.0 - u * u, gap = (1.0 - r) - u * u;
        if (gap == 0.0) return 0.0;
        const double ge = u * std::sqrt(2.0 - u * u) * phi(eta) * theta_blend(eta, s, c);
        return 2.0 * u * (ge - gr) / gap;
    };
    constexpr std::size_t limit = 4000;
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(limit);
    std::vector<double> ends{s, c, 1.0};
    if (inside && r != c) ends.push_back(r);
    for (const double e : cuts)
        if (e > s && e < 1.0) ends.push_back(e);
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    double total = inside ? gr * std::log((1.0 - r) / (r - s)) : 0.0;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        double result = 0.0, error = 0.0;
        gsl_function fn;
        fn.function = [](double x, void* q) { return (*static_cast<const std::function<double(double)>*>(q))(x); };
        fn.params = const_cast<std::function<double(double)>*>(&h_u);
        const int status = gsl_integration_qags(&fn, std::sqrt(1.0 - ends[i + 1]), std::sqrt(1.0 - ends[i]), 1e-15,
                                                1e-14, limit, w, &result, &error);
        EXPECT_TRUE(status == GSL_SUCCESS || error < accepted) << "reference at r = " << r << ": " << error;
        total += result;
    }
    gsl_integration_workspace_free(w);
    return M_1_PI * total;
}
