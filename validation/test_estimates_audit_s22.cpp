// SPDX-License-Identifier: GPL-3.0-or-later
// Session 22's audit of the printed estimates (issue 24, "every estimate a bound"), continuing session 21's
// (validation/test_estimates_audit_s21.cpp) at points it did not reach: `point ... --json` at the default settings
// (no n: the ladder's rung, docs/formulation.md 8(q)) against the product solution at n = 1000 of the same load, for
// every quantity the JSON key error_estimate holds. Each must hold |answer - reference| <= estimate + the reference's
// own estimate (every estimate is absolute, in its quantity's units: error_estimate.hpp).
// The rough pair's references at n = 1000 (Johnson's level, driven) take about 3 min CPU each, too much to solve in
// every run: they are stored below (value and its own estimate, all digits), measured in session 22 on main b077a23
// (Release, `point SCENE LOAD --method product --n 1000 --json`) and listed in docs/robustness.md ("Session 22: the
// points session 21 did not reach"), and solved again only by the large_n case StoredReferencesSolvedAgain; the default
// answers are solved here, so a change of the ladder, the estimates or the solvers that moves an answer outside its
// estimate fails the test. The smooth pair at full coupling near sliding has a cheap
// reference, solved here. The test can fail: on the rows the reference can tell (its own estimate under a tenth of the
// distance), an estimate 16 times smaller (Richardson's |x_n - x_{n/2}|/15 at order 4, or less) under-reports xi at
// Q/f = 0.05, which the test checks. Not here: the under-report the audit found (the rough pair at full coupling braked
// at Q/f = -0.99, docs/robustness.md), mended and tested in validation/test_sign_change_s22.cpp.
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "command_output.hpp"

namespace {

struct stored {
    const char* key;
    double value;     // the product solution at n = 1000
    double estimate;  // its own printed estimate
};

struct comparison {
    std::string key;
    double estimate, distance, reference_estimate;
};

double value_of(const nlohmann::json& o, const std::string& key) {
    if (key == "pressure_peak_p") return o["pressure_peak"]["p"].get<double>();
    if (key == "pressure_peak_r") return o["pressure_peak"]["r"].get<double>();
    return o[key].get<double>();
}

std::string data(const std::string& name) { return std::string(ROUGHROLL_DATA) + "/" + name; }

// The default answer of `path` at `load` against the stored reference: one comparison per estimate printed, each
// asserted to bound its distance with the reference's estimate added; every stored key must be printed.
std::vector<comparison> audit(const std::string& path, const std::string& load, const std::vector<stored>& reference) {
    const command_output o =
        run_command(std::string(ROUGHROLL_CLI) + " point " + path + " " + load + " --json --quiet");
    EXPECT_EQ(o.status, 0) << load << "\n" << o.text;
    std::vector<comparison> out;
    if (o.status != 0) return out;
    const nlohmann::json a = nlohmann::json::parse(o.text);
    EXPECT_TRUE(a["checks_hold"].get<bool>()) << load;
    const auto& e = a["error_estimate"];
    EXPECT_TRUE(e.is_object()) << load << ": no estimate printed";
    if (!e.is_object()) return out;
    for (const stored& s : reference) {
        EXPECT_TRUE(e.contains(s.key)) << load << " " << s.key;
        if (!e.contains(s.key)) continue;
        const comparison c{s.key, e[s.key].get<double>(), std::fabs(value_of(a, s.key) - s.value), s.estimate};
        std::printf("%-24s n = %4d %-16s estimate %.3g distance %.3g (reference's estimate %.3g)\n", load.c_str(),
                    a["n"].get<int>(), s.key, c.estimate, c.distance, c.reference_estimate);
        EXPECT_LE(c.distance, c.estimate + c.reference_estimate) << load << " " << s.key;
        out.push_back(c);
    }
    return out;
}

// As `audit`, against the product solution at n = 1000 solved here (points whose reference is cheap).
std::vector<comparison> audit_live(const std::string& path, const std::string& load) {
    const command_output o = run_command(std::string(ROUGHROLL_CLI) + " point " + path + " " + load +
                                         " --method product --n 1000 --json --quiet");
    EXPECT_EQ(o.status, 0) << load << " at n = 1000\n" << o.text;
    if (o.status != 0) return {};
    const nlohmann::json r = nlohmann::json::parse(o.text);
    const auto& er = r["error_estimate"];
    EXPECT_TRUE(er.is_object()) << load << " at n = 1000: no estimate printed";
    if (!er.is_object()) return {};
    std::vector<stored> reference;
    for (const char* key : {"c0", "stick_start", "xi", "hertz_load_ratio", "pressure_peak_p", "pressure_peak_r"})
        if (er.contains(key)) reference.push_back({key, value_of(r, key), er[key].get<double>()});
    return audit(path, load, reference);
}

// How many of the rows the reference can tell (its estimate under a tenth of the distance) an estimate 16 times
// smaller would under-report.
int caught_if_sixteen_times_smaller(const std::vector<comparison>& rows, int& told) {
    int caught = 0;
    told = 0;
    for (const auto& c : rows) {
        if (c.reference_estimate >= 0.1 * c.distance) continue;
        ++told;
        if (c.distance > c.estimate / 16.0 + c.reference_estimate) ++caught;
    }
    return caught;
}

// The stored references (docs/robustness.md, "Session 22: the points session 21 did not reach").
const std::vector<stored> driven_005 = {
    // product, n = 1000, Q/f = 0.05 (session 22, main b077a23)
    {"c0", 0.57202098414054725, 7.8315765966929163e-09},
    {"stick_start", -0.81988251551811842, 7.8824896482453866e-09},
    {"xi", -0.059958305307663287, 1.3956496286238954e-12},
    {"hertz_load_ratio", 1.4726672424352603, 6.8652565242118884e-11},
    {"pressure_peak_p", 0.64595559510646827, 1.0986128934234104e-11},
    {"pressure_peak_r", -2.2351666799300804e-08, 1.5417084328510231e-07},
};
const std::vector<stored> driven_03 = {
    // product, n = 1000, Q/f = 0.3
    {"c0", 0.17543926753097794, 7.9564481274418285e-09},
    {"stick_start", -0.85753692795888492, 8.0373378667929927e-09},
    {"xi", -0.048435051884757593, 1.0230119848991671e-12},
    {"hertz_load_ratio", 1.4726672424352603, 6.8652565242118884e-11},
    {"pressure_peak_p", 0.64595559510646827, 1.0986128934234104e-11},
    {"pressure_peak_r", -2.2351666799300804e-08, 1.5417084328510231e-07},
};

}  // namespace

// The rough pair (data/aluminium-on-steel-rough.toml) at Johnson's level, driven at Q/f = 0.05 and 0.3 (session 21's
// references at n = 1000 did not finish there): the ladder answers at n = 128 in about 5 s CPU each; the references
// took 194 s and 185 s CPU (five zones at Q/f = 0.05, three at 0.3). xi holds its estimate by factors 11.6 and 57
// against references 100 times closer (their xi to 1.4e-12 and 1.0e-12), the start by 61 and 40, the peak pressure by
// 17 (reference 1.1e-11), c0 by 470 and 580 (reference 8e-9: the zone ends' rounding floor at n = 1000, 8(q)).
TEST(EstimatesAuditS22, RoughPairDrivenWithinTheirEstimates) {
    std::vector<comparison> all = audit(data("aluminium-on-steel-rough.toml"), "--Q-over-f 0.05", driven_005);
    for (const auto& c : audit(data("aluminium-on-steel-rough.toml"), "--Q-over-f 0.3", driven_03)) all.push_back(c);
    EXPECT_EQ(all.size(), 12u);
    int told = 0;
    const int caught = caught_if_sixteen_times_smaller(all, told);
    std::printf("an estimate 16 times smaller under-reports %d of the %d rows the reference can tell\n", caught, told);
    EXPECT_GE(caught, 1);  // measured: xi at Q/f = 0.05 (distance 3.8e-10, estimate 4.4e-9)
}

// The smooth pair at full coupling driven at Q/f = 0.99 (three zones; session 21 did not reach it): the ladder answers
// at n = 512, and the reference at n = 1000 is cheap (about 3 s CPU), so it is solved here. Measured on b077a23: c0
// 456, xi 1.7e3, P_H/P2 10.6, the peak pressure 18.4 times their distances, the start 2.2 and the peak position 2.3
// (both within the reference's own estimates, 1.2e-6 and 4.5e-5).
TEST(EstimatesAuditS22, FullCouplingDrivenNearSlidingWithinItsEstimates) {
    const std::string full = changed_scene(data("aluminium-on-steel.toml"),
                                           {{"coupling = \"johnson\"", "coupling = \"full\""}}, "roughroll-audit-s22");
    ASSERT_FALSE(full.empty());
    const std::vector<comparison> rows = audit_live(full, "--Q-over-f 0.99");
    std::remove(full.c_str());
    EXPECT_EQ(rows.size(), 6u);
}

// The stored rows are not stale: the references at n = 1000 solved again, each stored value within the estimates of
// the stored and the new solution together (each bounds its own distance from the exact value, so the two can be no
// further apart). A change of the solvers that moves a reference by more fails here, before the comparisons above
// silently use a wrong reference. large_n: two references at n = 1000, about 190 s CPU each.
TEST(EstimatesAuditS22, StoredReferencesSolvedAgain) {
    for (const auto& [load, reference] :
         {std::pair<std::string, const std::vector<stored>*>{"--Q-over-f 0.05", &driven_005},
          std::pair<std::string, const std::vector<stored>*>{"--Q-over-f 0.3", &driven_03}}) {
        const command_output o =
            run_command(std::string(ROUGHROLL_CLI) + " point " + data("aluminium-on-steel-rough.toml") + " " + load +
                        " --method product --n 1000 --json --quiet");
        ASSERT_EQ(o.status, 0) << load << "\n" << o.text;
        const nlohmann::json r = nlohmann::json::parse(o.text);
        for (const stored& s : *reference) {
            const double now = value_of(r, s.key), now_estimate = r["error_estimate"][s.key].get<double>();
            std::printf("%-16s %-16s stored %.17g now %.17g (estimates %.3g, %.3g)\n", load.c_str(), s.key, s.value,
                        now, s.estimate, now_estimate);
            EXPECT_LE(std::fabs(now - s.value), s.estimate + now_estimate) << load << " " << s.key;
        }
    }
}
