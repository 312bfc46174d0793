// SPDX-License-Identifier: GPL-3.0-or-later
// The reference of the rough rollers' layer tables (cut_convolution, docs/formulation.md 8(o)): their definition by
// GSL's adaptive quadrature, for tests/test_rough_step0_s19.cpp (the braked zone) and tests/test_rough_blend_s20.cpp
// (the driven zone's blend).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/model/kernel.hpp"

namespace roughroll_test {

// int_{-1}^{1} g(eta) K(eta - r) d eta by GSL's adaptive rules on each piece [a, b] between -1, the cuts, r and 1 (g's
// one-sided roots and the kernel's jump at piece ends): QAGS in eta (its extrapolation takes a root at or just beyond
// the piece's end, r within 1e-9 of a cut), QAGS and QAG's 61-point rule in eta = (a + b)/2 - (b - a)/2 cos u (the roots
// at the ends smooth in u; QAGS in eta met GSL's round-off at n = 256, 5.6e-10, next to a zone end), in this order, the
// first that succeeds. (QAG in u alone was 8e-13 off at r = a + 1e-8 in tests/test_rough_step0_s19.cpp: mpmath's value of that convolution,
// 0.282707502397335935, is the table's to 2e-16.)
inline double convolution_by_qags(const std::function<double(double)>& g, const roughroll::kernel& k, double r, std::vector<double> cuts) {
    cuts.push_back(-1.0);
    cuts.push_back(1.0);
    cuts.push_back(r);
    std::sort(cuts.begin(), cuts.end());
    double mid = 0.0, half = 0.0;
    const std::function<double(double)> in_eta = [&](double eta) { return eta == r ? 0.0 : g(eta) * k(eta - r); };
    const std::function<double(double)> in_u = [&](double u) { return in_eta(mid - half * std::cos(u)) * half * std::sin(u); };
    const auto call = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
    gsl_function E{call, const_cast<std::function<double(double)>*>(&in_eta)};
    gsl_function U{call, const_cast<std::function<double(double)>*>(&in_u)};
    gsl_set_error_handler_off();  // a failed rule returns its status to the fallbacks below, not through abort()
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(4000);
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        if (!(cuts[i + 1] > cuts[i])) continue;
        mid = 0.5 * (cuts[i] + cuts[i + 1]);
        half = 0.5 * (cuts[i + 1] - cuts[i]);
        double result = 0.0, error = 0.0;
        // A rule that stops at GSL's round-off (GSL_EROUND) with its error estimate below 1e-14 has met what the
        // comparison needs (1e-12) and is taken too.
        const auto met = [&](int status) { return status == GSL_SUCCESS || (status == GSL_EROUND && error < 1e-14); };
        int status = gsl_integration_qags(&E, cuts[i], cuts[i + 1], 1e-15, 1e-13, 4000, w, &result, &error);
        if (!met(status)) status = gsl_integration_qags(&U, 0.0, M_PI, 1e-15, 1e-13, 4000, w, &result, &error);
        if (!met(status))
            status = gsl_integration_qag(&U, 0.0, M_PI, 1e-15, 1e-13, 4000, GSL_INTEG_GAUSS61, w, &result, &error);
        EXPECT_TRUE(met(status)) << cuts[i] << " " << cuts[i + 1] << " " << status << " " << error;
        sum += result;
    }
    gsl_integration_workspace_free(w);
    return sum;
}

}  // namespace roughroll_test
