// SPDX-License-Identifier: GPL-3.0-or-later
// A point of the tangential problem (3.21)-(3.22) as every solver returns it and every report reads
// it: the load, the creep, the zones (zone_layout.hpp), the stick traction's coefficients and the
// checks (3.3)-(3.4). A value, apart from the solvers (tangential_problem.hpp, one_parameter.hpp,
// dissimilar_zones.hpp): part of the public interface (roughroll.hpp).
#pragma once

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

// The paper's inequalities checked on interior grids of each zone.
struct traction_checks {
    double pressure_margin;       // min p on (-1, 1): p >= 0
    double stick_margin;          // (3.3) min of (f p - |p1|)/f on the stick zone
    double slip_margin;           // (3.4) min of v/f on the slip zone (v with the sign of Q)
    double stick_rounding = 0.0;  // the stick margin's rounding floor: (3.3) holds when margin >= -floor
    double slip_rounding = 0.0;   // the slip margin's: (3.4) holds when margin > -floor
    bool pressure_holds;
    bool stick_holds;
    bool slip_holds;

    bool hold() const { return pressure_holds && stick_holds && slip_holds; }
};

struct tangential_solution {
    double Q;                   // P1/P2
    double f;                   // friction coefficient
    double xi;                  // dimensionless creep
    double sign;                // +1, or -1 for the mirror case Q < 0
    std::vector<double> psi_b;  // U coefficients of psi(tau) for |Q| (multiply by sign)
    // Full coupling's braked stick zone (docs/formulation.md 8(v)): where weight_a > 0, psi_b are the coefficients
    // of psi in P_j^(a,b), a = weight_a, b = weight_b, and q = (1 - t)^a (1 + t)^b psi; 0: the U-series above.
    double weight_a = 0.0, weight_b = 0.0;
    int iterations;             // root-search iterations (secant or Brent; 0 without a search)
    double rcond;               // of the last tangential system (1 without a solve)
    double load_slope = 0.0;    // dQ/dc0 at c0 from the root search's last secant (0: unknown)
    double ends_resolution = 0.0;  // the zone ends' Newton resolution (newton_root::resolution); 0 without Newton
    traction_checks checks;
    // Dundurs' forcing of the |Q| problem (docs/formulation.md 8(e)): sigma beta_D, with sigma the
    // slip direction of both slip zones; the stick equation's right side and the slip velocity
    // gain forcing * p(r). 0 for the paper's problem.
    double forcing = 0.0;
    // The zones from -1 to 1, each stick or slip with its direction, and the route that found them
    // (zone_layout.hpp, docs/formulation.md 7(i)); its first stick zone is [start(), c0()]. Slip zones in
    // both directions (layout.opposite(): the blended stick zone of 8(g), five zones) make traction,
    // slip velocity and checks dissimilar_zones' own; layout.layers_neglected(): the no-slip solution
    // of 8(n), whose traction and checks are dissimilar_zones' too.
    zone_layout layout;
    // The stick zones' own systems, one per stick zone of the layout from r = -1, where the layout has several (five
    // zones, 8(j): each zone's psi_b, xi_k, rcond and forcing; the point's xi, Q, sign and checks are the whole
    // structure's, its psi_b empty); null where the point's own psi_b and xi are its one stick zone's. Shared: copies
    // of a point (full coupling's iterates, a curve's rows) share them. Read through zone_system(k).
    std::shared_ptr<const std::vector<tangential_solution>> zone_systems;

    // The ends of the first stick zone from r = -1, [start, c0] (docs/formulation.md 7(i)): the paper's
    // zone [-1, c0]; three zones [s, c0]; five zones the first, [s1, c1]; gross sliding the point
    // [r*, r*] (r* = -1 on the paper's zone); full stick and the layers-neglected no slip [-1, 1].
    // Derived from the layout, the one source of the zones; without zones (default-built) std::out_of_range.
    double c0() const { return layout.stick_zone(0).to; }
    double start() const { return layout.stick_zone(0).from; }
    double rho() const { return 0.5 * (c0() - start()); }
    // The second stick zone [start2, end2) of five zones (8(j)); 2, 2 (outside the contact) for every
    // other structure.
    double start2() const { return layout.stick_zones() > 1 ? layout.stick_zone(1).from : 2.0; }
    double end2() const { return layout.stick_zones() > 1 ? layout.stick_zone(1).to : 2.0; }
    // r on a stick zone [from, to) of the layout
    bool sticks(double r) const { return layout.sticks(r); }
    // The system of the k-th stick zone from r = -1 (its psi_b, xi_k, its ends [start(), c0()]): the point itself
    // where it has one stick zone; std::out_of_range for k >= layout.stick_zones(), and where the systems are not
    // one per stick zone of the layout (a layout changed after its systems were made, or built by hand without them:
    // a programming error, exit 70, as layout.stick_zone's; not a system read for another zone).
    const tangential_solution& zone_system(std::size_t k) const {
        const std::size_t zones = layout.stick_zones();
        if (k < zones) {
            if (zone_systems && zone_systems->size() == zones) return (*zone_systems)[k];
            if (!zone_systems && zones == 1) return *this;
        }
        throw std::out_of_range("no system of stick zone " + std::to_string(k + 1) + " on this solution (" +
                                std::to_string(zones) + " stick zones, " +
                                std::to_string(zone_systems ? zone_systems->size() : 1) + " systems)");
    }
};

}  // namespace roughroll
