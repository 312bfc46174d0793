// SPDX-License-Identifier: GPL-3.0-or-later
// Free rolling (Q = 0) at full coupling from f = 1 on (issue 24, 7; docs/formulation.md 8(t), "The layers' bound at
// full coupling"): the no-slip limit of 8(p) with its edge layers neglected, answered where the five zones' leading
// slip zone is below every n's resolution, its creep and P_H/P2 within the bound of the neglected layers. The bound is
// checked against two routes that do not use it: full coupling's own five zones at f = 0.1 .. 0.19 (the largest f they
// answer), where the premises it rests on are measured too, and Johnson's five zones against 8(f)'s no-slip creep with
// the same formula at eps = 0. The limit as beta_D -> 0 is Johnson's level's, both answered by the program.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/no_slip_coupled.hpp"

#include "aluminium_on_steel.hpp"
#include "command_output.hpp"

namespace {
// The pair's scene with each key = value of `changes` replaced (the key's whole line), written to a temporary file.
std::string scene_with(const std::vector<std::pair<std::string, std::string>>& changes) {
    return changed_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml", changes, "roughroll-no-slip-full");
}

struct answered {
    int status;
    std::string text;
    nlohmann::json out;
};

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

answered point_of(const std::string& scene, double f, const std::string& options = "") {
    const command_output o = run_command(std::string(ROUGHROLL_CLI) + " point " + scene + " --Q 0 --friction " +
                                         number(f) + " " + options + " --json 2>&1");
    answered a{o.status, o.text, {}};
    if (o.status == 0) a.out = nlohmann::json::parse(o.text);
    return a;
}

// 8(p): tanh(pi eps) = -beta_D; the limit's lambda = P_H/P2 and creep, and |F_ns| = c sqrt(1 - r^2).
double epsilon_of(double beta) { return std::log((1.0 - beta) / (1.0 + beta)) / (2.0 * M_PI); }
double lambda_of(double eps) { return 1.0 / (1.0 + 4.0 * eps * eps); }
double creep_of(double eps) { return 4.0 * eps * lambda_of(eps) / M_PI; }
// The full level's crossing (8(p), "The edges") and Johnson's (8(g)).
double full_crossing(double beta, double f) { return 2.0 / (1.0 + std::exp(std::atan(f) / std::fabs(epsilon_of(beta)))); }
double johnson_crossing(double beta, double f) { return 2.0 / (1.0 + std::exp(M_PI * f / std::fabs(beta))); }

// Dundurs' beta_D of two materials (8(a)), as aluminium_on_steel.hpp writes it out.
double beta_of(double mu1, double nu1, double mu2, double nu2) {
    const double C = (1.0 - nu1) / mu1 + (1.0 - nu2) / mu2;
    return ((1.0 - 2.0 * nu1) / mu1 - (1.0 - 2.0 * nu2) / mu2) / (2.0 * C);
}

// `roughroll traction` at an explicit n on `points` rows: the header's xi, P_H/P2 and zones, and each row's r, p, p1.
struct traction_table {
    double xi = 0.0, lambda = 0.0;
    std::vector<std::pair<bool, std::pair<double, double>>> zones;  // stick?, [from, to]
    std::vector<double> r, p, p1;
    bool checks = false;
};

traction_table traction_of(const std::string& scene, double f, int n, int points) {
    char dir[] = "/tmp/roughroll-no-slip-traction-XXXXXX";
    traction_table t;
    if (mkdtemp(dir) == nullptr) return t;
    const command_output o = run_command(std::string(ROUGHROLL_CLI) + " traction " + scene + " --Q 0 --friction " +
                                         number(f) + " --n " + std::to_string(n) + " --method product --points " +
                                         std::to_string(points) + " --no-plot --quiet --out " + dir + " --name t 2>&1");
    EXPECT_EQ(o.status, 0) << o.text;
    const std::string csv = std::string(dir) + "/traction-t.csv";
    std::ifstream in(csv);
    std::string line;
    const std::regex head(R"(xi = ([-0-9.e+]+), P_H/P2 = ([-0-9.e+]+),.*checks = (\w+))");
    const std::regex zone(R"((stick|slip[-+]) \[([-0-9.e+]+), ([-0-9.e+]+)\])");
    bool header = true;
    while (std::getline(in, line)) {
        std::smatch m;
        if (!line.empty() && line[0] == '#') {
            if (std::regex_search(line, m, head)) {
                t.xi = std::stod(m[1]);
                t.lambda = std::stod(m[2]);
                t.checks = m[3] == "hold";
            }
            if (line.find("# zones") == 0)
                for (std::sregex_iterator z(line.begin(), line.end(), zone), end; z != end; ++z)
                    t.zones.push_back({(*z)[1] == "stick", {std::stod((*z)[2]), std::stod((*z)[3])}});
            continue;
        }
        if (header) {  // the column names
            header = false;
            continue;
        }
        std::stringstream row(line);
        std::string cell[3];
        for (std::string& c : cell) std::getline(row, c, ',');
        t.r.push_back(std::stod(cell[0]));
        t.p.push_back(std::stod(cell[1]));
        t.p1.push_back(std::stod(cell[2]));
    }
    std::remove(csv.c_str());
    std::remove((std::string(dir) + "/traction-t.gp").c_str());
    rmdir(dir);
    return t;
}
}  // namespace

// Issue 24, 7: free rolling at full coupling at f = 1, 10, 1e3, 1e6, refused before ("the slip zone at the leading edge
// ... is thinner than ... the zone search resolves"). Answered at the default settings by the no-slip limit: its creep
// and P_H/P2 in closed form (8(p), written out here), zone path "no-slip", checks holding, the estimates within the
// default tolerance and at least the layers' bound, the layers' crossing the full level's. At f = 1e6 the creep is
// the routine's (no_slip_coupled, 8(t)): the f -> infinity limit. The limit differs from Johnson's by 8.8e-5, far
// beyond the estimates: the coupling is resolved.
TEST(NoSlipFull, FreeRollingAnsweredFromFOne) {
    const std::string full = scene_with({{"coupling = \"johnson\"", "coupling = \"full\""}});
    ASSERT_FALSE(full.empty());
    const double eps = epsilon_of(beta_al_st);
    const double johnson = -4.0 * beta_al_st / (M_PI * M_PI);
    for (const double f : {1.0, 10.0, 1e3, 1e6}) {
        SCOPED_TRACE(f);
        const answered a = point_of(full, f);
        ASSERT_EQ(a.status, 0) << a.text;
        const nlohmann::json& o = a.out;
        EXPECT_EQ(o["coupling"]["level"], "full");
        EXPECT_EQ(o["zone_path"], "no-slip");
        EXPECT_TRUE(o["checks_hold"].get<bool>()) << o["checks"].dump();
        const double xi = o["xi"], lambda = o["hertz_load_ratio"];
        EXPECT_NEAR(xi, creep_of(eps), 4e-16);
        EXPECT_NEAR(lambda, lambda_of(eps), 4e-16);
        EXPECT_EQ(o["c0"].get<double>(), 1.0);
        EXPECT_EQ(o["stick_start"].get<double>(), -1.0);
        const nlohmann::json& e = o["error_estimate"];
        ASSERT_TRUE(e.is_object()) << o.dump();
        const roughroll::neglected_layers l = roughroll::coupled_no_slip_layers(beta_al_st, f);
        EXPECT_GE(e["xi"].get<double>(), l.xi_bound);
        EXPECT_GE(e["hertz_load_ratio"].get<double>(), l.lambda_bound);
        EXPECT_LE(e["xi"].get<double>(), 1e-4 * std::fabs(xi));
        EXPECT_LE(e["hertz_load_ratio"].get<double>(), 1e-4 * lambda);
        EXPECT_LE(e["c0"].get<double>(), 1e-4);
        EXPECT_LT(e["xi"].get<double>(), 0.1 * std::fabs(xi - johnson));
        const nlohmann::json& layers = o["edge_layers"];
        ASSERT_TRUE(layers.is_object()) << o.dump();
        EXPECT_NEAR(layers["crossing"].get<double>(), full_crossing(beta_al_st, f),
                    1e-12 * full_crossing(beta_al_st, f));
        EXPECT_EQ(layers["thickness_bound"].get<double>(), 2.0 * layers["crossing"].get<double>());
        // The physical peak at the same P2, 8(p): sqrt(lambda) cosh(pi eps) - 1 = +0.624 %.
        EXPECT_NEAR(o["coupling"]["peak_pressure_change"].get<double>(),
                    std::sqrt(lambda_of(eps)) * std::cosh(M_PI * eps) - 1.0, 1e-14);
        EXPECT_NEAR(o["si"]["a_over_a_hertz"].get<double>(), std::sqrt(lambda_of(eps)), 1e-12);
        if (f == 1e6) {
            const roughroll::no_slip_coupled_solution limit =
                roughroll::no_slip_coupled(beta_al_st, roughroll::kernel{}, roughroll::kernel{}, 0);
            EXPECT_NEAR(xi, limit.xi, 1e-16);
        }
    }
    std::remove(full.c_str());
}

// The bound against full coupling's own five zones (n = 256, product, checks holding; the largest f they answer is
// 0.19, 8(p)): |xi - xi_ns| and |P_H/P2 - lambda_ns| within coupled_no_slip_layers' bounds, and the two premises the
// bounds rest on, measured on the solved zones and tractions: each layer (everything outside the main stick zone)
// thinner than t = 2 t_c (measured 0.556 and 0.906 t_c at f = 0.19), and |F| = |p - i p1| <= kappa c sqrt(1 - r^2) in
// the layers (measured at most 1.006 against kappa = 2). Measured: the creep's distance 0.26 to 0.34 % of its bound,
// -0.0174, -0.0166, -0.0163 t_c (first order in t_c, 8(t)).
namespace {
// One row of BoundHoldsAgainstTheFiveZones: the premises and the bounds of 8(t) on full coupling's five zones of a
// smooth pair at friction f (n = 256, product, 8001 rows); returns the creep's distance over t_c.
double five_zones_within_the_bound(const std::string& scene, double beta, double f) {
    const double eps = epsilon_of(beta);
    const double c = M_2_PI * lambda_of(eps) * std::cosh(M_PI * eps);
    const traction_table t = traction_of(scene, f, 256, 8001);
    EXPECT_EQ(t.zones.size(), 5u);
    if (t.zones.size() != 5u) return 0.0;
    EXPECT_TRUE(t.checks);
    const roughroll::neglected_layers l = roughroll::coupled_no_slip_layers(beta, f);
    const double s1 = t.zones[1].second.first, c1 = t.zones[1].second.second;
    EXPECT_TRUE(t.zones[1].first);
    EXPECT_LT(1.0 + s1, l.thickness);
    EXPECT_LT(1.0 - c1, l.thickness);
    double kappa = 0.0;
    for (std::size_t i = 0; i < t.r.size(); ++i) {
        const double r = t.r[i];
        if (!(std::fabs(r) < 1.0) || (r >= s1 && r <= c1)) continue;
        kappa = std::max(kappa, std::hypot(t.p[i], t.p1[i]) / (c * std::sqrt((1.0 - r) * (1.0 + r))));
    }
    EXPECT_GT(kappa, 0.9);  // the layers were sampled
    EXPECT_LT(kappa, roughroll::kappa_layers);
    EXPECT_LT(std::fabs(t.xi - creep_of(eps)), l.xi_bound);
    EXPECT_LT(std::fabs(t.lambda - lambda_of(eps)), l.lambda_bound);
    return (t.xi - creep_of(eps)) / l.crossing;
}
}  // namespace

TEST(NoSlipFull, BoundHoldsAgainstTheFiveZones) {
    const std::string full = scene_with({{"coupling = \"johnson\"", "coupling = \"full\""}});
    ASSERT_FALSE(full.empty());
    for (const double f : {0.1, 0.15, 0.19}) {
        SCOPED_TRACE(f);
        // First order in t_c, as derived: the distance over t_c within 15 % of -0.016.
        EXPECT_NEAR(five_zones_within_the_bound(full, beta_al_st, f), -0.0165, 0.0025);
    }
    std::remove(full.c_str());
}

// The premises at twice the pair's largest slip angle (session 16 review): the edge problem at full coupling depends
// on the slip angle theta = atan f, not only on t_c (8(t)), so a synthetic smooth pair with a larger |eps| (beta_D =
// 0.392, eps = -0.1317: mu 20e9, nu 0.1 on 200e9, 0.3) reaches theta = 0.29 and 0.38 at a resolved t_c (0.197, 0.106).
// Measured by the review: layers 0.63 and 1.05-1.07 t_c, kappa 1.06 and 1.05, the creep's distance 0.57 % and 0.72 %
// of its bound (-0.053 t_c). Beyond theta ~ 0.42 the five zones fail their checks (8(t)): no route measures there.
TEST(NoSlipFull, BoundHoldsAtLargerSlipAngles) {
    const std::string full = scene_with({{"coupling = \"johnson\"", "coupling = \"full\""},
                                         {"shear_modulus = 23e9", "shear_modulus = 20e9"},
                                         {"poisson = 0.31", "poisson = 0.1"},
                                         {"shear_modulus = 82e9", "shear_modulus = 200e9"},
                                         {"poisson = 0.28", "poisson = 0.3"}});
    ASSERT_FALSE(full.empty());
    const double beta = beta_of(20e9, 0.1, 200e9, 0.3);
    ASSERT_NEAR(epsilon_of(beta), -0.1317, 1e-4);
    for (const double f : {0.3, 0.4}) {
        SCOPED_TRACE(f);
        EXPECT_LT(five_zones_within_the_bound(full, beta, f), 0.0);
    }
    std::remove(full.c_str());
}

// The same formula at eps = 0 on Johnson's level (Hertz's pressure, c = 2/pi, Johnson's crossing): the five zones'
// distance from 8(f)'s no-slip creep -4 beta_D/pi^2 within it at f = 0.2 and 0.3 (n = 128 and 512, product, checks
// holding; the five zones, not the layers' route, below f = 0.306). Measured 0.4 % and 0.4 % of it (-0.0159 t_c).
TEST(NoSlipFull, SameBoundAtJohnsonsLevel) {
    const std::string johnson = std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml";
    for (const auto& [f, n] : {std::pair{0.2, 128}, std::pair{0.3, 512}}) {
        SCOPED_TRACE(f);
        const answered a = point_of(johnson, f, "--n " + std::to_string(n) + " --method product");
        ASSERT_EQ(a.status, 0) << a.text;
        EXPECT_EQ(a.out["zone_path"], "general");
        EXPECT_TRUE(a.out["checks_hold"].get<bool>());
        const double tc = johnson_crossing(beta_al_st, f);
        const roughroll::neglected_layers l = roughroll::coupled_layers_bound(0.0, tc);
        const double distance = a.out["xi"].get<double>() + 4.0 * beta_al_st / (M_PI * M_PI);
        EXPECT_LT(std::fabs(distance), l.xi_bound);
        EXPECT_GT(std::fabs(distance), 1e-3 * l.xi_bound);  // a bound of the right order, not a vacuous one
        EXPECT_LT(1.0 + a.out["stick_start"].get<double>(), l.thickness);
    }
}

// beta_D -> 0: full coupling's no-slip creep tends to Johnson's, xi_full - xi_J = -(4/pi^2)(1/3 - 4/pi^2) beta_D^3
// (8(p)): 0.029161 beta_D^3, both answered by the program at f = 1 (Johnson's layers' route of 8(n), full coupling's
// limit of 8(t)) for two pairs of nearly equal rollers (beta_D 0.0127 and 0.0443), the ratio within 1 % of the
// coefficient (8(t) measured 0.02916 .. 0.02919 for beta_D up to 0.04). On the old program full coupling was refused.
TEST(NoSlipFull, SmallBetaApproachesJohnsonsLevel) {
    const double coefficient = -4.0 / (M_PI * M_PI) * (1.0 / 3.0 - 4.0 / (M_PI * M_PI));
    for (const double mu1 : {75e9, 60e9}) {
        SCOPED_TRACE(mu1);
        const std::string modulus = "shear_modulus = " + number(mu1);
        const double beta = beta_of(mu1, 0.3, 82e9, 0.3);
        const std::vector<std::pair<std::string, std::string>> materials{
            {"shear_modulus = 23e9", modulus}, {"poisson = 0.31", "poisson = 0.3"}, {"poisson = 0.28", "poisson = 0.3"}};
        std::vector<std::pair<std::string, std::string>> coupled = materials;
        coupled.push_back({"coupling = \"johnson\"", "coupling = \"full\""});
        const std::string j = scene_with(materials), full = scene_with(coupled);
        ASSERT_FALSE(j.empty());
        ASSERT_FALSE(full.empty());
        const answered a = point_of(full, 1.0), b = point_of(j, 1.0);
        ASSERT_EQ(a.status, 0) << a.text;
        ASSERT_EQ(b.status, 0) << b.text;
        EXPECT_NEAR(a.out["beta_d"].get<double>(), beta, 1e-14);
        EXPECT_EQ(a.out["coupling"]["level"], "full");
        EXPECT_EQ(b.out["coupling"]["level"], "johnson");
        const double difference = a.out["xi"].get<double>() - b.out["xi"].get<double>();
        EXPECT_NEAR(difference / std::pow(beta, 3), coefficient, 0.01 * coefficient);
        EXPECT_LT(a.out["error_estimate"]["xi"].get<double>() + b.out["error_estimate"]["xi"].get<double>(),
                  1e-3 * std::fabs(difference));
        std::remove(j.c_str());
        std::remove(full.c_str());
    }
}

// The peak pressure of the no-slip route (8(t), "The peak pressure"; session 16 review N2: it was reported without an
// estimate). Its estimate is the reported peak's distance from the closed form's, (0, (2/pi) lambda cosh(pi eps)), plus
// the layers' peak bounds; at Johnson's level the pressure is Hertz's, (0, 2/pi), no bound. Checked here against the
// closed form written out (not the program's): the estimate covers the distance, is not vacuous (within 1e-4 of the
// peak at the default tolerance's range), and at n = 32 the interpolant's distance (2.1e-6) exceeds the layers' bound
// (9.2e-7) at f = 1: the two parts are both needed. On the old program error_estimate had no pressure_peak_r/p here.
// The layers' part is checked against the bounds' leading order in t = 2 t_c, worked out by hand from 8(t)'s
// formulas (session 17 review N2: the test had restated the program's own sum, coupled_no_slip_layers' bounds added
// to the distance). With kappa = 2, s = sqrt(1 + 4 eps^2), ch = cosh(pi eps): j = 3 c t, Lambda = 3 pi c t/s,
// D(0) = ch ((2/pi) Lambda + j) = 3 ch c t (1 + 2/s); at rho = 1/2, delta = 1/2: G = ch [s/(sqrt(3)/2) ((2/pi) Lambda
// + 2 j) + 4 j] = 12 ch c t (1 + (1 + s)/sqrt(3)), k = c cos(|eps| log 3), r_b = G/k (localised: r_b < 1/2), D(r_b) =
// D(0) (1 + O(r_b)). Each up to a relative O(t + r_b), below 1e-4 here; for the pair r_b = 26.2 t, D = 5.79 t (8(t):
// f = 1 gives 4.2e-6 and 9.2e-7). The estimate lies within 1e-3 of distance plus these.
TEST(NoSlipFull, PeakEstimatedOnTheRoute) {
    const std::string full = scene_with({{"coupling = \"johnson\"", "coupling = \"full\""}});
    ASSERT_FALSE(full.empty());
    const double eps = epsilon_of(beta_al_st);
    const double c = M_2_PI * lambda_of(eps) * std::cosh(M_PI * eps);
    for (const auto& [f, options] : {std::pair<double, std::string>{0.8, ""},
                                     {1.0, ""},
                                     {10.0, ""},
                                     {1e3, ""},
                                     {1.0, "--n 32 --method product"}}) {
        SCOPED_TRACE(f);
        SCOPED_TRACE(options);
        const answered a = point_of(full, f, options);
        ASSERT_EQ(a.status, 0) << a.text;
        ASSERT_EQ(a.out["zone_path"], "no-slip");
        const nlohmann::json& e = a.out["error_estimate"];
        ASSERT_TRUE(e.contains("pressure_peak_r") && e.contains("pressure_peak_p")) << a.out.dump();
        const double r = a.out["pressure_peak"]["r"], p = a.out["pressure_peak"]["p"];
        const double t = 2.0 * full_crossing(beta_al_st, f), s = std::sqrt(1.0 + 4.0 * eps * eps);
        const double ch = std::cosh(M_PI * eps);
        const double r_b =
            12.0 * ch * t * (1.0 + (1.0 + s) / std::sqrt(3.0)) / std::cos(std::fabs(eps) * std::log(3.0));
        const double D = 3.0 * ch * c * t * (1.0 + 2.0 / s);
        ASSERT_LT(r_b, 1e-4);  // localised near r = 0, and the leading order within 1e-4 relative
        const double er = e["pressure_peak_r"], ep = e["pressure_peak_p"];
        EXPECT_GE(er, std::fabs(r) + (1.0 - 1e-3) * r_b);
        EXPECT_LE(er, std::fabs(r) + (1.0 + 1e-3) * r_b);
        // The floors: the pressure's rounding (n eps c at n <= 1000, 32 eps c) within 1e-12.
        EXPECT_GE(ep, std::fabs(p - c) + (1.0 - 1e-3) * D);
        EXPECT_LE(ep, std::fabs(p - c) + (1.0 + 1e-3) * D + 1e-12);
        EXPECT_LE(er, 1e-4);
        EXPECT_LE(ep, 1e-4 * p);
        if (!options.empty()) {
            EXPECT_GT(std::fabs(p - c), 2.0 * D);  // the interpolant's part
        }
    }
    const std::string johnson = std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml";
    for (const double f : {0.31, 1.0, 10.0}) {
        SCOPED_TRACE(f);
        const answered a = point_of(johnson, f);
        ASSERT_EQ(a.status, 0) << a.text;
        ASSERT_EQ(a.out["zone_path"], "no-slip");
        const nlohmann::json& e = a.out["error_estimate"];
        ASSERT_TRUE(e.contains("pressure_peak_r") && e.contains("pressure_peak_p")) << a.out.dump();
        const double r = a.out["pressure_peak"]["r"], p = a.out["pressure_peak"]["p"];
        EXPECT_GE(e["pressure_peak_r"].get<double>(), std::fabs(r));
        EXPECT_GE(e["pressure_peak_p"].get<double>(), std::fabs(p - M_2_PI));
        EXPECT_LE(e["pressure_peak_r"].get<double>(), 1e-6);
        EXPECT_LE(e["pressure_peak_p"].get<double>(), 1e-12);
    }
    std::remove(full.c_str());
}

// The peak's bound against full coupling's own five zones (n = 256, product; f = 0.1 and 0.19, where they answer,
// 8(p)). Three checks, each on numbers the route does not use:
// 1. the pointwise inverse of 8(t) "The peak pressure" is an identity: dF(0) = F(0) - F_ns(0) of the five zones'
//    traction equals cosh(pi eps) W(0) [(2/pi) Delta lambda + (1/pi) int_out Y dF/eta] with their own zones, Delta
//    lambda and layers' dF (quadrature of the 8001 rows, linear between them, eta = end -+ u^2 at the main zone's
//    ends):
//    measured 4.6e-4 and 1.7e-3 relative (the rows' interpolation);
// 2. coupled_peak_bound with the five zones' measured inputs (thickness, J0, Delta lambda, the layers' largest |dF|)
//    bounds the distance of the five zones' peak from the closed form's, (0, c), up to the five zones' own peak
//    estimate; at f = 0.19 it localises the peak (measured: the bounds r 7.1e-3, p 9.6e-4 against the distances
//    1.0e-4 +- 2.7e-4 and 1.30e-4 +- 1.4e-7; at f = 0.1 not localised, p within 0.079 against 4.8e-4 +- 7.7e-6): the
//    peak moves with the layers, beyond its own estimate, and the bound covers it;
// 3. the route's bound at that f (the premises' inputs, coupled_no_slip_layers) holds too (there not localised: the
//    layers at f <= 0.19 are 10^4 times thicker than where the route answers), and the premises' inputs exceed the
//    measured ones (2.'s bound is the premises' formula on smaller inputs).
namespace {
void peak_within_the_bound(const std::string& scene, double beta, double f) {
    using cplx = std::complex<double>;
    const double eps = epsilon_of(beta), lambda_ns = lambda_of(eps);
    const double c = M_2_PI * lambda_ns * std::cosh(M_PI * eps);
    const traction_table t = traction_of(scene, f, 256, 8001);
    const answered o = point_of(scene, f, "--n 256 --method product");
    ASSERT_EQ(o.status, 0) << o.text;
    ASSERT_EQ(t.zones.size(), 5u);
    ASSERT_TRUE(o.out["error_estimate"].contains("pressure_peak_p")) << o.out.dump();
    const double a = t.zones[1].second.first, b = t.zones[1].second.second;
    const auto f_ns = [&](double r) {
        return std::fabs(r) < 1.0
                   ? c * std::sqrt((1.0 + r) * (1.0 - r)) * std::polar(1.0, eps * std::log((1.0 + r) / (1.0 - r)))
                   : cplx(0.0);
    };
    std::vector<cplx> dF(t.r.size());
    double layer_sup = 0.0;
    std::size_t centre = 0;
    for (std::size_t i = 0; i < t.r.size(); ++i) {
        dF[i] = cplx(t.p[i], -t.p1[i]) - f_ns(t.r[i]);
        if (t.r[i] < a || t.r[i] > b) layer_sup = std::max(layer_sup, std::abs(dF[i]));
        if (std::fabs(t.r[i]) < std::fabs(t.r[centre])) centre = i;
    }
    ASSERT_EQ(t.r[centre], 0.0);
    const auto dF_at = [&](double x) {  // linear between the rows (uniform)
        const double h = t.r[1] - t.r[0];
        const std::size_t k = std::min(t.r.size() - 2, static_cast<std::size_t>(std::max(0.0, (x - t.r[0]) / h)));
        const double w = (x - t.r[k]) / (t.r[k + 1] - t.r[k]);
        return dF[k] * (1.0 - w) + dF[k + 1] * w;
    };
    // Y = (eta - a)^(-1/2 - i eps) (eta - b)^(-1/2 + i eps) off the cut [a, b]: -|..| |..| before a, + after b.
    const auto Y = [&](double eta) {
        const cplx y =
            std::pow(cplx(std::fabs(eta - a)), cplx(-0.5, -eps)) * std::pow(cplx(std::fabs(eta - b)), cplx(-0.5, eps));
        return eta < a ? -y : y;
    };
    cplx I = 0.0;
    double J0 = 0.0;
    for (const bool lead : {true, false}) {
        const double length = std::sqrt(lead ? 1.0 + a : 1.0 - b);
        constexpr int N = 20000;
        const double h = length / N;
        for (int k = 0; k < N; ++k) {
            const double u = (k + 0.5) * h, eta = lead ? a - u * u : b + u * u;
            const cplx v = Y(eta) * dF_at(eta) * (2.0 * u * h);
            I += v / eta;
            J0 += std::abs(v);
        }
    }
    const double dlambda = t.lambda - lambda_ns;
    const cplx W0 = std::pow(cplx(-a), cplx(0.5, eps)) * std::pow(cplx(b), cplx(0.5, -eps));
    const cplx represented = std::cosh(M_PI * eps) * W0 * (M_2_PI * dlambda + I / M_PI);
    EXPECT_LT(std::abs(represented - dF[centre]), 4e-3 * std::abs(dF[centre])) << represented << " " << dF[centre];
    // 2.: the bound on the measured inputs.
    const double thickness = std::max(1.0 + a, 1.0 - b);
    const roughroll::layers_peak measured =
        roughroll::coupled_peak_bound(eps, c, thickness, J0 / M_PI, std::fabs(dlambda), layer_sup);
    const double r5 = o.out["pressure_peak"]["r"], p5 = o.out["pressure_peak"]["p"];
    const double er = o.out["error_estimate"]["pressure_peak_r"], ep = o.out["error_estimate"]["pressure_peak_p"];
    if (f > 0.15) {  // thin enough layers to localise the peak (t_c = 0.034; at f = 0.1, 0.21, they are not)
        EXPECT_LT(measured.r, 0.5);
    }
    EXPECT_LE(std::fabs(r5), measured.r + er);
    EXPECT_LE(std::fabs(p5 - c), measured.p + ep);
    EXPECT_GT(std::fabs(p5 - c), 10.0 * ep);  // the peak did move, beyond its own estimate: the bound is what covers it
    // 3.: the route's bound (the premises) and its inputs against the measured ones.
    const roughroll::neglected_layers l = roughroll::coupled_no_slip_layers(beta, f);
    const double tp = l.thickness;
    EXPECT_LT(thickness, tp);
    EXPECT_LT(J0 / M_PI, (1.0 + roughroll::kappa_layers) * c * tp / std::sqrt(1.0 - tp));
    EXPECT_LT(std::fabs(dlambda), l.lambda_bound);
    EXPECT_LT(layer_sup, (1.0 + roughroll::kappa_layers) * c * std::sqrt(2.0 * tp));
    EXPECT_LE(std::fabs(r5), l.peak_r_bound + er);
    EXPECT_LE(std::fabs(p5 - c), l.peak_p_bound + ep);
}
}  // namespace

TEST(NoSlipFull, PeakBoundHoldsAgainstTheFiveZones) {
    const std::string full = scene_with({{"coupling = \"johnson\"", "coupling = \"full\""}});
    ASSERT_FALSE(full.empty());
    for (const double f : {0.1, 0.19}) {
        SCOPED_TRACE(f);
        peak_within_the_bound(full, beta_al_st, f);
    }
    std::remove(full.c_str());
}

// The route's choice and the ladder's check see one sum (session 16 review N6): the choice compared the layers' bounds
// alone (xi_bound/|xi|, t, the P_H/P2 bound over P_H/P2) with the tolerance, the ladder the estimate, which adds the
// rounding (4 eps |xi|, n eps P_H/P2). At a tolerance equal to the bounds' ratio (f = 1: 6.2230580936e-6) the old
// program chose the route and then refused every rung ("no n up to 1000 meets the tolerance ... 6.2230580945e-6
// relative"); now the choice takes the estimate's ratio (neglected_layers_relative): there the point is refused before
// any rung with the advice naming the tolerance that answers, and at the estimate's own ratio it is answered.
TEST(NoSlipFull, RouteChosenAsTheLadderChecksIt) {
    const std::string full = scene_with({{"coupling = \"johnson\"", "coupling = \"full\""}});
    ASSERT_FALSE(full.empty());
    const answered a = point_of(full, 1.0);
    ASSERT_EQ(a.status, 0) << a.text;
    const nlohmann::json& l = a.out["edge_layers"];
    const nlohmann::json& e = a.out["error_estimate"];
    const double xi = std::fabs(a.out["xi"].get<double>()), lambda = a.out["hertz_load_ratio"];
    const double bounds = std::max({l["xi_bound"].get<double>() / xi, l["thickness_bound"].get<double>(),
                                    l["hertz_load_ratio_bound"].get<double>() / lambda});
    const double estimate = std::max({e["xi"].get<double>() / xi, e["hertz_load_ratio"].get<double>() / lambda,
                                      e["c0"].get<double>(), e["stick_start"].get<double>()});
    ASSERT_LT(bounds, estimate);  // the rounding the bounds leave out
    const answered below = point_of(full, 1.0, "--tolerance " + number(bounds));
    EXPECT_NE(below.status, 0);
    EXPECT_EQ(below.text.find("no n up to 1000 meets"), std::string::npos) << below.text;
    EXPECT_NE(below.text.find("a tolerance of 6.3e-06 or more"), std::string::npos) << below.text;
    // The ladder compares each estimate at the largest n, whose rounding floor is the largest: within 2 %.
    const answered at = point_of(full, 1.0, "--tolerance " + number(estimate * 1.02));
    ASSERT_EQ(at.status, 0) << at.text;
    EXPECT_EQ(at.out["zone_path"], "no-slip");
    std::remove(full.c_str());
}
