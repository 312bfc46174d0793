// SPDX-License-Identifier: GPL-3.0-or-later
// Loads of dissimilar rollers whose stick zones the zone search cannot resolve, refused before any solve (one line
// naming what answers instead), where the search would otherwise run for minutes or fail in the quadrature:
//   - free rolling near complete slip (f small against |beta_D|, docs/formulation.md 8(f) "Below the rounding"): stick
//     zones 18.3 f wide (the pair) narrower than a few of W's breakpoint separations, per coupling level;
//   - one ulp below sliding with the roller driven (Q beta_D > 0, 8(m) "Driven, next to sliding"): the blended stick
//     zone lies within about 2e-9 of the leading edge, where W's quadrature no longer cuts its breakpoints;
//   - at full coupling, driven below 1 - 1.1e-9 (8(m) "Full coupling next to sliding", measured): the alternation's
//     lambda, e, xi change by more than its 1e-12 at every step (the braked side is refused at the alternation's first
//     sign instead, full_coupling.cpp).
// Both coupling levels, smooth or rough rollers: the rules read beta_D, f, Q and the level (the surfaces for the
// advice).
#pragma once

#include <optional>
#include <string>

#include "roughroll/model/dissimilar.hpp"

namespace roughroll {

// The refusal of a load |Q| < f on rollers of these materials (`rough`: layered surfaces) at friction f, where one of
// the rules above applies; empty otherwise (beta_d = 0 and gross sliding |Q| >= f are never refused).
std::optional<std::string> unresolvable_zones(const dissimilar& materials, bool rough, double f, double Q);

}  // namespace roughroll
