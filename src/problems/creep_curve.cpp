// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/creep_curve.hpp"

#include <cmath>
#include <string>

#include "roughroll/base/text.hpp"
#include "roughroll/numerics/gauss_chebyshev.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

namespace {
void check_curve_points(int points) {
    if (points < 2 || points > 100000) throw input_error("a curve needs between 2 and 100000 points");
}

// A refused row (contact.hpp, curve_point): the given load Q or stick end c0 (the other NaN),
// NaN for every computed number, so that no refused row can pass for an answer; Carter's
// closed form at what was given (at the same c0 on a swept curve), never NaN.
curve_point refused_row(double Q, double c0, double f, const std::string& at, const resolution_error& why) {
    const double nan = std::nan("");
    tangential_solution s = zone_solution(f, nan, c0, nan, Q, {}, nan);
    s.sign = s.load_slope = nan;
    s.checks = traction_checks{nan, nan, nan, nan, nan, false, false, false};
    const carter_point smooth = std::isnan(Q) ? carter_point{c0, carter_at_stick_end(c0, f).xi} : carter(Q, f);
    return {std::move(s), smooth, std::nullopt, "curve point at " + at + ": " + one_line(why.what())};
}
}  // namespace

resolution_error advised_at_given_n(const unadvised_refusal& refusal, int n) {
    // With n given, what the user can change is n, as the ladder advises where it climbs (no three zones of dissimilar
    // rollers at this n or a level of its estimate, docs/formulation.md 8(g), 8(j)).
    return resolution_error(std::string(refusal.what()) + "; at the given n = " + std::to_string(n) +
                            ": a larger n (solver.n, --n; at most " + std::to_string(max_nodes) +
                            ") may find its zones, or leave n out and the ladder of levels tries n up to " +
                            std::to_string(max_nodes) + "; or try another method or zone search");
}

curve_point refused_load(double Q, double f, const resolution_error& why) {
    return refused_row(Q, std::nan(""), f, "Q = " + shortest(Q) + " (Q/f = " + shortest(Q / f) + ")", why);
}

std::vector<double> curve_loads(int points, double f) {
    check_curve_points(points);
    std::vector<double> loads(points);
    for (int i = 0; i < points; ++i) {
        const double v = 1.0 - static_cast<double>(i) / (points - 1);  // 1 - u
        loads[i] = f * (1.0 - v * v);
    }
    loads.back() = f;  // exactly, so the last point is the onset of gross sliding
    return loads;
}

std::vector<double> curve_loads(int points, double f, double beta_d) {
    if (beta_d == 0.0) return curve_loads(points, f);
    // Dissimilar rollers: the curve is not odd in Q (8(h)), so -f..f, uniform in Q (the five/three
    // zone transitions lie near free rolling, 8(j) 4a); the ends exactly -f and f.
    check_curve_points(points);
    std::vector<double> loads(points);
    for (int i = 0; i < points; ++i) loads[i] = f * (2.0 * i - (points - 1)) / (points - 1);
    loads.front() = -f;
    loads.back() = f;
    return loads;
}

std::vector<curve_point> creep_curve(contact& c, const std::vector<double>& loads,
                                     const std::function<void()>& before_row,
                                     const refusal_before_solve& refused_at_once, int given_n, curve_rows start) {
    std::vector<curve_point> rows;
    rows.reserve(loads.size());
    const tangential_solution* previous = nullptr;
    for (double Q : loads) {
        // A refused row is this point only (curve_point): the curve goes on, the next row searching alone.
        const auto refuse = [&](const resolution_error& why) {
            rows.push_back(refused_load(Q, c.friction(), why));
            previous = nullptr;
        };
        if (before_row) before_row();
        if (const std::optional<std::string> why = refused_at_once ? refused_at_once(Q) : std::nullopt) {
            refuse(resolution_error(*why));
            continue;
        }
        try {
            tangential_solution s =
                start == curve_rows::continued && previous ? c.continued_point(Q, *previous) : c.point(Q);
            const auto e = c.estimate(s);
            rows.push_back({std::move(s), carter(Q, c.friction()), e, {}});
            previous = &rows.back().solution;   // rows reserved: the address stays
        } catch (const unadvised_refusal& e) {  // its line names no change: at a given n, what to change is n
            refuse(given_n > 0 ? advised_at_given_n(e, given_n) : resolution_error(e));
        } catch (const resolution_error& e) {
            refuse(e);
        }
    }
    return rows;
}

std::vector<curve_point> swept_curve(contact& c, int points, const std::function<void()>& before_row,
                                     const refusal_before_solve& refused_at_once, int given_n) {
    check_curve_points(points);
    check_sweepable(c.materials());
    // Dissimilar rollers have no single stick end to sweep (8(g), 8(j)): their rows at curve_loads, each started
    // from the previous row's zones (a continuation in the load, 8(j) 10).
    if (c.materials().beta_d != 0.0)
        return creep_curve(c, curve_loads(points, c.friction(), c.materials().beta_d), before_row, refused_at_once,
                           given_n, curve_rows::continued);
    std::vector<curve_point> rows;
    rows.reserve(points);
    for (int i = 0; i < points; ++i) {
        // rho = (1 + c0)/2 uniform from 1 to 0: Carter's Q/f = 1 - rho^2, the loads of curve_loads.
        const double rho = 1.0 - static_cast<double>(i) / (points - 1);
        const double c0 = i + 1 == points ? -1.0 : 2.0 * rho - 1.0;
        if (before_row) before_row();
        try {
            contact::swept_point p = c.at_stick_end(c0);
            const carter_point smooth = carter(p.solution.Q, c.friction());
            rows.push_back({std::move(p.solution), smooth, p.estimate, {}});
        } catch (const resolution_error& e) {  // this point only (curve_point): the curve goes on
            rows.push_back(refused_row(std::nan(""), c0, c.friction(), "c0 = " + shortest(c0), e));
        }
    }
    return rows;
}

}  // namespace roughroll
