// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/base/error.hpp"
#include "roughroll/base/gsl_handles.hpp"

#include <gsl/gsl_errno.h>

namespace roughroll {

void gsl_check(int status, const std::string& context) {
    if (status != GSL_SUCCESS) {
        throw numerical_error(context + ": " + gsl_strerror(status));
    }
}

void gsl_guard() {
    // A function-local static runs once and is thread-safe; it holds no state
    // of roughroll's own, only the fact that GSL's handler is off.
    static const bool off = [] {
        gsl_set_error_handler_off();
        return true;
    }();
    (void)off;
}

matrix_ptr make_matrix(std::size_t rows, std::size_t cols) {
    gsl_guard();
    matrix_ptr m(gsl_matrix_alloc(rows, cols));
    if (!m) throw numerical_error("cannot allocate a " + std::to_string(rows) + "x" + std::to_string(cols) + " matrix");
    return m;
}

vector_ptr make_vector(std::size_t size) {
    gsl_guard();
    vector_ptr v(gsl_vector_alloc(size));
    if (!v) throw numerical_error("cannot allocate a vector of " + std::to_string(size));
    return v;
}

permutation_ptr make_permutation(std::size_t size) {
    gsl_guard();
    permutation_ptr p(gsl_permutation_alloc(size));
    if (!p) throw numerical_error("cannot allocate a permutation of " + std::to_string(size));
    return p;
}

interp_ptr make_interp(const gsl_interp_type* type, std::size_t size) {
    gsl_guard();
    interp_ptr p(gsl_interp_alloc(type, size));
    if (!p)
        throw numerical_error("cannot allocate a " + std::string(type->name) + " spline of " + std::to_string(size) +
                              " points");
    return p;
}

interp_accel_ptr make_interp_accel() {
    gsl_guard();
    interp_accel_ptr p(gsl_interp_accel_alloc());
    if (!p) throw numerical_error("cannot allocate a spline accelerator");
    return p;
}

integration_workspace_ptr make_integration_workspace(std::size_t intervals) {
    gsl_guard();
    integration_workspace_ptr p(gsl_integration_workspace_alloc(intervals));
    if (!p)
        throw numerical_error("cannot allocate a quadrature workspace of " + std::to_string(intervals) + " intervals");
    return p;
}

}  // namespace roughroll
