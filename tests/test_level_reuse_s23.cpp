// SPDX-License-Identifier: GPL-3.0-or-later
// Full coupling's changes of opposite sign on rough rollers, confirmed on level 2n (docs/formulation.md 8(q) "Changes of
// opposite sign"), on made-up levels:
//   - the peak pressure confirms as the table's quantities do, and is refused where level 2n cannot be solved or n/2, n,
//     2n give no estimate (the program before kept the three levels' rule there, silently);
//   - a ladder's rung whose estimate from n/4, n/2, n already fails the ladder's tolerance does not solve level 2n: its
//     estimate is a lower bound (a confirmation only raises an estimate, so the rung cannot answer either way), and
//     rung 2n solves that level as its own point;
//   - off full coupling the peak confirms on level 2n too, never refused (8(e) "The peak confirmed on level 2n").
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/problems/zone_layout.hpp"

using namespace roughroll;

namespace {

// Full coupling on rough rollers, level n = 64 the finest of n/4, n/2, n (self 2).
estimate_point rough_point() {
    estimate_point p{method::product, 64, 2, estimate_structure::full_coupling, false, true, "Q", 0.0};
    p.rough = true;
    return p;
}

// A peak at r with value 1 at every level (the value does not change: only the position is confirmed) and no
// resolution band, so that the position's floor is 0 and every estimate below is exact arithmetic.
pressure_peak peak_at(double r) {
    pressure_peak k{};
    k.r = r;
    k.p = 1.0;
    k.r_resolution = 0.0;
    k.p_rounding = 0.0;
    return k;
}

estimate_level level_of(double xi) {
    tangential_solution t{};
    t.xi = xi;
    t.layout = one_stick_zone(-1.0, 0.5);
    return estimate_level{t, 1.0};
}

}  // namespace

// The position changes +2, -0.5 over n/4, n/2, n (opposite signs, above the floor 0). The three levels' rule gives 4.
// Level 2n at 5.5 (changes -0.5, +3 over n/2, n, 2n): twice the larger, 6, bounds level 2n, and level n is 3 farther:
// 9. Where level 2n cannot be solved, refused (the program before answered 4, the three levels' rule, which such changes
// do not make a bound); where n/2, n, 2n stall (-0.5, -0.5: no fall), refused as the table's quantities are (before: 4).
TEST(LevelReuse, PeakConfirmedOnLevelTwoNOrRefused) {
    const std::array<pressure_peak, 3> peaks{peak_at(1.0), peak_at(3.0), peak_at(2.5)};
    const estimate_point p = rough_point();
    int solved = 0;
    const auto at = [&solved](double r) {
        return [&solved, r]() -> std::optional<pressure_peak> {
            ++solved;
            return peak_at(r);
        };
    };
    EXPECT_TRUE(peak_asks_level_two_n(peaks, p));
    EXPECT_EQ(peak_from_levels(peaks, p, at(5.5)).r, 9.0);
    EXPECT_EQ(solved, 1);

    const auto none = []() -> std::optional<pressure_peak> { return std::nullopt; };
    EXPECT_THROW(peak_from_levels(peaks, p, none), resolution_error) << "level 2n not solved: no estimate";
    EXPECT_THROW(peak_from_levels(peaks, p, at(2.0)), resolution_error) << "n/2, n, 2n stall: no estimate";

    // Where the refusal is asked of a ladder's rung, it names what the user can change (the ladder climbs).
    estimate_point rung = p;
    rung.n_given = false;
    try {
        peak_from_levels(peaks, rung, none);
        ADD_FAILURE() << "not refused";
    } catch (const resolution_error& e) {
        const std::string line = e.what();
        EXPECT_NE(line.find("the peak pressure's position"), std::string::npos) << line;
        EXPECT_NE(line.find("a larger n"), std::string::npos) << line;
    }

    // Not confirmed where the point's estimate is a lower bound already (its rung cannot answer), nor above n = 500
    // (no level 2n: 8(q)'s limit), nor on smooth rollers: the three levels' 4, level 2n not asked.
    solved = 0;
    estimate_point lower = p;
    lower.lower_bound = true;
    EXPECT_EQ(peak_from_levels(peaks, lower, at(5.5)).r, 4.0);
    estimate_point top = p;
    top.n = 1000;
    EXPECT_EQ(peak_from_levels(peaks, top, at(5.5)).r, 4.0);
    estimate_point smooth = p;
    smooth.rough = false;
    EXPECT_EQ(peak_from_levels(peaks, smooth, at(5.5)).r, 4.0);
    EXPECT_EQ(solved, 0);
    EXPECT_FALSE(peak_asks_level_two_n(peaks, top));
    EXPECT_FALSE(peak_asks_level_two_n(peaks, smooth));
    EXPECT_FALSE(peak_asks_level_two_n({peak_at(1.0), peak_at(3.0), peak_at(3.5)}, p)) << "one sign: not asked";
}

// xi changes +2, -0.5 over n/4, n/2, n (as test_sign_change_s22's made-up levels): without level 2n twice the larger,
// 4; confirmed on level 2n at 5.5, 9. A ladder's tolerance that 4 already fails: level 2n is not solved, the estimate
// is the lower bound 4, marked. A tolerance that 4 meets: confirmed (9) as before, whatever the tolerance then says.
TEST(LevelReuse, RungThatCannotAnswerDoesNotSolveLevelTwoN) {
    const std::array<estimate_level, 3> levels{level_of(1.0), level_of(3.0), level_of(2.5)};
    const std::vector<estimated_quantity> table{{"xi", value_xi, 0.0, 0.0, false, true, &error_estimate::xi}};
    int solved = 0;
    const auto finer = [&]() -> std::optional<estimate_level> {
        ++solved;
        return level_of(5.5);
    };
    estimate_point p = rough_point();
    std::vector<double> asked;  // the estimates the ladder's test was shown
    p.fails_tolerance = [&asked](const error_estimate& e) {
        asked.push_back(e.xi);
        return e.xi > 3.0;
    };
    const error_estimate low = estimate_from_levels(table, levels, finer, p);
    EXPECT_EQ(solved, 0) << "level 2n solved for a rung that cannot answer";
    EXPECT_TRUE(low.lower_bound);
    EXPECT_EQ(low.xi, 4.0);
    EXPECT_EQ(asked, std::vector<double>{4.0});
    EXPECT_NE(low.against.find("a lower bound"), std::string::npos) << low.against;
    ASSERT_TRUE(low.changes.has_value()) << "the ladder's rules (a), (b) read the changes of a lower bound too";
    EXPECT_EQ(low.changes->last.xi, 0.5 - 4.0 * coupling_end_tolerance);

    p.fails_tolerance = [](const error_estimate& e) { return e.xi > 5.0; };
    const error_estimate confirmed = estimate_from_levels(table, levels, finer, p);
    EXPECT_EQ(solved, 1);
    EXPECT_FALSE(confirmed.lower_bound);
    EXPECT_EQ(confirmed.xi, 9.0);
    EXPECT_NE(confirmed.against.find("confirmed on n/2, n, 2n"), std::string::npos) << confirmed.against;

    // No ladder (n given): confirmed, as before.
    p.fails_tolerance = nullptr;
    EXPECT_EQ(estimate_from_levels(table, levels, finer, p).xi, 9.0);
    EXPECT_EQ(solved, 2);

    // Changes of one sign (no confirmation asked): the test is not asked, nothing marked.
    const std::array<estimate_level, 3> falling{level_of(1.0), level_of(3.0), level_of(3.5)};
    asked.clear();
    p.fails_tolerance = [&asked](const error_estimate& e) {
        asked.push_back(e.xi);
        return true;
    };
    const error_estimate one_sign = estimate_from_levels(table, falling, finer, p);
    EXPECT_FALSE(one_sign.lower_bound);
    EXPECT_TRUE(asked.empty());
    EXPECT_EQ(solved, 2);
}

// Off full coupling (docs/formulation.md 8(e) "The peak confirmed on level 2n", session 26 audit F5): the paper's
// problem and dissimilar rollers at Johnson's level by product, the same positions +2, -0.5 over n/4, n/2, n.
// error_bound's rule takes the ratio -4 as twice the last change, 1 (what the program printed before). Level 2n at 5.5:
// n/2, n, 2n show no order (-0.5, +3), so twice their larger change plus the change above n, 9. Level 2n not at hand:
// twice the larger change of the three levels, 4. Never refused off full coupling.
TEST(LevelReuse, PeakConfirmedOffFullCoupling) {
    const std::array<pressure_peak, 3> peaks{peak_at(1.0), peak_at(3.0), peak_at(2.5)};
    for (const estimate_structure s : {estimate_structure::paper, estimate_structure::dissimilar}) {
        const estimate_point p{method::product, 64, 2, s, false, true, "Q", 0.0};
        EXPECT_TRUE(peak_asks_level_two_n(peaks, p));
        EXPECT_EQ(peak_from_levels(peaks, p, [] { return std::optional<pressure_peak>(peak_at(5.5)); }).r, 9.0);
        EXPECT_EQ(peak_from_levels(peaks, p, [] { return std::optional<pressure_peak>(); }).r, 4.0);
        EXPECT_FALSE(peak_asks_level_two_n({peak_at(1.0), peak_at(3.0), peak_at(3.5)}, p)) << "one sign: not asked";
    }
}
