// SPDX-License-Identifier: GPL-3.0-or-later
// Typed errors of roughroll and the bridge from GSL status codes to them.
//
// GSL's default error handler aborts the process; roughroll turns it off once
// (gsl_guard) and converts every non-zero status into a numerical_error that
// carries gsl_strerror() and the context, so the CLI can exit 2 with one line.
#pragma once

#include <stdexcept>
#include <string>

namespace roughroll {

// Base of every error roughroll reports to a user: the message is one line.
class error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Bad input: a scene, a parameter, a command-line value.
class input_error : public error {
public:
    using error::error;
};

// A case the chosen discretisation cannot resolve (it would return noise).
class resolution_error : public error {
public:
    using error::error;
};

// A case that no n of the chosen method resolves (a zone structure the method does not build): the
// line names what to change, and the ladder of levels refuses it at the rung that found it, not after
// climbing to the top.
class beyond_method_error : public resolution_error {
public:
    using resolution_error::resolution_error;
};

// A refusal whose line says what cannot be resolved but not what the user can change, because that depends
// on how the point was asked (no three zones of dissimilar rollers carry the load at this n): the ladder of
// levels adds its advice (give n, another method or zone search), which it leaves off a resolution_error
// whose own line names what to change.
class unadvised_refusal : public resolution_error {
public:
    using resolution_error::resolution_error;
};

// A refusal at the limit the rounding of this n sets (the zone ends' Newton stopped at a rounding beyond its cap,
// numerics/damped_newton.hpp), thrown by a zone search that found nothing on any of its routes, the limit met on one
// (problems/zone_newton.hpp, rounding_limits): the rounding grows with n, so its line advises a smaller n, and the
// ladder of levels climbs no higher.
class rounding_limit_error : public resolution_error {
public:
    using resolution_error::resolution_error;
};

// A numerical fault: a GSL status, a singular system, a non-finite result,
// a root search without a bracket.
class numerical_error : public error {
public:
    using error::error;
};

// Throws numerical_error("<context>: <gsl_strerror(status)>") unless status is 0.
void gsl_check(int status, const std::string& context);

// Turns GSL's aborting error handler off for the lifetime of the process.
// Idempotent; call before the first GSL routine (the solvers do).
void gsl_guard();

}  // namespace roughroll
