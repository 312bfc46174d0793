// SPDX-License-Identifier: GPL-3.0-or-later
// `roughroll point --json` at the five-zone loads of dissimilar rollers (docs/formulation.md 8(j)):
// free rolling and Bentall and Johnson's driven Q/f = +0.75 (f = 0.05, data/aluminium-on-steel.toml,
// n = 32), against the library's own search (dissimilar_zones::five_zones without a guess), which
// validate_dissimilar_five_zones checks against the grid route. The CLI reaches its level n from
// the coarser levels' ends; both are roots of the same equations, so they agree to Newton's resolution.
#include <cmath>
#include <cstdio>
#include <string>

#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "aluminium_on_steel.hpp"
#include "command_output.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"

using namespace roughroll;

namespace {
struct run_result {
    int status;
    nlohmann::json out;
};

run_result run_point(double Q, const char* scene = "aluminium-on-steel.toml", int n = 32) {
    const std::string command = std::string(ROUGHROLL_CLI) + " point " + ROUGHROLL_DATA + "/" + scene + " --n " +
                                std::to_string(n) + " --Q " + std::to_string(Q) + " --json";
    const command_output o = run_command(command);
    return {o.status, o.text.empty() ? nlohmann::json{} : nlohmann::json::parse(o.text)};
}

void agrees(double Q) {
    const double f = 0.05;
    contact c(roughness{}, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    dissimilar_zones d(tangential_of(c), kernel::tangential(roughness{}), beta_al_st);
    const auto s = d.five_zones(Q);
    ASSERT_TRUE(s);
    ASSERT_TRUE(s->checks.hold());
    const run_result r = run_point(Q);
    ASSERT_EQ(r.status, 0);
    const nlohmann::json& j = r.out;
    std::printf("Q/f = %.2f: CLI xi %.12f, library %.12f; stick [%.9f, %.9f], [%.9f, %.9f]\n", Q / f,
                j["xi"].get<double>(), s->xi, s->start(), s->c0(), s->start2(), s->end2());
    EXPECT_TRUE(j["checks_hold"].get<bool>());
    EXPECT_TRUE(j["checks"]["stick_traction_bound_3_3"].get<bool>());
    EXPECT_TRUE(j["checks"]["slip_velocity_positive_3_4"].get<bool>());
    // The load asked for (as the decimal given on the command line), not Newton's solved one.
    EXPECT_DOUBLE_EQ(j["Q"].get<double>(), Q);
    EXPECT_NEAR(j["beta_d"].get<double>(), beta_al_st, 1e-12);  // the materials', as for three zones
    EXPECT_NEAR(j["xi"].get<double>(), s->xi, 1e-10);
    EXPECT_NEAR(j["stick_start"].get<double>(), s->start(), 1e-9);
    EXPECT_NEAR(j["c0"].get<double>(), s->c0(), 1e-9);
    const nlohmann::json& z = j["zones"];
    ASSERT_EQ(z.size(), 5u);
    const double ends[] = {-1.0, s->start(), s->c0(), s->start2(), s->end2(), 1.0};
    const char* states[] = {"slip", "stick", "slip", "stick", "slip"};
    const int directions[] = {-1, 0, 1, 0, -1};  // beta_D > 0: slip-, stick, slip+, stick, slip- (8(j))
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_NEAR(z[k]["from"].get<double>(), ends[k], 1e-9) << k;
        EXPECT_NEAR(z[k]["to"].get<double>(), ends[k + 1], 1e-9) << k;
        EXPECT_EQ(z[k]["state"].get<std::string>(), states[k]) << k;
        EXPECT_EQ(z[k]["direction"].get<int>(), directions[k]) << k;
    }
    // An honest estimate on three levels, the ends within Newton's resolution and the levels' spread.
    ASSERT_TRUE(j["error_estimate"].is_object());
    EXPECT_GT(j["error_estimate"]["xi"].get<double>(), 0.0);
    EXPECT_LT(j["error_estimate"]["xi"].get<double>(), 1e-6);
}
}  // namespace

TEST(FiveZonePoints, FreeRolling) { agrees(0.0); }
TEST(FiveZonePoints, DrivenBentallJohnson) { agrees(0.75 * 0.05); }

// The rough pair's free rolling at n = 64: its levels n/4, n/2, n = 16, 32, 64 do not converge
// visibly in the second stick zone's end (level 16 happens to lie close to 32), and n = 32 shares
// that set (n/4 = 8 is below the asymptotic range). The second chance one level finer (32, 64, 128)
// answers, and its estimates bound the distance to the n = 128 point plus that point's own estimate.
// Refused before the second chance.
TEST(FiveZonePoints, RoughPairSecondChanceBoundsTheError) {
    const run_result r = run_point(0.0, "aluminium-on-steel-rough.toml", 64);
    ASSERT_EQ(r.status, 0);
    const run_result fine = run_point(0.0, "aluminium-on-steel-rough.toml", 128);
    ASSERT_EQ(fine.status, 0);
    const nlohmann::json& e = r.out["error_estimate"];
    ASSERT_TRUE(e.is_object());
    EXPECT_NE(e["against"].get<std::string>().find("n/2, n, 2n where n/4 fell short"), std::string::npos);
    ASSERT_EQ(r.out["zones"].size(), 5u);
    const auto end2 = [](const nlohmann::json& j) { return j["zones"][3]["to"].get<double>(); };
    std::printf("n = 64: xi %.12f +- %.2e, c0 %.10f +- %.2e, end2 %.10f; n = 128: %.12f, %.10f, %.10f\n",
                r.out["xi"].get<double>(), e["xi"].get<double>(), r.out["c0"].get<double>(), e["c0"].get<double>(),
                end2(r.out), fine.out["xi"].get<double>(), fine.out["c0"].get<double>(), end2(fine.out));
    // |error of n = 64| <= |v64 - v128| + (n = 128's own bound): that sum must stay within n = 64's bound.
    const nlohmann::json& e_fine = fine.out["error_estimate"];
    auto within = [&](double coarse, double finer, double bound_fine, double bound, const char* what) {
        EXPECT_LE(std::fabs(coarse - finer) + bound_fine, bound) << what;
    };
    within(r.out["xi"].get<double>(), fine.out["xi"].get<double>(), e_fine["xi"].get<double>(), e["xi"].get<double>(),
           "xi");
    within(r.out["c0"].get<double>(), fine.out["c0"].get<double>(), e_fine["c0"].get<double>(), e["c0"].get<double>(),
           "c0");
    within(end2(r.out), end2(fine.out), e_fine["c0"].get<double>(), e["c0"].get<double>(),
           "the second stick zone's end (its bound folded into c0's)");
    within(r.out["stick_start"].get<double>(), fine.out["stick_start"].get<double>(),
           e_fine["stick_start"].get<double>(), e["stick_start"].get<double>(), "stick start");
}

// A refusal that needs a solve first (moved here from tests/cli_bad_input.sh, whose rows must be
// refused before any solve: this one took 60 s under the sanitizers on a busy machine): free
// rolling of the pair at f = 0.2 and n = 16, whose five zones' edge layers are thinner than the
// collocation resolves (docs/formulation.md 8(j) 4a). Exit 2, one stderr line, nothing on stdout.
TEST(FiveZonePoints, ZoneBelowResolutionIsOneLineAndExitTwo) {
    char folder[] = "/tmp/roughroll-refusal-XXXXXX";
    ASSERT_NE(mkdtemp(folder), nullptr);
    const std::string dir = folder, scene = dir + "/betawide.toml";
    {
        FILE* out = std::fopen(scene.c_str(), "w");
        ASSERT_NE(out, nullptr);
        std::fputs("friction = 0.2\nbeta_d = 0.14\nQ = 0.0\n[solver]\nn = 16\nmethod = \"product\"\n", out);
        std::fclose(out);
    }
    const std::string command = std::string(ROUGHROLL_CLI) + " point " + scene + " >" + dir + "/out 2>" + dir + "/err";
    const int status = std::system(command.c_str());
    const auto slurp = [](const std::string& path) {
        std::string text;
        if (FILE* in = std::fopen(path.c_str(), "r")) {
            char buffer[4096];
            while (const std::size_t got = std::fread(buffer, 1, sizeof buffer, in)) text.append(buffer, got);
            std::fclose(in);
        }
        return text;
    };
    const std::string out = slurp(dir + "/out"), err = slurp(dir + "/err");
    std::printf("%s", err.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    EXPECT_TRUE(out.empty());
    ASSERT_FALSE(err.empty());
    EXPECT_EQ(err.find('\n'), err.size() - 1) << "one line";
    EXPECT_NE(err.find("resolution"), std::string::npos);
    std::remove((dir + "/out").c_str());
    std::remove((dir + "/err").c_str());
    std::remove(scene.c_str());
    rmdir(folder);
}
