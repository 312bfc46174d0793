// SPDX-License-Identifier: GPL-3.0-or-later
// The no-slip limit at full coupling (problems/no_slip_coupled, docs/formulation.md 8(p), 8(t)) against routes that
// share none of its numerics: 8(p)'s closed form for smooth rollers (derived from the fundamental function alone);
// for rough layers the coupled equations (D1), (D2) evaluated on its p and p1 by GSL's QAWC (Cauchy) and QAGS (the
// layers' kernels, split at their jump), and the low-order route of validation/no_slip_full.py (sqrt(1 - r^2) U_k
// bases for p and p1, no oscillation carried, least squares, Richardson on n = 256, 512, 1024); and the order of
// convergence in n.
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/model/kernel.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/no_slip_coupled.hpp"

#include "rough_pair.hpp"

using namespace roughroll;
using roughroll_test::beta_pair;
using roughroll_test::rough_pair;

namespace {

// 8(p)'s closed form, written from its own formulas: F = (2/pi) lambda cosh(pi eps) sqrt(1 - r^2) exp(i eps Lambda).
double closed_pressure(double eps, double r) {
    const double lambda = 1.0 / (1.0 + 4.0 * eps * eps);
    return 2.0 / M_PI * lambda * std::cosh(M_PI * eps) * std::sqrt(1.0 - r * r) * std::cos(eps * std::log((1.0 + r) / (1.0 - r)));
}
double closed_traction(double eps, double r) {
    const double lambda = 1.0 / (1.0 + 4.0 * eps * eps);
    return -2.0 / M_PI * lambda * std::cosh(M_PI * eps) * std::sqrt(1.0 - r * r) * std::sin(eps * std::log((1.0 + r) / (1.0 - r)));
}

struct field {
    const no_slip_coupled_solution* s;
    bool traction;  // p1, else p
    const kernel* k = nullptr;
    double r = 0.0;  // the kernel's argument is eta - r
};
double value_of(double eta, void* p) {
    const field& f = *static_cast<const field*>(p);
    const double v = f.traction ? f.s->traction(eta) : f.s->pressure(eta);
    return f.k ? v * (*f.k)(eta - f.r) : v;
}

// (1/pi) PV int g/(eta - r) by QAWC; int g K(eta - r) by QAGS on each side of the jump; int g by QAGS.
struct quadrature {
    gsl_integration_workspace* ws = gsl_integration_workspace_alloc(2000);
    ~quadrature() { gsl_integration_workspace_free(ws); }
    double cauchy(field f, double r) {
        f.k = nullptr;
        gsl_function F{&value_of, &f};
        double v = 0.0, e = 0.0;
        EXPECT_EQ(gsl_integration_qawc(&F, -1.0, 1.0, r, 1e-13, 1e-11, 2000, ws, &v, &e), GSL_SUCCESS);
        return v / M_PI;
    }
    double layer(field f, const kernel& k, double r) {
        f.k = &k;
        f.r = r;
        gsl_function F{&value_of, &f};
        double sum = 0.0;
        for (const auto& [a, b] : {std::pair{-1.0, r}, std::pair{r, 1.0}}) {
            double v = 0.0, e = 0.0;
            EXPECT_EQ(gsl_integration_qags(&F, a, b, 1e-14, 1e-12, 2000, ws, &v, &e), GSL_SUCCESS);
            sum += v;
        }
        return sum;
    }
    double load(field f) {
        f.k = nullptr;
        gsl_function F{&value_of, &f};
        double v = 0.0, e = 0.0;
        EXPECT_EQ(gsl_integration_qags(&F, -1.0, 1.0, 1e-14, 1e-12, 2000, ws, &v, &e), GSL_SUCCESS);
        return v;
    }
};

}  // namespace

// Smooth rollers: 8(p)'s lambda = 1/(1 + 4 eps^2), e = 0, xi = 4 eps/(pi (1 + 4 eps^2)), p and p1 pointwise, at every n
// (phi = c_0 exactly: the higher T_j's images must not disturb it).
TEST(NoSlipCoupled, SmoothRollersGiveBuflersClosedForm) {
    const kernel none;
    for (const double beta : {beta_pair, 0.5, -0.3, 0.7}) {
        for (const int n : {0, 1, 8, 40}) {
            SCOPED_TRACE(::testing::Message() << "beta_D " << beta << ", n " << n);
            const no_slip_coupled_solution s = no_slip_coupled(beta, none, none, n);
            const double eps = std::log((1.0 - beta) / (1.0 + beta)) / (2.0 * M_PI);
            EXPECT_NEAR(std::tanh(M_PI * s.epsilon), -beta, 1e-15);
            EXPECT_NEAR(s.load_ratio, 1.0 / (1.0 + 4.0 * eps * eps), 1e-13);
            EXPECT_NEAR(s.xi, 4.0 * eps / (M_PI * (1.0 + 4.0 * eps * eps)), 1e-13);
            EXPECT_NEAR(s.offset, 0.0, 1e-13);
            EXPECT_NEAR(s.tangential_load, 0.0, 1e-13);
            for (const double r : {-0.9999, -0.6, 0.0, 0.3, 0.95}) {
                EXPECT_NEAR(s.pressure(r), closed_pressure(eps, r), 1e-13) << r;
                EXPECT_NEAR(s.traction(r), closed_traction(eps, r), 1e-13) << r;
            }
        }
    }
    // The pair with beta_D from its materials (8(a), written out): 8(p)'s table (-0.0582058, lambda 0.9915696), not
    // Johnson's -4 beta_D/pi^2 = -0.0582936.
    const double C = 0.69 / 23.0 + 0.72 / 82.0, beta_materials = (0.38 / 23.0 - 0.44 / 82.0) / (2.0 * C);
    const no_slip_coupled_solution s = no_slip_coupled(beta_materials, none, none, 0);
    EXPECT_NEAR(s.xi, -0.0582058, 5e-8);
    EXPECT_NEAR(s.load_ratio, 0.9915696, 5e-8);
    EXPECT_GT(std::fabs(s.xi + 4.0 * beta_materials / (M_PI * M_PI)), 8e-5);
}

// Rough layers: p and p1 of the solution put into (D1) and the stick equation of (D2) by GSL's quadratures (no
// fundamental function, no Joukowski coefficients, no tanh-sinh): the residuals at seven points, the loads int p = 1
// and int p1 = 0. Measured at n = 96: residuals at most 1.2e-7 (D1 at r = -0.98; 1e-9 to 1e-8 inside), the collocation's
// error between its points (8(t)).
TEST(NoSlipCoupled, RoughLayersSolveTheCoupledEquationsByQuadrature) {
    gsl_set_error_handler_off();
    const roughness layer = rough_pair();
    const kernel k1 = kernel::tangential(layer), k2 = kernel::normal(layer);
    const no_slip_coupled_solution s = no_slip_coupled(beta_pair, k1, k2, 96);
    quadrature q;
    const field p{&s, false}, p1{&s, true};
    EXPECT_NEAR(q.load(p), 1.0, 1e-10);
    EXPECT_NEAR(q.load(p1), 0.0, 1e-10);
    EXPECT_NEAR(s.offset, 0.0, 1e-12);  // p even, p1 odd: the kernels are odd (8(t))
    for (const double r : {-0.98, -0.7, -0.25, 0.05, 0.4, 0.75, 0.97}) {
        SCOPED_TRACE(r);
        const double d1 = q.cauchy(p, r) + q.layer(p, k2, r) + beta_pair * s.traction(r) + 2.0 / M_PI * s.load_ratio * (r + s.offset);
        const double d2 = q.cauchy(p1, r) + q.layer(p1, k1, r) - beta_pair * s.pressure(r) - s.xi;
        EXPECT_LT(std::fabs(d1), 2e-7);
        EXPECT_LT(std::fabs(d2), 2e-7);
    }
}

// Against the independent low-order route (validation/no_slip_full.py, route B: p, p1 = sqrt(1 - r^2) sum U_k, order 2,
// Richardson-extrapolated from n = 256, 512, 1024; 8(t)'s table): lambda = 1.5097108403, xi = -0.0555262924, the routine at
// n = 256 within 3e-9 (measured 8e-10, 2e-10). And the order: lambda's and xi's changes from n = 64 to 128 to 256 fall by
// more than 8 (measured 16.2 and 14.6; 3.9 would be route B's order 2).
TEST(NoSlipCoupled, RoughLayersAgainstTheLowOrderRoute) {
    const roughness layer = rough_pair();
    const kernel k1 = kernel::tangential(layer), k2 = kernel::normal(layer);
    std::vector<no_slip_coupled_solution> levels;
    for (const int n : {64, 128, 256}) levels.push_back(no_slip_coupled(beta_pair, k1, k2, n));
    EXPECT_NEAR(levels[2].load_ratio, 1.5097108403, 3e-9);
    EXPECT_NEAR(levels[2].xi, -0.0555262924, 3e-9);
    const double l1 = levels[1].load_ratio - levels[0].load_ratio, l2 = levels[2].load_ratio - levels[1].load_ratio;
    const double x1 = levels[1].xi - levels[0].xi, x2 = levels[2].xi - levels[1].xi;
    EXPECT_GT(std::fabs(l1 / l2), 8.0);
    EXPECT_GT(std::fabs(x1 / x2), 8.0);
    // The layers raise lambda (2(c): roughness adds compliance) and keep the creep's sign.
    EXPECT_GT(levels[2].load_ratio, 1.0);
    EXPECT_LT(levels[2].xi, 0.0);
}

// The crossing where |p1| = f p (8(t), item 1): smooth rollers against 8(p)'s 2/(1 + exp(arctan(f)/|eps|)), from f = 0.05
// (t_c = 0.2) to 1e6 (t_c at t_inf = 3.2e-15 for the pair, past the rounding of r); rough layers: |p1| = f p at the point
// returned (r = -1 + t_c, f = 0.2) and, for thin layers (f = 10, t_c = 6e-15), 2 exp(-(arctan f + |theta|)/|eps|) with theta
// the phase of phi(-1) (measured: equal to 1e-8; 1.0004 at f = 0.5, t_c = 1.8e-5, where the layers are not thin).
TEST(NoSlipCoupled, CrossingWhereTheTractionReachesFrictionTimesPressure) {
    const kernel none;
    for (const double beta : {beta_pair, 0.5}) {
        const no_slip_coupled_solution s = no_slip_coupled(beta, none, none, 0);
        const double eps = std::fabs(std::log((1.0 - beta) / (1.0 + beta)) / (2.0 * M_PI));
        for (const double f : {0.05, 0.2, 1.0, 10.0, 1e6}) {
            const double expected = 2.0 / (1.0 + std::exp(std::atan(f) / eps));
            EXPECT_NEAR(s.crossing(f) / expected, 1.0, 1e-12) << beta << " " << f;
        }
    }
    const roughness layer = rough_pair();
    const no_slip_coupled_solution s = no_slip_coupled(beta_pair, kernel::tangential(layer), kernel::normal(layer), 96);
    const double t = s.crossing(0.2);
    EXPECT_GT(t, 1e-3);
    EXPECT_NEAR(std::fabs(s.traction(-1.0 + t)) / s.pressure(-1.0 + t), 0.2, 1e-9);
    std::complex<double> edge = 0.0;  // phi(-1) = sum (-1)^j phi_j
    for (std::size_t j = 0; j < s.phi.size(); ++j) edge += (j % 2 == 0 ? 1.0 : -1.0) * s.phi[j];
    const double eps = std::fabs(s.epsilon);
    EXPECT_NEAR(s.crossing(10.0) / (2.0 * std::exp(-(std::atan(10.0) + std::fabs(std::arg(edge))) / eps)), 1.0, 1e-6);
    EXPECT_THROW(s.crossing(0.0), input_error);
}

// Exchanging the rollers (beta_D -> -beta_D with the same layers) changes the signs of p1 and xi and keeps p and lambda
// (8(h)); beta_D = 0 and |beta_D| >= 3/4 are refused with one line.
TEST(NoSlipCoupled, ExchangedRollersAndRefusals) {
    const roughness layer = rough_pair();
    const kernel k1 = kernel::tangential(layer), k2 = kernel::normal(layer);
    const no_slip_coupled_solution a = no_slip_coupled(beta_pair, k1, k2, 32), b = no_slip_coupled(-beta_pair, k1, k2, 32);
    EXPECT_NEAR(a.load_ratio, b.load_ratio, 1e-13);
    EXPECT_NEAR(a.xi, -b.xi, 1e-14);
    for (const double r : {-0.8, 0.1, 0.6}) {
        EXPECT_NEAR(a.pressure(r), b.pressure(r), 1e-13);
        EXPECT_NEAR(a.traction(r), -b.traction(r), 1e-13);
    }
    EXPECT_THROW(no_slip_coupled(0.0, k1, k2, 8), input_error);
    EXPECT_THROW(no_slip_coupled(0.75, k1, k2, 8), input_error);
    EXPECT_THROW(no_slip_coupled(0.1, k1, k2, -1), input_error);
}

// The route's traction (edge_layers.hpp, coupled_no_slip_traction; session 16 review N5): the limit's p1 held to
// [-f p, f p] with the pressure reported beside it. Where that pressure is negative (the limit's tension within
// t_inf = 2/(1 + exp(pi/(2 |eps|))) of an edge: 2.5e-4 at beta_D = 0.498) the old clamp returned -f p = f |p|, positive
// whatever p1's sign, and |p1| > f p in the row; now 0. And with the reported pressure (the interpolant of
// no_slip_normal, n = 32, which differs from the closed form between the nodes) every row keeps |p1| <= f p.
TEST(NoSlipCoupled, RouteTractionHeldByTheReportedPressure) {
    const double beta = 0.498, f = 10.0;
    const roughroll::no_slip_coupled_solution limit = roughroll::no_slip_coupled(beta, {}, {}, 0);
    const double t_inf = 2.0 / (1.0 + std::exp(M_PI / (2.0 * std::fabs(limit.epsilon))));
    ASSERT_GT(t_inf, 1e-4);
    for (const double r : {-1.0 + 1e-6, -1.0 + 1e-5, 1.0 - 1e-5}) {
        SCOPED_TRACE(r);
        const double p = limit.pressure(r);
        ASSERT_LT(p, 0.0);  // inside t_inf: tension
        EXPECT_EQ(roughroll::coupled_no_slip_traction(limit, f, p, r), 0.0);
    }
    const roughroll::normal_solution reported = roughroll::no_slip_normal(limit, 32, roughroll::method::product);
    int clamped = 0;
    for (int i = 0; i <= 20000; ++i) {  // at f = 1: t_c = 0.022
        const double r = -1.0 + 2.0 * i / 20000.0, p = reported.pressure(r);
        const double p1 = roughroll::coupled_no_slip_traction(limit, 1.0, p, r);
        EXPECT_LE(std::fabs(p1), std::max(0.0, p)) << r;
        if (std::fabs(p1) < std::fabs(limit.traction(r))) {
            ++clamped;
        } else {
            EXPECT_EQ(p1, limit.traction(r)) << r;
        }
    }
    EXPECT_GT(clamped, 100);  // rows within t_c of the edges
}
