// SPDX-License-Identifier: GPL-3.0-or-later
// The audits of the printed estimates (issue 24, "every estimate a bound"; validation/test_estimates_audit_s22.cpp,
// _s23.cpp): `point ... --json` against a reference, the product solution at n = 1000 of the same load, for every
// quantity the JSON key error_estimate holds. Each must hold |answer - reference| <= estimate + the reference's own
// estimate: every estimate is absolute, in its quantity's units (error_estimate.hpp), and bounds its own distance from
// the exact value, so the two together bound the distance between the answer and the reference.
// The programs that include this define ROUGHROLL_CLI and ROUGHROLL_DATA (validation/CMakeLists.txt, Makefile.am).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "command_output.hpp"

namespace estimates_audit {

struct stored {
    const char* key;
    double value;     // the product solution at n = 1000
    double estimate;  // its own printed estimate
};

struct comparison {
    std::string key;
    double estimate, distance, reference_estimate;
};

// Every quantity with an estimate in the JSON output, in the order the audits print them.
inline const char* const keys[] = {"c0", "stick_start", "xi", "hertz_load_ratio", "pressure_peak_p", "pressure_peak_r"};

// With the second stick zone's ends of a five-zone answer (validation/test_rough_five_zones_s22.cpp), which have no
// estimate of their own: they fold into the start's and c0's (zone_ends_table), as estimate_key says.
inline const char* const five_zone_keys[] = {"c0",       "stick_start",       "second_stick_from", "second_stick_to",
                                             "xi",       "hertz_load_ratio",  "pressure_peak_p",   "pressure_peak_r"};

// The second stick zone's `end` ("from" or "to") of a five-zone answer (a failed expectation and NaN where none).
inline double second_stick(const nlohmann::json& o, const char* end) {
    int stick = 0;
    for (const auto& z : o["zones"])
        if (z["state"] == "stick" && ++stick == 2) return z[end].get<double>();
    ADD_FAILURE() << "no second stick zone";
    return NAN;
}

inline double value_of(const nlohmann::json& o, const std::string& key) {
    if (key == "pressure_peak_p") return o["pressure_peak"]["p"].get<double>();
    if (key == "pressure_peak_r") return o["pressure_peak"]["r"].get<double>();
    if (key == "second_stick_from") return second_stick(o, "from");
    if (key == "second_stick_to") return second_stick(o, "to");
    return o[key].get<double>();
}

// The key of the estimate that bounds `key`'s error: its own, but the second stick zone's ends (five_zone_keys).
inline std::string estimate_key(const std::string& key) {
    if (key == "second_stick_from") return "stick_start";
    if (key == "second_stick_to") return "c0";
    return key;
}

inline std::string data(const std::string& name) { return std::string(ROUGHROLL_DATA) + "/" + name; }

// `scene` of data/ with coupling = "full" in a temporary file (removed by the caller; empty where none could be made).
inline std::string full_coupling(const std::string& scene) {
    return changed_scene(data(scene), {{"coupling = \"johnson\"", "coupling = \"full\""}}, "roughroll-audit");
}

// `point PATH OPTIONS --json`: its JSON, a null one (and a failed expectation) where it exits non-zero.
inline nlohmann::json point(const std::string& path, const std::string& options) {
    const command_output o =
        run_command(std::string(ROUGHROLL_CLI) + " point " + path + " " + options + " --json --quiet");
    EXPECT_EQ(o.status, 0) << options << "\n" << o.text;
    return o.status == 0 ? nlohmann::json::parse(o.text) : nlohmann::json();
}

// A reference's rows: every estimate it prints, with its value (of `keys`, or of the keys given).
template <typename Keys = decltype(keys)>
std::vector<stored> reference_rows(const nlohmann::json& r, const Keys& of = keys) {
    std::vector<stored> out;
    if (!r.is_object() || !r["error_estimate"].is_object()) return out;
    for (const char* key : of)
        if (r["error_estimate"].contains(estimate_key(key)))
            out.push_back({key, value_of(r, key), r["error_estimate"][estimate_key(key)].get<double>()});
    return out;
}

// The answer `a` (of `load`, its options: the default settings, or a given n) against `reference`: one comparison per
// estimate printed, each asserted to bound its distance with the reference's estimate added; every reference key must
// be printed, and the checks must hold.
inline std::vector<comparison> compare(const nlohmann::json& a, const std::string& load,
                                       const std::vector<stored>& reference) {
    std::vector<comparison> out;
    if (!a.is_object()) return out;
    EXPECT_TRUE(a["checks_hold"].get<bool>()) << load;
    const auto& e = a["error_estimate"];
    EXPECT_TRUE(e.is_object()) << load << ": no estimate printed";
    if (!e.is_object()) return out;
    for (const stored& s : reference) {
        const std::string ek = estimate_key(s.key);
        EXPECT_TRUE(e.contains(ek)) << load << " " << s.key;
        if (!e.contains(ek)) continue;
        const comparison c{s.key, e[ek].get<double>(), std::fabs(value_of(a, s.key) - s.value), s.estimate};
        std::printf("%-24s n = %4d %-16s estimate %.3g distance %.3g (reference's estimate %.3g)\n", load.c_str(),
                    a["n"].get<int>(), s.key, c.estimate, c.distance, c.reference_estimate);
        EXPECT_LE(c.distance, c.estimate + c.reference_estimate) << load << " " << s.key;
        out.push_back(c);
    }
    return out;
}

// The answer of `path` at `load` against `reference` (compare).
inline std::vector<comparison> audit(const std::string& path, const std::string& load,
                                     const std::vector<stored>& reference) {
    return compare(point(path, load), load, reference);
}

// The test can fail: of the rows the reference can tell (its estimate under `tell` times the distance), how many an
// estimate `factor` times smaller would under-report. `told` is set to the number of such rows.
inline int caught_if_smaller(const std::vector<comparison>& rows, double factor, double tell, int& told) {
    int caught = 0;
    told = 0;
    for (const auto& c : rows) {
        if (c.reference_estimate >= tell * c.distance) continue;
        ++told;
        if (c.distance > c.estimate / factor + c.reference_estimate) ++caught;
    }
    return caught;
}

// The stored rows are not stale: the reference's load (`options`) solved again now by its `method` at `n`, each
// stored value within the estimates of the stored and the new solution together (each bounds its own distance from the
// exact value, so the two can be no further apart). Solved again at the reference's own n (1000) this cannot see a
// stale value within about twice the stored estimate; at a cheaper n, within the stored plus the new estimate. The new
// estimate is asserted to exceed the stored one by at most `blind` times each estimate the audits compare with this
// reference (`audited`, the comparisons of `audit`): a stale value that this check misses and n = 1000's would have
// caught then moves no audited comparison by more than that fraction of its estimate.
// `method` is the reference's (product for the audits' references; the scene's default, extrapolated, for
// test_rough_five_zones_s22's).
inline void solved_again(const std::string& path, const std::string& options, int n,
                         const std::vector<stored>& reference, const std::vector<comparison>& audited, double blind,
                         const std::string& method = "product") {
    const nlohmann::json r = point(path, options + " --method " + method + " --n " + std::to_string(n));
    ASSERT_TRUE(r.is_object()) << options << " at n = " << n;
    ASSERT_TRUE(r["error_estimate"].is_object()) << options << " at n = " << n << ": no estimate printed";
    for (const stored& s : reference) {
        const std::string ek = estimate_key(s.key);
        const bool printed = r["error_estimate"].contains(ek);
        EXPECT_TRUE(printed) << options << " at n = " << n << ": no estimate of " << s.key;
        if (!printed) continue;
        const double value = value_of(r, s.key), estimate = r["error_estimate"][ek].get<double>();
        std::printf("%-16s %-16s stored %.17g, n = %d: %.17g (estimates %.3g, %.3g)\n", options.c_str(), s.key, s.value,
                    n, value, s.estimate, estimate);
        EXPECT_LE(std::fabs(value - s.value), s.estimate + estimate) << options << " " << s.key;
        int compared = 0;
        for (const comparison& c : audited)
            if (c.key == s.key) {
                ++compared;
                std::printf("%-16s %-16s (n = %d's estimate - the stored one) / the audited one %.3g\n",
                            options.c_str(), s.key, n, (estimate - s.estimate) / c.estimate);
                EXPECT_LE(estimate - s.estimate, blind * c.estimate)
                    << options << " " << s.key << ": n = " << n << " is too coarse to tell a stale reference";
            }
        EXPECT_GE(compared, 1) << options << " " << s.key << ": no audited row";
    }
}

}  // namespace estimates_audit
