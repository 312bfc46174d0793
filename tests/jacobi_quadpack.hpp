// SPDX-License-Identifier: GPL-3.0-or-later
// QUADPACK's routes to the Cauchy transforms of a Jacobi weight w(t) = (1 - t)^a (1 + t)^b times a smooth function:
// the references tests/test_jacobi_weights.cpp (8(v)) and tests/test_jacobi_cauchy.cpp (8(y)) check the Gauss-Jacobi
// collocation against (they share nothing with it but the definition). Header-only, for tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "quadpack_common.hpp"

namespace jacobi_quadpack {
using namespace roughroll;

using quadpack_common::function_of;
using quadpack_common::integrand;

// 2000 subintervals, and QAWS's table of the end powers.
struct workspace : quadpack_common::interval_workspace {
    gsl_integration_qaws_table* const t = gsl_integration_qaws_table_alloc(0.0, 0.0, 0, 0);
    workspace() : interval_workspace(2000) {}
    ~workspace() { gsl_integration_qaws_table_free(t); }
};

// QUADPACK's status: a round-off stop is accepted where its own error estimate is at rounding (below 1e-15 of
// the value, or absolute 1e-16), anything else throws.
inline void accept(int status, double value, double error, const char* what) {
    if (status == GSL_EROUND && error <= std::max(1e-16, 1e-15 * std::fabs(value))) return;
    gsl_check(status, what);
}

// int_lo^hi (x - lo)^alpha (hi - x)^beta g(x) dx by QAWS.
inline double qaws(const integrand& g, double lo, double hi, double alpha, double beta) {
    gsl_guard();
    workspace ws;
    gsl_check(gsl_integration_qaws_table_set(ws.t, alpha, beta, 0, 0), "qaws table");
    gsl_function F = function_of(g);
    double r = 0.0, e = 0.0;
    accept(gsl_integration_qaws(&F, lo, hi, ws.t, 0.0, 1.2e-14, ws.limit, ws.w, &r, &e), r, e, "qaws");
    return r;
}

// (1/pi) PV int_{-1}^{1} w(tau) chi(tau)/(tau - x) d tau, |x| < 1: QAWS on [-1, l] and [u, 1] (the end powers as
// QAWS's weight), QAWC on [l, u] around x, l = (x - 1)/2, u = (x + 1)/2.
inline double hilbert(const integrand& chi, double a, double b, double x) {
    gsl_guard();
    const double l = 0.5 * (x - 1.0), u = 0.5 * (x + 1.0);
    const double left = qaws([&](double t) { return std::pow(1.0 - t, a) * chi(t) / (t - x); }, -1.0, l, b, 0.0);
    const double right = qaws([&](double t) { return std::pow(1.0 + t, b) * chi(t) / (t - x); }, u, 1.0, 0.0, a);
    workspace ws;
    const integrand g = [&](double t) { return jacobi_weight(a, b, t) * chi(t); };
    gsl_function F = function_of(g);
    double mid = 0.0, e = 0.0;
    accept(gsl_integration_qawc(&F, l, u, x, 0.0, 1.2e-14, ws.limit, ws.w, &mid, &e), mid, e, "qawc");
    return M_1_PI * (left + mid + right);
}

// The model problems' dense system A x = F by LU (A is overwritten); x as a vector.
inline std::vector<double> lu_solved(gsl_matrix* A, const gsl_vector* F) {
    gsl_vector* x = gsl_vector_alloc(F->size);
    gsl_permutation* perm = gsl_permutation_alloc(F->size);
    int sign = 0;
    gsl_check(gsl_linalg_LU_decomp(A, perm, &sign), "LU");
    gsl_check(gsl_linalg_LU_solve(A, perm, F, x), "LU solve");
    std::vector<double> out(x->data, x->data + x->size);
    gsl_permutation_free(perm);
    gsl_vector_free(x);
    return out;
}
}  // namespace jacobi_quadpack
