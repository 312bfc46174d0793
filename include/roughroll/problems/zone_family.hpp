// SPDX-License-Identifier: GPL-3.0-or-later
// The stick zones [s, c(s)] that carry a load |Q| < f, and the search along them for the one whose entry
// condition holds (docs/formulation.md 7(e) step 3; 7(g); 8(g)). For a start s the end c(s) is the root of
// the load's excess
//   e(c) = Q(s, c) - |Q|  on (s, 1],   e(s) > 0 (no stick zone: the slip zones carry more than |Q|),
// falling as the zone grows, by Brent (brent_root) to 1e-15 in r. Along the family the entry condition
// E(s) of the zone [s, c(s)] (psi(-1) = 0 of 7(b), v(s-) = 0 of 7(g)) vanishes at the answer: trial
// starts are scanned for its sign changes, and a bracket is solved by Newton from the zone interpolated
// between its trials (zone_newton.hpp), else by Brent on s (each start with its own end: nested Brent).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// The end c in (start, 1] with excess(c) = 0, where excess(start) > 0 > excess(1); empty where no end
// carries the load. `near`: the end of a nearby start, tried first on a bracket of half-width 1e-3.
std::optional<double> stick_zone_end(const std::function<double(double)>& excess, double start,
                                     std::optional<double> near = std::nullopt);

// A search's zones: the end carrying |Q| for a start (empty where none), the system on a zone, and
// the entry condition of its solution.
struct zone_family {
    std::function<std::optional<double>(double start)> end;
    std::function<tangential_solution(double start, double end)> solve;
    std::function<double(const tangential_solution&)> entry;
};

struct zone_trial {
    double start, end, entry;
};

using zone_newton_from = std::function<std::optional<tangential_solution>(double start, double end)>;

// The trials at `starts`, in order, after `trials`. `to_first_bracket`: stop after the first trial whose
// entry changes sign against the one before (brackets_entry), and at a start without a zone or whose zone
// fails to solve (numerical_error); else every start is tried, one without a zone skipped.
std::vector<zone_trial> scan_starts(const zone_family& family, std::vector<zone_trial> trials,
                                    const std::vector<double>& starts, bool to_first_bracket);

// Whether E changes sign between two trials (an unknown, NaN, entry counts as positive).
bool brackets_entry(const zone_trial& lo, const zone_trial& hi);

// The zone of a bracket [lo, hi] of E: `newton` from the interpolated zone (from hi's where lo's entry
// is unknown), else Brent on the start; numerical_error where Brent fails or a start has no zone.
tangential_solution zone_in_bracket(const zone_family& family, const zone_trial& lo, const zone_trial& hi,
                                    const zone_newton_from& newton);

// A search's |Q| solution as the point at Q: general where its stick zone starts inside the contact,
// the mirror for Q < 0 (apply_load_sign, `what` naming the search), its checks (3.3)-(3.4) by `check`
// (empty: the search made them, in the |Q| frame, whose checks are Q's).
tangential_solution searched_point(tangential_solution s, double Q, const char* what,
                                   const std::function<traction_checks(const tangential_solution&)>& check);

}  // namespace roughroll
