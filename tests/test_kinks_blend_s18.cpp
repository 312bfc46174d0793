// SPDX-License-Identifier: GPL-3.0-or-later
// kinks_blend's own rule beyond max_nodes (docs/formulation.md 8(o), "W with the kinks"): the expansion of g W_1 on
// the kink zone takes m = terms + 37/log(ellipse) nodes, a transform's rule (gauss_chebyshev::transform), which may
// exceed max_nodes, the collocation's limit. Until session 18 m was capped at max_nodes, and pressure_kinks::blend
// declined (a) a zone whose ellipse asked 500 or more extra nodes (the first stick zone at 1 + s ~ 2e-3: full coupling's
// free rolling at f = 0.3) and (b) at n = 1000 a g whose terms beyond m - extra summed to more than 1e-7 of all
// (f = 0.2), sending W to adaptive quadrature at every collocation point. Both cases here, against GSL's QAGS of
// W's definition with the kinks' ends as break points (the pattern of BlendedCauchy.WithTheKinksAgainstAdaptive-
// QuadratureOfTheDefinition, tests/test_blended_cauchy.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "blended_cauchy_reference.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/numerics/blended_cauchy.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

using namespace roughroll;

namespace {
// The definition by QAGS (blended_cauchy_reference.hpp); its own estimate may reach 3e-13 where g has 1000 terms (GSL's
// round-off on an oscillating integrand): below the 1e-12 asserted of the difference.
double reference(const std::function<double(double)>& phi, double s, double c, double r, const std::vector<double>& cuts) {
    return blended_reference(phi, s, c, r, cuts, 3e-13);
}

// W's Cauchy part with the kinks of psi on the stick zone [s, c] (the kink zone itself: a converged alternation),
// series part by blended_cauchy, kinks part by kinks_blend, against the reference; returns the largest difference.
double worst_against_reference(int n, const std::vector<double>& psi, double s, double c) {
    const std::vector<double> series{M_2_PI, 0.01, -0.02, 0.004, 1e-3, -5e-4};
    const gauss_chebyshev rule(n);
    pressure_kinks k;
    k.add_zone(rule, 0.1438337, -1.0, s, c, psi);
    const auto series_part = blended_cauchy::make(series, s, c);
    const auto kinks_part = k.blend(s, c);
    EXPECT_TRUE(series_part) << "zone [" << s << ", " << c << "]";
    EXPECT_TRUE(kinks_part) << "kinks_blend declined the zone [" << s << ", " << c << "] at n = " << n;
    if (!series_part || !kinks_part) return INFINITY;
    const std::function<double(double)> phi = [&](double eta) { return u_series(series, eta) + k.factor(eta); };
    const double rho = 0.5 * (c - s);
    double worst = 0.0;
    for (const double r : {-1.0, -0.9995, s + 1e-7, s + 1e-4, s + 0.3 * rho, 0.5 * (s + c), c - 1e-3 * rho, c + 1e-6,
                           s - 1e-6, 0.97, 1.0}) {
        if (r < -1.0 || r > 1.0) continue;
        const auto a = (*series_part)(r), b = (*kinks_part)(r, theta_blend(r, s, c));
        EXPECT_TRUE(a && b) << "r = " << r;
        if (!a || !b) return INFINITY;
        const double error = std::fabs(*a + *b - reference(phi, s, c, r, k.ends()));
        EXPECT_LT(error, 1e-12) << "zone [" << s << ", " << c << "], n = " << n << ", r = " << r;
        worst = std::max(worst, error);
    }
    return worst;
}
}  // namespace

// (a) A stick zone starting 2e-3 from the leading edge and reaching 0.99 (the shape of f = 0.3's first zone): the
// ellipse through the images of r = -1 asks 584 extra nodes, at and above max_nodes/2 = 500, where the old rule declined
// at every n. A smooth five-term psi: g = psi/sqrt(1 - r^2) has a few hundred terms (the same ellipse).
TEST(KinksBlend, AZoneNearAnEdgeAgainstAdaptiveQuadratureOfTheDefinition) {
    gsl_set_error_handler_off();
    const std::vector<double> psi{0.02, 0.012, -0.004, 0.001, -2e-4};
    double worst = 0.0;
    for (const int n : {256, 1000}) worst = std::max(worst, worst_against_reference(n, psi, -0.998, 0.99));
    std::printf("worst difference: %.2g\n", worst);
}

// (b) n = 1000 and a psi whose coefficients fall algebraically (1e-3 cos(0.9 j)/(1 + j)^2.5, all 1000 above
// rounding, as psi's slow fall next to the entry at f = 0.2), zone [-0.98484, 0.975] (extra about 230): g's terms
// beyond 1000 - extra sum to far more than 1e-7 of all, so the old capped rule declined; the uncapped one takes
// m = 1000 + extra nodes and drops nothing.
TEST(KinksBlend, AllOfAThousandTermGAgainstAdaptiveQuadratureOfTheDefinition) {
    gsl_set_error_handler_off();
    std::vector<double> psi;
    for (int j = 0; j < max_nodes; ++j) psi.push_back(1e-3 * std::cos(0.9 * j) / std::pow(1.0 + j, 2.5));
    const double worst = worst_against_reference(max_nodes, psi, -0.98484, 0.975);
    std::printf("worst difference: %.2g\n", worst);
}

// The transform's rule goes beyond max_nodes; the collocation's does not (its dense system, n <= max_nodes).
TEST(KinksBlend, TheTransformRuleGoesBeyondMaxNodesTheCollocationsDoesNot) {
    EXPECT_THROW(gauss_chebyshev(max_nodes + 1), input_error);
    const gauss_chebyshev big = gauss_chebyshev::transform(max_transform_nodes);
    EXPECT_EQ(big.n, max_transform_nodes);
    EXPECT_DOUBLE_EQ(big.nodes.front(), std::cos(M_PI / (max_transform_nodes + 1)));
    EXPECT_THROW(gauss_chebyshev::transform(max_transform_nodes + 1), numerical_error);
    // The same nodes and weights as the collocation's rule where both exist.
    const gauss_chebyshev a(777), b = gauss_chebyshev::transform(777);
    EXPECT_EQ(a.nodes, b.nodes);
    EXPECT_EQ(a.weights, b.weights);
    EXPECT_EQ(a.collocation, b.collocation);
}
