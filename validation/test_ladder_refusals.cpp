// SPDX-License-Identifier: GPL-3.0-or-later
// Refusals of the ladder decided before any solve (issue 24, 5 and 7; contact::beyond_every_n,
// docs/formulation.md 8(n) "Beyond every n"): free rolling of aluminium on steel, smooth, Johnson's
// level, whose edge layers are too thin for n = 1000 to meet the tolerance and too thick to be
// neglected within it. Before, the ladder climbed to n = 1000 first (f = 0.5: about 8 min CPU at
// n = 1000, 31 min wall on a loaded machine) and refused there. The quick refusal is asserted by
// the levels solved (the contacts' checkpoint, called before every level's solve), not by time:
// on the old program the first level's checkpoint throws and the test fails at once.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/level_ladder.hpp"

using namespace roughroll;

namespace {
// Thrown by the checkpoint: a level was about to be solved.
struct level_solved : std::runtime_error {
    level_solved() : std::runtime_error("a level was solved") {}
};

struct ladder_run {
    std::string refusal;  // the resolution_error's line; empty when the ladder started a solve
    int rungs_built = 0;  // contacts the factory made
    bool solved = false;  // a level's solve was started
};

// The ladder at friction f, free rolling, the tolerance `tol` (empty: the default), every rung's
// contact stopping at its first level's solve.
ladder_run run(double f, std::optional<double> tol = std::nullopt) {
    ladder_run r;
    solver_options options;
    options.tolerance = tol;
    level_ladder ladder(options, roughness{}, [&](int n) {
        ++r.rungs_built;
        auto c = std::make_unique<contact>(roughness{}, f, solver_options{n, options.how, options.zones, tol},
                                           dissimilar{beta_al_st, coupling_level::johnson});
        c->set_checkpoint([] { throw level_solved(); });
        return c;
    });
    try {
        ladder.point(0.0);
        ADD_FAILURE() << "f = " << f << ": answered without a solve";
    } catch (const resolution_error& e) {
        r.refusal = e.what();
    } catch (const level_solved&) {
        r.solved = true;
    }
    return r;
}

// The edge layers' crossing t_c and the layers-neglected route's relative bound (8(n)).
double crossing(double f) { return no_slip_layers(beta_al_st, f).crossing; }
double layers_relative(double f) {
    return no_slip_layers(beta_al_st, f).xi_bound / std::fabs(no_slip_creep(beta_al_st));
}
}  // namespace

// f = 0.45, 0.5, 0.55, 0.6 at the default tolerance: no level solved, one rung's contact built, the
// line names the tolerance that answers (the layers neglected).
TEST(LadderRefusals, FreeRollingBeyondEveryNRefusedBeforeAnySolve) {
    for (const double f : {0.45, 0.5, 0.55, 0.6}) {
        SCOPED_TRACE(f);
        ASSERT_GT(layers_relative(f), default_tolerance);  // not answered by the layers neglected
        const ladder_run r = run(f);
        EXPECT_FALSE(r.solved);
        EXPECT_EQ(r.rungs_built, 1);
        EXPECT_NE(r.refusal.find("no n up to 1000 meets the tolerance"), std::string::npos) << r.refusal;
        EXPECT_NE(r.refusal.find("--tolerance"), std::string::npos) << r.refusal;
        EXPECT_EQ(r.refusal.find('\n'), std::string::npos) << r.refusal;
        EXPECT_EQ(r.refusal.find("::"), std::string::npos) << r.refusal;  // no function names
    }
    // f = 0.5: the same tolerance as the refusal after the climb named (0.00078, docs/formulation.md 8(n)).
    EXPECT_NE(run(0.5).refusal.find("a tolerance of 0.00078 or more"), std::string::npos);
}

// The rule's edge at the default tolerance: x = t_c 1000^2 with 0.3 exp(-0.57 sqrt(x)) = 1e-4, x = 197,
// f = 0.4226. Above it refused at once; below (f = 0.35, answered at n = 1000 by the climb, and
// f = 0.42) the ladder solves.
TEST(LadderRefusals, OnlyWhereTheMeasuredChangeExceedsTheTolerance) {
    EXPECT_LT(crossing(0.42) * 1e6, 230.0);
    EXPECT_GT(crossing(0.42) * 1e6, 197.0);
    EXPECT_TRUE(run(0.35).solved);
    EXPECT_TRUE(run(0.42).solved);
    EXPECT_FALSE(run(0.425).solved);
    // A tolerance the layers' route meets answers without a solve (8(n)); one between the measured
    // change at n = 1000 and the layers' bound climbs: f = 0.45, change above 8.1e-4, bound 2.1e-3.
    EXPECT_GT(layers_relative(0.45), 2e-3);
    EXPECT_TRUE(run(0.45, 2e-3).solved);
    EXPECT_FALSE(run(0.45, 5e-4).solved);
    // Beyond the measured range (x > 555) never refused at once, whatever the tolerance.
    EXPECT_GT(crossing(0.37) * 1e6, 555.0);
    EXPECT_TRUE(run(0.37, 1e-9).solved);
}

// The refusal is the contact's, for the ladder's top rung: an explicit n (no ladder) is solved as before.
TEST(LadderRefusals, OnlyTheLadderRefusesAtOnce) {
    contact c(roughness{}, 0.5, solver_options{128}, dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_TRUE(c.beyond_every_n(0.0, 1000, default_tolerance).has_value());
    EXPECT_FALSE(c.beyond_every_n(0.0, 1000, 1e-3).has_value());  // the layers neglected answer
    EXPECT_FALSE(c.beyond_every_n(0.05, 1000, default_tolerance).has_value());  // Q != 0: not this structure
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
    EXPECT_FALSE(rough.beyond_every_n(0.0, 1000, default_tolerance).has_value());
    contact full(roughness{}, 0.5, solver_options{128}, dissimilar{beta_al_st, coupling_level::full});
    EXPECT_FALSE(full.beyond_every_n(0.0, 1000, default_tolerance).has_value());
    // The law was measured on product integration (the levels of 'product' and 'extrapolated'), not 'paper'.
    contact product(roughness{}, 0.5, solver_options{96, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_TRUE(product.beyond_every_n(0.0, 1000, default_tolerance).has_value());
    contact paper(roughness{}, 0.5, solver_options{200, method::paper}, dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_FALSE(paper.beyond_every_n(0.0, 1000, default_tolerance).has_value());
}
