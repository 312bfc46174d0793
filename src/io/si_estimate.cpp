// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/si_estimate.hpp"

#include <cmath>
#include <limits>

#include "roughroll/model/carter.hpp"
#include "roughroll/problems/contact_width.hpp"

namespace roughroll {

namespace {
// |s' v' - s v| for |s' - s| <= rs s and |v' - v| <= e: s (e + rs (|v| + e)) (docs/formulation.md 2(j), "The SI
// values' estimates").
double scaled(double s, double rs, double v, double e) { return s * (e + rs * (std::fabs(v) + e)); }

// The relative error of a ratio n/d whose parts have the relative errors rn, rd (rd < 1): (rn + rd)/(1 - rd).
double ratio_relative(double rn, double rd) {
    return rd < 1.0 ? (rn + rd) / (1.0 - rd) : std::numeric_limits<double>::infinity();
}
}  // namespace

si_estimate estimate_si(const si_point& p, const error_estimate& e, double Q, double c0, double xi,
                        const std::optional<pressure_peak>& peak) {
    const double lambda = p.P_H / p.P2;  // the width's P_H/P2 (contact_width::lambda)
    si_estimate s{};
    double load_relative = 0.0;  // P2 as reported: the given load, or the load the paper's width carries
    if (p.width == width_rule::hertz) {
        // a = a_H exactly; the load P2/lambda carries lambda's error: |lambda/lambda' - 1| <= E/(lambda - E).
        s.a = 0.0;
        load_relative = e.lambda < lambda ? e.lambda / (lambda - e.lambda) : std::numeric_limits<double>::infinity();
    } else {
        // x = a/a_H, x^2 = lambda: x is off by at most E_lambda/(2x) (2(j) "The width's error": P_H/P2's estimate is
        // at least 2x dx), and the search stops within width_search_tolerance of its root.
        const double x = p.a / p.a_hertz;
        s.a = p.a_hertz * e.lambda / (2.0 * x) + (p.width_iterations > 0 ? width_search_tolerance * p.a : 0.0);
    }
    const double a_relative = s.a / p.a;
    const double pressure_relative = ratio_relative(load_relative, a_relative);  // P2/a, and C P2/a
    s.a_over_a_hertz = s.a / p.a_hertz;
    s.c = scaled(p.a, a_relative, c0, e.c0);
    s.P2 = load_relative * p.P2;
    // P_H = (a/a_H)^2 P2 at a given load (|(1 + r)^2 - 1| for a's relative error r); for the paper's width the Hertz
    // load of a = a_H, the given P2 itself.
    s.P_H = p.width == width_rule::hertz ? 0.0 : p.P_H * a_relative * (2.0 + a_relative);
    s.P1 = scaled(p.P2, load_relative, Q, e.Q);
    s.xi1 = scaled(p.creep_scale, pressure_relative, xi, e.xi);
    if (peak && e.peak) {
        s.p_peak = scaled(p.p_scale, pressure_relative, peak->p, e.peak->p);
        s.x_peak = scaled(p.a, a_relative, peak->r, e.peak->r);
        // None where level 2n would be needed and the point's estimate did not solve it (peak_from_levels: NaN).
        if (!std::isnan(e.peak->centre)) s.p_centre = scaled(p.p_scale, pressure_relative, peak->centre, e.peak->centre);
    }
    s.surfaces_relative = a_relative;  // T = a/(4 C t), A = a alpha (3.26): each proportional to a
    return s;
}

si_curve_cells si_curve_row(const physical_scene& scene, const contact_width& w, const curve_point& row) {
    const double none = std::numeric_limits<double>::quiet_NaN();
    const tangential_solution& s = row.solution;
    if (row.is_refused()) {
        // Only what was given: the load Q (creep_curve), or the stick end c0 (swept_curve, Carter's load at it).
        const bool at_Q = !std::isnan(s.Q);
        const double given_Q = at_Q ? s.Q : carter_at_stick_end(s.c0(), s.f).Q;
        const si_point p = to_si(scene, w, given_Q, s.f, 0.0, 0.0);
        return {at_Q ? p.P1 : none, none, p.xi1_carter, at_Q && scene.width == width_rule::given_load ? 0.0 : none,
                none};
    }
    const si_point p = to_si(scene, w, s.Q, s.f, s.c0(), s.xi);
    if (!row.estimate) return {p.P1, p.xi1, p.xi1_carter, none, none};
    // docs/formulation.md 2(j), "The SI values' estimates": the row's estimates scaled.
    const si_estimate e = estimate_si(p, *row.estimate, s.Q, s.c0(), s.xi);
    return {p.P1, p.xi1, p.xi1_carter, e.P1, e.xi1};
}

}  // namespace roughroll
