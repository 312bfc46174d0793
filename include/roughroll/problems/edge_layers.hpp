// SPDX-License-Identifier: GPL-3.0-or-later
// Free rolling of smooth dissimilar rollers at large friction with the edge layers neglected
// (docs/formulation.md 8(n)). Johnson's level, Hertz's pressure p = (2/pi) sqrt(1 - r^2), Q = 0:
// the no-slip solution of 8(f), stick on the whole contact,
//   H[p1] = xi + beta_D p,   int p1 = 0,   p1 bounded at both edges:
//   p1(r) = -(2 beta_D/pi^2) sqrt(1 - r^2) log((1 - r)/(1 + r)),   xi = -4 beta_D/pi^2,
// with |p1|/(f p) = (|beta_D|/(pi f)) |log((1 - r)/(1 + r))| above 1 only in the layers
//   t_c = 2/(1 + exp(pi f/|beta_D|))   (about 2 exp(-pi f/|beta_D|))
// at each edge, where the model slips (8(g)). The layers' effect on the main stick zone's traction is
// neglected; the point reports the model's main stick zone [s1, c1] and its creep to first order in t_c
// (8(n), "The layers' positions"), the traction f p on the layers (layers_neglected_traction) and the leading
// layer's slip velocity from its inner problem (layers_neglected_slip_velocity; the trailing layer's: NaN):
//   1 + s1 = (4/e^2) t_c   (derived: the leading layer's entry condition, an inner problem on the
//                           scale t_c),
//   1 - c1 = 0.889 t_c     (the trailing layer's inner problem, whose answer drifts with log(1/t_c)
//                           from 0.873 to 0.899 t_c; checked against the five zones continued in f),
//   xi = -4 beta_D/pi^2 - (2 beta_D/pi^2) Phi(1 + s1) = -4 beta_D/pi^2 - (8 beta_D/(pi^2 e^2)) t_c
//        (the load identity of 8(n), exact up to the remainder R of the leading layer's bound B1).
// Each within its bound below; above the largest t_c measured (0.026) the bound falls back to the
// layers' thickness bound t = 2 t_c (the solved layers are 0.54 and 0.88 t_c thick, 8(n)).
// The bounds of neglecting the layers (8(n)): the pointwise B(t) = t/sqrt(1 - t) [(2|beta_D|/pi^2)
// (log(2/t) + 2 log 2 - 1) + 2 f/pi] and the leading layer's B1 ~ 0.124 |beta_D| t_c on
// |xi_model + 4 beta_D/pi^2|. The checks (3.3)-(3.4) hold on [-1 + t, 1 - t]. P_H/P2 is Johnson's
// (not moved by the tangential traction).
#pragma once

#include "roughroll/model/kernel.hpp"
#include "roughroll/problems/no_slip_coupled.hpp"
#include "roughroll/problems/normal_solution.hpp"
#include "roughroll/problems/tangential_solution.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

struct neglected_layers {
    double crossing;        // t_c: where |p1| of the no-slip solution reaches f p, from each edge
    double thickness;       // t = 2 t_c: the bound of either layer's thickness (the premise of every bound)
    double xi_shift;        // the reported xi minus the no-slip creep: -(2 beta_D/pi^2) Phi((4/e^2) t_c)
    double xi_bound;        // the bound of |xi_model - (no-slip creep + xi_shift)|
    double pointwise;       // B(t): the first bound of |xi_model - no-slip creep| alone (8(n))
    double sharp;           // min(B, B1): the sharper bound of |xi_model - no-slip creep| (8(n), the leading layer)
    double leading;         // 1 + s1 reported: (4/e^2) t_c
    double leading_bound;   // the bound of |1 + s1_model - leading|
    double trailing;        // 1 - c1 reported: 0.889 t_c
    double trailing_bound;  // the bound of |1 - c1_model - trailing|
    double lambda_bound = 0.0;  // the bound of |P_H/P2 model - reported|: 0 at Johnson's level (Hertz's pressure)
    // The bounds of the model's peak pressure (position r, value p in units of P2/a) from the closed form's, r = 0 and
    // p = (2/pi) lambda_ns cosh(pi eps) (8(t), "The peak pressure"): 0 at Johnson's level, whose pressure is Hertz's.
    double peak_r_bound = 0.0;
    double peak_p_bound = 0.0;
};

// The layers of the no-slip solution at Dundurs' beta_d != 0 and friction f > 0.
neglected_layers no_slip_layers(double beta_d, double f);

// Free rolling of smooth rollers at full coupling with the edge layers neglected (docs/formulation.md 8(t), "The
// layers' bound at full coupling"): the no-slip limit of 8(p) (no_slip_coupled.hpp), reported as stick on [-1, 1].
// crossing t_c = 2/(1 + exp(atan(f)/|eps|)) (8(p), "The edges"), t = 2 t_c, xi_shift 0 (no first-order shift is
// derived at this level), leading = trailing = 0 within t, and from the two weighted identities of 8(t) on the main
// stick zone (exact) with |F_model - F_ns| <= (1 + kappa) c sqrt(1 - r^2) in the layers,
//   |xi_model - xi_ns| <= (1 + kappa) c t/sqrt(1 - t) (1 + 4 |eps|/(1 - t)),
//   |lambda_model - lambda_ns| <= pi (1 + kappa) c t (1 + t)/((1 - t)^(5/2) sqrt(1 + 4 eps^2)),
// c = (2/pi) lambda_ns cosh(pi eps) (|F_ns| = c sqrt(1 - r^2) exactly), and the peak pressure's (8(t), "The peak
// pressure": the pointwise inverse on the main stick zone, dF = cosh(pi eps) W [(2/pi) Delta lambda + (1/pi) int_out
// Y dF/(eta - r)], near r = 0 within D(r) = cosh(pi eps) [(2/pi) lambda_bound + j/(1 - t - |r|)], j = (1 + kappa) c
// t/sqrt(1 - t); its derivative puts the model's peak within G/k of r = 0). Two premises are measured, not proved:
// each layer thinner than t, and |F_model| <= kappa c sqrt(1 - r^2) in the layers with kappa = 2 (kappa_layers; the
// five zones at f = 0.1 .. 0.19 give at most 1.0x, 8(t)). Only for t < 1/2; beyond, every bound is infinite.
constexpr double kappa_layers = 2.0;
neglected_layers coupled_no_slip_layers(double beta_d, double f);
// The bounds of the point's own level: full coupling's (8(t)) where `full`, else Johnson's (8(n)).
neglected_layers neglected_layers_at(double beta_d, double f, bool full);

// The route's error estimate at n nodes (contact's estimate; 8(n) "Where it answers", 8(t) "Wired"): P_H/P2 the layers'
// bound plus the reported pressure's rounding, the ends their bounds, xi its bound plus 4 eps |xi|; xi and lambda the
// reported creep and P_H/P2 (Johnson's level: no_slip_creep + xi_shift and Hertz's 1; full coupling: the limit's).
struct layers_estimate {
    double lambda, c0, xi, start;
};
layers_estimate neglected_layers_estimate(const neglected_layers& layers, double xi, double lambda, int n);
// The largest relative part of that estimate at the largest n (max_nodes), each over the scale the ladder's tolerance
// check divides it by (check_estimate: |xi|, P_H/P2, the half-width for the ends): the one sum both the route's choice
// (dissimilar_model.cpp) and the ladder's check see, so that a route chosen at a tolerance meets it at every rung.
double neglected_layers_relative(const neglected_layers& layers, double xi, double lambda);
// The same bounds at Bufler's eps and the crossing t_c (coupled_no_slip_layers: the pair's eps and the full level's
// t_c). At eps = 0 the formula at Johnson's level (Hertz's pressure, c = 2/pi): 8(t) compares it there with the five
// zones' distance from 8(f)'s no-slip creep, a check of its size on a second level (not a proof there: |F_ns| exceeds
// c sqrt(1 - r^2) in the layers by 8(f)'s logarithm).
neglected_layers coupled_layers_bound(double epsilon, double crossing);
// The peak's bounds of 8(t), "The peak pressure", from upper bounds of their inputs: Bufler's eps, c = (2/pi)
// lambda_ns cosh(pi eps) (the limit's peak), t each layer's thickness, j = J0/pi, lambda_bound |Delta lambda|,
// layer_sup the layers' largest |F - F_ns|. Returns the bounds of |r_peak| and |p_peak - c| of the model; {1, U}
// where the peak is not localised near r = 0 (anywhere in the contact, within the bound U of |p - p_ns|); infinite
// for t >= 1/2.
struct layers_peak {
    double r, p;
};
layers_peak coupled_peak_bound(double epsilon, double c, double t, double j, double lambda_bound, double layer_sup);

// The point of that route at friction f: stick on [-1, 1] (the layers' route, "no-slip"), xi the limit's, Q = 0, its
// checks (3.3)-(3.4) on [-1 + t, 1 - t] with the limit's p and p1 (|p1| < f p there by construction), the pressure
// margin that of `pressure` (the reported normal solution) on the same [-1 + t, 1 - t] (the limit's tension within
// t_inf of an edge lies in the neglected layers, covered by the estimates: 8(t), "Where the route checks"), `rounding`
// the margins' floor.
tangential_solution coupled_no_slip_point(const no_slip_coupled_solution& limit, double f, const normal_solution& pressure,
                                          double rounding);
// Its traction at r: the limit's p1 held to [-f p, f p], p = `pressure` the reported pressure at r (the limit's at the
// nodes, its interpolant between them: no_slip_normal), so that every reported row keeps (3.3); |p1| exceeds f p only
// within t_c of the edges (the layers). Where the reported p < 0 (the limit's tension within t_inf of an edge, 8(t)
// "Where the limit is an approximation", item 2, inside the layers) p1 is 0.
double coupled_no_slip_traction(const no_slip_coupled_solution& limit, double f, double pressure, double r);

// The crossing t_c of free rolling's edge layers at Johnson's level for any pair, smooth or rough (docs/formulation.md
// 8(n), "Rough rollers: beyond every n"): the distance from either edge (the larger of the two) where |p1|/p of the
// no-slip solution reaches f. That solution is one linear solve on the level of `normal` (stick on [-1, 1], Dundurs'
// forcing beta_d, layer kernels k1 = K1*, k2 = K2*; for rough rollers it has no closed form). g = |p1|/p grows like
// (|beta_D|/pi) log(1/x) at x = 1 +- r -> 0, which no n resolves below a few end spacings, so where the crossing lies
// below x0 = max(1e-3, ten end spacings (pi^2/2)/n^2) it is extrapolated from g(x0) with that slope:
//   t_c = x0 exp(-(pi/|beta_D|)(f - g(x0))).
// Measured on the rough pair (8(n), "Rough rollers"): the local slope rises to |beta_D|/pi from below as x falls (0.87
// of it at 1e-2, 0.97 at 1e-3), so the extrapolation overestimates t_c: against the crossing found directly on n = 1000's
// solution, by 1.7 %, 4 %, 6 % at f = 0.25, 0.3, 0.35 from n = 128 (x0 = 3e-3), 1 % to 2.4 % from n >= 256 (x0 = 1e-3);
// smooth rollers: 8(n)'s 2/(1 + exp(pi f/|beta_D|)) within 0.6 % at n = 128 (g(x0) of the collocation). Above x0: the
// root nearest the centre, by bisection in log x. 0 where the extrapolation underflows.
struct layers_crossing {
    double crossing;  // t_c at f
    double x0, g0;    // the extrapolation's base: |p1|/p = g0 at x0 (the no-slip solution's; independent of f)
    double slope;     // |beta_D|/pi
    // The friction at which the extrapolated crossing is t < x0: g0 + slope log(x0/t).
    double friction_at(double t) const;
};
layers_crossing johnson_layers_crossing(const normal_solution& normal, const kernel& k1, const kernel& k2,
                                        double beta_d, double f);

// The no-slip solution of 8(f) at Q = 0: its traction p1(r) on [-1, 1] and its creep xi.
double no_slip_traction(double beta_d, double r);
double no_slip_creep(double beta_d);

// The traction the layers-neglected point reports at r (8(n), "The layers' traction"): on a slip zone of its
// layout (the layers) f p with the zone's direction, the sign of p1 there (-sgn(beta_D) on the leading layer,
// sgn(beta_D) on the trailing one); on its stick zone the no-slip traction held to [-f p, f p] (it exceeds f p
// within t_c of the edges). `pressure` is p at r.
double layers_neglected_traction(const zone_layout& layout, double beta_d, double f, double pressure, double r);

// The slip velocity v of (3.6) the layers-neglected point reports at r (8(n), "The layers' slip velocity"): on the
// leading layer [-1, s1) the leading order of its inner problem, in closed form (x = 1 + r, t_a = 1 + s1 = (4/e^2) t_c),
//   v = -(4 beta_D/pi^2) sqrt(2) [sqrt(t_a - x) - sqrt(x) atan(sqrt((t_a - x)/x))],
// of the layer's direction -sgn(beta_D), 0 at s1 (the entry condition), within 0.25 t_c of |v(-1)| (measured against
// the five zones); 0 on the main stick zone [s1, c1]; NaN (not resolved) on the trailing layer (c1, 1], which holds
// slip, a stick zone and reversed slip, so v there changes sign and its inner problem is not solved by the program.
double layers_neglected_slip_velocity(const zone_layout& layout, double beta_d, double r);

}  // namespace roughroll
