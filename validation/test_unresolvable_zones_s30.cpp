// SPDX-License-Identifier: GPL-3.0-or-later
// Session 29 audit H1 and M2 (issue 24): stick zones of dissimilar rollers that no n resolves, refused before any solve
// with one line naming what answers (unresolvable_zones.hpp).
//   - Free rolling near complete slip (docs/formulation.md 8(f), "Below the rounding"): the smooth pair at f = 1e-10
//     and 1e-12 ran for more than 96 s CPU and printed nothing.
//   - Driven next to sliding (8(m), "Driven, next to sliding"): Q/f one ulp below 1 was refused after 38 s naming
//     Q/f = 1, and 1 - 1e-14 exited with the quadrature library's own text.
// Asserted by the refusal, its text and the levels solved (ladder_first_solve.hpp: every contact stops at its first
// level's solve), never by time. On the old code each refused load started a solve.
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "ladder_first_solve.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/full_coupling.hpp"

using namespace roughroll;

namespace {
using ladder_first_solve::ladder_run;

ladder_run run(double f, double q, coupling_level level = coupling_level::johnson) {
    return ladder_first_solve::run(f, roughness{}, level, std::nullopt, q * f);
}

// The point at n = 128 (no ladder): the refusal's line, or empty where a level's solve was started.
std::string at_given_n(double f, double q, coupling_level level) {
    contact c(roughness{}, f, solver_options{128, method::product}, dissimilar{beta_al_st, level});
    c.set_checkpoint([] { throw ladder_first_solve::level_solved(); });
    try {
        c.point(q * f);
        ADD_FAILURE() << "answered without a solve";
    } catch (const resolution_error& e) {
        return e.what();
    } catch (const ladder_first_solve::level_solved&) {
    }
    return {};
}

bool names(const std::string& line, const std::string& what) { return line.find(what) != std::string::npos; }

const double one_ulp_below = std::nextafter(1.0, 0.0);
}  // namespace

// Free rolling whose stick zones (18.34 f for the pair, 8(f)) are narrower than 5 (Johnson's level) or 1 (full coupling)
// of W's breakpoint separations 1e-9: refused at once, at a given n too, naming f = 1e-9, which the ladder starts to solve
// (and answers: xi -0.08376320829348358 in 1.5 s). The least f answered before at each level (3e-10, 1e-10) is not refused.
TEST(UnresolvableZonesS30, FreeRollingBelowTheBreakpointsRefusedBeforeAnySolve) {
    const struct {
        coupling_level level;
        std::vector<double> refused;
        double kept;
    } levels[] = {{coupling_level::johnson, {2e-10, 1e-10, 1e-12}, 3e-10}, {coupling_level::full, {3e-11, 1e-12}, 1e-10}};
    for (const auto& l : levels) {
        for (const double f : l.refused) {
            const ladder_run r = run(f, 0.0, l.level);
            EXPECT_FALSE(r.solved) << "f = " << f;
            EXPECT_TRUE(names(r.refusal, "free rolling of dissimilar rollers (beta_d = 0.144) at f = ")) << r.refusal;
            EXPECT_TRUE(names(r.refusal, "near complete slip")) << r.refusal;
            EXPECT_TRUE(names(r.refusal, "a friction f of at least 1e-09 (friction, --friction) answers it")) << r.refusal;
            EXPECT_TRUE(names(r.refusal, "8(f)")) << r.refusal;
            EXPECT_FALSE(names(r.refusal, "unresolvable")) << "a function's name in the line: " << r.refusal;
            EXPECT_EQ(at_given_n(f, 0.0, l.level), r.refusal) << "f = " << f;
        }
        EXPECT_TRUE(run(l.kept, 0.0, l.level).solved) << l.kept;
        EXPECT_TRUE(at_given_n(l.kept, 0.0, l.level).empty()) << l.kept;
        EXPECT_TRUE(run(1e-9, 0.0, l.level).solved);
    }
    // Rough rollers: the same rule, whose advice says that their free rolling was not answered at such f either (the
    // rough pair at f = 1e-9 .. 1e-6: no answer within 11-14 s CPU).
    const ladder_run rough = ladder_first_solve::run(1e-10, rough_pair_at_a(), coupling_level::johnson);
    EXPECT_FALSE(rough.solved);
    EXPECT_TRUE(names(rough.refusal, "is searched, though rough rollers' free rolling was not answered")) << rough.refusal;
    // The stick zones' width the line gives, 4 f p/(pi |beta_D p'|) at r* (8(f)): 18.34 f, measured 18.34 f.
    EXPECT_TRUE(names(run(1e-10, 0.0).refusal, "about 1.8e-09 of the half-width wide, below 5 times the 1e-09"))
        << run(1e-10, 0.0).refusal;
}

// Driven next to sliding, 1 - Q/f below 1e-13 (four ulps inside): refused at once naming gross sliding, which answers,
// with the bound of the leading slip zone from its load, (3 pi gap/(8 sqrt 2))^(2/3) (8(m)): 2.0e-11 at one ulp. Q/f =
// 0.9999999999999 is not refused at f = 0.05 (answered in 0.17 s), 1e-3 or 1e-6 (Q = (Q/f) f leaves a gap of 9.992e-14
// there); the braked side one ulp from -1 is not refused (answered in 0.18 s: its stick zone is interior, 8(m)).
TEST(UnresolvableZonesS30, DrivenNextToSlidingRefusedBeforeAnySolve) {
    const double f = 0.05;  // the scene's
    for (const double q : {one_ulp_below, 1.0 - 1e-14, 1.0 - 7e-14}) {
        const ladder_run r = run(f, q);
        EXPECT_FALSE(r.solved) << q;
        EXPECT_TRUE(names(r.refusal, "Q/f = 1 (gross sliding) answers")) << r.refusal;
        EXPECT_TRUE(names(r.refusal, "8(m)")) << r.refusal;
        EXPECT_TRUE(names(r.refusal, "Q/f = " + shortest(q) + ": next to sliding")) << r.refusal;
        EXPECT_EQ(at_given_n(f, q, coupling_level::johnson), r.refusal);
    }
    EXPECT_TRUE(names(run(f, one_ulp_below).refusal, "within about 2e-11 of the leading edge"));
    // Full coupling: the same refusal.
    const ladder_run full = run(f, one_ulp_below, coupling_level::full);
    EXPECT_FALSE(full.solved);
    EXPECT_TRUE(names(full.refusal, "Q/f = 1 (gross sliding) answers")) << full.refusal;
    EXPECT_EQ(at_given_n(f, one_ulp_below, coupling_level::full), full.refusal);
    for (const double g : {f, 1e-3, 1e-6}) {
        EXPECT_TRUE(run(g, 0.9999999999999).solved) << g;
        EXPECT_FALSE(run(g, one_ulp_below).solved) << g;
    }
    EXPECT_TRUE(run(f, -one_ulp_below).solved);
    contact c(roughness{}, f, solver_options{128, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_NO_THROW(c.point(f));
}

// Session 31 (closing note of session 30, item 4; 8(m), "Full coupling next to sliding"). Driven below 1 - 1.1e-9 at full
// coupling the alternation's lambda, e, xi change by more than its 1e-12 at every step: refused before any solve, naming
// gross sliding and Johnson's level (old code: 1 - 1e-12 and 1 - 1e-13 ran 14-19 s CPU to the quadrature's own text,
// 1 - 1e-9 6.9 s). Searched as before: 1 - 1e-8 (n = 64 and 128 answer at f = 0.05 and 0.1) and Johnson's level.
TEST(UnresolvableZonesS31, DrivenFullCouplingNextToSlidingRefusedBeforeAnySolve) {
    for (const double f : {0.05, 0.1}) {
        for (const double q : {1.0 - 1e-9, 1.0 - 1e-10, 1.0 - 1e-12, 0.9999999999999}) {
            const ladder_run r = run(f, q, coupling_level::full);
            EXPECT_FALSE(r.solved) << f << " " << q;
            EXPECT_TRUE(names(r.refusal, "driven next to sliding")) << r.refusal;
            EXPECT_TRUE(names(r.refusal, "Q/f = 1 (gross sliding) answers")) << r.refusal;
            EXPECT_TRUE(names(r.refusal, "coupling = \"johnson\" may answer it")) << r.refusal;
            EXPECT_TRUE(names(r.refusal, "8(m)")) << r.refusal;
            EXPECT_EQ(at_given_n(f, q, coupling_level::full), r.refusal) << f << " " << q;
            EXPECT_TRUE(run(f, q).solved) << "Johnson's level, f = " << f << ", Q/f = " << q;
        }
        EXPECT_TRUE(run(f, 1.0 - 1e-8, coupling_level::full).solved) << f;
        EXPECT_TRUE(at_given_n(f, 1.0 - 1e-8, coupling_level::full).empty()) << f;
    }
    // Within 1e-13 of sliding both levels keep the line of session 30 (the stick zone at the leading edge).
    EXPECT_TRUE(names(run(0.05, one_ulp_below, coupling_level::full).refusal, "next to sliding on the driven side"));
}

// Braked within 2 eps of sliding the load's rounding moves the thin stick zone's ends by a quarter of its width or more:
// at f = 0.05 one ulp cycled by 6e-7 with period three for 40 steps at every level (60 s CPU to the refusal). Refused at
// the alternation's first cycle (the ends' largest change over three steps no smaller than over the three before), by
// its steps counted (the contact's checkpoint, once per step), not by time, naming Johnson's level, which answers it. At
// f = 0.3 one ulp (1 - |Q|/f = eps) settles and is answered as before.
TEST(UnresolvableZonesS31, BrakedFullCouplingWithinRoundingRefusedAtTheFirstCycle) {
    int steps = 0;
    contact c(roughness{}, 0.05, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::full});
    c.set_checkpoint([&steps] { ++steps; });
    try {
        c.point(-one_ulp_below * 0.05);
        ADD_FAILURE() << "answered";
    } catch (const resolution_error& e) {
        EXPECT_TRUE(names(e.what(), "braked within rounding of sliding")) << e.what();
        EXPECT_TRUE(names(e.what(), "coupling = \"johnson\" answers the load")) << e.what();
        EXPECT_TRUE(names(e.what(), "8(m)")) << e.what();
    }
    EXPECT_LT(steps, coupling_max_iterations);
    contact settles(roughness{}, 0.3, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::full});
    EXPECT_TRUE(settles.point(-one_ulp_below * 0.3).checks.hold());
}
