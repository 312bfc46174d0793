// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's inequalities on every zone of a solution (docs/formulation.md 2(h); 7(b) for a stick
// zone inside the contact, 8(g) for slip zones of either direction), whatever searched the zones:
//   p >= 0                    on (-1, 1),
//   (3.3)  f p - |p1| >= 0     on each stick zone,
//   (3.4)  d v > 0             on each slip zone, d its direction (p1 = d f p there), v of (3.6),
// on 200 interior Chebyshev points of each zone, clustered towards its ends where the tractions have
// their square-root behaviour, the margins relative to f. (3.3) holds to a rounding floor when the
// solver has one (docs/formulation.md 7(d): the collocation cancels the right-hand side's terms to the
// size of q), i.e. margin >= -floor, and (3.4) when margin > -floor.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

// What a solver supplies to check its zones.
struct zone_check_terms {
    double f;
    // min p on (-1, 1) (least_pressure: independent of the zones); the no-slip route's on [-1 + t, 1 - t]
    double pressure_margin;
    double rounding;         // the margins' rounding floor, reported with them
    bool within_rounding;    // the floor applies (else the margins are held to 0)
    // f p - |p1| at points of one stick zone.
    std::function<std::vector<double>(const std::vector<double>& r)> stick_gap;
    // v at the points of every slip zone, in descending order (the zones from r = 1 back to -1).
    std::function<std::vector<double>(const std::vector<double>& r)> slip_velocity;
};

traction_checks check_zones(const std::vector<zone>& zones, const zone_check_terms& terms);

// The same from p, p1 and v at one point at a time (terms' stick_gap and slip_velocity unused).
traction_checks check_zones(const std::vector<zone>& zones, zone_check_terms terms, const std::function<double(double)>& p,
                            const std::function<double(double)>& p1, const std::function<double(double)>& v);

// min p of (4.1) on the check grid of (-1, 1).
double least_pressure(const normal_solution& normal);
// The same on the check grid of (from, to): a route that models the pressure only there (the no-slip limit at full
// coupling, its edge layers neglected: docs/formulation.md 8(t), "Where the route checks").
double least_pressure(const normal_solution& normal, double from, double to);

// The margins (3.3)-(3.4) as a refusal shows them, "stick -0.00255, slip 0.331" (computed values: three significant
// digits). A margin over no zone of its kind (+infinity: the minimum over an empty set) reads "no slip zone", one
// that is not a finite number "stick not finite": never "inf" or "nan".
std::string margins_text(const traction_checks& c);

}  // namespace roughroll
