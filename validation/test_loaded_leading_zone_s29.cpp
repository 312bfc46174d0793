// SPDX-License-Identifier: GPL-3.0-or-later
// Audit s28 F1: smooth aluminium on steel at Johnson's level, 0.31 < f < 1 and a small load |Q/f| (three zones slipping
// one way, the leading slip zone about 0.54 t(kappa) thick, docs/formulation.md 8(j) item 11): the ladder had run for
// minutes and printed nothing (f = 0.5, Q/f = -0.001: more than 4 min CPU), or refused after 11 to 38 s. Two fixes
// (8(n), "Beyond every n", item 7): the zone scan's halving pass towards the leading edge starts whenever no start of the
// clustered scan carries |Q| (zone_solver), so the three zones are found where the levels resolve the leading zone; and
// the measured law of that zone's change between levels n/2 and n refuses, before any solve, the loads whose top rung
// cannot meet the tolerance. Asserted by what is found and by the levels solved, not by time.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "ladder_first_solve.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"

using namespace roughroll;

namespace {
using ladder_first_solve::ladder_run;
using ladder_first_solve::named_friction;

// The ladder for the smooth pair at friction f and load Q/f = q, Johnson's level, tolerance `tol` (empty: the default),
// every rung's contact stopping at its first level's solve.
ladder_run run(double f, double q, std::optional<double> tol = std::nullopt) {
    return ladder_first_solve::run(f, roughness{}, coupling_level::johnson, tol, q * f);
}

// The three zones at Q/f = q on level n (the zone search alone, from its scan).
tangential_solution three_zones(double f, double q, int n) {
    contact c(roughness{}, f, solver_options{n, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    dissimilar_zones d(tangential_of(c), kernel{}, beta_al_st);
    return d.solve(q * f);
}
}  // namespace

// f = 0.4, Q/f = -0.001: the leading slip zone is 1.74e-4 (0.54 t(kappa)), inside the scan's first start (4.8e-3 off the
// edge), whose zone to the edge still carries more than |Q|. Before the fix no start had an end, the halving pass did
// not start, and level 512 found no three zones (refused after 38 s, its five-zone search included). Level 256 and 512
// find them, with the checks holding and the structure slip-, stick, slip-; the change of 1 + s between them lies on
// the law the quick refusal takes a tenth of (8(n) item 2, x = t(kappa) n^2: 3 exp(-0.57 sqrt(x))), as item 7 measured.
TEST(LoadedLeadingZoneS29, ThreeZonesWithAThinLeadingZoneAreFound) {
    const double f = 0.4, q = -0.001;
    const tangential_solution coarse = three_zones(f, q, 256), fine = three_zones(f, q, 512);
    for (const tangential_solution* s : {&coarse, &fine}) {
        EXPECT_TRUE(s->checks.hold());
        EXPECT_EQ(s->layout.stick_zones(), 1u);
        EXPECT_FALSE(s->layout.opposite());
    }
    const double t = leading_zone_estimate(beta_al_st, f, q * f);
    const double lead = 1.0 + fine.start();
    std::printf("t(kappa) %.5e, 1 + s %.5e (n = 512), %.5e (n = 256), trailing 1 - c %.4e\n", t, lead,
                1.0 + coarse.start(), 1.0 - fine.c0());
    EXPECT_NEAR(lead / t, 4.0 * std::exp(-2.0), 0.01);  // 0.5414 measured (8(n), "The layers' positions": 0.5413)
    const double x = t * 512.0 * 512.0, law = 3.0 * std::exp(-0.57 * std::sqrt(x));
    const double change = std::fabs(fine.start() - coarse.start()) / lead;
    std::printf("x = %.1f: change %.4e, law %.4e\n", x, change, law);
    EXPECT_GT(change, 0.5 * law);
    EXPECT_LT(change, 2.0 * law);
}

// Loads whose leading zone no n up to 1000 resolves to the default tolerance by the law's tenth (x_top = t(kappa) 1000^2
// below 197): refused with no level solved, naming a smaller friction (at this Q/f) and the free-rolling route. Before,
// no rule was asked at Q != 0 below f = 0.80 (the thinnest zone's, 8(j) item 11), and the ladder climbed: f = 0.5 at
// Q/f = -0.001 ran for more than 4 min CPU with nothing printed. The friction named is not refused (a level is solved),
// nor is f = 0.4 (x_top = 322: the ladder tries it, and refuses it after 1.7 s naming the tolerance that answers), nor
// f = 0.5 at a tolerance above the one the refusal names.
TEST(LoadedLeadingZoneS29, BeyondEveryNRefusedBeforeAnySolve) {
    for (const double q : {-0.2, -0.001, 0.001, 0.05}) {
        std::optional<double> reach;
        for (const double f : {0.5, 0.7}) {
            const ladder_run r = run(f, q);
            EXPECT_FALSE(r.solved) << "f = " << f << ", Q/f = " << q;
            EXPECT_NE(r.refusal.find("no n up to 1000 meets the tolerance"), std::string::npos) << r.refusal;
            EXPECT_NE(r.refusal.find("slip zone at the leading edge"), std::string::npos) << r.refusal;
            EXPECT_NE(r.refusal.find("smaller friction f"), std::string::npos) << r.refusal;
            EXPECT_EQ(r.refusal.find("::"), std::string::npos) << r.refusal;
            const std::optional<double> named = named_friction(r.refusal);
            ASSERT_TRUE(named) << r.refusal;
            if (reach) {
                EXPECT_EQ(*named, *reach) << "f = " << f;  // the rule's edge at this Q/f, whatever f asked
            }
            reach = named;
        }
        std::printf("Q/f = %g: refused above f = %.2f\n", q, *reach);
        EXPECT_GT(*reach, 0.38);
        EXPECT_LT(*reach, 0.5);
        EXPECT_TRUE(run(*reach, q).solved) << "Q/f = " << q;
    }
    EXPECT_TRUE(run(0.4, -0.001).solved);
    EXPECT_TRUE(run(0.5, -0.001, 0.05).solved);
    // |Q/f| above the range the law was compared at (1/2): not refused by it.
    EXPECT_TRUE(run(0.5, -0.6).solved);
}
