// SPDX-License-Identifier: GPL-3.0-or-later
// The zone search's near-edge pass (zone_solver.cpp, general_search): where no bracket of a scan of every bracket
// answers, starts halving their distance to the leading edge. It opens below the scan's first trial, or, where no
// start carries |Q| because the first start's empty zone carries less (the blended zones of 8(g): the clustered scan
// of dissimilar rollers), below that first start. The latter entry reads the scan's first start: before, it did so
// for a scan without `clustered` too, where the start list can be empty (starts from -1 up to r*, and r* = -1), and
// read past an empty vector. Checked on a made-up stick-zone operator, in closed form, with no start at all.
#include <optional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/stick_zone_operator.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_newton.hpp"
#include "roughroll/problems/zone_solver.hpp"

namespace roughroll {
namespace {
constexpr double f = 0.3, Q = 0.2;

// Zones [s, c] carrying f (1 - (c - s)), entry condition E = s + 0.5; the least point r* = -1, so that the scan up to
// r* has no start inside (-1, 1); the empty zone carries |Q|, not more (the empty-scan entry's condition).
stick_zone_operator without_starts() {
    stick_zone_operator op;
    op.f = f;
    op.paper_zone = [](double, bool) { return std::nullopt; };
    op.solve = [](double s, double c) { return zone_solution(f, s, c, 0.0, f * (1.0 - (c - s)), {s + 0.5}); };
    op.excess = [](const tangential_solution& t, double magnitude) { return t.Q - magnitude; };
    op.empty_load = [](double) { return Q; };
    op.entry = op.newton_entry = [](const tangential_solution& t) { return t.psi_b[0]; };
    op.gross_sliding = [] { return zone_solution(f, -1.0, -1.0, 0.0, f); };
    op.check = [](const tangential_solution&) { return traction_checks{1.0, 1.0, 1.0, 0.0, 0.0, true, true, true}; };
    op.method.name = "the made-up zone search";
    op.method.refusal = "no made-up zone carries the load";
    op.method.scan_to_least_point = true;
    op.method.every_bracket = true;
    op.method.edge = edge_zone::absent;
    op.method.relative_load = false;
    op.method.newton_tolerance = 1e-11;
    return op;
}

TEST(ZoneSearch, NoStartsIsNoZoneOfTheStructure) {
    // No start, no trial, no bracket: "no zone of the structure" (empty; solve refuses with the operator's line).
    // Before, the empty-scan entry of the near-edge pass read the first of no starts (a crash in the Release build).
    EXPECT_FALSE(zone_solver(without_starts()).find(Q));
    try {
        zone_solver(without_starts()).solve(Q);
        ADD_FAILURE() << "no refusal";
    } catch (const resolution_error& e) {
        EXPECT_EQ(std::string(e.what()), "no made-up zone carries the load");
    }
}

TEST(ZoneSearch, NewtonStartsFromTheCoarserLayoutsEndsAndRefusesAnotherCount) {
    // The made-up family's root: E = s + 0.5 = 0 and f (1 - (c - s)) = Q, the zone [-0.5, -1/6]. With no start of its
    // own the search finds it only from the ends given (a layout's stick_ends(), docs/formulation.md 7(k)); ends of
    // another count than one zone's (s, c) are refused, not dropped in silence (session 27 review R17), as the
    // programming error they are (std::invalid_argument, the CLI's "internal error"; review R23).
    const std::optional<tangential_solution> s = zone_solver(without_starts()).find(Q, false, {-0.45, -0.2});
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->start(), -0.5, 1e-12);
    EXPECT_NEAR(s->c0(), -0.5 + (1.0 - Q / f), 1e-12);
    EXPECT_THROW(zone_solver(without_starts()).find(Q, false, {-0.45, -0.2, 0.1, 0.3}), std::invalid_argument);
    rounding_limits met;
    EXPECT_THROW(zone_newton(without_starts(), Q, {-0.45, -0.2, 0.1}, met), std::invalid_argument);
}

TEST(ZoneSearch, AScanWithoutClusteredStartsDoesNotEnterThePassWhereNoStartCarries) {
    // Starts up to r* = 0.5 and every empty zone carrying less than |Q| (no zone end exists): the scan has starts and
    // no trial. The empty-scan entry of the near-edge pass is the clustered scan's alone (the blended zones of 8(g));
    // without `clustered` the search ends at the scan: no start nearer the edge than both scans' first starts
    // (-1 + 1.5/32 plain, -cos(pi/32) = -0.99518 clustered) is asked for. Between e51a784 and ad359a5 the entry
    // dropped `clustered` and this scan went on towards the edge.
    int near_edge = 0;
    const auto count = [&near_edge](double s) {
        if (s < -0.996) ++near_edge;
    };
    stick_zone_operator op = without_starts();
    op.gross_sliding = [] { return zone_solution(f, 0.5, 0.5, 0.0, f); };
    op.empty_load = [count](double s) {
        count(s);
        return 0.5 * Q;
    };
    op.solve = [count](double s, double c) {
        count(s);
        return zone_solution(f, s, c, 0.0, 0.5 * f * (1.0 - (c - s)), {s + 0.5});
    };
    EXPECT_FALSE(zone_solver(op).find(Q));
    EXPECT_EQ(near_edge, 0);
    // The clustered scan does enter it: starts below its first are asked for.
    op.method.clustered = true;
    op.method.scan_to_least_point = false;
    near_edge = 0;
    EXPECT_FALSE(zone_solver(op).find(Q));
    EXPECT_GT(near_edge, 0);
}

// Every start's root judged by one rule (first_holding, docs/formulation.md 7(k)): a root whose checks fail no longer
// ends the search where a later start gives one whose checks hold. Zones [s, c] carrying f (1 - (c - s)), entry
// condition E(s) = -(s + 0.9) (s - 0.2): the zone from the leading edge has E(-1) = -0.12 <= 0 (7(b)'s answer) but fails
// the (made-up) checks, which hold on zones starting above -0.95; the scan's first bracket holds the root s = -0.9,
// c = s + 1/3. Before session 26 the zone from the edge answered with its failed checks (start -1).
TEST(ZoneSearch, ARootFailingItsChecksDoesNotEndTheSearch) {
    stick_zone_operator op = without_starts();
    const auto entry = [](double s) { return -(s + 0.9) * (s - 0.2); };
    op.solve = [entry](double s, double c) { return zone_solution(f, s, c, 0.0, f * (1.0 - (c - s)), {entry(s)}); };
    op.empty_load = [](double) { return f; };  // no stick zone: the slip zones carry f > |Q|
    op.check = [](const tangential_solution& t) {
        const bool holds = t.start() > -0.95;
        return traction_checks{1.0, holds ? 1.0 : -1.0, 1.0, 0.0, 0.0, true, holds, true};
    };
    op.method.scan_to_least_point = false;
    op.method.every_bracket = false;
    op.method.edge = edge_zone::needed;
    const std::optional<tangential_solution> s = zone_solver(op).find(Q);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->checks.hold());
    EXPECT_NEAR(s->start(), -0.9, 1e-9);
    EXPECT_NEAR(s->c0(), -0.9 + 1.0 / 3.0, 1e-9);
    // Where no start gives a root whose checks hold (they hold nowhere), the first root stands: the edge's.
    op.check = [](const tangential_solution&) { return traction_checks{1.0, -1.0, 1.0, 0.0, 0.0, true, false, true}; };
    const std::optional<tangential_solution> failing = zone_solver(op).find(Q);
    ASSERT_TRUE(failing);
    EXPECT_FALSE(failing->checks.hold());
    EXPECT_EQ(failing->start(), -1.0);
}

}  // namespace
}  // namespace roughroll
