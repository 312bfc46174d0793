// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/edge_layers.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/blended_cauchy.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/root_search.hpp"
#include "roughroll/problems/gross_sliding.hpp"
#include "roughroll/problems/zone_layout.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {
constexpr int start_scan = 32;           // trial starts of the stick zone
constexpr int shape_samples = 2001;      // samples of p for "even and decreasing" (complete slip)
constexpr std::size_t traction_memo_size = 1 << 16;  // points of traction's memo before it starts again
// The context of a fault in the blended zone's integrals (W and its Cauchy part), as the user reads it.
constexpr const char* w_context =
    "dissimilar rollers: the integral W of the blended stick zone (docs/formulation.md 8(g))";
// W of the blended zone and int p Theta (end_quadrature: qag in the variable that makes the integrands' 3/2-power
// ends and the sqrt at r = 1 analytic): the error GSL's own estimate may keep when it cannot reach its tolerances, a
// limit on each whole integral (W's Cauchy part, each of K1*'s terms, int p Theta), not on each of the pieces it is
// summed from (within_accepted).
constexpr double quadrature_accepted = 1e-10;

// Why no three zones answer a load (an unadvised_refusal: no zone of that structure at this n, which a
// point answers by five zones or refuses; never a numerical fault, docs/robustness.md).
std::string no_three_zones(double Q, double f, const std::string& why) {
    // Q/f in full (shortest): one ulp below sliding must not read as Q/f = 1, which gross sliding answers (session 29 audit).
    return "dissimilar rollers at Q/f = " + shortest(Q / f) + ": " + why + " (docs/formulation.md 8(g), 8(j))";
}
}  // namespace

void check_dissimilar(const dissimilar& materials, const solver_options& options) {
    check_beta_d(materials.beta_d);
    if (materials.beta_d == 0.0) return;  // the paper's problem at both coupling levels (8(d))
    const bool limit = options.how == method::one_parameter;  // Johnson's level only (8(s)); its paper's zone may hold
    const char* refusal =
        limit ? (materials.coupling == coupling_level::full
                     ? "coupling 'full' with method 'one-parameter' and beta_d != 0: only Johnson's level is derived "
                       "for the one-parameter limit (docs/formulation.md 8(s)); use coupling = \"johnson\", or method "
                       "'product' or 'extrapolated'"
                     : nullptr)
        : options.zones == zone_search::single
            ? "zones 'single' with beta_d != 0: the paper's stick zone from r = -1 is never the answer "
              "for dissimilar rollers (docs/formulation.md 8(g)); use 'auto' or 'general'"
            : nullptr;
    if (refusal) throw input_error(refusal);
}

namespace {
// kappa of leading_zone_estimate at the load Q (docs/formulation.md 8(j) item 11).
double edge_kappa(double beta_d, double f, double Q) {
    // With beta_D small against f, p1 is the beta_D = 0 traction plus the no-slip term of 8(g), whose
    // ratio to f p grows like (|beta_D|/(pi f)) log(2/(1 + r)) at the leading edge; Carter's traction
    // there has p1/(f p) = sgn(Q) (1 - sqrt(rho)), rho = sqrt(1 - |Q|/f) (2(f): q/(f p) -> sqrt(rho) as
    // r -> -1). The term pushes p1 towards -sgn(beta_D) f p (8(g): slip -sgn(beta_D) at the leading
    // edge), so it reaches the slip limit where its ratio exceeds kappa = sqrt(rho) for Q beta_D < 0 (a
    // braked roller 1: slip with Q), 2 - sqrt(rho) for Q beta_D > 0 (driven: slip against Q), 1 at free
    // rolling: a leading slip zone 2 exp(-pi f kappa/|beta_D|) thick.
    const double rho = std::sqrt(std::max(0.0, 1.0 - std::fabs(Q) / f));
    return Q == 0.0 ? 1.0 : Q * beta_d < 0.0 ? std::sqrt(rho) : 2.0 - std::sqrt(rho);
}
}  // namespace

double leading_zone_estimate(double beta_d, double f, double Q) {
    if (beta_d == 0.0) return 0.0;
    return 2.0 * std::exp(-M_PI * f * edge_kappa(beta_d, f, Q) / std::fabs(beta_d));
}

double thinnest_edge_zone(int n) {
    // A hundredth of the collocation's node spacing (pi^2/2)/n^2 at the end of a zone of half-length 1
    // (docs/formulation.md 8(j) item 11: measured, zones of a few times the spacing are resolved).
    return 0.01 * 0.5 * M_PI * M_PI / (static_cast<double>(n) * n);
}

void check_edge_zones_resolvable(double beta_d, double f, double Q, int n, double tolerance) {
    if (beta_d == 0.0 || !(std::fabs(Q) < f)) return;  // gross sliding: no zones to find (8(g))
    const double thickness = leading_zone_estimate(beta_d, f, Q), thinnest = thinnest_edge_zone(n);
    if (thickness >= thinnest) return;
    // The |beta_D| at which the estimate reaches the thinnest zone: pi f kappa/log(2/thinnest).
    const double needed = M_PI * f * edge_kappa(beta_d, f, Q) / std::log(2.0 / thinnest);
    // The n from which thinnest_edge_zone(n) is below the zone, where that n exists.
    const double first_n = std::ceil(std::sqrt(thinnest_edge_zone(1) / thickness));
    std::ostringstream msg;
    msg.precision(3);
    msg << "dissimilar rollers (beta_d = " << beta_d << ") at Q/f = " << shortest(Q / f) << " and n = " << n
        << ": the slip zone at the leading edge (";
    if (thickness > 0.0)
        msg << "about " << thickness << " of the half-width";
    else
        msg << "below the smallest double";
    msg << ") is thinner than the " << thinnest << " the zone search resolves (|beta_d| >= " << needed
        << " needed; docs/formulation.md 8(j) item 11)";
    if (first_n <= max_nodes)
        msg << "; a larger n (" << static_cast<int>(first_n) << " to " << max_nodes
            << ") passes this bound, but the search is not known to answer near it";
    else
        msg << "; no n up to " << max_nodes << " resolves it, so the load is beyond the method's reach for these "
            << "rollers";
    // Equal materials move xi by at most max(p) |beta_D| = (2/pi) |beta_D| on Hertz's pressure at both limits of
    // 8(f) (complete slip: beta_D p(r_c); no slip: (4/pi^2) |beta_D|), against a creep of at least |Q|/pi (no slip
    // Q/pi; Carter's (2f/pi)(1 - sqrt(1 - |Q|/f)) above it): a relative change of at most 2 |beta_D|/|Q|, within
    // the user's relative tolerance where 2 |beta_D| <= tolerance |Q| (never at free rolling).
    if (2.0 * std::fabs(beta_d) <= tolerance * std::fabs(Q))
        msg << "; set beta_d = 0 (equal materials) for the paper's problem, whose results differ by O(beta_d)";
    throw resolution_error(msg.str());
}

double load_between(const normal_solution& normal, double lo, double hi) {
    // p = phi(r) sqrt(1 - r^2), phi = sum_j b_j U_j(r) (4.1). With r = cos theta,
    // int U_j sqrt(1 - r^2) dr = int sin((j + 1) theta) sin(theta) d theta
    //   = (1/2) int [cos(j theta) - cos((j + 2) theta)] d theta, from theta(hi) to theta(lo).
    const double t_lo = std::acos(std::clamp(hi, -1.0, 1.0)), t_hi = std::acos(std::clamp(lo, -1.0, 1.0));
    const auto primitive = [](int j, double t) {
        const double first = j == 0 ? t : std::sin(j * t) / j;
        return 0.5 * (first - std::sin((j + 2) * t) / (j + 2));
    };
    double sum = 0.0;
    for (std::size_t j = 0; j < normal.b.size(); ++j) {
        const int k = static_cast<int>(j);
        sum += normal.b[j] * (primitive(k, t_hi) - primitive(k, t_lo));
    }
    return normal.kinks ? sum + normal.kinks->integral(lo, hi) : sum;  // p_q^0's part (8(l) step 0, 8(o))
}

complete_slip complete_slip_creep(const normal_solution& normal, double beta_d, double Q_over_f) {
    check_beta_d(beta_d);
    if (beta_d == 0.0) throw input_error("complete slip: beta_d = 0 has no complete-slip creep of order beta_d");
    if (!(std::fabs(Q_over_f) <= 1.0)) throw input_error("complete slip: |Q/f| must be at most 1");
    // 8(f) needs p even and decreasing in |r|: then sgn(beta_D) v > 0 exactly on a central band.
    const double scale = normal.pressure(0.0);
    double previous = scale;
    for (int i = 1; i < shape_samples; ++i) {
        const double r = static_cast<double>(i) / (shape_samples - 1) * (1.0 - 1e-9);
        const double p = normal.pressure(r), mirrored = normal.pressure(-r);
        if (std::fabs(p - mirrored) > 1e-10 * scale || p > previous + 1e-12 * scale)
            throw input_error(
                "complete slip (docs/formulation.md 8(f)): the pressure is not even and decreasing in "
                "|r| (at r = " +
                shortest(r) + "), so the central band of slip is not derived");
        previous = p;
    }
    const double target = 0.5 * (1.0 + (beta_d > 0.0 ? Q_over_f : -Q_over_f));
    const double total = load_between(normal, -1.0, 1.0);
    complete_slip c{};
    if (target <= 0.0) {
        c.r_c = 0.0;
    } else if (target >= total) {
        c.r_c = 1.0;
    } else {
        c.r_c = brent_root([&](double r) { return load_between(normal, -r, r) - target; }, 0.0, 1.0, 1e-15, 0.0, 200,
                           "complete slip: the edge of the central band")
                    .x;
    }
    c.xi = -beta_d * normal.pressure(c.r_c);
    return c;
}

dissimilar_zones::dissimilar_zones(tangential_solver& solver, const kernel& k1, double beta_d)
    : solver_(solver),
      k1_(k1),
      beta_d_(beta_d),
      f_(solver.friction()),
      pressure_b_(solver.normal().b),
      pressure_kinks_(solver.normal().kinks) {
    check_beta_d(beta_d);
    // The pressure's U-series without its exact trailing zeros (Hertz: one term): the same values
    // (u_series skips them too, bit for bit), trimmed once here so that the many values W's
    // quadrature takes do not each scan them.
    pressure_b_.resize(significant_terms(pressure_b_));
    // A rough layer's pressure keeps all n terms (they fall algebraically, not below rounding), and W
    // takes its values by the hundred thousand per zone solve: a table whose representation error is
    // bounded by eps sum |b_j| gives them at the cost of an acos and a panel's 25 terms
    // (u_series_table.hpp). Up to twice that many terms the series is summed as it is (measured
    // slower with the table at 32 terms; docs/performance.md), and Hertz's one term stays exact. Built at the
    // first value asked (table()): a structure that never asks (the three zones of one direction: each step of
    // full coupling's alternation builds this workspace) does not pay for it.
}

const u_series_table* dissimilar_zones::table() const {
    if (!pressure_table_ && pressure_b_.size() > static_cast<std::size_t>(2 * theta_panels::degree + 2))
        pressure_table_.emplace(pressure_b_);
    return pressure_table_ ? &*pressure_table_ : nullptr;
}

double dissimilar_zones::pressure(double r) const {
    if (std::fabs(r) >= 1.0) return 0.0;
    const u_series_table* tabulated = table();
    const double smooth = tabulated ? (*tabulated)(r) : u_series(pressure_b_, r) * std::sqrt(1.0 - r * r);  // (4.1)
    return pressure_kinks_ ? smooth + (*pressure_kinks_)(r) : smooth;  // as normal_solution::pressure (8(l))
}

double dissimilar_zones::H(double r, double start, double c0) const {
    // 0 on the leading slip zone, Theta(t) on the stick zone, 1 on the trailing slip zone (8(g)).
    if (r <= start) return 0.0;
    if (r >= c0) return 1.0;
    const double t = std::clamp((r - start) / (0.5 * (c0 - start)) - 1.0, -1.0, 1.0);
    return 0.5 + M_1_PI * (std::asin(t) + t * std::sqrt(1.0 - t * t));
}

const blended_cauchy* dissimilar_zones::blend_of(double start, double c0) {
    return blends_(start, c0, [&] { return blended_cauchy::make(pressure_b_, start, c0); });
}

const kinks_blend* dissimilar_zones::kinks_blend_of(double start, double c0) {
    return kinks_blends_(start, c0, [&] { return pressure_kinks_->blend(start, c0); });
}

double dissimilar_zones::W(double r, double start, double c0) {
    return W(std::vector<double>{r}, start, c0).front();  // the batched sums are bit for bit the pointwise ones
}

std::vector<double> dissimilar_zones::W(const std::vector<double>& r, double start, double c0) {
    // W(r) = L1[p H](r) = (1/pi) PV int_s^1 g(eta)/(eta - r) d eta + int_s^1 g(eta) K1*(eta - r) d eta, g = p H
    // (zero on [-1, s)). The Cauchy part is linear in p = sqrt(1 - r^2) phi + p_q^0: that of the U-series as a mean
    // of steps in closed form (blended_cauchy, docs/formulation.md 8(g) "W of the blend as a mean of steps"), and
    // with the kinks carried (full coupling, 8(l) step 0) that of p_q^0 H by Tricomi's identity (kinks_blend,
    // 8(o) "W with the kinks"). Where either declines (a zone at an edge), the whole p by adaptive quadrature.
    // The closed forms' n-term sums are taken for all points of r side by side (bit for bit as point by point).
    const std::size_t count = r.size();
    std::vector<std::optional<double>> cauchy(count);
    if (const blended_cauchy* blend = blend_of(start, c0)) (*blend)(r.data(), cauchy.data(), count);
    if (pressure_kinks_ && std::any_of(cauchy.begin(), cauchy.end(), [](const auto& w) { return w.has_value(); })) {
        const kinks_blend* kinks = kinks_blend_of(start, c0);
        std::vector<std::optional<double>> part(count);
        if (kinks) {
            std::vector<double> blends(count);
            for (std::size_t i = 0; i < count; ++i) blends[i] = H(r[i], start, c0);
            (*kinks)(r.data(), blends.data(), part.data(), count);
        }
        for (std::size_t i = 0; i < count; ++i)
            cauchy[i] = cauchy[i] && part[i] ? std::optional<double>(*cauchy[i] + *part[i]) : std::nullopt;
    }
    std::vector<double> w(count);
    for (std::size_t i = 0; i < count; ++i) w[i] = completed_W(r[i], cauchy[i], start, c0);
    return w;
}

double dissimilar_zones::completed_W(double r, const std::optional<double>& cauchy, double start, double c0) {
    // The Cauchy part where the closed forms declined, by adaptive quadrature; then the terms of K1*.
    double w = cauchy ? *cauchy : cauchy_by_quadrature(r, start, c0);
    if (k1_.terms().empty()) return w;
    const auto g = [&](double eta) { return pressure(eta) * H(eta, start, c0); };
    const std::vector<double> points = breakpoints(r, start, c0);
    for (const auto& term : k1_.terms()) {
        const std::function<double(double)> integrand = [&](double eta) {
            const double z = eta - r;
            return z == 0.0 ? 0.0 : g(eta) * std::exp(-term.A * std::fabs(z)) * (z > 0.0 ? 1.0 : -1.0);
        };
        // Cut in the angle where one GSL call over a piece meets its rounding (end_quadrature::pieces, 8(p)): p's
        // U-series oscillates across [c0, r] (about n/2 periods over the angle pi), which GSL's 21-point rule reads as
        // error that bisection does not reduce (GSL_EROUND; measured: the rough pair driven at Q/f = 0.9, full coupling,
        // n = 384 and 512, 6e-10..3e-9 on [c0, r] for r near the edge, docs/formulation.md 8(u)). Where one call
        // succeeds, pieces keeps its value bit for bit.
        w += term.T * integrate_over(points, w_context, true, integrand);
    }
    return w;
}

std::vector<double> dissimilar_zones::breakpoints(double r, double start, double c0) const {
    std::vector<double> points{start, 1.0};
    if (c0 > start && c0 < 1.0) points.push_back(c0);
    // r as a breakpoint only away from the others: an interval of a few ulp (r = 1 - 1e-16, reached by
    // sampling towards the edge) leaves qagp nothing to bisect, and reports round-off.
    const bool inside = r > start && r < 1.0;
    if (inside && std::fabs(r - c0) > breakpoint_apart && 1.0 - r > breakpoint_apart && r - start > breakpoint_apart)
        points.push_back(r);
    if (pressure_kinks_) add_kink_points(points, *pressure_kinks_, breakpoint_apart);  // p's one-sided roots (8(o))
    std::sort(points.begin(), points.end());
    return points;
}

double dissimilar_zones::cauchy_by_quadrature(double r, double start, double c0) {
    // (1/pi) PV int_s^1 g(eta)/(eta - r) d eta, g = p H. Inside (s, 1) with g(r) subtracted,
    // int (g(eta) - g(r))/(eta - r) + g(r) log((1 - r)/(r - s)); the breakpoints are s, c0, r, 1 and the kinks' ends.
    const auto g = [&](double eta) { return pressure(eta) * H(eta, start, c0); };
    const bool inside = r > start && r < 1.0;
    const double gr = inside ? g(r) : 0.0;
    const std::vector<double> points = breakpoints(r, start, c0);
    // r within `breakpoint_apart` of the trailing edge (not cut there; up to nextafter(1, 0)): subtracting the
    // constant g(r) leaves (g(eta) - g(r))/(eta - r) ~ -1/(sqrt(1 - eta) + sqrt(1 - r)), a spike of
    // height 1/sqrt(1 - r) and width 1 - r at eta = 1 that no quadrature resolves (GSL: round-off).
    // There g = sqrt(1 - eta) h(eta) on the last piece [a, 1], h = phi(eta) sqrt(1 + eta) H smooth
    // ((4.1)), and sqrt(1 - eta) h(r) is subtracted instead: the rest, sqrt(1 - eta) (h(eta) - h(r))/
    // (eta - r), is smooth times the square root that end_quadrature makes analytic, and with
    // u = sqrt(1 - eta), d = sqrt(1 - r), U = sqrt(1 - a) (docs/formulation.md 8(j) item 3)
    //   PV int_a^1 sqrt(1 - eta)/(eta - r) d eta = int_0^U 2 u^2/(d^2 - u^2) du = -2 U + d log((U + d)/(U - d)).
    // The pieces below a (r outside them) carry no subtraction. p at eta near 1 from sqrt((1 - eta)(1 + eta)),
    // exact for the node eta, where 1 - eta^2 loses 1 - eta's digits; p_q^0 likewise from its factor (8(o)).
    const double a = points[points.size() - 2];
    if (inside && !(1.0 - r > breakpoint_apart) && r - a > breakpoint_apart) {
        // p/sqrt(1 - eta^2): phi (the series, or its table's p divided back) + p_q^0's factor.
        const auto edge_pressure = [&](double eta) {
            if (!(eta < 1.0)) return 0.0;
            const double root = std::sqrt((1.0 - eta) * (1.0 + eta));
            const double kinks = pressure_kinks_ ? pressure_kinks_->factor(eta) * root : 0.0;
            const u_series_table* tabulated = table();
            return (tabulated ? (*tabulated)(eta) : u_series(pressure_b_, eta) * root) + kinks;
        };
        const double kr = pressure_kinks_ ? pressure_kinks_->factor(r) : 0.0;  // p_q^0/sqrt(1 - r^2) (8(o))
        const double hr = (u_series(pressure_b_, r) + kr) * std::sqrt(1.0 + r) * H(r, start, c0);  // h(r)
        const double d = std::sqrt(1.0 - r), U = std::sqrt(1.0 - a);
        const auto subtracted = [&](bool last) -> std::function<double(double)> {
            return [&, last](double eta) {
                if (eta == r) return 0.0;  // a bounded integrand's single point
                const double ge = edge_pressure(eta) * H(eta, start, c0);
                return (last ? ge - std::sqrt(1.0 - eta) * hr : ge) / (eta - r);
            };
        };
        const double w = integrate_over(points, w_context, false, subtracted(false), subtracted(true));
        return M_1_PI * (w + hr * (-2.0 * U + d * std::log((U + d) / (U - d))));
    }
    double w = M_1_PI * integrate_over(points, w_context, true, [&](double eta) { return (g(eta) - gr) / (eta - r); });
    if (gr != 0.0) w += M_1_PI * gr * std::log((1.0 - r) / (r - start));
    return w;
}

double dissimilar_zones::integrate_over(const std::vector<double>& points, const char* what, bool cut,
                                        const std::function<double(double)>& integrand,
                                        const std::function<double(double)>& last) {
    return within_accepted(points.size() - 1, quadrature_accepted, [&](std::size_t i, double accepted) {
               const std::function<double(double)>& piece = last && i + 2 == points.size() ? last : integrand;
               return cut ? quadrature_.pieces(piece, points[i], points[i + 1], solver_.normal().rule.n, what, accepted)
                          : quadrature_.piece(piece, points[i], points[i + 1], what, accepted);
           }).value;
}

double dissimilar_zones::load_under_H(double start, double c0) {
    // int p H = int_s^c p Theta (end_quadrature) + int_c^1 p (closed form, load_between).
    // On the weighted pressure (the U-series zero) int_s^c p Theta by W's fixed rule (kinks_blend::zone_load,
    // docs/formulation.md 8(x) "W's routes"): end_quadrature on the first five-zone stick zone, where p carries q's
    // n-term series, erred by 8e-12 at n = 1000 with GSL's estimate 4e-13.
    if (pressure_kinks_ && pressure_kinks_->weighted() &&
        std::all_of(pressure_b_.begin(), pressure_b_.end(), [](double b) { return b == 0.0; }))
        if (const kinks_blend* kinks = kinks_blend_of(start, c0))
            if (const std::optional<double> zone = kinks->zone_load()) return *zone + load_between(solver_.normal(), c0, 1.0);
    const std::function<double(double)> pressure_theta = [&](double x) { return pressure(x) * H(x, start, c0); };
    std::vector<double> points{start, c0};
    if (pressure_kinks_) add_kink_points(points, *pressure_kinks_, 1e-9);  // p's one-sided roots (8(o))
    std::sort(points.begin(), points.end());
    return integrate_over(points, "dissimilar rollers: the load of the blended stick zone (docs/formulation.md 8(g))",
                          true, pressure_theta) +
           load_between(solver_.normal(), c0, 1.0);
}

std::vector<double> dissimilar_zones::blended_G(const std::vector<double>& r, const std::function<double(double)>& phi) {
    std::vector<double> g = solver_.G(r);
    const normal_solution& normal = solver_.normal();
    if (normal.projected.empty() || !k1_.empty()) return g;
    for (std::size_t m = 0; m < r.size(); ++m) {
        const double weight = phi(r[m]);
        if (weight != 0.0) g[m] += weight * (normal.projected_minus_hilbert(r[m]) - g[m]);
    }
    return g;
}

tangential_solution dissimilar_zones::blended(double start, double c0, double b) {
    // 8(g) in the |Q| frame, leading slip -1, trailing +1: L1[q] = xi' + b p - f L1[p S] on the stick zone, S = 2 H - 1.
    // L1[p S] = L1[p_d S] + L1[(p - p_d) S] with L1[p_d S] = G_d + 2 W from the discrete p_d, and the second term as
    // S(r) L1[p - p_d] = -S (G - G_d) (8(u)): at each end the slip side beyond it (S = +1 beyond the exit, -1 before
    // the entry) is then read through G's formula, which carries the pressure's kinks exactly, and p_d's residual
    // there drops out. So L1[p S] = G + 2 W - 2 H (G - G_d) = 2 G_H + 2 W - G, G_H = (1 - H) G + H G_d, and the
    // right side is that of solve_on_zone (xi' + f G + b p) plus -2 f (G_H + W). (With G_H = G the projection's residual
    // of the kink beyond the exit reached c: order 1, 8(u).)
    const std::vector<double> r = solver_.collocation_points(start, c0);
    const std::vector<double> g = blended_G(r, [&](double x) { return H(x, start, c0); }), w = W(r, start, c0);
    std::vector<double> extra(r.size());
    for (std::size_t m = 0; m < r.size(); ++m) extra[m] = -2.0 * f_ * (g[m] + w[m]);
    tangential_solution s = solver_.solve_on_zone(start, c0, b, &extra);
    // Q' = f (2 int p H - 1) + rho int q, where solve_on_zone gave f + rho int q.
    s.Q += 2.0 * f_ * load_under_H(start, c0) - 2.0 * f_;
    s.layout = opposite_zones(start, c0);
    return s;
}

stick_zone_operator dissimilar_zones::zone_operator(bool opposite, double b, double magnitude) {
    // The three zones of 8(g) in the |Q| frame with the forcing b: both slip zones with Q (the collocation
    // with Dundurs' forcing b p), or the leading one against it (the blended zone).
    stick_zone_operator op;
    op.f = f_;
    // The paper's zone from r = -1 is never the answer (8(g)).
    op.paper_zone = [](double, bool) -> std::optional<tangential_solution> { return std::nullopt; };
    op.solve = [this, b, opposite](double start, double c0) {
        return opposite ? blended(start, c0, b) : solver_.solve_on_zone(start, c0, b);
    };
    op.excess = [](const tangential_solution& t, double load) { return t.Q - load; };
    // Q' with no stick zone: f (both slip zones with Q), or p1 = -f p before the start and f p after it.
    op.empty_load = [this, opposite](double start) {
        return opposite ? f_ * (1.0 - 2.0 * load_between(solver_.normal(), -1.0, start)) : f_;
    };
    op.entry = op.newton_entry = zone_solver::entry_coefficient;  // psi(-1) = 0 (7(b)), absolute
    op.gross_sliding = [this, b] { return gross_sliding(b); };
    op.check = [this](const tangential_solution& t) { return check(t); };
    // Of this kind only: solve tries the other. The message is the user's where no caller answers the load.
    std::ostringstream refusal;
    refusal.precision(6);
    refusal << "dissimilar rollers at |Q|/f = " << magnitude / f_
            << ": no three zones carry the load at n = " << solver_.normal().rule.n
            << "; another n may find them (docs/formulation.md 8(g), 8(j))";
    op.method.name = "dissimilar rollers' zone search";
    op.method.refusal = refusal.str();
    // The starts clustered towards both edges (Chebyshev), where thin leading slip zones put the start, all
    // scanned; each bracket in turn from the leading edge, the first zone whose checks hold the answer; no zone
    // from the leading edge; Newton's residuals absolute, its steps down to the entry's rounding
    // (zone_end_resolution).
    op.method.scan = start_scan;
    op.method.clustered = true;
    op.method.every_bracket = true;
    op.method.edge = edge_zone::absent;
    op.method.relative_load = false;
    op.method.newton_tolerance = zone_end_resolution;
    return op;
}

double dissimilar_zones::traction(const tangential_solution& s, double r) {
    if (s.layout.stick_zones() == 2) {
        // Full coupling asks the previous iterate's p1 at the same points again and again (G of every zone solve
        // and slip velocity of a five-zone system, 8(e)): each value once per point (the same value, bit for bit).
        // The memo holds the solution it is for, so that its address is not another's while it is kept.
        if (tractions_of_ != s.zone_systems || tractions_.size() > traction_memo_size) {
            tractions_of_ = s.zone_systems;
            tractions_.clear();
        }
        const auto [at, fresh] = tractions_.try_emplace(r, 0.0);
        if (fresh) at->second = stick_zones_traction(s, r);
        return at->second;
    }
    if (s.layout.layers_neglected())  // 8(n): f p on the layers, the no-slip traction on the main stick zone
        return layers_neglected_traction(s.layout, beta_d_, f_, solver_.normal().pressure(r), r);
    // solver_.traction is sign (f p + q0); the blended zone subtracts 2 f p (1 - H) (8(g)).
    const double t = solver_.traction(s, r);
    if (!s.layout.opposite()) return t;
    return t - s.sign * 2.0 * f_ * solver_.normal().pressure(r) * (1.0 - H(r, s.start(), s.c0()));
}

double dissimilar_zones::slip_velocity(const tangential_solution& s, double r) {
    if (s.layout.stick_zones() == 2) return stick_zones_slip_velocity(s, r);
    if (s.layout.layers_neglected()) return layers_neglected_slip_velocity(s.layout, beta_d_, r);  // 8(n)
    const double v = solver_.slip_velocity(s, r);
    if (!s.layout.opposite() || s.sticks(r)) return v;
    // L1[p S] as on the stick zone (blended): G_H = G on the leading slip zone (H = 0), G_d on the trailing one (8(u)).
    const double x = std::clamp(r, -1.0, 1.0);
    const double g = blended_G({x}, [&](double y) { return H(y, s.start(), s.c0()); }).front();
    return v - s.sign * 2.0 * f_ * (g + W(x, s.start(), s.c0()));
}

traction_checks dissimilar_zones::check(const tangential_solution& s) {
    if (!s.layout.opposite()) return solver_.check(s);
    // (3.3) on the stick zones, (3.4) on the slip zones with their own directions (the layout). Five zones with the
    // pressure their systems take (pressure, five_zone_system), their traction apart from traction's memo (which keeps
    // full coupling's previous iterate while its step's answer is checked).
    const bool five = s.layout.stick_zones() == 2;
    return check_zones(
        s.layout.zones, opposite_checks(s), [&](double r) { return five ? pressure(r) : solver_.normal().pressure(r); },
        [&](double r) { return five ? stick_zones_traction(s, r) : traction(s, r); },
        [&](double r) { return slip_velocity(s, r); });
}

zone_check_terms dissimilar_zones::opposite_checks(const tangential_solution& s) {
    // The stick zones' systems cancel the right side xi + b p - f G - 2 f W (8(g)) to q = O(f): its terms are of size
    // S = |xi| + |beta_D| max(1, P_H/P2) + f K, so the margins (3.3)-(3.4), relative to f, carry a rounding of
    // 8 n eps S / f, as the single zone's of 7(d) with the forcing's term (8(m)'s S). Near complete slip (f << |beta_D|)
    // that exceeds the true stick margin: held to 0 there, a root failed by rounding alone (docs/formulation.md 8(f),
    // "Below the rounding", "The floor of the opposite zones"). rounding(x) is the floor of terms |x| + f K.
    const double forcing = std::fabs(beta_d_) * std::max(1.0, std::fabs(solver_.normal().lambda));
    const double floor = solver_.rounding(std::fabs(s.xi) + forcing);
    return {f_, solver_.pressure_margin(), floor, true, nullptr, nullptr};
}

zone_check_terms dissimilar_zones::blended_checks() {
    // The blended zones of 8(g): margins held to 0 (the floor reported is the |Q| system's at xi = 0).
    return {f_, solver_.pressure_margin(), solver_.rounding(0.0), false, nullptr, nullptr};
}

tangential_solution dissimilar_zones::gross_sliding(double b) {
    // w = b p + f G (8(g)), least at either edge or inside.
    return roughroll::gross_sliding(
        solver_.normal(), f_, b, [this](const std::vector<double>& r) { return solver_.G(r); }, true,
        "dissimilar rollers at gross sliding");
}

tangential_solution dissimilar_zones::solve(double Q, const std::vector<double>& ends, bool opposite, bool only_this_kind) {
    ++three_zone_searches_;
    const double magnitude = load_magnitude(Q, f_);
    if (magnitude == 0.0)
        throw unadvised_refusal(no_three_zones(Q, f_,
                                               "free rolling has five zones (slip, stick, reversed slip, stick, slip), "
                                               "not three"));
    check_load_resolvable(magnitude, f_);
    const double b = (Q > 0.0 ? 1.0 : -1.0) * beta_d_;  // the mirror of 8(h): the |Q| problem's forcing
    // The structure the hint names first (the coarser level's, when extrapolating), then the other one: both slip
    // zones in the direction of Q, or the leading one against it (at |Q| = f both are the zone search's gross
    // sliding). The first whose checks hold is the answer; else one that fails them, for the caller to refuse.
    // A structure with no zone is an empty find; a numerical fault (a GSL status, a singular system) of either search
    // is kept and, where neither structure answers, rethrown as the fault; where neither answers and a Newton of either
    // stopped at the ends' rounding limit, that is the refusal (zone_newton.hpp). The structures are the search's starts
    // (first_holding, zone_start.hpp).
    std::optional<numerical_error> fault;
    rounding_limits met;
    std::vector<bool> structures{opposite};
    if (!only_this_kind) structures.push_back(!opposite);
    std::optional<tangential_solution> found = search_from<tangential_solution>(structures, [&](bool blend) {
        start_verdict<tangential_solution> verdict;
        try {
            verdict.root = zone_solver(zone_operator(blend, b, magnitude)).find(magnitude, false, ends, met);
        } catch (const resolution_error&) {
        } catch (const numerical_error& e) {
            if (!fault) fault = e;
        }
        return verdict;
    });
    if (!found && fault) throw *fault;
    if (!found && met.met()) throw rounding_limit_error(met.refusal());
    if (!found)
        throw unadvised_refusal(
            no_three_zones(Q, f_, "no three zones (slip in either direction at each edge) carry Q"));
    tangential_solution s = std::move(*found);
    s.layout.route = zone_route::general;  // gross sliding's too, where r* = -1 (the paper's edge form)
    // The checks of the |Q| problem (the zone search made them) are those of Q: the mirror of 8(h) changes
    // the signs of p1 and v together.
    apply_load_sign(s, Q, "dissimilar rollers");
    return s;
}

void require_checks(const tangential_solution& s) {
    if (s.checks.hold()) return;
    throw unadvised_refusal(no_three_zones(
        s.Q, s.f,
        "the three zones (slip in either direction at each edge) fail the checks (3.3)-(3.4) (margins: " +
            margins_text(s.checks) + ")"));
}

}  // namespace roughroll
