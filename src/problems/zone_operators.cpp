// SPDX-License-Identifier: GPL-3.0-or-later
// The two stick-zone operators of the one zone search (stick_zone_operator.hpp, zone_solver.hpp): the
// collocation of (4.4) and the Glauert system of the one-parameter limit, the parts they share (the zone's
// system, the load's excess, gross sliding, the checks: tangential_problem::zone_operator_of), and each one's entry
// condition and zone near gross sliding to leading order (docs/formulation.md 7(e), 7(g)).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/one_parameter.hpp"
#include "roughroll/problems/stick_zone_operator.hpp"
#include "roughroll/problems/tangential_solver.hpp"
#include "roughroll/problems/zone_solver.hpp"

namespace roughroll {

namespace {
// The collocation's steps in the zone ends: psi(-1) carries rounding of about 1e-13 (a sum of n
// coefficients of the collocation solution), which moves the root by a few 1e-12; below 1e-11 the
// steps are that noise (measured), and Brent's 1e-15 is no closer.
constexpr double collocation_tolerance = 1e-11;

// The refusal where the scan of starts ends on no bracket of the entry condition (zone_solver::general).
std::string no_zone_between_slips(const char* search, const char* entry, const char* single_exists) {
    return std::string(search) + ": no stick zone between two slip zones carries this load (the entry condition " +
           entry +
           " = 0 has no root on the scanned starts): its zones have another structure; zones = \"auto\" "
           "reports the paper's single zone with its checks" +
           single_exists;
}

std::optional<tangential_solution> continuation(tangential_solver& single, double magnitude, double point) {
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
    // collocation_tolerance or stops shrinking (the rounding floor). Empty when r* is at an edge, or
    // G'' is not positive, or the iteration leaves [-1, 1] or fails to contract: the caller scans.
    constexpr int iterations = 40;
    // Below this half-length the model zone is returned when the discrete conditions are rounding.
    constexpr double model_only = 1e-4;
    const double f = single.friction(), gap = f - magnitude;
    if (!(gap > 0.0)) return std::nullopt;
    const double room = 0.5 * std::min(1.0 + point, 1.0 - point);
    if (!(room > 0.0)) return std::nullopt;
    const double h = std::min(1e-3, 0.5 * room);
    const double curvature = (single.G(point - h) - 2.0 * single.G(point) + single.G(point + h)) / (h * h);
    if (!(curvature > 0.0 && std::isfinite(curvature))) return std::nullopt;
    const double model_rho = std::cbrt(4.0 * gap / (M_PI * f * curvature));
    // Where rounding hides the discrete conditions (F_1's rounding grows like n^2 and reaches O(1)
    // at n = 256 and 1 - |Q|/f = 1e-15 on the scene T = 100, A = 1), the model zone itself is the
    // answer: its error O(rho^2) (measured 1e-9 in rho at 1 - 1e-15) is below what the discrete
    // conditions resolve there. Only for rho < model_only, where that error is that small.
    const auto model_zone = [&]() -> std::optional<tangential_solution> {
        if (!(model_rho < model_only) || !(point - 0.5 * model_rho > -1.0 && point + 1.5 * model_rho <= 1.0))
            return std::nullopt;
        tangential_solution t = single.solve_on_zone(point - 0.5 * model_rho, point + 1.5 * model_rho);
        t.iterations = 0;
        return t;
    };
    double rho = model_rho, gamma = 0.5;
    double last_step = std::numeric_limits<double>::infinity();
    for (int iteration = 1; iteration <= iterations; ++iteration) {
        const double m = point + gamma * rho;
        // Iterates far from the model (more than its O(rho) corrections allow) are rounding's walk.
        if (!(m - rho > -1.0 && m + rho <= 1.0) || std::fabs(gamma - 0.5) > 0.1 ||
            std::fabs(std::log(rho / model_rho)) > 0.1)
            return model_zone();
        tangential_solution t = single.solve_on_zone(m - rho, m + rho);
        const double deficit = -rho * M_PI_2 * t.psi_b[0];
        if (!(deficit > 0.0)) return model_zone();
        const double F0 = std::log(deficit / gap), F1 = zone_solver::entry_coefficient(t) / std::fabs(t.psi_b[0]);
        const double dgamma = 0.5 * F1, du = -(F0 + F1) / 3.0;
        const double next_rho = rho * std::exp(du), next_gamma = gamma + dgamma;
        const double step = std::fabs(point + next_gamma * next_rho - m) + std::fabs(next_rho - rho);
        if (step <= collocation_tolerance || (iteration > 1 && step > 0.5 * last_step && step < 0.1 * rho)) {
            t.iterations = iteration;
            return t;
        }
        last_step = step;
        rho = next_rho;
        gamma = next_gamma;
    }
    return model_zone();
}

std::optional<std::pair<double, double>> brush_zone(const one_parameter_solver& single, double forcing,
                                                    double magnitude, double point) {
    // A short zone at r*, where w = b p + f G is least (b = 0 but for dissimilar rollers, 8(s)): eps1/rho
    // dominates H (the brush model), and with w = w* + k (r - r*)^2, k = w''/2, the stick equation
    // eps1 q' = xi + w, q(s) = q(c) = 0 and the entry condition q'(s) = 0 give the zone
    // [r* - L/3, r* + 2L/3] and f - |Q| = k L^4/(36 eps1) (docs/formulation.md 7(g)). Empty at an edge or
    // where w'' <= 0.
    const double eps1 = single.eps().tangential, f = single.friction();
    const double room = std::min(1.0 + point, 1.0 - point);
    if (!(eps1 > 0.0 && room > 0.0)) return std::nullopt;
    const double h = std::min(1e-3, 0.25 * room);
    // w/scale: G itself without Dundurs' forcing (scale f), so that the paper's problem keeps its digits.
    const double scale = forcing == 0.0 ? f : 1.0;
    const auto w = [&](double r) { return forcing == 0.0 ? single.G(r) : single.sliding_velocity(forcing, r); };
    const double k = 0.5 * scale * (w(point - h) - 2.0 * w(point) + w(point + h)) / (h * h);
    if (!(k > 0.0 && std::isfinite(k))) return std::nullopt;
    const double L = std::pow(36.0 * eps1 * (f - magnitude) / k, 0.25);
    if (!(point - L / 3.0 > -1.0 && point + 2.0 * L / 3.0 <= 1.0)) return std::nullopt;
    return std::make_pair(point - L / 3.0, point + 2.0 * L / 3.0);
}
}  // namespace

stick_zone_operator tangential_problem::zone_operator_of(double forcing) {
    stick_zone_operator op;
    op.f = f_;
    op.solve = [this, forcing](double start, double end) { return on_zone(start, end, forcing, false); };
    // Q(s, c) - |Q| = rho int q + (f - |Q|) (3.22), without the O(f) sum that cancels (7(d)): f - |Q| is exact
    // (Sterbenz, |Q| >= f/2 where it matters) and rho int q keeps its relative digits, where f + rho int q
    // rounds to ulp(f) (at |Q|/f = 1 - 1e-15 six ulps: the ends found from Q itself were noise, 7(e)).
    // int psi sqrt(1 - t^2) = (pi/2) b_0 (the Glauert system's c_0 likewise, 7(g)).
    op.excess = [f = f_](const tangential_solution& t, double magnitude) {
        return t.rho() * (t.psi_b.empty() ? 0.0 : M_PI_2 * t.psi_b[0]) + (f - magnitude);
    };
    op.empty_load = [f = f_](double) { return f; };
    // w = b p + f G (7(d), 8(s)): its least point in place of the paper's edge form.
    op.gross_sliding = [this, forcing] { return least_sliding(forcing); };
    op.check = [this](const tangential_solution& t) { return check(t); };
    return op;
}

stick_zone_operator tangential_solver::zone_operator() {
    stick_zone_operator op = zone_operator_of(0.0);
    op.paper_zone = [this](double Q, bool searching) -> std::optional<tangential_solution> {
        if (searching) return std::nullopt;
        return solve(Q);
    };
    op.entry = zone_solver::entry_coefficient;
    // psi(-1)/|b_0|: relative, so that it keeps its digits as the zone collapses at gross sliding (7(e)).
    op.newton_entry = [](const tangential_solution& t) {
        return zone_solver::entry_coefficient(t) / std::fabs(t.psi_b[0]);
    };
    op.near_sliding = [this](double magnitude, double point, const zone_newton_from&) {
        return continuation(*this, magnitude, point);
    };
    op.method.name = "zone solver";
    op.method.refusal = no_zone_between_slips("general zone search", "psi(-1)", "");
    op.method.newton_tolerance = collocation_tolerance;
    return op;
}

double one_parameter_solver::entry_velocity(const tangential_solution& s) const {
    // 7(g): at t = -1 the stick equation reads (eps1/rho) q'(-1) = xi + b p(start) + f G(start) - H[q](-1)
    // (b: Dundurs' forcing, 8(s)), and H[sin((j+1) phi)] = -T_{j+1}(t) gives
    // H[q](-1) = -sum_j c_j T_{j+1}(-1) = sum_j (-1)^j c_j.
    double h = 0.0;
    for (std::size_t j = 0; j < s.psi_b.size(); ++j) h += (j % 2 == 0 ? 1.0 : -1.0) * s.psi_b[j];
    return s.xi + sliding_velocity(s.forcing, s.start()) - h;
}

stick_zone_operator one_parameter_solver::zone_operator(double forcing) {
    stick_zone_operator op = zone_operator_of(forcing);
    op.paper_zone = [this](double Q, bool) -> std::optional<tangential_solution> {
        try {
            return solve(Q);
        } catch (const numerical_error&) {
            // The paper's zone near gross sliding when eps2 > eps1: its c0 tends to -1 and its system
            // (stiffness eps1/rho) is singular to working precision; the general zone is not.
            const double magnitude = load_magnitude(Q, f_);
            if (magnitude == 0.0 || magnitude == f_) throw;
            return std::nullopt;
        }
    };
    // E needs no scale: Newton's step does not depend on the residuals' units.
    op.entry = op.newton_entry = [this](const tangential_solution& t) { return entry_velocity(t); };
    op.near_sliding = [this, forcing](double magnitude, double point,
                                      const zone_newton_from& newton) -> std::optional<tangential_solution> {
        if (const auto zone = brush_zone(*this, forcing, magnitude, point)) return newton(zone->first, zone->second);
        return std::nullopt;
    };
    op.method.name = "one-parameter zone search";
    op.method.refusal = no_zone_between_slips("one-parameter zone search", "v(s-)", " where it exists");
    // Starts in [-1, r*] (the zone straddles r* and collapses onto it at gross sliding), each end searched near the
    // last; the paper's zone opens the scan where its system is solved (singular near gross sliding: the scan decides).
    op.method.scan = 16;
    op.method.scan_to_least_point = true;
    op.method.chained_ends = true;
    op.method.edge = edge_zone::tried;
    op.method.newton_tolerance = 1e-12;
    return op;
}

}  // namespace roughroll
