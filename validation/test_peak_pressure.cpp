// SPDX-License-Identifier: GPL-3.0-or-later
// The peak pressure (normal_problem.hpp, peak_of) and its change under full coupling (full_coupling.hpp,
// coupling_summary::peak_pressure_change; docs/formulation.md 8(e)), each against a second route:
// Hertz's closed form, a dense sampling, and the peak in pascals of a physical scene solved at both
// coupling levels through its own width search.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {
const std::string data = ROUGHROLL_DATA;

scene_point al_steel(coupling_level level) {
    scene s = read_scene(data + "/aluminium-on-steel.toml");
    s.materials.coupling = level;
    s.solver.n = 48;             // full coupling's free rolling is refused at n = 32 (8(r))
    return solve_point(s, 0.0);  // free rolling: five zones, the largest change (8(e))
}
}  // namespace

TEST(PeakPressure, HertzIsTwoOverPiAtTheCentre) {
    const pressure_peak peak = peak_of(solve_normal(kernel::normal(roughness{}), 64, method::product));
    EXPECT_NEAR(peak.p, 2.0 / M_PI, tol::few_roundings);
    EXPECT_NEAR(peak.r, 0.0, 1e-7);  // a flat maximum: r to about sqrt(eps)
}

TEST(PeakPressure, RoughPressureAgainstADenseSampling) {
    // A rough layer flattens and widens the pressure (Fig. 2 scenes' T = 1, A = 1): its peak is no
    // closed form. 400001 samples bound it from below within (h/2)^2 |p''| ~ 1e-11.
    roughness r;
    r.cylinder1.normal = {1.0, 1.0};
    const normal_solution p = solve_normal(kernel::normal(r), 128, method::product);
    const pressure_peak peak = peak_of(p);
    double sampled = 0.0, at = 0.0;
    for (int i = 0; i <= 400000; ++i) {
        const double x = -1.0 + 2.0 * i / 400000.0;
        if (p.pressure(x) > sampled) sampled = p.pressure(x), at = x;
    }
    EXPECT_GE(peak.p, sampled - tol::few_roundings);
    EXPECT_LE(peak.p - sampled, 1e-10);
    EXPECT_NEAR(peak.r, at, 1e-5);
    EXPECT_LT(peak.p, 2.0 / M_PI);  // the layer lowers the peak below Hertz's
}

TEST(PeakPressure, CoupledChangeIsThePhysicalPeaksAtTheSameLoad) {
    // peak_pressure_change = (p_max/p_max,J) sqrt(lambda_J/lambda) - 1 from the dimensionless solutions;
    // the physical scene's own route: its width found at each level (a follows lambda at full
    // coupling), and p_peak in Pa = p_max P2/a.
    const scene_point johnson = al_steel(coupling_level::johnson);
    const scene_point full = al_steel(coupling_level::full);
    ASSERT_TRUE(full.solved.coupling() && johnson.width && full.width);
    const auto pascals = [](const scene_point& s) {
        const si_point si = *s.report().si;
        return si.p_scale * peak_of(s.solved.normal()).p;
    };
    EXPECT_EQ(johnson.report().si->P2, full.report().si->P2);  // the same normal load
    const double physical = pascals(full) / pascals(johnson) - 1.0;
    EXPECT_NEAR(full.solved.coupling()->peak_pressure_change, physical, 1e-6 * std::fabs(physical));
    // Not the dimensionless change at the narrower coupled width (0.31 %, which the JSON reported
    // as pressure_max_change): the width's own change adds half of -Delta lambda/lambda.
    const double dimensionless = peak_of(full.solved.normal()).p / peak_of(johnson.solved.normal()).p - 1.0;
    EXPECT_GT(physical - dimensionless, 1e-3);
}
