// SPDX-License-Identifier: GPL-3.0-or-later
// RAII owners of GSL objects: std::unique_ptr with GSL's own _free functions.
#pragma once

#include <cstddef>
#include <memory>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_vector.h>

namespace roughroll {

struct gsl_deleter {
    void operator()(gsl_matrix* m) const { gsl_matrix_free(m); }
    void operator()(gsl_vector* v) const { gsl_vector_free(v); }
    void operator()(gsl_permutation* p) const { gsl_permutation_free(p); }
    void operator()(gsl_root_fsolver* s) const { gsl_root_fsolver_free(s); }
    void operator()(gsl_interp* i) const { gsl_interp_free(i); }
    void operator()(gsl_interp_accel* a) const { gsl_interp_accel_free(a); }
    void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};

using matrix_ptr = std::unique_ptr<gsl_matrix, gsl_deleter>;
using vector_ptr = std::unique_ptr<gsl_vector, gsl_deleter>;
using permutation_ptr = std::unique_ptr<gsl_permutation, gsl_deleter>;
using root_solver_ptr = std::unique_ptr<gsl_root_fsolver, gsl_deleter>;

// The micro-geometry's (micro_geometry.cpp, roughness_parameters.cpp): the periodic spline of a
// measured profile, its lookup accelerator and the adaptive quadrature's workspace.
using interp_ptr = std::unique_ptr<gsl_interp, gsl_deleter>;
using interp_accel_ptr = std::unique_ptr<gsl_interp_accel, gsl_deleter>;
using integration_workspace_ptr = std::unique_ptr<gsl_integration_workspace, gsl_deleter>;

// Allocators that throw numerical_error instead of returning null. All of them are defined
// in error.cpp, the one file that allocates GSL objects.
matrix_ptr make_matrix(std::size_t rows, std::size_t cols);
vector_ptr make_vector(std::size_t size);
permutation_ptr make_permutation(std::size_t size);
interp_ptr make_interp(const gsl_interp_type* type, std::size_t size);
interp_accel_ptr make_interp_accel();
integration_workspace_ptr make_integration_workspace(std::size_t intervals);

}  // namespace roughroll
