#include "roughroll/numerics/linear_system.hpp"

#include <cmath>
#include <sstream>

#include <gsl/gsl_linalg.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

dense_system::dense_system(std::size_t size)
    : size_(size),
      a_(make_matrix(size, size)),
      b_(make_vector(size)),
      x_(make_vector(size)),
      work_(make_vector(3 * size)),
      perm_(make_permutation(size)) {}

const gsl_vector* dense_system::solve(const std::string& context) {
    int signum = 0;
    gsl_check(gsl_linalg_LU_decomp(a_.get(), perm_.get(), &signum), context + ": LU decomposition");
    gsl_check(gsl_linalg_tri_upper_rcond(a_.get(), &rcond_, work_.get()), context + ": condition estimate");
    if (!(rcond_ > 1e3 * GSL_DBL_EPSILON)) {
        std::ostringstream msg;
        msg << context << ": the linear system is singular to working precision (reciprocal condition "
            << rcond_ << ")";
        throw numerical_error(msg.str());
    }
    gsl_check(gsl_linalg_LU_solve(a_.get(), perm_.get(), b_.get(), x_.get()), context + ": LU solve");
    for (std::size_t i = 0; i < size_; ++i)
        if (!std::isfinite(gsl_vector_get(x_.get(), i)))
            throw numerical_error(context + ": the solution is not finite");
    return x_.get();
}

}  // namespace roughroll
