// SPDX-License-Identifier: GPL-3.0-or-later
// W of the blended stick zone as a mean of steps (blended_cauchy, docs/formulation.md 8(g)) against GSL's
// adaptive Cauchy-weighted quadrature (QAWC) of its definition, for Hertz's pressure and series of several
// terms, zones inside the contact and near its edges, r on the zone, beside it, off it and at the edges.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/numerics/blended_cauchy.hpp"
#include "roughroll/numerics/quadrature.hpp"

using namespace roughroll;

namespace {
double theta_blend(double eta, double s, double c) {
    if (eta <= s) return 0.0;
    if (eta >= c) return 1.0;
    const double t = std::clamp((eta - s) / (0.5 * (c - s)) - 1.0, -1.0, 1.0);
    return 0.5 + M_1_PI * (std::asin(t) + t * std::sqrt(1.0 - t * t));
}

// (1/pi) PV int_s^1 p H/(eta - r) as (1/pi) [int_s^1 (g(eta) - g(r))/(eta - r) d eta + g(r) log((1 - r)/(r - s))],
// g = p H (g(r) = 0 for r outside (s, 1)), the bounded integrand by QAGS on the pieces between s, c, r and 1,
// each in u = sqrt(1 - eta) (the square root of p at eta = 1 made analytic).
double reference(const std::vector<double>& b, double s, double c, double r) {
    const std::function<double(double)> g = [&](double eta) {
        return std::sqrt((1.0 - eta) * (1.0 + eta)) * u_series(b, eta) * theta_blend(eta, s, c);
    };
    const bool inside = r > s && r < 1.0;
    const double gr = inside ? g(r) : 0.0;
    // In u, 1 - eta = u^2 exactly: p = u sqrt(2 - u^2) phi(1 - u^2), eta - r = (1 - r) - u^2, d eta = -2 u du.
    const std::function<double(double)> h_u = [&](double u) {
        const double eta = 1.0 - u * u, gap = (1.0 - r) - u * u;
        if (gap == 0.0) return 0.0;
        const double ge = u * std::sqrt(2.0 - u * u) * u_series(b, eta) * theta_blend(eta, s, c);
        return 2.0 * u * (ge - gr) / gap;
    };
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(2000);
    std::vector<double> ends{s, c, 1.0};
    if (inside && r != c) ends.push_back(r);
    std::sort(ends.begin(), ends.end());
    double total = inside ? gr * std::log((1.0 - r) / (r - s)) : 0.0;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        double result = 0.0, error = 0.0;
        gsl_function fn;
        fn.function = [](double x, void* q) { return (*static_cast<const std::function<double(double)>*>(q))(x); };
        fn.params = const_cast<std::function<double(double)>*>(&h_u);
        const int status = gsl_integration_qags(&fn, std::sqrt(1.0 - ends[i + 1]), std::sqrt(1.0 - ends[i]), 1e-15,
                                                1e-14, 2000, w, &result, &error);
        EXPECT_TRUE(status == GSL_SUCCESS || error < 1e-13) << "reference at r = " << r << ": " << error;
        total += result;
    }
    gsl_integration_workspace_free(w);
    return M_1_PI * total;
}
}  // namespace

TEST(BlendedCauchy, AgreesWithAdaptiveQuadratureOfTheDefinition) {
    gsl_set_error_handler_off();
    const std::vector<std::vector<double>> pressures{
        {M_2_PI},                                       // Hertz's, one term
        {M_2_PI, 0.01, -0.02, 0.004, 1e-3, -5e-4},      // a coupled pressure's first terms
        {0.5, 0.1, 0.05, -0.03, 0.02, 0.01, -0.005, 0.003, 2e-3, -1e-3, 5e-4, 1e-4}};
    const std::vector<std::pair<double, double>> zones{
        {-0.689, 0.495}, {0.838, 0.922}, {-0.99, 0.3}, {-0.2, 0.99}, {0.5, 0.999}, {-0.98, -0.5}};
    int compared = 0;
    for (const auto& b : pressures)
        for (const auto& [s, c] : zones) {
            const auto w = blended_cauchy::make(b, s, c);
            ASSERT_TRUE(w) << "zone [" << s << ", " << c << "]";
            const double rho = 0.5 * (c - s);
            std::vector<double> rs{-1.0, -0.999, s + 1e-7, s + 0.3 * rho, 0.5 * (s + c), c - 1e-3 * rho, 0.97, 1.0};
            if (c < 1.0) rs.push_back(c + 1e-6);
            if (s > -1.0) rs.push_back(s - 1e-6);
            for (const double r : rs) {
                if (r < -1.0 || r > 1.0 || r == s || r == c) continue;
                const auto value = (*w)(r);
                ASSERT_TRUE(value) << "r = " << r;
                EXPECT_NEAR(*value, reference(b, s, c, r), 1e-12) << "zone [" << s << ", " << c << "], r = " << r << ", b_0 = " << b[0] << ", terms " << b.size();
                ++compared;
            }
        }
    EXPECT_GT(compared, 100);
}

TEST(BlendedCauchy, DeclinesZonesAtAnEdgeAndOutside) {
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, -1.0 + 1e-9, 0.5));  // no rule of 1023 nodes converges
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, -0.2, 1.0));  // a zone at the edge: algebraic, not geometric
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, 0.5, 0.5));
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, -1.1, 0.5));
    const auto w = blended_cauchy::make({M_2_PI}, -0.5, 0.5);
    ASSERT_TRUE(w);
    EXPECT_FALSE((*w)(1.5));
}
