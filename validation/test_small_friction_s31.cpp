// SPDX-License-Identifier: GPL-3.0-or-later
// Session 30's open item 2 (issue 24): dissimilar rollers near complete slip, loaded. Bentall and Johnson's pair at
// Johnson's level, Q/f = +-0.5 at f = 1e-9, -0.5 at 1e-8 and -0.9 at 1e-7, ran for minutes without an answer (the
// ladder up to n = 1000), and at a given n = 128 were refused ("no five zones ... are found at n = 128"): the search's
// continuation in the load moved the stick zones, O(f/beta_D) wide, by thousands of their widths per step, and the
// roots it reached failed (3.3) by rounding alone (docs/formulation.md 8(f), "Below the rounding", "The complete-slip
// start", "The floor of the opposite zones"). Each is now answered at n = 128: five zones, checks holding, each stick
// zone of the width 8(f) derives, 4 f p/(pi |beta_D p'|) at the central band's edge, and the creep at the complete-slip
// limit xi_0 = -beta_D p(r_c). Asserted on the answers, never by time.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "roughroll/problems/contact.hpp"

using namespace roughroll;

namespace {
// The edge r_c of the central band that carries (1 + Q/f)/2 of Hertz's load (beta_D > 0, 8(f)), by bisection:
// (2/pi)(asin r + r sqrt(1 - r^2)) is the load on |x| < r.
double band_edge(double q) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((std::asin(mid) + mid * std::sqrt(1.0 - mid * mid)) * M_2_PI < 0.5 * (1.0 + q) ? lo : hi) = mid;
    }
    return lo;
}
}  // namespace

TEST(SmallFrictionS31, LoadedPairNearCompleteSlipAnsweredAtOneTwentyEight) {
    const struct {
        double f, q;
    } points[] = {{1e-9, 0.5}, {1e-9, -0.5}, {1e-8, -0.5}, {1e-7, -0.9}, {4e-10, 0.0}};
    for (const auto& p : points) {
        SCOPED_TRACE(testing::Message() << "f = " << p.f << ", Q/f = " << p.q);
        contact c(roughness{}, p.f, solver_options{128, method::extrapolated},
                  dissimilar{beta_al_st, coupling_level::johnson});
        tangential_solution s;
        ASSERT_NO_THROW(s = c.point(p.q * p.f));
        EXPECT_TRUE(s.checks.hold());
        ASSERT_EQ(s.layout.stick_zones(), 2u);
        // Hertz: p = (2/pi) sqrt(1 - r^2), p/|p'| = (1 - r^2)/r, so the width is 4 f (1 - r_c^2)/(pi beta_D r_c).
        const double r_c = band_edge(p.q), width = 4.0 * p.f * (1.0 - r_c * r_c) / (M_PI * beta_al_st * r_c);
        for (std::size_t k = 0; k < 2; ++k) {
            const zone& z = s.layout.stick_zone(k);
            EXPECT_NEAR(z.to - z.from, width, 0.01 * width) << "stick zone " << k;
            EXPECT_NEAR(std::fabs(0.5 * (z.from + z.to)), r_c, 10.0 * width) << "stick zone " << k;
        }
        // The creep near the limit (8(f): xi - xi_0 falls faster than f; measured 8e-12 at f = 1e-7, Q/f = 0.5, 4.8e-10
        // at Q/f = -0.9, where the zones are 12 times wider; 1e-15 at f = 1e-9).
        EXPECT_NEAR(s.xi, -beta_al_st * M_2_PI * std::sqrt(1.0 - r_c * r_c), p.f < 1e-7 ? 1e-11 : 1e-9);
    }
}
