// SPDX-License-Identifier: GPL-3.0-or-later
// The stick equation on a zone [s, c] with slip on both sides in the direction of Q, as the one zone
// search (zone_solver.hpp) sees it: like a GSL solver type beside its one driver, a value per method
// (docs/formulation.md 5, 7(e), 7(g)). Two implementations:
//   - the collocation of (4.4) (tangential_solver::zone_operator): L1[q](r) = xi + f G(r),
//     q = psi(t) sqrt(1 - t^2), entry condition psi(-1) = 0 (7(b)), the zone near gross sliding by
//     the chord iteration from the model zone [r* - rho/2, r* + 3 rho/2] (7(e));
//   - the Glauert system of the one-parameter limit (one_parameter_solver::zone_operator, section 6):
//     H[q] + (eps1/rho) q' = xi + f G, q = sum_j c_j sin((j+1) phi), entry condition
//     v(s-) = eps1 q'(s+) = 0 (7(g)), the zone near gross sliding by Newton from the brush model's
//     [r* - L/3, r* + 2L/3] (7(g)).
// Both solve the |Q| problem (sign +1) with r = s + rho (t + 1), rho = (c - s)/2, rho int q = Q - f
// (3.22). What else differs between the two searches is data here: the trial starts, Newton's
// tolerance, how the zone ends are bracketed and the words of the refusals.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_family.hpp"

namespace roughroll {

// How the search goes beyond the operator, per method.
struct zone_search_method {
    const char* name;     // the search, in messages
    const char* refusal;  // no root of the entry condition on the scanned starts (first_bracket_zone)
    // Trial starts -1 + (top + 1) k/scan < 1, k = 1..scan, top = r* (scan_to_least_point) or 1.
    int scan;
    bool scan_to_least_point;
    bool chained_ends;        // each zone's end searched first near the last one found (stick_zone_end)
    bool edge_zone_required;  // without the paper's zone, the zone from r = -1 carrying |Q| must exist
    double newton_tolerance;  // Newton's last full step in the zone ends, absolute in r
};

struct stick_zone_operator {
    double f;  // friction coefficient
    // The paper's zone [-1, c0] at the load Q, checked (the fast path); empty where the search goes
    // without it: `searching` (a search asked for whatever the single zone gives) for the
    // collocation; a system singular to working precision for the Glauert one (its c0 -> -1 near
    // gross sliding when eps2 > eps1).
    std::function<std::optional<tangential_solution>(double Q, bool searching)> paper_zone;
    std::function<tangential_solution(double start, double end)> solve;  // the system on [start, end], unchecked
    std::function<double(const tangential_solution&)> load_integral;      // rho int q = Q(s, c) - f (3.22)
    std::function<double(const tangential_solution&)> entry;              // the entry condition's E (E = 0)
    std::function<double(const tangential_solution&)> newton_entry;       // E in Newton's units (zone_newton.hpp)
    std::function<double(double)> G;                                       // (3.25) and its limit
    std::function<std::vector<double>(const std::vector<double>&)> G_sampled;  // at points in any order
    std::function<traction_checks(const tangential_solution&)> check;     // p >= 0, (3.3)-(3.4)
    // The zone near gross sliding from the operator's leading-order model at r* = `least_point`, where
    // G is least; `newton` refines a zone (start, end); empty where the model does not apply.
    std::function<std::optional<tangential_solution>(double magnitude, double least_point,
                                                     const zone_newton_from& newton)>
        near_sliding;
    zone_search_method method;
};

}  // namespace roughroll
