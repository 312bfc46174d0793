// SPDX-License-Identifier: GPL-3.0-or-later
// The zones where the physics puts them in the one-parameter limit (docs/formulation.md 7(g)):
// the complementarity form of (3.2)-(3.4) for the Winkler-layer operator H + eps1 d/dr, for
// Q >= 0 (Q < 0 is the mirror). The structures solved:
//   - the paper's: stick [-1, c0], slip (c0, 1]: one_parameter_solver::solve, the fast path;
//   - slip [-1, s), stick [s, c0], slip (c0, 1], both slip zones in the direction of Q, when
//     the paper's zone would carry p1 > f p at its leading end (eps2 > eps1 near gross
//     sliding, section 6). On the stick zone p1 = f p + q, q = 0 at both ends (built into the
//     sine series), and
//       H[q](t) + (eps1/rho) q'(t) = xi + f G(r),  r = s + rho (t + 1),  rho int q = Q - f
//     (one_parameter_solver::solve_on_zone), plus the entry condition of 7(g):
//       E = eps1 q'(s+) = v(s-) = xi + f G(s) - H[q](t = -1) = 0,
//     the slip velocity vanishing where material enters the stick zone;
//   - gross sliding |Q| = f (gross_sliding.hpp).
// (s, c0) solve Q(s, c0) = |Q| (in the gap form rho int q + (f - |Q|), 7(d)) and E = 0 along the
// zones carrying |Q| (zone_family.hpp); other structures are refused (resolution_error).
#pragma once

#include <optional>
#include <utility>

#include "roughroll/problems/one_parameter.hpp"

namespace roughroll {

class one_parameter_zones {
public:
    // The one-parameter solver supplies G, the system on any stick zone, the fast path, the
    // tractions, slip velocities and checks; it must outlive this workspace.
    explicit one_parameter_zones(one_parameter_solver& single);

    // The solution for the load Q, |Q| <= f: the single zone when its checks hold (or
    // `force_general` is false and the search throws: then the single zone, flagged), else the
    // general search. `force_general` runs the search in any case (where the paper's structure
    // holds it ends at start = -1).
    tangential_solution solve(double Q, bool force_general = false);

    // E = eps1 q'(start+) of a stick-zone solution: xi + f G(start) - H[q](-1), H[q](-1) =
    // sum_j (-1)^j c_j (7(g)). The entry condition is E = 0; at start = -1, E <= 0 is (3.3).
    double entry_velocity(const tangential_solution& s) const;

private:
    tangential_solution general(double magnitude, std::optional<double> single_end);
    tangential_solution gross_sliding() const;
    std::optional<tangential_solution> newton(double magnitude, double start, double c0);
    // The zone to leading order near gross sliding at r* = point (7(g)), as (start, c0).
    std::optional<std::pair<double, double>> asymptotic_zone(double magnitude, double point) const;

    one_parameter_solver& single_;
    double f_;
};

}  // namespace roughroll
