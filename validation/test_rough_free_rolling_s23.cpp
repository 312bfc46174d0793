// SPDX-License-Identifier: GPL-3.0-or-later
// Free rolling of the rough pair (data/aluminium-on-steel-rough.toml, Johnson's level) at f = 0.1 and 0.2: five zones
// (slip-, stick, slip+, stick, slip-) exist, but the search found none ("no five zones ... are found at n = 1000
// either", after about 360 s CPU): its scan of driven loads Q/f = k/8 lay beyond the rough pair's five zones, which close
// in the load near free rolling (below Q/f = 0.086 at f = 0.1), so the driven three zones held at every scan load and
// gave no start. The scan's loads 1/16, 1/32, 1/64 give one (docs/formulation.md 8(j) 4a). The root the search reaches
// is checked against an independent path to it: the five zones of f = 0.05 (which the k/8 scan finds) continued in f
// at Q = 0 by Newton from the previous f's ends, steps of 0.0125 (the ends depend on beta_D/f alone, 8(h)).
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "aluminium_on_steel.hpp"

using namespace roughroll;

namespace {
struct level {
    contact c;
    dissimilar_zones d;
    level(double f, int n)
        : c(rough_pair_at_a(), f, solver_options{n, method::product}, dissimilar{beta_al_st, coupling_level::johnson}),
          d(tangential_of(c), kernel::tangential(rough_pair_at_a()), beta_al_st) {}
};

void print(const char* what, double f, const tangential_solution& s) {
    std::printf("%s f = %.4f: [%.9f, %.9f, %.9f, %.9f], xi %.12f, margins stick %.2e slip %.2e\n", what, f, s.start(), s.c0(),
                s.start2(), s.end2(), s.xi, s.checks.stick_margin, s.checks.slip_margin);
}

// Free rolling at f by the search alone, and by the continuation in f from f = 0.05's search.
void search_against_continuation(double f, int n) {
    std::optional<tangential_solution> searched;
    {
        level l(f, n);
        searched = l.d.five_zones(0.0);
    }
    ASSERT_TRUE(searched) << "the search finds no five zones at f = " << f;
    print("search      ", f, *searched);
    EXPECT_TRUE(searched->checks.hold());
    std::optional<tangential_solution> s;
    {
        level l(0.05, n);
        s = l.d.five_zones(0.0);
    }
    ASSERT_TRUE(s) << "no five zones at f = 0.05";
    const int steps = static_cast<int>(std::lround((f - 0.05) / 0.0125));
    for (int i = 1; i <= steps && s; ++i) {
        level l(0.05 + 0.0125 * i, n);
        s = l.d.five_zones(0.0, s->layout.stick_ends());
    }
    ASSERT_TRUE(s) << "the continuation in f stops";
    print("continuation", f, *s);
    EXPECT_TRUE(s->checks.hold());
    // Two Newton roots of the same equations, each to its ends' resolution (zone_end_resolution 1e-11, times the
    // conditioning): the same root where they agree far below the zones' sizes (the thinnest 1e-3).
    EXPECT_NEAR(searched->start(), s->start(), 1e-8);
    EXPECT_NEAR(searched->c0(), s->c0(), 1e-8);
    EXPECT_NEAR(searched->start2(), s->start2(), 1e-8);
    EXPECT_NEAR(searched->end2(), s->end2(), 1e-8);
    EXPECT_NEAR(searched->xi, s->xi, 1e-10);
}
}  // namespace

// beta_D/f = 1.44: the scan at |beta_D| (inside [1, 6]).
TEST(RoughFreeRolling, FoundByTheSearchAtATenth) { search_against_continuation(0.1, 32); }

// beta_D/f = 0.72: the scan at the forcing 1.5 f, continued in the forcing to |beta_D| (outside [1, 6]).
TEST(RoughFreeRolling, FoundByTheSearchAtTwoTenths) { search_against_continuation(0.2, 64); }

// f = 0.1 again at n = 16 (search and continuation agree there too: measured on main 57b4b3a the same ends to 1e-9 as
// at n = 32): cheap enough for the sanitized run (about 1 s CPU in Release; the two tests above are large_n), so that
// the search's added scan loads and this program's route run under ASan/UBSan.
TEST(RoughFreeRolling, FoundByTheSearchAtATenthAtSixteen) { search_against_continuation(0.1, 16); }
