// SPDX-License-Identifier: GPL-3.0-or-later
// The error estimates of a physical scene's results in SI units (si_point, to_si), each from the dimensionless
// estimates (error_estimate) by the scaling that makes the SI value (docs/formulation.md 2(j), "The SI values'
// estimates"): one rule for the point's text and JSON, the curve's CSV and the Python module, so that all print the
// same numbers.
//   a = x a_H with x^2 = P_H/P2 at a given load: e_a = a_H E_lambda/(2x) (+ the width search's 1e-12 x a_H where it
//     searched); 0 for the paper's width a = a_H (contact_width = "hertz"), where the load P2/lambda carries instead
//     the relative error E_lambda/(lambda - E_lambda);
//   y = s v, s a scale with relative error rs, v a dimensionless value with estimate e_v:
//     |s' v' - s v| <= s (e_v + rs (|v| + e_v)), a bound for any error within those of s and v;
//   the scales: a (c = c0 a, x_peak = r a, T and A of (3.26)), P2 (P1 = Q P2, P_H = lambda P2), P2/a (the
//     pressures: the peak's and the centre's), C P2/a (xi1): a ratio's relative error (r_num + r_den)/(1 - r_den).
// a_H and Carter's xi1 are closed forms of the scene's inputs (3.27): no estimate beyond rounding, as Carter's
// dimensionless columns.
#pragma once

#include <optional>

#include "roughroll/model/physical_scene.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "roughroll/problems/error_estimate.hpp"
#include "roughroll/problems/normal_solution.hpp"

namespace roughroll {

struct si_estimate {
    double a;               // m
    double a_over_a_hertz;  // a's estimate over a_H
    double c;               // m
    double P_H, P2, P1;     // N/m (P2: 0 where it is the given load)
    double xi1;
    std::optional<double> p_peak, x_peak;  // Pa, m: where the point's peak has an estimate (error_estimate::peak)
    std::optional<double> p_centre;        // Pa: the pressure at the centre, from the same levels (peak_error::centre)
    double surfaces_relative;              // T and A at a, each relative (both scale as a, (3.26))
};

// The estimates of p's values from the dimensionless estimate e of the point it scales (its Q, c0, xi, and its peak
// pressure where printed; Q's estimate is e.Q, 0 at a given load).
si_estimate estimate_si(const si_point& p, const error_estimate& e, double Q, double c0, double xi,
                        const std::optional<pressure_peak>& peak = std::nullopt);

// A physical curve's SI cells for one row (`write_curve_csv`'s columns and Python's Scene.curve arrays, one rule): P1,
// xi1, Carter's xi1 and the estimates of P1 and xi1 (the row's estimates scaled by estimate_si), NaN where a cell is
// empty. A refused row has only what was given: P1 = Q P2 of a given load (NaN on a curve swept in c0), Carter's xi1 at
// it (Carter's load at a given c0), and P1's estimate 0 where P2 is the given load (the load the paper's width carries
// has none here); xi1 and its estimate NaN. `w`: the row's width.
struct si_curve_cells {
    double P1, xi1, xi1_carter;
    double P1_error, xi1_error;
};
si_curve_cells si_curve_row(const physical_scene& scene, const contact_width& w, const curve_point& row);

}  // namespace roughroll
