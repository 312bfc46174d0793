// SPDX-License-Identifier: GPL-3.0-or-later
// A refusal names the second stick zone's ends as themselves (five zones, docs/formulation.md 8(j)): their estimates are
// folded into c0's and the start's (formulation 7 "What c0 means"), and the ladder's line named the member ("stick
// start") where the second zone's start was the one that failed (full coupling's free rolling at f = 0.1 .. 0.45: s2
// wobbles between rungs). The estimate records whose end it is (error_estimate::start_second_zone, c0_second_zone, also
// in full coupling's level changes), check_estimate names it, and gives the least tolerance that accepts the estimate.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/level_ladder.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {
namespace {

// Free rolling's five zones at full coupling, f = 0.2 (n = 128: s1 -0.98483, c1 0.97528, s2 0.99292, c2 0.99845).
constexpr double s1 = -0.984834714870792, c1 = 0.975281940834336, s2 = 0.9929221973258827, c2 = 0.9984475729633667;

estimate_level five(double d1, double d2) {
    tangential_solution t{};
    t.layout = five_zones_layout(s1 + d1, c1, s2 + d2, c2, 1);
    t.xi = -0.0586508861;
    return estimate_level{t, 0.99203859};
}

using est = error_estimate;
const std::vector<estimated_quantity> table{
    {"c0", value_c0, 0.0, 0.0, false, true, &est::c0, true},
    {"the stick zone's start", value_start, 0.0, 0.0, false, true, &est::start, true},
    {"the second stick zone's end", value_end2, 0.0, 0.0, false, true, &est::c0, true},
    {"the second stick zone's start", value_start2, 0.0, 0.0, false, true, &est::start, true}};

error_estimate estimate_of(const std::array<estimate_level, 3>& levels) {
    const estimate_point p{method::extrapolated, 128, 2, estimate_structure::full_coupling, false, true, "Q", 0.0};
    return estimate_from_levels(
        table, levels, [] { return std::optional<estimate_level>(); }, p);
}

TEST(SecondZoneRefusal, TheEstimateRecordsWhoseStartItIs) {
    // The second zone's start changes 3.5e-6, -7.6e-7 (the wobble), the main zone's 1e-7, 5e-8: its bound is s2's.
    const error_estimate second = estimate_of({five(0.0, 0.0), five(1e-7, 3.5e-6), five(1.5e-7, 3.5e-6 - 7.6e-7)});
    EXPECT_TRUE(second.start_second_zone);
    EXPECT_FALSE(second.c0_second_zone);  // c0 and c2 did not move: the main zone's end (the first folded) is kept
    EXPECT_GE(second.start, 2.0 * 3.5e-6);
    ASSERT_TRUE(second.changes);
    EXPECT_TRUE(second.changes->last.start_second_zone);  // the next rung's certain part is s2's too
    // The main zone's start the larger: named as before.
    const error_estimate first = estimate_of({five(0.0, 0.0), five(3.5e-6, 1e-7), five(3.5e-6 - 7.6e-7, 1.5e-7)});
    EXPECT_FALSE(first.start_second_zone);
    EXPECT_FALSE(first.changes->last.start_second_zone);
}

TEST(SecondZoneRefusal, TheCheckNamesItAndTheToleranceThatAcceptsIt) {
    const tangential_solution s = five(0.0, 0.0).solution;
    error_estimate e{1e-9, 1e-9, 1e-12, 0.0, "", false, 2.1e-4};
    e.start_second_zone = true;
    const tolerance_check t = check_estimate(s, 0.99203859, e, 1e-4);
    EXPECT_GT(t.ratio, 1.0);
    EXPECT_EQ(t.quantity, "the second stick zone's start");
    EXPECT_EQ(t.estimate, 2.1e-4);
    // Its scale is the start's (1 + s1): the least accepting tolerance 2.1e-4/(1 + s1) = 0.0138, and every other
    // quantity within it.
    EXPECT_NEAR(t.answering, 2.1e-4 / (1.0 + s1), 1e-15);
    EXPECT_EQ(t.answering_quantity, "the second stick zone's start");
    EXPECT_LE(check_estimate(s, 0.99203859, e, t.answering * (1.0 + 1e-12)).ratio, 1.0);
    EXPECT_GT(check_estimate(s, 0.99203859, e, 0.99 * t.answering).ratio, 1.0);
    // Without the flag: the member's old name.
    e.start_second_zone = false;
    EXPECT_EQ(check_estimate(s, 0.99203859, e, 1e-4).quantity, "stick start");
    e.c0_second_zone = true;
    e.c0 = 1e-3;
    EXPECT_EQ(check_estimate(s, 0.99203859, e, 1e-4).quantity, "the second stick zone's end");
}

TEST(SecondZoneRefusal, TheAcceptingToleranceNamesItsOwnQuantity) {
    // Below every floor's tolerance the largest ratio e / floor and the largest relative estimate e / s may be of two
    // quantities: the advised tolerance is the second's, and the refusal names it (session 28 audit F4: fig2a-T1 at
    // --tolerance 1e-300 named P_H/P2 for the tolerance xi sets).
    tangential_solution s = five(0.0, 0.0).solution;
    s.f = 0.2;  // xi's floor is of |xi| + f (the problem's scale), P_H/P2's of lambda: e/floor and e/s order them apart
    const error_estimate e{1e-9, 0.0, 1e-10, 0.0, "", false, 0.0};
    const tolerance_check t = check_estimate(s, 0.99203859, e, 1e-300);
    EXPECT_EQ(t.quantity, "P_H/P2");
    EXPECT_EQ(t.answering_quantity, "xi");
    EXPECT_EQ(t.answering, 1e-10 / std::fabs(s.xi));
}

TEST(SecondZoneRefusal, NoToleranceAcceptsAnEstimateOfAZeroValueAboveItsFloor) {
    tangential_solution s = five(0.0, 0.0).solution;
    s.xi = 0.0;
    const error_estimate e{0.0, 0.0, 1e-3, 0.0, "", false, 0.0};
    EXPECT_TRUE(std::isinf(check_estimate(s, 1.0, e, 1e-4).answering));
}

// A level change that stalls (the second zone's start moves 1.49e-7 then 1.43e-7: free rolling's rung 256 at f = 0.2) is
// refused. With n given, the line advises another n or leaving n out (the ladder may answer below n too, also below
// n = 1000); on a ladder's rung it advises only the larger n the ladder goes on to: "leave n out" would advise what the
// user did (session 18 review).
TEST(SecondZoneRefusal, AStalledLevelAdvisesLeavingNOutOnlyWhereNWasGiven) {
    const std::array<estimate_level, 3> levels{five(0.0, 0.0), five(0.0, 1.49e-7), five(0.0, 1.49e-7 + 1.43e-7)};
    const auto refusal = [&](bool n_given, int n = 256) {
        estimate_point p{method::extrapolated, n, 2, estimate_structure::full_coupling, false, true, "Q", 0.0};
        p.n_given = n_given;
        try {
            estimate_from_levels(
                table, levels, [] { return std::optional<estimate_level>(); }, p);
        } catch (const resolution_error& e) {
            return std::string(e.what());
        }
        return std::string("answered");
    };
    const std::string given = refusal(true), rung = refusal(false);
    EXPECT_NE(given.find("does not converge visibly"), std::string::npos) << given;
    EXPECT_NE(given.find("leave n out"), std::string::npos) << given;
    EXPECT_NE(rung.find("does not converge visibly"), std::string::npos) << rung;
    EXPECT_EQ(rung.find("leave n out"), std::string::npos) << rung;
    EXPECT_NE(rung.find("a larger n (at most 1000) may converge"), std::string::npos) << rung;
    // At n = 1000 given, a smaller n may converge (the levels 250, 500, 1000 wobble where 128, 256, 512 need not): the
    // ladder; on the ladder's top rung, nothing is left to try.
    const std::string largest = refusal(true, 1000), top = refusal(false, 1000);
    EXPECT_NE(largest.find("a smaller n may converge (leave n out"), std::string::npos) << largest;
    EXPECT_EQ(largest.find("beyond the method's reach"), std::string::npos) << largest;
    EXPECT_NE(top.find("n is at its largest, so the load is beyond the method's reach"), std::string::npos) << top;
}

}  // namespace
}  // namespace roughroll
