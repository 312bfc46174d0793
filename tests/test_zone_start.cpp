// SPDX-License-Identifier: GPL-3.0-or-later
// The acceptance every zone search shares (zone_start.hpp, docs/formulation.md 7(k) "One acceptance, starts with
// verdicts"): starts tried in order, the first root whose checks hold the answer (later starts not tried), a root whose
// checks fail standing only where no later start gives one that holds (the first such), a verdict that ends the search
// ending it with what stands. On made-up roots: each start's verdict is written out, no solver enters.
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_start.hpp"

namespace roughroll {
namespace {
// A made-up start: its root's xi (none: no root), whether its checks hold, whether the search ends there.
struct start {
    std::optional<double> xi;
    bool holds;
    bool ends;
};

struct outcome {
    std::optional<double> xi;  // the answer's xi, empty: nothing
    int tried;                 // how many starts were tried
};

outcome searched(const std::vector<start>& starts) {
    int tried = 0;
    const std::optional<tangential_solution> s = search_from<tangential_solution>(starts, [&](const start& at) {
        ++tried;
        start_verdict<tangential_solution> verdict;
        verdict.ends_search = at.ends;
        if (at.xi) {
            verdict.root = zone_solution(0.3, -0.5, 0.5, *at.xi, 0.1, {}, 1.0);
            verdict.root->checks = traction_checks{1.0, at.holds ? 1.0 : -1.0, 1.0, 0.0, 0.0, true, at.holds, true};
        }
        return verdict;
    });
    return {s ? std::optional<double>(s->xi) : std::nullopt, tried};
}

TEST(ZoneStart, FirstRootWhoseChecksHoldAnswers) {
    const outcome o = searched({{1.0, false, false}, {std::nullopt, false, false}, {2.0, true, false}, {3.0, true, false}});
    EXPECT_EQ(o.xi, 2.0);
    EXPECT_EQ(o.tried, 3);  // the fourth start is not tried
}

TEST(ZoneStart, FirstFailingRootStandsWhereNoneHolds) {
    const outcome o = searched({{std::nullopt, false, false}, {1.0, false, false}, {2.0, false, false}});
    EXPECT_EQ(o.xi, 1.0);
    EXPECT_EQ(o.tried, 3);
    EXPECT_EQ(searched({{std::nullopt, false, false}}).xi, std::nullopt);
}

TEST(ZoneStart, AVerdictThatEndsTheSearchEndsIt) {
    // A stop without a root (five zones' transition to three zones): what stands is the answer, later starts untried.
    outcome o = searched({{1.0, false, false}, {std::nullopt, false, true}, {2.0, true, false}});
    EXPECT_EQ(o.xi, 1.0);
    EXPECT_EQ(o.tried, 2);
    // A stop with a root whose checks hold: that root answers; with one whose checks fail: the first failing stands.
    o = searched({{1.0, false, false}, {2.0, true, true}, {3.0, true, false}});
    EXPECT_EQ(o.xi, 2.0);
    o = searched({{1.0, false, false}, {2.0, false, true}, {3.0, true, false}});
    EXPECT_EQ(o.xi, 1.0);
    EXPECT_EQ(o.tried, 2);
}
}  // namespace
}  // namespace roughroll
