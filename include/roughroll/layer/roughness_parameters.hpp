// SPDX-License-Identifier: GPL-3.0-or-later
// The roughness parameters k, t and alpha of (2.10)-(2.15) from the micro-geometry, by GSL's
// adaptive quadrature or, for measured profiles, a fixed rule piece by piece
// (piecewise_averages.hpp). For each x1 the layer integrals over x2 in [h0(x1), H]
//   a(x1)   = int d^2 dx2        (m)              (2.6)
//   a3(x1)  = int d d' dx2       (dimensionless)  (2.7)   (= -d(h0)^2/2 for every d)
//   a33(x1) = int (d')^2 dx2     (1/m)            (2.8)
// and their averages <f> = (1/l) int_0^l f dx1 (2.9), with h_1 = dh/dx1, give
//   k^(1) = mu0 [<a33> - <a3 h_1>^2/<a h_1^2>]                                          (2.11)
//   k^(2) = (lambda0 + 2mu0) [<a33> - (lambda0/(lambda0+2mu0))^2 <a3 h_1>^2/<a h_1^2>]  (2.12), E11
//           (the paper prints ((lambda0+mu0)/(lambda0+2mu0))^2: normal_factor::printed,
//            docs/formulation.md, erratum E11, derives the factor from (2.3)-(2.5))
//   t^(1) = (lambda0 + 2mu0)/2 [<a> - <a h_1>^2/<a h_1^2>]                               (2.13)
//   t^(2) = mu0/2 [<a> - <a h_1>^2/<a h_1^2>]                                            (2.14)
//   alpha^(i) = sqrt(k^(i)/(2 t^(i)))                                                    (2.15)
// in Pa/m (k), Pa m (t) and 1/m (alpha). Superscript (1) is tangential, (2) normal.
// The inner integrals are computed in the dimensionless depth below the top u = (H - x2)/H,
// with H factored out analytically (dhat(u) = d(H(1 - u)), dhat_u = d dhat/du = -H d'):
//   a = H int_0^u0 dhat^2 du,  a3 = -int_0^u0 dhat dhat_u du,  a33 = (1/H) int_0^u0 dhat_u^2 du,
// u0 = (H - h0(x1))/H, and the outer averages are of a/H, a3 and a33 H: no step leaves the
// range of double for any H that check_conditions accepts, and h0 -> H loses no precision.
#pragma once

#include "roughroll/layer/micro_geometry.hpp"

namespace roughroll {

// The averages (2.9) that (2.11)-(2.14) use.
struct layer_averages {
    double a = 0.0;             // <a>, m
    double a3_h1 = 0.0;         // <a3 h_1>, dimensionless
    double a33 = 0.0;           // <a33>, 1/m
    double a_h1 = 0.0;          // <a h_1>, m
    double a_h1_squared = 0.0;  // <a h_1^2>, m
};

// The layer integrals (2.6)-(2.8) at one x1, with GSL's error estimates.
struct layer_integrals {
    double a = 0.0, a3 = 0.0, a33 = 0.0;
    double a_error = 0.0, a3_error = 0.0, a33_error = 0.0;
};

// k, t and alpha of one direction.
struct direction_parameters {
    double k = 0.0;      // Pa/m
    double t = 0.0;      // Pa m
    double alpha = 0.0;  // 1/m
};

struct roughness_parameters {
    double k_tangential = 0.0, k_normal = 0.0;          // k^(1), k^(2), Pa/m
    double t_tangential = 0.0, t_normal = 0.0;          // t^(1), t^(2), Pa m
    double alpha_tangential = 0.0, alpha_normal = 0.0;  // alpha^(1), alpha^(2), 1/m
    layer_averages averages;
    // Error estimates: of each average (the outer quadrature's estimate over l, plus the
    // largest inner estimate times the weight h_1 or h_1^2 it was multiplied by), and of k,
    // t, alpha propagated from those to first order.
    layer_averages averages_error;
    double k_tangential_error = 0.0, k_normal_error = 0.0;
    double t_tangential_error = 0.0, t_normal_error = 0.0;
    double alpha_tangential_error = 0.0, alpha_normal_error = 0.0;
    int evaluations = 0;  // points x1 of the outer quadratures (adaptive: summed over the five)
};

// The five averages of the dimensionless layer integrals a/H, a3, a33 H (so <a>/H, <a3 h_1>,
// <a33> H, <a h_1>/H, <a h_1^2>/H in the fields of layer_averages), with their error
// estimates and the number of points x1 they took: what either rule below returns, and
// compute_roughness_parameters scales back to SI (every product within double's range).
struct scaled_averages {
    layer_averages value;
    layer_averages error;
    int evaluations = 0;
};

// How the averages (2.9) are integrated:
//   adaptive   nested gsl_integration_qag: outer over x1 split at the breakpoints, inner over
//              the depth for each x1 (tolerances below); any profile
//   piecewise  a fixed Gauss-Kronrod rule on every piece with the inner integrals in closed
//              form (piecewise_averages.hpp): linear in the number of samples, for measured
//              profiles of 1e4 to 1e6 samples
//   automatic  piecewise for a measured profile, adaptive for the built-in ones
enum class averages_rule { automatic, adaptive, piecewise };

// The tolerances of the quadratures: relative, and absolute against a scale of the integral
// (the inner ones against the same integral over the whole layer, u0 = 1; the signed averages
// <a h_1>, <a3 h_1> against their Cauchy-Schwarz bounds sqrt(<a><a h_1^2>), sqrt(<a33><a h_1^2>)).
constexpr double inner_tolerance = 1e-13;
constexpr double outer_tolerance = 1e-12;

// (2.6)-(2.8) at x1 in SI units, by gsl_integration_qag (Gauss-Kronrod 21) over u in [0, u0].
layer_integrals integrals_at(const micro_geometry& g, double x1);

// (2.11)-(2.15) from averages (no quadrature), with the factor of (2.12) chosen by `factor`:
// throws numerical_error when <a h_1^2> is not positive or a k or t is not finite and > 0.
roughness_parameters parameters_from_averages(const layer_averages& averages, double lambda0, double mu0,
                                              normal_factor factor = normal_factor::derived);

// The whole computation: check_conditions, the averages by `rule`, then (2.11)-(2.15) with
// their error estimates (propagated to first order from the averages').
roughness_parameters compute_roughness_parameters(const micro_geometry& g,
                                                  averages_rule rule = averages_rule::automatic);

}  // namespace roughroll
