// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/gross_sliding.hpp"
#include "roughroll/problems/zone_family.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {
constexpr int start_scan = 32;  // trial starts of the stick zone, bracketing the entry condition
constexpr int newton_iterations = 40;
// Below this 1 - |Q|/f the search starts from gross sliding (continuation) before scanning.
constexpr double near_sliding = 1e-4;
// Below this half-length of the model zone it is returned when the discrete conditions are rounding.
constexpr double model_only = 1e-4;
// Newton's steps in the zone ends: psi(-1) carries rounding of about 1e-13 (a sum of n
// coefficients of the collocation solution), which moves the root by a few 1e-12; below
// 1e-11 the steps are that noise (measured), and Brent's 1e-15 is no closer.
constexpr double newton_tolerance = 1e-11;
}  // namespace

double zone_solver::load_excess(const tangential_solution& t, double magnitude) const {
    // Q - |Q| = rho int q - (f - |Q|) (4.5): f - |Q| is exact (Sterbenz, |Q| >= f/2 where it
    // matters) and rho int q = rho (pi/2) b_0 keeps its relative digits, where f + rho int q
    // rounds to ulp(f) = 5.6e-17 for f = 0.3: at |Q|/f = 1 - 1e-15 the gap is six ulps and the
    // zone ends found from Q itself were noise (docs/formulation.md 7(e)).
    const double integral = t.psi_b.empty() ? 0.0 : M_PI_2 * t.psi_b[0];  // int psi sqrt(1 - t^2)
    return t.rho() * integral + (f_ - magnitude);
}

zone_solver::zone_solver(tangential_solver& single) : single_(single), f_(single.friction()) {}

double zone_solver::entry_coefficient(const tangential_solution& s) {
    return s.psi_b.empty() ? 0.0 : u_series(s.psi_b, -1.0);  // psi(-1) = sum_j b_j U_j(-1)
}

zone_family zone_solver::family(double magnitude) {
    // Q(start, c0) falls from f (no stick zone, c0 = start) as the zone grows (7(c)), in the gap form
    // rho int q + (f - |Q|): Q - |Q| without the O(f) sum that cancels.
    return {[this, magnitude](double start) {
                return stick_zone_end(
                    [this, start, magnitude](double c0) {
                        return c0 <= start ? f_ - magnitude : load_excess(single_.solve_on_zone(start, c0), magnitude);
                    },
                    start);
            },
            [this](double start, double end) { return single_.solve_on_zone(start, end); }, entry_coefficient};
}

tangential_solution zone_solver::gross_sliding() {
    // w = G: xi = -f min G (docs/formulation.md 7(d)).
    return roughroll::gross_sliding(f_, f_, [this](const std::vector<double>& r) { return single_.G(r); },
                                    [this](double r) { return single_.G(r); });
}

std::optional<tangential_solution> zone_solver::newton(double magnitude, double start, double c0) {
    // Newton on F = (log(-rho int q / (f - |Q|)), psi(-1) / |b_0|) in the zone's midpoint m and
    // u = log rho (docs/formulation.md 7(e); zone_ends_newton): both components are relative, so they
    // keep their digits as the zone collapses at gross sliding (rho -> 0, f - |Q| -> 0), and F_0 is
    // close to linear in u (rho int q ~ -kappa rho^k), so Newton converges from a zone far off in
    // size, such as the continuation guess from gross sliding. Empty when it does not converge: the
    // caller falls back to Brent.
    const auto entry = [](const tangential_solution& t) { return entry_coefficient(t) / std::fabs(t.psi_b[0]); };
    return zone_ends_newton([this](double s, double c) { return single_.solve_on_zone(s, c); }, entry, f_ - magnitude,
                            start, c0, newton_iterations, newton_tolerance);
}

std::optional<tangential_solution> zone_solver::continuation(double magnitude) {
    // Near gross sliding the stick zone [s, c] is short around r*, the interior point where G is
    // least, and f G ~ f G* + f G''/2 (r - r*)^2 on it. In t, r - r* = rho (t + gamma) with
    // gamma = (m - r*)/rho, and the stick equation (section 7(a), kernel term O(rho)) is solved by
    // psi = b_0 + b_1 U_1, b_1 = -k/2, b_0 = -2 k gamma, k = f G'' rho^2 / 2 (the Cauchy operator
    // maps U_j sqrt(1 - t^2) to -T_{j+1}). Hence, to leading order in rho (docs/formulation.md 7(e)):
    //   entry condition psi(-1) = k (1 - 2 gamma) = 0:  gamma = 1/2, the zone [r* - rho/2, r* + 3 rho/2];
    //   f - |Q| = -rho int q = (pi/4) f G'' rho^3:        rho = cbrt(4 (f - |Q|) / (pi f G'')).
    // The residuals F_0 = log((f - Q)/(f - |Q|)) (from the gap form, which keeps its digits) and
    // F_1 = psi(-1)/|b_0| = (1 - 2 gamma)/(2 gamma) have, in (gamma, u = log rho), the model
    // Jacobian [[2, 3], [-2, 0]] at gamma = 1/2. The chord iteration with that fixed Jacobian
    // contracts by O(rho) per step and, unlike Newton with differenced Jacobians, is not thrown
    // off by the rounding of F (about 1e-4 relative at 1 - |Q|/f = 1e-15, where the variation
    // of f G over the zone, 1e-10, meets G's rounding, 1e-14). It stops when the step is below
    // newton_tolerance or stops shrinking (the rounding floor). Empty when r* is at an edge, or
    // G'' is not positive, or the iteration leaves [-1, 1] or fails to contract: the caller scans.
    const double gap = f_ - magnitude;
    if (!(gap > 0.0)) return std::nullopt;
    const double point = gross_sliding().c0;
    const double room = 0.5 * std::min(1.0 + point, 1.0 - point);
    if (!(room > 0.0)) return std::nullopt;
    const double h = std::min(1e-3, 0.5 * room);
    const double curvature = (single_.G(point - h) - 2.0 * single_.G(point) + single_.G(point + h)) / (h * h);
    if (!(curvature > 0.0 && std::isfinite(curvature))) return std::nullopt;
    const double model_rho = std::cbrt(4.0 * gap / (M_PI * f_ * curvature));
    // Where rounding hides the discrete conditions (F_1's rounding grows like n^2 and reaches O(1)
    // at n = 256 and 1 - |Q|/f = 1e-15 on the scene T = 100, A = 1), the model zone itself is the
    // answer: its error O(rho^2) (measured 1e-9 in rho at 1 - 1e-15) is below what the discrete
    // conditions resolve there. Only for rho < model_only, where that error is that small.
    const auto model_zone = [&]() -> std::optional<tangential_solution> {
        if (!(model_rho < model_only) || !(point - 0.5 * model_rho > -1.0 && point + 1.5 * model_rho <= 1.0))
            return std::nullopt;
        tangential_solution t = single_.solve_on_zone(point - 0.5 * model_rho, point + 1.5 * model_rho);
        t.iterations = 0;
        return t;
    };
    double rho = model_rho, gamma = 0.5;
    double last_step = std::numeric_limits<double>::infinity();
    for (int iteration = 1; iteration <= newton_iterations; ++iteration) {
        const double m = point + gamma * rho;
        // Iterates far from the model (more than its O(rho) corrections allow) are rounding's walk.
        if (!(m - rho > -1.0 && m + rho <= 1.0) || std::fabs(gamma - 0.5) > 0.1 ||
            std::fabs(std::log(rho / model_rho)) > 0.1)
            return model_zone();
        tangential_solution t = single_.solve_on_zone(m - rho, m + rho);
        const double deficit = -rho * M_PI_2 * t.psi_b[0];
        if (!(deficit > 0.0)) return model_zone();
        const double F0 = std::log(deficit / gap), F1 = entry_coefficient(t) / std::fabs(t.psi_b[0]);
        const double dgamma = 0.5 * F1, du = -(F0 + F1) / 3.0;
        const double next_rho = rho * std::exp(du), next_gamma = gamma + dgamma;
        const double step = std::fabs(point + next_gamma * next_rho - m) + std::fabs(next_rho - rho);
        if (step <= newton_tolerance || (iteration > 1 && step > 0.5 * last_step && step < 0.1 * rho)) {
            t.iterations = iteration;
            return t;
        }
        last_step = step;
        rho = next_rho;
        gamma = next_gamma;
    }
    return model_zone();
}

tangential_solution zone_solver::general(double magnitude, std::optional<zone_guess> guess,
                                         std::optional<double> single_end) {
    // The paper's zone first: if psi(-1) <= 0 at start = -1 it is the answer (7(b)).
    const zone_family zones = family(magnitude);
    const std::optional<double> edge_end = single_end ? single_end : zones.end(-1.0);
    if (!edge_end) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "zone solver: no stick zone from the leading edge carries |Q|/f = " << magnitude / f_;
        throw numerical_error(msg.str());
    }
    const tangential_solution at_edge = single_.solve_on_zone(-1.0, *edge_end);
    const double at_edge_entry = entry_coefficient(at_edge);
    if (at_edge_entry <= 0.0) return at_edge;
    // Near gross sliding: continuation from |Q| = f, where the zone collapses at the point r*
    // where G is least (7(d)); before the coarse level's guess, which rounding makes no better.
    if (f_ - magnitude <= near_sliding * f_)
        if (auto s = continuation(magnitude)) return *s;
    // Newton from the coarse level's zone when extrapolating.
    if (guess && guess->start > -1.0)
        if (auto s = newton(magnitude, guess->start, guess->c0)) return *s;
    // Else bracket the entry condition along the family of zones [s, c(s)] that carry |Q|
    // (7(e), zone_family.hpp): the starts towards the trailing edge until psi(-1) changes sign.
    std::vector<double> starts;
    for (int k = 1; k < start_scan; ++k) starts.push_back(-1.0 + 2.0 * k / start_scan);
    return first_bracket_zone(
        zones, scan_starts(zones, {{-1.0, *edge_end, at_edge_entry}}, starts, true),
        [&](double start, double end) { return newton(magnitude, start, end); },
        "general zone search: no stick zone between two slip zones carries this load (the entry condition "
        "psi(-1) = 0 has no root on the scanned starts): its zones have another structure; zones = \"auto\" "
        "reports the paper's single zone with its checks");
}

tangential_solution zone_solver::solve(double Q, bool force_general, std::optional<zone_guess> guess) {
    const double magnitude = load_magnitude(Q, f_);
    std::optional<double> single_end;
    if (!force_general || magnitude == 0.0) {
        tangential_solution s = single_.solve(Q);
        if (s.checks.hold() || magnitude == 0.0) return s;
        single_end = s.c0;
    }
    check_load_resolvable(magnitude, f_);
    const auto search = [&](std::optional<zone_guess> g) {
        return searched_point(magnitude == f_ ? gross_sliding() : general(magnitude, g, single_end), Q, "zone solver",
                              [this](const tangential_solution& t) { return single_.check(t); });
    };
    tangential_solution s = search(guess);
    // Newton from a guess may find another zone that solves both conditions but not the
    // inequalities (seen near s = 0.97 while it wandered): then search without the guess.
    if (guess && !s.checks.hold()) s = search(std::nullopt);
    return s;
}

}  // namespace roughroll
