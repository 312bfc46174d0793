// SPDX-License-Identifier: GPL-3.0-or-later
// Creep curves: a contact's points at a list of loads (creep_curve) or swept in the stick zone's end
// (swept_curve), each row answered with its estimate or refused with its one line (docs/robustness.md).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/model/dissimilar.hpp"
#include "roughroll/problems/contact.hpp"

namespace roughroll {

// One row of a creep curve: solved, or refused. A refused row is a point the method cannot
// answer honestly at this n (a resolution_error of contact::point, contact::estimate or
// contact::at_stick_end: the levels do not converge visibly, a load below the resolution);
// the curve goes on past it. Its `solution` keeps only what was given, the load Q of
// creep_curve (and `smooth`, Carter's closed form at that Q) or the stick end c0 of
// swept_curve; every other number is NaN, and `refused` holds one line naming the point and
// the reason. Only resolution_error is absorbed: input_error (bad input) and numerical_error
// (a GSL status, a singular or non-finite system, a zone search that finds no structure, any
// of which may be a bug or a scene-wide fault) still abort the curve (docs/robustness.md).
struct curve_point {
    tangential_solution solution;
    carter_point smooth;                     // Carter's curve at the same Q
    std::optional<error_estimate> estimate;  // contact::estimate
    std::string refused;                     // empty: solved; else "Q = ...: <the resolution_error>"

    bool is_refused() const { return !refused.empty(); }
};

// Q/f = 1 - (1 - u)^2 for u uniform on [0, 1]: `points` loads from 0 to f, dense
// near Q = f where the creep curve steepens (there xi ~ sqrt(1 - Q/f)).
std::vector<double> curve_loads(int points, double f);
// The default loads of a curve for Dundurs' beta_D: curve_loads(points, f) for beta_D = 0; else
// `points` loads uniform from -f to f (the creep curve of dissimilar rollers is not odd in Q,
// docs/formulation.md 8(h)).
std::vector<double> curve_loads(int points, double f, double beta_d);

// Why the point at a load Q is refused before any solve (the ladder's contact::beyond_every_n for its top
// rung, problems/level_ladder.hpp): one line; empty where the row is to be solved.
using refusal_before_solve = std::function<std::optional<std::string>(double Q)>;

// A refusal whose line names no change (unadvised_refusal, base/error.hpp: no three zones at this n) at an n the user
// gave: its line with what the user can change there (a larger n, n left out for the ladder, another method or zone
// search), as the ladder of levels advises where it climbs. One text for a point (io/scene_point) and a curve's rows.
resolution_error advised_at_given_n(const unadvised_refusal& refusal, int n);

// `before_row`, when set, is called before each row: a caller's hook between rows (the Python
// module checks for Ctrl-C there); what it throws ends the curve. `refused_at_once`, when set, is
// asked after `before_row`: a row it gives a line for is refused with that line, no level solved.
// `given_n`: the n the user gave the contact, whose rows refused by an unadvised_refusal get advised_at_given_n's
// line; 0 for a ladder's rung (the ladder solves such a row again and advises where no rung answers it).
// `start`: alone, each row searched from its own starts; continued, each row after an answered one started from that
// row's zones (contact::continued_point, a continuation in the load: dissimilar rollers' swept curve), the same points
// to Newton's resolution.
enum class curve_rows { alone, continued };
std::vector<curve_point> creep_curve(contact& c, const std::vector<double>& loads,
                                     const std::function<void()>& before_row = {},
                                     const refusal_before_solve& refused_at_once = {}, int given_n = 0,
                                     curve_rows start = curve_rows::alone);
// The row of creep_curve for a load Q refused by `why`.
curve_point refused_load(double Q, double f, const resolution_error& why);

// A creep curve swept in c0 from 1 to -1 (rho = (1 + c0)/2 uniform): one linear solve per
// point, no root search; the loads are Q(c0), dense near f as in curve_loads. For dissimilar
// rollers (beta_D != 0, Johnson's level; check_sweepable refuses coupling "full") no c0 parametrises
// the zones (8(g)): the rows of creep_curve at curve_loads(points, f, beta_D), each continued from the
// previous answered row (curve_rows::continued), the same points to Newton's resolution.
// `refused_at_once`, `given_n`: as creep_curve's, for the rows of dissimilar rollers (a load each; never asked of a row
// swept in c0).
std::vector<curve_point> swept_curve(contact& c, int points, const std::function<void()>& before_row = {},
                                     const refusal_before_solve& refused_at_once = {}, int given_n = 0);

}  // namespace roughroll
