// SPDX-License-Identifier: GPL-3.0-or-later
// Five zones' xi at its rounding (point_estimate.cpp floors_at; docs/formulation.md 8(q) "Five zones' xi at its
// rounding"; session 29 audit L2): each stick zone of five has its own system, and xi is read off (4.4) of each as off
// the general search's one zone, so it carries that zone's floor (stick_system_floor), which the point's empty psi_b
// had left out. Free rolling of data/aluminium-on-steel.toml at f = 1e-6, n = 1000 was refused as "xi does not converge
// visibly over the levels n = 250, 500, 1000 (differences 6.66e-16, -2.83e-14)": 3e-13 relative, rounding.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/problems/point_estimate.hpp"

using namespace roughroll;

namespace {
// Free rolling of the pair (Johnson's level: five zones) at friction f and n nodes.
scene_point free_rolling(double f, int n) {
    scene s = read_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml");
    s.friction = f;
    override_solver(s, n, std::nullopt);
    return solve_point(s, load_given(0.0));
}
}  // namespace

// The floor of xi on five zones is the stick systems' (growth 8 of n eps (|xi| + f K)), as on one zone of the general
// search: 8 times what it was (n eps (|xi| + f K) alone).
TEST(FiveZoneXiFloor, IsTheStickSystemsFloor) {
    const scene_point p = free_rolling(0.05, 32);
    ASSERT_EQ(p.solution.layout.stick_zones(), 2u);
    const double lambda = p.solved.normal().lambda;
    const rounding_floors floor = floors_at(32, p.solution, p.solution, lambda, 0.05, 0.0);
    EXPECT_GE(floor.xi, stick_system_floor(32, std::fabs(p.solution.xi) + 0.05 * std::max(1.0, lambda)));
    ASSERT_TRUE(p.estimate);
    EXPECT_GE(p.estimate->xi, floor.xi);
}

// f = 1e-6 at n = 1000: answered (refused before), its xi within the floor of n = 1000 and the sum of its estimate and
// n = 512's (levels 128, 256, 512, a second solution at other nodes) of n = 512's xi.
TEST(FiveZoneXiFloor, FreeRollingAtAMillionthAnsweredAtNThousand) {
    const scene_point p = free_rolling(1e-6, 1000);
    ASSERT_TRUE(p.estimate);
    ASSERT_EQ(p.solution.layout.stick_zones(), 2u);
    EXPECT_GE(p.estimate->xi, stick_system_floor(1000, std::fabs(p.solution.xi)));
    const scene_point reference = free_rolling(1e-6, 512);
    ASSERT_TRUE(reference.estimate);
    EXPECT_LE(std::fabs(p.solution.xi - reference.solution.xi), p.estimate->xi + reference.estimate->xi);
    EXPECT_LE(p.estimate->xi, 1e-11 * std::fabs(p.solution.xi));  // rounding: 2.1e-12 relative
}

// A raised floor never lowers an estimate where the changes show a visible ratio (error_bound.cpp, the both-rounding
// branch; session 30 review): changes 6, 4 (ratio 1.5) give 16 + 1 at the floor 1; at the floor 8 both are within it, and
// the rounding rule alone gave 8 + 4 = 12.
TEST(FiveZoneXiFloor, RaisedFloorNeverLowersTheEstimate) {
    const three_levels v{0.0, 6.0, 10.0};
    const error_bound low = bound_error(v, 4, reported_value{2, false}, 1.0);
    ASSERT_TRUE(low.resolved);
    EXPECT_DOUBLE_EQ(low.value, 17.0);
    for (const double floor : {4.0, 6.0, 8.0, 100.0}) {
        const error_bound high = bound_error(v, 4, reported_value{2, false}, floor);
        ASSERT_TRUE(high.resolved);
        EXPECT_GE(high.value, low.value) << "floor " << floor;
        EXPECT_GE(high.value, 16.0 + floor) << "floor " << floor;
    }
    // Changes within the floor that show no visible ratio (4.4, 4.04, 4.0004 then 4: below 1.5) keep the rounding rule,
    // floor + |d2|: their geometric tail 2/(r - 1) would have made 88, 808, 80008 of them at the floor 8.
    for (const double d1 : {4.4, 4.04, 4.0004}) {
        const error_bound b = bound_error({0.0, d1, d1 + 4.0}, 4, reported_value{2, false}, 8.0);
        ASSERT_TRUE(b.resolved);
        EXPECT_DOUBLE_EQ(b.value, 12.0) << "d1 " << d1;
    }
}
