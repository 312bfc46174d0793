// SPDX-License-Identifier: GPL-3.0-or-later
// Free rolling of smooth dissimilar rollers at large friction with the edge layers neglected
// (docs/formulation.md 8(n)). Johnson's level, Hertz's pressure p = (2/pi) sqrt(1 - r^2), Q = 0:
// the no-slip solution of 8(f), stick on the whole contact,
//   H[p1] = xi + beta_D p,   int p1 = 0,   p1 bounded at both edges:
//   p1(r) = -(2 beta_D/pi^2) sqrt(1 - r^2) log((1 - r)/(1 + r)),   xi = -4 beta_D/pi^2,
// with |p1|/(f p) = (|beta_D|/(pi f)) |log((1 - r)/(1 + r))| above 1 only in the layers
//   t_c = 2/(1 + exp(pi f/|beta_D|))   (about 2 exp(-pi f/|beta_D|))
// at each edge, where the model slips (8(g)). The layers are neglected, and the creep of the model
// (the five zones, 8(j) 4a) lies within
//   |xi_model - xi| <= B(t) = t/sqrt(1 - t) [ (2|beta_D|/pi^2)(log(2/t) + 2 log 2 - 1) + 2 f/pi ],
// t = 2 t_c the bound of either layer's thickness (the solved layers are 0.5 to 0.9 t_c thick, 8(n)):
// the Hilbert problem of p1_model - p1 on the main stick zone, whose solvability fixes the change of
// xi by the layers' traction, |p1_model - p1| <= |p1| + f p there. Sharper (8(n), "the leading
// layer"): the leading layer is one slip zone, where p1_model - p1 is known, and the load identity
// makes the trailing layer's part equal to the leading one's, so
//   |xi_model - xi| <= B1(t) ~ (2|beta_D|/pi^2) max(e^(2 log 2 - 2) t_c, -Phi(t)) + O(t^2 log(1/t)),
// within a factor 1.2 to 2.2 of the distance measured (8(n)); the smaller of the two is used.
// The checks (3.3)-(3.4) hold on [-1 + t, 1 - t]. P_H/P2 is Johnson's (not moved by the tangential traction).
#pragma once

namespace roughroll {

struct neglected_layers {
    double crossing;   // t_c: where |p1| of the no-slip solution reaches f p, from each edge
    double thickness;  // t = 2 t_c: the bound of either layer's thickness used in the bound below
    double xi_bound;   // min(B, B1): the bound of |xi_model - xi| from neglecting both layers
    double pointwise;  // B(t): the first bound alone (|p1_model - p1| <= |p1| + f p in both layers)
};

// The layers of the no-slip solution at Dundurs' beta_d != 0 and friction f > 0.
neglected_layers no_slip_layers(double beta_d, double f);

// The no-slip solution of 8(f) at Q = 0: its traction p1(r) on [-1, 1] and its creep xi.
double no_slip_traction(double beta_d, double r);
double no_slip_creep(double beta_d);

}  // namespace roughroll
