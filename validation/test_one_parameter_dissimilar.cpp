// SPDX-License-Identifier: GPL-3.0-or-later
// The one-parameter limit for dissimilar rollers at Johnson's level (docs/formulation.md 8(s)): the
// stick equation H[q] + eps1 q' = xi + b p + f G with Dundurs' forcing b = sgn(Q) beta_D. Checked
// against routes that do not share its structure or its discretisation:
//   - beta_D -> 0: the paper's problem, bit for bit at 0 and linearly in beta_D near it;
//   - free rolling: p1 odd and Q = 0 exactly (8(s), the parity of H + eps1 d/dr);
//   - large eps (the brush model): the closed form of 8(s), distance O(1/eps);
//   - the grid route of 7(f) with the Winkler kernel and Dundurs' term (no structure assumed);
//   - the two-parameter model (method "product", Johnson's coupling) as A grows with 2T/A^2 fixed.
// And the refusals of the structures not built.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/level_ladder.hpp"
#include "roughroll/problems/one_parameter.hpp"
#include "roughroll/problems/zone_layout.hpp"
#include "test_zones_low_order.hpp"

using namespace roughroll;

namespace {
// 2T/A^2 = eps in both directions on cylinder 1, decay rate A (the one-parameter limit takes 2T/A^2 only).
roughness scaled(double A, double eps) {
    roughness r;
    r.cylinder1.normal = {0.5 * eps * A * A, A};
    r.cylinder1.tangential = {0.5 * eps * A * A, A};
    return r;
}

// Scene A: |beta_D| small against eps1 f, the paper's zone from r = -1 at every load (8(s)).
// Scene B: f = 0.05, the braked side has slip with Q at both edges around one stick zone; the driven side
// slips against Q at the leading edge (refused).
constexpr double eps = 0.2, beta = 0.1, f_a = 0.3, f_b = 0.05;

contact limit(double f, int n, double beta_d = beta, zone_search zones = zone_search::automatic) {
    return contact(scaled(1.0, eps), f, solver_options{n, method::one_parameter, zones}, dissimilar{beta_d});
}
}  // namespace

// beta_D = 0 is today's problem bit for bit; near it xi moves linearly (ratio 2 between beta_D and 2 beta_D).
TEST(OneParameterDissimilar, BetaToZeroIsThePaperProblem) {
    for (double ratio : {-0.5, 0.5, 0.9}) {
        SCOPED_TRACE("Q/f = " + std::to_string(ratio));
        contact paper(scaled(1.0, eps), f_a, solver_options{128, method::one_parameter});
        const tangential_solution p = paper.point(ratio * f_a);
        const tangential_solution zero = limit(f_a, 128, 0.0).point(ratio * f_a);
        EXPECT_EQ(zero.xi, p.xi);
        EXPECT_EQ(zero.c0(), p.c0());
        const tangential_solution small = limit(f_a, 128, 1e-6).point(ratio * f_a);
        const tangential_solution twice = limit(f_a, 128, 2e-6).point(ratio * f_a);
        const double step = small.xi - p.xi;
        EXPECT_LT(std::fabs(step), 1e-5);
        EXPECT_NEAR((twice.xi - p.xi) / step, 2.0, 1e-3);
        EXPECT_TRUE(small.checks.hold());
    }
}

// Free rolling: H + eps1 d/dr maps odd functions onto even ones and b p is even, so the whole contact sticks
// with p1 odd, and Q = 0 needs no search (8(s)).
TEST(OneParameterDissimilar, FreeRollingTractionIsOdd) {
    one_parameter_solver s(compliances{eps, eps}, f_a, 128, beta);
    const tangential_solution stick = s.solve_on_zone(-1.0, 1.0, beta);
    EXPECT_NEAR(stick.Q, 0.0, 1e-13);
    const tangential_solution point = s.solve(0.0);
    EXPECT_TRUE(point.checks.hold());
    for (double r : {0.1, 0.4, 0.8, 0.99})
        EXPECT_NEAR(s.traction(point, r), -s.traction(point, -r), 1e-12) << r;
    EXPECT_LT(s.traction(point, -0.5), 0.0);  // beta_D > 0: p1 against the motion at the leading side
}

// Large eps: eps1 q' = xi + b p + f G with p = (3/4)(1 - r^2), G = (3/2) eps1 r (section 6), q(-1) = q(c0) = 0:
// rho = (1 + c0)/2 from f rho^3 + (b/eps1) rho^3 (1 - rho) = f - |Q|, and
// xi = (3/2) f eps1 (1 - rho) - (1/2) b rho (3 - 2 rho) (8(s)). Measured relative distances in xi at eps = 10, 100:
// 0.13, 0.013 (Q/f = 0.5), 0.020, 0.0019 (-0.5), 5.2e-3, 5.5e-4 (0): O(1/eps).
TEST(OneParameterDissimilar, LargeComplianceIsTheBrush) {
    constexpr double f = 0.005;
    for (double ratio : {0.5, -0.5, 0.0}) {
        std::vector<double> distance;
        for (double e : {10.0, 100.0}) {
            const double sign = ratio < 0.0 ? -1.0 : 1.0, beta_d = f * e;  // b/eps1 = sgn(Q) f
            const double b_over_eps = sign * f, b = sign * beta_d, gap = f * (1.0 - std::fabs(ratio));
            double lo = 0.0, hi = 1.0;  // f rho^3 + (b/eps1) rho^3 (1 - rho) - (f - |Q|) rises on [0, 1] here
            for (int k = 0; k < 200; ++k) {
                const double rho = 0.5 * (lo + hi);
                (f * rho * rho * rho + b_over_eps * rho * rho * rho * (1.0 - rho) > gap ? hi : lo) = rho;
            }
            const double rho = 0.5 * (lo + hi);
            const double xi = sign * (1.5 * f * e * (1.0 - rho) - 0.5 * b * rho * (3.0 - 2.0 * rho));
            contact c(scaled(1.0, e), f, solver_options{128, method::one_parameter}, dissimilar{beta_d});
            const tangential_solution s = c.point(ratio * f);
            EXPECT_TRUE(s.checks.hold()) << e;
            EXPECT_NEAR(s.c0(), 2.0 * rho - 1.0, 0.1 / e) << e;  // measured 7.2e-3, 7.3e-4 at Q/f = -0.5
            distance.push_back(std::fabs(s.xi / xi - 1.0));
        }
        SCOPED_TRACE("Q/f = " + std::to_string(ratio));
        EXPECT_GT(distance[0] / distance[1], 5.0);
        EXPECT_LT(distance[1], 2e-2);
    }
}

// The grid route of 7(f) (cells, no structure, no end condition) with the Winkler kernel (A = 1e8,
// 2T/A^2 = eps1) and Dundurs' term on the same pressure finds the same zones (ends within two cells) and
// the creep within its own change from N = 100 to 200 (order 1 in scene A: xi = -0.117128, -0.117770,
// -0.118102, -0.118269 for N = 100..800 against -0.1184342 at n = 128; order 2 in scene B).
TEST(OneParameterDissimilar, AgreesWithTheGridRoute) {
    struct scene {
        double f, ratio;
        int n;
        std::vector<int> states;  // the grid's runs from r = -1 (0 stick, +-1 slip with that sign)
    };
    for (const scene& c : {scene{f_a, -0.5, 128, {0, -1}}, scene{f_a, 0.5, 128, {0, 1}},
                           scene{f_b, -0.5, 256, {-1, 0, -1}}}) {
        SCOPED_TRACE("f = " + std::to_string(c.f) + ", Q/f = " + std::to_string(c.ratio));
        contact lim = limit(c.f, c.n);
        const tangential_solution s = lim.point(c.ratio * c.f);
        EXPECT_TRUE(s.checks.hold());
        const kernel winkler(std::vector<exponential_term>{{0.5 * eps * 1e16, 1e8}});
        const validation::grid_solution coarse =
            validation::solve_on_grid(lim.normal(), winkler, c.f, c.ratio * c.f, 100, 0, beta);
        const validation::grid_solution fine =
            validation::solve_on_grid(lim.normal(), winkler, c.f, c.ratio * c.f, 200, 0, beta);
        const auto runs = fine.runs();
        ASSERT_EQ(runs.size(), c.states.size());
        for (std::size_t k = 0; k < runs.size(); ++k) EXPECT_EQ(runs[k].state, c.states[k]) << k;
        const std::size_t stick = c.states.size() == 2 ? 0 : 1;
        EXPECT_NEAR(runs[stick].from, s.start(), 2.0 * fine.h);
        EXPECT_NEAR(runs[stick].to, s.c0(), 2.0 * fine.h);
        EXPECT_LT(std::fabs(fine.xi - s.xi), 1.5 * std::fabs(fine.xi - coarse.xi))
            << fine.xi << " " << coarse.xi << " " << s.xi;
    }
}

// The two-parameter model at Johnson's level (method "product", its three zones of 8(g)) tends to the limit
// as A = 40, 80, 160 with 2T/A^2 = eps (scene B, braked: slip with Q at both edges). Measured distances in xi
// 1.13e-3, 6.37e-4, 3.42e-4 (local orders 0.83, 0.90), in c0 5.5e-3, 3.0e-3, 1.6e-3 (0.90, 0.93), in s 3.8e-3,
// 2.6e-3, 1.5e-3: O(1/A) as for beta_D = 0 (section 6), and Richardson's rule for 1/A from A = 80, 160 is 7, 11
// and 4 times closer than A = 160.
TEST(OneParameterDissimilar, TwoParameterTendsToTheLimit) {
    const tangential_solution lim = limit(f_b, 256).point(-0.5 * f_b);
    ASSERT_TRUE(lim.checks.hold());
    std::vector<tangential_solution> two;
    for (double A : {40.0, 80.0, 160.0}) {
        contact c(scaled(A, eps), f_b, solver_options{128, method::product}, dissimilar{beta});
        two.push_back(c.point(-0.5 * f_b));
        EXPECT_TRUE(two.back().checks.hold()) << A;
        EXPECT_GT(two.back().start(), -1.0) << A;
    }
    const auto check = [&](const char* what, auto get, double lowest_order, double closer) {
        SCOPED_TRACE(what);
        std::vector<double> d;
        for (const tangential_solution& t : two) d.push_back(std::fabs(get(t) - get(lim)));
        EXPECT_GT(d[0], d[1]);
        EXPECT_GT(std::log2(d[1] / d[2]), lowest_order);
        EXPECT_LT(std::log2(d[1] / d[2]), 1.3);
        const double richardson = 2.0 * get(two[2]) - get(two[1]);
        EXPECT_LT(closer * std::fabs(richardson - get(lim)), d[2]);
    };
    check("xi", [](const tangential_solution& t) { return t.xi; }, 0.75, 4.0);
    check("c0", [](const tangential_solution& t) { return t.c0(); }, 0.75, 4.0);
    check("s", [](const tangential_solution& t) { return t.start(); }, 0.6, 2.0);
}

// The paper's zone holds at every load of scene A, with the creep rising through the loads; gross sliding at |Q| = f.
TEST(OneParameterDissimilar, ChecksHoldOnSceneA) {
    contact c = limit(f_a, 128);
    double last = -INFINITY;
    for (double ratio : {-1.0, -0.99, -0.9, -0.5, -0.1, 0.0, 0.1, 0.5, 0.9, 0.99, 1.0}) {
        const tangential_solution s = c.point(ratio * f_a);
        EXPECT_TRUE(s.checks.hold()) << ratio;
        if (std::fabs(ratio) < 1.0) {
            EXPECT_EQ(s.start(), -1.0) << ratio;
        }
        EXPECT_GT(s.xi, last) << ratio;
        last = s.xi;
    }
}

// At |Q| = f the stick zone shrinks to the point r* where b p + f G is least (8(s), 7(d)); where r* lies inside the
// contact (braked: scene A r* = -0.99999, scene B -0.453) the point has slip on both sides, the general search's
// structure, and zone_path says "general" as at every braked load of scene B below f (it said "single", the paper's
// zone shrunk onto r = -1). The edge form (scene A driven, r* = -1) stays "single".
TEST(OneParameterDissimilar, GrossSlidingInsideTheContactIsTheGeneralStructure) {
    for (const double f : {f_a, f_b}) {
        SCOPED_TRACE("f = " + std::to_string(f));
        contact c = limit(f, 128);
        const tangential_solution s = c.point(-f);
        EXPECT_TRUE(s.checks.hold());
        EXPECT_GT(s.start(), -1.0);
        EXPECT_EQ(s.start(), s.c0());
        EXPECT_EQ(std::string(to_string(s.layout.route)), "general");
    }
    contact a = limit(f_a, 128);
    const tangential_solution edge = a.point(f_a);
    EXPECT_EQ(edge.start(), -1.0);
    EXPECT_EQ(std::string(to_string(edge.layout.route)), "single");
}

// What is not built is refused in one line that says what to change: slip against Q (scene B driven, free
// rolling), the entry's discretisation at n = 128 (n = 256 resolves it), full coupling.
TEST(OneParameterDissimilar, RefusesWhatItDoesNotBuild) {
    const auto refusal = [](double f, int n, double Q) {
        try {
            limit(f, n).point(Q);
        } catch (const resolution_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(refusal(f_b, 128, 0.5 * f_b).find("use method 'product'"), std::string::npos);
    EXPECT_NE(refusal(f_b, 128, 0.0).find("use method 'product'"), std::string::npos);
    EXPECT_NE(refusal(f_b, 128, -0.5 * f_b).find("set n = 256"), std::string::npos);
    EXPECT_THROW(contact(scaled(1.0, eps), f_a, solver_options{128, method::one_parameter},
                         dissimilar{beta, coupling_level::full}),
                 input_error);
    // eps2 = 0 < eps1: the creep at |Q| = f is unbounded with Dundurs' forcing too (G(-1) = -infinity), said as such
    // at both signs of Q (was "zone solver: G of (3.25) is not finite" for beta_d != 0).
    roughness no_normal_layer;
    no_normal_layer.cylinder1.tangential = {0.5 * eps, 1.0};
    contact layered(no_normal_layer, f_a, solver_options{128, method::one_parameter}, dissimilar{beta});
    EXPECT_THROW(layered.point(f_a), input_error);
    EXPECT_THROW(layered.point(-f_a), input_error);
}

// Without a tangential layer (eps1 = 0) the edges slip as for half-spaces (8(g)): the limit's stick zone from
// r = -1 held its discrete checks at n = 64 .. 256 (margins 1e-3 .. 1e-5, shrinking) while the product found
// a leading slip zone against Q; refused at once.
TEST(OneParameterDissimilar, RefusedWithoutATangentialLayer) {
    roughness normal_only;
    normal_only.cylinder1.normal = {0.5 * eps, 1.0};
    EXPECT_THROW(contact(normal_only, f_a, solver_options{128, method::one_parameter}, dissimilar{beta}), input_error);
    EXPECT_THROW(contact(roughness{}, f_a, solver_options{128, method::one_parameter}, dissimilar{beta}), input_error);
    EXPECT_NO_THROW(contact(roughness{}, f_a, solver_options{128, method::one_parameter}, dissimilar{0.0}));
}

// A structure the limit does not build is refused by the first rung that finds it, with its own line, not
// after the ladder climbed every n to 1000 (was 8 s at Q/f = 0.5 and minutes on aluminium on steel).
TEST(OneParameterDissimilar, LadderRefusesWhatItDoesNotBuildAtOnce) {
    int rungs = 0;
    level_ladder ladder(solver_options{0, method::one_parameter}, scaled(1.0, eps), [&](int n) {
        ++rungs;
        return std::make_unique<contact>(scaled(1.0, eps), f_b, solver_options{n, method::one_parameter},
                                         dissimilar{beta});
    });
    try {
        ladder.point(0.5 * f_b);
        ADD_FAILURE() << "answered";
    } catch (const beyond_method_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("use method 'product'"), std::string::npos) << what;
        EXPECT_EQ(what.find("no n up to"), std::string::npos) << what;
    }
    EXPECT_EQ(rungs, 1);
}
