#include "roughroll/problems/zone_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/root_search.hpp"

namespace roughroll {

namespace {
constexpr int start_scan = 32;            // trial starts of the stick zone, bracketing the entry condition
constexpr int least_G_samples = 2001;     // samples of G for its least value (gross sliding)
constexpr double end_tolerance = 1e-15;   // zone ends, absolute in r
constexpr double guess_half_width = 1e-5;  // bracket around a coarse level's start
}  // namespace

std::vector<zone> zones_of(const tangential_solution& s) {
    const int direction = s.sign < 0.0 ? -1 : 1;
    std::vector<zone> z;
    if (s.start > -1.0) z.push_back({-1.0, s.start, false, direction});
    z.push_back({s.start, s.c0, true, 0});
    if (s.c0 < 1.0) z.push_back({s.c0, 1.0, false, direction});
    return z;
}

zone_solver::zone_solver(tangential_solver& single) : single_(single), f_(single.friction()) {}

double zone_solver::entry_coefficient(const tangential_solution& s) {
    return s.psi_b.empty() ? 0.0 : u_series(s.psi_b, -1.0);  // psi(-1) = sum_j b_j U_j(-1)
}

double zone_solver::stick_end(double start, double magnitude) {
    // Q(start, c0) falls from f (no stick zone, c0 = start) as the zone grows (7(c)).
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

tangential_solution zone_solver::gross_sliding() {
    // |Q| = f: p1 = f p everywhere and v = xi + f G >= 0 with equality somewhere: the stick
    // zone shrinks to the point where G is least, xi = -f min G (docs/formulation.md 7(d)).
    std::vector<double> r(least_G_samples);
    for (int i = 0; i < least_G_samples; ++i) r[i] = 1.0 - 2.0 * i / (least_G_samples - 1);  // descending
    const std::vector<double> g = single_.G(r);
    for (double value : g)
        if (!std::isfinite(value))
            throw numerical_error("zone solver: G of (3.25) is not finite (roughness parameters too large?)");
    const auto least = static_cast<int>(std::min_element(g.begin(), g.end()) - g.begin());
    double lo = r[std::min(least + 1, least_G_samples - 1)], hi = r[std::max(least - 1, 0)];
    // Golden section on the sample's bracket (G is smooth inside (-1, 1)).
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
    tangential_solution s = gross_sliding_solution(f_, value);
    s.c0 = point;
    s.start = point;
    s.general = point > -1.0;
    return s;
}

tangential_solution zone_solver::general(double magnitude, std::optional<double> guess) {
    // The entry condition psi(-1) = 0 along the family of zones [start, c0(start)] that carry
    // |Q| (docs/formulation.md 7(c)); the paper's zone when psi(-1) <= 0 already at start = -1.
    const auto entry = [this, magnitude](double start) {
        return entry_coefficient(single_.solve_on_zone(start, stick_end(start, magnitude)));
    };
    double found = -1.0;
    int iterations = 0;
    if (entry(-1.0) > 0.0) {
        double lo = -1.0, hi = std::numeric_limits<double>::quiet_NaN();
        if (guess && *guess > -1.0) {
            const double a = std::max(-1.0, *guess - guess_half_width), b = *guess + guess_half_width;
            try {
                if (entry(a) > 0.0 && entry(b) <= 0.0) lo = a, hi = b;
            } catch (const numerical_error&) {
            }
        }
        // Else scan the starts towards the trailing edge until psi(-1) changes sign; a start
        // from which no zone carries |Q| ends the scan.
        for (int k = 1; std::isnan(hi) && k < start_scan; ++k) {
            const double trial = -1.0 + 2.0 * k / start_scan;
            double e;
            try {
                e = entry(trial);
            } catch (const numerical_error&) {
                break;
            }
            if (e <= 0.0) hi = trial;
            else lo = trial;
        }
        if (std::isnan(hi))
            throw numerical_error(
                "zone solver: the entry condition psi(-1) = 0 has no root on the scanned starts of the stick zone "
                "(a structure the solver does not cover)");
        const root r = brent_root(entry, lo, hi, end_tolerance, 0.0, 200, "Brent search for the stick zone's start");
        found = r.x;
        iterations = r.iterations;
    }
    tangential_solution s = single_.solve_on_zone(found, stick_end(found, magnitude));
    s.iterations = iterations;
    s.general = found > -1.0;
    return s;
}

tangential_solution zone_solver::solve(double Q, bool force_general, std::optional<double> guess) {
    const double magnitude = load_magnitude(Q, f_);
    if (!force_general || magnitude == 0.0) {
        tangential_solution s = single_.solve(Q);
        if (s.checks.hold() || magnitude == 0.0) return s;
    }
    check_load_resolvable(magnitude, f_);
    tangential_solution s = magnitude == f_ ? gross_sliding() : general(magnitude, guess);
    apply_load_sign(s, Q, "zone solver");
    s.checks = single_.check(s);
    return s;
}

}  // namespace roughroll
