// SPDX-License-Identifier: GPL-3.0-or-later
// Physical scenes (physical_scene.hpp): Hertz's and Carter's dimensional formulas for smooth
// rollers, the half-width found for a given load carrying exactly that load, the paper's
// convention (a = a_H) reproducing the dimensionless problem, and the units scaling out.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "roughroll/problems/contact_width.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/model/physical_scene.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/problems/level_ladder.hpp"
#include "roughroll/problems/load_ratio.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {
constexpr double pi = 3.14159265358979323846;

// Steel rollers, R1 = R2 = 20 mm, 100 N/mm, Q = 0.15, f = 0.3; `rough` appended as written.
scene steel(const std::string& rough, const std::string& extra = "") {
    return parse_scene(
        "E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 1e5\nP1 = 1.5e4\nfriction = 0.3\n" + extra + "\n" + rough,
        "test");
}

const std::string rough_k_t = "[cylinder1.tangential]\nk = 4e14\nt = 1.5e6\n[cylinder1.normal]\nk = 8e14\nt = 1.5e6\n";

double lambda_of(const roughness& r, const scene& s) { return contact(r, s.friction, s.solver).normal().lambda; }

contact_width width_of(const scene& s) {
    return find_width(*s.physical, [&s](const roughness& r) { return lambda_of(r, s); });
}

struct solved {
    contact_width width;
    si_point si;
    tangential_solution point;
};

solved solve(const scene& s) {
    const contact_width w = width_of(s);
    contact c(roughness_at(*s.physical, w.a), s.friction, s.solver);
    const tangential_solution p = c.point(*s.Q);
    return {w, to_si(*s.physical, w, p.Q, p.f, p.c0(), p.xi), p};
}
}  // namespace

// Johnson, Contact Mechanics (4.43) for identical materials, b^2 = 8 P R (1 - nu^2)/(pi E), and
// Carter's creep ratio xi1 = (f a / R)(1 - sqrt(1 - Q/f)): written here from those forms, not (3.27).
TEST(GivenLoad, SmoothRollersAreHertzAndCarter) {
    const scene s = steel("");
    ASSERT_TRUE(s.physical);
    const solved r = solve(s);
    const double R = 0.01, E = 210e9, nu = 0.3, P = 1e5, f = 0.3, Q = 0.15;
    const double b = std::sqrt(8.0 * P * R * (1.0 - nu * nu) / (pi * E));
    EXPECT_NEAR(r.width.a, b, tol::few_roundings * b);
    EXPECT_EQ(r.width.iterations, 0);  // smooth: no search, no kernel
    EXPECT_NEAR(r.si.xi1, f * b / R * (1.0 - std::sqrt(1.0 - Q / f)), 1e-14);
    EXPECT_NEAR(r.si.xi1, r.si.xi1_carter, tol::few_roundings);
    EXPECT_NEAR(r.si.c, b * (2.0 * std::sqrt(1.0 - Q / f) - 1.0), tol::few_roundings);
    EXPECT_NEAR(r.si.P1, 1.5e4, 1e-9);
}

// The root of lambda(a) = (a/a_H)^2: at the width found, a contact solved independently
// carries P2, i.e. P_H(a)/lambda(a) = P2 with P_H(a) the Hertz load of width a.
TEST(GivenLoad, TheWidthFoundCarriesTheLoad) {
    for (const char* how : {"extrapolated", "product", "paper"}) {
        const scene s = steel(rough_k_t, "");
        scene t = s;
        t.solver.how = method_from_string(how);
        const contact_width w = width_of(t);
        EXPECT_GT(w.a, w.a_hertz) << how;  // roughness adds compliance (E2): a wider contact
        EXPECT_GT(w.iterations, 0) << how;
        const double lambda = lambda_of(roughness_at(*t.physical, w.a), t);
        const physical_scene& p = *t.physical;
        const double P_H = pi * p.shear_modulus() * w.a * w.a / (4.0 * (1.0 - p.nu) * p.radius());
        EXPECT_NEAR(P_H / lambda, p.P2, 1e-9 * p.P2) << how;
        EXPECT_NEAR(w.lambda, lambda, 1e-9 * lambda) << how;
    }
}

// With contact_width = "hertz" and T, A written in the scene, the model is the paper's
// dimensionless problem at those T, A: the same lambda, c0 and xi; the load carried is P2/lambda.
TEST(GivenLoad, HertzWidthIsThePapersProblem) {
    const std::string TA = "[cylinder1.tangential]\nT = 0.5\nA = 0.5\n[cylinder1.normal]\nT = 0.5\nA = 0.5\n";
    const scene paper = parse_scene("friction = 0.3\nQ = 0.15\n" + TA, "paper");
    const scene phys = parse_scene(
        "E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.05\nP2 = 3e5\nQ = 0.15\nfriction = 0.3\ncontact_width = \"hertz\"\n" +
            TA,
        "physical");
    const roughness r = roughness_at(*phys.physical, hertz_half_width(*phys.physical, 3e5));
    EXPECT_NEAR(r.cylinder1.normal.T, 0.5, tol::few_roundings);
    EXPECT_NEAR(r.cylinder1.normal.A, 0.5, tol::few_roundings);
    EXPECT_NEAR(r.cylinder1.tangential.T, 0.5, tol::few_roundings);
    EXPECT_EQ(r.cylinder2.normal.T, 0.0);

    contact a(paper.surfaces, 0.3, paper.solver);
    const tangential_solution pa = a.point(0.15);
    const solved ph = solve(phys);
    EXPECT_NEAR(ph.width.lambda, a.normal().lambda, tol::two_routes);
    EXPECT_NEAR(ph.point.c0(), pa.c0(), tol::two_routes);
    EXPECT_NEAR(ph.point.xi, pa.xi, tol::two_routes);
    EXPECT_NEAR(ph.width.load, 3e5 / a.normal().lambda, 1e-6);
    EXPECT_EQ(ph.width.a, ph.width.a_hertz);
}

// Every stress (E, P2/length, P1/length, k length, t/length) times 7: T, A and a_H are
// unchanged, so are a, c and xi1; the tractions scale by 7.
TEST(GivenLoad, StressUnitsScaleOut) {
    const solved one = solve(steel(rough_k_t));
    const scene s7 = parse_scene(
        "E = 1470e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 7e5\nP1 = 1.05e5\nfriction = 0.3\n"
        "[cylinder1.tangential]\nk = 28e14\nt = 10.5e6\n[cylinder1.normal]\nk = 56e14\nt = 10.5e6\n",
        "x7");
    const solved seven = solve(s7);
    EXPECT_NEAR(seven.width.a, one.width.a, 1e-11 * one.width.a);
    EXPECT_NEAR(seven.si.c, one.si.c, 1e-11 * one.width.a);
    EXPECT_NEAR(seven.si.xi1, one.si.xi1, 1e-10 * one.si.xi1);
    EXPECT_NEAR(seven.si.p_scale, 7.0 * one.si.p_scale, 1e-10 * seven.si.p_scale);
}

// A softer layer (k and t halved) widens the contact and raises the creep; both stay above
// the smooth rollers' (Sec. 4: "the creep between rough rollers is higher").
TEST(GivenLoad, SofterRoughnessWidensTheContactAndRaisesTheCreep) {
    const solved smooth_rollers = solve(steel(""));
    const solved stiff = solve(steel(rough_k_t));
    const solved soft =
        solve(steel("[cylinder1.tangential]\nk = 2e14\nt = 0.75e6\n[cylinder1.normal]\nk = 4e14\nt = 0.75e6\n"));
    EXPECT_GT(stiff.width.a, smooth_rollers.width.a);
    EXPECT_GT(soft.width.a, stiff.width.a);
    EXPECT_GT(stiff.si.xi1, smooth_rollers.si.xi1);
    EXPECT_GT(soft.si.xi1, stiff.si.xi1);
    EXPECT_TRUE(soft.point.checks.hold());
}

// A roller on a plane (R2 = inf) is Hertz's with R = R1.
TEST(GivenLoad, RollerOnAPlane) {
    const scene s =
        parse_scene("E = 210e9\nnu = 0.3\nR1 = 0.01\nR2 = inf\nP2 = 1e5\nQ = 0.1\nfriction = 0.3\n", "plane");
    EXPECT_EQ(s.physical->radius(), 0.01);
    const double b = std::sqrt(8.0 * 1e5 * 0.01 * (1.0 - 0.09) / (pi * 210e9));
    EXPECT_NEAR(width_of(s).a, b, tol::few_roundings * b);
}

// An independent limit: a very soft normal layer is a Winkler foundation, p = k (delta - x^2/(2R)),
// which carries P2 = 2 k a^3/(3 R) on the half-width a = (3 R P2 / (2 k))^(1/3). The one-parameter
// model's width tends to it as k falls (the half-spaces' share of the compliance vanishes).
TEST(GivenLoad, SoftLayerTendsToWinkler) {
    double previous = 1.0;
    for (const char* k : {"1e13", "1e12"}) {
        // 10 N/mm, so that a stays below R/10 (find_width refuses wider contacts).
        const scene s = parse_scene(std::string("E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 1e4\nQ = 0.1\n"
                                                "friction = 0.3\n[cylinder1.normal]\nk = ") +
                                        k + "\nt = 1\n[solver]\nmethod = \"one-parameter\"\n",
                                    "winkler");
        const double winkler = std::cbrt(3.0 * 0.01 * 1e4 / (2.0 * std::stod(k)));
        const double gap = std::fabs(width_of(s).a / winkler - 1.0);
        EXPECT_LT(gap, 0.5 * previous) << "k = " << k;
        previous = gap;
    }
    EXPECT_LT(previous, 5e-3);
}

// The bracket starts at a = sqrt(lambda(a_H)) a_H, near the root: the paper's scheme at n = 200
// resolves A up to about 32, the root's A = 30.04, while a bracket grown by 1.25 would try 37.5.
TEST(GivenLoad, BracketStaysWithinTheResolution) {
    const scene s = steel("[cylinder1.normal]\nT = 0.5\nA = 30\n[solver]\nmethod = \"paper\"\nn = 200\n");
    const contact_width w = width_of(s);
    EXPECT_GT(w.a, w.a_hertz);
    EXPECT_NEAR(lambda_of(roughness_at(*s.physical, w.a), s), w.lambda, 1e-9 * w.lambda);
}

TEST(GivenLoad, SharedNormalProblemsGiveTheSamePoint) {
    // The width search's normal problems (normal_cache: the set-up per n and the solutions) serve
    // its trials and the contact at the width found; the width, the point and its estimate are
    // those of the same search and contact without the cache, to the last bit, for each method.
    for (const char* how : {"product", "extrapolated"}) {
        scene s = steel(rough_k_t, std::string("[solver]\nmethod = \"") + how + "\"\n");
        auto search = [&s](normal_cache* cache) {
            return find_width(
                *s.physical, [&](const roughness& r) { return load_ratio(r, s.solver, cache); },
                [&](const roughness& r) { return coarse_load_ratio(r, s.solver, cache); });
        };
        normal_cache cache;
        const contact_width shared = search(&cache), alone = search(nullptr);
        ASSERT_EQ(shared.a, alone.a) << how;
        contact with(roughness_at(*s.physical, shared.a), s.friction, s.solver, {}, &cache);
        contact without(roughness_at(*s.physical, alone.a), s.friction, s.solver);
        const tangential_solution p = with.point(*s.Q), q = without.point(*s.Q);
        EXPECT_EQ(with.normal().lambda, without.normal().lambda) << how;
        EXPECT_EQ(p.c0(), q.c0()) << how;
        EXPECT_EQ(p.xi, q.xi) << how;
        EXPECT_EQ(with.estimate(p)->xi, without.estimate(q)->xi) << how;
    }
}

// The width's error in the estimate (docs/formulation.md 2(j) "The width's error"; session 26 audit F4): the rough
// aluminium-on-steel pair by the one-parameter method at n = 256, whose levels are all solved at n = 256's width. The
// reference is the same point at n = 1000 (`roughroll point data/aluminium-on-steel-rough.toml --method one-parameter
// --n 1000 [--Q-over-f -0.3]`, each at its own width; n = 768 agrees to 4e-8, the order-2 limit from 768 and 1000 is
// 6e-8 from it, both far inside the margins below). Without the width's term c0's estimate is 1.84e-7 against the
// distance 8.33e-7 (ratio 0.22), 1.35e-7 against 2.59e-7 at Q/f = -0.3 (0.52); with it 3.2 and above.
TEST(GivenLoad, EstimateCarriesTheWidthsError) {
    const struct {
        double Q_over_f, c0_at_1000;
    } points[] = {{-0.75, 0.4769279607893175}, {-0.3, 0.8590238763869142}};
    for (const auto& at : points) {
        scene s = read_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel-rough.toml");
        override_solver(s, 256, std::string("one-parameter"));
        const scene_point p = solve_point(s, load_given(load_kind::Q_over_f, at.Q_over_f));
        ASSERT_TRUE(p.estimate) << at.Q_over_f;
        EXPECT_GE(p.estimate->c0, std::fabs(p.solution.c0() - at.c0_at_1000)) << at.Q_over_f;
    }
}

// The width's error on a curve swept in c0 (session 26 review R17; docs/formulation.md 2(j) "The width's error"): each
// row's Q(c0) and xi(c0) are solved at level n's width, which carries lambda_n's error; the row is moved at its c0 (the
// input, exact). data/steel-rollers.toml by the one-parameter method, `roughroll curve --sweep --points 7 --method
// one-parameter --n N`, against the same rows at `--n 1000` (each at its own width; stored below). Without the width's
// term Q's least ratio of estimate to distance was 0.47, 0.94, 0.89, 0.89 at n = 32, 64, 128, 256 (c0 = 2/3: 1.45e-6
// against 3.08e-6 at n = 32); with it 2.41, 2.85, 2.98, 3.17.
TEST(GivenLoad, SweptRowsCarryTheWidthsError) {
    const double c0_at[] = {2.0 / 3.0, 1.0 / 3.0, 0.0, -1.0 / 3.0, -2.0 / 3.0, -1.0};
    const double Q_at_1000[] = {0.11909477921258055, 0.2000052301447185, 0.2531296847559555, 0.2839552792043436,
                                0.29749731678391433, 0.3};
    const double xi_at_1000[] = {0.10724378061764638, 0.20846841932601626, 0.3098838258466356,
                                 0.4154855526825807,  0.5317971640978141,  0.6889048441664071};
    for (const int n : {32, 64, 128, 256}) {
        scene s = read_scene(std::string(ROUGHROLL_DATA) + "/steel-rollers.toml");
        override_solver(s, n, std::string("one-parameter"));
        const scene_curve curve = curve_of(s, std::nullopt, 7, true);
        ASSERT_EQ(curve.rows.size(), 7u);
        for (int i = 0; i < 6; ++i) {
            const curve_point& row = curve.rows[i + 1];  // row 0: full stick, Q = 0 exactly
            SCOPED_TRACE("n = " + std::to_string(n) + ", c0 = " + std::to_string(c0_at[i]));
            ASSERT_TRUE(row.estimate);
            ASSERT_NEAR(row.solution.c0(), c0_at[i], 1e-15);
            EXPECT_GE(row.estimate->Q, std::fabs(row.solution.Q - Q_at_1000[i]));
            EXPECT_GE(row.estimate->xi, std::fabs(row.solution.xi - xi_at_1000[i]));
        }
    }
}

// The coupled width on a ladder (docs/formulation.md 2(j) "The coupled width on a ladder"; session 27 audit A1): the
// rough pair at full coupling, braked at Q/f = -0.5, climbs to n = 512, each rung settling its own width. A rung above the
// first starts its width search from the rung below's coupling (the coupled P_H/P2 less Johnson's), within the coupling's
// level change of the root: fewer width iterations than the same search at that n alone (a given n, no rung below; before
// session 29 every rung searched so, the same count: 9 and 9). Both polish to the same step rule (1e-12 in the width), so
// the two answers are within the sum of their estimates (the width within the bounds the SI values take from P_H/P2's
// estimates, E/(2x) of a_H), and each width's coupled point carries its P_H/P2 = x^2 as before (RollersExchangedKeepTheWidth).
TEST(GivenLoad, CoupledWidthOnALadderStartsFromTheRungBelow) {
    scene s = read_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel-rough.toml");
    s.materials.coupling = coupling_level::full;
    const load_given load(load_kind::Q_over_f, -0.5);
    const scene_point climbed = solve_point(s, load);
    const int n = climbed.settled.solver.nodes();
    ASSERT_GT(n, ladder_rungs(s.solver.how).front());  // a rung above the first answers
    scene given = s;
    override_solver(given, n, std::nullopt);
    const scene_point alone = solve_point(given, load);
    ASSERT_TRUE(climbed.width && alone.width && climbed.estimate && alone.estimate);
    EXPECT_LT(climbed.width->iterations, alone.width->iterations);
    // The step rule, not a residual: lambda_n(x) = x^2 to the polish's 1e-12 in x (|F'| ~ 2.4), at the top rung as alone.
    for (const scene_point* p : {&climbed, &alone}) {
        const double x = p->width->a / p->width->a_hertz;
        EXPECT_NEAR(p->solved.normal().lambda, x * x, 1e-11) << p->settled.solver.nodes();
    }
    const error_estimate &e = *climbed.estimate, &f = *alone.estimate;
    const auto a_bound = [](const scene_point& p) {
        return p.width->a_hertz * p.estimate->lambda / (2.0 * p.width->a / p.width->a_hertz);
    };
    EXPECT_LE(std::fabs(climbed.width->a - alone.width->a), a_bound(climbed) + a_bound(alone));
    EXPECT_LE(std::fabs(climbed.solved.normal().lambda - alone.solved.normal().lambda), e.lambda + f.lambda);
    EXPECT_LE(std::fabs(climbed.solution.c0() - alone.solution.c0()), e.c0 + f.c0);
    EXPECT_LE(std::fabs(climbed.solution.start() - alone.solution.start()), e.start + f.start);
    EXPECT_LE(std::fabs(climbed.solution.xi - alone.solution.xi), e.xi + f.xi);
}
