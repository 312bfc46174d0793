// SPDX-License-Identifier: GPL-3.0-or-later
// Gross sliding, |Q| = f (docs/formulation.md 2(g), 7(d), 8(g), 8(s)): p1 = f p on the whole contact of the
// |Q| problem, q = 0, and the slip velocity of (3.6) with (3.15),
//   v(r) = xi + scale w(r) >= 0        (3.4),   w = G of (3.25) (scale f), or b p + f G (scale 1)
//                                                with Dundurs' forcing b of 8(e),
// must vanish somewhere (the limit of a shrinking stick zone): the stick zone shrinks to the point r*
// where w is least, and
//   xi = -scale w(r*),   r* = argmin_[-1, 1] w.
// The paper's edge form (2(g)) is r* = -1, xi = -f G(-1), the answer for G' >= 0. One construction
// for every zone search (the paper's single zone, the general and one-parameter searches, the
// dissimilar three zones).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// The |Q| solution at gross sliding with the stick zone shrunk to `point` and the creep `xi`
// (Q = f, no stick traction, rcond 1: no system is solved). Route general where `point` > -1 (slip on both sides).
tangential_solution gross_sliding_at(double f, double point, double xi);

// The least point r* of w on [-1, 1] and the solution there with its forcing b: w = G (scale f) for b = 0,
// else w = b p + f G (scale 1), p the pressure of `normal`; `G` at points in descending order
// (least_on_contact: 2001 samples, golden section, the edge r = -1 compared, and r = 1 with `trailing_edge`;
// `who` opens its message).
tangential_solution gross_sliding(const normal_solution& normal, double f, double forcing,
                                  const std::function<std::vector<double>(const std::vector<double>&)>& G,
                                  bool trailing_edge = false, const std::string& who = "zone solver");

}  // namespace roughroll
