// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/root_search.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/gsl_handles.hpp"

namespace roughroll {

namespace {
struct brent_context {
    const std::function<double(double)>& f;
    std::exception_ptr failure;
};

// GSL calls this through C frames: no exception may cross them, so a failure is
// stored and reported as NaN, which stops the iteration with GSL_EBADFUNC.
double call(double x, void* params) {
    auto* ctx = static_cast<brent_context*>(params);
    try {
        return ctx->f(x);
    } catch (...) {
        ctx->failure = std::current_exception();
        return std::numeric_limits<double>::quiet_NaN();
    }
}
}  // namespace

root brent_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel,
                int max_iterations, const std::string& what) {
    brent_context ctx{f, nullptr};
    gsl_function fn{&call, &ctx};
    gsl_guard();
    root_solver_ptr brent(gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
    if (!brent) throw numerical_error(what + ": cannot allocate the Brent root solver");
    const int set = gsl_root_fsolver_set(brent.get(), &fn, lo, hi);
    if (ctx.failure) std::rethrow_exception(ctx.failure);
    gsl_check(set, what + ": bracket");
    int status = GSL_CONTINUE;
    int iter = 0;
    while (status == GSL_CONTINUE && iter < max_iterations) {
        ++iter;
        status = gsl_root_fsolver_iterate(brent.get());
        if (ctx.failure) std::rethrow_exception(ctx.failure);
        gsl_check(status, what);
        status = gsl_root_test_interval(gsl_root_fsolver_x_lower(brent.get()), gsl_root_fsolver_x_upper(brent.get()),
                                        epsabs, epsrel);
    }
    if (status != GSL_SUCCESS)
        throw numerical_error(what + " did not converge in " + std::to_string(iter) + " iterations");
    return {gsl_root_fsolver_root(brent.get()), iter, std::numeric_limits<double>::quiet_NaN()};
}

namespace {
// The secant iteration on f(c) = load(c) - target from x0, x1, kept inside [-1, 1]: converges
// superlinearly from a start close to the root (the coarse level's root, or Carter's c0);
// empty when it leaves [-1, 1], stalls, or exceeds its iterations (the caller then brackets).
// Stops when the next step is below `tolerance`, returning the last point evaluated (whose
// solution the caller keeps), within `tolerance` of the secant's root.
std::optional<root> secant(const std::function<double(double)>& f, double x0, double x1, double tolerance,
                           int max_iterations, std::optional<double> slope = std::nullopt) {
    double f0 = f(x0);
    if (slope && std::isfinite(*slope) && *slope < 0.0) {
        // A Newton step with the slope of the level below (accurate to its discretisation
        // error): from a start within ~1e-8 of the root it lands within ~1e-16.
        const double x = x0 - f0 / *slope;
        if (x >= -1.0 && x <= 1.0 && x != x0) x1 = x;
    }
    double f1 = f(x1);
    for (int it = 1; it <= max_iterations; ++it) {
        if (!(std::isfinite(f0) && std::isfinite(f1)) || f1 == f0) return std::nullopt;
        // Q(c0) decreases from f at c0 = -1 to 0 at c0 = 1: a secant slope >= 0 is a
        // discretisation that does not resolve the scene (or a wrong branch); Brent decides.
        const double secant_slope = (f1 - f0) / (x1 - x0);
        if (!(secant_slope < 0.0)) return std::nullopt;
        if (f1 == 0.0) return root{x1, it, secant_slope};
        const double x2 = x1 - f1 / secant_slope;
        if (!(x2 >= -1.0 && x2 <= 1.0)) return std::nullopt;
        if (std::fabs(x2 - x1) <= tolerance) return root{x1, it, secant_slope};
        x0 = x1;
        f0 = f1;
        x1 = x2;
        f1 = f(x1);
    }
    return std::nullopt;
}
}  // namespace

root stick_end_for_load(const std::function<double(double)>& load, double target, std::optional<double> guess,
                        const std::string& what, const std::function<void()>& before_full_range,
                        std::optional<double> start, std::optional<double> slope) {
    constexpr int max_iterations = 200;
    constexpr double tolerance = 1e-15;
    const auto residual = [&](double c0) { return load(c0) - target; };
    if (guess && *guess > -1.0 && *guess < 1.0) {
        // Secant from the guess (a root within the coarse level's error, ~1e-8): two or three loads.
        const double step = *guess > 0.0 ? -1e-7 : 1e-7;
        if (const auto r = secant(residual, *guess, *guess + step, tolerance, 8, slope)) return *r;
    }
    if (before_full_range) before_full_range();
    if (start && *start > -1.0 && *start < 1.0) {
        // Secant from a rough start (Carter's c0): a few loads where Q(c0) is smooth.
        const double step = *start > 0.0 ? -1e-3 : 1e-3;
        if (const auto r = secant(residual, *start, *start + step, tolerance, 12)) return *r;
    }
    return brent_root(residual, -1.0, 1.0, tolerance, 0.0, max_iterations, what);
}

}  // namespace roughroll
