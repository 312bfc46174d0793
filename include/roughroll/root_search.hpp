// A scalar root by gsl_root_fsolver_brent, GSL's iterate-then-test loop: the root search
// for c0 at a given Q (Sec. 4, after (4.5)) and for the half-width a at a given load
// (physical_scene.hpp). Exceptions thrown by the function pass through GSL's C frames safely.
#pragma once

#include <functional>
#include <string>

namespace roughroll {

struct root {
    double x;
    int iterations;
};

// The root of f in [lo, hi], where f(lo) and f(hi) differ in sign, to
// gsl_root_test_interval(epsabs, epsrel). `what` names the search in messages
// ("Brent search for c0"). Throws numerical_error on a GSL status or no convergence
// within max_iterations, and rethrows whatever f throws.
root brent_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel,
                int max_iterations, const std::string& what);

}  // namespace roughroll
