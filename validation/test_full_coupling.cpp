// Full coupling of dissimilar rollers (docs/formulation.md 8(e)): the alternation of (D1) and (D2).
//   - the converged pair is self-consistent: the pressure's Chebyshev-U coefficients b solve the
//     projection of (D1), b_{j-1} = (2/pi) lambda delta_j1 + c_j[beta_D p1] and (2/pi) lambda e = -c_0[beta_D p1],
//     with c_j of the point's own traction p1 by GSL's adaptive QAGP (the zone ends as break points),
//     a route that shares neither the projection's quadrature nor the alternation;
//   - lambda, e and xi converge in n (the projected right side; the point values of p1 at the
//     collocation points left lambda erratic at 4e-5, 8(e));
//   - exchanging the rollers (beta_D -> -beta_D) with Q -> -Q gives xi -> -xi, the same pressure;
//   - beta_D = 0 is today's problem bit for bit (DissimilarProduct.BetaZeroIsTodaysProblemForEveryMethod).
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/problems/contact.hpp"

using namespace roughroll;

namespace {
// Dundurs' beta_D of aluminium (roller 1) on steel, 8(a).
const double beta_al_st = [] {
    const double C = 0.69 / 23.0 + 0.72 / 82.0;
    return (0.38 / 23.0 - 0.44 / 82.0) / (2.0 * C);
}();
const double f = 0.05;

contact full(int n, double beta = beta_al_st) {
    return contact(roughness{}, f, solver_options{n, method::product}, dissimilar{beta, coupling_level::full});
}

// (2 - delta_j0)/pi int_0^pi g(cos t) cos(j t) dt by QAGP, break points at acos of the ends.
double coefficient(const std::function<double(double)>& g, std::vector<double> ends, int j) {
    struct data {
        const std::function<double(double)>* g;
        int j;
    } d{&g, j};
    gsl_function F{[](double t, void* p) {
                       const auto* d = static_cast<const data*>(p);
                       return (*d->g)(std::cos(t)) * std::cos(d->j * t);
                   },
                   &d};
    std::vector<double> pts{0.0, M_PI};
    for (double r : ends)
        if (r > -1.0 && r < 1.0) pts.push_back(std::acos(r));
    std::sort(pts.begin(), pts.end());
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(4000);
    double result = 0.0, error = 0.0;
    const int status = gsl_integration_qagp(&F, pts.data(), pts.size(), 1e-13, 0.0, 4000, w, &result, &error);
    gsl_integration_workspace_free(w);
    EXPECT_TRUE(status == GSL_SUCCESS || (status == GSL_EROUND && error < 1e-12)) << j << ": " << error;
    return (j == 0 ? 1.0 : 2.0) / M_PI * result;
}
}  // namespace

TEST(FullCoupling, ConvergedPairSolvesTheProjectedNormalProblem) {
    for (const double Q : {-0.75 * f, 0.75 * f}) {
        contact c = full(32);
        const tangential_solution s = c.point(Q);
        ASSERT_NE(c.coupling(), nullptr);
        EXPECT_TRUE(c.distribution(s).checks.hold());
        const normal_solution& p = c.normal();
        const std::function<double(double)> coupled = [&](double r) { return beta_al_st * c.traction(s, r); };
        const std::vector<double> ends{s.start, s.c0, s.start2, s.end2};
        // The alternation stops when the traction's changes are below 1e-12 in xi and lambda, so
        // the last p1 and the one p was solved with differ by about that.
        EXPECT_NEAR(M_2_PI * p.lambda * p.offset, -coefficient(coupled, ends, 0), 1e-10) << Q;
        for (int j = 1; j <= 32; ++j)
            EXPECT_NEAR(p.b[j - 1], (j == 1 ? M_2_PI * p.lambda : 0.0) + coefficient(coupled, ends, j), 1e-10)
                << "Q = " << Q << ", j = " << j;
        // The coupling matters at this size: the pressure is not Johnson's.
        EXPECT_GT(std::fabs(p.offset), 1e-3);
    }
}

// Q/f = -0.75 (three zones): lambda and e to 1e-7 already at n = 32, xi to 1e-6; with the point
// values of p1 on the right side lambda moved by 2e-5 between n = 32 and 128 (8(e)).
TEST(FullCoupling, LambdaOffsetAndCreepConverge) {
    contact coarse = full(32), fine = full(128);
    const tangential_solution a = coarse.point(-0.75 * f), b = fine.point(-0.75 * f);
    EXPECT_NEAR(coarse.normal().lambda, fine.normal().lambda, 1e-7);
    EXPECT_NEAR(coarse.normal().offset, fine.normal().offset, 1e-7);
    EXPECT_NEAR(a.xi, b.xi, 1e-6);
    // ... while the full coupling moves xi from Johnson's by 5.6e-5 and lambda by 1.6e-4.
    contact johnson(roughness{}, f, solver_options{128, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    EXPECT_GT(std::fabs(b.xi - johnson.point(-0.75 * f).xi), 5e-5);
    EXPECT_GT(std::fabs(fine.normal().lambda - 1.0), 1e-4);
}

// Roller 1 and 2 exchanged: beta_D -> -beta_D, and Q -> -Q in roller 1's sign: beta_D p1 and with
// it the pressure are unchanged, p1 and xi change sign.
TEST(FullCoupling, RollersExchanged) {
    contact a = full(32), b = full(32, -beta_al_st);
    const tangential_solution sa = a.point(-0.75 * f), sb = b.point(0.75 * f);
    EXPECT_NEAR(sa.xi, -sb.xi, 1e-13);
    EXPECT_NEAR(a.normal().lambda, b.normal().lambda, 1e-13);
    EXPECT_NEAR(a.normal().offset, b.normal().offset, 1e-13);
    for (double x : {-0.9, -0.3, 0.2, 0.95}) {
        EXPECT_NEAR(a.traction(sa, x), -b.traction(sb, x), 1e-12);
        EXPECT_NEAR(a.normal().pressure(x), b.normal().pressure(x), 1e-13);
    }
}

// CONTACT's free rolling of this pair at f = 0.05 with full coupling, |xi1| = 0.000429 as its user
// guide is quoted (docs/reproduction.md), with xi1 = (pi a/(2R)) xi, a/R = 0.1/25 (8(f)): full coupling
// rounds to it at n = 32, Johnson's level does not (0.000428), and the two differ by more than
// CONTACT's last digit allows for either alone.
TEST(FullCoupling, FreeRollingAgainstContact) {
    const double scale = M_PI * (0.1 / 25.0) / 2.0;
    contact c = full(32);
    contact johnson(roughness{}, f, solver_options{32, method::product}, dissimilar{beta_al_st, coupling_level::johnson});
    const tangential_solution s = c.point(0.0), j = johnson.point(0.0);
    EXPECT_TRUE(s.five);
    EXPECT_NEAR(-scale * s.xi, 0.000429, 0.5e-6);
    EXPECT_GT(std::fabs(-scale * j.xi - 0.000429), 0.5e-6);
}

