// SPDX-License-Identifier: GPL-3.0-or-later
// The cost of full coupling's climb (issue 24, "Done when": full coupling at most 3 times Johnson's point; session 19,
// docs/performance.md "Full coupling: one chain of levels over the rungs").
//  - The rungs share full coupling's levels (point_model::shared_by_rungs, level_store): rung 2n's levels n/2, n are
//    rung n's, so each n of the climb is solved once and rung 2n's alternation starts from rung n's point (one chain
//    n/4 .. 2n); its numbers stay inside the estimates of the rung solved alone (whose chain starts at n/4 from
//    Johnson's point).
//  - A physical scene of a smooth pair at full coupling builds its rungs without solving them: the width follows from
//    the answer's lambda (io/scene_point.cpp). Its ladder then does exactly the work of the same pair given
//    dimensionless (beta_D as the scene computes it): the same checkpoint calls, the same numbers. Before, each rung
//    solved its point to find its width when it was built, and again in the climb, and the top rung's point was solved
//    before rule (a') of docs/formulation.md 8(q) could read its levels.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/level_ladder.hpp"

using namespace roughroll;

namespace {
// The pair's scene (data/aluminium-on-steel.toml) at full coupling, physical (its radii, moduli and P2).
scene physical_full(double f, double Q, const std::string& extra = "") {
    std::ifstream in(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml");
    std::stringstream text;
    text << in.rdbuf();
    std::string t = text.str();
    const std::string johnson = "coupling = \"johnson\"";
    const auto at = t.find(johnson);
    EXPECT_NE(at, std::string::npos);
    t.replace(at, johnson.size(), "coupling = \"full\"\n" + extra);
    scene s = parse_scene(t, "physical.toml");
    s.friction = f;
    s.Q = Q;
    return s;
}

// The same pair dimensionless: beta_D as the physical scene computes it, no radii, no load.
scene dimensionless_twin(const scene& physical, const std::string& extra = "") {
    char beta[64];
    std::snprintf(beta, sizeof beta, "%.17g", physical.materials.beta_d);
    std::ostringstream t;
    t << "friction = 0.05\nQ = 0\nbeta_d = " << beta << "\ncoupling = \"full\"\n" << extra;
    scene s = parse_scene(t.str(), "twin.toml");
    s.friction = physical.friction;
    s.Q = physical.Q;
    EXPECT_EQ(s.materials.beta_d, physical.materials.beta_d);
    return s;
}
}  // namespace

// Free rolling at f = 0.1 (five zones), default settings: answered at rung 256 (rungs 128, 256). (Until session 25 the
// driven Q/f = +0.75 at f = 0.05, which climbed to 256 on the plateau path; on the exact weight it answers at n = 64,
// docs/formulation.md 8(z), "The driven five zones on the weight"; f = 0.1 climbs as it did and meets every line below.)
// Each n of
// the climb is made once (on the program before, 64 and 128 twice: rung 256 solved its levels again from another
// start), rung 256's alternation starts from level 128, and its numbers lie within their estimates of rung 256 solved
// alone (a contact with no store: the chain 64, 128, 256 from Johnson's point at 64).
// Session 23 (docs/formulation.md 8(j), "Johnson's point from the coarser rung's five zones"): rung 256's Johnson's
// point (the plateau's and the weighted path's decision, 8(x), and the estimate's levels' start) comes from level 128's
// five zones, which rung 128 solved: no three-zone search at 256 (on the program before, one: "Which is: 1"); the
// contact alone, whose levels are fresh, searches them once at its level (they fail their checks there). Its numbers
// within the estimates below guard the rule's answer; the golden outputs are identical.
TEST(CostS19, FullCouplingRungsShareOneChain) {
    const dissimilar pair{beta_al_st, coupling_level::full};
    const double f = 0.1, Q = 0.0;
    std::optional<level_ladder::answer> a;
    std::unique_ptr<contact> answering;
    {
        level_ladder ladder(solver_options{}, roughness{}, [&](int n, const std::shared_ptr<level_store>& levels) {
            return std::make_unique<contact>(
                contact_internals::with_levels(roughness{}, f, solver_options{n}, pair, nullptr, levels));
        });
        a = ladder.point(Q);
        ASSERT_EQ(a->n, 256);
        for (int n : {32, 64, 128, 256}) EXPECT_EQ(ladder.levels().made(n), 1) << "n = " << n;
        answering = ladder.release(a->n);
    }
    ASSERT_TRUE(answering->coupling() && a->estimate);
    EXPECT_EQ(answering->coupling()->start_level, 128);
    ASSERT_NE(contact_internals::johnson_zones(*answering), nullptr);
    EXPECT_EQ(contact_internals::johnson_zones(*answering)->three_zone_searches(), 0u);
    contact alone(roughness{}, f, solver_options{256}, pair);
    const tangential_solution p = alone.point(Q);
    const std::optional<error_estimate> e = alone.estimate(p);
    ASSERT_TRUE(e);
    ASSERT_EQ(p.layout.stick_zones(), 2u);
    ASSERT_NE(contact_internals::johnson_zones(alone), nullptr);
    EXPECT_EQ(contact_internals::johnson_zones(alone)->three_zone_searches(), 1u);
    EXPECT_LE(std::fabs(a->solution.start() - p.start()), std::min(a->estimate->start, e->start));
    EXPECT_LE(std::fabs(a->solution.start2() - p.start2()), std::min(a->estimate->start, e->start));
    EXPECT_LE(std::fabs(a->solution.c0() - p.c0()), std::min(a->estimate->c0, e->c0));
    EXPECT_LE(std::fabs(a->solution.end2() - p.end2()), std::min(a->estimate->c0, e->c0));
    EXPECT_LE(std::fabs(a->solution.xi - p.xi), std::min(a->estimate->xi, e->xi));
    EXPECT_LE(std::fabs(answering->normal().lambda - alone.normal().lambda), std::min(a->estimate->lambda, e->lambda));
}

// Braked Q/f = -0.75 (three zones, answered at rung 128): the physical scene's ladder calls its checkpoint exactly as
// often as its dimensionless twin's (the program before called it more: each rung's point solved when the rung was
// built, for its width, then asked again by the climb), and gives the same numbers, bit for bit; the width is the
// answer's, a = a_H sqrt(lambda).
TEST(CostS19, PhysicalRungsBuiltWithoutASolve) {
    const scene physical = physical_full(0.05, -0.75 * 0.05);
    const scene twin = dimensionless_twin(physical);
    int physical_calls = 0, twin_calls = 0;
    const scene_point p = solve_point(physical, std::nullopt, [&physical_calls] { ++physical_calls; });
    const scene_point d = solve_point(twin, std::nullopt, [&twin_calls] { ++twin_calls; });
    EXPECT_GT(twin_calls, 0);
    EXPECT_EQ(physical_calls, twin_calls);
    EXPECT_EQ(p.solution.xi, d.solution.xi);
    EXPECT_EQ(p.solution.start(), d.solution.start());
    EXPECT_EQ(p.solution.c0(), d.solution.c0());
    ASSERT_TRUE(p.estimate && d.estimate && p.width);
    EXPECT_EQ(p.estimate->start, d.estimate->start);
    const double lambda = p.solved.normal().lambda;
    EXPECT_EQ(lambda, d.solved.normal().lambda);
    EXPECT_DOUBLE_EQ(p.width->a, p.width->a_hertz * std::sqrt(lambda));
    EXPECT_EQ(p.width->lambda, lambda);
}

// Free rolling at f = 0.2 and the tolerance 1e-5: refused, rung 512 not solved by rule (a') of 8(q) (its levels up to
// 256 alone; rung 1000 before the five zones took the weight w_N, 8(x) "Landed"). The physical scene does its twin's
// work (the program before solved the top rung's point to find its width first: more checkpoint calls) and refuses
// with the same line. large_n: about 280 s CPU since 8(x) (7.5 s per solve before: 8(x) names the defect).
TEST(CostS19, PhysicalTopRungRefusedBeforeItsPoint) {
    const scene physical = physical_full(0.2, 0.0, "[solver]\ntolerance = 1e-5\n");
    const scene twin = dimensionless_twin(physical, "[solver]\ntolerance = 1e-5\n");
    int physical_calls = 0, twin_calls = 0;
    std::string physical_line, twin_line;
    try {
        solve_point(physical, std::nullopt, [&physical_calls] { ++physical_calls; });
        ADD_FAILURE() << "physical answered";
    } catch (const resolution_error& e) {
        physical_line = e.what();
    }
    try {
        solve_point(twin, std::nullopt, [&twin_calls] { ++twin_calls; });
        ADD_FAILURE() << "twin answered";
    } catch (const resolution_error& e) {
        twin_line = e.what();
    }
    EXPECT_NE(physical_line.find("n = 512 was not solved"), std::string::npos) << physical_line;
    EXPECT_EQ(physical_line, twin_line);
    EXPECT_GT(twin_calls, 0);
    EXPECT_EQ(physical_calls, twin_calls);
}

// The store's key takes 'extrapolated' on smooth rollers as 'product' (level_store::computed_by), but a model keeps the
// method it was made with, which its normal reports (JSON "method"): a rung's contact under 'extrapolated' is never
// given a full-coupling level made first as 'product' (the review of a00e696: a level 2n asked before rung 2n); a
// level asking for 'product' takes the rung's model. Nothing is solved here (the models' normal problems only).
TEST(CostS19, ExtrapolatedRungNeverGivenAProductLevel) {
    const dissimilar pair{beta_al_st, coupling_level::full};
    const auto store = std::make_shared<level_store>();
    const contact level = contact_internals::with_levels(roughroll::roughness{}, 0.05,
                                                         solver_options{64, method::product}, pair, nullptr, store);
    const contact rung = contact_internals::with_levels(roughroll::roughness{}, 0.05,
                                                        solver_options{64, method::extrapolated}, pair, nullptr, store);
    EXPECT_EQ(level.normal().how, method::product);
    EXPECT_EQ(rung.normal().how, method::extrapolated);
    EXPECT_EQ(store->made(64), 2);
    // The other way round the level is the rung's model: made once.
    const auto other = std::make_shared<level_store>();
    const contact rung2 = contact_internals::with_levels(roughroll::roughness{}, 0.05,
                                                         solver_options{64, method::extrapolated}, pair, nullptr, other);
    const contact level2 = contact_internals::with_levels(roughroll::roughness{}, 0.05,
                                                          solver_options{64, method::product}, pair, nullptr, other);
    EXPECT_EQ(other->made(64), 1);
    EXPECT_EQ(&rung2.normal(), &level2.normal());
}
