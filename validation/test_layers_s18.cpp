// SPDX-License-Identifier: GPL-3.0-or-later
// The no-slip route of full coupling checks where it models the contact (docs/formulation.md 8(t), "Wired"), so the
// tolerance its refusal names answers; and a curve's rows at a given n say what to change, as a point does.
#include <cmath>
#include <cstdio>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "roughroll/base/error.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/no_slip_coupled.hpp"
#include "roughroll/problems/zone_checks.hpp"

#include "command_output.hpp"

namespace {
// Dundurs' beta_D of two materials (8(a)).
double beta_of(double mu1, double nu1, double mu2, double nu2) {
    const double C = (1.0 - nu1) / mu1 + (1.0 - nu2) / mu2;
    return ((1.0 - 2.0 * nu1) / mu1 - (1.0 - 2.0 * nu2) / mu2) / (2.0 * C);
}

// A smooth pair with beta_D = 0.498 (a soft roller 1 with nu = 0 on a stiff one) at full coupling: its limit's tension
// reaches t_inf = 2.4e-4 from the edges (8(t) "Where the limit is an approximation", item 2), beyond the check grid's
// outer points (3.1e-5 from them).
std::string pair_498() {
    return changed_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml",
                         {{"coupling = \"johnson\"", "coupling = \"full\""},
                          {"shear_modulus = 23e9", "shear_modulus = 1e9"},
                          {"poisson = 0.31", "poisson = 0.0"},
                          {"shear_modulus = 82e9", "shear_modulus = 274e9"},
                          {"poisson = 0.28", "poisson = 0.3"}},
                         "roughroll-layers-s18");
}

command_output point_of(const std::string& scene, const std::string& options) {
    return run_command(std::string(ROUGHROLL_CLI) + " point " + scene + " --Q 0 --friction 10 " + options + " 2>&1");
}

// The tolerance a refusal names for the no-slip route, "a tolerance of X or more (...; n not given)"; 0 where none.
double advised_tolerance(const std::string& text) {
    const std::regex advice(R"(a tolerance of ([0-9.e+-]+) or more \(solver\.tolerance, --tolerance; n not given\))");
    std::smatch m;
    return std::regex_search(text, m, advice) ? std::stod(m[1]) : 0.0;
}
}  // namespace

// Session 17's report: at beta_D = 0.498, f = 10 the refusal advised "a tolerance of 0.015 or more", and at 0.015 and
// 0.02 the route was chosen and then refused ("the checks (3.3)-(3.4) fail"): p >= 0 was checked on all of (-1, 1),
// where the limit's interpolated pressure is negative within t_inf of the edges, inside the neglected layers. Now the
// route checks p >= 0 where it checks (3.3)-(3.4), on [-1 + t, 1 - t]. The advice followed, with no n and with the
// n given left out as it says, answers; so does a larger tolerance. Fails on the old program (refused at the advice).
TEST(LayersS18, NoSlipRouteAnswersAtTheToleranceItsRefusalNames) {
    ASSERT_NEAR(beta_of(1e9, 0.0, 274e9, 0.3), 0.498, 1e-5);
    const std::string scene = pair_498();
    ASSERT_FALSE(scene.empty());
    for (const std::string& given : {std::string(), std::string("--n 128")}) {
        SCOPED_TRACE(given);
        const command_output refused = point_of(scene, given);
        ASSERT_NE(refused.status, 0) << refused.text;
        const double advised = advised_tolerance(refused.text);
        ASSERT_GT(advised, 0.0) << refused.text;
        ASSERT_LT(advised, 0.02) << refused.text;
        for (const double tolerance : {advised, 0.02}) {
            SCOPED_TRACE(tolerance);
            const command_output o = point_of(scene, "--tolerance " + std::to_string(tolerance) + " --json");
            ASSERT_EQ(o.status, 0) << o.text;
            const nlohmann::json out = nlohmann::json::parse(o.text);
            EXPECT_EQ(out["zone_path"], "no-slip");
            EXPECT_TRUE(out["checks_hold"].get<bool>()) << out["checks"].dump();
            EXPECT_GT(out["checks"]["pressure_margin"].get<double>(), 0.0);
        }
    }
    std::remove(scene.c_str());
}

// What the rule leaves out is inside the layers and inside the route's estimates (8(t), "Wired"). The limit at
// beta_D = 0.498, f = 10 (closed form of 8(p), no_slip_coupled at n = 0), its pressure reported at n = 128
// (no_slip_normal): (1) the old rule's p >= 0 on the grid of (-1, 1) fails (the reason the advice did not answer), the
// new one on [-1 + t, 1 - t] holds; (2) the tension lies within t_inf < t_c < t of the edges (atan f < pi/2), checked
// on the closed form written out here, p_ns = c sqrt(1 - r^2) cos(eps log((1 + r)/(1 - r))); (3) it is inside the
// premise's bound of the layers' |F - F_ns| <= (1 + kappa) c sqrt(x (2 - x)) that the estimates of xi, P_H/P2 and the
// peak rest on (|p_ns| <= c sqrt(x (2 - x)) and the model's p >= 0), and its load (both edges, by quadrature of the
// closed form) is below 1e-3 of the P_H/P2 bound.
TEST(LayersS18, LimitsTensionLiesInsideTheLayersAndTheEstimates) {
    const double beta = 0.498, f = 10.0;
    const roughroll::no_slip_coupled_solution limit = roughroll::no_slip_coupled(beta, {}, {}, 0);
    const roughroll::neglected_layers layers = roughroll::coupled_no_slip_layers(beta, f);
    const double eps = std::log((1.0 - beta) / (1.0 + beta)) / (2.0 * M_PI);
    const double lambda = 1.0 / (1.0 + 4.0 * eps * eps);
    const double c = M_2_PI * lambda * std::cosh(M_PI * eps);
    const auto p_ns = [&](double x, bool leading) {  // at distance x from an edge
        return c * std::sqrt(x * (2.0 - x)) * std::cos(eps * std::log(leading ? x / (2.0 - x) : (2.0 - x) / x));
    };
    const double t_inf = 2.0 / (1.0 + std::exp(M_PI / (2.0 * std::fabs(eps))));
    const double t = layers.thickness;
    ASSERT_LT(t_inf, layers.crossing);
    ASSERT_LT(layers.crossing, t);
    const roughroll::normal_solution reported = roughroll::no_slip_normal(limit, 128, roughroll::method::extrapolated);
    EXPECT_LT(roughroll::least_pressure(reported), 0.0);  // the old rule
    EXPECT_GT(roughroll::least_pressure(reported, -1.0 + t, 1.0 - t), 0.0);
    EXPECT_NEAR(limit.pressure(-1.0 + 1e-3), p_ns(1e-3, true), 1e-12);  // the closed form is the limit's
    // (2), (3): on a grid in log x from 1e-16 to t, both edges.
    constexpr int N = 20000;
    double least = 0.0, tension_load = 0.0;
    for (const bool leading : {true, false}) {
        for (int k = 0; k < N; ++k) {
            const double u = std::log(1e-16) + (std::log(t) - std::log(1e-16)) * (k + 0.5) / N;
            const double x = std::exp(u), dx = x * (std::log(t) - std::log(1e-16)) / N;
            const double p = p_ns(x, leading);
            if (p < 0.0) {
                EXPECT_LT(x, t_inf * (1.0 + 1e-9)) << x;
                EXPECT_LE(-p, c * std::sqrt(x * (2.0 - x)) * (1.0 + 1e-12));
                least = std::min(least, p);
                tension_load -= p * dx;
            }
        }
    }
    EXPECT_LT(least, 0.0);  // the tension was sampled
    EXPECT_LT(-least, (1.0 + roughroll::kappa_layers) * c * std::sqrt(2.0 * t));
    EXPECT_LT(tension_load, 2.0 * 2.0 * M_SQRT2 / 3.0 * c * std::pow(t_inf, 1.5));  // 8(t) item 2's bound
    EXPECT_LT(tension_load, 1e-3 * layers.lambda_bound);
}

// Session 17 gave a point at a given n whose refusal names nothing to change (unadvised_refusal: no three zones at
// this n) the ladder's advice (RefusedRows.AGivenNsUnadvisedRefusalSaysWhatToChange); a curve's row at a given n
// printed the bare line. The rough pair braked at f = 0.5, Q/f = -0.75, n = 128, as a curve's one row (6 s CPU). Fails
// on the old program (no "at the given n").
TEST(LayersS18, CurveRowAtAGivenNSaysWhatToChange) {
    roughroll::scene s = roughroll::read_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel-rough.toml");
    s.friction = 0.5;
    roughroll::override_solver(s, 128, std::nullopt);
    const roughroll::scene_curve curve = roughroll::curve_of(s, std::vector<double>{-0.375}, 1, false);
    ASSERT_EQ(curve.rows.size(), 1u);
    ASSERT_TRUE(curve.rows[0].is_refused());
    const std::string& why = curve.rows[0].refused;
    EXPECT_NE(why.find("no three zones"), std::string::npos) << why;
    EXPECT_NE(why.find("at the given n = 128: a larger n"), std::string::npos) << why;
    EXPECT_NE(why.find("leave n out"), std::string::npos) << why;
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}
