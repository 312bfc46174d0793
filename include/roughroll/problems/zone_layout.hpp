// SPDX-License-Identifier: GPL-3.0-or-later
// The stick and slip zones of a solution as data, from r = -1 to 1 (docs/formulation.md 7, 8(g),
// 8(j)): the paper's [stick, slip] (3.2); [slip, stick, slip] of the general search (7); the
// leading slip zone against the trailing one of dissimilar rollers (8(g)); the five zones of free
// rolling (8(j)); gross sliding (a stick zone shrunk to a point) and full stick. What the reports
// (io/output, the traction plot, the Python module) read, without the solvers that found them.
#pragma once

#include <vector>

#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// One zone of the contact in r = x1/a.
struct zone {
    double from, to;
    bool stick;
    int direction;  // slip: +1 or -1, the sign of p1 there (and of the slip velocity, (3.4)); stick: 0
};

// The zones of s from r = -1 to 1: [-1, start) slip when start > -1, [start, c0] stick (a point at
// gross sliding), (c0, 1] slip when c0 < 1, slip in the direction of Q; the leading slip zone
// reversed for a blended stick zone (s.opposite, 8(g)); five zones from s.five (8(j)): slip -d,
// stick, slip d, stick, slip -d with d = sgn beta_D.
std::vector<zone> zones_of(const tangential_solution& s);
std::vector<zone> zones_of(const five_zone_solution& v);  // the five zones alone

}  // namespace roughroll
