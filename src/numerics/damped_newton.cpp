// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/damped_newton.hpp"

#include <cmath>

#include <gsl/gsl_linalg.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/gsl_handles.hpp"

namespace roughroll {

namespace {
// The Newton step dx of J dx = -F by GSL's LU; empty when J is singular (a zero pivot, as the
// zero determinant the 2 x 2 searches tested before) or anything is not finite.
std::optional<std::vector<double>> newton_step(const std::vector<std::vector<double>>& J,
                                               const std::vector<double>& F) {
    const std::size_t k = F.size();
    matrix_ptr a = make_matrix(k, k);
    vector_ptr b = make_vector(k), x = make_vector(k);
    permutation_ptr perm = make_permutation(k);
    for (std::size_t i = 0; i < k; ++i) {
        if (!std::isfinite(F[i])) return std::nullopt;
        gsl_vector_set(b.get(), i, -F[i]);
        for (std::size_t j = 0; j < k; ++j) {
            if (!std::isfinite(J[i][j])) return std::nullopt;
            gsl_matrix_set(a.get(), i, j, J[i][j]);
        }
    }
    int signum = 0;
    gsl_check(gsl_linalg_LU_decomp(a.get(), perm.get(), &signum), "damped Newton: LU decomposition");
    for (std::size_t i = 0; i < k; ++i)
        if (!(gsl_matrix_get(a.get(), i, i) != 0.0)) return std::nullopt;
    gsl_check(gsl_linalg_LU_solve(a.get(), perm.get(), b.get(), x.get()), "damped Newton: LU solve");
    std::vector<double> dx(k);
    for (std::size_t i = 0; i < k; ++i) {
        dx[i] = gsl_vector_get(x.get(), i);
        if (!std::isfinite(dx[i])) return std::nullopt;
    }
    return dx;
}
}  // namespace

newton_result damped_newton(const newton_problem& problem, std::vector<double> x, const newton_options& options) {
    const newton_result none{newton_stop::no_root, std::nullopt};
    const auto inside = [&](const std::vector<double>& y) { return !problem.inside || problem.inside(y); };
    if (!inside(x)) return none;
    auto F = problem.residual(x);
    if (!F) return none;
    const std::size_t k = x.size();
    double last_full = -1.0;  // the size of the last step if it was a full one within F's rounding, else -1
    for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
        // The Jacobian column by column, by forward differences.
        std::vector<std::vector<double>> J(F->size(), std::vector<double>(k));
        for (std::size_t j = 0; j < k; ++j) {
            const double h = problem.difference_step(x, j);
            std::vector<double> y = x;
            y[j] += h;
            const auto Fy = problem.residual(y);
            if (!Fy) return none;
            for (std::size_t i = 0; i < F->size(); ++i) J[i][j] = ((*Fy)[i] - (*F)[i]) / h;
        }
        const auto dx = newton_step(J, *F);
        if (!dx) return none;
        // Damping: halve the step until it lands inside and F is defined there.
        double step = 1.0;
        std::vector<double> next(k);
        std::optional<std::vector<double>> F_next;
        for (;;) {
            for (std::size_t j = 0; j < k; ++j) next[j] = x[j] + step * (*dx)[j];
            if (inside(next) && (F_next = problem.residual(next))) break;
            step *= 0.5;
            if (step < options.min_step) return none;
        }
        x = next;
        F = F_next;
        const double size = step == 1.0 ? problem.step_size(x, *dx) : -1.0;
        if (step == 1.0 && size <= options.tolerance)
            return {newton_stop::root, newton_root{x, iteration, options.tolerance}};
        // At the rounding floor: two full steps within F's rounding at x, the second not contracting. Within the cap
        // a root to that rounding; beyond it the stop is the limit F's rounding sets, reported as such (the steps
        // that follow are that rounding's: one below the tolerance would be chance).
        const double rounding = step == 1.0 && problem.rounding ? problem.rounding(x) : -1.0;
        const bool rounded = step == 1.0 && size <= rounding;
        if (rounded && last_full >= 0.0 && size >= last_full) {
            if (rounding <= options.rounding_cap * options.tolerance)
                return {newton_stop::root, newton_root{x, iteration, rounding}};
            return {newton_stop::rounding_limit, std::nullopt, rounding};
        }
        last_full = rounded ? size : -1.0;
    }
    return none;
}

}  // namespace roughroll
