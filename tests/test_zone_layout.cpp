// SPDX-License-Identifier: GPL-3.0-or-later
// problems/zone_layout: the stick zones a solution's c0(), start(), start2() and end2() read, and what a
// solution without zones (built by hand, never by a solver) does when asked for them.
#include "roughroll/problems/zone_layout.hpp"

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {
namespace {

TEST(ZoneLayout, StickZonesAreCountedFromTheLeadingEdge) {
    const zone_layout five = five_zones_layout(-0.9, -0.2, 0.1, 0.6, 1);
    ASSERT_EQ(five.stick_zones(), 2u);
    EXPECT_EQ(five.stick_zone(0).from, -0.9);
    EXPECT_EQ(five.stick_zone(0).to, -0.2);
    EXPECT_EQ(five.stick_zone(1).from, 0.1);
    EXPECT_EQ(five.stick_zone(1).to, 0.6);

    tangential_solution s{};
    s.layout = one_stick_zone(-0.5, 0.25);
    EXPECT_EQ(s.start(), -0.5);
    EXPECT_EQ(s.c0(), 0.25);
    EXPECT_EQ(s.start2(), 2.0);  // one stick zone: the second lies outside the contact
    EXPECT_EQ(s.end2(), 2.0);
}

// A zone the layout lacks is a programming error: std::out_of_range (a std::logic_error, which the
// program reports as an internal error, exit 70), never a roughroll::error (a fault of the input,
// exit 2), with a message that says which zone and why instead of naming a C++ function.
TEST(ZoneLayout, AMissingStickZoneIsAnOutOfRangeError) {
    static_assert(std::is_base_of_v<std::logic_error, std::out_of_range>);
    static_assert(!std::is_base_of_v<error, std::out_of_range>);
    const tangential_solution none{};
    EXPECT_THROW(none.c0(), std::out_of_range);
    EXPECT_THROW(none.start(), std::out_of_range);
    EXPECT_THROW(none.rho(), std::out_of_range);
    EXPECT_EQ(none.start2(), 2.0);  // guarded by stick_zones()
    try {
        none.c0();
        FAIL() << "c0() of a solution without zones returned";
    } catch (const std::out_of_range& e) {
        EXPECT_EQ(std::string(e.what()),
                  "no stick zone 1 among the layout's 0 (a solution gets its zones from a solver)");
    }
    try {
        (void)one_stick_zone(-1.0, 0.3).stick_zone(1);
        FAIL() << "a second stick zone of one";
    } catch (const std::out_of_range& e) {
        EXPECT_EQ(std::string(e.what()),
                  "no stick zone 2 among the layout's 1 (a solution gets its zones from a solver)");
    }
}

// One system per stick zone (docs/formulation.md 7(k)): a point of one stick zone is its own zone's system; a point of
// several carries them in order from r = -1, shared by its copies; a zone it lacks, or a layout of several zones
// without their systems (built by hand), is std::out_of_range. (Fails where zone_system(k) returns the point for every
// k, or the systems in another order.)
TEST(ZoneLayout, OneSystemPerStickZone) {
    const tangential_solution one = zone_solution(0.3, -0.5, 0.25, 0.1, 0.2, {1.0, 2.0}, 1.0);
    EXPECT_EQ(&one.zone_system(0), &one);
    EXPECT_THROW((void)one.zone_system(1), std::out_of_range);

    tangential_solution five = zone_solution(0.3, -0.9, -0.2, 0.1, 0.0, {}, 1.0);
    five.layout = five_zones_layout(-0.9, -0.2, 0.1, 0.6, 1);
    EXPECT_THROW((void)five.zone_system(0), std::out_of_range);  // two stick zones, no systems
    five.zone_systems = std::make_shared<const std::vector<tangential_solution>>(std::vector{
        zone_solution(0.3, -0.9, -0.2, 0.1, 0.0, {3.0}, 1.0), zone_solution(0.3, 0.1, 0.6, 0.1, 0.0, {4.0}, 1.0)});
    const tangential_solution copy = five;
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(copy.zone_system(k).start(), five.layout.stick_zone(k).from) << k;
        EXPECT_EQ(copy.zone_system(k).c0(), five.layout.stick_zone(k).to) << k;
        EXPECT_EQ(&copy.zone_system(k), &five.zone_system(k)) << k;  // shared, not copied
    }
    EXPECT_EQ(copy.zone_system(1).psi_b, std::vector<double>{4.0});
    EXPECT_THROW((void)copy.zone_system(2), std::out_of_range);
}

// The systems are held to one per stick zone of the layout (session 25 review R9): a layout changed after its systems
// were made (one stick zone left, or three) reads no system of another zone, and stick_systems (Newton's residuals,
// zone_newton.hpp) lists exactly the layout's. (Fails before session 26: zone_systems->at(k) answered zone 1's system
// on a one-zone layout and zone 2's on a layout of three stick zones, and stick_systems listed both systems.)
TEST(ZoneLayout, SystemsCountedAgainstTheLayout) {
    tangential_solution s = zone_solution(0.3, -0.9, -0.2, 0.1, 0.0, {}, 1.0);
    s.zone_systems = std::make_shared<const std::vector<tangential_solution>>(std::vector{
        zone_solution(0.3, -0.9, -0.2, 0.1, 0.0, {3.0}, 1.0), zone_solution(0.3, 0.1, 0.6, 0.1, 0.0, {4.0}, 1.0)});
    EXPECT_THROW((void)s.zone_system(0), std::out_of_range);  // one stick zone, two systems
    EXPECT_THROW((void)stick_systems(s), std::out_of_range);
    try {
        (void)s.zone_system(0);
    } catch (const std::out_of_range& e) {
        EXPECT_EQ(std::string(e.what()), "no system of stick zone 1 on this solution (1 stick zones, 2 systems)");
    }
    s.layout = {{{-1.0, -0.9, false, -1}, {-0.9, -0.2, true, 0}, {-0.2, 0.1, false, 1}, {0.1, 0.3, true, 0},
                 {0.3, 0.4, false, -1}, {0.4, 0.6, true, 0}, {0.6, 1.0, false, -1}},
                zone_route::general};
    EXPECT_THROW((void)s.zone_system(1), std::out_of_range);  // three stick zones, two systems
    s.layout = five_zones_layout(-0.9, -0.2, 0.1, 0.6, 1);
    EXPECT_EQ(s.zone_system(1).psi_b, std::vector<double>{4.0});
    EXPECT_EQ(stick_systems(s).size(), 2u);
}

// The levels of an estimate compare zone ends only on the same zones (docs/formulation.md 7(e) "Unlike zones are not
// compared"): the same kinds in the same order, whatever the ends; a leading slip zone at one level and none at another,
// another slip direction, or five zones against three are unlike. (Fails where same_zones reads the count alone.)
TEST(ZoneLayout, SameZonesComparesKindsNotEnds) {
    const zone_layout general = one_stick_zone(-0.98, -0.88, zone_route::general);
    EXPECT_TRUE(same_zones(general, one_stick_zone(-0.97, -0.80, zone_route::general)));
    EXPECT_FALSE(same_zones(general, one_stick_zone(-1.0, -0.88, zone_route::general)));  // no leading slip zone
    EXPECT_FALSE(same_zones(general, opposite_zones(-0.98, -0.88)));                      // leading slip against Q
    EXPECT_FALSE(same_zones(general, one_stick_zone(-0.98, -0.88, zone_route::general, -1)));
    EXPECT_FALSE(same_zones(five_zones_layout(-0.9, -0.2, 0.1, 0.6, 1), opposite_zones(-0.9, 0.6)));
    EXPECT_EQ(zones_kinds(general), "slip+, stick, slip+");
    EXPECT_EQ(zones_kinds(five_zones_layout(-0.9, -0.2, 0.1, 0.6, 1)), "slip-, stick, slip+, stick, slip-");
}

}  // namespace
}  // namespace roughroll
