// SPDX-License-Identifier: GPL-3.0-or-later
// QUADPACK's routes to the Hilbert transform and the integral of a function that is smooth between given cuts (the
// plateau's ramps, a stick zone's ends): the references tests/test_weighted_pressure.cpp (8(w)) and
// validation/test_five_zones_weighted_s20.cpp (8(x)) check the weighted pressure against. They share nothing with the
// solver but the definitions. Header-only, for tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "quadpack_common.hpp"

namespace hilbert_on_pieces {

using quadpack_common::function_of;
using quadpack_common::integrand;

// 4000 subintervals.
struct workspace : quadpack_common::interval_workspace {
    workspace() : interval_workspace(4000) {}
};

// QUADPACK's status: a round-off stop is accepted where its own error estimate is below 1e-12, anything else fails
// the calling test.
inline void expect_converged(int status, double err) {
    EXPECT_TRUE(status == GSL_SUCCESS || (status == GSL_EROUND && err < 1e-12)) << status << " " << err;
}

// (1/pi) PV int_{-1}^{1} g(eta)/(eta - r) d eta, g smooth between `cuts`: QAWC on [r - d, r + d], QAGS elsewhere.
inline double hilbert(const integrand& g, double r, std::vector<double> cuts) {
    workspace ws;
    double d = 0.5 * std::min(1.0 - std::fabs(r), 0.1);
    for (const double c : cuts) d = std::min(d, 0.5 * std::fabs(c - r));
    std::vector<double> pts{-1.0, 1.0, r - d, r + d};
    for (const double c : cuts) pts.push_back(c);
    std::sort(pts.begin(), pts.end());
    double sum = 0.0, err = 0.0;
    const integrand h = [&](double eta) { return g(eta) / (eta - r); };
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const double lo = pts[i], hi = pts[i + 1];
        if (!(hi > lo)) continue;
        double v = 0.0;
        if (lo == r - d && hi == r + d) {
            gsl_function F = function_of(g);
            expect_converged(gsl_integration_qawc(&F, lo, hi, r, 1e-15, 1e-13, ws.limit, ws.w, &v, &err), err);
        } else {
            gsl_function F = function_of(h);
            expect_converged(gsl_integration_qags(&F, lo, hi, 1e-15, 1e-13, ws.limit, ws.w, &v, &err), err);
        }
        sum += v;
    }
    return sum * M_1_PI;
}

// int_{-1}^{1} g, g smooth between `cuts`: QAGS on each piece.
inline double integral(const integrand& g, std::vector<double> cuts) {
    workspace ws;
    cuts.push_back(-1.0);
    cuts.push_back(1.0);
    std::sort(cuts.begin(), cuts.end());
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        double v = 0.0, err = 0.0;
        gsl_function F = function_of(g);
        expect_converged(gsl_integration_qags(&F, cuts[i], cuts[i + 1], 1e-15, 1e-14, ws.limit, ws.w, &v, &err), err);
        sum += v;
    }
    return sum;
}

// int_s^c g on `parts` pieces graded to both ends by the cosine map (a stick zone's square-root ends, where the blend
// and the pressure bend): QAGS at 1e-13 relative on each piece; the sum and the sum of QUADPACK's estimates.
struct graded_integral {
    double value = 0.0;
    double estimate = 0.0;
};
inline graded_integral integral_graded(const integrand& g, double s, double c, int parts) {
    workspace ws;
    std::vector<double> cuts{s};
    for (int j = 1; j < parts; ++j) cuts.push_back(s + (c - s) * (0.5 - 0.5 * std::cos(M_PI * j / parts)));
    cuts.push_back(c);
    graded_integral total;
    gsl_function F = function_of(g);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        double v = 0.0, err = 0.0;
        expect_converged(gsl_integration_qags(&F, cuts[i], cuts[i + 1], 1e-17, 1e-13, ws.limit, ws.w, &v, &err), err);
        total.value += v;
        total.estimate += err;
    }
    return total;
}

}  // namespace hilbert_on_pieces
