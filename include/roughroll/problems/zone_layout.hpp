// SPDX-License-Identifier: GPL-3.0-or-later
// The stick and slip zones of a solution as data, from r = -1 to 1 (docs/formulation.md 7 "The
// layout"): each zone stick, or slip with its direction, and the route that found them. Every
// structure the solvers produce is one of
//   - the paper's [stick, slip] (3.2): stick [-1, c0], slip (c0, 1] in the direction of Q;
//   - [slip, stick, slip] of the general search (7) and of dissimilar rollers with both slip zones
//     in the direction of Q (8(e));
//   - [slip, stick, slip] with the leading slip against the trailing one (dissimilar rollers, 8(g));
//   - the five zones of free rolling, slip -d, stick, slip d, stick, slip -d, d = sgn beta_D (8(j));
//   - gross sliding: a stick zone shrunk to a point (2(g), 8(g)); full stick: stick [-1, 1];
//   - no slip with the edge layers neglected (8(n)): stick [-1, 1], the route saying so.
// What the reports (io/output, the traction plot, the Python module), the checks and the estimate
// read, without the solvers that found them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace roughroll {

// One zone of the contact in r = x1/a.
struct zone {
    double from, to;
    bool stick;
    int direction;  // slip: +1 or -1, the sign of p1 there (and of the slip velocity, (3.4)); stick: 0
};

// How the zones were found: the paper's single zone [-1, c0] (its root search, or Carter's closed
// form), the general search of section 7 (and every structure of dissimilar rollers, 8(g), 8(j)),
// or the no-slip solution with the edge layers neglected (8(n)), which is not found by a search.
enum class zone_route { single, general, layers_neglected };
const char* to_string(zone_route route);  // "single", "general", "no-slip" (the outputs' zone_path)

struct zone_layout {
    std::vector<zone> zones;  // adjacent, from r = -1 to 1
    zone_route route = zone_route::single;

    std::size_t stick_zones() const;
    // The k-th stick zone from r = -1; std::out_of_range for k >= stick_zones() (no solver asks for one).
    const zone& stick_zone(std::size_t k) const;
    // The ends of the stick zones from r = -1, each zone's from and to: [start, c0] of one zone, (s1, c1, s2, c2)
    // of five (the start of Newton's method in the ends, zone_newton.hpp; the nodes between them, point_estimate).
    std::vector<double> stick_ends() const;
    // r on a stick zone [from, to): the half-open zone the slip velocity's sweeps skip.
    bool sticks(double r) const;
    // Slip zones in both directions: the blended stick zone of 8(g), and the five zones of 8(j).
    bool opposite() const;
    bool layers_neglected() const { return route == zone_route::layers_neglected; }
    bool general() const { return route != zone_route::single; }  // not the paper's single zone
};

// One stick zone [start, c0] with slip in `direction` on both sides: [-1, start) when start > -1,
// (c0, 1] when c0 < 1. The paper's zone (start = -1), the general search's (7), the equal-direction
// three zones of dissimilar rollers (8(e)), gross sliding (start = c0), full stick (c0 = 1).
zone_layout one_stick_zone(double start, double c0, zone_route route = zone_route::single, int direction = 1);
// The leading slip zone against the trailing one (8(g)): slip -direction [-1, start) when start > -1,
// stick [start, c0], slip direction (c0, 1] when c0 < 1. Route general.
zone_layout opposite_zones(double start, double c0, int direction = 1);
// Five zones (8(j)): slip -d [-1, s1), stick [s1, c1], slip d (c1, s2), stick [s2, c2], slip -d (c2, 1].
// Route general.
zone_layout five_zones_layout(double s1, double c1, double s2, double c2, int d);
// No slip on [-1, 1], the edge layers neglected (8(n)).
zone_layout layers_neglected_layout();
// Whether a and b have the same zones in the same order, each stick or slip in the same direction (their ends may
// differ): the levels of an estimate compare their zone ends only where this holds (docs/formulation.md 7(e), "Unlike
// zones are not compared").
bool same_zones(const zone_layout& a, const zone_layout& b);
// A zone's kind as the outputs name it: "stick", "slip+" or "slip-" (the slip direction).
const char* zone_kind(const zone& z);
// The zones' kinds from r = -1, e.g. "slip+, stick, slip+" (a refusal's words for a structure).
std::string zones_kinds(const zone_layout& layout);
// The mirror of a load Q < 0 (docs/formulation.md 2, 8(h)): every slip direction changes sign.
zone_layout mirrored(zone_layout layout);

}  // namespace roughroll
