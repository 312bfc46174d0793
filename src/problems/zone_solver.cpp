#include "roughroll/problems/zone_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/kernel_moments.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/root_search.hpp"

namespace roughroll {

namespace {
constexpr int check_points = 200;      // interior points per zone for (3.3), (3.4), as tangential_solver
constexpr int start_scan = 32;         // trial starts of the stick zone, bracketing the entry condition
constexpr int min_search_points = 2001;  // samples of G for its least value (gross sliding)
constexpr double end_tolerance = 1e-15;  // zone ends, absolute in r

// Interior Chebyshev points of (lo, hi), clustered towards the ends (the ends excluded).
double grid_point(double lo, double hi, int i) {
    const double x = std::cos(M_PI * (i + 0.5) / check_points);
    return 0.5 * (lo + hi) + 0.5 * (hi - lo) * x;
}
}  // namespace

zone_solver::zone_solver(tangential_solver& single, const kernel& k1, double f) : single_(single), k1_(k1), f_(f) {
    if (!(std::isfinite(f) && f > 0.0)) throw input_error("friction coefficient f must be positive and finite");
}

double zone_solver::entry_coefficient(const tangential_solution& s) const {
    // psi(-1) = sum_j b_j U_j(-1): the coefficient of sqrt(1 + t) in q at the zone's start.
    return s.psi_b.empty() ? 0.0 : u_series(s.psi_b, -1.0);
}

double zone_solver::stick_end(double start, double magnitude) {
    // Q(start, c0) falls from f (no stick zone, c0 = start) as the zone grows.
    const auto excess = [this, start, magnitude](double c0) {
        return (c0 <= start ? f_ : single_.solve_on_zone(start, c0).Q) - magnitude;
    };
    if (!(excess(1.0) < 0.0)) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "zone solver: no stick zone from r = " << start << " carries |Q|/f = " << magnitude / f_;
        throw numerical_error(msg.str());
    }
    return brent_root(excess, start, 1.0, end_tolerance, 0.0, 200, "Brent search for the stick zone's end").x;
}

std::vector<zone> zone_solver::zones_of(double start, double c0, double sign) const {
    const int direction = sign < 0.0 ? -1 : 1;
    std::vector<zone> z;
    if (start > -1.0) z.push_back({-1.0, start, false, direction});
    z.push_back({start, c0, true, 0});
    if (c0 < 1.0) z.push_back({c0, 1.0, false, direction});
    return z;
}

zone_solution zone_solver::gross_sliding() {
    // |Q| = f: p1 = f p everywhere and v = xi + f G >= 0 with equality somewhere: the stick
    // zone shrinks to the point where G is least, xi = -f min G (docs/formulation.md 7(d)).
    std::vector<double> r(min_search_points);
    for (int i = 0; i < min_search_points; ++i) r[i] = 1.0 - 2.0 * i / (min_search_points - 1);  // descending
    const std::vector<double> g = single_.G(r);
    const auto least = static_cast<int>(std::min_element(g.begin(), g.end()) - g.begin());
    double lo = r[std::min(least + 1, min_search_points - 1)], hi = r[std::max(least - 1, 0)];
    // Golden section on the bracket: G is smooth off r = -1, the sample brackets its minimum.
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    double g1 = single_.G(x1), g2 = single_.G(x2);
    while (hi - lo > 1e-12) {
        if (g1 <= g2) {
            hi = x2, x2 = x1, g2 = g1;
            x1 = hi - golden * (hi - lo), g1 = single_.G(x1);
        } else {
            lo = x1, x1 = x2, g1 = g2;
            x2 = lo + golden * (hi - lo), g2 = single_.G(x2);
        }
    }
    double point = 0.5 * (lo + hi), value = single_.G(point);
    const double at_edge = single_.G(-1.0);
    if (at_edge <= value) point = -1.0, value = at_edge;
    zone_solution s;
    s.single = gross_sliding_solution(f_, value);
    s.single.c0 = point;
    s.start = point;
    s.zones = zones_of(point, point, 1.0);
    s.general = point > -1.0;
    return s;
}

zone_solution zone_solver::general(double magnitude) {
    // The entry condition psi(-1) = 0 along the family of zones [start, c0(start)] that
    // carry |Q| (docs/formulation.md 7(c)); the paper's zone when it already holds at -1.
    const auto entry = [this, magnitude](double start) {
        return entry_coefficient(single_.solve_on_zone(start, stick_end(start, magnitude)));
    };
    zone_solution s;
    const double at_edge = entry(-1.0);
    double found = -1.0;
    int iterations = 0;
    if (at_edge > 0.0) {
        // Scan starts towards the trailing edge until psi(-1) changes sign (it must before
        // the zone no longer fits), then Brent between the last two.
        double lo = -1.0, hi = std::numeric_limits<double>::quiet_NaN();
        for (int k = 1; k < start_scan; ++k) {
            const double trial = -1.0 + 2.0 * k / start_scan;
            double e;
            try {
                e = entry(trial);
            } catch (const numerical_error&) {
                break;  // the zone no longer fits: the root lies before
            }
            if (e <= 0.0) {
                hi = trial;
                break;
            }
            lo = trial;
        }
        if (std::isnan(hi)) {
            // Bisect between the last good start and the first that failed to fit.
            throw numerical_error("zone solver: the entry condition psi(-1) = 0 has no root on the scanned starts");
        }
        const root r = brent_root(entry, lo, hi, end_tolerance, 0.0, 200, "Brent search for the stick zone's start");
        found = r.x;
        iterations = r.iterations;
    }
    s.single = single_.solve_on_zone(found, stick_end(found, magnitude));
    s.single.iterations = iterations;
    s.start = found;
    s.zones = zones_of(found, s.single.c0, 1.0);
    s.general = found > -1.0;
    return s;
}

zone_solution zone_solver::solve(double Q, bool force_general) {
    const double magnitude = load_magnitude(Q, f_);
    zone_solution s;
    if (!force_general) {
        s.single = single_.solve(Q);
        s.zones = zones_of(-1.0, s.single.c0, s.single.sign);
        if (s.single.checks.hold() || magnitude == 0.0) return s;
    }
    if (magnitude == 0.0) {
        s.single = single_.solve(0.0);
        s.zones = zones_of(-1.0, 1.0, 1.0);
        return s;
    }
    check_load_resolvable(magnitude, f_);
    s = magnitude == f_ ? gross_sliding() : general(magnitude);
    apply_load_sign(s.single, Q, "zone solver");
    for (zone& z : s.zones) z.direction *= Q < 0.0 ? -1 : 1;
    s.single.checks = check(s);
    return s;
}

double zone_solver::traction(const zone_solution& s, double r) {
    // (3.15): p1 = f p + q on the stick zone, f p on the slip zones (times the load's sign).
    const double rho = 0.5 * (s.single.c0 - s.start);
    double q = 0.0;
    if (r > s.start && r < s.single.c0 && !s.single.psi_b.empty()) {
        const double t = (r - s.start) / rho - 1.0;
        q = u_series(s.single.psi_b, t) * std::sqrt(std::max(0.0, 1.0 - t * t));
    }
    return s.single.sign * (f_ * single_.normal().pressure(r) + q);
}

double zone_solver::slip_velocity(const zone_solution& s, double r) {
    // (3.6) with (3.15): v = xi + f G(r) - L1[q](r) off the stick zone, for |Q|; L1[q] in the
    // zone's variable t, |t| > 1: the Cauchy transform of the U-series and the stretched kernel.
    if (r >= s.start && r <= s.single.c0) return 0.0;
    const double rho = 0.5 * (s.single.c0 - s.start);
    double lq = 0.0;
    if (rho > 0.0 && !s.single.psi_b.empty()) {
        const double t = (r - s.start) / rho - 1.0;
        const kernel stretched = k1_.stretched(rho);
        lq = cauchy_u_series(s.single.psi_b, t);
        if (!stretched.empty())
            lq += kernel_moments(stretched, static_cast<int>(s.single.psi_b.size())).integrate(s.single.psi_b, t);
    }
    const double magnitude_xi = s.single.sign * s.single.xi;
    return s.single.sign * (magnitude_xi + f_ * single_.G(r) - lq);
}

traction_checks zone_solver::check(const zone_solution& s) {
    traction_checks c{};
    c.pressure_margin = std::numeric_limits<double>::infinity();
    c.stick_margin = std::numeric_limits<double>::infinity();
    c.slip_margin = std::numeric_limits<double>::infinity();
    auto lower = [](double& margin, double v) {
        if (!(v >= margin)) margin = v;  // a NaN fails
    };
    const auto& normal = single_.normal();
    for (int i = 0; i < check_points; ++i) lower(c.pressure_margin, normal.pressure(grid_point(-1.0, 1.0, i)));
    for (const zone& z : s.zones) {
        if (!(z.to > z.from)) continue;
        for (int i = 0; i < check_points; ++i) {
            const double r = grid_point(z.from, z.to, i);
            if (z.stick) lower(c.stick_margin, (f_ * normal.pressure(r) - std::fabs(traction(s, r))) / f_);
            else lower(c.slip_margin, z.direction * slip_velocity(s, r) / f_);
        }
    }
    c.pressure_holds = c.pressure_margin >= 0.0;
    c.stick_holds = c.stick_margin >= 0.0;
    c.slip_holds = c.slip_margin > 0.0;
    return c;
}

}  // namespace roughroll
