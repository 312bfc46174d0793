// SPDX-License-Identifier: GPL-3.0-or-later
// Five zones of dissimilar rollers (docs/formulation.md 8(g), 8(j)): slip-, stick, slip+, stick,
// slip- (beta_D > 0), by the product's two-zone collocation and Newton in the four ends, against
// the independent grid route (no structure assumed), free rolling and Bentall and Johnson's
// driven case Q/f = +0.75 at f = 0.05, aluminium on steel.
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include <gsl/gsl_math.h>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "aluminium_on_steel.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "test_zones_low_order.hpp"

using namespace roughroll;

namespace {
// The product's five zones at (f, Q), n = 32, found without a guess (dissimilar_zones::five_zones).
tangential_solution product(double f, double Q, int n = 32, const roughness& r = roughness{}) {
    contact c(r, f, solver_options{n, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    dissimilar_zones d(tangential_of(c), kernel::tangential(r), beta_al_st);
    const auto s = d.five_zones(Q);
    if (!s) throw numerical_error("five zones: no start converged");
    return *s;
}

// The product against the grid route: the grid's five runs, its creep within the route's error (the
// order-1 Richardson value of N = 100, 200 within their spread), the ends within two cells of N = 200.
double against_grid(double f, double Q, const roughness& r = roughness{}) {
    const tangential_solution s = product(f, Q, 32, r);
    std::printf(
        "f = %.3f, Q/f = %.2f: stick [%.6f, %.6f], [%.6f, %.6f], xi %.9f (Newton %d); margins stick "
        "%.2e, slip %.2e\n",
        f, Q / f, s.start(), s.c0(), s.start2(), s.end2(), s.xi, s.iterations, s.checks.stick_margin, s.checks.slip_margin);
    EXPECT_TRUE(s.checks.hold()) << s.checks.stick_margin << " " << s.checks.slip_margin;
    EXPECT_NEAR(s.Q, Q, 1e-14);
    contact c(r, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    const normal_solution& hertz = c.normal();
    std::vector<double> xi;
    std::vector<validation::grid_solution::run> runs;
    for (int N : {100, 200}) {
        const auto g = validation::solve_on_grid(hertz, kernel::tangential(r), f, Q, N, 0, beta_al_st);
        xi.push_back(g.xi);
        runs = g.runs();
        std::printf("  grid N = %d: xi %.9f, %zu runs\n", N, g.xi, runs.size());
    }
    const double richardson = 2.0 * xi[1] - xi[0], spread = std::fabs(xi[1] - xi[0]);
    std::printf("  product - grid(200) %.2e, product - Richardson %.2e, spread %.2e\n", s.xi - xi[1], s.xi - richardson,
                spread);
    EXPECT_LT(std::fabs(s.xi - richardson), spread);
    EXPECT_EQ(runs.size(), 5u);
    if (runs.size() != 5u) return s.xi;
    const std::vector<int> states{-1, 0, 1, 0, -1};
    const std::vector<double> ends = s.layout.stick_ends();
    for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(runs[k].state, states[k]);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(ends[k], runs[k].to, 0.02) << "end " << k;
    return s.xi;
}
}  // namespace

// Free rolling (Q = 0), the structure 8(g) saw on the grid, at f = 0.05 and 0.1; and 8(f): its creep
// lies between the complete-slip limit -2/pi cos(phi) beta_D and the no-slip limit Q/pi - 4 beta_D/pi^2,
// and moves towards no slip as f grows.
TEST(DissimilarFiveZones, FreeRollingAgainstTheGridRoute) {
    const double xi05 = against_grid(0.05, 0.0), xi10 = against_grid(0.1, 0.0);
    const double no_slip = -4.0 * beta_al_st / (M_PI * M_PI), complete = -0.5823613 * beta_al_st;
    std::printf("complete slip %.7f < xi(0.05) %.7f < xi(0.1) %.7f < no slip %.7f\n", complete, xi05, xi10, no_slip);
    EXPECT_LT(complete, xi05);
    EXPECT_LT(xi05, xi10);
    EXPECT_LT(xi10, no_slip);
}

// The same with a rough layer on roller 1 (tangential (T, A) = (1, 0.5), normal (0.5, 2), as
// DissimilarProduct's): the pressure is the rough normal solution, G and W carry K1*.
TEST(DissimilarFiveZones, RoughFreeRollingAgainstTheGridRoute) {
    against_grid(0.05, 0.0, roughness{{{1.0, 0.5}, {0.5, 2.0}}, {}});
}

// Bentall and Johnson's driven case Q/f = +0.75, f = 0.05: the three zones of the grid (its cells
// cannot hold the trailing layer) plus a trailing stick zone and slip- layer within 1e-3 of r = 1,
// where the three zones had v < 0 (DissimilarProduct.DrivenAtThreeQuartersHasATrailingLayer).
TEST(DissimilarFiveZones, DrivenAtThreeQuarters) {
    const double f = 0.05, Q = 0.75 * f;
    const tangential_solution s = product(f, Q);
    std::printf("Q/f = 0.75: stick [%.9f, %.9f], [%.9f, %.9f], xi %.10f; margins %.2e, %.2e\n", s.start(), s.c0(), s.start2(), s.end2(),
                s.xi, s.checks.stick_margin, s.checks.slip_margin);
    EXPECT_TRUE(s.checks.hold());
    EXPECT_GT(s.start2(), 0.999);
    const normal_solution hertz = hertz_solution(32, method::product);
    const auto g100 = validation::solve_on_grid(hertz, kernel{}, f, Q, 100, 0, beta_al_st);
    const auto g200 = validation::solve_on_grid(hertz, kernel{}, f, Q, 200, 0, beta_al_st);
    const auto runs = g200.runs();
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_NEAR(s.start(), runs[0].to, 0.02);
    EXPECT_NEAR(s.c0(), runs[1].to, 0.02);
    const double richardson = 2.0 * g200.xi - g100.xi, spread = std::fabs(g200.xi - g100.xi);
    std::printf("  grid %.9f, %.9f; product - Richardson %.2e, spread %.2e\n", g100.xi, g200.xi, s.xi - richardson,
                spread);
    EXPECT_LT(std::fabs(s.xi - richardson), spread);
}

// The slip velocity up to the trailing edge of the driven case, as the traction plot samples it: W's
// Cauchy point r at the end of its last piece (r = 1) or within 1e-9 of it (where W does not cut
// there) gives finite values that approach v(1) as sqrt(1 - r) does, the change shrinking about ten
// times per hundredfold step. (W in the analytic variable alone returned NaN at r = 1 here, eta
// rounding onto the end; the route in eta before it threw at 1 - r = 1e-12: end_quadrature::piece now
// falls back from one to the other.)
TEST(DissimilarFiveZones, SlipVelocityUpToTheTrailingEdge) {
    const double f = 0.05, Q = 0.75 * f;
    contact c(roughness{}, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    dissimilar_zones d(tangential_of(c), kernel{}, beta_al_st);
    const auto s = d.five_zones(Q);
    ASSERT_TRUE(s.has_value());
    std::vector<double> v;
    for (double gap : {1e-6, 1e-8, 1e-10, 1e-12, 0.0}) {
        v.push_back(d.slip_velocity(*s, 1.0 - gap));
        ASSERT_TRUE(std::isfinite(v.back())) << "r = 1 - " << gap;
    }
    for (std::size_t k = 2; k < v.size(); ++k)
        EXPECT_LT(std::fabs(v[k] - v[k - 1]), 0.2 * std::fabs(v[k - 1] - v[k - 2])) << "step " << k;
}

// Convergence in n and the honest estimate: the difference of n = 16 and 32 bounds the distance of
// n = 32 from n = 64, for the creep and the four ends (free rolling, f = 0.05).
TEST(DissimilarFiveZones, ConvergesInN) {
    const double f = 0.05;
    for (const roughness& r : {roughness{}, roughness{{{1.0, 0.5}, {0.5, 2.0}}, {}}}) {
        const tangential_solution b = product(f, 0.0, 32, r);
        // The other levels by Newton from n = 32's ends, as the levels of an estimate are found.
        const auto level = [&](int n) {
            contact c(r, f, solver_options{n, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
            dissimilar_zones d(tangential_of(c), kernel::tangential(r), beta_al_st);
            const auto s = d.five_zones(0.0, b.layout.stick_ends());
            if (!s) throw numerical_error("five zones: Newton from the n = 32 ends did not converge");
            EXPECT_TRUE(s->checks.hold()) << n;
            return *s;
        };
        const tangential_solution a = level(16), c = level(64);
        const auto row = [](const tangential_solution& s) { return std::vector<double>{s.xi, s.start(), s.c0(), s.start2(), s.end2()}; };
        const auto ra = row(a), rb = row(b), rc = row(c);
        const char* names[] = {"xi", "s1", "c1", "s2", "c2"};
        for (std::size_t k = 0; k < ra.size(); ++k) {
            std::printf("  %s %s: n = 16/32 %.2e, 32/64 %.2e\n", r.smooth() ? "smooth" : "rough", names[k],
                        std::fabs(rb[k] - ra[k]), std::fabs(rc[k] - rb[k]));
            EXPECT_LE(std::fabs(rc[k] - rb[k]), std::max(std::fabs(rb[k] - ra[k]), zone_end_resolution)) << k;
        }
    }
}

// 8(h): exchanging the rollers, (beta_D, Q) -> (-beta_D, -Q), gives the same ends and the opposite
// creep, traction and slip velocity, to the bit (the same equations in the frame beta_D > 0).
TEST(DissimilarFiveZones, RollersExchanged) {
    const double f = 0.05;
    for (double Q : {0.0, 0.75 * f}) {
        contact c(roughness{}, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
        dissimilar_zones d(tangential_of(c), kernel{}, beta_al_st), e(tangential_of(c), kernel{}, -beta_al_st);
        const auto a = d.five_zones(Q), b = e.five_zones(-Q);
        ASSERT_TRUE(a && b);
        EXPECT_EQ(a->start(), b->start());
        EXPECT_EQ(a->c0(), b->c0());
        EXPECT_EQ(a->start2(), b->start2());
        EXPECT_EQ(a->end2(), b->end2());
        EXPECT_EQ(a->xi, -b->xi);
        EXPECT_EQ(a->Q, -b->Q);
        EXPECT_TRUE(b->checks.hold());
        for (double r : {-0.95, -0.5, 0.0, 0.7, 0.93, 0.99, 0.9999}) {
            EXPECT_EQ(d.traction(*a, r), -e.traction(*b, r)) << r;
            EXPECT_EQ(d.slip_velocity(*a, r), -e.slip_velocity(*b, r)) << r;
        }
        EXPECT_THROW(d.five_zones(f), input_error);
        EXPECT_THROW(d.five_zones(0.0, {-0.5, 0.5}), std::invalid_argument);  // one zone's ends: a programming error
        EXPECT_FALSE(d.five_zones(0.0, {-0.5, 0.6, 0.5, 0.9}));  // overlapping zones: outside, no Newton
    }
}

// Robustness: scenes a rounding apart find the same answer (a 1-ulp change of beta_D once made
// Newton's last continuation step fail at n = 64, and sampling v at 1 - 1e-16 made W's qagp
// report round-off; both fixed: steps halved where Newton fails, r kept off the breakpoints).
TEST(DissimilarFiveZones, NearbyScenesAllSolve) {
    const double f = 0.05;
    // Smooth, xi converges in n to the bit (ConvergesInN): one reference at n = 32 serves n = 64 too.
    const double reference = product(f, 0.0, 32).xi;
    const std::vector<std::pair<double, int>> cases{{beta_al_st * (1.0 - 1e-15), 32},
                                                    {0.1438337435056057, 32},
                                                    {beta_al_st * (1.0 + 1e-9), 32},
                                                    {0.1438337435056057, 64}};
    for (const auto& [beta, n] : cases) {
        contact c(roughness{}, f, solver_options{n, method::product}, dissimilar{beta, coupling_level::johnson});
        dissimilar_zones d(tangential_of(c), kernel{}, beta);
        const auto s = d.five_zones(0.0);
        ASSERT_TRUE(s) << beta << " " << n;
        EXPECT_TRUE(s->checks.hold());
        // xi is about -0.47 beta_D here: a relative change 1e-9 of beta_D moves it by about 1e-10.
        EXPECT_NEAR(s->xi, reference, 1e-9) << beta << " " << n;
    }
}

// 8(f), towards no slip: free rolling from f = 0.1 to 0.2 in steps of 0.025, each by Newton from the
// previous f's ends (by 8(h) the ends depend on beta_D/f alone, so they are near). The edge zones
// thin like 2 exp(-pi f/beta_D) (8(g)), and the creep's distance from the no-slip limit
// -4 beta_D/pi^2 falls by the same factor per step, exp(-pi 0.025/beta_D) = 0.579 (measured within 5 %).
TEST(DissimilarFiveZones, TowardsNoSlip) {
    const double no_slip = -4.0 * beta_al_st / (M_PI * M_PI);
    std::vector<double> ends, distance;
    for (double f : {0.1, 0.125, 0.15, 0.175, 0.2}) {
        contact c(roughness{}, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
        dissimilar_zones d(tangential_of(c), kernel{}, beta_al_st);
        const auto s = ends.empty() ? d.five_zones(0.0) : d.five_zones(0.0, ends);
        ASSERT_TRUE(s) << f;
        EXPECT_TRUE(s->checks.hold()) << f;
        ends = s->layout.stick_ends();
        distance.push_back(s->xi - no_slip);
        std::printf("f = %.3f: stick [%.6f, %.6f], [%.6f, %.6f], xi %.9f, xi - no slip %.3e\n", f, s->start(), s->c0(), s->start2(),
                    s->end2(), s->xi, distance.back());
    }
    const double expected = std::exp(-M_PI * 0.025 / beta_al_st);
    for (std::size_t k = 1; k < distance.size(); ++k) {
        EXPECT_LT(distance[k], 0.0);
        EXPECT_NEAR(distance[k] / distance[k - 1], expected, 0.05 * expected) << k;
    }
}

// 8(f), towards complete slip: free rolling at f = 0.04 down to 0.0025 (beta_D/f = 3.6 to 58; below
// f = 0.025, by the continuation in beta_D/f of five_zones(Q), 8(j) 4a) moves monotonically towards
// -0.5823613 beta_D (Bentall and Johnson's 0.457), staying above it; the distance falls by more
// than 1.7 per halving of f, faster as f falls (measured 1.79, 2.05, 2.31, 2.58: the grid's rate was
// about f, this tends to f^1.4 and beyond).
TEST(DissimilarFiveZones, TowardsCompleteSlip) {
    const double complete = -0.5823613 * beta_al_st;
    double previous = 0.0, previous_ratio = 0.0;
    for (double f : {0.04, 0.02, 0.01, 0.005, 0.0025}) {
        const tangential_solution s = product(f, 0.0);
        EXPECT_TRUE(s.checks.hold()) << f;
        std::printf("f = %.5f: stick [%.6f, %.6f], [%.6f, %.6f], xi %.9f, xi - complete slip %.3e\n", f, s.start(), s.c0(),
                    s.start2(), s.end2(), s.xi, s.xi - complete);
        EXPECT_GT(s.xi, complete);
        if (previous != 0.0) {
            EXPECT_LT(s.xi, previous);
            const double ratio = (previous - complete) / (s.xi - complete);
            EXPECT_GT(ratio, std::max(1.7, previous_ratio)) << f;
            previous_ratio = ratio;
        }
        previous = s.xi;
    }
}

// 8(j) 4a, the other side: free rolling at f = 0.2 without a guess (the continuation in beta_D/f
// from 1.5) is the root the continuation in f reaches (TowardsNoSlip), and at f = 0.3 the zones
// beyond the main stick zone (1e-4 long) are below n = 32's resolution: the checks fail, and
// points refuse it.
TEST(DissimilarFiveZones, LargeFrictionByContinuationInBetaOverF) {
    const tangential_solution s = product(0.2, 0.0);
    std::printf("f = 0.2: stick [%.7f, %.7f], [%.7f, %.7f], xi %.9f\n", s.start(), s.c0(), s.start2(), s.end2(), s.xi);
    EXPECT_TRUE(s.checks.hold());
    EXPECT_NEAR(s.xi, -0.058692205, 1e-9);  // TowardsNoSlip's f = 0.2, continued in f
    EXPECT_NEAR(s.c0(), 0.977972, 1e-6);
    EXPECT_NEAR(s.start2(), 0.993672, 1e-6);
    EXPECT_FALSE(product(0.3, 0.0).checks.hold());
}

// 8(j) 4a, the braked side near free rolling (Q/f < 0 for beta_D > 0), f = 0.05: five zones continued
// from free rolling down in the load, the slip+ zone (c1, s2) closing; below Q/f = -0.0725 they are
// gone and the three zones slip-, stick [s1, c2], slip- hold (the merged stick zone). The grid route
// (no structure assumed) puts the transition in the same place: five runs at Q/f = -0.06, three at -0.09.
TEST(DissimilarFiveZones, BrakedSideHandsOverToThreeZones) {
    const double f = 0.05;
    contact c(roughness{}, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    dissimilar_zones d(tangential_of(c), kernel{}, beta_al_st);
    const auto near = d.five_zones(-0.02 * f);
    ASSERT_TRUE(near);
    EXPECT_TRUE(near->checks.hold());
    std::printf("Q/f = -0.02: stick [%.6f, %.6f], [%.6f, %.6f], xi %.9f\n", near->start(), near->c0(), near->start2(), near->end2(),
                near->xi);
    const auto last = d.five_zones(-0.0725 * f, near->layout.stick_ends());
    ASSERT_TRUE(last);
    EXPECT_TRUE(last->checks.hold());
    EXPECT_LT(last->start2() - last->c0(), 0.06);  // the slip+ zone closing
    // Three zones fail at -0.0725 (the traction reaches +f p inside: the slip+ zone) and hold at -0.075.
    EXPECT_FALSE(d.solve(-0.0725 * f).checks.hold());
    const tangential_solution three = d.solve(-0.075 * f);
    EXPECT_TRUE(three.checks.hold());
    EXPECT_FALSE(three.layout.opposite());
    std::printf("Q/f = -0.0725: five [%.6f, %.6f], [%.6f, %.6f] xi %.9f; -0.075: three [%.6f, %.6f] xi %.9f\n",
                last->start(), last->c0(), last->start2(), last->end2(), last->xi, three.start(), three.c0(), three.xi);
    // Continuity through the transition: the merged stick zone's ends are the outer ends of the five,
    // and the creep moves by the local slope times the step (slope from the five zones' -0.02 .. -0.0725).
    EXPECT_NEAR(three.start(), last->start(), 0.002);
    EXPECT_NEAR(three.c0(), last->end2(), 0.002);
    const double slope = (last->xi - near->xi) / (-0.0525 * f);
    EXPECT_LT(std::fabs(three.xi - last->xi), 2.0 * std::fabs(slope) * 0.0025 * f);
    const normal_solution hertz = hertz_solution(32, method::product);
    EXPECT_EQ(validation::solve_on_grid(hertz, kernel{}, f, -0.06 * f, 200, 0, beta_al_st).runs().size(), 5u);
    EXPECT_EQ(validation::solve_on_grid(hertz, kernel{}, f, -0.09 * f, 200, 0, beta_al_st).runs().size(), 3u);
}
