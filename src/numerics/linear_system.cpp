// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/linear_system.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

namespace {
constexpr double singular_rcond = 1e3 * GSL_DBL_EPSILON;  // below: singular to working precision
constexpr double max_contraction = 0.5;                   // q of linear_system.hpp
constexpr double backward_error_bound = 4.0 * GSL_DBL_EPSILON;

void refuse_singular(const std::string& context, double rcond) {
    std::ostringstream msg;
    msg << context << ": the linear system is singular to working precision (reciprocal condition " << rcond << ")";
    throw numerical_error(msg.str());
}

void check_finite(const gsl_vector* x, const std::string& context) {
    for (std::size_t i = 0; i < x->size; ++i)
        if (!std::isfinite(gsl_vector_get(x, i))) throw numerical_error(context + ": the solution is not finite");
}

double max_norm(const gsl_vector* v) { return std::fabs(gsl_vector_get(v, gsl_blas_idamax(v))); }

// The infinity norm of a matrix: its largest absolute row sum.
double max_row_sum(const gsl_matrix* a) {
    double largest = 0.0;
    for (std::size_t i = 0; i < a->size1; ++i) {
        const gsl_vector_const_view row = gsl_matrix_const_row(a, i);
        largest = std::max(largest, gsl_blas_dasum(&row.vector));
    }
    return largest;
}
}  // namespace

void dense_system::clear() {
    in_place_ = false;
    gsl_matrix_set_zero(a_.get());
    gsl_vector_set_zero(b_.get());
}

dense_system::dense_system(std::size_t size)
    : size_(size),
      a_(make_matrix(size, size)),
      b_(make_vector(size)),
      x_(make_vector(size)),
      work_(make_vector(3 * size)),
      perm_(make_permutation(size)) {}

dense_system::refinement::refinement(std::size_t size)
    : lu(make_matrix(size, size)),
      inverse(make_matrix(size, size)),
      basis(make_matrix(krylov_dimension + 1, size)),
      history(make_matrix(history_size, size)),
      candidates(make_matrix(history_size + 1, size)),
      products(make_matrix(size, history_size + 1)),
      residual(make_vector(size)),
      scratch(make_vector(size)),
      tau(make_vector(history_size + 1)),
      coefficients(make_vector(history_size + 1)) {}

const gsl_vector* dense_system::solve(const std::string& context) {
    refined_ = false;
    factorised_ = false;
    in_place_ = false;
    int signum = 0;
    gsl_check(gsl_linalg_LU_decomp(a_.get(), perm_.get(), &signum), context + ": LU decomposition");
    // Refining: the factorisation kept as near_->lu, the next matrix assembled in the other buffer.
    if (near_) std::swap(a_, near_->lu);
    const gsl_matrix* lu = near_ ? near_->lu.get() : a_.get();
    gsl_check(gsl_linalg_tri_upper_rcond(lu, &rcond_, work_.get()), context + ": condition estimate");
    if (!(rcond_ > singular_rcond)) refuse_singular(context, rcond_);
    gsl_check(gsl_linalg_LU_solve(lu, perm_.get(), b_.get(), x_.get()), context + ": LU solve");
    check_finite(x_.get(), context);
    in_place_ = !near_;
    if (near_) {
        factor_rcond_ = rcond_;
        factorised_ = true;
        near_->inverse_valid = false;
        remember(x_.get());
    }
    return x_.get();
}

const gsl_vector* dense_system::solve_factorised(const std::string& context) {
    if (!in_place_) throw numerical_error(context + ": no factorisation of this matrix to reuse");
    refined_ = false;
    gsl_check(gsl_linalg_LU_solve(a_.get(), perm_.get(), b_.get(), x_.get()), context + ": LU solve");
    check_finite(x_.get(), context);
    return x_.get();
}

void dense_system::remember(const gsl_vector* x) {
    gsl_vector_view row = gsl_matrix_row(near_->history.get(), static_cast<std::size_t>(near_->history_next));
    gsl_vector_memcpy(&row.vector, x);
    near_->history_next = (near_->history_next + 1) % history_size;
    near_->history_count = std::min(near_->history_count + 1, history_size);
}

void dense_system::precondition(const gsl_vector* in, gsl_vector* out, const std::string& context) {
    // M^{-1} as a matrix, once per factorisation: one gemv per product instead of two triangular
    // solves (twice as fast with GSL's CBLAS at n = 129), over the many solves of a sweep.
    if (!near_->inverse_valid) {
        gsl_check(gsl_linalg_LU_invert(near_->lu.get(), perm_.get(), near_->inverse.get()),
                  context + ": inverse (refinement)");
        near_->inverse_valid = true;
    }
    gsl_check(gsl_blas_dgemv(CblasNoTrans, 1.0, near_->inverse.get(), in, 0.0, out), context + ": refinement product");
}

void dense_system::start(const std::string& context) {
    // x_0 = M^{-1} b, or the combination of it and the last solutions (the previous points of a
    // sweep) with the least residual |b - A x_0|_2: their polynomial extrapolation in c0, found
    // without knowing the c0 (a few gemv and a QR of n x 4, against GMRES steps saved).
    gsl_vector* x = x_.get();
    precondition(b_.get(), x, context);
    if (near_->history_count == 0) return;
    const std::size_t k = static_cast<std::size_t>(near_->history_count) + 1;
    gsl_matrix_view y = gsl_matrix_submatrix(near_->candidates.get(), 0, 0, k, size_);  // rows: candidates
    gsl_matrix_view w = gsl_matrix_submatrix(near_->products.get(), 0, 0, size_, k);    // columns: A y_i
    gsl_vector_view y0 = gsl_matrix_row(&y.matrix, 0);
    gsl_vector_memcpy(&y0.vector, x);
    gsl_matrix_const_view past = gsl_matrix_const_submatrix(near_->history.get(), 0, 0, k - 1, size_);
    gsl_matrix_view rest = gsl_matrix_submatrix(&y.matrix, 1, 0, k - 1, size_);
    gsl_matrix_memcpy(&rest.matrix, &past.matrix);
    gsl_check(gsl_blas_dgemm(CblasNoTrans, CblasTrans, 1.0, a_.get(), &y.matrix, 0.0, &w.matrix),
              context + ": refinement start");
    gsl_vector_view tau = gsl_vector_subvector(near_->tau.get(), 0, k);
    gsl_vector_view c = gsl_vector_subvector(near_->coefficients.get(), 0, k);
    // A rank-deficient set (a repeated c0) leaves x_0 = M^{-1} b.
    if (gsl_linalg_QR_decomp(&w.matrix, &tau.vector) != GSL_SUCCESS) return;
    for (std::size_t i = 0; i < k; ++i)
        if (!(std::fabs(gsl_matrix_get(&w.matrix, i, i)) > 1e3 * GSL_DBL_EPSILON * max_norm(b_.get()))) return;
    if (gsl_linalg_QR_lssolve(&w.matrix, &tau.vector, b_.get(), &c.vector, near_->residual.get()) != GSL_SUCCESS)
        return;
    gsl_check(gsl_blas_dgemv(CblasTrans, 1.0, &y.matrix, &c.vector, 0.0, x), context + ": refinement start");
}

const gsl_vector* dense_system::solve_near(const std::string& context) {
    if (!near_) {
        // The factorisation of the last solve() was overwritten by this matrix's assembly:
        // this one is factorised, and kept from here on.
        near_ = std::make_unique<refinement>(size_);
        factorised_ = false;
    }
    if (factorised_ && refine(context)) return x_.get();
    return solve(context);
}

bool dense_system::refine(const std::string& context) {
    gsl_vector* x = x_.get();
    gsl_vector* r = near_->residual.get();
    gsl_matrix* v = near_->basis.get();  // row j: the Krylov vector v_j of M^{-1} A
    start(context);
    const double a_norm = max_row_sum(a_.get());
    const double b_norm = max_norm(b_.get());
    double q = 0.0;  // the largest |G v_j| seen, |v_j| = 1
    std::vector<double> h((krylov_dimension + 1) * krylov_dimension), cs(krylov_dimension), sn(krylov_dimension),
        g(krylov_dimension + 1);
    auto H = [&](int i, int j) -> double& { return h[static_cast<std::size_t>(i * krylov_dimension + j)]; };
    for (int cycle = 0;; ++cycle) {
        gsl_check(gsl_vector_memcpy(r, b_.get()), context + ": refinement residual");
        gsl_check(gsl_blas_dgemv(CblasNoTrans, -1.0, a_.get(), x, 1.0, r), context + ": refinement residual");
        const double backward = max_norm(r) / (a_norm * max_norm(x) + b_norm);
        if (backward <= backward_error_bound) {
            // x solves A x = b to rounding, as the LU route's solution does (the test at which
            // LAPACK's dgerfs stops); q = 0 when x_0 already did (A = M to rounding).
            rcond_ = factor_rcond_ * (1.0 - q) / (1.0 + q);
            if (!(rcond_ > singular_rcond)) return false;  // decided by a fresh factorisation
            check_finite(x, context);
            remember(x);
            refined_ = true;
            return true;
        }
        if (cycle == max_cycles) return false;
        // GMRES on M^{-1} A d = M^{-1} r (Saad's algorithm 6.9, modified Gram-Schmidt, Givens
        // rotations), the correction d added to x.
        gsl_check(gsl_vector_memcpy(near_->scratch.get(), r), context + ": refinement residual");
        precondition(near_->scratch.get(), r, context);
        const double beta = gsl_blas_dnrm2(r);
        if (!(beta > 0.0) || !std::isfinite(beta)) return false;
        gsl_vector_view v0 = gsl_matrix_row(v, 0);
        gsl_check(gsl_vector_memcpy(&v0.vector, r), context + ": refinement basis");
        gsl_vector_scale(&v0.vector, 1.0 / beta);
        std::fill(g.begin(), g.end(), 0.0);
        g[0] = beta;
        const double target = GSL_DBL_EPSILON * gsl_blas_dnrm2(x);
        int used = 0;
        for (int j = 0; j < krylov_dimension; ++j) {
            gsl_vector_view vj = gsl_matrix_row(v, static_cast<std::size_t>(j));
            gsl_vector_view w = gsl_matrix_row(v, static_cast<std::size_t>(j + 1));
            gsl_check(gsl_blas_dgemv(CblasNoTrans, 1.0, a_.get(), &vj.vector, 0.0, near_->scratch.get()),
                      context + ": refinement product");
            precondition(near_->scratch.get(), &w.vector, context);
            // |G v_j| = |v_j - M^{-1} A v_j|, in r (free until the next cycle).
            gsl_check(gsl_vector_memcpy(r, &vj.vector), context + ": refinement contraction");
            gsl_check(gsl_vector_sub(r, &w.vector), context + ": refinement contraction");
            q = std::max(q, gsl_blas_dnrm2(r));
            if (!(q <= max_contraction)) return false;  // M is no near factorisation of A: factorise
            for (int i = 0; i <= j; ++i) {
                gsl_vector_view vi = gsl_matrix_row(v, static_cast<std::size_t>(i));
                gsl_check(gsl_blas_ddot(&w.vector, &vi.vector, &H(i, j)), context + ": refinement basis");
                gsl_check(gsl_blas_daxpy(-H(i, j), &vi.vector, &w.vector), context + ": refinement basis");
            }
            H(j + 1, j) = gsl_blas_dnrm2(&w.vector);
            for (int i = 0; i < j; ++i) {  // the previous rotations on column j
                const double t = cs[i] * H(i, j) + sn[i] * H(i + 1, j);
                H(i + 1, j) = -sn[i] * H(i, j) + cs[i] * H(i + 1, j);
                H(i, j) = t;
            }
            const double rho = std::hypot(H(j, j), H(j + 1, j));
            const double subdiagonal = H(j + 1, j);
            cs[j] = H(j, j) / rho;
            sn[j] = subdiagonal / rho;
            H(j, j) = rho;
            H(j + 1, j) = 0.0;
            g[j + 1] = -sn[j] * g[j];
            g[j] = cs[j] * g[j];
            used = j + 1;
            if (std::fabs(g[j + 1]) <= target || !(subdiagonal > 0.0)) break;  // converged (or exact)
            gsl_vector_scale(&w.vector, 1.0 / subdiagonal);
        }
        for (int i = used - 1; i >= 0; --i) {  // H y = g, y in g
            for (int k = i + 1; k < used; ++k) g[i] -= H(i, k) * g[k];
            g[i] /= H(i, i);
        }
        for (int i = 0; i < used; ++i) {
            gsl_vector_view vi = gsl_matrix_row(v, static_cast<std::size_t>(i));
            gsl_check(gsl_blas_daxpy(g[i], &vi.vector, x), context + ": refinement step");
        }
    }
}

}  // namespace roughroll
