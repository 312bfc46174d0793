// SPDX-License-Identifier: GPL-3.0-or-later
// A dense square system A x = b solved by GSL's LU (gsl_linalg_LU_decomp/solve), with a
// singularity test: the reciprocal condition number of the U factor.
//
// solve_near() solves a matrix A close to the last one factorised, M (consecutive c0 of a curve
// swept in c0), with M as a preconditioner (docs/formulation.md, "Swept points refined on the
// previous factorisation"): GMRES (Saad, alg. 6.9) on M^{-1} A d = M^{-1} (b - A x), started at
// the combination of M^{-1} b and the last solutions with the least residual. A solution is kept
// only when the true residual's normwise backward error |b - A x|/(|A| |x| + |b|) (max norms) is
// at most 4 eps, the accuracy of the LU solution itself; otherwise A is factorised afresh: when
// a sample |G v| of G = I - M^{-1} A on a unit vector exceeds q = 1/2, or two cycles of
// krylov_dimension steps do not reach the test. With |G| <= q, A = M (I - G) and
// cond(A) <= cond(M) (1 + q)/(1 - q): the refined solve's reciprocal condition estimate is the
// factorisation's times (1 - q)/(1 + q), q the largest sample, refused below the threshold of a
// fresh factorisation (which then decides).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "roughroll/base/gsl_handles.hpp"

namespace roughroll {

class dense_system {
public:
    static constexpr int krylov_dimension = 8;  // GMRES steps per cycle
    static constexpr int max_cycles = 2;
    static constexpr int history_size = 3;  // last solutions kept for the refinement's start

    explicit dense_system(std::size_t size);

    // The matrix to assemble before each solve (its contents are not kept by a solve).
    gsl_matrix* matrix() {
        in_place_ = false;  // about to be assembled: the factors it holds are gone
        return a_.get();
    }
    gsl_vector* rhs() { return b_.get(); }
    void clear();  // A = 0 and b = 0, for a system assembled by adding terms

    // Factorises the matrix and solves; throws numerical_error naming `context` when GSL
    // fails or the system is singular to working precision.
    const gsl_vector* solve(const std::string& context);
    // The same solution to rounding, by refinement on the last factorisation when it
    // converges (above), else by solve().
    const gsl_vector* solve_near(const std::string& context);
    // The matrix of the last solve() again, with a new right side: its LU factors reused (two
    // triangular solves, no factorisation; the same solution and rcond as solve() would give).
    // Needs a last solve() whose factors nothing has overwritten since (no matrix() or clear(),
    // no solve_near()); else numerical_error.
    const gsl_vector* solve_factorised(const std::string& context);
    bool holds_factors() const { return in_place_; }  // solve_factorised() may be called

    // The a posteriori bound on the rounding of x_i of the last solve() or solve_factorised() (docs/formulation.md
    // 8(w), "The solve's rounding, a posteriori"): |x_i - x*_i| for x* the exact solution of the assembled system
    // with each entry of A and b perturbed by up to `entry_rounding` relative (the assembly's rounding), from the
    // residual in compensated arithmetic, one step of refinement through the same LU (dx) and the row i of A^{-1}
    // (a transposed solve): O(size^2), against the factorisation's O(size^3). Needs keep_matrix() before the
    // solve() and the factors held (holds_factors()); else numerical_error.
    double rounding_bound(std::size_t i, double entry_rounding);
    // From the next solve() on, a copy of the assembled matrix is kept for rounding_bound (size^2 doubles).
    void keep_matrix() { keep_ = true; }

    double rcond() const { return rcond_; }    // of the last solve (above)
    bool refined() const { return refined_; }  // whether the last solve was refined

private:
    bool refine(const std::string& context);
    void start(const std::string& context);
    void remember(const gsl_vector* x);
    void precondition(const gsl_vector* in, gsl_vector* out, const std::string& context);

    // solve_near's workspace, allocated by its first call (a system never refined, the
    // normal problems and the points at a given Q, keeps the size it had).
    struct refinement {
        explicit refinement(std::size_t size);
        matrix_ptr lu;                    // the last factorisation M (the matrix is assembled in a_)
        matrix_ptr inverse;               // M^{-1}, formed by the first refinement on a factorisation
        matrix_ptr basis;                 // GMRES's Krylov vectors, one per row
        matrix_ptr history;               // the last solutions, one per row
        matrix_ptr candidates, products;  // the start's candidates (rows) and A times them (columns)
        vector_ptr residual, scratch, tau, coefficients;
        int history_count = 0, history_next = 0;
        bool inverse_valid = false;
    };

    std::size_t size_;
    matrix_ptr a_;  // the matrix assembled, factorised in place by solve() unless refining
    vector_ptr b_, x_, work_;
    std::unique_ptr<refinement> near_;
    permutation_ptr perm_;
    double rcond_ = 0.0;         // of the last solve
    double factor_rcond_ = 0.0;  // of near_->lu's U
    bool factorised_ = false, refined_ = false;
    bool in_place_ = false;  // a_ holds the factors of the last solve() (for solve_factorised)
    bool keep_ = false;      // keep_matrix(): kept_ holds the matrix the factors in a_ are of
    matrix_ptr kept_;
};

}  // namespace roughroll
