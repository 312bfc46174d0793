// SPDX-License-Identifier: GPL-3.0-or-later
// The stick equation on a zone [s, c] between two slip zones, as the one zone search (zone_solver.hpp)
// sees it: like a GSL solver type beside its one driver, a value per method (docs/formulation.md 5,
// 7(e), 7(g), 8(g)). The implementations:
//   - the collocation of (4.4) (tangential_solver::zone_operator): L1[q](r) = xi + f G(r),
//     q = psi(t) sqrt(1 - t^2), entry condition psi(-1) = 0 (7(b)), the zone near gross sliding by
//     the chord iteration from the model zone [r* - rho/2, r* + 3 rho/2] (7(e));
//   - the Glauert system of the one-parameter limit (one_parameter_solver::zone_operator, section 6):
//     H[q] + (eps1/rho) q' = xi + f G, q = sum_j c_j sin((j+1) phi), entry condition
//     v(s-) = eps1 q'(s+) = 0 (7(g)), the zone near gross sliding by Newton from the brush model's
//     [r* - L/3, r* + 2L/3] (7(g));
//   - the three zones of dissimilar rollers (dissimilar_zones::zone_operator, 8(e), 8(g)): the
//     collocation with Dundurs' forcing, L1[q] = xi' + b p + f G, both slip zones in the direction of Q;
//     or the blended zone of 8(g), L1[q] = xi' + b p - f G - 2 f W, the leading slip against Q; entry
//     condition psi(-1) = 0. The paper's zone from r = -1 is never their answer (8(g)).
// Each solves the |Q| problem (sign +1) with r = s + rho (t + 1), rho = (c - s)/2. What else differs
// between the searches is data here: the trial starts and how a bracket answers, Newton's residuals
// and tolerance, the zone from the leading edge, and the words of the refusals.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/numerics/interval_newton.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

class rounding_limits;  // zone_newton.hpp

// The zone from r = -1 (the paper's, 7(b)): `needed` (the search refuses a load no such zone carries),
// `tried` (its trial opens the scan, its end unknown where the paper's system is singular), `absent`
// (not of this structure: dissimilar rollers, 8(g)).
enum class edge_zone { needed, tried, absent };

// How the search goes beyond the operator, per method: each operator names the fields it sets; the defaults
// are the collocation's plain search.
struct zone_search_method {
    const char* name = "";  // the search, in messages
    std::string refusal;    // no zone of the structure carries the load on the scanned starts (resolution_error)
    // Trial starts: -1 + (top + 1) k/scan < 1, k = 1..scan, top = r* (scan_to_least_point) or 1; or
    // (`clustered`) towards both edges, where thin slip zones put the start, -cos(pi k/scan), k < scan.
    int scan = 32;
    bool clustered = false;
    bool scan_to_least_point = false;
    // How the scan answers (zone_solver.cpp): false: the starts up to the first sign change of the entry
    // condition, its bracket's zone; true: every start, each bracket in order, the first zone whose checks
    // (3.3)-(3.4) hold, else the first solved; where no bracket gives a zone, starts halving their distance to the
    // leading edge below the first trial, down to 1e-12 (a thin leading slip zone, near gross sliding, 8(g)); with
    // `clustered`, where no start carries |Q|, below the first start.
    bool every_bracket = false;
    bool chained_ends = false;  // each zone's end searched first near the last one found (stick_zone_end)
    edge_zone edge = edge_zone::needed;
    // Newton's residuals (zone_newton.hpp): relative, (log(-rho int q/(f - |Q|)), newton_entry) in
    // (m, log rho) (7(e), 7(g)); else absolute, ((Q - |Q|)/f, newton_entry) in (m, rho) (8(g), 8(j)).
    bool relative_load = true;
    double newton_tolerance = 0.0;  // Newton's last full step in the zone ends, absolute in r
};

// Newton in the ends of a zone (start, end) at the load asked (ends_newton, zone_newton.hpp); empty where it does
// not converge.
using zone_newton_from = std::function<std::optional<tangential_solution>(double start, double end)>;

struct stick_zone_operator {
    double f;  // friction coefficient
    // The paper's zone [-1, c0] at the load Q, checked (the fast path); empty where the search goes
    // without it: `searching` (a search asked for whatever the single zone gives) for the
    // collocation; a system singular to working precision for the Glauert one (its c0 -> -1 near
    // gross sliding when eps2 > eps1); always for dissimilar rollers.
    std::function<std::optional<tangential_solution>(double Q, bool searching)> paper_zone;
    std::function<tangential_solution(double start, double end)> solve;  // the system on [start, end], unchecked
    // The systems on k stick zones at their ends (in order from r = -1), unchecked, empty where they fail (off the
    // family: Newton halves its step), for Newton in the ends (zone_newton, zone_solver.hpp): the five zones' two
    // (8(j), dissimilar_zones::five_zone_system); unset: `solve` on the one zone (a fault there is the search's).
    std::function<std::optional<tangential_solution>(const std::vector<stick_span>& zones)> systems;
    // Q(s, c) - |Q| of a solution (7(c): falling as the zone grows), in the form that keeps its digits.
    std::function<double(const tangential_solution&, double magnitude)> excess;
    std::function<double(double start)> empty_load;                    // Q(s, s): no stick zone, the slip zones' load
    std::function<double(const tangential_solution&)> entry;           // the entry condition's E (E = 0)
    std::function<double(const tangential_solution&)> newton_entry;    // E in Newton's units (zone_newton.hpp)
    std::function<tangential_solution()> gross_sliding;                // |Q| = f: its stick point r*, where w is least
    std::function<traction_checks(const tangential_solution&)> check;  // p >= 0, (3.3)-(3.4)
    // The zone near gross sliding from the operator's leading-order model at r* = `least_point`, where
    // G is least; `newton` refines a zone (start, end); empty (or none) where the model does not apply.
    std::function<std::optional<tangential_solution>(double magnitude, double least_point,
                                                     const zone_newton_from& newton)>
        near_sliding;
    // A root of these zones from another structure at `load` (find_zones' `three_zones` start, zone_start.hpp): the
    // five zones' from the driven three zones (8(j) 4a, dissimilar_zones::from_three_zones), unchecked; `holds` where
    // that structure is the answer at `load`. Unset but for the five zones.
    std::function<std::optional<tangential_solution>(double load, bool& holds, rounding_limits& met)> seed;
    zone_search_method method;
};

}  // namespace roughroll
