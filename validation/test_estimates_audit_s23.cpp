// SPDX-License-Identifier: GPL-3.0-or-later
// Session 23's audit of the printed estimates (issue 24, "every estimate a bound"), continuing sessions 21 and 22
// (validation/test_estimates_audit_s21.cpp, _s22.cpp) at the points they did not reach: `point ... --json` at the
// default settings (no n: the ladder's rung, docs/formulation.md 8(q)) against the product solution at n = 1000 of the
// same load, for every quantity the JSON key error_estimate holds. Each must hold |answer - reference| <= estimate +
// the reference's own estimate (every estimate is absolute, in its quantity's units: error_estimate.hpp).
// The smooth pair at full coupling driven at Q/f = 0.3 (five zones, W's weighted route of 8(x); its reference at
// n = 1000 was refused in session 22 before W's fix) has a cheap reference (about 15 s CPU), solved here.
// At --tolerance 1e-8 both smooth points are refused at once (8.5 s and 1.3 s CPU), each advising n = 256 with its
// best estimate: the answers at n = 256 are audited here too. The rough pair at full coupling driven at Q/f = 0.99 is
// refused at the default settings, advising n = 256: that answer is audited against a stored reference at n = 1000
// (154 s CPU), whose load the same large_n case solves again at n = 512 so that a stale row fails. /work/notes/s23-audit3.md has the whole
// table and the points not reached (docs/robustness.md "Session 23").
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "estimates_audit.hpp"

namespace {

using namespace estimates_audit;

// The rough pair at full coupling driven at Q/f = 0.99: product, n = 1000, session 23, main 36eb361 (154 s CPU;
// docs/robustness.md "Session 23: the points session 22 did not reach").
const std::vector<stored> rough_full_099 = {
    {"c0", -0.9450110128252458, 9.818529035524547e-08},
    {"stick_start", -0.9898658869959507, 1.095055525159238e-06},
    {"xi", 0.028812941371545716, 4.4211161516547055e-09},
    {"hertz_load_ratio", 1.472323274757018, 1.4295600976931848e-09},
    {"pressure_peak_p", 0.6458832143992208, 1.109871331620401e-07},
    {"pressure_peak_r", -0.002679580362696844, 3.937437304423652e-05},
};

}  // namespace

// The smooth pair at full coupling driven at Q/f = 0.3: five zones (slip, stick, slip, stick, slip) on the weighted
// route of 8(x), answered at rung 128 in under a second of CPU; its reference at n = 1000 (about 15 s CPU) is solved
// here. Also n = 256 given: the answer a --tolerance 1e-8 refusal names as its best (at n = 256, its stick start
// +- 1.2e-6), so that refusal's figure is checked too. Measured on main 36eb361 (estimate / distance): rung 128 c0 30,
// start 56, xi 23, P_H/P2 6.2, peak p 17, peak r 3.7 (within the reference's 6.1e-5); n = 256 22, 17, 9.0, 42, 13, 25.
// The reference at n = 1000 is not much closer (its own estimates 1.9e-8 for c0, 1.2e-10 for xi against distances
// 4.5e-8 and 3.1e-10), so only an estimate about 40 times too small is caught: 64 times smaller under-reports c0 and
// xi at rung 128, which the test checks. On main before W's fix (b077a23) the reference was refused (179 s CPU, session
// 22: "the five zones ... are not found again"), which fails the test.
TEST(EstimatesAuditS23, FullCouplingDrivenFiveZonesWithinTheirEstimates) {
    const std::string full = full_coupling("aluminium-on-steel.toml");
    ASSERT_FALSE(full.empty());
    const std::vector<stored> reference = reference_rows(point(full, "--Q-over-f 0.3 --method product --n 1000"));
    EXPECT_EQ(reference.size(), 6u);
    const std::vector<comparison> rows = audit(full, "--Q-over-f 0.3", reference);
    EXPECT_EQ(rows.size(), 6u);
    EXPECT_EQ(audit(full, "--Q-over-f 0.3 --n 256", reference).size(), 6u);
    std::remove(full.c_str());
    int told = 0;  // the rows whose reference's estimate is under half the distance
    const int caught = caught_if_smaller(rows, 64.0, 0.5, told);
    std::printf("an estimate 64 times smaller under-reports %d of the %d rows the reference can tell\n", caught, told);
    EXPECT_GE(caught, 2);  // measured: c0 (distance 4.5e-8, estimate 1.4e-6) and xi (3.1e-10, 7.0e-9)
}

// The smooth pair at full coupling driven at Q/f = 0.99 (three zones) at n = 256, the n of its --tolerance 1e-8 refusal's
// best estimate (stick start +- 2e-6); the default (rung 512) is validation/test_estimates_audit_s22.cpp's. Reference at
// n = 1000 about 3 s CPU. Measured on main 36eb361: c0 53, start 11.5, xi 14.7, P_H/P2 13.6, peak p 413, peak r 9.1.
TEST(EstimatesAuditS23, FullCouplingNearSlidingAtTheAdvisedN) {
    const std::string full = full_coupling("aluminium-on-steel.toml");
    ASSERT_FALSE(full.empty());
    const std::vector<stored> reference = reference_rows(point(full, "--Q-over-f 0.99 --method product --n 1000"));
    EXPECT_EQ(reference.size(), 6u);
    EXPECT_EQ(audit(full, "--Q-over-f 0.99 --n 256", reference).size(), 6u);
    std::remove(full.c_str());
}

// The rough pair at full coupling driven at Q/f = 0.99: the default point is refused after about 220 s CPU (no rung up
// to 1000 meets 1e-4; the best is n = 256, stick start +- 3.4e-6, which the refusal names). That answer at
// n = 256 (its estimate confirmed on level 512: the changes change sign, 8(q)) against the stored reference at
// n = 1000. Measured on main 36eb361 (estimate / distance): c0 3.0e3, start 25, xi 30, P_H/P2 808, peak p 110, peak r
// 22 (every reference estimate above half its distance: the reference cannot tell below these).
// Then the stored rows are not stale (estimates_audit.hpp, solved_again): the load solved again at n = 512 (86 s CPU
// against 154 s at n = 1000), each stored value within the stored and the new estimate together, the new estimate
// above the stored one by at most 0.35 of each audited estimate (blind: measured on main 96e3a6a xi 0.30, start 0.14,
// P_H/P2 0.058, c0 0.036, peak p 0.014, peak r below the stored; 0.35 is xi's need rounded up). What this can still
// miss: a stored value off the exact one by up to e_s + 2 e_512 (e_s its stored estimate, e_512 n = 512's, which
// bounds n = 512's own error), i.e. up to 3 e_s + 0.7 e_a (e_a the audited n = 256 estimate); at n = 1000 it was about
// 3 e_s. A stale row missed so moves the audit's bound, so an under-report of the n = 256 answer passes only while its
// true error stays below e_a + e_s plus that staleness: 1.7 e_a + 4 e_s at most (xi, the worst row: 1.7 e_a measured,
// 3.3e-7 against e_a = 1.9e-7), where the re-solve at n = 1000 allowed about 1.1 e_a. The measured distances are 1/22
// .. 1/3000 of e_a, so only an estimate 1.7 times too small could hide behind a reference that stale.
// large_n: about 140 s CPU.
TEST(EstimatesAuditS23, RoughFullCouplingNearSlidingAtTheAdvisedN) {
    const std::string full = full_coupling("aluminium-on-steel-rough.toml");
    ASSERT_FALSE(full.empty());
    const std::vector<comparison> rows = audit(full, "--Q-over-f 0.99 --n 256", rough_full_099);
    EXPECT_EQ(rows.size(), 6u);
    solved_again(full, "--Q-over-f 0.99", 512, rough_full_099, rows, 0.35);
    std::remove(full.c_str());
}
