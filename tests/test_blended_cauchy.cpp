// SPDX-License-Identifier: GPL-3.0-or-later
// W of the blended stick zone as a mean of steps (blended_cauchy, docs/formulation.md 8(g)) against GSL's
// adaptive quadrature (QAGS, g(r) subtracted) of its definition, for Hertz's pressure and series of several
// terms, zones inside the contact and near its edges, r on the zone, beside it, off it and at the edges; and
// with the pressure's kinks p_q^0 of full coupling added (the series' part + kinks_blend, 8(o)).
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
#include "roughroll/numerics/blended_cauchy.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

using namespace roughroll;

namespace {
// The definition by QAGS (blended_cauchy_reference.hpp).
double reference(const std::function<double(double)>& phi, double s, double c, double r,
                 const std::vector<double>& cuts = {}) {
    return blended_reference(phi, s, c, r, cuts);
}

double reference(const std::vector<double>& b, double s, double c, double r) {
    return reference([&](double eta) { return u_series(b, eta); }, s, c, r);
}
}  // namespace

TEST(BlendedCauchy, AgreesWithAdaptiveQuadratureOfTheDefinition) {
    gsl_set_error_handler_off();
    const std::vector<std::vector<double>> pressures{
        {M_2_PI},                                       // Hertz's, one term
        {M_2_PI, 0.01, -0.02, 0.004, 1e-3, -5e-4},      // a coupled pressure's first terms
        {0.5, 0.1, 0.05, -0.03, 0.02, 0.01, -0.005, 0.003, 2e-3, -1e-3, 5e-4, 1e-4}};
    const std::vector<std::pair<double, double>> zones{
        {-0.689, 0.495}, {0.838, 0.922}, {-0.99, 0.3}, {-0.2, 0.99}, {0.5, 0.999}, {-0.98, -0.5}};
    int compared = 0;
    for (const auto& b : pressures)
        for (const auto& [s, c] : zones) {
            const auto w = blended_cauchy::make(b, s, c);
            ASSERT_TRUE(w) << "zone [" << s << ", " << c << "]";
            const double rho = 0.5 * (c - s);
            std::vector<double> rs{-1.0, -0.999, s + 1e-7, s + 0.3 * rho, 0.5 * (s + c), c - 1e-3 * rho, 0.97, 1.0};
            if (c < 1.0) rs.push_back(c + 1e-6);
            if (s > -1.0) rs.push_back(s - 1e-6);
            for (const double r : rs) {
                if (r < -1.0 || r > 1.0 || r == s || r == c) continue;
                const auto value = (*w)(r);
                ASSERT_TRUE(value) << "r = " << r;
                EXPECT_NEAR(*value, reference(b, s, c, r), 1e-12) << "zone [" << s << ", " << c << "], r = " << r << ", b_0 = " << b[0] << ", terms " << b.size();
                ++compared;
            }
        }
    EXPECT_GT(compared, 100);
}

TEST(BlendedCauchy, DeclinesZonesAtAnEdgeAndOutside) {
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, -1.0 + 1e-9, 0.5));  // no rule of 1023 nodes converges
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, -0.2, 1.0));  // a zone at the edge: algebraic, not geometric
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, 0.5, 0.5));
    EXPECT_FALSE(blended_cauchy::make({M_2_PI}, -1.1, 0.5));
    const auto w = blended_cauchy::make({M_2_PI}, -0.5, 0.5);
    ASSERT_TRUE(w);
    EXPECT_FALSE((*w)(1.5));
}

// With the pressure's kinks of full coupling, p = sqrt(1 - eta^2) phi + p_q^0 (docs/formulation.md 8(l) step 0): W's
// Cauchy part as dissimilar_zones::W sums it, blended_cauchy of the series plus kinks_blend of p_q^0 (Tricomi's
// identity, 8(o) "W with the kinks"), against QAGS of the definition with the kinks' ends as break points. The
// kink zone is the stick zone itself (a converged alternation), or moved by delta = 1e-9, the alternation's
// tolerance of the ends, or by 1e-5 (an early step; the expansion then carries an error of order delta^(3/2)).
TEST(BlendedCauchy, WithTheKinksAgainstAdaptiveQuadratureOfTheDefinition) {
    gsl_set_error_handler_off();
    const std::vector<double> series{M_2_PI, 0.01, -0.02, 0.004, 1e-3, -5e-4};
    // The driven pair's stick zone, a braked one, one towards the trailing edge; psi with psi(-1) = 0 roughly.
    const std::vector<std::pair<double, double>> zones{{-0.9308, -0.7391}, {-0.5633, 0.4942}, {0.5, 0.95}};
    const std::vector<double> psi{0.02, 0.012, -0.004, 0.001, -2e-4};
    int compared = 0;
    double worst_converged = 0.0, worst_early = 0.0;
    for (const int n : {16, 64})
        for (const auto& [s, c] : zones)
            for (const double delta : {0.0, 1e-9, 1e-5}) {
                const gauss_chebyshev rule(n);
                pressure_kinks k;
                k.add_zone(rule, 0.1438337, -1.0, s - delta, c + 0.5 * delta, psi);
                const auto series_part = blended_cauchy::make(series, s, c);
                const auto kinks_part = k.blend(s, c);
                ASSERT_TRUE(series_part && kinks_part) << "zone [" << s << ", " << c << "]";
                const std::function<double(double)> phi = [&](double eta) { return u_series(series, eta) + k.factor(eta); };
                const double rho = 0.5 * (c - s);
                for (const double r : {-1.0, -0.95, s + 1e-7, s + 0.3 * rho, 0.5 * (s + c), c - 1e-3 * rho, c + 1e-6,
                                       s - 1e-6, 0.97, 1.0}) {
                    if (r < -1.0 || r > 1.0) continue;
                    const auto a = (*series_part)(r), b = (*kinks_part)(r, theta_blend(r, s, c));
                    ASSERT_TRUE(a && b) << "r = " << r;
                    const double error = std::fabs(*a + *b - reference(phi, s, c, r, k.ends()));
                    if (delta <= 1e-9) {
                        EXPECT_LT(error, 1e-12) << "zone [" << s << ", " << c << "], delta " << delta << ", r = " << r;
                        worst_converged = std::max(worst_converged, error);
                    } else {
                        EXPECT_LT(error, 1e-10) << "zone [" << s << ", " << c << "], delta " << delta << ", r = " << r;
                        worst_early = std::max(worst_early, error);
                    }
                    ++compared;
                }
            }
    std::printf("worst difference: %.2g (delta <= 1e-9), %.2g (delta = 1e-5)\n", worst_converged, worst_early);
    EXPECT_GT(compared, 150);
}

// The batched forms (dissimilar_zones::W at a zone's collocation points) give each point's scalar value bit for bit:
// blocks of 8 with a partial last one, points inside and outside the kink zone (blend 0 and not), at and beyond the
// edges (W_1 empty there: both empty), and series of n = 129 terms.
TEST(BlendedCauchy, BatchedEqualsPointByPoint) {
    std::vector<double> series, psi;
    for (int j = 0; j < 129; ++j) series.push_back((j == 0 ? M_2_PI : 0.0) + 1e-3 * std::sin(0.7 * j + 0.3) / (1.0 + j));
    for (int j = 0; j < 40; ++j) psi.push_back(0.02 * std::cos(0.9 * j) / (1.0 + j * j));
    const double s = -0.5633, c = 0.4942;
    const gauss_chebyshev rule(129);
    pressure_kinks k;
    k.add_zone(rule, 0.1438337, -1.0, s, c, psi);
    k.add_zone(rule, 0.1438337, 1.0, 0.6, 0.9, psi);
    const auto series_part = blended_cauchy::make(series, s, c);
    const auto kinks_part = k.blend(s, c);
    ASSERT_TRUE(series_part && kinks_part);
    std::vector<double> r, blend;
    for (const double x : rule.collocation) r.push_back(0.5 * (c - s) * (x + 1.0) + s);
    for (int i = 0; i < 37; ++i) r.push_back(-1.0 + 2.0 * i / 36.0);
    r.insert(r.end(), {1.0, -1.0, 1.5, s, c, 0.6, 0.75});
    for (const double x : r) blend.push_back(theta_blend(x, s, c));
    std::vector<std::optional<double>> a(r.size()), b(r.size());
    (*series_part)(r.data(), a.data(), r.size());
    (*kinks_part)(r.data(), blend.data(), b.data(), r.size());
    int compared = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const auto a1 = (*series_part)(r[i]), b1 = (*kinks_part)(r[i], blend[i]);
        ASSERT_EQ(a[i].has_value(), a1.has_value()) << "r = " << r[i];
        ASSERT_EQ(b[i].has_value(), b1.has_value()) << "r = " << r[i];
        if (a1) {
            EXPECT_EQ(*a[i], *a1) << "r = " << r[i];
        }
        if (b1) {
            EXPECT_EQ(*b[i], *b1) << "r = " << r[i];
        }
        compared += a1.has_value() && b1.has_value();
    }
    EXPECT_GT(compared, 170);
}
