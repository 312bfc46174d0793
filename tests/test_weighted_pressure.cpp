// SPDX-License-Identifier: GPL-3.0-or-later
// The weighted normal operator of plan C (docs/formulation.md 8(w)): p = w_N phi + p_q with w_N = (1 - r)^a_N
// (1 + r)^(1 - a_N), a_N = 1/2 + atan(k_E)/pi, k_E = sigma beta_D f in the operator (H + k_E).
// 1. Gross sliding (s18-exponents test 2): the closed form of 8(e) (Plemelj) p = C w_N, lambda = 1/(1 - 4 delta^2/pi^2),
//    e = -2 delta/pi, taken from the formulas, not from the program, to 1e-13 at n = 8; the square-root basis
//    (the old solve, the same right side) misses it by > 1e-7 there (the control that the test can fail).
// 2. p_q of a stick zone: (H + k_E)[p_q] = -beta_D q + C, its load int p_q and C, checked by QUADPACK (QAWC around
//    the point, QAGS on the pieces between the zone ends), not by the identity p_q is built on.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

#include "hilbert_on_pieces.hpp"

using namespace roughroll;

namespace {
constexpr double beta_al_st = 0.1438;  // the pair's beta_D (order of magnitude; any value < 1 tests the same)

using hilbert_on_pieces::hilbert;
using hilbert_on_pieces::integral;
using hilbert_on_pieces::integrand;
}  // namespace

TEST(NormalWeighted, GrossSlidingClosedFormAtEightNodes) {
    gsl_set_error_handler_off();
    for (const double f : {0.05, 0.2, 1.0}) {
        for (const double sigma : {1.0, -1.0}) {
            const double k = beta_al_st * sigma * f, delta = std::atan(k), a = 0.5 + delta / M_PI;
            const double C = std::cos(delta) / (2.0 * M_PI * a * (1.0 - a));
            const double lambda = 1.0 / (1.0 - 4.0 * delta * delta / (M_PI * M_PI)), e = -2.0 * delta / M_PI;
            const auto p = [&](double r) { return C * std::pow(1.0 - r, a) * std::pow(1.0 + r, 1.0 - a); };
            // Gross sliding: beta_D p1 = k p on the whole contact.
            const std::function<double(double)> coupled = [&](double r) { return k * p(r); };
            normal_solver solver(8, method::product);
            auto w = std::make_shared<pressure_kinks>();
            w->set_weight(k);
            const normal_solution s = solver.solve_weighted(coupled, p, {}, w);
            EXPECT_NEAR(s.lambda, lambda, 1e-13) << f << " " << sigma;
            EXPECT_NEAR(s.offset, e, 1e-13) << f << " " << sigma;
            double worst = 0.0;
            for (double r = -0.999; r < 1.0; r += 0.037) worst = std::max(worst, std::fabs(s.pressure(r) - p(r)));
            EXPECT_LT(worst, 1e-13) << f << " " << sigma;
            // The control: the square-root basis with beta_D p1 = k p of its own previous iterate on the right side
            // (the old alternation, 8(e)), converged, at the same n.
            normal_solver old(8, method::product);
            normal_solution o = old.solve(kernel{});
            for (int it = 0; it < 60; ++it) {
                const normal_solution prev = o;
                o = old.solve(kernel{}, [&prev, k](double r) { return k * prev.pressure(r); }, {});
            }
            double old_worst = 0.0;
            for (double r = -0.999; r < 1.0; r += 0.037) old_worst = std::max(old_worst, std::fabs(o.pressure(r) - p(r)));
            std::printf("f %g sigma %+g: weighted lambda err %.2g e err %.2g p err %.2g; old lambda err %.2g e err %.2g "
                        "p err %.2g\n",
                        f, sigma, std::fabs(s.lambda - lambda), std::fabs(s.offset - e), worst,
                        std::fabs(o.lambda - lambda), std::fabs(o.offset - e), old_worst);
            EXPECT_GT(std::fabs(o.lambda - lambda) + std::fabs(o.offset - e), 1e-7) << f << " " << sigma;
        }
    }
}

TEST(NormalWeighted, KinkPartSolvesTheEquationByQuadpack) {
    gsl_set_error_handler_off();
    const double beta = 0.3;
    for (const double k : {0.06, -0.06}) {
        for (const double a_z : {0.5 - std::atan(k) / M_PI, 0.5}) {
            const double start = -0.45, c0 = 0.3, rho = 0.5 * (c0 - start), sign = k > 0 ? 1.0 : -1.0;
            pressure_kinks pk;
            pk.set_weight(k);
            const auto psi = [](double t) { return (1.0 + t) * (0.7 - 0.3 * t + 0.2 * t * t); };
            pk.add_weighted_zone(24, beta, sign, start, c0, a_z, psi);
            const std::vector<double> cuts{start, c0};
            // The q carried is the interpolant's (removed()); with psi a polynomial and 1/w_N analytic on the zone it
            // is the exact q to about 1e-15 at 24 nodes.
            const integrand q = [&](double r) {
                const double t = (r - start) / rho - 1.0;
                return std::fabs(t) < 1.0 ? sign * jacobi_weight(a_z, 1.0 - a_z, t) * psi(t) : 0.0;
            };
            const double a_n = 0.5 + std::atan(k) / M_PI;
            const integrand w_n = [&](double r) { return jacobi_weight(a_n, 1.0 - a_n, r); };
            const double C = beta * std::sin(M_PI * a_n) / M_PI * integral([&](double r) { return q(r) / w_n(r); }, cuts);
            EXPECT_NEAR(pk.constant(), C, 1e-12) << k << " " << a_z;
            const integrand pq = [&](double r) { return pk.kink_part(r); };
            EXPECT_NEAR(pk.load(), integral(pq, cuts), 1e-12) << k << " " << a_z;
            double worst = 0.0;
            for (const double r : {-0.95, -0.6, -0.46, -0.3, 0.0, 0.2, 0.299, 0.31, 0.6, 0.97}) {
                EXPECT_NEAR(pk.removed(r), beta * q(r), 1e-13) << r;
                const double lhs = hilbert(pq, r, cuts) + k * pq(r);
                worst = std::max(worst, std::fabs(lhs - (-beta * q(r) + C)));
                EXPECT_NEAR(lhs, -beta * q(r) + C, 1e-10) << k << " " << a_z << " r " << r;
            }
            std::printf("k %+g a_Z %.5f: (H + k) p_q + beta q - C worst %.2g; C %.6g; load %.6g\n", k, a_z, worst, C,
                        pk.load());
        }
    }
}

// The tabulated recurrence sums the same series as jacobi_values' (DLMF 18.9), for the exponents the weighted
// pressure uses: (a_N, 1 - a_N), the zone's (a_Z, 1 - a_Z) and the shifted (-a_Z, a_Z - 1) (where a + b = -1).
TEST(NormalWeighted, TabulatedRecurrenceAgreesWithJacobiValues) {
    std::vector<double> c(40);
    for (std::size_t j = 0; j < c.size(); ++j) c[j] = std::cos(1.3 * j) / (1.0 + j);
    for (const double a : {0.48092, 0.5, 0.51908, -0.48092, -0.51908}) {
        const double b = a > 0.0 ? 1.0 - a : -1.0 - a;
        const jacobi_recurrence rec(a, b, static_cast<int>(c.size()));
        std::vector<double> p(c.size() + 1);
        for (const double x : {-1.0, -0.7, 0.0, 0.33, 0.999, 1.0, 1.2, -1.05}) {
            jacobi_values(a, b, x, static_cast<int>(p.size()), p.data());
            double plain = 0.0, shifted = 0.0, size = 0.0;
            for (std::size_t j = 0; j < c.size(); ++j) {
                plain += c[j] * p[j];
                shifted += c[j] * p[j + 1];
                size += std::fabs(c[j] * p[j]) + std::fabs(c[j] * p[j + 1]);
            }
            EXPECT_NEAR(rec.series(c, x), plain, 1e-14 * size) << a << " " << x;
            if (c.size() + 1 <= rec.A.size() + 1) {
                const jacobi_recurrence longer(a, b, static_cast<int>(c.size()) + 1);
                EXPECT_NEAR(longer.series_shifted(c, x), shifted, 1e-14 * size) << a << " " << x;
            }
        }
    }
}
