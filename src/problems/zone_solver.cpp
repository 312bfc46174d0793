#include "roughroll/problems/zone_solver.hpp"

#include <algorithm>
#include <array>
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
constexpr int newton_iterations = 40;
// Newton's steps in the zone ends: psi(-1) carries rounding of about 1e-13 (a sum of n
// coefficients of the collocation solution), which moves the root by a few 1e-12; below
// 1e-11 the steps are that noise (measured), and Brent's 1e-15 is no closer.
constexpr double newton_tolerance = 1e-11;
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
    return s;
}

std::optional<tangential_solution> zone_solver::newton(double magnitude, double start, double c0) {
    // Newton on F = (Q - |Q|, psi(-1)) in the zone's midpoint m and half-length rho (near gross
    // sliding Q - f ~ -rho^2 depends on rho alone, psi(-1) mostly on m), the Jacobian by forward
    // differences (steps 1e-7 rho), each step halved until -1 < m - rho and m + rho <= 1, rho > 0.
    // Empty when it does not converge: the caller falls back to Brent.
    const auto residual = [this, magnitude](double m, double rho) {
        const tangential_solution t = single_.solve_on_zone(m - rho, m + rho);
        return std::array<double, 2>{(t.Q - magnitude) / f_, entry_coefficient(t)};
    };
    double m = 0.5 * (start + c0), rho = 0.5 * (c0 - start);
    for (int iteration = 1; iteration <= newton_iterations; ++iteration) {
        const auto F = residual(m, rho);
        const double h = 1e-7 * rho;
        const auto Fm = residual(m - h, rho);  // m - h - rho > -1 unless at the edge: then rho - h below
        const auto Fr = residual(m, rho - h);
        const double a = (F[0] - Fm[0]) / h, b = (F[0] - Fr[0]) / h;
        const double c = (F[1] - Fm[1]) / h, d = (F[1] - Fr[1]) / h;
        const double det = a * d - b * c;
        if (!(std::isfinite(det) && det != 0.0)) return std::nullopt;
        const double dm = -(d * F[0] - b * F[1]) / det, dr = -(a * F[1] - c * F[0]) / det;
        double step = 1.0;
        while (!(rho + step * dr > 0.0 && m + step * (dm - dr) - rho > -1.0 && m + step * (dm + dr) + rho <= 1.0)) {
            step *= 0.5;
            if (step < 1e-6) return std::nullopt;
        }
        m += step * dm;
        rho += step * dr;
        if (step == 1.0 && std::fabs(dm) + std::fabs(dr) <= newton_tolerance) {
            tangential_solution s = single_.solve_on_zone(m - rho, m + rho);
            s.iterations = iteration;
            return s;
        }
    }
    return std::nullopt;
}

tangential_solution zone_solver::general(double magnitude, std::optional<zone_guess> guess,
                                         std::optional<double> single_end) {
    // The paper's zone first: if psi(-1) <= 0 at start = -1 it is the answer (7(b)).
    const double edge_end = single_end ? *single_end : stick_end(-1.0, magnitude);
    tangential_solution at_edge = single_.solve_on_zone(-1.0, edge_end);
    const double at_edge_entry = entry_coefficient(at_edge);
    if (at_edge_entry <= 0.0) return at_edge;
    // Newton from the coarse level's zone when extrapolating.
    if (guess && guess->start > -1.0)
        if (auto s = newton(magnitude, guess->start, guess->c0)) return *s;
    // Else bracket the entry condition along the family of zones [s, c(s)] that carry |Q|
    // (7(e)): scan the starts towards the trailing edge until psi(-1) changes sign (a start from
    // which no zone carries |Q| ends the scan), Newton from the interpolated zone, Brent if that fails.
    const auto entry = [this, magnitude](double start) {
        return entry_coefficient(single_.solve_on_zone(start, stick_end(start, magnitude)));
    };
    double lo = -1.0, hi = std::numeric_limits<double>::quiet_NaN();
    double lo_entry = at_edge_entry, hi_entry = 0.0, lo_end = edge_end, hi_end = 0.0;
    for (int k = 1; std::isnan(hi) && k < start_scan; ++k) {
        const double trial = -1.0 + 2.0 * k / start_scan;
        double end, e;
        try {
            end = stick_end(trial, magnitude);
            e = entry_coefficient(single_.solve_on_zone(trial, end));
        } catch (const numerical_error&) {
            break;
        }
        if (e <= 0.0) hi = trial, hi_entry = e, hi_end = end;
        else lo = trial, lo_entry = e, lo_end = end;
    }
    if (std::isnan(hi))
        throw numerical_error(
            "zone solver: the entry condition psi(-1) = 0 has no root on the scanned starts of the stick zone "
            "(a structure the solver does not cover)");
    const double w = lo_entry / (lo_entry - hi_entry);
    if (auto s = newton(magnitude, lo + w * (hi - lo), lo_end + w * (hi_end - lo_end))) return *s;
    const root r = brent_root(entry, lo, hi, end_tolerance, 0.0, 200, "Brent search for the stick zone's start");
    tangential_solution s = single_.solve_on_zone(r.x, stick_end(r.x, magnitude));
    s.iterations = r.iterations;
    return s;
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
        tangential_solution s = magnitude == f_ ? gross_sliding() : general(magnitude, g, single_end);
        s.general = s.start > -1.0;
        apply_load_sign(s, Q, "zone solver");
        s.checks = single_.check(s);
        return s;
    };
    tangential_solution s = search(guess);
    // Newton from a guess may find another zone that solves both conditions but not the
    // inequalities (seen near s = 0.97 while it wandered): then search without the guess.
    if (guess && !s.checks.hold()) s = search(std::nullopt);
    return s;
}

}  // namespace roughroll
