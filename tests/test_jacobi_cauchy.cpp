// SPDX-License-Identifier: GPL-3.0-or-later
// Cauchy transforms on a Jacobi weight with a + b != 1 (docs/formulation.md 8(y)): C_0(x) = (1/pi) PV int w/(tau - x)
// in closed form against QUADPACK (QAWS at the ends, QAWC around the point: not the closed form), its reduction to
// 8(v)'s forms at a + b = 1, and the collocation of (H - k(x))[w psi] - xi on the model problem of session 18
// ("mockA", tests/test_jacobi_weights.cpp) with the exact q = w chi on the blended zone's weight a = b = 1/2 - eps
// (8(l): eps_in = -eps_out) and the blend's varying k(t) = k S(t), S = (2/pi)(asin t + t sqrt(1 - t^2)) (8(g)).
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/jacobi_cauchy.hpp"

#include "jacobi_quadpack.hpp"

using namespace roughroll;

namespace {
using namespace jacobi_quadpack;

// (1/pi) int w chi/(tau - x) for |x| > 1 by QAWS (w as QAWS's weight).
double outside(const integrand& chi, double a, double b, double x) {
    return M_1_PI * qaws([&](double t) { return chi(t) / (t - x); }, -1.0, 1.0, b, a);
}

double one(double) { return 1.0; }

// A smooth chi with chi(-1) = 0 (the entry condition) that no polynomial of degree n - 1 holds: the collocation's
// error is then its own, falling spectrally where the weight carries the exponents.
double chi(double t) { return (1.0 + t) * (0.7 - 0.3 * t + 0.2 * std::cos(3.0 * t)); }

double blend(double t) { return M_2_PI * (std::asin(t) + t * std::sqrt((1.0 - t) * (1.0 + t))); }  // S = 2 Theta - 1

struct errors {
    double psi = 0.0, entry = 0.0, load = 0.0, xi = 0.0;
    double largest() const { return std::max({psi, entry, load, xi}); }
};

// (H - k)[w chi] - xi = F at the points of `c` (its own or replaced), F = (H - k)[w_true chi] by QUADPACK on the true
// weight (a_true, b_true); solved on c's weight; errors of psi_k = chi(t_k) (only where the weights agree), xi = 0,
// psi(-1) = 0 and the load int w psi.
errors model_errors(const jacobi_cauchy_collocation& c, double a_true, double b_true,
                    const std::function<double(double)>& k) {
    const int n = c.rule.n;
    const double a = c.rule.a, b = c.rule.b;
    gsl_matrix* A = gsl_matrix_calloc(n + 1, n + 1);
    gsl_vector* F = gsl_vector_alloc(n + 1);
    std::vector<double> kx(n + 1);
    for (int m = 0; m <= n; ++m) kx[m] = k(c.collocation[m]);
    c.add_to(A, kx);
    for (int m = 0; m <= n; ++m) {
        gsl_matrix_set(A, m, n, -1.0);
        const double xm = c.collocation[m];
        gsl_vector_set(F, m, hilbert(chi, a_true, b_true, xm) - kx[m] * jacobi_weight(a_true, b_true, xm) * chi(xm));
    }
    const std::vector<double> x = lu_solved(A, F);
    errors e;
    std::vector<double> psi(n);
    double load = 0.0;
    for (int j = 0; j < n; ++j) {
        psi[j] = x[j];
        if (a == a_true && b == b_true) e.psi = std::max(e.psi, std::fabs(psi[j] - chi(c.rule.nodes[j])));
        load += c.rule.weights[j] * psi[j];
    }
    e.xi = std::fabs(x[n]);
    e.entry = std::fabs(jacobi_series(jacobi_coefficients(c.rule, psi), a, b, -1.0));
    e.load = std::fabs(load - qaws(chi, -1.0, 1.0, b_true, a_true));
    gsl_vector_free(F);
    gsl_matrix_free(A);
    return e;
}

std::vector<double> chebyshev_points(int count) {  // zeros of T_count, ascending
    std::vector<double> x(count);
    for (int m = 0; m < count; ++m) x[m] = -std::cos((m + 0.5) * M_PI / count);
    return x;
}
}  // namespace

TEST(JacobiCauchy, WeightTransformAgainstQuadpack) {
    // C_0 inside (QAWS + QAWC) and outside (QAWS) for exponents across (0, 1), a + b on both sides of 1. Within 1e-2 of
    // the ends QUADPACK's own error reaches 1e-11 (against mpmath, below), so the points here keep that distance.
    const double pairs[][2] = {{0.1, 0.3}, {0.4977, 0.4977}, {0.45, 0.45}, {0.3, 0.9}, {0.9, 0.2}, {0.7, 0.6}, {0.5, 0.5}};
    double worst = 0.0;
    for (const auto& p : pairs) {
        const double a = p[0], b = p[1];
        for (double x : {-0.99, -0.97, -0.6, -0.2, 0.0, 0.05, 0.4, 0.9, 0.99}) {
            const double ref = hilbert(one, a, b, x), got = jacobi_weight_cauchy(a, b, x);
            worst = std::max(worst, std::fabs(got - ref) / std::max(1.0, std::fabs(ref)));
            EXPECT_NEAR(got, ref, 1e-13 * std::max(1.0, std::fabs(ref))) << a << " " << b << " inside " << x;
        }
        for (double x : {1.01, 1.3, 2.9, 3.1, 40.0, -1.01, -1.9, -7.0}) {
            const double ref = outside(one, a, b, x), got = jacobi_weight_cauchy(a, b, x);
            worst = std::max(worst, std::fabs(got - ref) / std::max(1.0, std::fabs(ref)));
            EXPECT_NEAR(got, ref, 1e-13 * std::max(1.0, std::fabs(ref))) << a << " " << b << " outside " << x;
        }
    }
    std::printf("C_0 against QUADPACK: largest relative difference %.2e\n", worst);
}

TEST(JacobiCauchy, WeightTransformNextToTheEnds) {
    // Within 1e-4 .. 1e-7 of the ends, against 40-digit values by mpmath (an independent route: its tanh-sinh quad of
    // (w(tau) - w(x))/(tau - x) plus w(x) log((1 - x)/(1 + x)) inside, of w/(tau - x) outside, which agrees with the
    // closed form to all 20 digits printed; x the exact doubles given here). GSL's 2F1 as y = 2/(1 - x) -> 1 alone
    // erred 1.4e-10 at x = -1 - 1e-6 (the reason for the connection formula).
    const double cases[][4] = {{0.1, 0.3, 0.99999, -2.8435407470555795915},
                               {0.3, 0.9, 0.99999, -1.8667470532974636598},
                               {0.9, 0.2, -0.9999, 2.4715541521842166213},
                               {0.4977, 0.4977, -0.99999, 1.0031592555741683715},
                               {0.1, 0.3, 1.0000001, -3.246832188582509238},
                               {0.1, 0.3, -1.000001, 1.3262566214170800514},
                               {0.7, 0.6, 1.000001, -0.7790328311944250417},
                               {0.4977, 0.4977, -1.0000001, 1.0027390475413320962},
                               {0.3, 0.9, 1.0000001, -1.8913149512901457212}};
    for (const auto& c : cases)
        EXPECT_NEAR(jacobi_weight_cauchy(c[0], c[1], c[2]), c[3], 1e-13 * std::fabs(c[3])) << c[0] << " " << c[1] << " " << c[2];
}

TEST(JacobiCauchy, ReducesToTheClosedFormOfEightV) {
    // a + b = 1 (8(v)): inside cot(pi a) w - (x + 1 - 2a)/sin(pi a) (item 2's identity at j = 0), outside
    // (X - x - 1 + 2a)/sin(pi a), X = (x - 1)^a (x + 1)^b continued from above the cut.
    for (double a : {0.5, 0.4977, 0.52, 0.3}) {
        const double b = 1.0 - a, s = std::sin(M_PI * a);
        for (double x : {-0.999, -0.5, 0.0, 0.3, 0.9999}) {
            const double expected = jacobi_weight(a, b, x) / std::tan(M_PI * a) - (x + 1.0 - 2.0 * a) / s;
            EXPECT_NEAR(jacobi_weight_cauchy(a, b, x), expected, 1e-14) << a << " " << x;
        }
        for (double x : {-5.0, -1.0 - 1e-6, 1.0 + 1e-6, 1.2, 30.0}) {
            const double X = std::copysign(std::pow(std::fabs(x - 1.0), a) * std::pow(std::fabs(x + 1.0), b), x);
            EXPECT_NEAR(jacobi_weight_cauchy(a, b, x), (X - x - 1.0 + 2.0 * a) / s, 1e-13 * std::fabs(x)) << a << " " << x;
        }
    }
}

TEST(JacobiCauchy, CollocationIsEightVWhereTheIdentityHolds) {
    // a + b = 1, k = cot(pi a): D(x_m) = 0 at the zeros of P_{n+1}^(-a,-b), so the matrix is 8(v)'s (1/pi) W_k/(t_k - x_m).
    const double a = 0.5 - std::atan(0.06) / M_PI;
    const int n = 12;
    const jacobi_cauchy_collocation c(n, a, 1.0 - a);
    const jacobi_collocation v(n, a);
    gsl_matrix* A = gsl_matrix_calloc(n + 1, n + 1);
    c.add_to(A, std::vector<double>(n + 1, 1.0 / std::tan(M_PI * a)));
    for (int m = 0; m <= n; ++m) {
        EXPECT_NEAR(c.collocation[m], v.collocation[m], 1e-15);
        for (int k = 0; k < n; ++k)
            EXPECT_NEAR(gsl_matrix_get(A, m, k), M_1_PI * v.rule.weights[k] / (v.rule.nodes[k] - v.collocation[m]), 1e-12)
                << m << " " << k;
    }
    gsl_matrix_free(A);
}

TEST(JacobiCauchy, LagrangeBasisInterpolates) {
    const jacobi_cauchy_collocation c(9, 0.47, 0.31);
    for (double x : {-1.0, -0.63, 0.111, 0.98, 1.0, 1.4}) {
        const std::vector<double> l = c.lagrange(x);
        double p = 0.0;
        for (int k = 0; k < 9; ++k) p += l[k] * (0.5 + std::pow(c.rule.nodes[k], 8) - 2.0 * c.rule.nodes[k]);  // degree 8 < n
        EXPECT_NEAR(p, 0.5 + std::pow(x, 8) - 2.0 * x, 1e-13 * std::max(1.0, std::pow(std::fabs(x), 8))) << x;
    }
}

TEST(JacobiCauchy, BlendedZoneConvergesSpectrally) {
    // The blended zone's weight a = b = 1/2 - eps (eps = atan(k)/pi) with k(t) = k S(t), and a constant k on the same
    // weight (a + b != 1, not a local structure of the model, but an exact solution all the same): the errors of
    // psi, xi, psi(-1) and the load fall to rounding. Both point sets measured; the zeros of P_{n+1}^(-a,-b) asserted.
    for (double k : {0.06, -0.2, 0.0071917}) {
        const double a = 0.5 - std::atan(k) / M_PI;
        for (const bool varying : {true, false}) {
            const std::function<double(double)> kx = [&](double t) { return varying ? k * blend(t) : k; };
            double last = 1.0;
            for (int n : {4, 8, 12, 16, 24, 32}) {
                const jacobi_cauchy_collocation c(n, a, a);
                jacobi_cauchy_collocation cheb(n, a, a);
                cheb.collocation = chebyshev_points(n + 1);
                const errors e = model_errors(c, a, a, kx), ec = model_errors(cheb, a, a, kx);
                std::printf("k = %g %s n = %2d: Jacobi points psi %.1e xi %.1e psi(-1) %.1e load %.1e | Chebyshev "
                            "points %.1e\n",
                            k, varying ? "S(t)" : "const", n, e.psi, e.xi, e.entry, e.load, ec.largest());
                last = e.largest();
            }
            EXPECT_LT(last, 1e-13) << k << " " << varying;
        }
    }
}

TEST(JacobiCauchy, SquareRootWeightMissesTheBlendedExponents) {
    // The control: the same problem on the weight a = b = 1/2 (today's blended zone) errs far above rounding.
    for (double k : {0.06, 0.0071917}) {
        const double a = 0.5 - std::atan(k) / M_PI;
        for (int n : {16, 32}) {
            const jacobi_cauchy_collocation c(n, 0.5, 0.5);
            const errors e = model_errors(c, a, a, [&](double t) { return k * blend(t); });
            std::printf("square root, k = %g, n = %d: xi %.1e psi(-1) %.1e load %.1e\n", k, n, e.xi, e.entry, e.load);
            EXPECT_GT(e.load, 1e-9) << k << " " << n;
        }
    }
}
