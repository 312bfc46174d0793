// SPDX-License-Identifier: GPL-3.0-or-later
// The tangential problem with the zone structure found, not assumed (docs/formulation.md,
// section 7). The complementarity form of (3.2)-(3.4), for Q >= 0 (Q < 0 is the mirror):
//   stick zone:  v = xi - L1[p1] = 0,          |p1| <= f p                     (3.2), (3.3)
//   slip zone:   p1 = f p sgn v,               v != 0                          (3.4), (3.15)
//   int p1 = Q                                                                 (3.13)
// The structures solved, at the order of the product-integration scheme (4.4):
//   - the paper's: stick [-1, c0], slip (c0, 1]: tangential_solver::solve, the fast path;
//   - slip [-1, s), stick [s, c0], slip (c0, 1], both slip zones in the direction of Q: the
//     structure when the paper's zone would carry |p1| > f p at its leading end (section
//     7(c)). On the stick zone p1 = f p + q with q = psi(t) sqrt(1 - t^2) and
//       L1[q](r) = xi + f G(r),  r = s + rho (t + 1),  rho = (c0 - s)/2,  rho int q = Q - f
//     (tangential_solver::solve_on_zone), plus the entry condition of 7(b), psi(t = -1) = 0:
//     the traction reaches the bound f p smoothly where material enters the stick zone;
//   - gross sliding |Q| = f (gross_sliding.hpp, 7(d)).
// (s, c0) solve Q(s, c0) = |Q| and psi_{s,c0}(-1) = 0 along the zones carrying |Q| (zone_family.hpp).
// Other structures (slip against Q, several stick zones) are refused (resolution_error), and an
// answer of the wrong structure fails the checks (zone_checks.hpp); zones = "auto" then keeps the
// single zone.
#pragma once

#include <optional>
#include <vector>

#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_family.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

// A zone near the one sought (the coarse level's, when extrapolating).
struct zone_guess {
    double start, c0;
};

class zone_solver {
public:
    // The tangential solver supplies G, the system (4.4) on any stick zone, the fast path, the
    // tractions, slip velocities and checks of every structure; it must outlive this workspace.
    explicit zone_solver(tangential_solver& single);

    // The solution of the complementarity problem for the load Q, |Q| <= f: the single zone
    // when its checks hold, else the general search. `force_general` runs the search in any
    // case (where the paper's structure holds it ends at start = -1, the single zone).
    // `guess`: a zone near the one sought, the start of a Newton iteration (7(e)).
    tangential_solution solve(double Q, bool force_general = false, std::optional<zone_guess> guess = std::nullopt);

    // psi(t = -1) of a solution's stick zone: the coefficient of sqrt(1 + t) in q at its start.
    static double entry_coefficient(const tangential_solution& s);

private:
    // single_end: the fast path's c0 at this load, when it was solved (saves one search).
    tangential_solution general(double magnitude, std::optional<zone_guess> guess, std::optional<double> single_end);
    std::optional<tangential_solution> newton(double magnitude, double start, double c0);
    std::optional<tangential_solution> continuation(double magnitude);  // from gross sliding, 7(e)
    tangential_solution gross_sliding();
    zone_family family(double magnitude);  // the zones carrying |Q| = magnitude (zone_family.hpp)
    double load_excess(const tangential_solution& t, double magnitude) const;  // Q - |Q|, without f's rounding

    tangential_solver& single_;
    double f_;
};

}  // namespace roughroll
