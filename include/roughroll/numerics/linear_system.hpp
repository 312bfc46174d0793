// A dense square system solved by GSL's LU (gsl_linalg_LU_decomp/solve), with a
// singularity test: the reciprocal condition number of the U factor.
#pragma once

#include <cstddef>
#include <string>

#include "roughroll/base/gsl_handles.hpp"

namespace roughroll {

class dense_system {
public:
    explicit dense_system(std::size_t size);

    gsl_matrix* matrix() { return a_.get(); }
    gsl_vector* rhs() { return b_.get(); }

    // Factorises the matrix in place and solves; throws numerical_error naming
    // `context` when GSL fails or the system is singular to working precision.
    const gsl_vector* solve(const std::string& context);

    double rcond() const { return rcond_; }  // of the last factorisation's U

private:
    std::size_t size_;
    matrix_ptr a_;
    vector_ptr b_, x_, work_;
    permutation_ptr perm_;
    double rcond_ = 0.0;
};

}  // namespace roughroll
