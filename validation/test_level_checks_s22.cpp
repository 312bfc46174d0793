// SPDX-License-Identifier: GPL-3.0-or-later
// Full coupling's five-zone checks (3.3)-(3.4) made only where they are read (issue 24: full coupling at most 3 times
// Johnson's point; docs/formulation.md 8(q), "The checks where they are read", session 22). A level of an estimate
// (full_coupling::solve unchecked) makes none of its five-zone steps' checks: before, every step's were made and never
// read (free rolling of the pair: 31 % of the point). A reported point's are made at every step, as before, and the
// steps do not depend on them. UncheckedLevelMakesNoFiveZoneChecks fails on the program before (its unchecked point's
// checks were made: "s.checks.hold() true").
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_solver.hpp"

using namespace roughroll;

namespace {
const double f = 0.05;

// Johnson's level of the pair at n: Hertz's pressure, its solver and zones workspace, and free rolling's five zones
// (the alternation's start, k = 0).
struct johnson_free_rolling {
    explicit johnson_free_rolling(int n)
        : hertz(hertz_solution(n, method::product)), solver(hertz, kernel{}, kernel{}, f), zones(solver, kernel{}, beta_al_st) {
        const auto v = zones.five_zones(0.0);
        if (!v) throw std::runtime_error("no five zones at Johnson's level");
        point = *v;
        point.Q = 0.0;
    }
    const normal_solution hertz;
    tangential_solver solver;
    dissimilar_zones zones;
    tangential_solution point;
};

void expect_same_checks(const traction_checks& a, const traction_checks& b) {
    EXPECT_EQ(a.pressure_margin, b.pressure_margin);
    EXPECT_EQ(a.stick_margin, b.stick_margin);
    EXPECT_EQ(a.slip_margin, b.slip_margin);
    EXPECT_EQ(a.stick_rounding, b.stick_rounding);
    EXPECT_EQ(a.slip_rounding, b.slip_rounding);
    EXPECT_EQ(a.hold(), b.hold());
}
}  // namespace

// Free rolling at n = 64 (five zones on the weight w_N, 8(x)): the unchecked alternation's point carries no checks (NaN
// margins), while the checks made on its zones afterwards hold; the same alternation checked reaches the same point bit for
// bit (the checks move no step), and its checks are those the converged step's workspace makes.
TEST(LevelChecks, UncheckedLevelMakesNoFiveZoneChecks) {
    johnson_free_rolling j(64);
    full_coupling level(kernel{}, kernel{}, 64, method::product, f, beta_al_st);
    const tangential_solution s = level.solve(j.hertz, j.zones, j.point, false);
    ASSERT_EQ(s.layout.stick_zones(), 2);
    ASSERT_TRUE(s.zone_systems);
    EXPECT_FALSE(s.checks.hold());
    EXPECT_TRUE(std::isnan(s.checks.stick_margin));  // not made: no margin reads as one that failed
    EXPECT_TRUE(std::isnan(s.checks.slip_margin));
    EXPECT_TRUE(std::isnan(s.checks.pressure_margin));
    const traction_checks made = level.zones().check(s);
    EXPECT_TRUE(made.hold()) << margins_text(made);

    full_coupling reported(kernel{}, kernel{}, 64, method::product, f, beta_al_st);
    const tangential_solution r = reported.solve(j.hertz, j.zones, j.point, true);
    ASSERT_EQ(r.layout.stick_zones(), 2);
    EXPECT_EQ(r.start(), s.start());
    EXPECT_EQ(r.c0(), s.c0());
    EXPECT_EQ(r.start2(), s.start2());
    EXPECT_EQ(r.end2(), s.end2());
    EXPECT_EQ(r.xi, s.xi);
    EXPECT_EQ(reported.normal().lambda, level.normal().lambda);
    EXPECT_EQ(reported.summary().iterations, level.summary().iterations);
    expect_same_checks(r.checks, made);
}

// A reported point whose converged five zones fail the checks is refused as before, with those checks' margins: free
// rolling at n = 32 misses (3.4) one grid point before s2 (8(r); the golden file point-al-steel-full-Q0's refusal).
TEST(LevelChecks, ReportedPointFailingItsChecksRefusedWithTheirMargins) {
    johnson_free_rolling j(32);
    full_coupling level(kernel{}, kernel{}, 32, method::product, f, beta_al_st);
    const tangential_solution s = level.solve(j.hertz, j.zones, j.point, false);
    ASSERT_EQ(s.layout.stick_zones(), 2);
    const traction_checks made = level.zones().check(s);
    ASSERT_FALSE(made.hold());
    full_coupling reported(kernel{}, kernel{}, 32, method::product, f, beta_al_st);
    try {
        reported.solve(j.hertz, j.zones, j.point, true);
        FAIL() << "answered with failed checks";
    } catch (const resolution_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("the coupled zones fail the checks"), std::string::npos) << what;
        EXPECT_NE(what.find(margins_text(made)), std::string::npos) << what << " / " << margins_text(made);
    }
}
