// SPDX-License-Identifier: GPL-3.0-or-later
// The errata of docs/formulation.md (section 4) that change a number, each shown by solving the
// paper as printed next to the consistent formulation the library solves. The printed
// variants live here only: the library never solves them.
//
//   E2   (3.23)-(3.24) overall sign -          -> negative normal load, creep below Carter
//   E4   (3.25) t* maps the stick variable to [-c0, 1]  -> alone: creep of the wrong sign
//   E5   (3.16), (3.21) right side xi - f G    -> with or without E4: Q(c0) > f, no root for c0
//   E6   (3.21) K1*(tau - t) without Jacobian  -> the stick equation is not satisfied
//   E8   (4.4) G(s_m) by the node sum          -> Q(c0) jumps, c0 loses its 1/n^2 convergence
//
// The tangential system is assembled here from the library's public building blocks,
// with a switch per erratum; with every switch off it is the library's system (checked).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/model/carter.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/numerics/linear_system.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/tangential_solver.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {

// Which parts of the tangential system (4.4)-(4.5) are taken as printed.
struct variant {
    bool printed_map = false;     // E4: G at t* = rho t + (1 - rho), not r(t) = rho t + rho - 1
    bool printed_sign = false;    // E5: right side xi - f G, not xi + f G
    bool printed_kernel = false;  // E6: K1*(eta_k - s_m), not rho K1*(rho (eta_k - s_m))
};

struct stick_solution {
    double c0, xi, Q;
    std::vector<double> psi_b;  // U coefficients of psi(t), q0 = psi sqrt(1 - t^2)

    double rho() const { return 0.5 * (1.0 + c0); }
};

using g_function = std::function<double(double)>;

// The tangential system at a trial c0, assembled as src/problems/tangential_problem.cpp does:
// rows m = 0..n collocation at s_m, columns psi_k and -1 for xi, right side +-f G(map(s_m));
// then Q(c0) = f + rho sum_k w_k psi_k (4.5).
stick_solution solve_at(const normal_solution& normal, const kernel& k1, double f, const g_function& G, double c0,
                        variant v) {
    const auto& rule = normal.rule;
    const int n = rule.n;
    const double rho = 0.5 * (1.0 + c0);
    dense_system system(static_cast<std::size_t>(n) + 1);
    gsl_matrix* a = system.matrix();
    gsl_matrix_set_zero(a);
    add_cauchy_term(a, rule);
    add_kernel_term(a, v.printed_kernel ? k1 : k1.stretched(rho), rule, normal.how);
    for (int m = 0; m <= n; ++m) {
        gsl_matrix_set(a, m, n, -1.0);
        const double s = rule.collocation[m];
        const double r = v.printed_map ? rho * s + (1.0 - rho) : rho * (s + 1.0) - 1.0;
        gsl_vector_set(system.rhs(), m, (v.printed_sign ? -f : f) * G(r));
    }
    const gsl_vector* x = system.solve("test tangential system");
    std::vector<double> psi(n);
    double load = 0.0;
    for (int k = 0; k < n; ++k) {
        psi[k] = gsl_vector_get(x, k);
        load += rule.weights[k] * psi[k];
    }
    return {c0, gsl_vector_get(x, n), f + rho * load, u_coefficients(rule, psi)};
}

// c0 with Q(c0) = Q by bisection: Q(-1) = f > Q > Q(1) brackets the root, and bisection
// needs no continuity, so it also serves the node-sum variant of E8 whose Q(c0) jumps.
stick_solution solve_for(const normal_solution& normal, const kernel& k1, double f, const g_function& G, double Q,
                         variant v) {
    double lo = -1.0, hi = 1.0;
    while (hi - lo > 1e-14) {
        const double mid = 0.5 * (lo + hi);
        (solve_at(normal, k1, f, G, mid, v).Q > Q ? lo : hi) = mid;
    }
    return solve_at(normal, k1, f, G, 0.5 * (lo + hi), v);
}

// int_{-1}^{c0} q0(eta) K(eta - r) d eta by GSL's adaptive QAWS, independent of the
// library's quadratures: split at the jump eta = r, the square-root end of each piece
// (q0 ~ sqrt(eta + 1) at -1, sqrt(c0 - eta) at c0) taken by the QAWS weight.
double stick_kernel_integral(const stick_solution& s, const kernel& k, double r) {
    struct piece {
        const stick_solution* s;
        const kernel* k;
        double r;
        bool left;  // [-1, r]: weight sqrt(eta + 1); [r, c0]: weight sqrt(c0 - eta)
    };
    auto integrand = [](double eta, void* p) {
        const auto* c = static_cast<const piece*>(p);
        const double rho = c->s->rho();
        // sqrt(1 - t^2) = sqrt((eta + 1)(c0 - eta))/rho; the weight carries one factor.
        const double other = c->left ? c->s->c0 - eta : eta + 1.0;
        return u_series(c->s->psi_b, (eta + 1.0 - rho) / rho) * std::sqrt(std::max(0.0, other)) / rho *
               (*c->k)(eta - c->r);
    };
    gsl_guard();
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
    double total = 0.0;
    for (bool left : {true, false}) {
        gsl_integration_qaws_table* t = gsl_integration_qaws_table_alloc(left ? 0.5 : 0.0, left ? 0.0 : 0.5, 0, 0);
        piece p{&s, &k, r, left};
        gsl_function F{integrand, &p};
        double value = 0.0, err = 0.0;
        const int status =
            gsl_integration_qaws(&F, left ? -1.0 : r, left ? r : s.c0, t, 1e-15, 1e-12, 1000, w, &value, &err);
        gsl_integration_qaws_table_free(t);
        EXPECT_EQ(status, GSL_SUCCESS) << gsl_strerror(status) << " at r = " << r;
        EXPECT_LT(err, 1e-11) << "QAWS error estimate at r = " << r;  // far below the residuals measured
        total += value;
    }
    gsl_integration_workspace_free(w);
    return total;
}

// Residual of the ORIGINAL stick-zone equation, in the physical coordinate r:
//   (1/pi) PV int_{-1}^{c0} q0/(eta - r) + int_{-1}^{c0} q0 K1*(eta - r) - xi - f G(r).
// The Cauchy part is invariant under eta = rho (tau + 1) - 1 and exact for the U-series.
double stick_residual(const stick_solution& s, const kernel& k1, double f, const g_function& G, double r) {
    const double t = (r + 1.0 - s.rho()) / s.rho();
    return cauchy_u_series(s.psi_b, t) + stick_kernel_integral(s, k1, r) - s.xi - f * G(r);
}

kernel single_term(double T, double A) { return kernel(std::vector<exponential_term>{{T, A}}); }

}  // namespace

TEST(Errata, E2PrintedKernelSign) {
    // (3.9)-(3.10), (3.23)-(3.24) print K* = -[T exp(-A|z|)] sgn z. Roughness adds
    // compliance only with the sign +: then lambda = P_H/P2 > 1 and the creep lies above
    // Carter's, as Sec. 4 concludes. The printed sign reverses both. No tolerances: the
    // assertions are inequalities about O(1) quantities (lambda - 1, xi/xi_Carter - 1).
    const int n = 64;
    const double f = 0.3, Q = 0.15;

    const kernel printed1 = single_term(-1.0, 0.5), consistent1 = single_term(1.0, 0.5);
    const double lp1 = normal_solver(n, method::paper).solve(printed1).lambda;
    const double lc1 = normal_solver(n, method::paper).solve(consistent1).lambda;
    EXPECT_LT(lp1, 0.0) << "T = 1, A = 0.5: printed sign gives P_H/P2 = " << lp1
                        << " (a negative normal load), consistent " << lc1;
    EXPECT_GT(lc1, 1.0) << "T = 1, A = 0.5: consistent P_H/P2 = " << lc1 << ", printed " << lp1;

    const kernel printed = single_term(-0.5, 0.5), consistent = single_term(0.5, 0.5);
    const normal_solution np = normal_solver(n, method::paper).solve(printed);
    const normal_solution nc = normal_solver(n, method::paper).solve(consistent);
    EXPECT_LT(np.lambda, 1.0) << "T = A = 0.5: printed P_H/P2 = " << np.lambda << ", consistent " << nc.lambda;
    EXPECT_GT(nc.lambda, 1.0) << "T = A = 0.5: consistent P_H/P2 = " << nc.lambda << ", printed " << np.lambda;

    const double xi_printed = tangential_solver(np, printed, printed, f).solve(Q).xi;
    const double xi_consistent = tangential_solver(nc, consistent, consistent, f).solve(Q).xi;
    const double xi_carter = carter(Q, f).xi;
    EXPECT_LT(xi_printed, xi_carter) << "T = A = 0.5, Q/f = 0.5: printed sign gives creep " << xi_printed
                                     << " below Carter's " << xi_carter << " (consistent " << xi_consistent
                                     << "), against Sec. 4's conclusion";
    EXPECT_GT(xi_consistent, xi_carter) << "T = A = 0.5, Q/f = 0.5: consistent creep " << xi_consistent << ", Carter "
                                        << xi_carter << ", printed " << xi_printed;
}

TEST(Errata, E4E5PrintedStickMapAndSign) {
    // Smooth cylinders (empty kernels, lambda = 1, G(r) = (2/pi) r): psi is a constant b0,
    // the Cauchy term of b0 sqrt(1 - t^2) is -b0 t (exact at every n), and each variant
    // is solved in closed form by matching the terms in t, with rho = (1 + c0)/2:
    //   consistent  -b0 t - xi = +(2f/pi)(rho t + rho - 1): Q = f(1 - rho^2), xi = (2f/pi)(1 - rho)  (Carter)
    //   E4 and E5   -b0 t - xi = -(2f/pi)(rho t + 1 - rho): Q = f(1 + rho^2) > f
    //   E5 alone    -b0 t - xi = -(2f/pi)(rho t + rho - 1): Q = f(1 + rho^2) > f, xi < 0
    //   E4 alone    -b0 t - xi = +(2f/pi)(rho t + 1 - rho): Q = f(1 - rho^2),  xi = -(2f/pi)(1 - rho)
    // So with (3.16)/(3.21)'s sign the load exceeds f for every c0 and the Brent search on
    // [-1, 1] has no root for any 0 < Q < f; with (3.25)'s map alone a root exists but the
    // creep has the wrong sign. The scheme reproduces these exactly: tolerance 1e-13 is
    // rounding in an LU solve of size n + 1 = 33 on O(0.1) quantities (measured 3e-16).
    const double f = 0.3;
    const normal_solution hertz = hertz_solution(32, method::paper);
    const g_function G = [](double r) { return M_2_PI * r; };
    const kernel smooth;
    for (int i = 0; i <= 40; ++i) {
        const double c0 = i == 0 ? -0.999 : i == 40 ? 0.999 : -1.0 + i / 20.0;
        const double rho = 0.5 * (1.0 + c0), carter_xi = M_2_PI * f * (1.0 - rho);
        const stick_solution ok = solve_at(hertz, smooth, f, G, c0, {});
        const stick_solution both = solve_at(hertz, smooth, f, G, c0, {true, true, false});
        const stick_solution e5 = solve_at(hertz, smooth, f, G, c0, {false, true, false});
        const stick_solution e4 = solve_at(hertz, smooth, f, G, c0, {true, false, false});

        EXPECT_NEAR(ok.Q, f * (1.0 - rho * rho), tol::dense_solve) << "consistent, c0 = " << c0;
        EXPECT_NEAR(ok.xi, carter_xi, tol::dense_solve) << "consistent, c0 = " << c0;

        EXPECT_GT(both.Q, f) << "E4 + E5 as printed, c0 = " << c0 << ": Q(c0) = " << both.Q << " > f = " << f;
        EXPECT_NEAR(both.Q, f * (1.0 + rho * rho), tol::dense_solve) << "E4 + E5, c0 = " << c0;

        EXPECT_GT(e5.Q, f) << "E5 alone, c0 = " << c0 << ": Q(c0) = " << e5.Q;
        EXPECT_LT(e5.xi, 0.0) << "E5 alone, c0 = " << c0 << ": xi = " << e5.xi;

        EXPECT_NEAR(e4.Q, ok.Q, tol::dense_solve) << "E4 alone, c0 = " << c0;
        EXPECT_NEAR(e4.xi, -carter_xi, tol::dense_solve) << "E4 alone, c0 = " << c0 << ": creep opposite to the load";
    }
}

TEST(Errata, E6MissingJacobian) {
    // (3.21) prints the kernel term as int q(tau) K1*(tau - t) d tau. With s = r0 tau - r1
    // the Jacobian is rho = (1 + c0)/2 and s - x1 = a rho (tau - t): the consistent term is
    // rho int q K1*(rho (tau - t)). Both variants are solved for the same load and the
    // residual of the original stick equation is evaluated in r, off the collocation points,
    // with an independent kernel quadrature (QAWS).
    const double f = 0.3, Q = 0.15;
    const kernel k = single_term(1.0, 0.5);  // K1* = K2*: G(r) = (2/pi) lambda r
    const carter_point smooth = carter(Q, f);
    // Stick-zone points as fractions of [-1, c0]. The midpoint is left out: with equal
    // kernels both residuals are odd about it and vanish there (measured 1e-15).
    const double fractions[] = {0.05, 0.1, 0.3, 0.7, 0.9, 0.95};

    double res_ok[2] = {0, 0}, res_printed[2] = {0, 0};
    const int ns[2] = {48, 96};
    for (int i = 0; i < 2; ++i) {
        const normal_solution normal = normal_solver(ns[i], method::paper).solve(k);
        const g_function G = [&](double r) { return M_2_PI * normal.lambda * r; };
        const stick_solution ok = solve_for(normal, k, f, G, Q, {});
        const stick_solution printed = solve_for(normal, k, f, G, Q, {false, false, true});

        // Switches off, the test's system is the library's: same c0 and xi up to the two
        // root searches' tolerances (1e-14 here, 1e-15 Brent) times the slope of Q(c0).
        const tangential_solution lib = tangential_solver(normal, k, k, f).solve(Q);
        EXPECT_NEAR(ok.c0, lib.c0(), tol::two_routes);
        EXPECT_NEAR(ok.xi, lib.xi, tol::two_routes);

        // Why the printed form fails: with K1* = K2* and no Jacobian, the stick equation in
        // t is the normal equation (3.19) in r, solved by q = -f rho p. Then Q = f(1 - rho^2)
        // and xi = lambda (2f/pi)(1 - rho) + f rho gamma_0n: c0 is Carter's whatever the
        // roughness, and xi is Carter's times lambda. Exact for the discrete system too
        // (same matrix as (4.2)), so only the bisection tolerance and rounding remain.
        EXPECT_NEAR(printed.c0, smooth.c0, tol::two_routes) << "printed (3.21) loses the roughness in c0";
        EXPECT_NEAR(printed.xi, normal.lambda * smooth.xi, tol::two_routes);
        // The consistent c0 depends on the roughness: O(0.1) away from Carter's here.
        EXPECT_GT(std::fabs(ok.c0 - smooth.c0), 0.01) << "consistent c0 " << ok.c0 << ", Carter " << smooth.c0;

        for (double u : fractions) {
            const double r_ok = -1.0 + (1.0 + ok.c0) * u, r_printed = -1.0 + (1.0 + printed.c0) * u;
            res_ok[i] = std::max(res_ok[i], std::fabs(stick_residual(ok, k, f, G, r_ok)));
            res_printed[i] = std::max(res_printed[i], std::fabs(stick_residual(printed, k, f, G, r_printed)));
        }
        std::printf(
            "E6 n = %d: c0 %.10f (printed %.10f, Carter %.10f), xi %.10f (printed %.10f), "
            "max |residual| %.3e (printed %.3e)\n",
            ns[i], ok.c0, printed.c0, smooth.c0, ok.xi, printed.xi, res_ok[i], res_printed[i]);
    }
    // Consistent: the residual is discretisation error of the paper's scheme (second order
    // for kernels with a jump, docs/formulation.md, section 3): it falls by about 4 from
    // n = 48 to 96 (accept more than 3). Printed: the residual is the missing Jacobian,
    // a model error that does not fall with n (accept a change below 1.5x) and exceeds
    // the consistent one by orders of magnitude (accept more than 100x).
    EXPECT_GT(res_ok[0] / res_ok[1], 3.0) << res_ok[0] << " -> " << res_ok[1];
    EXPECT_LT(res_printed[0] / res_printed[1], 1.5) << res_printed[0] << " -> " << res_printed[1];
    EXPECT_GT(res_printed[1], 100.0 * res_ok[1]) << "printed " << res_printed[1] << ", consistent " << res_ok[1];
}

TEST(Errata, E8NodeSumG) {
    // (4.4) prints G*[s_m, phi(s_m)] and invites the node sum
    //   G(r_m) = (2/pi) lambda r_m + sum_k w_k phi_k (K2* - K1*)(eta_k - r_m).
    // With K1* != K2* the summand jumps at eta_k = r_m, and r_m = rho (s_m + 1) - 1 moves
    // with c0: each time it crosses a node, G(r_m) and so Q(c0) jump. The library
    // integrates G on the interpolant of phi, split at the jump: G and Q(c0) are smooth.
    const double f = 0.3, Q = 0.15;
    roughness surfaces;
    surfaces.cylinder1.tangential = {0.8, 1.5};
    surfaces.cylinder1.normal = {0.5, 0.5};
    surfaces.cylinder2.tangential = {0.3, 3.0};
    const kernel k1 = kernel::tangential(surfaces), k2 = kernel::normal(surfaces), dk = k2.minus(k1);

    contact reference(surfaces, f, solver_options{320, method::product});
    const double c0_ref = reference.point(Q).c0();

    double previous_lib = 0.0;  // the library's c0 error at n/2
    for (int n : {40, 80, 160}) {
        const normal_solution normal = normal_solver(n, method::paper).solve(k2);
        tangential_solver lib(normal, k1, k2, f);
        const g_function G_lib = [&](double r) { return lib.G(r); };
        const g_function G_sum = [&](double r) {
            double g = M_2_PI * normal.lambda * r;
            for (int k = 0; k < n; ++k) g += normal.rule.weights[k] * normal.phi[k] * dk(normal.rule.nodes[k] - r);
            return g;
        };
        // The only difference between the variants is G: with the library's G the test's
        // system gives the library's Q(c0) (to rounding).
        EXPECT_NEAR(solve_at(normal, k1, f, G_lib, 0.3, {}).Q, lib.load(0.3), tol::dense_solve);

        if (n <= 80) {
            // (a) Q(c0) on grids of step d = 1e-3 and 1e-4 over [0, 0.02]. The largest second
            // difference scales as d^2 for a smooth function (falls 100x), as d at a kink
            // (10x) and not at all at a jump (1x). Accept: library more than 50x, node sum
            // less than 3x, i.e. a jump.
            double second[2][2] = {{0, 0}, {0, 0}};  // [variant: lib, sum][grid]
            const int steps[2] = {20, 200};
            for (int g = 0; g < 2; ++g) {
                std::vector<double> q_lib, q_sum;
                for (int i = 0; i <= steps[g]; ++i) {
                    const double c0 = 0.02 * i / steps[g];
                    q_lib.push_back(solve_at(normal, k1, f, G_lib, c0, {}).Q);
                    q_sum.push_back(solve_at(normal, k1, f, G_sum, c0, {}).Q);
                }
                for (int i = 1; i < steps[g]; ++i) {
                    second[0][g] = std::max(second[0][g], std::fabs(q_lib[i + 1] - 2 * q_lib[i] + q_lib[i - 1]));
                    second[1][g] = std::max(second[1][g], std::fabs(q_sum[i + 1] - 2 * q_sum[i] + q_sum[i - 1]));
                }
            }
            std::printf(
                "E8 n = %d: max |second difference of Q(c0)|, d = 1e-3 -> 1e-4: library %.3e -> %.3e, "
                "node sum %.3e -> %.3e\n",
                n, second[0][0], second[0][1], second[1][0], second[1][1]);
            EXPECT_GT(second[0][0] / second[0][1], 50.0) << "library Q(c0) should be smooth, n = " << n;
            EXPECT_LT(second[1][0] / second[1][1], 3.0) << "node-sum Q(c0) should jump, n = " << n;
        }

        // (b) c0 against the product-integration reference at n = 320.
        const double err_lib = lib.solve(Q).c0() - c0_ref;
        const double err_sum = solve_for(normal, k1, f, G_sum, Q, {}).c0 - c0_ref;
        std::printf("E8 n = %d: c0 error library %.3e, node sum %.3e\n", n, err_lib, err_sum);
        if (n > 40) {
            // Second order (docs/formulation.md, section 3): about 4 per doubling, accept 3 to 5.3.
            EXPECT_GT(previous_lib / err_lib, 3.0) << "n = " << n << ": " << previous_lib << " -> " << err_lib;
            EXPECT_LT(previous_lib / err_lib, 5.3) << "n = " << n << ": " << previous_lib << " -> " << err_lib;
        }
        previous_lib = err_lib;
        // The node sum's G is only first-order accurate (a jump inside a node interval) and
        // its error varies erratically with n (it changes sign; near n = 120 it passes
        // through zero by accident), so no order can be read from it. What holds at the
        // n of the brief: it stays at least an order of magnitude above the consistent error.
        EXPECT_GT(std::fabs(err_sum), 10.0 * std::fabs(err_lib))
            << "n = " << n << ": node sum " << err_sum << ", library " << err_lib;
    }
}
