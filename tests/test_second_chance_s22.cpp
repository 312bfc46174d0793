// SPDX-License-Identifier: GPL-3.0-or-later
// The estimate's second chance (levels n/2, n, 2n where n/4, n/2, n give no estimate) where its last change is within
// the floor F of those levels (docs/formulation.md 8(j), "A last change within the floor"). The second chance accepted
// only an observed order p - 1 (d1/d2 >= 8), so a last change of rounding, whose sign and size mean nothing, refused
// the point: the rough pair's free rolling at n = 384 (data/aluminium-on-steel-rough.toml), whose second zone's start
// moved -1.51e-8 then 3.54e-10 over 192, 384, 768 within F = 4.0e-9. Now such levels are bounded by 2 (|d2| + F) + F
// where the change before, less its own rounding, is at least 2 (|d2| + F) (they contract into the floor at least as an
// order-1 method), by bound_error's rounding branch where both changes are within F, and refused where
// F < |d1| < 2 (|d2| + F) + F. The made-up levels below are that point's (--method product: its s2 at 192, 384, 768;
// 96 chosen so that n/4, n/2, n fail: ratio -3.3).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {
namespace {

// The rough pair's five zones at n = 384 (free rolling, f = 0.05, Johnson's level).
constexpr double s1 = -0.8134237449751915, c1 = 0.6880060484521053, c2 = 0.9662936532367653;
constexpr double s2_192 = 0.91856664201678984;
constexpr double floor_2n = 4.0e-9;  // the second chance's floor of the ends (eps/rcond of level 768's zone systems)

estimate_level five(double s2) {
    tangential_solution t{};
    t.layout = five_zones_layout(s1, c1, s2, c2, 1);
    t.xi = -0.0618160561;
    return estimate_level{t, 1.4726672424};
}

using est = error_estimate;
// The floor of n/4, n/2, n (1e-12) lets those levels show their ratio; the finer floor is level 2n's.
const std::vector<estimated_quantity> table{
    {"the second stick zone's start", value_start2, 1e-12, floor_2n, false, true, &est::start}};

// The estimate of level n = 384 from s2 at 96 (192's value + d0), 192, 384 (+ d1), 768 (+ d1 + d2); or the refusal.
struct outcome {
    std::optional<error_estimate> e;
    std::string refusal;
};
outcome estimate_of(double d0, double d1, double d2) {
    const std::array<estimate_level, 3> levels{five(s2_192 - d0), five(s2_192), five(s2_192 + d1)};
    const estimate_level finer = five(s2_192 + d1 + d2);
    const estimate_point p{method::product, 384, 2, estimate_structure::dissimilar, false, true, "Q", 0.0};
    try {
        return {estimate_from_levels(
                    table, levels, [&] { return std::optional<estimate_level>(finer); }, p),
                ""};
    } catch (const resolution_error& e) {
        return {std::nullopt, e.what()};
    }
}

constexpr double d0 = 5.0e-8;  // n/4 -> n/2: with d1 = -1.51e-8 a ratio of -3.3, no estimate from n/4, n/2, n

TEST(SecondChanceWithinFloor, ALastChangeOfRoundingAfterAContractionIsBounded) {
    // The rough pair's levels: refused before ("does not converge visibly over the levels n = 192, 384, 768").
    const outcome o = estimate_of(d0, -1.51e-8, 3.54e-10);
    ASSERT_TRUE(o.e) << o.refusal;
    // 2 (|d2| + F) + F: at least the floor, and above level n's distance from the finer levels (3.54e-10).
    EXPECT_NEAR(o.e->start, 2.0 * (3.54e-10 + floor_2n) + floor_2n, 1e-15);
    EXPECT_TRUE(o.e->start_second_zone);
    EXPECT_NE(o.e->against.find("n/2, n, 2n where n/4 fell short"), std::string::npos) << o.e->against;
    // The sign of the rounding does not matter.
    const outcome other = estimate_of(d0, -1.51e-8, -3.54e-10);
    ASSERT_TRUE(other.e) << other.refusal;
    EXPECT_NEAR(other.e->start, o.e->start, 1e-15);
}

TEST(SecondChanceWithinFloor, BothChangesOfRoundingAreBounded) {
    // d1 = 2e-9, d2 = 1e-9, both within F: no ratio to read (2, below 8: refused before); bound_error's rounding
    // branch, F + |d1| + |d2| for the middle level.
    const outcome o = estimate_of(-3.0e-9, 2.0e-9, 1.0e-9);  // n/4, n/2, n: ratio -1.5, no estimate
    ASSERT_TRUE(o.e) << o.refusal;
    EXPECT_NEAR(o.e->start, floor_2n + 3.0e-9, 1e-15);
}

TEST(SecondChanceWithinFloor, NoContractionIntoTheFloorIsRefused) {
    // The change before (6e-9) is above F but below twice the change the last may hide (2 (|d2| + F) = 8.7e-9): the
    // levels need not have converged, a coincidence of levels n and 2n is not excluded.
    const outcome o = estimate_of(1.2e-8, -6.0e-9, 3.54e-10);
    EXPECT_FALSE(o.e) << o.e->start;
    EXPECT_NE(o.refusal.find("the second stick zone's start does not converge visibly over the levels n = 192, 384, 768"),
              std::string::npos)
        << o.refusal;
    // The change before, less its own rounding F, must reach 2h: d1 = -1e-8 lies between 2h = 8.7e-9 and 2h + F =
    // 1.27e-8, its discretisation part perhaps only 6e-9, no contraction by 2.
    const outcome margin = estimate_of(2.0e-8, -1.0e-8, 3.54e-10);
    EXPECT_FALSE(margin.e) << margin.e->start;
    EXPECT_NE(margin.refusal.find("over the levels n = 192, 384, 768"), std::string::npos) << margin.refusal;
    // A last change above the floor keeps the rule of before: at least order p - 1 (here -1.51e-8, 5e-9: ratio -3).
    const outcome above = estimate_of(d0, -1.51e-8, 5.0e-9);
    EXPECT_FALSE(above.e) << above.e->start;
    EXPECT_NE(above.refusal.find("over the levels n = 192, 384, 768"), std::string::npos) << above.refusal;
}

}  // namespace
}  // namespace roughroll
