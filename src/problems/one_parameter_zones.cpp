// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/one_parameter_zones.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <sstream>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/gross_sliding.hpp"
#include "roughroll/problems/zone_family.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {
constexpr int start_scan = 16;           // trial starts of the stick zone in [-1, r*], bracketing E = 0
constexpr int newton_iterations = 40;
constexpr double near_sliding = 1e-4;       // below this 1 - |Q|/f Newton starts from the asymptotic zone
constexpr double newton_tolerance = 1e-12;  // Newton's last full step in the zone ends, absolute in r
}  // namespace

one_parameter_zones::one_parameter_zones(one_parameter_solver& single) : single_(single), f_(single.friction()) {}

double one_parameter_zones::entry_velocity(const tangential_solution& s) const {
    // 7(g): at t = -1 the stick equation reads (eps1/rho) q'(-1) = xi + f G(start) - H[q](-1), and
    // H[sin((j+1) phi)] = -T_{j+1}(t) gives H[q](-1) = -sum_j c_j T_{j+1}(-1) = sum_j (-1)^j c_j.
    double h = 0.0;
    for (std::size_t j = 0; j < s.psi_b.size(); ++j) h += (j % 2 == 0 ? 1.0 : -1.0) * s.psi_b[j];
    return s.xi + f_ * single_.G(s.start) - h;
}

tangential_solution one_parameter_zones::gross_sliding() const {
    // w = G (7(d)); G'(-1) = -infinity when eps2 > eps1, so r* is inside the contact.
    const one_parameter_solver& g = single_;
    return roughroll::gross_sliding(
        f_, f_,
        [&g](const std::vector<double>& r) {
            std::vector<double> out(r.size());
            for (std::size_t i = 0; i < r.size(); ++i) out[i] = g.G(r[i]);
            return out;
        },
        [&g](double r) { return g.G(r); });
}

tangential_solution one_parameter_zones::general(double magnitude, std::optional<double> single_end) {
    // The paper's zone first: E <= 0 at start = -1 is the edge inequality (7(g)). Without it
    // (its system singular: near gross sliding its zone shrinks onto r = -1) the scan decides.
    double at_edge_entry = std::numeric_limits<double>::quiet_NaN();
    if (single_end) {
        tangential_solution at_edge = single_.solve_on_zone(-1.0, *single_end);
        at_edge_entry = entry_velocity(at_edge);
        if (at_edge_entry <= 0.0) return at_edge;
    }
    // Bracket E = 0 along the family of zones [s, c(s)] that carry |Q|: starts from -1 towards
    // the point where G is least (the zone collapses onto it at gross sliding), then Brent.
    // The zone straddles r*, where G is least, and collapses onto it at gross sliding: the
    // starts scanned lie in [-1, r*].
    const double point = gross_sliding().c0;
    // Near gross sliding Newton starts from the asymptotic zone of 7(g) first.
    if (f_ - magnitude <= near_sliding * f_)
        if (const auto zone = asymptotic_zone(magnitude, point))
            if (auto s = newton(magnitude, zone->first, zone->second)) return *s;
    // Q(start, c0) - |Q| in the gap form rho (pi/2) c_0 + (f - |Q|) (7(d)), falling from f - |Q| at
    // c0 = start; each end found first near the end of the zone solved last (the next start's).
    std::optional<double> end = single_end;
    const zone_family zones{[&](double start) {
                                const auto c = stick_zone_end(
                                    [&](double c0) {
                                        if (c0 <= start) return f_ - magnitude;
                                        const tangential_solution t = single_.solve_on_zone(start, c0);
                                        return t.rho() * M_PI_2 * t.psi_b[0] + (f_ - magnitude);
                                    },
                                    start, end);
                                if (c) end = c;
                                return c;
                            },
                            [this](double start, double c0) { return single_.solve_on_zone(start, c0); },
                            [this](const tangential_solution& t) { return entry_velocity(t); }};
    std::vector<double> starts;
    for (int k = 1; k <= start_scan; ++k) starts.push_back(-1.0 + (point + 1.0) * k / start_scan);
    return first_bracket_zone(
        zones, scan_starts(zones, {{-1.0, single_end.value_or(-1.0), at_edge_entry}}, starts, true),
        [&](double start, double c0) { return newton(magnitude, start, c0); },
        "one-parameter zone search: no stick zone between two slip zones carries this load (the entry "
        "condition v(s-) = 0 has no root on the scanned starts): its zones have another structure; "
        "zones = \"auto\" reports the paper's single zone with its checks where it exists");
}

std::optional<std::pair<double, double>> one_parameter_zones::asymptotic_zone(double magnitude, double point) const {
    // A short zone at r*, where G is least: eps1/rho dominates H (the brush model), and with
    // f G = f G* + k (r - r*)^2, k = f G''/2, the stick equation eps1 q' = xi + f G, q(s) = q(c) = 0
    // and the entry condition q'(s) = 0 give the zone [r* - L/3, r* + 2L/3] and
    // f - |Q| = k L^4/(36 eps1) (docs/formulation.md 7(g)). Empty at an edge or where G'' <= 0.
    const double eps1 = single_.eps().tangential;
    const double room = std::min(1.0 + point, 1.0 - point);
    if (!(eps1 > 0.0 && room > 0.0)) return std::nullopt;
    const double h = std::min(1e-3, 0.25 * room);
    const double k = 0.5 * f_ * (single_.G(point - h) - 2.0 * single_.G(point) + single_.G(point + h)) / (h * h);
    if (!(k > 0.0 && std::isfinite(k))) return std::nullopt;
    const double L = std::pow(36.0 * eps1 * (f_ - magnitude) / k, 0.25);
    if (!(point - L / 3.0 > -1.0 && point + 2.0 * L / 3.0 <= 1.0)) return std::nullopt;
    return std::make_pair(point - L / 3.0, point + 2.0 * L / 3.0);
}

std::optional<tangential_solution> one_parameter_zones::newton(double magnitude, double start, double c0) {
    // Newton on F = (log(-rho int q / (f - |Q|)), E) in the zone's midpoint m and log rho, as
    // zone_solver's (docs/formulation.md 7(e), 7(g); zone_ends_newton): the load in the gap form,
    // relative; E needs no scale (Newton's step does not depend on the residuals' units). It stops
    // when a full step is below 1e-12 in r; empty when it does not converge.
    return zone_ends_newton([this](double s, double c) { return single_.solve_on_zone(s, c); },
                            [this](const tangential_solution& t) { return entry_velocity(t); }, f_ - magnitude, start,
                            c0, newton_iterations, newton_tolerance);
}

tangential_solution one_parameter_zones::solve(double Q, bool force_general) {
    const double magnitude = load_magnitude(Q, f_);
    std::optional<tangential_solution> single;
    try {
        single = single_.solve(Q);
    } catch (const numerical_error&) {
        // The paper's zone near gross sliding when eps2 > eps1: its c0 tends to -1 and its system
        // (stiffness eps1/rho) is singular to working precision; the general zone is not.
        if (magnitude == 0.0 || magnitude == f_) throw;
    }
    if (single && (magnitude == 0.0 || (!force_general && single->checks.hold()))) return *single;
    check_load_resolvable(magnitude, f_);
    return searched_point(
        magnitude == f_ ? gross_sliding()
                        : general(magnitude, single ? std::optional<double>(single->c0) : std::nullopt),
        Q, "one-parameter zone search", [this](const tangential_solution& t) { return single_.check(t); });
}

}  // namespace roughroll
