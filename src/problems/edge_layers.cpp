// SPDX-License-Identifier: GPL-3.0-or-later
// The no-slip solution of free rolling with its edge layers neglected (docs/formulation.md 8(f), 8(n)).
#include "roughroll/problems/edge_layers.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

namespace {
// 8(n), "Sharper: the leading layer": the five zones' leading layer [-1, -1 + t_a] is one slip zone
// (8(j) 4a), where d = p1 - p1_ns = (2/pi)(b/pi) sqrt(x(2 - x)) [log(t_c/x) + eps(x)], x = 1 + r,
// |eps| <= -log(1 - t/2), is known; the load identity int_out d W = 0 (W = |r - m|/sqrt(|r - a||r - b|),
// from int p1 = int p1_ns = 0 and the bounded inverse on the main stick zone (a, b)) puts the trailing
// layer's part of xi - xi_ns equal to the leading one's up to t/h of it, so
//   |xi - xi_ns| <= (b/pi^2) [2 sup|Phi| + 2 t eps + 2 (kappa - 1)(sup Psi + t eps)] + t B/(2 (1 - t)),
// Phi(t_a) = t_a (log(t_c/t_a) + 2 log 2 - 1) over 0 < t_a <= t, Psi its bound of the |log| integral,
// kappa = sqrt((2 - t)/(2 - 2t)) (1 + t/(2 (1 - t))) the weights' spread, B the pointwise bound (8(n)).
double leading_layer_bound(double b, double crossing, double t, double pointwise) {
    if (!(t > 0.0 && crossing > 0.0)) return 0.0;
    const double c = 2.0 * M_LN2 - 1.0;
    const auto phi = [&](double ta) { return ta * (std::log(crossing / ta) + c); };
    const double stationary = crossing * std::exp(c - 1.0);  // Phi's maximum, e^(c-1) t_c, at t_a = e^(c-1) t_c
    const double phi_max = t >= stationary ? stationary : phi(t);
    const double phi_sup = std::max(phi_max, -phi(t));  // Phi falls past its maximum: |Phi| largest at an end
    const double psi_sup = std::max(phi_max, t * (std::fabs(std::log(t / crossing)) + c));
    const double eps = -std::log1p(-0.5 * t);
    const double kappa = std::sqrt((2.0 - t) / (2.0 - 2.0 * t)) * (1.0 + t / (2.0 * (1.0 - t)));
    return b / (M_PI * M_PI) * (2.0 * phi_sup + 2.0 * t * eps + 2.0 * (kappa - 1.0) * (psi_sup + t * eps)) +
           t * pointwise / (2.0 * (1.0 - t));
}
}  // namespace

neglected_layers no_slip_layers(double beta_d, double f) {
    const double b = std::fabs(beta_d);
    // |p1|/(f p) = (b/(pi f)) log((1 - r)/(1 + r)) = 1 at 1 + r = 2/(1 + e^(pi f/b)) (8(g)).
    const double crossing = 2.0 / (1.0 + std::exp(M_PI * f / b));
    const double t = 2.0 * crossing;
    // 8(n): per layer (1/pi) int |p1_model - p1|/sqrt(|eta - a||eta - b|), with |p1| <= (2b/pi^2)
    // sqrt(2x) log(2/x) and f p <= (2f/pi) sqrt(2x) at x = 1 + r < t, and |eta - b| >= 2 - 2t; the
    // integrals t (pi/2)(log(2/t) + 2 log 2 - 1) and t pi/2 of sqrt(x) log(2/x) and sqrt(x) against
    // 1/sqrt(t - x). Both layers: twice.
    // Only for thin layers (t < 1/2); thicker ones are no layers: no bound.
    if (!(t < 0.5)) return {crossing, t, HUGE_VAL, HUGE_VAL};
    double pointwise = 0.0;
    if (t > 0.0)
        pointwise = t / std::sqrt(1.0 - t) *
                    (2.0 * b / (M_PI * M_PI) * (std::log(2.0 / t) + 2.0 * M_LN2 - 1.0) + 2.0 * f / M_PI);
    // Both are bounds; the leading layer's is the sharper one for thin layers (8(n)).
    const double bound = std::min(pointwise, leading_layer_bound(b, crossing, t, pointwise));
    return {crossing, t, bound, pointwise};
}

double no_slip_traction(double beta_d, double r) {
    if (!(r > -1.0 && r < 1.0)) return 0.0;
    // sqrt(1 - r^2) from (1 - r)(1 + r): no cancellation at either edge.
    return -2.0 * beta_d / (M_PI * M_PI) * std::sqrt((1.0 - r) * (1.0 + r)) * std::log((1.0 - r) / (1.0 + r));
}

double no_slip_creep(double beta_d) { return -4.0 * beta_d / (M_PI * M_PI); }

tangential_solution dissimilar_zones::layers_neglected_point() {
    const neglected_layers layers = no_slip_layers(beta_d_, f_);
    tangential_solution s = zone_solution(f_, -1.0, 1.0, no_slip_creep(beta_d_), 0.0);
    s.forcing = beta_d_;  // the frame's sign is 1: beta_D itself (8(h) is built into the closed form)
    s.layout = layers_neglected_layout();  // stick on [-1, 1], the route no-slip
    // (3.3) outside the layers, where |p1| < f p by construction (the test that it is, 8(n)); no slip zone.
    const double t = std::min(layers.thickness, 0.5);
    const std::vector<zone> checked{{-1.0 + t, 1.0 - t, true, 0}};
    s.checks = check_zones(
        checked, blended_checks(), [&](double r) { return solver_.normal().pressure(r); },
        [&](double r) { return no_slip_traction(beta_d_, r); }, [](double) { return 0.0; });
    return s;
}

}  // namespace roughroll
