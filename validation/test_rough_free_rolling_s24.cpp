// SPDX-License-Identifier: GPL-3.0-or-later
// Free rolling of the rough pair (data/aluminium-on-steel-rough.toml's layer) at large friction (issue 24, 7;
// docs/formulation.md 8(n), "Rough rollers: beyond every n"). No route neglects a rough pair's edge layers, so the ladder
// must resolve them, and from f of about 0.35 on (Johnson's level and full coupling) no n up to 1000 does: the ladder
// had climbed before refusing (f = 0.5: more than 30 s CPU at Johnson's level, minutes at full coupling), or refused at
// once with the smooth pair's estimate and advice to change beta_d. It now refuses before any solve, from the crossing
// of the pair's own no-slip solution, naming the friction below which the rule lets the ladder climb. Checked here:
// the crossing against the closed form of smooth rollers (8(n)); against the five zones' leading layer of the rough
// pair (the derived (4/e^2) t_c); the measured law of the layer's change between levels n/2 and n for the rough pair
// (8(n) item 2, measured on smooth rollers); and the refusals by the levels solved (none), not by time.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "ladder_first_solve.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/level_ladder.hpp"

using namespace roughroll;

namespace {
using ladder_first_solve::ladder_run;
using ladder_first_solve::named_friction;

// The ladder for the rough pair's free rolling at friction f and the default tolerance, every rung's contact stopping
// at its first level's solve.
ladder_run run(double f, coupling_level level) { return ladder_first_solve::run(f, rough_pair_at_a(), level); }
}  // namespace

// Smooth rollers: the no-slip solution is 8(n)'s closed form and t_c = 2/(1 + exp(pi f/|beta_D|)); the crossing found on
// the level's solution (f = 0.05, 0.2: above x0, by bisection; 0.5, 1: extrapolated from x0) agrees with it.
TEST(RoughFreeRollingS24, CrossingOfSmoothRollersIsTheClosedForm) {
    for (const double f : {0.05, 0.2, 0.5, 1.0}) {
        const contact c(roughness{}, f, solver_options{128, method::product},
                        dissimilar{beta_al_st, coupling_level::johnson});
        const double t = johnson_layers_crossing(c.normal(), kernel{}, kernel{}, beta_al_st, f).crossing;
        const double exact = 2.0 / (1.0 + std::exp(M_PI * f / beta_al_st));
        // f = 0.5, 1: 0.57 % below, n = 128's g(x0) at x0 = ten end spacings (8(n), "Rough rollers").
        EXPECT_NEAR(t / exact, 1.0, 1e-2) << "f = " << f;
    }
}

// The rough pair at f = 0.2 (and 0.25, near the rule's edge): its five zones (the search at n = 64, Newton at n = 128 from its ends) have the leading
// layer 1 + s1 = (4/e^2) t_c (1 + O(t_c)) of the derivation (8(n), "The layers' positions": the inner problem on the scale
// t_c, where the layer kernels are a regular term), with t_c the rough pair's own crossing (0.0054), not the smooth
// formula's (0.025); and the layer's change from n = 64 to 128 lies on the law the quick refusal uses (8(n) item 2,
// measured on smooth rollers: 3 exp(-0.57 sqrt(x)), x = t_c n^2), above the tenth of it that the rule takes.
TEST(RoughFreeRollingS24, CrossingAndLawAgainstTheFiveZones) {
    const double f = 0.2;
    const roughness rough = rough_pair_at_a();
    std::optional<tangential_solution> coarse, fine;
    {
        contact c(rough, f, solver_options{64, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
        dissimilar_zones d(tangential_of(c), kernel::tangential(rough), beta_al_st);
        coarse = d.five_zones(0.0);
    }
    ASSERT_TRUE(coarse && coarse->checks.hold()) << "no five zones at n = 64";
    contact c(rough, f, solver_options{128, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    const double t_c =
        johnson_layers_crossing(c.normal(), kernel::tangential(rough), kernel::normal(rough), beta_al_st, f).crossing;
    {
        dissimilar_zones d(tangential_of(c), kernel::tangential(rough), beta_al_st);
        fine = d.five_zones(0.0, coarse->layout.stick_ends());
    }
    ASSERT_TRUE(fine && fine->checks.hold()) << "no five zones at n = 128";
    const double smooth = 2.0 / (1.0 + std::exp(M_PI * f / beta_al_st));
    std::printf("t_c %.6e (smooth formula %.6e), 1 + s1 = %.6e (n = 128), %.6e (n = 64)\n", t_c, smooth, 1.0 + fine->start(),
                1.0 + coarse->start());
    EXPECT_LT(t_c, 0.3 * smooth);
    // 4/e^2 + 0.125 t_c (the correction measured on smooth rollers) = 0.5420; the five zones at n = 128 are within 1e-3
    // of their limit in 1 + s1 (relative: the change to n = 256 in rough5's continuation, s23).
    const double ratio = (1.0 + fine->start()) / t_c;
    EXPECT_NEAR(ratio, 4.0 * std::exp(-2.0) + 0.125 * t_c, 0.01) << ratio;
    const double x = t_c * 128.0 * 128.0;
    const double change = std::fabs(fine->start() - coarse->start()) / (1.0 + fine->start());
    const double law = 3.0 * std::exp(-0.57 * std::sqrt(x));
    std::printf("x = %.1f: change %.4e, law %.4e\n", x, change, law);
    EXPECT_GT(change, 0.5 * law);
    EXPECT_LT(change, 2.0 * law);

    // Near the rule's edge (x = 196 at n = 1000 and the default tolerance): f = 0.25, levels 160 and 320, x = 177, the
    // five zones continued in f at n = 128 (Newton from the previous f's ends) and then in n.
    std::optional<tangential_solution> s = fine;
    const auto next = [&](double at_f, int n, double* crossing = nullptr) {
        contact l(rough, at_f, solver_options{n, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
        if (crossing)
            *crossing = johnson_layers_crossing(l.normal(), kernel::tangential(rough), kernel::normal(rough),
                                                beta_al_st, at_f)
                            .crossing;
        dissimilar_zones d(tangential_of(l), kernel::tangential(rough), beta_al_st);
        s = d.five_zones(0.0, s->layout.stick_ends());
        ASSERT_TRUE(s && s->checks.hold()) << "f = " << at_f << ", n = " << n;
    };
    next(0.225, 128);
    next(0.25, 128);
    next(0.25, 160);
    const double half = s->start();
    double t = 0.0;
    next(0.25, 320, &t);
    const double x_edge = t * 320.0 * 320.0, change_edge = std::fabs(s->start() - half) / (1.0 + s->start());
    const double law_edge = 3.0 * std::exp(-0.57 * std::sqrt(x_edge));
    std::printf("f = 0.25: t_c %.4e, x = %.1f: change %.4e, law %.4e\n", t, x_edge, change_edge, law_edge);
    EXPECT_GT(x_edge, 150.0);
    EXPECT_GT(change_edge, 0.5 * law_edge);
    EXPECT_LT(change_edge, 2.0 * law_edge);
}

// f = 0.5, 1, 10, 1e3, 1e6 at both coupling levels: refused with no level solved, naming the friction below which the
// ladder climbs; that friction is not refused (a level is solved), 0.02 above it is (the advice is rounded down to two
// digits). f = 0.2, which the ladder answers at Johnson's level (n = 512, session 23), is not refused.
TEST(RoughFreeRollingS24, BeyondEveryNRefusedBeforeAnySolve) {
    for (const coupling_level level : {coupling_level::johnson, coupling_level::full}) {
        const char* name = level == coupling_level::full ? "full" : "johnson";
        std::optional<double> reach;
        for (const double f : {0.5, 1.0, 10.0, 1e3, 1e6}) {
            const ladder_run r = run(f, level);
            EXPECT_FALSE(r.solved) << name << " f = " << f;
            EXPECT_NE(r.refusal.find("no n up to 1000 meets the tolerance"), std::string::npos) << r.refusal;
            EXPECT_NE(r.refusal.find("smaller friction f"), std::string::npos) << r.refusal;
            const std::optional<double> named = named_friction(r.refusal);
            ASSERT_TRUE(named) << r.refusal;
            if (reach) {
                EXPECT_EQ(*named, *reach) << name << " f = " << f;  // the rule's edge, whatever f asked
            }
            reach = named;
        }
        std::printf("%s: refused above f = %.2f\n", name, *reach);
        EXPECT_GT(*reach, 0.25);
        EXPECT_LT(*reach, 0.45);
        EXPECT_TRUE(run(*reach, level).solved) << name;
        EXPECT_FALSE(run(*reach + 0.02, level).solved) << name;
        EXPECT_TRUE(run(0.2, level).solved) << name;
    }
}
