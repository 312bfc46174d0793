// SPDX-License-Identifier: GPL-3.0-or-later
// Step 0 of docs/formulation.md 8(l) for rough rollers (8(o), "Rough rollers"): the pressure's kinks p_q^0 carried with
// the layer terms K2[p_q^0] on the normal right side and (K2 - K1)[p_q^0] in G, both tabulated by cut_convolution
// (cut_convolution.hpp) with the zone ends as cuts. Here the tables against GSL's QAGS of their definition,
// int p_q^0(eta) K(eta - r) d eta, on the pieces between the edges, the zone ends and r; the rough pair's exit
// converging faster than order 1 is validation/test_rough_step0_s19.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/cut_convolution.hpp"
#include "roughroll/numerics/gauss_chebyshev.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/normal_solution.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

#include "convolution_by_qags.hpp"
#include "rough_pair.hpp"

using namespace roughroll;
using roughroll_test::beta_pair;
using roughroll_test::convolution_by_qags;
using roughroll_test::rough_pair;

namespace {


// A stick zone's psi with n algebraically falling terms (as a converged zone's: q ~ (c - r)^(1/2 - eps)).
std::vector<double> falling_psi(int n) {
    std::vector<double> psi(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) psi[j] = (j % 2 == 0 ? 0.3 : -0.2) / std::pow(j + 1.0, 2.5);
    return psi;
}

// p_q^0 = beta_D sign sqrt(1 - r^2) H[q/sqrt(1 - r^2)] of stick zones [s, c] (docs/formulation.md 8(l) step 0), written
// from its definition apart from pressure_kinks (no tables): g = psi/sqrt(1 - r^2) expanded in U_j on the zone's
// Gauss-Chebyshev nodes, its Cauchy integral the series cauchy_u_series in the zone variable (section 3).
struct kink_zone {
    double s, c;
    std::vector<double> b;
};
kink_zone zone_of(const gauss_chebyshev& rule, double s, double c, const std::vector<double>& psi) {
    const double rho = 0.5 * (c - s);
    std::vector<double> g(static_cast<std::size_t>(rule.n));
    for (int i = 0; i < rule.n; ++i) {
        const double r = s + rho * (rule.nodes[i] + 1.0);
        g[i] = u_series(psi, rule.nodes[i]) / std::sqrt(1.0 - r * r);
    }
    return {s, c, u_coefficients(rule, g)};
}
double kinks_pressure(const std::vector<kink_zone>& zones, double amplitude, double r) {
    if (!(std::fabs(r) < 1.0)) return 0.0;
    double h = 0.0;
    for (const kink_zone& z : zones) {
        const double rho = 0.5 * (z.c - z.s);
        h += amplitude * cauchy_u_series(z.b, (r - z.s) / rho - 1.0);
    }
    return std::sqrt((1.0 - r) * (1.0 + r)) * h;
}

// The largest difference of the kinks' layer tables from QAGS over r from the edges to 1e-9 of the zone ends.
double worst_layers(const pressure_kinks& k, const std::vector<kink_zone>& zones, double amplitude, const kernel& k1,
                    const kernel& k2, const std::vector<double>& probes) {
    const kernel difference = k2.minus(k1);
    const std::function<double(double)> p = [&](double eta) { return kinks_pressure(zones, amplitude, eta); };
    double worst = 0.0;
    for (const double r : probes) {
        const double normal = convolution_by_qags(p, k2, r, k.ends());
        const double diff = convolution_by_qags(p, difference, r, k.ends());
        worst = std::max({worst, std::fabs(k.layer_normal(r) - normal), std::fabs(k.layer_difference(r) - diff)});
        if (std::fabs(k.layer_normal(r) - normal) > 1e-12 || std::fabs(k.layer_difference(r) - diff) > 1e-12)
            std::printf("  r %.12f: %.3g %.3g\n", r, k.layer_normal(r) - normal, k.layer_difference(r) - diff);
    }
    return worst;
}

}  // namespace

// One braked stick zone (the rough pair's at Q/f = -0.75: [-0.68, 0.40]) and two (five zones' kinds of zones), n = 16,
// 64 and 256, the layers of the rough pair: both tables within 1e-12 of QAGS, at points from the edges to 1e-9 of the
// zone ends on both sides (where p_q^0 has its square roots and the tables their 3/2 powers).
TEST(RoughStep0, LayerTablesAgainstQagsOfTheirDefinition) {
    const kernel k1 = kernel::tangential(rough_pair()), k2 = kernel::normal(rough_pair());
    for (const int n : {16, 64, 256}) {
        const gauss_chebyshev rule(n);
        pressure_kinks one;
        one.add_zone(rule, beta_pair, -1.0, -0.684, 0.4045, falling_psi(n));
        one.add_layers(k2, k1);
        ASSERT_TRUE(one.layered());
        pressure_kinks two;
        two.add_zone(rule, beta_pair, -1.0, -0.93, -0.6, falling_psi(n));
        two.add_zone(rule, beta_pair, -1.0, 0.1, 0.35, falling_psi(n));
        two.add_layers(k2, k1);
        const std::vector<kink_zone> zones_one{zone_of(rule, -0.684, 0.4045, falling_psi(n))},
            zones_two{zone_of(rule, -0.93, -0.6, falling_psi(n)), zone_of(rule, 0.1, 0.35, falling_psi(n))};
        for (const pressure_kinks* k : {&one, &two}) {
            std::vector<double> probes{-1.0, -0.999999, -0.7, 0.0, 0.37, 0.9, 0.999999, 1.0};
            for (const double e : k->ends())
                for (const double d : {-1e-9, -1e-4, 0.0, 1e-4, 1e-9}) probes.push_back(e + d);
            const double worst =
                worst_layers(*k, k == &one ? zones_one : zones_two, -beta_pair, k1, k2, probes);
            std::printf("n %3d, %zu zone(s): worst %.2g\n", n, k->ends().size() / 2, worst);
            EXPECT_LT(worst, 1e-12) << n;
        }
        // The normal right side takes K2[p_q^0] through removed() (beta_D q less it).
        pressure_kinks bare;
        bare.add_zone(rule, beta_pair, -1.0, -0.684, 0.4045, falling_psi(n));
        for (const double r : {-0.9, -0.2, 0.39, 0.6})
            EXPECT_DOUBLE_EQ(one.removed(r), bare.removed(r) - one.layer_normal(r)) << r;
    }
}

// A kernel with one term and a function with square roots at two cuts (not from pressure_kinks): sqrt(1 - r^2) times
// (r - a)_+^(1/2) + cos(7 r) (b - r)_+^(1/2), whose convolution is known only by quadrature.
TEST(RoughStep0, CutConvolutionOfOneSidedRoots) {
    const double a = -0.3, b = 0.55;
    const std::function<double(double)> g = [a, b](double r) {
        if (!(std::fabs(r) < 1.0)) return 0.0;
        return std::sqrt((1.0 - r) * (1.0 + r)) *
               (std::sqrt(std::max(r - a, 0.0)) + std::cos(7.0 * r) * std::sqrt(std::max(b - r, 0.0)));
    };
    const kernel k({{2.5, 3.0}, {-0.7, 0.4}});
    const cut_convolution table(
        k, [&g](const double* r, double* out, std::size_t count) { for (std::size_t i = 0; i < count; ++i) out[i] = g(r[i]); },
        {b, a}, 16, 0.4);
    double worst = 0.0;
    for (const double r : {-1.0, -0.5, a - 1e-8, a, a + 1e-8, 0.0, b - 1e-8, b, b + 1e-8, 0.8, 1.0})
        worst = std::max(worst, std::fabs(table(r) - convolution_by_qags(g, k, r, {a, b})));
    std::printf("one-sided roots: worst %.2g, %d panels\n", worst, table.panels());
    EXPECT_LT(worst, 1e-12);
}
