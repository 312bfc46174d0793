// SPDX-License-Identifier: GPL-3.0-or-later
// A scalar root by gsl_root_fsolver_brent, GSL's iterate-then-test loop: the root search
// for c0 at a given Q (Sec. 4, after (4.5)) and for the half-width a at a given load
// (physical_scene.hpp). Exceptions thrown by the function pass through GSL's C frames safely.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace roughroll {

struct root {
    double x;
    int iterations;
    double slope;  // of the function at x, from the last secant step (NaN from Brent)
};

// The root of f in [lo, hi], where f(lo) and f(hi) differ in sign, to
// gsl_root_test_interval(epsabs, epsrel). `what` names the search in messages
// ("Brent search for c0"). Throws numerical_error on a GSL status or no convergence
// within max_iterations, and rethrows whatever f throws.
root brent_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel,
                int max_iterations, const std::string& what);

// The end c0 of the stick zone at which the load Q(c0) of (4.5) (or its one-parameter
// counterpart) equals `target` in (0, f), Q(-1) = f and Q(1) <= target, to 1e-15 in c0:
// by the secant iteration from `guess` (the coarse level's c0 when extrapolating: two or
// three loads), else from `start` (Carter's c0), else by Brent on [-1, 1]. The secant must
// stay in [-1, 1] and converge within a few steps, else the next way is taken.
// `slope`: dQ/dc0 near `guess` (the level below's), for a first Newton step from it.
// `before_full_range`, when given, runs before any search not started from `guess` (to refuse
// a target below a discretisation's Q(1)). The root returned is the last c0 evaluated.
root stick_end_for_load(const std::function<double(double)>& load, double target, std::optional<double> guess,
                        const std::string& what, const std::function<void()>& before_full_range = {},
                        std::optional<double> start = std::nullopt, std::optional<double> slope = std::nullopt);

}  // namespace roughroll
