// SPDX-License-Identifier: GPL-3.0-or-later
// The pressure's kinks p_q^0 (docs/formulation.md 8(l) step 0, 8(o)): int_lo^hi p_q^0 (pressure_kinks::integral,
// the part of int_c^1 p that the blended zones' load and W take when p_q^0 is carried) against GSL's adaptive QAGP
// of p_q^0 itself, the zone ends as break points: a route that shares only the definition. (The driven three zones
// and five zones with p_q^0 were built and measured, 8(o), and are not carried: no test of them here.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>

#include "roughroll/problems/pressure_kinks.hpp"

using namespace roughroll;

namespace {
double qagp(const std::function<double(double)>& g, std::vector<double> points) {
    std::sort(points.begin(), points.end());
    gsl_function F{[](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
                   const_cast<std::function<double(double)>*>(&g)};
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(2000);
    double result = 0.0, error = 0.0;
    const int status = gsl_integration_qagp(&F, points.data(), points.size(), 1e-15, 1e-13, 2000, w, &result, &error);
    gsl_integration_workspace_free(w);
    EXPECT_TRUE(status == GSL_SUCCESS || (status == GSL_EROUND && error < 1e-13)) << error;
    return result;
}
}  // namespace

// Two stick zones with psi of a few terms (the entry condition psi(-1) = 0 is not needed for the identity).
TEST(PressureKinks, IntegralAgainstQagp) {
    const gauss_chebyshev rule(32);
    pressure_kinks k;
    k.add_zone(rule, 0.14, -1.0, -0.6, 0.45, {0.3, 0.2, -0.05, 0.01});
    k.add_zone(rule, 0.14, -1.0, 0.8, 0.93, {-0.02, 0.015, 0.004});
    const std::function<double(double)> p = [&](double r) { return k(r); };
    for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
             {-1.0, 1.0}, {0.45, 1.0}, {-1.0, -0.6}, {-0.3, 0.85}, {0.9, 0.99}, {0.93, 1.0}, {0.2, 0.2}}) {
        std::vector<double> points{lo, hi};
        for (const double e : k.ends())
            if (e > lo && e < hi) points.push_back(e);
        const double reference = hi > lo ? qagp(p, points) : 0.0;
        EXPECT_NEAR(k.integral(lo, hi), reference, 1e-14) << lo << " " << hi;
    }
    // The whole contact's integral is the load that the normal solve's load row takes off (pressure_kinks::load).
    EXPECT_NEAR(k.integral(-1.0, 1.0), k.load(), 1e-14);
    // factor() is p_q^0 without its sqrt(1 - r^2), as W's edge path uses it.
    for (const double r : {-0.99, -0.6, 0.0, 0.45, 0.86, 0.999999})
        EXPECT_NEAR(k.factor(r) * std::sqrt(1.0 - r * r), k(r), 1e-15) << r;
}
