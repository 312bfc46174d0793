// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/damped_newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

// |F|'s Euclidean norm, for the test of a kept Jacobian's step.
double norm_of(const std::vector<double>& F) {
    double sum = 0.0;
    for (const double v : F) sum += v * v;
    return std::sqrt(sum);
}
}  // namespace

newton_result damped_newton(const newton_problem& problem, std::vector<double> x, const newton_options& options,
                            newton_jacobian* kept) {
    const newton_result none{newton_stop::no_root, std::nullopt};
    const auto inside = [&](const std::vector<double>& y) { return !problem.inside || problem.inside(y); };
    const auto residual = [&](const std::vector<double>& y) {
        if (kept) ++kept->residuals;
        return problem.residual(y);
    };
    // No root: a kept Jacobian is not handed on (the next solve differences afresh).
    const auto fail = [&]() {
        if (kept) kept->J.clear();
        return none;
    };
    if (!inside(x)) return fail();
    auto F = residual(x);
    if (!F) return fail();
    const std::size_t k = x.size();
    // The Jacobian at x, column by column, by forward differences; empty where F is undefined at a difference point.
    const auto differences = [&]() -> std::optional<std::vector<std::vector<double>>> {
        std::vector<std::vector<double>> J(F->size(), std::vector<double>(k));
        for (std::size_t j = 0; j < k; ++j) {
            const double h = problem.difference_step(x, j);
            std::vector<double> y = x;
            y[j] += h;
            const auto Fy = residual(y);
            if (!Fy) return std::nullopt;
            for (std::size_t i = 0; i < F->size(); ++i) J[i][j] = ((*Fy)[i] - (*F)[i]) / h;
        }
        if (kept) ++kept->differenced;
        return J;
    };
    std::vector<std::vector<double>> J;
    // Whether J is a kept or updated one (Broyden's), not differenced at x: its step is only tried.
    bool updated = kept && kept->J.size() == F->size() && kept->J.front().size() == k;
    if (updated) J = kept->J;
    double last_full = -1.0;  // the size of the last step if it was a full one within F's rounding, else -1
    double last_size = -1.0;  // the size of the last full step (a kept Jacobian's contraction test), else -1
    for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
        std::optional<std::vector<double>> dx;
        double step = 1.0;
        std::vector<double> next(k);
        std::optional<std::vector<double>> F_next;
        bool taken = false;
        if (updated) {
            // The kept Jacobian's step, whole or not at all: it must land inside, with F defined there, and contract
            // (|F| halved, or a step at most half the last full one), or be one below the tolerance or F's rounding
            // after a full step of this solve (the stops below judge it as any full step: a Jacobian differenced there
            // would measure that rounding). A first step below the tolerance proves nothing: a kept J too large by a
            // factor s makes every step s times too short, and the stop would call the start a root (session 17
            // review F1); it is differenced at x instead, k residuals once per solve.
            dx = newton_step(J, *F);
            // The root before the step (docs/formulation.md 8(e), "The root before the last step"): after a full step
            // of this solve, a step of this Jacobian shorter than half the last one contracts by rho = size/last_size
            // <= 1/2, and the steps left sum to at most size/(1 - rho): within the tolerance, or within F's rounding
            // at x where that is at most rounding_cap tolerances (the rounding stop's root below, without its two
            // steps of rounding), x is the root to that resolution and the residual at x + dx (a five-zone system) is
            // not needed. The last residual was at x, so the caller's solution is x's and F's rounding is asked there.
            if (dx && last_size > 0.0) {
                const double size = problem.step_size(x, *dx);
                const double rho = size / last_size;
                const double floor =
                    problem.rounding ? std::max(options.tolerance, problem.rounding(x)) : options.tolerance;
                if (rho <= 0.5 && size / (1.0 - rho) <= floor && floor <= options.rounding_cap * options.tolerance) {
                    kept->J = J;
                    return {newton_stop::root, newton_root{x, iteration - 1, floor}};
                }
            }
            if (dx) {
                for (std::size_t j = 0; j < k; ++j) next[j] = x[j] + (*dx)[j];
                if (inside(next) && (F_next = residual(next))) {
                    const double size = problem.step_size(next, *dx);
                    const double floor = problem.rounding ? std::max(options.tolerance, problem.rounding(next))
                                                          : options.tolerance;
                    taken = (size <= floor && last_size > 0.0) || norm_of(*F_next) <= 0.5 * norm_of(*F) ||
                            (last_size > 0.0 && size <= 0.5 * last_size);
                }
            }
            updated = taken;
        }
        if (!taken) {
            auto differenced = differences();
            if (!differenced) return fail();
            J = std::move(*differenced);
            dx = newton_step(J, *F);
            if (!dx) return fail();
            // Damping: halve the step until it lands inside and F is defined there.
            for (;;) {
                for (std::size_t j = 0; j < k; ++j) next[j] = x[j] + step * (*dx)[j];
                if (inside(next) && (F_next = residual(next))) break;
                step *= 0.5;
                if (step < options.min_step) return fail();
            }
        }
        if (kept) {
            // Broyden's update along the step taken, J += (dF - J s) s^T / (s^T s), where the step's longest component
            // reaches the shortest difference step: a step shorter than every difference step measures F's rounding,
            // not its slope, and would spoil J.
            std::vector<double> s(k);
            double ss = 0.0, longest = 0.0, shortest_h = std::numeric_limits<double>::infinity();
            for (std::size_t j = 0; j < k; ++j) {
                s[j] = step * (*dx)[j];
                ss += s[j] * s[j];
                longest = std::max(longest, std::fabs(s[j]));
                shortest_h = std::min(shortest_h, std::fabs(problem.difference_step(next, j)));
            }
            if (ss > 0.0 && longest >= shortest_h) {
                for (std::size_t i = 0; i < F->size(); ++i) {
                    double r = (*F_next)[i] - (*F)[i];
                    for (std::size_t j = 0; j < k; ++j) r -= J[i][j] * s[j];
                    for (std::size_t j = 0; j < k; ++j) J[i][j] += r * s[j] / ss;
                }
            }
            updated = true;
        }
        x = next;
        F = F_next;
        const double size = step == 1.0 ? problem.step_size(x, *dx) : -1.0;
        last_size = size;
        if (step == 1.0 && size <= options.tolerance) {
            if (kept) kept->J = J;
            return {newton_stop::root, newton_root{x, iteration, options.tolerance}};
        }
        // At the rounding floor: two full steps within F's rounding at x, the second not contracting. Within the cap
        // a root to that rounding; beyond it the stop is the limit F's rounding sets, reported as such (the steps
        // that follow are that rounding's: one below the tolerance would be chance).
        const double rounding = step == 1.0 && problem.rounding ? problem.rounding(x) : -1.0;
        const bool rounded = step == 1.0 && size <= rounding;
        if (rounded && last_full >= 0.0 && size >= last_full) {
            if (rounding <= options.rounding_cap * options.tolerance) {
                if (kept) kept->J = J;
                return {newton_stop::root, newton_root{x, iteration, rounding}};
            }
            if (kept) kept->J.clear();
            return {newton_stop::rounding_limit, std::nullopt, rounding};
        }
        last_full = rounded ? size : -1.0;
    }
    return fail();
}

}  // namespace roughroll
