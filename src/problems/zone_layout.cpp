// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_layout.hpp"

#include "roughroll/problems/dissimilar_zones.hpp"

namespace roughroll {

std::vector<zone> zones_of(const five_zone_solution& v) {
    // slip -sign, stick, slip +sign, stick, slip -sign (8(j)), sign = sgn beta_D.
    const int d = v.sign > 0.0 ? 1 : -1;
    return {zone{-1.0, v.s1, false, -d}, zone{v.s1, v.c1, true, 0}, zone{v.c1, v.s2, false, d},
            zone{v.s2, v.c2, true, 0}, zone{v.c2, 1.0, false, -d}};
}

std::vector<zone> zones_of(const tangential_solution& s) {
    if (s.five) return zones_of(*s.five);
    const int direction = s.sign < 0.0 ? -1 : 1;
    std::vector<zone> z;
    if (s.start > -1.0) z.push_back({-1.0, s.start, false, s.opposite ? -direction : direction});
    z.push_back({s.start, s.c0, true, 0});
    if (s.c0 < 1.0) z.push_back({s.c0, 1.0, false, direction});
    return z;
}

}  // namespace roughroll
