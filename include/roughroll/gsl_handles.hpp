// RAII owners of GSL objects: std::unique_ptr with GSL's own _free functions.
#pragma once

#include <cstddef>
#include <memory>

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
};

using matrix_ptr = std::unique_ptr<gsl_matrix, gsl_deleter>;
using vector_ptr = std::unique_ptr<gsl_vector, gsl_deleter>;
using permutation_ptr = std::unique_ptr<gsl_permutation, gsl_deleter>;
using root_solver_ptr = std::unique_ptr<gsl_root_fsolver, gsl_deleter>;

// Allocators that throw numerical_error instead of returning null.
matrix_ptr make_matrix(std::size_t rows, std::size_t cols);
vector_ptr make_vector(std::size_t size);
permutation_ptr make_permutation(std::size_t size);

}  // namespace roughroll
