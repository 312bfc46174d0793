// SPDX-License-Identifier: GPL-3.0-or-later
// Convergence of the rough solution as n grows. The reference comes from the other
// discretisation (product integration at large n), not from the same scheme, and the
// observed orders are measured: about 2 for the paper's node sums (the kernels jump at
// z = 0), about 4 for product integration.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {
struct values {
    double lambda, c0, xi;
};

values solve(const roughness& r, method how, int n, double Q, double f = 0.3) {
    contact c(r, f, solver_options{n, how});
    const auto s = c.point(Q);
    return {c.normal().lambda, s.c0(), s.xi};
}

roughness equal_kernels() {
    roughness r;
    r.cylinder1.tangential = r.cylinder1.normal = {0.5, 0.5};
    return r;
}

roughness unequal_kernels() {
    roughness r;
    r.cylinder1.tangential = {0.8, 1.5};
    r.cylinder1.normal = {0.5, 0.5};
    r.cylinder2.tangential = {0.3, 3.0};
    return r;
}

// Observed order of convergence from errors at n and 2n.
double order(double e_n, double e_2n) { return std::log2(std::fabs(e_n) / std::fabs(e_2n)); }

void expect_order(const roughness& r, method how, const std::vector<int>& ns, double lo, double hi, int ref_n = 320) {
    const double Q = 0.15;
    const values ref = solve(r, method::product, ref_n, Q);
    std::vector<values> err;
    for (int n : ns) {
        const values v = solve(r, how, n, Q);
        err.push_back({v.lambda - ref.lambda, v.c0 - ref.c0, v.xi - ref.xi});
    }
    for (std::size_t i = 0; i + 1 < ns.size(); ++i) {
        for (auto [name, a, b] :
             {std::tuple{"lambda", err[i].lambda, err[i + 1].lambda}, std::tuple{"c0", err[i].c0, err[i + 1].c0},
              std::tuple{"xi", err[i].xi, err[i + 1].xi}}) {
            const double p = order(a, b);
            EXPECT_GT(p, lo) << name << " n = " << ns[i] << ": errors " << a << " -> " << b;
            EXPECT_LT(p, hi) << name << " n = " << ns[i] << ": errors " << a << " -> " << b;
        }
    }
}
}  // namespace

TEST(Convergence, PaperSchemeIsSecondOrderEqualKernels) {
    expect_order(equal_kernels(), method::paper, {20, 40, 80, 160}, 1.8, 2.2);
}

TEST(Convergence, PaperSchemeIsSecondOrderUnequalKernels) {
    // G integrated on the interpolant split at its jump (E8): c0 converges too.
    expect_order(unequal_kernels(), method::paper, {20, 40, 80, 160}, 1.7, 2.3);
}

TEST(Convergence, ProductIntegrationIsFourthOrder) {
    // The pressure's end behaviour (1 -+ r)^{3/2} log(1 -+ r) left by the kernels limits the
    // order to 4. The unequal case's c0 error changes sign near n = 24, so the rate is read
    // from n = 48 on, against the finest product solution (the paper's scheme is too coarse
    // to serve as reference here).
    expect_order(equal_kernels(), method::product, {48, 96, 192}, 3.5, 4.6, 480);
    expect_order(unequal_kernels(), method::product, {48, 96, 192}, 3.5, 4.6, 480);
}

TEST(Convergence, GammaTendsToZero) {
    // (4.8): gamma_0n -> 0. The problem is symmetric with an odd right side, so the
    // consistency condition holds by itself and gamma_0n stays at rounding level.
    for (int n : {10, 40, 160}) {
        contact c(equal_kernels(), 0.3, solver_options{n, method::paper});
        EXPECT_LT(std::fabs(c.normal().gamma), tol::dense_solve) << "n = " << n;
    }
}

TEST(Convergence, ExtrapolatedReaches1e10) {
    // Richardson's rule on product integration at 64 and 128 against the product solution
    // at 480 (error ~5e-12 by its n^-4 rate): the extrapolated values agree to 1e-10 relative,
    // and the reported estimate is not below the actual difference.
    for (const roughness& r : {equal_kernels(), unequal_kernels()}) {
        contact ext(r, 0.3, solver_options{128, method::extrapolated});
        contact ref(r, 0.3, solver_options{480, method::product});
        EXPECT_NEAR(ext.normal().lambda / ref.normal().lambda, 1.0, 1e-10);
        for (double ratio : {0.1, 0.5, 0.9}) {
            const auto s = ext.point(ratio * 0.3), sr = ref.point(ratio * 0.3);
            EXPECT_NEAR(s.c0(), sr.c0(), 1e-10 * std::fabs(sr.c0())) << "Q/f = " << ratio;
            EXPECT_NEAR(s.xi / sr.xi, 1.0, 1e-10) << "Q/f = " << ratio;
            const auto e = ext.estimate(s);
            ASSERT_TRUE(e.has_value());
            EXPECT_GE(e->xi, std::fabs(s.xi - sr.xi));
            EXPECT_GE(e->c0, std::fabs(s.c0() - sr.c0()));
        }
    }
}

TEST(Convergence, SweptCurveAgreesWithRootSearchAndReaches1e10) {
    // A curve swept in c0 gives (Q(c0), xi(c0)) without a root search: solving for that Q
    // by Brent returns the same c0 and xi, and the extrapolated sweep at 128 agrees with the
    // product solution at 480 (same c0) to 1e-10 relative in Q and xi.
    for (const roughness& r : {equal_kernels(), unequal_kernels()}) {
        contact ext(r, 0.3, solver_options{128, method::extrapolated});
        contact ref(r, 0.3, solver_options{480, method::product});
        const auto curve = swept_curve(ext, 11);
        ASSERT_EQ(curve.size(), 11u);
        EXPECT_EQ(curve.front().solution.Q, 0.0);
        EXPECT_EQ(curve.back().solution.Q, 0.3);
        for (std::size_t i = 1; i + 1 < curve.size(); ++i) {
            const auto& s = curve[i].solution;
            const auto sr = ref.at_stick_end(s.c0()).solution;
            EXPECT_NEAR(s.Q / sr.Q, 1.0, 1e-10) << "c0 = " << s.c0();
            EXPECT_NEAR(s.xi / sr.xi, 1.0, 1e-10) << "c0 = " << s.c0();
            ASSERT_TRUE(curve[i].estimate.has_value());
            EXPECT_GE(curve[i].estimate->xi, std::fabs(s.xi - sr.xi));
            EXPECT_GE(curve[i].estimate->Q, std::fabs(s.Q - sr.Q));
            EXPECT_TRUE(s.checks.hold());
            // Round trip through the root search at the product level n = 128.
            contact prod(r, 0.3, solver_options{128, method::product});
            const auto level = prod.at_stick_end(s.c0()).solution;
            const auto back = prod.point(level.Q);
            EXPECT_NEAR(back.c0(), s.c0(), 1e-13);
            EXPECT_NEAR(back.xi, level.xi, 1e-13);
        }
    }
}
