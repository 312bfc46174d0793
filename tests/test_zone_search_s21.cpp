// SPDX-License-Identifier: GPL-3.0-or-later
// The zone ends' resolution that every zone search reports (ends_newton, problems/zone_newton.hpp; docs/formulation.md
// 8(j) "The ends' resolution"): the ends of the rounded equations are known to their rounding eps/rcond however Newton
// stopped, and the estimates take that resolution as their floor (newton_floor_excess). Before, a Newton whose last
// step fell below the tolerance reported the tolerance, 1e-11, even where the rounding was 100 times that (from
// n ~ 300 on, 8(q)): level differences made of that rounding then read as a convergence rate, and free rolling of
// data/aluminium-on-steel.toml at n = 1000 (Johnson's level) was refused on them.
#include <cfloat>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_newton.hpp"

using namespace roughroll;

namespace {
// A zone family whose load and entry condition are linear in the ends, with no rounding in them: Newton reaches its
// tolerance in a step or two at any rcond. Q(s, c) = f (1 - (c - s)), E = s + 0.5: the root s = -0.5, c = 1/6
// at Q = 0.1, f = 0.3.
std::function<std::optional<tangential_solution>(const std::vector<stick_span>&)> exact_family(double f, double rcond) {
    return [f, rcond](const std::vector<stick_span>& z) -> std::optional<tangential_solution> {
        const double s = z[0].start, c = z[0].end;
        return zone_solution(f, s, c, 0.0, f * (1.0 - (c - s)), {s + 0.5}, rcond);
    };
}
const auto entry = [](const tangential_solution& t) { return t.psi_b[0]; };
}  // namespace

TEST(ZoneEndsResolution, AtLeastTheSystemsRoundingWhereNewtonMetItsTolerance) {
    const double f = 0.3, Q = 0.1, tolerance = 1e-11;
    const std::vector<stick_span> from{{-0.45, 0.7, 0.0}};
    // rcond 1e-7: eps/rcond = 2.2e-9, 222 tolerances (inside the rounding stop's cap of 1000; the zone systems of the
    // rough pair's five zones at n = 768 have rcond 1.1e-7). The root is exact, Newton's last step below the tolerance.
    rounding_limits met;
    const auto s = ends_newton<tangential_solution>(exact_family(f, 1e-7), entry, Q, f, from, false, 40, tolerance, met);
    ASSERT_TRUE(s);
    EXPECT_FALSE(met.met());
    EXPECT_NEAR(s->start(), -0.5, 1e-14);
    EXPECT_NEAR(s->c0(), 1.0 / 6.0, 1e-14);
    // The resolution the estimates read: the systems' rounding, not the tolerance (old: 1e-11).
    EXPECT_GE(s->ends_resolution, DBL_EPSILON / 1e-7);
    EXPECT_LE(s->ends_resolution, 1.01 * DBL_EPSILON / 1e-7);
}

TEST(ZoneEndsResolution, TheToleranceWhereTheRoundingIsBelowIt) {
    const double f = 0.3, Q = 0.1, tolerance = 1e-11;
    const std::vector<stick_span> from{{-0.45, 0.7, 0.0}};
    // Well conditioned (eps/rcond 2.2e-16): the tolerance, as before.
    rounding_limits met;
    const auto s = ends_newton<tangential_solution>(exact_family(f, 1.0), entry, Q, f, from, false, 40, tolerance, met);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->ends_resolution, tolerance);
    // Relative residuals (one slip direction, 7(e)) are told no rounding (their floor is 8(m)'s entry_ends_floor):
    // the tolerance at any rcond. Their load's gap is log(-rho (pi/2) psi_0/(f - Q)); with psi_0 = s - 0.5 and the
    // entry psi_1 = s + 0.5 the root is s = -0.5, rho = 0.4/pi.
    const auto relative = [f](const std::vector<stick_span>& z) -> std::optional<tangential_solution> {
        const double s = z[0].start, c = z[0].end;
        return zone_solution(f, s, c, 0.0, 0.0, {s - 0.5, s + 0.5}, 1e-7);
    };
    const auto second = [](const tangential_solution& t) { return t.psi_b[1]; };
    const auto r = ends_newton<tangential_solution>(relative, second, Q, f, from, true, 40, tolerance, met);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->ends_resolution, tolerance);
}
