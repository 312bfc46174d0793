// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_layout.hpp"

#include <stdexcept>
#include <string>

namespace roughroll {

const char* to_string(zone_route route) {
    switch (route) {
        case zone_route::single: return "single";
        case zone_route::general: return "general";
        case zone_route::layers_neglected: return "no-slip";  // docs/formulation.md 8(n)
    }
    return "single";
}

std::size_t zone_layout::stick_zones() const {
    std::size_t k = 0;
    for (const zone& z : zones) k += z.stick ? 1 : 0;
    return k;
}

const zone& zone_layout::stick_zone(std::size_t k) const {
    std::size_t seen = 0;
    for (const zone& z : zones)
        if (z.stick && seen++ == k) return z;
    // Only a layout built by hand, as a default-built tangential_solution's, lacks the zone asked for: a
    // programming error (the program's "internal error", exit 70), not a fault of the input.
    throw std::out_of_range("no stick zone " + std::to_string(k + 1) + " among the layout's " +
                            std::to_string(stick_zones()) + " (a solution gets its zones from a solver)");
}

std::vector<double> zone_layout::stick_ends() const {
    std::vector<double> ends;
    for (const zone& z : zones)
        if (z.stick) ends.insert(ends.end(), {z.from, z.to});
    return ends;
}

bool zone_layout::sticks(double r) const {
    for (const zone& z : zones)
        if (z.stick && r >= z.from && r < z.to) return true;
    return false;
}

bool zone_layout::opposite() const {
    bool up = false, down = false;
    for (const zone& z : zones) {
        up = up || (!z.stick && z.direction > 0);
        down = down || (!z.stick && z.direction < 0);
    }
    return up && down;
}

bool same_zones(const zone_layout& a, const zone_layout& b) {
    if (a.zones.size() != b.zones.size()) return false;
    for (std::size_t i = 0; i < a.zones.size(); ++i)
        if (a.zones[i].stick != b.zones[i].stick || a.zones[i].direction != b.zones[i].direction) return false;
    return true;
}

const char* zone_kind(const zone& z) { return z.stick ? "stick" : z.direction > 0 ? "slip+" : "slip-"; }

std::string zones_kinds(const zone_layout& layout) {
    std::string text;
    for (const zone& z : layout.zones) text += (text.empty() ? "" : ", ") + std::string(zone_kind(z));
    return text;
}

namespace {
zone_layout three(double start, double c0, zone_route route, int leading, int trailing) {
    zone_layout l;
    l.route = route;
    if (start > -1.0) l.zones.push_back({-1.0, start, false, leading});
    l.zones.push_back({start, c0, true, 0});
    if (c0 < 1.0) l.zones.push_back({c0, 1.0, false, trailing});
    return l;
}
}  // namespace

zone_layout one_stick_zone(double start, double c0, zone_route route, int direction) {
    return three(start, c0, route, direction, direction);
}

zone_layout opposite_zones(double start, double c0, int direction) {
    return three(start, c0, zone_route::general, -direction, direction);
}

zone_layout five_zones_layout(double s1, double c1, double s2, double c2, int d) {
    return {{zone{-1.0, s1, false, -d}, zone{s1, c1, true, 0}, zone{c1, s2, false, d}, zone{s2, c2, true, 0},
             zone{c2, 1.0, false, -d}},
            zone_route::general};
}

zone_layout layers_neglected_layout() { return {{zone{-1.0, 1.0, true, 0}}, zone_route::layers_neglected}; }

zone_layout mirrored(zone_layout layout) {
    for (zone& z : layout.zones) z.direction = -z.direction;
    return layout;
}

}  // namespace roughroll
