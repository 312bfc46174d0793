// SPDX-License-Identifier: GPL-3.0-or-later
// The averages (2.9) of the layer integrals (2.6)-(2.8) piece by piece, without adaptive
// quadrature: the route for measured profiles, whose profilometer traces have 1e4 to 1e6
// samples (docs/roughness-parameters.md, "Piecewise rule"). Two ideas:
//
// 1. The inner integrals in closed form in u0 = (H - h0(x1))/H, dimensionless (a/H, a3, a33 H),
//    with dhat(u) = d(H(1 - u)) of micro_geometry.hpp and x = pi u0:
//      linear     a/H = u0^3/3                a3 = -u0^2/2          a33 H = u0
//      quadratic  a/H = u0^5/5                a3 = -u0^4/2          a33 H = 4 u0^3/3
//      cosine     a/H = (x - sin x)/(2 pi)    a3 = -sin^2(x/2)/2    a33 H = (pi/8)(x + sin x)
//    (a3 = -dhat(u0)^2/2 for every decay: (2.7) with d(H) = 0). x - sin x by its Taylor series
//    below x = 1, where the difference would cancel (u0 -> 0, the profile near the top).
//
// 2. The average over x1 by the 15-point Gauss-Kronrod rule (K15) on each piece between
//    profile_function::breakpoints() (for a measured profile the knot intervals, on each of
//    which h0 is one cubic), each piece cut into equal parts so that the period has at least
//    min_pieces of them (a built-in profile is one smooth piece over the whole period). The
//    error estimate of a piece is |K15 - G7|, G7 the 7-point Gauss rule on the same points
//    (so the error of the lower order: a generous estimate of K15's), and at least 50 eps
//    times the piece's integral of |f| (rounding, as QUADPACK's rules); the estimates add over
//    the pieces, the values by compensated (Neumaier) summation.
//
// The five averages share the points x1: 15 per piece, one closed form and one h_1 each.
#pragma once

#include "roughroll/layer/micro_geometry.hpp"
#include "roughroll/layer/roughness_parameters.hpp"

namespace roughroll {

// At least this many pieces per period (a built-in profile's single piece is cut into 64).
constexpr int min_pieces = 64;

// The inner integrals (2.6)-(2.8) of a built-in decay in closed form, dimensionless: a/H, a3,
// a33 H at depth u0 (formulas above). The error fields are 0: the forms are exact up to a few
// units of rounding, which the outer rule's rounding floor covers.
layer_integrals closed_form_layer_integrals(decay_kind kind, double u0);

// The five averages of g, dimensionless as scaled_averages says, by the rule above. Assumes
// check_conditions(g) holds (compute_roughness_parameters checks it first).
scaled_averages piecewise_averages(const micro_geometry& g);

}  // namespace roughroll
