// SPDX-License-Identifier: GPL-3.0-or-later
// Free rolling (Q = 0) of Bentall and Johnson's pair (data/aluminium-on-steel.toml, Johnson's level) at
// every friction from complete slip to no slip (issue 24, 7; docs/formulation.md 8(f), 8(j) 4a, 8(n)):
// `roughroll point --json` answered with its checks holding at f = 1e-6 .. 1e6, the creep between the
// two limits within its estimate; the complete-slip limit approached at the measured rate; the no-slip
// limit -4 beta_D/pi^2 within the estimate at f = 1e3 and 1e6, its closed form checked by an
// independent quadrature of the stick equation; the two routes (five zones, the edge layers
// neglected) agreeing within their estimates where both answer; the layers' route answering the
// f ~ 0.31 .. 0.486 between them with the main stick zone's ends and the creep to first order in the
// layers' thickness, against the program's five zones at f = 0.31 and the five zones continued in f (8(n),
// "The layers' positions"); its traction against its zones; both layers' inner problems solved with GSL.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_multiroots.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "aluminium_on_steel.hpp"
#include "command_output.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/level_ladder.hpp"

namespace {
struct run_result {
    int status;
    std::string text;
    nlohmann::json out;
};

run_result run_point(double f, const std::string& options = "", bool json = true) {
    char friction[32];
    std::snprintf(friction, sizeof friction, "%.17g", f);
    const std::string command = std::string(ROUGHROLL_CLI) + " point " + ROUGHROLL_DATA +
                                "/aluminium-on-steel.toml --Q 0 --friction " + friction + " " + options +
                                (json ? " --json" : "") + " 2>&1";
    const command_output o = run_command(command);
    run_result r{o.status, o.text, {}};
    if (json && o.status == 0) r.out = nlohmann::json::parse(o.text);
    return r;
}

double no_slip_limit() { return -4.0 * beta_al_st / (M_PI * M_PI); }

// The crossing t_c of 8(n), written out: 1 + r = 2/(1 + exp(pi f/beta_D)).
double crossing_of(double f) { return 2.0 / (1.0 + std::exp(M_PI * f / beta_al_st)); }
// The layers' positions and the creep to first order in t_c (8(n), "The layers' positions"): the leading
// layer (4/e^2) t_c, the creep's shift -(2 beta_D/pi^2)(4/e^2) t_c (Phi at its maximum).
double leading_of(double f) { return 4.0 / (M_E * M_E) * crossing_of(f); }
double first_order_creep(double f) { return no_slip_limit() - 2.0 * beta_al_st / (M_PI * M_PI) * leading_of(f); }

// The rows of `roughroll traction` for free rolling at f (its CSV, each cell as written), and its comment lines.
struct traction_csv {
    int status = 0;
    std::string text;                               // the command's output, for a failure's message
    std::vector<std::string> comments;              // the lines starting with '#'
    std::vector<std::vector<std::string>> rows;     // the cells of each row
    std::vector<std::string> header;
    const std::string& at(std::size_t row, const char* name) const {
        return rows.at(row).at(static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin()));
    }
    double number(std::size_t row, const char* name) const { return std::stod(at(row, name)); }
};

traction_csv run_traction(double f, const std::string& options, int points) {
    char folder[] = "/tmp/roughroll-layers-traction-XXXXXX";
    traction_csv t;
    if (mkdtemp(folder) == nullptr) {
        t.status = -1;
        t.text = "mkdtemp failed";
        return t;
    }
    const std::string out = folder;
    char friction[32];
    std::snprintf(friction, sizeof friction, "%.17g", f);
    const command_output o = run_command(std::string(ROUGHROLL_CLI) + " traction " + ROUGHROLL_DATA +
                                         "/aluminium-on-steel.toml --Q 0 --friction " + friction + " " + options +
                                         " --points " + std::to_string(points) +
                                         " --no-plot --quiet --name layers --out " + out + " 2>&1");
    t.status = o.status;
    t.text = o.text;
    std::ifstream csv(out + "/traction-layers.csv");
    for (std::string line; std::getline(csv, line);) {
        if (line.empty()) continue;
        if (line[0] == '#') {
            t.comments.push_back(line);
            continue;
        }
        std::vector<std::string> cells;
        std::stringstream cells_of(line);
        for (std::string cell; std::getline(cells_of, cell, ',');) cells.push_back(cell);
        (t.header.empty() ? t.header : t.rows.emplace_back()) = cells;
    }
    csv.close();
    for (const char* file : {"/traction-layers.csv", "/traction-layers.gp"}) std::remove((out + file).c_str());
    rmdir(folder);
    return t;
}
}  // namespace

// Every friction of the issue (f = 1e-6 and 0.5: below), the ladder at its default tolerance.
TEST(FreeRollingEveryF, AnsweredFromCompleteSlipToNoSlip) {
    const double xi0 = complete_slip_limit(), xi_inf = no_slip_limit();
    double previous = -HUGE_VAL;
    for (const double f : {1e-4, 0.05, 0.2, 1.0, 10.0, 1e3, 1e6}) {  // 1e-6: TowardsCompleteSlip
        const run_result r = run_point(f);
        ASSERT_EQ(r.status, 0) << "f = " << f << ": " << r.text;
        const nlohmann::json& j = r.out;
        const double xi = j["xi"].get<double>();
        ASSERT_TRUE(j["error_estimate"].is_object()) << "f = " << f;
        const double e = j["error_estimate"]["xi"].get<double>();
        std::printf("f = %g: n = %d, xi = %.15f +- %.3g, zones %zu%s\n", f, j["n"].get<int>(), xi, e,
                    j["zones"].size(), j.contains("edge_layers") ? ", edge layers neglected" : "");
        EXPECT_TRUE(j["checks_hold"].get<bool>()) << "f = " << f;
        EXPECT_EQ(j["Q"].get<double>(), 0.0);
        // Between the limits of 8(f), and rising with f (more stick, less slip against the rolling).
        EXPECT_GE(xi + e, xi0) << "f = " << f;
        EXPECT_LE(xi - e, xi_inf) << "f = " << f;
        EXPECT_GE(xi + e, previous) << "f = " << f;
        previous = xi;
        // The route: five zones up to f = 0.2, the edge layers neglected from f = 1 on (8(n)): at f = 1 the
        // main stick zone with the layers beside it (3.5e-10 and 5.8e-10 thick), from f = 10 on the layers
        // below an ulp of the edges (stick on [-1, 1]).
        EXPECT_EQ(j.contains("edge_layers"), f >= 1.0) << "f = " << f;
        EXPECT_EQ(j["zones"].size(), f < 1.0 ? 5u : f == 1.0 ? 3u : 1u) << "f = " << f;
    }
}

// f = 0.5, 0.55, 0.6 (issue 24, 7): answered at the default tolerance with the edge layers neglected,
// checks holding and every estimate below the tolerance (docs/formulation.md 8(n), the leading layer's
// bound B1: 1.1e-5, 3.7e-6, 1.2e-6 of xi; the zone ends within t = 7.2e-5, 2.4e-5, 8.1e-6 of the edges).
// Before, all three were refused (the pointwise bound B was 7.8e-4, 2.9e-4, 1.05e-4 of xi).
TEST(FreeRollingEveryF, HalfFrictionAnsweredWithTheLayersNeglected) {
    for (const double f : {0.5, 0.55, 0.6}) {
        const run_result r = run_point(f);
        ASSERT_EQ(r.status, 0) << "f = " << f << ": " << r.text;
        const nlohmann::json& j = r.out;
        EXPECT_TRUE(j["checks_hold"].get<bool>()) << f;
        EXPECT_TRUE(j.contains("edge_layers")) << f;
        const double xi = j["xi"].get<double>();
        EXPECT_NEAR(xi, first_order_creep(f), 4e-16 * std::fabs(xi)) << f;  // the closed form to first order
        const nlohmann::json& e = j["error_estimate"];
        EXPECT_LE(e["xi"].get<double>(), roughroll::default_tolerance * std::fabs(xi)) << f;
        EXPECT_LE(e["c0"].get<double>(), roughroll::default_tolerance) << f;  // relative to the half-width
        EXPECT_LE(e["stick_start"].get<double>(), roughroll::default_tolerance) << f;
    }
}

// f = 0.45 below the layers' route's estimates (its trailing end's bound 0.011 t_c = 1.19e-6 of the
// half-width): a tolerance of 5e-7 is refused at once, naming the tolerance that answers; that tolerance
// answers with the layers neglected. (Before the layers' positions, f = 0.45 was refused at the default
// tolerance, 1e-4, naming 0.00022: the ends were known only within t = 2 t_c of the edges.)
TEST(FreeRollingEveryF, RefusalSaysWhatToChange) {
    const run_result refused = run_point(0.45, "--tolerance 5e-7", false);
    EXPECT_NE(refused.status, 0);
    const std::string advice = "a tolerance of 1.2e-06 or more";
    EXPECT_NE(refused.text.find(advice), std::string::npos) << refused.text;
    EXPECT_NE(refused.text.find("--tolerance"), std::string::npos);
    EXPECT_NE(refused.text.find("zone ends"), std::string::npos) << refused.text;
    EXPECT_EQ(refused.text.find("::"), std::string::npos) << "no function name: " << refused.text;
    const run_result r = run_point(0.45, "--tolerance 1.2e-6");
    ASSERT_EQ(r.status, 0) << r.text;
    EXPECT_TRUE(r.out["checks_hold"].get<bool>());
    EXPECT_TRUE(r.out.contains("edge_layers"));
    EXPECT_NEAR(r.out["xi"].get<double>(), first_order_creep(0.45), 4e-16 * std::fabs(first_order_creep(0.45)));
}

// The gap between the routes (issue 24, 7): f = 0.39 to 0.47 were refused at the default settings (the
// five zones beyond every n, the layers' ends known only within t = 2 t_c). With the layers' positions
// (8(n)) the layers' route answers them at once, every estimate within the default tolerance, checks
// holding, the main stick zone between the layers (slip against beta_D before it, with it after). Their
// values against independent routes: the program's five zones at f = 0.31 (below) and the five zones
// continued in f up to 0.45 (LayersBoundAgainstTheFiveZonesContinued).
TEST(FreeRollingEveryF, GapAnsweredWithTheLayersPositions) {
    for (const double f : {0.39, 0.4, 0.425, 0.45, 0.47}) {
        const run_result r = run_point(f);
        ASSERT_EQ(r.status, 0) << "f = " << f << ": " << r.text;
        const nlohmann::json& j = r.out;
        EXPECT_TRUE(j["checks_hold"].get<bool>()) << f;
        EXPECT_EQ(j["zone_path"].get<std::string>(), "no-slip") << f;
        const double xi = j["xi"].get<double>();
        const nlohmann::json& e = j["error_estimate"];
        EXPECT_LE(e["xi"].get<double>(), roughroll::default_tolerance * std::fabs(xi)) << f;
        EXPECT_LE(e["c0"].get<double>(), roughroll::default_tolerance) << f;
        EXPECT_LE(e["stick_start"].get<double>(), roughroll::default_tolerance) << f;
        // The layers inside the crossing t_c (8(n)): where |p1| of no slip exceeds f p.
        const double tc = crossing_of(f);
        EXPECT_GT(j["stick_start"].get<double>(), -1.0) << f;
        EXPECT_LT(j["stick_start"].get<double>(), -1.0 + tc) << f;
        EXPECT_LT(j["c0"].get<double>(), 1.0) << f;
        EXPECT_GT(j["c0"].get<double>(), 1.0 - tc * (1.0 - 1e-9)) << f;
        ASSERT_EQ(j["zones"].size(), 3u) << f;
        EXPECT_EQ(j["zones"][0]["direction"].get<int>(), -1) << f;
        EXPECT_EQ(j["zones"][2]["direction"].get<int>(), 1) << f;
    }
}

// The bound against an independent route (docs/formulation.md 8(n)): the product's five zones at n = 500,
// continued in f by Newton from the previous f's ends (the physical root; the ladder's search is not
// used), resolve the layers up to f = 0.45 (t_c n^2 = 27) with their checks holding. Their distance
// from the no-slip creep lies within the sharper bound min(B, B1) at each f, and within a factor 1.6
// of it (measured 0.77 to 0.875: the bound is sharp), where the pointwise bound B was 27 to 72 times
// the distance. The layers' route's reported values (8(n), "The layers' positions") lie within their
// estimates of the continued root: the creep with its first-order shift (distances 1.8e-11 to 5e-8,
// 0.001 to 0.02 of the estimate), the trailing end 0.889 t_c (0.27 to 0.7 of its estimate 0.011 t_c),
// and the leading end (4/e^2) t_c within 0.25 t_c^2 where n = 500 resolves it (f <= 0.4: 0.4 to 0.5
// of the estimate; beyond, n = 500's own error exceeds it: the law is checked there at n = 720 in 8(n)). The five zones' own error is far below the distances (1.7e-6 to 4.5e-5): n = 500 and
// n = 1000, continued alike, agree in xi to 4e-14 up to f = 0.4 (measured; at 0.425 the continuation at
// n = 1000 lands on another root, its checks failing, 2e-11 from n = 500's xi). The program's answers at f = 0.35
// to 0.45 (the layers' route) lie within their estimates of the continued root (the stick start to f = 0.4).
TEST(FreeRollingEveryF, LayersBoundAgainstTheFiveZonesContinued) {
    using namespace roughroll;
    std::vector<double> ends;
    for (const double f : {0.2, 0.25, 0.3, 0.35, 0.375, 0.4, 0.425, 0.45}) {
        contact c(roughness{}, f, solver_options{500, method::product},
                  dissimilar{beta_al_st, coupling_level::johnson});
        dissimilar_zones d(tangential_of(c), kernel{}, beta_al_st);
        const auto s = ends.empty() ? d.five_zones(0.0) : d.five_zones(0.0, ends);
        ASSERT_TRUE(s) << f;
        ASSERT_TRUE(s->checks.hold()) << f;
        ends = s->layout.stick_ends();
        if (f < 0.3) continue;  // the continuation's start
        const neglected_layers layers = no_slip_layers(beta_al_st, f);
        const double distance = std::fabs(s->xi - no_slip_limit());
        const double reported = no_slip_limit() + layers.xi_shift;
        std::printf("f = %.3f: xi - no slip %.4g, bound %.4g (ratio %.3f), pointwise %.4g; layers %.4g %.4g (t %.4g); "
                    "reported xi %.3g off (estimate %.3g), ends %.3g (%.3g) %.3g (%.3g)\n",
                    f, s->xi - no_slip_limit(), layers.sharp, distance / layers.sharp, layers.pointwise, 1.0 + s->start(),
                    1.0 - s->c0(), layers.thickness, s->xi - reported, layers.xi_bound, 1.0 + s->start() - layers.leading,
                    layers.leading_bound, 1.0 - s->c0() - layers.trailing, layers.trailing_bound);
        EXPECT_LE(distance, layers.sharp) << f;
        EXPECT_GE(distance, layers.sharp / 1.6) << f;
        EXPECT_LT(1.0 + s->start(), layers.thickness) << f;  // the premise t = 2 t_c of 8(n)
        EXPECT_LT(1.0 - s->c0(), layers.thickness) << f;
        // The layers' route's values (8(n), "The layers' positions").
        EXPECT_NEAR(layers.xi_shift, first_order_creep(f) - no_slip_limit(), 4.0 * DBL_EPSILON * std::fabs(no_slip_limit())) << f;
        EXPECT_LE(std::fabs(s->xi - reported), layers.xi_bound) << f;
        EXPECT_LE(std::fabs(1.0 - s->c0() - layers.trailing), layers.trailing_bound) << f;
        if (f <= 0.4) {
            EXPECT_LE(std::fabs(1.0 + s->start() - layers.leading), layers.leading_bound) << f;
        }
        // The program's answer (the layers' route at the default tolerance from f = 0.306 on) within its
        // estimates of the continued five zones: the gap's values against an independent route.
        if (f < 0.35) continue;
        const run_result r = run_point(f);
        ASSERT_EQ(r.status, 0) << f << ": " << r.text;
        ASSERT_EQ(r.out["zone_path"].get<std::string>(), "no-slip") << f;
        const nlohmann::json& e = r.out["error_estimate"];
        EXPECT_LE(std::fabs(r.out["xi"].get<double>() - s->xi), e["xi"].get<double>()) << f;
        EXPECT_LE(std::fabs(r.out["c0"].get<double>() - s->c0()), e["c0"].get<double>()) << f;
        if (f <= 0.4) {
            EXPECT_LE(std::fabs(r.out["stick_start"].get<double>() - s->start()), e["stick_start"].get<double>()) << f;
        }
    }
}

// The other five zones of free rolling at large f (docs/formulation.md 8(n), "What limits the five zones"):
// at f = 0.43, n = 512, Newton from the coarser levels' ends (the program's explicit n) lands on a root whose
// reversed-slip zone has closed to 0.004 t_c (0.64 t_c on the physical root, continued in f) and whose main
// stick zone ends 0.67 t_c from the trailing edge (0.89 t_c). Its creep is the physical one's to 2e-11, its
// ends are not; what rejects it is (3.3) in the second stick zone, |p1| above f p by 1.9e-4 f across its
// middle (2 % of f p there), against margins held to 0 (measured: 0.95e-4 to 4e-4 f at f = 0.375 to 0.485,
// n = 384 to 1000, not falling with n).
// The program refuses that point, or answers within its estimate of the physical root (since the layers'
// positions of 8(n), by the layers' route, at an explicit n too).
TEST(FreeRollingEveryF, OtherFiveZonesFailTheStickCheck) {
    using namespace roughroll;
    const double f = 0.43;
    contact c(roughness{}, f, solver_options{512, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    dissimilar_zones d(tangential_of(c), kernel{}, beta_al_st);
    const double tc = no_slip_layers(beta_al_st, f).crossing;
    // Starts near each root (8 digits of the roots measured): Newton's roots, not these, are checked.
    const auto physical = d.five_zones(0.0, {-0.99990987, 0.99985233, 0.99995967, 0.99999555});
    const auto other = d.five_zones(0.0, {-0.99990987, 0.99988845, 0.99988912, 0.99999606});
    ASSERT_TRUE(physical && other);
    std::printf(
        "f = 0.43, n = 512: reversed slip %.4g tc (physical %.4g), trailing layer %.4g tc (%.4g), stick margin "
        "%.3g (%.3g), xi difference %.3g\n",
        (other->start2() - other->c0()) / tc, (physical->start2() - physical->c0()) / tc, (1.0 - other->c0()) / tc,
        (1.0 - physical->c0()) / tc, other->checks.stick_margin, physical->checks.stick_margin, other->xi - physical->xi);
    EXPECT_TRUE(physical->checks.hold());
    EXPECT_GT(physical->start2() - physical->c0(), 0.5 * tc);
    EXPECT_LT(other->start2() - other->c0(), 0.05 * tc);               // another root, not the physical one drifting
    EXPECT_GT(std::fabs(other->c0() - physical->c0()), 0.1 * tc);  // ends a fifth of the layer away
    EXPECT_LT(std::fabs(other->xi - physical->xi), 1e-10);     // the creep cannot tell them apart
    EXPECT_FALSE(other->checks.hold());
    EXPECT_LT(other->checks.stick_margin, -1e-4);  // far beyond any rounding: the check cannot miss it
    const double middle = 0.5 * (other->start2() + other->end2());
    EXPECT_LT(f * c.normal().pressure(middle) - std::fabs(d.traction(*other, middle)), -1e-4 * f);
    // Through the program: refused, or answered within its estimates of the physical root.
    const run_result r = run_point(f, "--n 512");
    if (r.status != 0) {
        EXPECT_NE(r.text.find("fail the checks"), std::string::npos) << r.text;
        return;
    }
    // Answered: by the layers' route (8(n): the closed form has no n), whose leading end (4/e^2) t_c is
    // sharper than n = 512's own (t_c n^2 = 42: the continued root's leading end is 1.5e-3 of the layer
    // off, 8(n) "What limits the five zones"), so the start is compared within that resolution too.
    const nlohmann::json& e = r.out["error_estimate"];
    EXPECT_TRUE(r.out["checks_hold"].get<bool>());
    EXPECT_LE(std::fabs(r.out["xi"].get<double>() - physical->xi), e["xi"].get<double>());
    EXPECT_LE(std::fabs(r.out["c0"].get<double>() - physical->c0()), e["c0"].get<double>());
    const double resolution = r.out["zone_path"].get<std::string>() == "no-slip" ? 3e-3 * (1.0 + physical->start()) : 0.0;
    EXPECT_LE(std::fabs(r.out["stick_start"].get<double>() - physical->start()), e["stick_start"].get<double>() + resolution);
}

// Complete slip (8(f)): the creep approaches -0.5823613 beta_D from above, its distance falling by 56
// from f = 1e-4 to 1e-5 and by 64 from 1e-5 to 1e-6 (measured; faster than f, slower than f^2).
TEST(FreeRollingEveryF, TowardsCompleteSlip) {
    const double xi0 = complete_slip_limit();
    const double d5 = run_point(1e-5).out["xi"].get<double>() - xi0;
    const run_result r6 = run_point(1e-6);
    const double d6 = r6.out["xi"].get<double>() - xi0;
    std::printf("distance from complete slip: %.4g (f = 1e-5), %.4g (f = 1e-6), ratio %.3g\n", d5, d6, d5 / d6);
    ASSERT_EQ(r6.status, 0) << r6.text;
    EXPECT_TRUE(r6.out["checks_hold"].get<bool>());
    EXPECT_EQ(r6.out["zones"].size(), 5u);
    EXPECT_GT(d6, 0.0);
    EXPECT_GT(d6, r6.out["error_estimate"]["xi"].get<double>());  // the distance is resolved, not rounding
    EXPECT_GT(d5 / d6, 10.0);
    EXPECT_LT(d5 / d6, 100.0);
    // Bentall and Johnson's 0.457 to its digits at f = 1e-6: -pi xi/(4 beta_D), 8(f).
    EXPECT_NEAR(-M_PI * r6.out["xi"].get<double>() / (4.0 * beta_al_st), 0.4573855087865, 1e-8);
}

// No slip (8(f), 8(n)): xi = -4 beta_D/pi^2 within the estimate at f = 1e3 and 1e6, the edge layers
// reported as neglected and thinner than the smallest double.
TEST(FreeRollingEveryF, NoSlipLimit) {
    for (const double f : {1e3, 1e6}) {
        const run_result r = run_point(f);
        ASSERT_EQ(r.status, 0) << r.text;
        const nlohmann::json& j = r.out;
        EXPECT_LE(std::fabs(j["xi"].get<double>() - no_slip_limit()), j["error_estimate"]["xi"].get<double>());
        EXPECT_LE(j["error_estimate"]["xi"].get<double>(), 1e-15);
        EXPECT_EQ(j["edge_layers"]["thickness_bound"].get<double>(), 0.0);
        EXPECT_TRUE(j["edge_layers"]["neglected"].get<bool>());
    }
    const run_result text = run_point(1.0, "", false);
    ASSERT_EQ(text.status, 0) << text.text;
    EXPECT_NE(text.text.find("edge layers         neglected: each thinner than 1.30699"), std::string::npos)
        << text.text;
}

// The closed form of the no-slip traction solves the stick equation H[p1] = xi + beta_D p of 8(f):
// the Cauchy principal value by GSL's QAWC, independently of the product's collocation.
TEST(FreeRollingEveryF, NoSlipClosedFormSolvesTheStickEquation) {
    gsl_set_error_handler_off();
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
    const auto p1 = [](double eta) {
        if (!(eta > -1.0 && eta < 1.0)) return 0.0;  // its limit at the edges (QAWC samples them)
        return -2.0 * beta_al_st / (M_PI * M_PI) * std::sqrt((1.0 - eta) * (1.0 + eta)) *
               std::log((1.0 - eta) / (1.0 + eta));
    };
    gsl_function F;
    F.function = [](double eta, void* p) { return (*static_cast<decltype(p1)*>(p))(eta); };
    F.params = const_cast<void*>(static_cast<const void*>(&p1));
    for (const double r : {-0.9, -0.7, 0.0, 0.3, 0.8, 0.95}) {
        double value = 0.0, error = 0.0;
        // The square-root-times-log ends limit QAWC's accuracy to about 1e-11 (its own error estimate).
        const int status = gsl_integration_qawc(&F, -1.0, 1.0, r, 1e-13, 0.0, 1000, w, &value, &error);
        EXPECT_TRUE(status == GSL_SUCCESS || status == GSL_EROUND) << gsl_strerror(status);
        EXPECT_LT(error, 1e-9) << "r = " << r;
        const double H = value / M_PI;  // (1/pi) PV int p1(eta)/(eta - r)
        const double p = 2.0 / M_PI * std::sqrt(1.0 - r * r);
        EXPECT_NEAR(H, no_slip_limit() + beta_al_st * p, 1e-10) << "r = " << r;
    }
    gsl_integration_workspace_free(w);
}

// Both routes through the program where both answer. f = 0.2: the five zones (n = 128, default tolerance) and
// the edge layers neglected (tolerance 0.5, above their estimates: 2.5e-4 and 1.6e-4 for the ends, 0.006 of xi
// for the creep); the five zones' layers are thinner than the bound t = 4/(1 + exp(pi f/beta_D)) of 8(n).
// f = 0.31 (8(n), "Against the five zones through the program"; the review found the gap test checking the
// route against its own constants): the layers' route at the default tolerance (its creep's bound 8.4e-5
// relative decides), the five zones at 1e-5 (the ladder's zone search, n = 512, estimates 4e-14 in xi, 4.4e-9
// and 2e-11 at the ends, below a hundredth of the route's). At both the creeps agree within the sum of their
// estimates and the route's ends, (4/e^2) t_c and 0.889 t_c from the edges, lie within their own estimates of
// the five zones' (measured at 0.31: 0.006, 0.50, 0.66 of them), a solver that does not know them. The ends'
// estimates are compared with the half-width by the tolerance (8(n), "The ends' estimates and their scale"),
// unlike the five zones' (with their slip zones' lengths): at 0.31, 1.1e-3 and 1.2e-2 of the layers' lengths.
TEST(FreeRollingEveryF, BothRoutesAgreeWhereBothAnswer) {
    struct both {
        double f;
        const char* five_options;
        const char* layers_options;
    };
    for (const both& b : {both{0.2, "", "--tolerance 0.5"}, both{0.31, "--tolerance 1e-5", ""}}) {
        const double f = b.f;
        const run_result five = run_point(f, b.five_options);
        const run_result layers = run_point(f, b.layers_options);
        ASSERT_EQ(five.status, 0) << five.text;
        ASSERT_EQ(layers.status, 0) << layers.text;
        ASSERT_EQ(five.out["zones"].size(), 5u) << f;
        ASSERT_EQ(five.out["zone_path"].get<std::string>(), "general") << f;
        ASSERT_EQ(layers.out["zone_path"].get<std::string>(), "no-slip") << f;
        ASSERT_TRUE(layers.out.contains("edge_layers")) << f;
        EXPECT_TRUE(five.out["checks_hold"].get<bool>()) << f;
        EXPECT_TRUE(layers.out["checks_hold"].get<bool>()) << f;
        for (const char* key : {"xi", "stick_start", "c0"}) {
            const double x5 = five.out[key].get<double>(), xL = layers.out[key].get<double>();
            const double e5 = five.out["error_estimate"][key].get<double>();
            const double eL = layers.out["error_estimate"][key].get<double>();
            std::printf("f = %g, %s: five zones (n = %d) %.15g +- %.3g, layers neglected %.15g +- %.3g, difference "
                        "%.3g (%.3f of the layers' estimate)\n",
                        f, key, five.out["n"].get<int>(), x5, e5, xL, eL, xL - x5, std::fabs(xL - x5) / eL);
            // The creep within both estimates; the ends within the layers' route's own (the five zones resolve them).
            EXPECT_LE(std::fabs(x5 - xL), std::string(key) == "xi" ? e5 + eL : eL) << f << " " << key;
            if (f == 0.31) {
                EXPECT_LE(e5, 0.01 * eL) << key;
            }
        }
        const double t = 4.0 / (1.0 + std::exp(M_PI * f / beta_al_st));
        EXPECT_NEAR(layers.out["edge_layers"]["thickness_bound"].get<double>(), t, 1e-12 * t);
        const nlohmann::json& z = five.out["zones"];
        const double leading = 1.0 + z[0]["to"].get<double>(), trailing = 1.0 - z[1]["to"].get<double>();
        std::printf("layers: leading %.4g (%.5f t_c), trailing %.4g (%.5f t_c), bound %.4g; the route's ends' "
                    "estimates relative to them %.3g, %.3g\n",
                    leading, 2.0 * leading / t, trailing, 2.0 * trailing / t, t,
                    layers.out["error_estimate"]["stick_start"].get<double>() / leading,
                    layers.out["error_estimate"]["c0"].get<double>() / trailing);
        EXPECT_LT(leading, t);
        EXPECT_LT(trailing, t);
    }
}

// The rollers exchanged (8(h)): (beta_D, Q) -> (-beta_D, -Q) changes the sign of xi and p1 and keeps
// the zones, on the layers-neglected structure too (library, n = 32, product: the closed form has no n).
TEST(FreeRollingEveryF, RollersExchangedWithTheLayersNeglected) {
    using namespace roughroll;
    const double f = 5.0;
    contact a(roughness{}, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    contact b(roughness{}, f, solver_options{32, method::product}, dissimilar{-beta_al_st, coupling_level::johnson});
    const tangential_solution sa = a.point(0.0), sb = b.point(-0.0);
    ASSERT_TRUE(sa.layout.layers_neglected());
    ASSERT_TRUE(sb.layout.layers_neglected());
    EXPECT_EQ(sa.xi, -sb.xi);
    EXPECT_EQ(sa.xi, no_slip_limit());
    for (const double r : {-0.999, -0.5, 0.1, 0.9}) {
        EXPECT_EQ(a.traction(sa, r), -b.traction(sb, r)) << r;
        EXPECT_LT(std::fabs(a.traction(sa, r)), f * a.normal().pressure(r)) << r;
        EXPECT_EQ(a.slip_velocity(sa, r), 0.0);
    }
    EXPECT_TRUE(sa.checks.hold());
    EXPECT_TRUE(sb.checks.hold());
    const auto e = a.estimate(sa);
    ASSERT_TRUE(e);
    EXPECT_LE(e->xi, 1e-15);
}

// The trailing layer's inner problem (docs/formulation.md 8(n), "The trailing layer"), solved here with GSL
// independently of the program: Y = (1 - r)/t_c, d in units of (2 beta_D/pi^2) sqrt(2 t_c); slip - on (0, Y3)
// with d = -sqrt(Y)(2L - log Y), stick (Y3, Y2), slip + on (Y2, Y1) with d = sqrt(Y) log Y, main stick Y > Y1;
// X0 = (z - Y2) sqrt((z - Y3)/(z - Y2)) sqrt(Y1 - z) (cuts on the stick set). Conditions: M0 = int d/X0 = 0
// (decay), M1/pi = -2/e^2 (the tail of the leading layer through the outer solution), and the entry at Y2,
// the finite part of the sqrt(Y2 - Y) coefficient of d = (r/pi) int d/(X0 (s - Y)):
//   C0 = int_{Y2}^{Y1} (F(s) - F(Y2))/(s - Y2) ds/sqrt((s - Y2)(Y1 - s)) + int_0^{Y3} d/(X0 (s - Y2)) = 0,
// F = sqrt(s) log(s)/sqrt(s - Y3), the finite part of int (s - Y2)^(-3/2)(Y1 - s)^(-1/2) being B(-1/2, 1/2) = 0.
namespace {
struct trailing_inner {
    double L;
    gsl_integration_workspace* w;
    gsl_integration_qaws_table* t;

    // int_0^{Y3} d(s) u(s)/X0(s) ds, X0 = -sqrt((Y3 - s)(Y2 - s)(Y1 - s)) there; QAWS with s^(1/2) (log s)^mu.
    template <class U>
    double reversed(const double y[3], U u) {
        const double Y1 = y[0], Y2 = y[1], Y3 = y[2];
        double total = 0.0;
        for (const int mu : {0, 1}) {
            gsl_integration_qaws_table_set(t, 0.5, -0.5, mu, 0);
            auto h = [&](double s) {
                const double c = mu == 0 ? 2.0 * L : -1.0;  // d/(-sqrt(s)) = 2L - log s
                return c * u(s) / std::sqrt((Y2 - s) * (Y1 - s));
            };
            total += qaws(h, 0.0, Y3);
        }
        return total;
    }
    // int_{Y2}^{Y1} v(s) ds/sqrt((s - Y2)(Y1 - s)).
    template <class V>
    double forward(const double y[3], V v) {
        gsl_integration_qaws_table_set(t, -0.5, -0.5, 0, 0);
        return qaws(v, y[1], y[0]);
    }
    template <class H>
    double qaws(H& h, double a, double b) {
        gsl_function F;
        F.function = [](double s, void* p) { return (*static_cast<H*>(p))(s); };
        F.params = &h;
        double value = 0.0, error = 0.0;
        const int status = gsl_integration_qaws(&F, a, b, t, 1e-13, 1e-11, 1000, w, &value, &error);
        if (status != GSL_SUCCESS && status != GSL_EROUND) ADD_FAILURE() << gsl_strerror(status);
        return value;
    }
    void residuals(const double y[3], double r[3]) {
        const double Y1 = y[0], Y2 = y[1], Y3 = y[2];
        const auto F = [&](double s) { return std::sqrt(s) * std::log(s) / std::sqrt(s - Y3); };
        const double M0 = reversed(y, [](double) { return 1.0; }) + forward(y, [&](double s) { return F(s); });
        const double M1 = reversed(y, [](double s) { return s; }) + forward(y, [&](double s) { return s * F(s); });
        const double FY2 = F(Y2);
        // F's difference quotient, its derivative within 1e-6 of Y2 (no cancellation; the difference O(1e-6 F'')).
        const double dF = ((std::log(Y2) + 2.0) / (2.0 * std::sqrt(Y2)) - 0.5 * std::sqrt(Y2) * std::log(Y2) / (Y2 - Y3)) /
                          std::sqrt(Y2 - Y3);
        const double C0 = reversed(y, [&](double s) { return 1.0 / (s - Y2); }) +
                          forward(y, [&](double s) { return s - Y2 < 1e-6 ? dF : (F(s) - FY2) / (s - Y2); });
        (void)Y1;
        r[0] = M0;
        r[1] = M1 / M_PI + 2.0 / (M_E * M_E);
        r[2] = C0;
    }
};

// Y1, Y2, Y3 at L by GSL's hybrid Newton from `start`.
std::vector<double> trailing_layer(double L, std::vector<double> start) {
    trailing_inner p{L, gsl_integration_workspace_alloc(1000), gsl_integration_qaws_table_alloc(0.0, 0.0, 0, 0)};
    gsl_multiroot_function F;
    F.n = 3;
    F.params = &p;
    F.f = [](const gsl_vector* x, void* q, gsl_vector* f) -> int {
        const double y[3] = {gsl_vector_get(x, 0), gsl_vector_get(x, 1), gsl_vector_get(x, 2)};
        if (!(0.0 < y[2] && y[2] < y[1] && y[1] < y[0])) return GSL_EDOM;
        double r[3];
        static_cast<trailing_inner*>(q)->residuals(y, r);
        for (int i = 0; i < 3; ++i) gsl_vector_set(f, i, r[i]);
        return GSL_SUCCESS;
    };
    gsl_vector* x = gsl_vector_alloc(3);
    for (int i = 0; i < 3; ++i) gsl_vector_set(x, i, start[i]);
    gsl_multiroot_fsolver* s = gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, 3);
    gsl_multiroot_fsolver_set(s, &F, x);
    int status = GSL_CONTINUE;
    for (int i = 0; i < 200 && status == GSL_CONTINUE; ++i) {
        if (gsl_multiroot_fsolver_iterate(s) != GSL_SUCCESS) break;
        status = gsl_multiroot_test_residual(s->f, 1e-11);
    }
    EXPECT_EQ(status, GSL_SUCCESS) << "L = " << L;
    std::vector<double> y{gsl_vector_get(s->x, 0), gsl_vector_get(s->x, 1), gsl_vector_get(s->x, 2)};
    gsl_multiroot_fsolver_free(s);
    gsl_vector_free(x);
    gsl_integration_qaws_table_free(p.t);
    gsl_integration_workspace_free(p.w);
    return y;
}
}  // namespace

// The trailing end the layers' route reports, 0.889 t_c within 0.011 t_c, against the trailing layer's inner
// problem from t_c = 2.5e-2 (L = 4.4) to t_c = 1e-300 (L = 691): its Y1 rises from 0.8734 to below 0.8992, inside
// [0.878, 0.900] once the O(t_c) correction (0.27 t_c, measured: the five zones minus the inner problem) is added;
// and the inner problem agrees with the five zones continued in f at n = 720 where they resolve the layer
// (f = 0.45 and 0.4625: 0.88603 and 0.88634, 8(n)) to that correction.
TEST(FreeRollingEveryF, TrailingLayerFromItsInnerProblem) {
    gsl_set_error_handler_off();
    std::vector<double> y{0.8734, 0.2516, 0.0497};
    double previous = 0.0;
    for (const double tc :
         {2.5e-2, 2.85e-3, 1.0774624328038951e-4, 8.2004e-5, 1e-6, 1e-10, DBL_EPSILON, 1e-40, 1e-80, 1e-300}) {
        const double L = std::log(2.0 / tc);
        y = trailing_layer(L, y);
        std::printf("t_c = %.3g (L = %.2f): Y1 = %.6f, Y2 = %.6f, Y3 = %.6f\n", tc, L, y[0], y[1], y[2]);
        EXPECT_GT(y[0], previous) << tc;  // rising with L
        previous = y[0];
        EXPECT_LT(y[0], 0.8992 + 1e-6) << tc;
        const double correction = 0.27 * tc;  // the O(t_c) correction, measured (8(n))
        EXPECT_LE(std::fabs(y[0] + correction - 0.889), 0.011) << tc;
        // Where the band alone bounds the end (t_c >= DBL_EPSILON: below, the bound carries t_c itself), its top
        // margin is at least 0.0047 t_c, not the 0.0008 t_c of the limit L -> infinity (edge_layers.cpp).
        if (tc >= DBL_EPSILON) {
            EXPECT_LE(y[0] + correction, 0.889 + 0.011 - 0.0047) << tc;
        }
        if (tc == 1.0774624328038951e-4) {
            EXPECT_NEAR(y[0], 0.88603, 0.3 * tc + 1e-5);
        }
        if (tc == 8.2004e-5) {
            EXPECT_NEAR(y[0], 0.88634, 0.3 * tc + 1e-5);
        }
        // The route's constants (8(n)) at a friction with this crossing: the reported end and its bound.
        if (tc >= 1e-80) {
            const double f = beta_al_st / M_PI * std::log(2.0 / tc - 1.0);
            const roughroll::neglected_layers l = roughroll::no_slip_layers(beta_al_st, f);
            EXPECT_LE(std::fabs((y[0] + correction) * l.crossing - l.trailing), l.trailing_bound) << tc;
            EXPECT_GE(l.trailing_bound, (tc < DBL_EPSILON ? 1.011 : 0.011) * l.crossing) << tc;
        }
    }
}

// The traction the layers' route reports agrees with its zones (8(n), "The layers' traction"; review of the
// layers' positions: it had been p1_ns everywhere, above f p inside the slip zones it reports). Library, both
// signs of beta_D (8(h)), f = 0.45: on the leading layer p1 = -sgn(beta_D) f p (the model's one slip zone), on
// the trailing layer sgn(beta_D) f p (its slip zone next to the main one), on the main stick zone p1_ns held to
// [-f p, f p] (held only within t_c of the edges); p1_ns itself exceeds f p in both layers.
TEST(FreeRollingEveryF, LayersTractionAgreesWithTheirZones) {
    using namespace roughroll;
    const double f = 0.45;
    for (const double beta : {beta_al_st, -beta_al_st}) {
        contact c(roughness{}, f, solver_options{128, method::product}, dissimilar{beta, coupling_level::johnson});
        const tangential_solution s = c.point(0.0);
        ASSERT_TRUE(s.layout.layers_neglected());
        const neglected_layers l = no_slip_layers(beta, f);
        const double sign = beta > 0.0 ? 1.0 : -1.0;
        ASSERT_EQ(s.layout.zones.size(), 3u);
        EXPECT_EQ(s.layout.zones[0].direction, -sign);
        EXPECT_EQ(s.layout.zones[2].direction, sign);
        for (const double k : {0.01, 0.25, 0.5, 0.75, 0.99}) {
            const double lead = -1.0 + k * l.leading, trail = 1.0 - k * l.trailing;
            const double p_lead = c.normal().pressure(lead), p_trail = c.normal().pressure(trail);
            EXPECT_EQ(c.traction(s, lead), -sign * f * p_lead) << k;
            EXPECT_EQ(c.traction(s, trail), sign * f * p_trail) << k;
            EXPECT_GT(std::fabs(no_slip_traction(beta, lead)), f * p_lead) << k;  // what it had reported
            EXPECT_GT(std::fabs(no_slip_traction(beta, trail)), f * p_trail) << k;
            EXPECT_FALSE(s.sticks(lead));
            EXPECT_FALSE(s.sticks(trail));
        }
        // The main stick zone: p1_ns where it is within f p (all of it beyond t_c from the edges), f p where not.
        for (const double r : {-1.0 + 0.6 * l.crossing, -1.0 + 0.99 * l.crossing, -1.0 + 1.01 * l.crossing, -0.5, 0.0,
                               0.7, 1.0 - 1.01 * l.crossing, 1.0 - 0.95 * l.crossing}) {
            ASSERT_TRUE(s.sticks(r)) << r;
            const double p1 = c.traction(s, r), ns = no_slip_traction(beta, r), limit = f * c.normal().pressure(r);
            EXPECT_LE(std::fabs(p1), limit) << r;
            EXPECT_EQ(p1, std::fabs(ns) <= limit ? ns : std::copysign(limit, ns)) << r;
            if (std::fabs(r) < 1.0 - l.crossing) {
                EXPECT_EQ(p1, ns) << r;
            }
        }
        EXPECT_TRUE(s.checks.hold());
    }
}

// The same through `roughroll traction` (the Python module's Scene.traction has its rows, traction_table.hpp):
// f = 0.2 at a tolerance of 0.5 (t_c = 0.025, so the grid's 801 points sample both layers): every row within
// |p1| <= f p, the slip rows at +-f p with the leading and trailing layers' signs, the rows beyond t = 2 t_c
// from the edges the no-slip traction; the slip velocity 0 on the stick rows, computed with the leading layer's
// direction on its rows, '-' (not resolved, said in a comment line) on the trailing layer's (both had been 0).
TEST(FreeRollingEveryF, LayersTractionThroughTheTractionCommand) {
    const traction_csv t = run_traction(0.2, "--tolerance 0.5", 801);
    ASSERT_EQ(t.status, 0) << t.text;
    int slip_rows = 0, stick_rows = 0, unresolved = 0;
    const double f = 0.2, t2 = 2.0 * crossing_of(f);
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const double r = t.number(i, "r"), p1 = t.number(i, "p1"), fp = t.number(i, "f_p");
        const std::string& v = t.at(i, "slip_velocity");
        EXPECT_LE(std::fabs(p1), fp) << r;
        if (t.at(i, "zone") == "slip") {
            ++slip_rows;
            EXPECT_EQ(p1, r < 0.0 ? -fp : fp) << r;  // beta_D > 0: slip - leading, slip + trailing
            // The slip velocity (8(n), "The layers' slip velocity"): the leading layer's, computed, in its direction
            // (it had been 0); the trailing layer's not resolved, '-' (it had been 0 too).
            if (r < 0.0) {
                EXPECT_LT(std::stod(v), 0.0) << r;
            } else {
                EXPECT_EQ(v, "-") << r;
                ++unresolved;
            }
        } else {
            ++stick_rows;
            EXPECT_EQ(v, "0") << r;
            if (std::fabs(r) < 1.0 - t2) {
                EXPECT_NEAR(p1, roughroll::no_slip_traction(beta_al_st, r), 1e-16) << r;
            }
        }
    }
    std::printf("traction at f = 0.2, layers neglected: %d slip rows (%d with v not resolved), %d stick rows\n",
                slip_rows, unresolved, stick_rows);
    EXPECT_GE(slip_rows, 6);  // both layers sampled: 0.0136 and 0.0222 wide, rows 0.0025 apart, and the edges
    EXPECT_GE(unresolved, 3);
    EXPECT_EQ(slip_rows + stick_rows, 801);
    EXPECT_NE(std::find_if(t.comments.begin(), t.comments.end(),
                           [](const std::string& c) { return c.find("slip_velocity '-': not resolved") != std::string::npos; }),
              t.comments.end());
}

// The leading layer's inner problem (docs/formulation.md 8(n), "The layers' positions"), solved here with GSL
// independently of the program and of the derivation's Phi: X = (1 + r)/t_c, d = p1 - p1_ns in units of
// (2 beta_D/pi^2) sqrt(2 t_c) equal to g(X) = sqrt(X) log(1/X) on the slip zone (0, A), and on X > A the
// half-line's bounded solution
//   d(X) = (sqrt(X - A)/pi) int_0^A g(S) dS/(sqrt(A - S)(X - S)).
// (1) d solves (1/pi) PV int_0^inf d(S) dS/(S - X) = 0 at X > A (nested quadrature: QAWS inside, QAWC, QAGIU).
// (2) Its sqrt(h) coefficient at X = A + h, c(A) = (1/pi)[int_0^A (g(S) - g(A))/(A - S)^(3/2) dS - 2 g(A)/sqrt(A)]
// (the limit of the formula, taken directly), agrees with (d(A + h) - g(A))/sqrt(h) extrapolated to h = 0.
// (3) The entry condition c(A) = 0 (no sqrt(h) term at s1), solved by bisection, has its root at 4/e^2: the
// leading layer 1 + s1 = (4/e^2) t_c that the route reports.
namespace {
struct leading_inner {
    gsl_integration_workspace* inner_w;
    gsl_integration_workspace* outer_w;
    gsl_integration_qaws_table* table;

    static double g(double X) { return -std::sqrt(X) * std::log(X); }
    double qaws(double (*f)(double, void*), void* params, double a, double b, double alpha, double beta, int mu) {
        gsl_integration_qaws_table_set(table, alpha, beta, mu, 0);
        gsl_function F{f, params};
        double value = 0.0, error = 0.0;
        const int status = gsl_integration_qaws(&F, a, b, table, 1e-14, 1e-12, 1000, inner_w, &value, &error);
        if (status != GSL_SUCCESS && status != GSL_EROUND) ADD_FAILURE() << "QAWS: " << gsl_strerror(status);
        return value;
    }
    // d(X), X > A: int_0^A S^(1/2) (A - S)^(-1/2) log(S) (-1/(X - S)) dS, QAWS's algebraic-logarithmic weight.
    double d(double A, double X) {
        if (!(X > A)) return g(A);  // continuous at A (QAWC's rule may sample the end)
        auto h = [X](double S) { return -1.0 / (X - S); };
        const double integral = qaws([](double S, void* p) { return (*static_cast<decltype(h)*>(p))(S); }, &h, 0.0, A,
                                     0.5, -0.5, 1);
        return std::sqrt(X - A) / M_PI * integral;
    }
    // c(A): the weight (A - S)^(-1/2), the difference quotient of g by its derivative within 1e-7 A of A.
    double c(double A) {
        const double gA = g(A), dg = -(std::log(A) + 2.0) / (2.0 * std::sqrt(A));
        auto h = [&](double S) { return A - S < 1e-7 * A ? -dg : (g(S) - gA) / (A - S); };
        const double J = qaws([](double S, void* p) { return (*static_cast<decltype(h)*>(p))(S); }, &h, 0.0, A, 0.0,
                              -0.5, 0);
        return (J - 2.0 * gA / std::sqrt(A)) / M_PI;
    }
    // (1/pi) PV int_0^inf d(S)/(S - X) dS at X > A: g on (0, A) (QAWS), d on (A, 2X + 1) (QAWC), the tail (QAGIU).
    // The slip zone's part alone, (1/pi) int_0^A g(S)/(S - X) dS: what the stick zone's d cancels.
    double slip_part(double A, double X) {
        auto on_slip = [X](double S) { return -1.0 / (S - X); };
        return qaws([](double S, void* p) { return (*static_cast<decltype(on_slip)*>(p))(S); }, &on_slip, 0.0, A,
                    0.5, 0.0, 1) /
               M_PI;
    }
    // (1/pi) PV int_0^inf d(S)/(S - X) dS at 0 < X < A, on the slip zone: g's principal value on (0, A), as
    // int (g(S) - g(X))/(S - X) dS (QAGP, break at X; g's log at 0 defeats QAWC) plus g(X) log((A - X)/X), the
    // stick zone's d on (A, A + 1) (QAGS: d - g(A) is O((S - A)^(1/2)) at A) and beyond (QAGIU). The slip velocity's
    // inner problem (8(n), "The layers' slip velocity"), from the formula's d without the closed form.
    double on_slip(double A, double X) {
        const double gX = g(X), dg = -(std::log(X) + 2.0) / (2.0 * std::sqrt(X));
        auto quotient = [&](double S) { return std::fabs(S - X) < 1e-7 * X ? dg : (g(S) - gX) / (S - X); };
        gsl_function G{[](double S, void* p) { return (*static_cast<decltype(quotient)*>(p))(S); }, &quotient};
        double pv = 0.0, near = 0.0, tail = 0.0, error = 0.0;
        double points[3] = {0.0, X, A};
        int status = gsl_integration_qagp(&G, points, 3, 1e-13, 1e-11, 1000, outer_w, &pv, &error);
        if (status != GSL_SUCCESS && status != GSL_EROUND) ADD_FAILURE() << "QAGP: " << gsl_strerror(status);
        pv += gX * std::log((A - X) / X);
        auto beyond = [&](double S) { return d(A, S) / (S - X); };
        gsl_function T{[](double S, void* p) { return (*static_cast<decltype(beyond)*>(p))(S); }, &beyond};
        status = gsl_integration_qags(&T, A, A + 1.0, 1e-13, 1e-11, 1000, outer_w, &near, &error);
        if (status != GSL_SUCCESS && status != GSL_EROUND) ADD_FAILURE() << "QAGS: " << gsl_strerror(status);
        status = gsl_integration_qagiu(&T, A + 1.0, 1e-13, 1e-11, 1000, outer_w, &tail, &error);
        if (status != GSL_SUCCESS && status != GSL_EROUND) ADD_FAILURE() << "QAGIU: " << gsl_strerror(status);
        return (pv + near + tail) / M_PI;
    }
    double half_line(double A, double X) {
        const double slip = M_PI * slip_part(A, X);
        auto on_stick = [&](double S) { return d(A, S); };
        gsl_function F{[](double S, void* p) { return (*static_cast<decltype(on_stick)*>(p))(S); }, &on_stick};
        double pv = 0.0, tail = 0.0, error = 0.0;
        int status = gsl_integration_qawc(&F, A, 2.0 * X + 1.0, X, 1e-12, 1e-10, 1000, outer_w, &pv, &error);
        if (status != GSL_SUCCESS && status != GSL_EROUND) ADD_FAILURE() << "QAWC: " << gsl_strerror(status);
        auto beyond = [&](double S) { return d(A, S) / (S - X); };
        gsl_function T{[](double S, void* p) { return (*static_cast<decltype(beyond)*>(p))(S); }, &beyond};
        status = gsl_integration_qagiu(&T, 2.0 * X + 1.0, 1e-12, 1e-10, 1000, outer_w, &tail, &error);
        if (status != GSL_SUCCESS && status != GSL_EROUND) ADD_FAILURE() << "QAGIU: " << gsl_strerror(status);
        return (slip + pv + tail) / M_PI;
    }
};
}  // namespace

TEST(FreeRollingEveryF, LeadingLayerFromItsInnerProblem) {
    gsl_set_error_handler_off();
    leading_inner p{gsl_integration_workspace_alloc(1000), gsl_integration_workspace_alloc(1000),
                    gsl_integration_qaws_table_alloc(0.0, 0.0, 0, 0)};
    const double root_expected = 4.0 / (M_E * M_E);
    // (1) The bounded solution solves the half-line equation (at A = 4/e^2 and at a wrong A alike).
    for (const double A : {root_expected, 0.5}) {
        for (const double X : {0.7, 1.0, 2.0, 5.0}) {
            const double residual = p.half_line(A, X), slip = p.slip_part(A, X);
            std::printf("A = %.6f, X = %.1f: (1/pi) PV int d/(S - X) = %.3g (the slip zone's part %.4g)\n", A, X,
                        residual, slip);
            EXPECT_LT(std::fabs(residual), 1e-8) << A << " " << X;
            EXPECT_GT(std::fabs(slip), 1e-3) << A << " " << X;  // a cancellation, not two zeros
        }
    }
    // (2) c(A) against the formula's d near A: (d(A + h) - g(A))/sqrt(h) = c + k sqrt(h) + O(h), extrapolated.
    for (const double A : {0.5, root_expected, 0.6}) {
        const double h = 1e-6;
        const double q1 = (p.d(A, A + h) - leading_inner::g(A)) / std::sqrt(h);
        const double q4 = (p.d(A, A + 4.0 * h) - leading_inner::g(A)) / std::sqrt(4.0 * h);
        const double extrapolated = 2.0 * q1 - q4;
        std::printf("A = %.6f: c = %.9f, from d near A %.9f\n", A, p.c(A), extrapolated);
        EXPECT_NEAR(extrapolated, p.c(A), 1e-5) << A;
    }
    EXPECT_LT(p.c(0.5), -0.05);  // 8(n): -0.079 and +0.103, a sqrt(h) term of either sign
    EXPECT_GT(p.c(0.6), 0.05);
    // (3) The entry condition's root by bisection.
    double lo = 0.5, hi = 0.6;
    for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
        const double mid = 0.5 * (lo + hi);
        (p.c(mid) < 0.0 ? lo : hi) = mid;
    }
    const double root = 0.5 * (lo + hi);
    std::printf("the entry condition's root: A = %.12f, 4/e^2 = %.12f, difference %.3g\n", root, root_expected,
                root - root_expected);
    EXPECT_NEAR(root, root_expected, 1e-9);
    // The route's leading end at f = 0.45 is that root times t_c (to rounding), within its bound of the model's.
    const roughroll::neglected_layers l = roughroll::no_slip_layers(beta_al_st, 0.45);
    EXPECT_NEAR(l.leading, root * l.crossing, 1e-9 * l.crossing);
    EXPECT_LT(1e-9 * l.crossing, l.leading_bound);
    gsl_integration_qaws_table_free(p.table);
    gsl_integration_workspace_free(p.outer_w);
    gsl_integration_workspace_free(p.inner_w);
}

// The leading layer's slip velocity (docs/formulation.md 8(n), "The layers' slip velocity"; it had been reported
// 0): v = Delta xi - H[d] = -(2 beta_D/pi^2) sqrt(2 t_c) (1/pi) PV int_0^inf D(S) dS/(S - X) to leading order, the
// library's closed form -(4 beta_D/pi^2) sqrt(2 t_a)(sin theta - theta cos theta) against that transform of the
// inner problem's D taken by quadrature (leading_inner::on_slip, from the formula's d, no closed form), at f = 0.45
// and both signs of beta_D (8(h)); its direction -sgn(beta_D) on the layer, 0 at s1 and on the main stick zone, NaN
// (not resolved) on the trailing layer (c1, 1].
TEST(FreeRollingEveryF, LeadingLayerSlipVelocityFromItsInnerProblem) {
    using namespace roughroll;
    gsl_set_error_handler_off();
    leading_inner p{gsl_integration_workspace_alloc(1000), gsl_integration_workspace_alloc(1000),
                    gsl_integration_qaws_table_alloc(0.0, 0.0, 0, 0)};
    const double f = 0.45;
    for (const double beta : {beta_al_st, -beta_al_st}) {
        contact c(roughness{}, f, solver_options{128, method::product}, dissimilar{beta, coupling_level::johnson});
        const tangential_solution s = c.point(0.0);
        ASSERT_TRUE(s.layout.layers_neglected());
        const double tc = no_slip_layers(beta, f).crossing, s1 = s.start(), c1 = s.c0();
        const double A = (1.0 + s1) / tc, scale = -2.0 * beta / (M_PI * M_PI) * std::sqrt(2.0 * tc);
        EXPECT_NEAR(A, 4.0 / (M_E * M_E), 1e-9);
        for (const double X : {1e-4, 0.05, 0.2, 0.4, 0.5, 0.54}) {
            const double r = -1.0 + X * tc, v = c.slip_velocity(s, r), quadrature = p.on_slip(A, (1.0 + r) / tc);
            std::printf("beta_D = %+.4f, X = %.4g: v/scale = %.12f, quadrature %.12f, difference %.2g\n", beta, X,
                        v / scale, quadrature, v / scale - quadrature);
            EXPECT_NEAR(v / scale, quadrature, 1e-11) << beta << " " << X;  // measured 1.4e-13 to 5.2e-13
            EXPECT_GT(-beta * v, 0.0) << X;  // the layer's direction -sgn(beta_D): (3.4)
        }
        EXPECT_EQ(c.slip_velocity(s, s1), 0.0);
        for (const double r : {-0.5, 0.0, 0.9, c1 - 1e-9}) EXPECT_EQ(c.slip_velocity(s, r), 0.0) << r;
        EXPECT_EQ(c.slip_velocity(s, c1), 0.0);  // the trailing layer's entry
        for (const double r : {c1 + 0.5 * (1.0 - c1), 1.0}) EXPECT_TRUE(std::isnan(c.slip_velocity(s, r))) << r;
    }
    gsl_integration_qaws_table_free(p.table);
    gsl_integration_workspace_free(p.outer_w);
    gsl_integration_workspace_free(p.inner_w);
}

// The leading layer's slip velocity against the program's five zones, which resolve the layer as a zone of their
// own (v of (3.6) from their collocation), at f = 0.2 (the five zones at the default tolerance, n = 128; the layers
// neglected at 0.5) and f = 0.31 (8(n), "Against the five zones through the program": the five zones at 1e-5,
// n = 512; the layers at the default tolerance), each on the rows of both leading slip zones of one grid. Measured
// (8(n)): the largest difference is 0.252 t_c and 0.250 t_c of |v(-1)| (6.1e-5 and 1.7e-6; the second order of the
// inner problem, O(t_c^(3/2)) against v's O(t_c^(1/2))); it had been all of |v|, 9.6e-3 and 2.9e-3 at the edge.
// The five zones' own trailing layer carries v of both signs (slip +, then reversed slip at the edge): why the
// route, reporting one slip zone there, does not report a v on it.
TEST(FreeRollingEveryF, LeadingLayerSlipVelocityAgainstTheFiveZones) {
    struct both {
        double f;
        const char* five_options;
        const char* layers_options;
        int points;
    };
    for (const both& b : {both{0.2, "", "--tolerance 0.5", 20001}, both{0.31, "--tolerance 1e-5", "", 99999}}) {
        const traction_csv five = run_traction(b.f, b.five_options, b.points);
        const traction_csv layers = run_traction(b.f, b.layers_options, b.points);
        ASSERT_EQ(five.status, 0) << five.text;
        ASSERT_EQ(layers.status, 0) << layers.text;
        ASSERT_EQ(five.rows.size(), layers.rows.size());
        const double tc = crossing_of(b.f);
        double largest = 0.0, edge = 0.0;
        int compared = 0, forward = 0, reversed = 0;
        for (std::size_t i = 0; i < five.rows.size(); ++i) {
            const double r = five.number(i, "r");
            ASSERT_EQ(r, layers.number(i, "r"));
            const bool slip5 = five.at(i, "zone") == "slip", slipL = layers.at(i, "zone") == "slip";
            if (r > 0.0 && slip5) {  // the five zones' trailing layer
                const double v = five.number(i, "slip_velocity");
                forward += v > 0.0;
                reversed += v < 0.0;
            }
            if (!(r < 0.0 && slip5 && slipL)) continue;
            const double v5 = five.number(i, "slip_velocity"), vL = layers.number(i, "slip_velocity");
            if (r == -1.0) edge = vL;
            largest = std::max(largest, std::fabs(vL - v5));
            ++compared;
        }
        std::printf("f = %g (t_c = %.4g): %d rows of the leading layer, v(-1) = %.6g, largest difference from the "
                    "five zones %.4g = %.4f t_c |v(-1)|; their trailing layer: %d rows v > 0, %d rows v < 0\n",
                    b.f, tc, compared, edge, largest, largest / (tc * std::fabs(edge)), forward, reversed);
        EXPECT_GE(compared, 50) << b.f;
        EXPECT_LT(edge, 0.0) << b.f;
        EXPECT_LE(largest, 0.3 * tc * std::fabs(edge)) << b.f;
        EXPECT_GT(forward, 0) << b.f;
        EXPECT_GT(reversed, 0) << b.f;
    }
}
