// SPDX-License-Identifier: GPL-3.0-or-later
// The no-slip solution of free rolling with its edge layers neglected (docs/formulation.md 8(f), 8(n)).
#include "roughroll/problems/edge_layers.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/numerics/gauss_chebyshev.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/no_slip_coupled.hpp"
#include "roughroll/problems/tangential_solver.hpp"
#include "roughroll/problems/zone_checks.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

namespace {
// 8(n), "The layers' positions": the leading layer's entry condition on the scale t_c makes
// Phi(t_a) = t_a (log(t_c/t_a) + 2 log 2 - 1) stationary, t_a = e^(2 log 2 - 2) t_c = (4/e^2) t_c.
const double leading_ratio = 4.0 * std::exp(-2.0);
// Its correction, measured 0.1246 t_c^2 to 0.1253 t_c^2 for t_c from 2.8e-3 to 2.5e-2 (the five zones
// continued in f, n = 500): twice that is the bound, up to the largest t_c measured; below it the
// derivation's leading order only gains.
constexpr double leading_correction = 0.25;
// The trailing layer (slip, stick, reversed slip): its inner problem on the scale t_c keeps L = log(2/t_c)
// and gives 1 - c1 from 0.8734 t_c (L = 4.4) rising to 0.8992 t_c (L -> infinity; 8(n), solved with
// QUADPACK), plus 0.27 t_c^2 (measured); the five zones continued in f give 0.8796 to 0.8863 t_c for t_c
// from 8.2e-5 to 2.5e-2: 0.889 t_c within 0.011 t_c for every t_c up to the largest measured.
// The band [0.878, 0.900] is tightest at its top, 0.0008 t_c above the inner problem's limit 0.8992 (review
// of the layers' positions), and that margin is enough: the limit is reached only as t_c -> 0, and below
// t_c = DBL_EPSILON the bound carries t_c itself (`rounding` below), so the band alone bounds the end only
// where L <= log(2/DBL_EPSILON) = 36.7, where Y1 + 0.27 t_c <= 0.8953 (largest at t_c = DBL_EPSILON: Y1
// rises as t_c falls, faster than the correction falls): a top margin of at least 0.0047 t_c, against the
// inner problem's error 6e-6 (QUADPACK against GSL) and the correction's spread (0.269 to 0.274 t_c:
// 1.3e-4 t_c at t_c = 0.026, where the bottom margin is 0.0022 t_c). Measured in
// validation/test_free_rolling_every_f.cpp (TrailingLayerFromItsInnerProblem); widening the band would
// loosen the estimate without a reason.
constexpr double trailing_ratio = 0.889;
constexpr double trailing_spread = 0.011;
constexpr double laws_measured_to = 0.026;

// 8(n), "Sharper: the leading layer": the five zones' leading layer [-1, -1 + t_a] is one slip zone
// (8(j) 4a), where d = p1 - p1_ns = (2/pi)(b/pi) sqrt(x(2 - x)) [log(t_c/x) + eps(x)], x = 1 + r,
// |eps| <= -log(1 - t/2), is known; the load identity int_out d W = 0 (W = |r - m|/sqrt(|r - a||r - b|),
// from int p1 = int p1_ns = 0 and the bounded inverse on the main stick zone (a, b)) puts the trailing
// layer's part of xi - xi_ns equal to the leading one's up to t/h of it, so
//   |xi - xi_ns + (2 b/pi^2) Phi(t_a)| <= R = (b/pi^2) [2 t eps + 2 (kappa - 1)(sup Psi + t eps)] + t B/(2 (1 - t)),
// Phi(t_a) = t_a (log(t_c/t_a) + 2 log 2 - 1) over 0 < t_a <= t, Psi its bound of the |log| integral,
// kappa = sqrt((2 - t)/(2 - 2t)) (1 + t/(2 (1 - t))) the weights' spread, B the pointwise bound (8(n)).
struct leading_layer {
    double phi_max;    // Phi's maximum over 0 < t_a <= t
    double phi_min;    // its minimum there (at t_a = t, or 0)
    double remainder;  // R
};

double phi(double crossing, double ta) { return ta * (std::log(crossing / ta) + 2.0 * M_LN2 - 1.0); }

leading_layer leading_layer_terms(double b, double crossing, double t, double pointwise) {
    const double c = 2.0 * M_LN2 - 1.0;
    const double stationary = leading_ratio * crossing;  // Phi's maximum, e^(c-1) t_c, at t_a = e^(c-1) t_c
    const double phi_max = t >= stationary ? stationary : phi(crossing, t);
    const double phi_min = std::min(0.0, phi(crossing, t));  // Phi falls past its maximum: least at an end
    const double psi_sup = std::max(phi_max, t * (std::fabs(std::log(t / crossing)) + c));
    const double eps = -std::log1p(-0.5 * t);
    const double kappa = std::sqrt((2.0 - t) / (2.0 - 2.0 * t)) * (1.0 + t / (2.0 * (1.0 - t)));
    const double remainder = b / (M_PI * M_PI) * (2.0 * t * eps + 2.0 * (kappa - 1.0) * (psi_sup + t * eps)) +
                             t * pointwise / (2.0 * (1.0 - t));
    return {phi_max, phi_min, remainder};
}
}  // namespace

neglected_layers no_slip_layers(double beta_d, double f) {
    const double b = std::fabs(beta_d);
    // |p1|/(f p) = (b/(pi f)) log((1 - r)/(1 + r)) = 1 at 1 + r = 2/(1 + e^(pi f/b)) (8(g)).
    const double crossing = 2.0 / (1.0 + std::exp(M_PI * f / b));
    const double t = 2.0 * crossing;
    // Only for thin layers (t < 1/2); thicker ones are no layers: no bound.
    if (!(t < 0.5)) return {crossing, t, 0.0, HUGE_VAL, HUGE_VAL, HUGE_VAL, 0.0, HUGE_VAL, 0.0, HUGE_VAL};
    if (!(t > 0.0)) return {};  // t_c below the smallest double: the no-slip solution, exactly
    // 8(n): per layer (1/pi) int |p1_model - p1|/sqrt(|eta - a||eta - b|), with |p1| <= (2b/pi^2)
    // sqrt(2x) log(2/x) and f p <= (2f/pi) sqrt(2x) at x = 1 + r < t, and |eta - b| >= 2 - 2t; the
    // integrals t (pi/2)(log(2/t) + 2 log 2 - 1) and t pi/2 of sqrt(x) log(2/x) and sqrt(x) against
    // 1/sqrt(t - x). Both layers: twice.
    const double pointwise =
        t / std::sqrt(1.0 - t) * (2.0 * b / (M_PI * M_PI) * (std::log(2.0 / t) + 2.0 * M_LN2 - 1.0) + 2.0 * f / M_PI);
    const leading_layer lead = leading_layer_terms(b, crossing, t, pointwise);
    const double weight = 2.0 * b / (M_PI * M_PI);
    // The ends (8(n), "The layers' positions"): both from their inner problems (the trailing one's range);
    // outside the laws' range each within the premise t of the edge. The reported -1 + leading and
    // 1 - trailing round by at most the layer itself or an ulp of 1.
    const bool laws = crossing <= laws_measured_to;
    const double leading = leading_ratio * crossing, trailing = trailing_ratio * crossing;
    const double rounding = std::min(crossing, DBL_EPSILON);
    const double leading_bound =
        (laws ? leading_correction * crossing * crossing : std::max(leading, t - leading)) + rounding;
    const double trailing_bound =
        (laws ? trailing_spread * crossing : std::max(trailing, t - trailing)) + rounding;
    // The creep with the leading layer's first-order effect, -(2 beta_D/pi^2) Phi(t_a) at t_a = leading
    // (Phi's maximum, = leading). Within R of it for the model's own t_a; Phi is concave (Phi'' = -1/t_a),
    // so t_a within e of its maximiser moves it by at most e^2/(2 (leading - e)); where the leading law
    // is not measured, by Phi's whole range over 0 < t_a <= t.
    const double shift = -std::copysign(weight, beta_d) * leading;
    const double phi_spread = laws && leading_bound < leading
                                  ? leading_bound * leading_bound / (2.0 * (leading - leading_bound))
                                  : lead.phi_max - lead.phi_min;
    const double identity = lead.remainder + weight * phi_spread;
    // The sharper bound of |xi_model - xi_ns| (B or B1), from xi_ns + shift: its distance added.
    const double sharp = std::min(pointwise, weight * std::max(lead.phi_max, -lead.phi_min) + lead.remainder);
    return {crossing,
            t,
            shift,
            std::min(identity, sharp + std::fabs(shift)),
            pointwise,
            sharp,
            leading,
            leading_bound,
            trailing,
            trailing_bound};
}

// 8(t), "The peak pressure": where the model's peak pressure lies and how far its value is from the limit's, the
// limit's peak being p_ns(0) = c at r = 0 (p_ns = c sqrt(1 - r^2) cos(eps log((1 + r)/(1 - r))), even, c its largest
// value). On the main stick zone (a, b) the difference dF = F - F_ns is, exactly (Plemelj on Omega Y, Omega the
// Cauchy integral of dF, Y of the two identities above),
//   dF(r) = cosh(pi eps) W(r) [(2/pi) Delta lambda + I(r)],   I(r) = (1/pi) int_out Y(eta) dF(eta)/(eta - r) d eta,
// W = (r - a)^(1/2 + i eps) (b - r)^(1/2 - i eps), |W| <= sqrt(1 - r^2), |Y| = 1/sqrt(|eta - a||eta - b|). With
// upper bounds t of the layers' thickness, j of J0/pi, Lambda of |Delta lambda| and S of the layers' |dF|
// (coupled_layers_bound: the premises' t = 2 t_c, j, Lambda and S = (1 + kappa) c sqrt(2 t); a test: the five zones'
// measured ones):
//   |dF(r)| <= D(r) = cosh(pi eps) [(2/pi) Lambda + j/(1 - t - |r|)]           (|r| < 1 - t; Lambda the P_H/P2 bound),
//   |dF| <= U = cosh(pi eps) [(2/pi) Lambda + 2 S]     (everywhere: each layer's part of
//            W I is at most its largest |dF|, since sqrt(r - a)/pi int_0^inf du/(sqrt(u) (u + r - a)) = 1),
//   |dF'(r)| <= G = cosh(pi eps) [2 sqrt(1/4 + eps^2)/sqrt((1 - t)^2 - rho^2) ((2/pi) Lambda + j/delta) + j/delta^2]
//            (|r| <= rho, delta = 1 - t - rho; |W'| = |W| |(1/2 + i eps)/(r - a) - (1/2 - i eps)/(b - r)|).
// If c sqrt(1 - rho^2) + U < c - D(0), the model's peak lies in |r| <= rho (nowhere else can p reach p(0)); there
// |p_ns'(r)| >= k |r|, k = c cos(|eps| log((1 + rho)/(1 - rho))) (p_ns' = -c [r cos(eps L) + 2 eps sin(eps L)]
// /sqrt(1 - r^2), both terms of one sign), and p' = 0 at the peak puts it within r_b = min(rho, G/k) of 0, its value
// within D(r_b) of c (p(0) >= c - D(0); p(r*) <= c + |dF(r*)|). Else: anywhere (1), within U.
layers_peak coupled_peak_bound(double epsilon, double c, double t, double j, double lambda_bound, double layer_sup) {
    constexpr double rho = 0.5;
    const double e = std::fabs(epsilon);
    if (!(t < 0.5)) return {HUGE_VAL, HUGE_VAL};
    const double ch = std::cosh(M_PI * e), load = M_2_PI * lambda_bound;
    const double D0 = ch * (load + j / (1.0 - t));
    const double U = ch * (load + 2.0 * layer_sup);
    const double turn = e * std::log((1.0 + rho) / (1.0 - rho));
    if (!(c * std::sqrt(1.0 - rho * rho) + U < c - D0 && turn < M_PI_2)) return {1.0, U};
    const double delta = 1.0 - t - rho;
    const double G =
        ch * (2.0 * std::sqrt(0.25 + e * e) / std::sqrt((1.0 - t) * (1.0 - t) - rho * rho) * (load + j / delta) +
              j / (delta * delta));
    const double r = std::min(rho, G / (c * std::cos(turn)));
    return {r, ch * (load + j / (1.0 - t - r))};
}

neglected_layers coupled_layers_bound(double epsilon, double crossing) {
    const double e = std::fabs(epsilon), t = 2.0 * crossing;
    if (!(t < 0.5))
        return {crossing, t,   0.0,      HUGE_VAL, HUGE_VAL, HUGE_VAL, 0.0,
                HUGE_VAL, 0.0, HUGE_VAL, HUGE_VAL, HUGE_VAL, HUGE_VAL};
    // 8(t), "The layers' bound at full coupling": with the weights omega = (r - a)^(-1/2 - i eps) (b - r)^(-1/2 + i eps)
    // and omega (r - m + 2 i eps h) on the main stick zone (a, b), h = (b - a)/2 >= 1 - t,
    //   pi |Delta xi| <= J0 + 4 |eps| h |Delta lambda|,   |Delta lambda| <= (h + t) J0/(h^2 sqrt(1 + 4 eps^2)),
    // J0 = int_out |dF|/sqrt(|eta - a||eta - b|) <= pi (1 + kappa) c t/sqrt(1 - t) (both layers: int_0^t_a
    // sqrt(x)/sqrt(t_a - x) = pi t_a/2, sqrt((2 - x)/(2 - t_b - x)) <= 1/sqrt(1 - t)).
    const double lambda = 1.0 / (1.0 + 4.0 * epsilon * epsilon);
    const double c = M_2_PI * lambda * std::cosh(M_PI * epsilon);
    const double j0_over_pi = (1.0 + kappa_layers) * c * t / std::sqrt(1.0 - t);
    const double xi_bound = j0_over_pi * (1.0 + 4.0 * e / (1.0 - t));
    const double lambda_bound =
        M_PI * j0_over_pi * (1.0 + t) / ((1.0 - t) * (1.0 - t) * std::sqrt(1.0 + 4.0 * epsilon * epsilon));
    // In the layers |dF| <= (1 + kappa) c sqrt(x (2 - x)) <= (1 + kappa) c sqrt(2 t) (premise (ii)).
    const layers_peak peak =
        coupled_peak_bound(epsilon, c, t, j0_over_pi, lambda_bound, (1.0 + kappa_layers) * c * std::sqrt(2.0 * t));
    // The main stick zone's ends within t of the edges; reported at the edges (stick on [-1, 1]).
    return {crossing, t, 0.0, xi_bound, xi_bound, xi_bound, 0.0, t, 0.0, t, lambda_bound, peak.r, peak.p};
}

neglected_layers coupled_no_slip_layers(double beta_d, double f) {
    return coupled_layers_bound(bufler_epsilon(beta_d), coupled_layers_crossing(beta_d, f));  // 8(p), "The edges"
}

neglected_layers neglected_layers_at(double beta_d, double f, bool full) {
    return full ? coupled_no_slip_layers(beta_d, f) : no_slip_layers(beta_d, f);
}

layers_estimate neglected_layers_estimate(const neglected_layers& layers, double xi, double lambda, int n) {
    return {rounding_floor(n, lambda) + layers.lambda_bound, layers.trailing_bound,
            layers.xi_bound + 4.0 * DBL_EPSILON * std::fabs(xi), layers.leading_bound};
}

double neglected_layers_relative(const neglected_layers& layers, double xi, double lambda) {
    // rounding_floor grows with n, so the estimate at max_nodes is the largest of any rung's; the ladder allows each
    // quantity at least tol times the scale below (check_estimate), so relative <= tol passes its check at every rung.
    const layers_estimate e = neglected_layers_estimate(layers, xi, lambda, max_nodes);
    return std::max({e.xi / std::fabs(xi), e.lambda / std::fabs(lambda), e.c0, e.start});
}

tangential_solution coupled_no_slip_point(const no_slip_coupled_solution& limit, double f, const normal_solution& pressure,
                                          double rounding) {
    const neglected_layers layers = coupled_no_slip_layers(limit.beta_d, f);
    tangential_solution s = zone_solution(f, -1.0, 1.0, limit.xi, 0.0);
    s.forcing = limit.beta_d;
    s.layout = layers_neglected_layout();
    // Every check where the route models the contact, [-1 + t, 1 - t] (8(t), "Where the route checks"): (3.3) holds
    // there by construction (|p1| < f p inside the crossing t_c < t), and so does p >= 0 for the limit (its tension
    // lies within t_inf < t_c of the edges, atan f < pi/2). Inside the layers the model slips and the limit is not its
    // solution: the limit's tension there is part of dF = F - F_ns, |dF| <= (1 + kappa) c sqrt(2 t), which the
    // estimates of xi, P_H/P2 and the peak bound through J0 and S (8(t), "The layers' bound at full coupling"). Checked
    // over (-1, 1), p >= 0 refused a route its own advice had named (beta_D = 0.498, f = 10: t_inf = 2.4e-4 on the
    // check grid's outer points).
    const double t = std::min(layers.thickness, 0.5);
    const std::vector<zone> checked{{-1.0 + t, 1.0 - t, true, 0}};
    s.checks = check_zones(
        checked, {f, least_pressure(pressure, -1.0 + t, 1.0 - t), rounding, false, nullptr, nullptr},
        [&](double r) { return limit.pressure(r); }, [&](double r) { return limit.traction(r); },
        [](double) { return 0.0; });
    return s;
}

double coupled_no_slip_traction(const no_slip_coupled_solution& limit, double f, double pressure, double r) {
    // The bound from the pressure reported beside the traction (not the closed form's: they differ between the nodes,
    // by up to 2.8e-5 within 1e-3 of an edge at n = 128, 8(t) "Wired"), and never negative: with p < 0 the bound f p
    // would be negative and the clamp would return -f p = f |p|, of a sign unrelated to p1's (review N5).
    const double bound = f * std::max(0.0, pressure);
    return std::max(-bound, std::min(bound, limit.traction(r)));
}

double layers_crossing::friction_at(double t) const { return g0 + slope * std::log(x0 / t); }

layers_crossing johnson_layers_crossing(const normal_solution& normal, const kernel& k1, const kernel& k2,
                                        double beta_d, double f) {
    if (beta_d == 0.0 || !(f > 0.0)) throw input_error("the crossing of the edge layers needs beta_d != 0 and f > 0");
    // The no-slip solution: the stick zone [-1, 1] of (4.4) with Dundurs' forcing (dissimilar_zones.hpp), bounded at
    // both edges, Q = 0 (p even, p1 odd: 8(f)); its own solver, so that no level's factorisation is touched.
    tangential_solver solver(normal, k1, k2, f);
    const tangential_solution s = solver.solve_on_zone(-1.0, 1.0, beta_d);
    // |p1|/p at x from the edge, the larger of the two edges (x carried without r's rounding: x >= 1e-3 here).
    const auto g = [&](double x) {
        return std::max(std::fabs(solver.traction(s, -1.0 + x)) / normal.pressure(-1.0 + x),
                        std::fabs(solver.traction(s, 1.0 - x)) / normal.pressure(1.0 - x));
    };
    const double n = normal.rule.n;
    const double x0 = std::max(1e-3, 10.0 * 0.5 * M_PI * M_PI / (n * n));
    const double g0 = g(x0), slope = std::fabs(beta_d) / M_PI;
    if (g0 < f) return {x0 * std::exp(-(f - g0) / slope), x0, g0, slope};
    // From the centre (g = 0) outwards in steps of 1/4 in log x to the first point past f, then bisection.
    double inside = 0.0, outside = inside;
    for (;;) {
        outside = std::max(inside - 0.25, std::log(x0));
        if (g(std::exp(outside)) >= f) break;
        inside = outside;
    }
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (inside + outside);
        (g(std::exp(mid)) >= f ? outside : inside) = mid;
    }
    return {std::exp(0.5 * (inside + outside)), x0, g0, slope};
}

double no_slip_traction(double beta_d, double r) {
    if (!(r > -1.0 && r < 1.0)) return 0.0;
    // sqrt(1 - r^2) from (1 - r)(1 + r): no cancellation at either edge.
    return -2.0 * beta_d / (M_PI * M_PI) * std::sqrt((1.0 - r) * (1.0 + r)) * std::log((1.0 - r) / (1.0 + r));
}

double no_slip_creep(double beta_d) { return -4.0 * beta_d / (M_PI * M_PI); }

double layers_neglected_traction(const zone_layout& layout, double beta_d, double f, double pressure, double r) {
    // 8(n), "The layers' traction": the leading layer is one slip zone of the model, p1 = -sgn(beta_D) f p
    // exactly (8(g), 8(j) 4a, "Sharper: the leading layer"); the trailing layer slips with sgn(beta_D) where
    // it meets the main stick zone (the inner problem's slip+ on (Y2, Y1) t_c from the edge, where p1_ns
    // exceeds f p and the model holds it at f p), its last 0.24 t_c a stick zone and reversed slip, not
    // resolved: reported as that first slip. The no-slip traction would exceed f p in both (|p1_ns| = f p at
    // t_c from each edge, 8(g)), against the zones. The ends belong to the slip zones: p1 = +-f p there (the
    // model's traction is continuous at s1 and c1).
    // On the main stick zone the no-slip traction held to [-f p, f p]: it exceeds f p within t_c of either edge,
    // i.e. on [s1, -1 + t_c) and (1 - t_c, c1] (s1 and c1 lie 0.54 and 0.89 t_c from the edges), where the model's
    // stick traction obeys (3.3); the projection onto [-f p, f p] is never farther from it than p1_ns.
    const double limit = f * pressure;
    for (const zone& z : layout.zones)
        if (!z.stick && r >= z.from && r <= z.to) return z.direction * limit;
    return std::max(-limit, std::min(limit, no_slip_traction(beta_d, r)));
}

double layers_neglected_slip_velocity(const zone_layout& layout, double beta_d, double r) {
    // 8(n), "The layers' slip velocity": v = xi - H[p1] + beta_D p (D2) is Delta xi - H[d], d = p1 - p1_ns (p1_ns
    // solves the stick equation everywhere). On the leading layer's scale H[d] is O(sqrt(t_c)), Delta xi O(t_c):
    // v = -(2 beta_D/pi^2) sqrt(2 t_c) H[D](X), D the inner problem's solution, whose Hilbert transform on its slip
    // zone (0, A) is 2 sqrt(A) (sin theta - theta cos theta), cos^2 theta = X/A, at A = 4/e^2. With x = t_c X and
    // t_a = A t_c: sqrt(2 t_a) sin theta = sqrt(2 (t_a - x)), sqrt(2 t_a) cos theta = sqrt(2 x).
    const zone* lead = layout.zones.empty() || layout.zones.front().stick ? nullptr : &layout.zones.front();
    const zone* trail = layout.zones.empty() || layout.zones.back().stick ? nullptr : &layout.zones.back();
    if (trail != nullptr && trail != lead && r > trail->from && r <= trail->to)
        return std::numeric_limits<double>::quiet_NaN();  // slip, stick, reversed slip: not resolved (8(n))
    if (lead == nullptr || !(r >= lead->from && r < lead->to)) return 0.0;  // the main stick zone
    // x and t_a - x without cancellation: 1 + r is exact for r in [-1, -1/2] (Sterbenz), and so is t_a = 1 + s1.
    const double x = std::max(0.0, 1.0 + r), ta = 1.0 + lead->to, rest = std::max(0.0, ta - x);
    // theta = atan(sqrt(rest/x)) (pi/2 at the edge); sin theta - theta cos theta = theta^3/3 - theta^5/30 +
    // theta^7/840 - ... near s1 (the entry: v = O((s1 - r)^(3/2))), taken from the series below theta = 0.03, where
    // the difference would lose more (eps/theta^2) than the series' remainder (theta^6/15120, relative).
    const double theta = std::atan2(std::sqrt(rest), std::sqrt(x)), t2 = theta * theta;
    const double shape = theta < 0.03 ? std::sqrt(ta) * theta * t2 * (1.0 / 3.0 - t2 * (1.0 / 30.0 - t2 / 840.0))
                                      : std::sqrt(rest) - std::sqrt(x) * theta;  // sqrt(t_a) (sin - theta cos)
    return -4.0 * beta_d / (M_PI * M_PI) * M_SQRT2 * shape;
}

tangential_solution dissimilar_zones::layers_neglected_point() {
    const neglected_layers layers = no_slip_layers(beta_d_, f_);
    // The main stick zone [s1, c1] where the model has it (8(n)), its creep to first order in t_c; the
    // layers beyond it reported as the model's slip zones next to the main one (the leading layer is
    // that one slip zone; the trailing one holds slip, a stick zone and reversed slip, not resolved).
    const double s1 = -1.0 + layers.leading, c1 = 1.0 - layers.trailing;
    tangential_solution s = zone_solution(f_, s1, c1, no_slip_creep(beta_d_) + layers.xi_shift, 0.0);
    s.forcing = beta_d_;  // the frame's sign is 1: beta_D itself (8(h) is built into the closed form)
    s.layout = opposite_zones(s1, c1, beta_d_ > 0.0 ? 1 : -1);
    s.layout.route = zone_route::layers_neglected;
    // (3.3) outside the layers, where |p1| < f p by construction (the test that it is, 8(n)): on p1_ns itself,
    // which the reported traction (layers_neglected_traction) is there unless it exceeds f p. No slip zone is
    // checked: the leading layer's velocity has its direction by construction (sin theta > theta cos theta on
    // (0, pi/2], layers_neglected_slip_velocity), the trailing layer's is not resolved.
    const double t = std::min(layers.thickness, 0.5);
    const std::vector<zone> checked{{-1.0 + t, 1.0 - t, true, 0}};
    s.checks = check_zones(
        checked, blended_checks(), [&](double r) { return solver_.normal().pressure(r); },
        [&](double r) { return no_slip_traction(beta_d_, r); }, [](double) { return 0.0; });
    return s;
}

}  // namespace roughroll
