// SPDX-License-Identifier: GPL-3.0-or-later
// The half-width a of a physical scene (docs/formulation.md 2(j)): the width at which the
// model carries the given load P2, lambda(T(a), A(a)) = (a / a_H(P2))^2, found by Brent on
// the normal problem alone (on a cheap level first, then polished); or the paper's a = a_H.
#pragma once

#include <functional>

#include "roughroll/model/physical_scene.hpp"
#include "roughroll/model/roughness.hpp"

namespace roughroll {

// The width search's relative tolerance in a (Brent's interval, the polish's last step): the width found is within it
// of its lambda's root (docs/formulation.md 2(j)); the SI values' estimates add it (io/si_estimate.hpp).
inline constexpr double width_search_tolerance = 1e-12;

// The half-width by the scene's width rule. `load_ratio` gives lambda = P_H/P2 for the
// roughness at a trial width (the normal problem (3.19)-(3.20) as a contact solves it).
// given_load: gsl_root_fsolver_brent on F(a) = lambda(a) - (a/a_H)^2, bracketed from a_H
// (F(a_H) = lambda - 1 >= 0: roughness adds compliance, E2) first to a_H sqrt(lambda(a_H)),
// then outwards by 1.25; trials beyond the method's resolution are halved back. Throws the
// solver's resolution_error or numerical_error prefixed with the trial width, numerical_error
// when no bracket is found, and input_error when a > R/10 (the half-spaces of (3.7)): no
// trial width beyond R/10 is solved, so a wide contact is refused as such, before any solve
// when a_H > R/10 already.
// `cheap_load_ratio`, when given (a coarser discretisation of the same lambda, e.g.
// coarse_load_ratio), is searched that way first; its root then starts a Newton step (on the
// cheap level's slope) and secant steps on `load_ratio`'s F until the next step is below 1e-12
// of a, the Brent search's tolerance (the width returned is the last one evaluated). Any failure of the cheap level or of the polish (an iterate
// outside (0, R/10], no convergence within 8 steps) falls back to the search above on
// `load_ratio` alone, so the answer and every refusal are `load_ratio`'s.
// `lambda_has_traction_term`: lambda holds the term in the tangential traction of full coupling
// (docs/formulation.md 8(c)), so that a smooth pair is not at Hertz's width: lambda then does not
// vary with a (no layer), and a = a_H sqrt(lambda(a_H)), one solve; else a smooth pair is Hertz's
// exactly (lambda = 1), with no solve.
contact_width find_width(const physical_scene& s, const std::function<double(const roughness&)>& load_ratio,
                         const std::function<double(const roughness&)>& cheap_load_ratio = {},
                         bool lambda_has_traction_term = false);

}  // namespace roughroll
