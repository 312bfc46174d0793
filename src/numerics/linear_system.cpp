// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/linear_system.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_permute_vector.h>

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
    if (keep_) {
        if (!kept_) kept_ = make_matrix(size_, size_);
        gsl_matrix_memcpy(kept_.get(), a_.get());
    }
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

double dense_system::rounding_bound(std::size_t i, double entry_rounding) {
    // docs/formulation.md 8(w), "The solve's rounding, a posteriori". x the computed solution, r = b - A x exactly,
    // so x - x* = -A^{-1} r. r^ is r by compensated dot products (Dot2 of Ogita, Rump and Oishi 2005: each product
    // split exactly by Dekker's TwoProduct, the sums' errors gathered by TwoSum), |r^ - r| <= u |r| + gamma_m^2 (|A||x|
    // + |b|), m = size + 1 terms (2 u |r^| below covers u |r|). dx solves (A + dA) dx = r^ through the LU, |dA| <=
    // gamma_3n |L||U| (Higham, Accuracy and Stability, Thm 9.4), so A^{-1} r^ = dx + A^{-1} dA dx: one step of
    // refinement, whose correction dx is the error of x to first order (Higham ch. 12). With y = A^{-T} e_i (row i
    // of A^{-1}), exactly:
    //   |x_i - x*_i| <= |dx_i| + |y|^T (gamma_3n |L||U||dx| + 2 u |r^| + gamma_m^2 (|A||x| + |b|)),
    // and the assembly's rounding (each entry of A and b within entry_rounding relative) moves x* by at most
    // |y|^T entry_rounding (|A||x| + |b|) to first order. y is computed by the same LU, relative error about
    // gamma_3n kappa, under 1/4 where used (else the a priori 2 u |x_i| / rcond is returned): the sum over |y| is
    // doubled for it and the second-order terms.
    if (!keep_ || !kept_ || !in_place_)
        throw numerical_error("dense system: a rounding bound without the kept matrix and its factors");
    const std::size_t n = size_;
    const double u = 0.5 * GSL_DBL_EPSILON;
    const double gamma_3n = 3.0 * n * u / (1.0 - 3.0 * n * u), gamma_m = (n + 1) * u / (1.0 - (n + 1) * u);
    const double x_i = gsl_vector_get(x_.get(), i);
    const double a_priori = 2.0 * GSL_DBL_EPSILON * std::fabs(x_i) / rcond_;
    if (!(gamma_3n / rcond_ < 0.25)) return a_priori;
    const gsl_matrix* a = kept_.get();
    const gsl_matrix* lu = a_.get();
    const vector_ptr r = make_vector(n), dx = make_vector(n), y = make_vector(n);
    // TwoProduct, p + pe = a_kj x_j exactly: by an fma where the target has one (there the compiler may contract
    // Dekker's splitting into fmas, which breaks its exactness), else by Dekker's splitting with x_j split once into
    // halves of 26 bits (Veltkamp), without the fma's library call (ten times the cost).
    constexpr double splitter = 134217729.0;  // 2^27 + 1
    const auto split = [](double v, double& hi, double& lo) {
        const double c = splitter * v;
        hi = c - (c - v);
        lo = v - hi;
    };
#if defined(FP_FAST_FMA) || defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    const auto two_product = [](double a, double b, double, double, double& p) {
        p = a * b;
        return std::fma(a, b, -p);
    };
#else
    const auto two_product = [&split](double a, double b, double bh, double bl, double& p) {
        double ah, al;
        split(a, ah, al);
        p = a * b;
        return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    };
#endif
    std::vector<double> x(n), xh(n), xl(n), size_of(n);  // size_of: |A||x| + |b|
    for (std::size_t j = 0; j < n; ++j) {
        x[j] = gsl_vector_get(x_.get(), j);
        split(x[j], xh[j], xl[j]);  // once per x_j (used by the splitting's TwoProduct only)
    }
    for (std::size_t k = 0; k < n; ++k) {
        const double* row = a->data + k * a->tda;
        double s = gsl_vector_get(b_.get(), k), c = 0.0, g = std::fabs(s);
        for (std::size_t j = 0; j < n; ++j) {
            double p;
            const double pe = two_product(-row[j], x[j], xh[j], xl[j], p);
            const double t = s + p, z = t - s, se = (s - (t - z)) + (p - z);  // TwoSum: t + se = s + p
            s = t;
            c += se + pe;
            g += std::fabs(p);
        }
        gsl_vector_set(r.get(), k, s + c);
        size_of[k] = g * (1.0 + gamma_m);  // |A||x| + |b| from rounded terms: at most that factor below
    }
    gsl_check(gsl_linalg_LU_solve(lu, perm_.get(), r.get(), dx.get()), "rounding bound: refinement step");
    // y = A^{-T} e_i: P A = L U, so A^T = U^T L^T P: U^T z = e_i, L^T v = z, y = P^T v.
    // The factors' backward error dA' is of P A (row k of L U is row perm[k] of A): A^{-1} P^T dA' dx, so its term pairs
    // with |P y| = |v| in the factors' row order; the residual's terms with |y| in A's.
    gsl_vector_set_basis(y.get(), i);
    gsl_check(gsl_blas_dtrsv(CblasUpper, CblasTrans, CblasNonUnit, lu, y.get()), "rounding bound: row of the inverse");
    gsl_check(gsl_blas_dtrsv(CblasLower, CblasTrans, CblasUnit, lu, y.get()), "rounding bound: row of the inverse");
    std::vector<double> v(y->data, y->data + n);  // y is contiguous (make_vector)
    gsl_check(gsl_permute_vector_inverse(perm_.get(), y.get()), "rounding bound: row of the inverse");
    // |L||U||dx|: |U||dx| first (upper, its diagonal), then |L| (unit lower) on it.
    std::vector<double> t(n), lut(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double* row = lu->data + k * lu->tda;
        double s = 0.0;
        for (std::size_t j = k; j < n; ++j) s += std::fabs(row[j] * dx->data[j * dx->stride]);
        t[k] = s;
    }
    for (std::size_t k = 0; k < n; ++k) {
        const double* row = lu->data + k * lu->tda;
        double s = t[k];
        for (std::size_t j = 0; j < k; ++j) s += std::fabs(row[j]) * t[j];
        lut[k] = s;
    }
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k)
        sum += std::fabs(v[k]) * gamma_3n * lut[k] +
               std::fabs(gsl_vector_get(y.get(), k)) * (2.0 * u * std::fabs(gsl_vector_get(r.get(), k)) +
                                                        (gamma_m * gamma_m + entry_rounding) * size_of[k]);
    const double bound = std::fabs(gsl_vector_get(dx.get(), i)) + 2.0 * sum;
    return std::isfinite(bound) ? bound : a_priori;
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
