// SPDX-License-Identifier: GPL-3.0-or-later
// The zone solver (docs/formulation.md section 7) and the independent low-order route
// (test_zones_low_order.hpp: full traction on a uniform grid, Kalker's upwind slip, rolling
// to the steady state, no zones assumed). Where the paper's structure holds it returns
// the single zone; where the single zone fails its checks (K1* dominating K2* at the leading
// edge, G'(-1) < 0, near gross sliding) it finds slip - stick - slip, whose solution satisfies
// (3.3)-(3.4) to rounding, converges in n, solves the unreduced equations of 2(b)/2(d)
// (checked by adaptive quadrature, without G, the stretched kernel or the zone's variable),
// and gives a creep curve continuous and monotone up to gross sliding, xi(f) = -f min G.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <functional>
#include <random>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/zone_solver.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "test_zones_low_order.hpp"
#include "zone_scenes.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {
constexpr double f = 0.3;

using zone_scenes::tangential_dominates_a;
using zone_scenes::tangential_dominates_b;
roughness equal_kernels() {  // Fig. 2(a), T = 1
    roughness r;
    r.cylinder1.tangential = {1.0, 0.5};
    r.cylinder1.normal = {1.0, 0.5};
    return r;
}
roughness unequal_kernels() {  // data/unequal-kernels.toml
    roughness r;
    r.cylinder1.tangential = {1.0, 0.5};
    r.cylinder1.normal = {0.5, 1.0};
    r.cylinder2.tangential = {0.3, 2.0};
    r.cylinder2.normal = {0.8, 0.5};
    return r;
}

struct solved {
    contact c;
    zone_solver zones;
    solved(const roughness& r, int n) : c(r, f, solver_options{n, method::product}), zones(tangential_of(c).zone_operator()) {}
};

double integrate(const std::function<double(double)>& g, double lo, double hi, double pole = NAN) {
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(2000);
    gsl_function F;
    F.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
    F.params = const_cast<std::function<double(double)>*>(&g);
    double result = 0.0, error = 0.0;
    const int status = std::isnan(pole)
                           ? gsl_integration_qags(&F, lo, hi, 1e-13, 1e-12, 2000, w, &result, &error)
                           : gsl_integration_qawc(&F, lo, hi, pole, 1e-13, 1e-12, 2000, w, &result, &error);
    gsl_integration_workspace_free(w);
    EXPECT_TRUE(status == GSL_SUCCESS || status == GSL_EROUND) << gsl_strerror(status);
    return result;
}

// L1[p1](r) of 2(b) on the whole contact, by adaptive quadrature: the Cauchy principal value
// (QAWC) and the kernel split at its jump (QAGS), from the traction alone.
double unreduced_operator(solved& s, const tangential_solution& z, const kernel& k1, double r) {
    const auto p1 = [&](double eta) { return tangential_of(s.c).traction(z, eta); };
    double sum = M_1_PI * integrate(p1, -1.0, 1.0, r);
    const auto kernel_term = [&](double eta) { return p1(eta) * k1(eta - r); };
    sum += integrate(kernel_term, -1.0, r) + integrate(kernel_term, r, 1.0);
    return sum;
}
}  // namespace

// Where the paper's structure holds, the general search (forced) ends at start = -1 and returns
// the single zone's c0 and xi: the same system at the same n, so to rounding; the extrapolated
// values then agree too, since both levels agree.
TEST(Zones, PapersStructureForcedIsTheSingleZone) {
    for (const roughness& r : {equal_kernels(), unequal_kernels(), roughness{}}) {
        solved s(r, 48);
        for (double load : {0.1, 0.5, 0.9, 1.0 - 1e-6, 1.0 - 1e-9, -0.7}) {
            const tangential_solution single = s.c.point(load * f);
            const tangential_solution z = s.zones.solve(load * f, true);
            EXPECT_EQ(z.start(), -1.0) << load;
            EXPECT_FALSE(z.layout.general());
            EXPECT_NEAR(z.c0(), single.c0(), 1e-10) << load;  // c0 near -1: conditioned as 1/(1 + c0)
            EXPECT_NEAR(z.xi, single.xi, 1e-12 * std::fabs(single.xi)) << load;
            EXPECT_TRUE(z.checks.hold()) << load;
            ASSERT_EQ(z.layout.zones.size(), 2u);
            EXPECT_TRUE(z.layout.zones[0].stick);
            EXPECT_EQ(z.layout.zones[1].direction, load < 0 ? -1 : 1);
        }
    }
}

// Where the single zone fails (3.3) near r = -1, the answer is slip - stick - slip in the
// direction of Q and satisfies every condition; the single zone fails its checks (so the scene
// does exercise the general path).
TEST(Zones, SlipStickSlipSatisfiesComplementarity) {
    for (const roughness& r : {tangential_dominates_a(), tangential_dominates_b()}) {
        solved s(r, 48);
        for (double gap : {1e-4, 1e-9}) {
            const double Q = (1.0 - gap) * f;
            EXPECT_FALSE(tangential_of(s.c).solve(Q).checks.stick_holds) << gap;
            const tangential_solution z = s.zones.solve(Q);
            EXPECT_TRUE(z.layout.general()) << gap;
            ASSERT_EQ(z.layout.zones.size(), 3u);
            EXPECT_FALSE(z.layout.zones[0].stick);
            EXPECT_TRUE(z.layout.zones[1].stick);
            EXPECT_FALSE(z.layout.zones[2].stick);
            EXPECT_GT(z.start(), -1.0);
            EXPECT_LT(z.start(), z.c0());
            EXPECT_GE(z.checks.stick_margin, -tol::margin_floor) << gap;
            EXPECT_GE(z.checks.slip_margin, -tol::margin_floor) << gap;
            EXPECT_GE(z.checks.pressure_margin, 0.0);
        }
    }
}

// The solution solves the equations it was not built from: L1[p1] = xi on the stick zone and
// int p1 = Q, by adaptive quadrature of the full traction (no G, no stretched kernel, no zone
// variable); v from the same operator equals slip_velocity on both slip zones.
TEST(Zones, SolvesTheUnreducedEquations) {
    const roughness r = tangential_dominates_a();
    solved s(r, 96);
    const kernel k1 = kernel::tangential(r);
    const double Q = (1.0 - 1e-3) * f;
    const tangential_solution z = s.zones.solve(Q);
    ASSERT_TRUE(z.layout.general());
    const auto p1 = [&](double eta) { return tangential_of(s.c).traction(z, eta); };
    EXPECT_NEAR(integrate(p1, -1.0, z.start()) + integrate(p1, z.start(), z.c0()) + integrate(p1, z.c0(), 1.0), Q, 1e-9);
    for (double u : {0.1, 0.37, 0.5, 0.81}) {
        const double x = z.start() + u * (z.c0() - z.start());
        EXPECT_NEAR(unreduced_operator(s, z, k1, x), z.xi, 1e-8) << x;
    }
    for (double x : {-0.999, 0.5 * (-1.0 + z.start()), 0.0, 0.9}) {
        EXPECT_NEAR(z.xi - unreduced_operator(s, z, k1, x), tangential_of(s.c).slip_velocity(z, x), 1e-8) << x;
    }
}

// Order about 4 in n (the product-integration scheme's): differences fall by more than 8 per
// doubling in xi, start and c0.
TEST(Zones, ConvergesInN) {
    const double Q = (1.0 - 1e-6) * f;
    std::vector<tangential_solution> z;
    for (int n : {32, 64, 128}) {
        solved s(tangential_dominates_a(), n);
        z.push_back(s.zones.solve(Q));
    }
    const auto ratio = [&](auto get) { return std::fabs(get(z[0]) - get(z[1])) / std::fabs(get(z[1]) - get(z[2])); };
    EXPECT_GT(ratio([](const tangential_solution& s) { return s.xi; }), 8.0);
    EXPECT_GT(ratio([](const tangential_solution& s) { return s.start(); }), 8.0);
    EXPECT_GT(ratio([](const tangential_solution& s) { return s.c0(); }), 8.0);
    EXPECT_LT(std::fabs(z[1].xi - z[2].xi), 1e-8);
}

// Through the region where the single zone fails, the creep rises monotonically with Q and
// tends to the gross-sliding creep -f min G, whose stick point is where G is least; the zones
// shrink onto it. The mirror load gives the mirror answer.
TEST(Zones, CreepCurveContinuousUpToGrossSliding) {
    solved s(tangential_dominates_a(), 48);
    double previous = -1.0;
    tangential_solution last;
    for (double gap : {0.1, 1e-3, 1e-6, 1e-10}) {
        last = s.zones.solve((1.0 - gap) * f);
        EXPECT_GT(last.xi, previous) << gap;
        EXPECT_GE(last.checks.stick_margin, -tol::margin_floor) << gap;
        EXPECT_GE(last.checks.slip_margin, -tol::margin_floor) << gap;
        previous = last.xi;
    }
    const tangential_solution sliding = s.zones.solve(f);
    EXPECT_GT(sliding.xi, previous);
    EXPECT_LT(sliding.xi - previous, 1e-7);
    EXPECT_NEAR(sliding.start(), last.start(), 1e-4);
    EXPECT_GT(sliding.start(), -1.0);
    // xi(f) = -f min G: no sampled point lies lower.
    for (int i = 0; i <= 400; ++i)
        EXPECT_LE(-sliding.xi / f, tangential_of(s.c).G(-1.0 + i / 200.0) + tol::few_roundings);
    EXPECT_GE(sliding.checks.slip_margin, -tol::margin_floor);
    const tangential_solution mirror = s.zones.solve(-(1.0 - 1e-6) * f);
    const tangential_solution direct = s.zones.solve((1.0 - 1e-6) * f);
    EXPECT_EQ(mirror.start(), direct.start());
    EXPECT_EQ(mirror.xi, -direct.xi);
    EXPECT_EQ(mirror.layout.zones.front().direction, -1);
    EXPECT_NEAR(mirror.checks.slip_margin, direct.checks.slip_margin, 1e-14);
}

namespace {
// The grid route at N and 2N: the error of 2N is about their difference (order 1).
struct grid_pair {
    validation::grid_solution coarse, fine;
    double estimate() const { return std::fabs(fine.xi - coarse.xi); }
    double extrapolated() const { return 2.0 * fine.xi - coarse.xi; }  // Richardson, order 1
};
// The high-order xi lies within the grid route's error: the difference N, 2N (the error of 2N
// for an order exactly 1, with a margin of half for the order's approach to 1), and the
// route's Richardson value is several times closer still where the order is 1 already
// (`asymptotic`; not yet on a stick zone of 20-40 cells, where 1.2-1.5 is measured).
void expect_within_grid_error(const grid_pair& g, double xi, bool asymptotic = true) {
    EXPECT_LT(std::fabs(g.fine.xi - xi), 1.5 * g.estimate());
    if (asymptotic) {
        EXPECT_LT(std::fabs(g.extrapolated() - xi), 0.25 * g.estimate());
    }
}
grid_pair grid_route(const contact& c, const roughness& r, double Q, int N) {
    const kernel k1 = kernel::tangential(r);
    return {validation::solve_on_grid(c.normal(), k1, f, Q, N), validation::solve_on_grid(c.normal(), k1, f, Q, 2 * N)};
}
}  // namespace

// Smooth cylinders: the grid route converges to Carter at order 1, and its stick zone is the
// leading [-1, c0] to within a cell; its error is within its own estimate (the difference N, 2N).
TEST(ZonesGridRoute, CarterAtOrderOne) {
    solved s(roughness{}, 8);
    const double Q = 0.5 * f;
    const tangential_solution carter_point = s.c.point(Q);
    std::vector<double> error;
    for (int N : {50, 100, 200}) {
        const auto g = validation::solve_on_grid(s.c.normal(), kernel{}, f, Q, N);
        error.push_back(std::fabs(g.xi - carter_point.xi));
        const auto runs = g.runs();
        ASSERT_EQ(runs.size(), 2u) << N;
        EXPECT_EQ(runs[0].state, 0);
        EXPECT_EQ(runs[1].state, 1);
        EXPECT_NEAR(runs[0].to, carter_point.c0(), 2.0 / N + 1e-12) << N;
    }
    for (std::size_t i = 1; i < error.size(); ++i) {
        const double order = std::log2(error[i - 1] / error[i]);
        EXPECT_GT(order, 0.8);
        EXPECT_LT(order, 1.3);
    }
}

// Fig. 2(a), T = 1, and the data/ unequal-kernels scene: the grid route, which knows nothing of
// G, the stretched kernel or the single zone, finds the paper's structure and the high-order xi
// within its own error estimate.
TEST(ZonesGridRoute, AgreesWithTheSingleZone) {
    for (const roughness& r : {equal_kernels(), unequal_kernels()}) {
        solved s(r, 48);
        for (double load : {0.3, 0.7}) {
            const tangential_solution single = s.c.point(load * f);
            const grid_pair g = grid_route(s.c, r, load * f, 100);
            SCOPED_TRACE(load);
            expect_within_grid_error(g, single.xi);
            const auto runs = g.fine.runs();
            ASSERT_EQ(runs.size(), 2u) << load;
            EXPECT_NEAR(runs[0].to, single.c0(), 2.0 * g.fine.h) << load;
        }
    }
}

// Where the single zone fails: the grid route finds slip - stick - slip in the direction of Q by
// itself, with the zone ends of the general solver to within a cell and its creep within the
// route's error estimate.
TEST(ZonesGridRoute, FindsSlipStickSlip) {
    const roughness r = tangential_dominates_a();
    solved s(r, 48);
    const double Q = (1.0 - 1e-2) * f;
    ASSERT_FALSE(tangential_of(s.c).solve(Q).checks.stick_holds);
    const tangential_solution z = s.zones.solve(Q);
    ASSERT_TRUE(z.layout.general());
    const grid_pair g = grid_route(s.c, r, Q, 200);
    expect_within_grid_error(g, z.xi, false);
    EXPECT_LT(std::fabs(g.fine.xi - z.xi), std::fabs(g.coarse.xi - z.xi));
    const auto runs = g.fine.runs();
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_EQ(runs[0].state, 1);
    EXPECT_EQ(runs[1].state, 0);
    EXPECT_EQ(runs[2].state, 1);
    EXPECT_NEAR(runs[1].from, z.start(), 2.0 * g.fine.h);
    EXPECT_NEAR(runs[1].to, z.c0(), 2.0 * g.fine.h);
}

// Acceptance: Fig. 2's scenes and the data/ unequal-kernels scene, by the default method
// (extrapolated, n = 128): with zones = "general" every point agrees with the default
// (zones = "auto", here the single zone) to 1e-10 in P_H/P2, c0 and xi, up to Q/f = 1 - 1e-9.
TEST(Zones, ForcedGeneralAgreesWithExtrapolated) {
    std::vector<roughness> scenes;
    // Fig. 2(a): T = 0.5, 1 at A = 0.5 (T = 0 is Carter: exact at every level); Fig. 2(b): A = 0, 1 at T = 0.5.
    for (const roughness_term term :
         {roughness_term{0.5, 0.5}, roughness_term{1.0, 0.5}, roughness_term{0.5, 0.0}, roughness_term{0.5, 1.0}}) {
        roughness r;
        r.cylinder1.tangential = r.cylinder1.normal = term;
        scenes.push_back(r);
    }
    scenes.push_back(unequal_kernels());
    for (const roughness& r : scenes) {
        contact automatic(r, f, solver_options{});
        contact general(r, f, solver_options{0, method::extrapolated, zone_search::general});
        EXPECT_NEAR(general.normal().lambda, automatic.normal().lambda, 1e-10);
        for (double load : {0.3, 0.9, 1.0 - 1e-9}) {
            const tangential_solution a = automatic.point(load * f), g = general.point(load * f);
            EXPECT_FALSE(a.layout.general());
            EXPECT_EQ(g.start(), -1.0) << load;
            EXPECT_NEAR(g.c0(), a.c0(), 1e-10) << load;
            EXPECT_NEAR(g.xi, a.xi, 1e-10) << load;
        }
    }
}

// Through contact: zones = "auto" takes the general path where the single zone fails, on both
// levels of an extrapolation, and reports level n with the n/2 difference as its estimate;
// zones = "single" keeps the paper's zone and its failed checks.
TEST(Zones, ContactTakesTheGeneralPathWhereNeeded) {
    const roughness r = tangential_dominates_a();
    contact automatic(r, f, solver_options{64, method::extrapolated, zone_search::automatic});
    contact single(r, f, solver_options{64, method::extrapolated, zone_search::single});
    contact fine(r, f, solver_options{64, method::product, zone_search::automatic});
    const double Q = (1.0 - 1e-6) * f;
    const tangential_solution a = automatic.point(Q), s = single.point(Q), level = fine.point(Q);
    EXPECT_TRUE(a.layout.general());
    EXPECT_TRUE(a.checks.hold());
    EXPECT_FALSE(s.layout.general());
    EXPECT_FALSE(s.checks.hold());
    EXPECT_GT(a.start(), -1.0);
    // Not extrapolated: level n, with the difference from n/2 as its estimate, which bounds
    // the error against a finer solution (n = 128).
    EXPECT_NEAR(a.xi, level.xi, 1e-13);
    EXPECT_NEAR(a.start(), level.start(), 1e-11);
    contact reference(r, f, solver_options{128, method::product, zone_search::automatic});
    const tangential_solution ref = reference.point(Q);
    const auto e = automatic.estimate(a);
    ASSERT_TRUE(e.has_value());
    EXPECT_EQ(e->against.rfind("n/2 (general zone search", 0), 0u) << e->against;
    EXPECT_LT(std::fabs(a.xi - ref.xi), e->xi);
    EXPECT_LT(std::fabs(a.c0() - ref.c0()), e->c0);
    EXPECT_EQ(automatic.distribution(a).start(), a.start());
    EXPECT_EQ(a.layout.zones.size(), 3u);
    // Mode "single" at a load where the single zone holds is the automatic answer itself.
    EXPECT_EQ(single.point(0.5 * f).xi, automatic.point(0.5 * f).xi);
}

// A creep curve through the region where the single zone starts to fail (the second scene,
// from Q/f ~ 1 - 1e-3 on), by the default method with zones = "auto": every point satisfies
// (3.3)-(3.4), the path switches to the general search there, and the creep rises
// monotonically; across the switch (extrapolated on one side, level n on the other) it moves
// by no more than the points' own estimates allow.
TEST(Zones, DefaultCurveThroughTheSwitch) {
    contact c(tangential_dominates_b(), f, solver_options{64, method::extrapolated, zone_search::automatic});
    double previous = -1.0;
    bool seen_single = false, seen_general = false;
    for (double gap : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 1e-5, 1e-7, 1e-9}) {
        const tangential_solution s = c.point((1.0 - gap) * f);
        EXPECT_TRUE(s.checks.hold()) << gap;
        EXPECT_GT(s.xi, previous) << gap;
        previous = s.xi;
        (s.layout.general() ? seen_general : seen_single) = true;
        if (s.layout.general()) {
            EXPECT_GT(s.start(), -1.0);
        }
    }
    EXPECT_TRUE(seen_single);
    EXPECT_TRUE(seen_general);
}

// The [solver] key: zones = "auto" | "single" | "general"; anything else is an input error
// naming the key.
TEST(Zones, SceneKey) {
    const auto scene_with = [](const std::string& zones_line) {
        const std::string path = ::testing::TempDir() + "zones_scene.toml";
        std::ofstream(path) << "friction = 0.3\nQ = 0.1\n[solver]\n" << zones_line << "\n";
        return path;
    };
    EXPECT_EQ(read_scene(scene_with("zones = \"general\"")).solver.zones, zone_search::general);
    EXPECT_EQ(read_scene(scene_with("zones = \"single\"")).solver.zones, zone_search::single);
    EXPECT_EQ(read_scene(scene_with("zones = \"auto\"")).solver.zones, zone_search::automatic);
    EXPECT_EQ(read_scene(scene_with("")).solver.zones, zone_search::automatic);
    try {
        read_scene(scene_with("zones = \"several\""));
        ADD_FAILURE() << "an unknown zone search was accepted";
    } catch (const input_error& e) {
        EXPECT_NE(std::string(e.what()).find("solver.zones"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_scene(scene_with("zones = 3")), input_error);
    // The one-parameter limit has its own search now (docs/formulation.md 7(g)): accepted.
    EXPECT_NO_THROW(contact(roughness{}, f, solver_options{0, method::one_parameter, zone_search::general}));
}

// Many scenes: 40 random scenes with both cylinders rough and the tangential roughness about
// ten times the normal one (T log-uniform in [0.3, 6] tangential, [0.03, 0.6] normal, A in
// [0.3, 20]; a fixed Mersenne twister, mapped by hand so that every library draws the same).
// Wherever the single zone fails its checks at Q/f = 0.999 or 1 - 1e-9, the zone search's
// answer satisfies (3.3)-(3.4); and it fails only where G'(-1) < 0 (7(c)). n = 32 keeps it fast.
TEST(Zones, ScanOfScenes) {
    std::mt19937 engine(12);
    const auto uniform = [&engine] { return static_cast<double>(engine()) / 4294967296.0; };
    int failing = 0;
    for (int scene = 0; scene < 40; ++scene) {
        const auto T = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform()); };
        const auto A = [&] { return 0.3 * std::pow(20.0 / 0.3, uniform()); };
        roughness r;
        r.cylinder1.tangential = {T(0.3, 6.0), A()};
        r.cylinder1.normal = {T(0.03, 0.6), A()};
        r.cylinder2.tangential = {T(0.3, 6.0), A()};
        r.cylinder2.normal = {T(0.03, 0.6), A()};
        solved s(r, 32);
        const double slope = (tangential_of(s.c).G(-1.0 + 1e-7) - tangential_of(s.c).G(-1.0)) / 1e-7;
        for (double gap : {1e-3, 1e-9}) {
            const double Q = (1.0 - gap) * f;
            if (tangential_of(s.c).solve(Q).checks.hold()) continue;
            ++failing;
            EXPECT_LT(slope, 0.0) << scene;
            const tangential_solution z = s.zones.solve(Q);
            EXPECT_TRUE(z.layout.general()) << scene << " " << gap;
            EXPECT_GE(z.checks.stick_margin, -tol::margin_floor) << scene << " " << gap;
            EXPECT_GE(z.checks.slip_margin, -tol::margin_floor) << scene << " " << gap;
        }
    }
    EXPECT_GE(failing, 10);  // the scan does exercise the search (29 of the 80 points, measured)
}

// The output of a general-path point: JSON zones from -1 to 1 with their states and directions,
// stick_start, zone_path; the summary lists the zones; the curve CSV counts them.
TEST(Zones, Output) {
    contact c(tangential_dominates_a(), f, solver_options{48, method::product, zone_search::automatic});
    const tangential_solution s = c.point(-(1.0 - 1e-3) * f);  // the mirror: slip in direction -1
    ASSERT_TRUE(s.layout.general());
    const nlohmann::json j = to_json(point_report{"", c.normal(), s, 0.0, c.estimate(s), std::nullopt});
    ASSERT_EQ(j["zones"].size(), 3u);
    EXPECT_EQ(j["zones"][0]["from"], -1.0);
    EXPECT_EQ(j["zones"][0]["state"], "slip");
    EXPECT_EQ(j["zones"][0]["direction"], -1);
    EXPECT_EQ(j["zones"][1]["state"], "stick");
    EXPECT_EQ(j["zones"][1]["from"], s.start());
    EXPECT_EQ(j["zones"][1]["to"], s.c0());
    EXPECT_EQ(j["zones"][2]["to"], 1.0);
    EXPECT_EQ(j["stick_start"], s.start());
    EXPECT_EQ(j["zone_path"], "general");
    EXPECT_EQ(j["checks_hold"], true);
    std::ostringstream text;
    write_summary(text, point_report{"", c.normal(), s, 0.0, std::nullopt, std::nullopt});
    EXPECT_NE(text.str().find("slip- [-1, "), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("(general zone search)"), std::string::npos);
    std::ostringstream csv;
    write_curve_csv(csv, creep_curve(c, {0.5 * f, (1.0 - 1e-3) * f}));
    std::string header, first, second;
    std::istringstream lines(csv.str());
    std::getline(lines, header);
    std::getline(lines, first);
    std::getline(lines, second);
    EXPECT_NE(header.find(",zones,stick_start"), std::string::npos);
    EXPECT_NE(first.find(",2,-1"), std::string::npos) << first;
    EXPECT_NE(second.find(",3,-0.98"), std::string::npos) << second;
}

// The text's "method, n" line names the closed form that answered a point where no zone search did
// (issue 24, 7): gross sliding and full stick of the paper's problem, the no-slip solution of dissimilar
// rollers with the edge layers neglected (formulation 8(n)); a searched point keeps "method, n".
TEST(PointText, MethodLineNamesTheClosedForm) {
    const double f = 0.3;
    const auto method_line = [](contact& c, double Q) {
        const tangential_solution s = c.point(Q);
        std::ostringstream text;
        write_summary(text, point_report{"", c.normal(), s, 0.0, std::nullopt, std::nullopt});
        const std::string all = text.str();
        const std::size_t at = all.find("  method, n           ");
        EXPECT_NE(at, std::string::npos) << all;
        return at == std::string::npos ? all : all.substr(at + 22, all.find('\n', at) - at - 22);
    };
    contact paper(roughness{{{1.0, 0.5}, {0.5, 2.0}}, {}}, f, solver_options{64, method::product});
    EXPECT_EQ(method_line(paper, f), "closed form: gross sliding (docs/formulation.md 2(g), 8(g)); pressure product, n = 64");
    EXPECT_EQ(method_line(paper, -f), "closed form: gross sliding (docs/formulation.md 2(g), 8(g)); pressure product, n = 64");
    EXPECT_EQ(method_line(paper, 0.0), "closed form: full stick (c0 = 1, xi = 0); pressure product, n = 64");
    EXPECT_EQ(method_line(paper, 0.5 * f), "product, 64");
    // Aluminium on steel (beta_D = 0.1438) at f = 1: free rolling with its layers neglected; a searched
    // point of the same pair (f = 0.05, Q/f = -0.75, three zones) keeps the method.
    contact layers(roughness{}, 1.0, solver_options{64, method::product}, dissimilar{0.1438, coupling_level::johnson});
    EXPECT_EQ(method_line(layers, 0.0),
              "closed form: no slip with the edge layers neglected (docs/formulation.md 8(n)); pressure product, n = 64");
    contact braked(roughness{}, 0.05, solver_options{64, method::product}, dissimilar{0.1438, coupling_level::johnson});
    EXPECT_EQ(method_line(braked, -0.0375), "product, 64");
}
