// SPDX-License-Identifier: GPL-3.0-or-later
// Refusals of the ladder decided before any solve (issue 24, 5 and 7; contact::beyond_every_n,
// docs/formulation.md 8(n) "Beyond every n"): free rolling of aluminium on steel, smooth, Johnson's
// level, whose edge layers are too thin for n = 1000 to meet the tolerance and too thick to be
// neglected within it. Before, the ladder climbed to n = 1000 first (f = 0.5: about 8 min CPU at
// n = 1000, 31 min wall on a loaded machine) and refused there. The quick refusal is asserted by
// the levels solved (the contacts' checkpoint, called before every level's solve), not by time:
// on the old program the first level's checkpoint throws and the test fails at once.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "ladder_first_solve.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/level_ladder.hpp"
#include "roughroll/problems/zone_layout.hpp"

using namespace roughroll;

namespace {
using ladder_first_solve::ladder_run;
using ladder_first_solve::level_solved;

// The ladder at friction f, free rolling of the smooth pair at Johnson's level, the tolerance `tol` (empty: the default),
// every rung's contact stopping at its first level's solve.
ladder_run run(double f, std::optional<double> tol = std::nullopt) {
    return ladder_first_solve::run(f, roughness{}, coupling_level::johnson, tol);
}

// The edge layers' crossing t_c and the layers-neglected route's largest relative estimate (8(n)):
// its bound on xi relative to xi, and the bounds of the main stick zone's ends.
double crossing(double f) { return no_slip_layers(beta_al_st, f).crossing; }
double layers_relative(double f) {
    const neglected_layers l = no_slip_layers(beta_al_st, f);
    return std::max({l.xi_bound / std::fabs(no_slip_creep(beta_al_st)), l.leading_bound, l.trailing_bound});
}
// Below the layers' route's estimates from f = 0.31 to 0.47 (their trailing end's 0.011 t_c = 1.19e-6 at
// f = 0.45, 7.7e-7 at 0.47, 8(n)): since the layers' positions the default
// tolerance is met by that route there, so the rule is tested at this one.
constexpr double fine = 5e-7;
}  // namespace

// f = 0.425, 0.45, 0.47 at the tolerance 5e-7: no level solved, one rung's contact built, the line
// names the tolerance that answers (the layers neglected).
TEST(LadderRefusals, FreeRollingBeyondEveryNRefusedBeforeAnySolve) {
    for (const double f : {0.425, 0.45, 0.47}) {
        SCOPED_TRACE(f);
        ASSERT_GT(layers_relative(f), fine);  // not answered by the layers neglected
        const ladder_run r = run(f, fine);
        EXPECT_FALSE(r.solved);
        EXPECT_EQ(r.rungs_built, 1);
        EXPECT_NE(r.refusal.find("no n up to 1000 meets the tolerance"), std::string::npos) << r.refusal;
        EXPECT_NE(r.refusal.find("--tolerance"), std::string::npos) << r.refusal;
        EXPECT_EQ(r.refusal.find('\n'), std::string::npos) << r.refusal;
        EXPECT_EQ(r.refusal.find("::"), std::string::npos) << r.refusal;  // no function names
    }
    // f = 0.45: the trailing end's bound 1.19e-6 (the zone ends), not the creep's 2.6e-7 (8(n)).
    EXPECT_NE(run(0.45, fine).refusal.find("a tolerance of 1.2e-06 or more"), std::string::npos);
    // At the default tolerance the layers' route answers them (before the layers' positions: refused).
    for (const double f : {0.425, 0.45, 0.47}) EXPECT_LE(layers_relative(f), default_tolerance) << f;
}

// The rule's edge at the tolerance 1e-6: x = t_c 1000^2 with 0.3 exp(-0.57 sqrt(x)) = 1e-6, x = 490,
// f = 0.3813. Above it (f = 0.385, x = 446) refused at once; below (f = 0.38, x = 497) the ladder solves.
TEST(LadderRefusals, OnlyWhereTheMeasuredChangeExceedsTheTolerance) {
    EXPECT_LT(crossing(0.38) * 1e6, 555.0);
    EXPECT_GT(crossing(0.38) * 1e6, 490.0);
    EXPECT_LT(crossing(0.385) * 1e6, 490.0);
    EXPECT_GT(layers_relative(0.38), 1e-6);
    EXPECT_GT(layers_relative(0.385), 1e-6);
    EXPECT_TRUE(run(0.38, 1e-6).solved);
    EXPECT_FALSE(run(0.385, 1e-6).solved);
    // A tolerance between the measured change at n = 1000 and the layers' route climbs: f = 0.39,
    // change 3.4e-6, route 4.4e-6 (its trailing end); below the change refused at once.
    EXPECT_GT(layers_relative(0.39), 3.7e-6);
    EXPECT_TRUE(run(0.39, 3.7e-6).solved);
    EXPECT_FALSE(run(0.39, 3e-6).solved);
    // Beyond the measured range (x > 555) never refused at once, whatever the tolerance.
    EXPECT_GT(crossing(0.37) * 1e6, 555.0);
    EXPECT_TRUE(run(0.37, 1e-9).solved);
}

// The refusal is the contact's, for the ladder's top rung: an explicit n (no ladder) is solved as before.
TEST(LadderRefusals, OnlyTheLadderRefusesAtOnce) {
    contact c(roughness{}, 0.45, solver_options{128}, dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_TRUE(c.beyond_every_n(0.0, 1000, fine).has_value());
    EXPECT_FALSE(c.beyond_every_n(0.0, 1000, default_tolerance).has_value());  // the layers neglected answer
    // Q != 0 since session 29: the leading slip zone on the scale t(kappa) (8(n) item 7; Q/f = 0.11, x_top = 80), at
    // 0 < |Q/f| <= 1/2 only, where the law was compared (test_loaded_leading_zone_s29.cpp).
    EXPECT_TRUE(c.beyond_every_n(0.05, 1000, fine).has_value());
    EXPECT_FALSE(c.beyond_every_n(0.3, 1000, fine).has_value());  // Q/f = 0.67: not asked
    // beta_D = 0: the paper's free rolling has no edge layers (it had been refused, the crossing being 0).
    for (const double f : {0.05, 0.3, 0.5}) {
        contact similar(roughness{}, f, solver_options{128});
        EXPECT_FALSE(similar.beyond_every_n(0.0, 1000, default_tolerance).has_value()) << f;
        EXPECT_FALSE(similar.beyond_every_n(0.0, 1000, 1e-9).has_value()) << f;
    }
    level_ladder paper_problem(solver_options{}, roughness{},
                               [](int n) { return std::make_unique<contact>(roughness{}, 0.3, solver_options{n}); });
    EXPECT_EQ(paper_problem.point(0.0).solution.c0(), 1.0);  // full stick, answered at the first rung
    contact rough(roughness{{{1.0, 0.5}, {}}, {}}, 0.5, solver_options{128}, dissimilar{beta_al_st, coupling_level::johnson});
    // Rough rollers since session 24: their own crossing (validation/test_rough_free_rolling_s24.cpp); this layer's at
    // f = 0.5 is t_c = 1.6e-5 (x = t_c 1000^2 = 16), so the law's tenth 0.031 exceeds 5e-7.
    EXPECT_TRUE(rough.beyond_every_n(0.0, 1000, fine).has_value());
    contact full(roughness{}, 0.5, solver_options{128}, dissimilar{beta_al_st, coupling_level::full});
    EXPECT_TRUE(full.beyond_every_n(0.0, 1000, fine).has_value());  // its own crossing (test_full_coupling.cpp)
    // The law was measured on product integration (the levels of 'product' and 'extrapolated'), not 'paper'.
    contact product(roughness{}, 0.45, solver_options{96, method::product},
                    dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_TRUE(product.beyond_every_n(0.0, 1000, fine).has_value());
    contact paper(roughness{}, 0.45, solver_options{200, method::paper},
                  dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_FALSE(paper.beyond_every_n(0.0, 1000, fine).has_value());
}

// Full coupling (docs/formulation.md 8(q)): the estimate is twice the larger of the last two level
// changes, so rung 2n's is at least twice rung n's last change, and where the zone ends converge at
// order 1 (five zones, the driven three zones) a tenth of the order-1 prediction is certain for every
// rung above. Smooth aluminium on steel, f = 0.05, dimensionless (its width does not enter).
namespace {
struct full_run {
    std::optional<level_ladder::answer> answer;
    std::string refusal;
    std::vector<int> solved;  // the rungs whose levels were started, in order
    int stopped_at = 0;       // the rung whose checkpoint stopped the climb (0: none)
};

// The ladder at Q/f, tolerance `tol`; a rung in `stop` throws at its first level's solve. The pair's beta_D and f
// unless given.
full_run run_full(double Q_over_f, std::optional<double> tol, const std::vector<int>& stop, double f = 0.05,
                  double beta_d = beta_al_st) {
    full_run r;
    solver_options options;
    options.tolerance = tol;
    level_ladder ladder(options, roughness{}, [&](int n) {
        auto c = std::make_unique<contact>(roughness{}, f, solver_options{n, options.how, options.zones, tol},
                                           dissimilar{beta_d, coupling_level::full});
        const bool stops = std::find(stop.begin(), stop.end(), n) != stop.end();
        c->set_checkpoint([&r, n, stops] {  // (copied to the rung's levels)
            if (r.solved.empty() || r.solved.back() != n) r.solved.push_back(n);
            if (stops) {
                r.stopped_at = n;
                throw level_solved();
            }
        });
        return c;
    });
    try {
        r.answer = ladder.point(Q_over_f * f);
    } catch (const resolution_error& e) {
        r.refusal = e.what();
    } catch (const level_solved&) {
    }
    return r;
}
}  // namespace

// Driven, Q/f = +0.75 (five zones), tolerance 1e-6. Before the five zones carried their kinks (8(r)),
// rung 128's stick start changed by about 1e-4 per level at order 1, and rule (b) of 8(q) refused the
// point after rung 128. With the kinks carried the ends converge at order 2 to 4.5, where a tenth of the
// order-1 prediction is no longer a certain lower bound at rung 1000 (m/n = 7.8): no rung is excluded by
// (b), so the ladder climbs (stopped here at rung 256) instead of claiming that no larger n can answer.
TEST(LadderRefusals, FullCouplingWithTheKinksCarriedHasNoOrderOneLaw) {
    const full_run r = run_full(0.75, 1e-6, {256, 512, 1000});
    EXPECT_EQ(r.solved, (std::vector<int>{128, 256}));
    EXPECT_EQ(r.stopped_at, 256);
    EXPECT_TRUE(r.refusal.empty()) << r.refusal;
}

// The same point at 1e-5. Since the plateau is carried at its trailing stick zone (0.68 spacings of n = 250: 8(p),
// "Where the plateau is carried"; session 16) rung 256 gives an estimate again (before, its trailing zone's end, not
// resolved by its levels, changed -2.15e-6 then -1.9e-6 and gave none, so 512 was solved at 5e-5), and the point is
// answered at rung 256 by default, and at 5e-5 rung 1000 is no longer reached (128, 256, 512 solved). Since the driven
// five zones are on the exact weight (8(z), "The driven five zones on the weight"; session 25) rung 256 answers 1e-5
// (and 3e-6 is answered at 512, no rung skipped); at 1e-6 (also 5e-7 .. 1e-7) rung 256's change from 128 puts rung 512's
// estimate above the tolerance at least (8(q)), so 512 is skipped; the climb goes on to 1000 (stopped here).
TEST(LadderRefusals, FullCouplingSkipsARungCertainToFail) {
    const full_run r = run_full(0.75, 1e-6, {1000});
    EXPECT_EQ(r.solved, (std::vector<int>{128, 256, 1000}));
    EXPECT_EQ(r.stopped_at, 1000);
}

// Braked, Q/f = -0.75 (three zones of one direction): since the stick zone and the pressure are on their Jacobi weights
// (8(v), 8(w)) the levels are spectral and the point answers below the first rung, at n = 32 (8(q), "Rungs below the
// first"), every estimate above its distance from n = 512; no rung from 128 on is solved. The driven Q/f = +0.9 (three
// zones of opposite directions, the kinks carried: 8(q)'s rules from rung 128) still answers at a rung, 256: rung 128
// answered it until the zone ends' chance floor took their order 1 (8(q) "A fall faster than the ends' order").
TEST(LadderRefusals, FullCouplingStillAnswersWhereARungMeetsTheTolerance) {
    const full_run r = run_full(-0.75, std::nullopt, {128, 256, 512, 1000});
    ASSERT_TRUE(r.answer.has_value()) << r.refusal;
    EXPECT_EQ(r.answer->n, 32);
    EXPECT_EQ(r.solved, (std::vector<int>{32}));
    const tangential_solution& s = r.answer->solution;
    const error_estimate& e = *r.answer->estimate;
    contact fine(roughness{}, 0.05, solver_options{512, method::product}, dissimilar{beta_al_st, coupling_level::full});
    const tangential_solution f = fine.point(-0.75 * 0.05);
    EXPECT_GE(e.start, std::fabs(s.start() - f.start()));
    EXPECT_GE(e.c0, std::fabs(s.c0() - f.c0()));
    EXPECT_GE(e.xi, std::fabs(s.xi - f.xi));
    const full_run driven = run_full(0.9, std::nullopt, {512, 1000});
    ASSERT_TRUE(driven.answer.has_value()) << driven.refusal;
    EXPECT_EQ(driven.answer->n, 256);
    EXPECT_EQ(driven.solved, (std::vector<int>{128, 256}));
}

// The changes behind a full-coupling estimate are the levels' own: level n/4, n/2, n solved apart.
TEST(LadderRefusals, FullCouplingEstimateCarriesItsLastLevelChange) {
    const dissimilar pair{beta_al_st, coupling_level::full};
    contact c(roughness{}, 0.05, solver_options{64, method::product}, pair);
    const tangential_solution s = c.point(0.75 * 0.05);
    const std::optional<error_estimate> e = c.estimate(s);
    ASSERT_TRUE(e && e->changes);
    contact half(roughness{}, 0.05, solver_options{32, method::product}, pair);
    const tangential_solution h = half.point(0.75 * 0.05);
    ASSERT_EQ(h.layout.stick_zones(), 2u);
    const double start = std::max(std::fabs(s.start() - h.start()), std::fabs(s.start2() - h.start2()));
    const double end = std::max(std::fabs(s.c0() - h.c0()), std::fabs(s.end2() - h.end2()));
    EXPECT_NEAR(e->changes->last.start, start, 1e-9);
    EXPECT_NEAR(e->changes->last.c0, end, 1e-9);
    EXPECT_NEAR(e->changes->last.xi, std::fabs(s.xi - h.xi), 1e-9);
    EXPECT_LE(e->changes->last.start, 0.5 * e->start);  // twice it is inside the estimate
    // Johnson's level: the three-level rule, no changes carried.
    contact johnson(roughness{}, 0.05, solver_options{64, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_FALSE(johnson.estimate(johnson.point(0.75 * 0.05))->changes.has_value());
}

// The ladder's last line after rungs that refused (issue 24, review): a refusal whose line names no change
// (unadvised_refusal: no three zones at this n) is followed by the ladder's advice; one whose line names it
// (resolution_error) is not; one beyond every n (beyond_method_error) stops the climb at its rung, its line
// alone; one at the rounding limit (rounding_limit_error) stops it too, within the ladder's line. Every rung of the
// paper's problem refuses at its first level's solve (the contacts' checkpoint).
namespace {
struct every_rung_refused {
    std::string line;
    int rungs_built = 0;
};

template <class refusal>
every_rung_refused every_rung_refuses(const std::string& reason) {
    every_rung_refused r;
    level_ladder ladder(solver_options{}, roughness{}, [&](int n) {
        ++r.rungs_built;
        auto c = std::make_unique<contact>(roughness{}, 0.3, solver_options{n});
        c->set_checkpoint([reason] { throw refusal(reason); });
        return c;
    });
    try {
        ladder.point(0.15);
        ADD_FAILURE() << "answered";
    } catch (const resolution_error& e) {
        r.line = e.what();
    }
    return r;
}

bool ends_with(const std::string& s, const std::string& end) {
    return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}
}  // namespace

TEST(LadderRefusals, AdviceOnlyAfterARefusalNamingNoChange) {
    const std::string advice = "; give n to see that point, or try another method or zone search";
    const every_rung_refused unadvised = every_rung_refuses<unadvised_refusal>("no zone here");
    EXPECT_EQ(unadvised.rungs_built, 4);
    EXPECT_TRUE(ends_with(unadvised.line, "(at n = 1000: no zone here)" + advice)) << unadvised.line;
    const every_rung_refused advised = every_rung_refuses<resolution_error>("no zone here; use method 'product'");
    EXPECT_EQ(advised.rungs_built, 4);
    EXPECT_TRUE(ends_with(advised.line, "(at n = 1000: no zone here; use method 'product')")) << advised.line;
    const every_rung_refused beyond = every_rung_refuses<beyond_method_error>("beyond every n; give Q = 0");
    EXPECT_EQ(beyond.rungs_built, 1);
    EXPECT_EQ(beyond.line, "beyond every n; give Q = 0");
}

// A rung whose zone ends' Newton stops at a rounding beyond its cap (rounding_limit_error, numerics/damped_newton.hpp):
// that rounding grows with n, so the ladder climbs no higher and its line is the rung's, which names what lowers it,
// with no advice added. Before, it was an empty search like any other, refused with "another n may find them", and
// the ladder climbed to n = 1000 (four rungs built) to end on the top rung's line.
TEST(LadderRefusals, RoundingLimitStopsTheClimb) {
    const every_rung_refused limit = every_rung_refuses<rounding_limit_error>(
        "the zone ends are not resolved at this n: give a smaller n");
    EXPECT_EQ(limit.rungs_built, 1);
    EXPECT_TRUE(ends_with(limit.line,
                          "(at n = 128: the zone ends are not resolved at this n: give a smaller n)"))
        << limit.line;
}

// docs/formulation.md 8(q), "A failure the levels settle", on made-up margins (session 26 review R1-R3): three
// consecutive rungs of one structure whose margin stays below zero by more than the full-coupling rule's bound of its
// changes settle; two rungs, a margin that tends to zero, changes that stall, or two structures do not.
namespace {
// The braked three zones (slip, stick, slip, one direction), the structure of the rungs below unless one is given.
zone_layout braked() { return one_stick_zone(-0.9, 0.5, zone_route::general); }
failed_rung failing(int n, double stick, const zone_layout& layout = braked(), double pressure = 0.1) {
    traction_checks c{};
    c.pressure_margin = pressure;
    c.stick_margin = stick;
    c.slip_margin = 1e-8;
    c.stick_rounding = 1e-12;
    c.pressure_holds = pressure >= 0.0;
    c.stick_holds = stick >= 0.0;
    c.slip_holds = true;
    return {n, c, layout};
}
std::optional<std::string> settles(double a, double b, double c, const zone_layout& last = braked()) {
    return settled_failure({failing(128, a), failing(256, b), failing(512, c, last)}, -0.0038, 0.05);
}
}  // namespace

TEST(LadderRefusals, SettledFailureNeedsThreeRungsOfOneStructure) {
    // The braked pair's -0.000921 at every rung, with changes of a few 1e-9 either way: settled.
    const std::optional<std::string> line = settles(-9.21e-4, -9.21e-4 + 2e-9, -9.21e-4 + 3e-9);
    ASSERT_TRUE(line.has_value());
    EXPECT_NE(line->find("at n = 128, 256 and 512 alike (stick margin"), std::string::npos) << *line;
    EXPECT_NE(line->find("coupling = \"johnson\" answers the load"), std::string::npos) << *line;
    EXPECT_EQ(line->find("::"), std::string::npos) << *line;
    EXPECT_TRUE(settles(-9.21e-4, -9.21e-4, -9.21e-4).has_value());  // no change at all: the floor alone
    // A margin halving towards zero (order 1): its changes' bound reaches past zero.
    EXPECT_FALSE(settles(-2e-4, -1e-4, -0.5e-4).has_value());
    // The zone ends' erratic sequence (8(q) "A fall faster than the ends' order") read as a margin about zero: changes
    // of one size stall (no bound), or the last rung holds.
    EXPECT_FALSE(settles(-8.0e-7, -6.8e-7, -5.6e-7).has_value());
    EXPECT_FALSE(settles(-8.0e-7, -6.8e-7, 9.0e-7).has_value());
    // Three rungs of two structures: their margins' differences are no convergence. Judged by the zones themselves
    // (same_zones): one stick zone from the edge (stick, slip) is not the three zones, though both have one stick zone
    // and one slip direction (which the rule compared before, and settled).
    EXPECT_FALSE(settles(-9.21e-4, -9.21e-4, -9.21e-4, five_zones_layout(-0.99, 0.2, 0.4, 0.98, 1)).has_value());
    EXPECT_FALSE(settles(-9.21e-4, -9.21e-4, -9.21e-4, one_stick_zone(-1.0, 0.5, zone_route::general)).has_value());
    EXPECT_FALSE(settles(-9.21e-4, -9.21e-4, -9.21e-4, mirrored(braked())).has_value());
    // The same zones with other ends: one structure.
    EXPECT_TRUE(settles(-9.21e-4, -9.21e-4, -9.21e-4, one_stick_zone(-0.8, 0.6, zone_route::general)).has_value());
    // The pressure's margin has no rounding floor; the same rule.
    const std::optional<std::string> open = settled_failure(
        {failing(128, 1e-3, braked(), -0.2), failing(256, 1e-3, braked(), -0.2), failing(512, 1e-3, braked(), -0.2)},
        -0.0038, 0.05);
    ASSERT_TRUE(open.has_value());
    EXPECT_NE(open->find("pressure turns negative"), std::string::npos) << *open;
    // One text with a rung's own refusal (coupled_failure_cause and _advice): the contact would open.
    EXPECT_NE(open->find("the contact would open"), std::string::npos) << *open;
    EXPECT_NE(open->find("coupling = \"johnson\" answers it without that term"), std::string::npos) << *open;
}

// docs/formulation.md 8(q), "An alternation that converges at no level" (issue 24; session 27 slowref item 2): beta_d =
// 0.7, f = 0.3, Q/f = -0.5 at full coupling. The alternation converges at no level (8 .. 1000 measured: 40 steps, or
// changes that grow), and a reported point's refusal named the first failed check of a non-converged iterate ("the
// coupled zones fail the checks"), after every rung (65 s CPU). Now a rung's line names the alternation, and once rungs
// 128 and 256 show it at their points and levels the ladder stops (rungs 512, 1000 throw here if started: the old
// program stops on 512's first solve, with no refusal).
TEST(LadderRefusals, AlternationConvergingAtNoLevelRefusedAfterTwoRungs) {
    contact rung(roughness{}, 0.3, solver_options{128}, dissimilar{0.7, coupling_level::full});
    try {
        rung.point(-0.15);
        ADD_FAILURE() << "answered at n = 128";
    } catch (const resolution_error& e) {
        const std::string line = e.what();
        EXPECT_NE(line.find("the alternation does not"), std::string::npos) << line;
        EXPECT_NE(line.find("failing the checks (3.3)-(3.4) on the way"), std::string::npos) << line;
        EXPECT_EQ(line.find("the coupled zones fail the checks"), std::string::npos) << line;
        EXPECT_NE(line.find("coupling = \"johnson\""), std::string::npos) << line;
    }
    const full_run r = run_full(-0.5, std::nullopt, {512, 1000}, 0.3, 0.7);
    EXPECT_EQ(r.stopped_at, 0);
    EXPECT_FALSE(r.answer.has_value());
    EXPECT_NE(r.refusal.find("converges at none of n = 32, 64, 128 and 256"), std::string::npos) << r.refusal;
    EXPECT_NE(r.refusal.find("coupling = \"johnson\" answers the load"), std::string::npos) << r.refusal;
    EXPECT_NE(r.refusal.find("--n 512"), std::string::npos) << r.refusal;
    EXPECT_EQ(r.refusal.find("fail the checks"), std::string::npos) << r.refusal;
    EXPECT_EQ(r.refusal.find('\n'), std::string::npos) << r.refusal;
    EXPECT_EQ(r.refusal.find("::"), std::string::npos) << r.refusal;
}
