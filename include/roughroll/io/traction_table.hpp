// SPDX-License-Identifier: GPL-3.0-or-later
// The tractions of one creep point on a grid of r = x1/a, with smooth cylinders' beside them and,
// for a physical scene, the same in SI units: the rows `roughroll traction` writes as CSV and
// Python's Scene.traction returns as arrays, computed here once for both.
//   r, p = a p2/P2 of (4.1), p1 = a p1/P2 of (3.15), the slip velocity v of (3.6) (0 on a stick
//   zone; NaN where not resolved: the trailing edge layer of a point with its layers neglected,
//   docs/formulation.md 8(n)), stick: r on a stick zone (contact::distributions);
//   p_hertz, p1_carter: Carter's smooth cylinders at the same Q and f, each on its own half-width
//   (Hertz's p = (2/pi) sqrt(1 - r^2); p1 = f p - (2 f/pi) sqrt(rho^2 - (r + 1 - rho)^2) on the
//   stick zone [-1, c0], rho = (1 + c0)/2 (Johnson, Contact Mechanics 8.4), with the sign of Q);
//   a physical scene: x1_m = r a (m), p2_Pa = p P2/a, p1_Pa = p1 P2/a (Pa) (physical_scene.hpp).
#pragma once

#include <optional>
#include <vector>

#include "roughroll/model/physical_scene.hpp"
#include "roughroll/problems/contact.hpp"

namespace roughroll {

struct traction_row {
    double r, p, p1, v;
    bool stick;
    double p_hertz, p1_carter;
    std::optional<double> x1_m, p2_Pa, p1_Pa;  // a physical scene's (`si` given)
};

// Carter's smooth tractions at r for the load Q and friction f (the header's formulas): {p, p1}.
struct smooth_traction {
    double p, p1;
};
smooth_traction carter_tractions(double r, double Q, double f);

// The rows at `grid` (each in [-1, 1]) of the distributions `level` of contact `c` (contact::
// distribution: level n's own c0 and xi when extrapolating), for the load Q at friction f; `si`:
// the point in SI units of a physical scene (its p_scale and a), nothing for a dimensionless one.
std::vector<traction_row> traction_table(contact& c, const tangential_solution& level, const std::vector<double>& grid,
                                         double Q, double f, const std::optional<si_point>& si);

}  // namespace roughroll
