#include "roughroll/numerics/root_search.hpp"

#include <algorithm>
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
    return {gsl_root_fsolver_root(brent.get()), iter};
}

root stick_end_for_load(const std::function<double(double)>& load, double target, std::optional<double> guess,
                        const std::string& what, const std::function<void()>& before_full_range) {
    constexpr int max_iterations = 200;
    double lo = -1.0, hi = 1.0;
    if (guess && *guess > -1.0 && *guess < 1.0) {
        const double a = std::max(-1.0, *guess - 1e-5), b = std::min(1.0, *guess + 1e-5);
        if (load(a) - target > 0.0 && load(b) - target < 0.0) {
            lo = a;
            hi = b;
        }
    }
    if (hi == 1.0 && before_full_range) before_full_range();
    return brent_root([&](double c0) { return load(c0) - target; }, lo, hi, 1e-15, 0.0, max_iterations, what);
}

}  // namespace roughroll
