// SPDX-License-Identifier: GPL-3.0-or-later
// Kernels (3.23)-(3.24) with errata E1, E2 and their moments against U_j sqrt(1 - x^2).
#include <algorithm>
#include <cmath>
#include <functional>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/gsl_handles.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/convolution_table.hpp"
#include "roughroll/numerics/u_series_table.hpp"
#include "roughroll/numerics/kernel_moments.hpp"
#include "roughroll/numerics/kernel_sweep.hpp"
#include "roughroll/numerics/theta_panels.hpp"
#include "tolerance.hpp"

using namespace roughroll;

namespace {
roughness both_rough() {
    roughness r;
    r.cylinder1.tangential = {0.5, 2.0};
    r.cylinder2.tangential = {0.25, 7.0};
    r.cylinder1.normal = {1.0, 0.5};
    return r;
}

// GSL's QAWS, adaptive with the algebraic end weights (1 + eta)^alpha (1 - eta)^beta
// integrated exactly: an independent route to int g(eta) sqrt(1 - eta^2) d eta on [lo, hi].
double adaptive(const std::function<double(double)>& g, double lo, double hi) {
    if (hi <= lo) return 0.0;
    const double alpha = lo == -1.0 ? 0.5 : 0.0, beta = hi == 1.0 ? 0.5 : 0.0;
    // The part of sqrt(1 - eta^2) that the weight does not carry stays in the integrand.
    std::function<double(double)> h = [&](double eta) {
        const double rest = (alpha == 0.5 ? 1.0 : std::sqrt(1.0 + eta)) * (beta == 0.5 ? 1.0 : std::sqrt(1.0 - eta));
        return g(eta) * rest;
    };
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(2000);
    gsl_integration_qaws_table* t = gsl_integration_qaws_table_alloc(alpha, beta, 0, 0);
    gsl_function F{[](double x, void* p) { return (*static_cast<std::function<double(double)>*>(p))(x); }, &h};
    double result = 0.0, err = 0.0;
    const int status = gsl_integration_qaws(&F, lo, hi, t, 1e-15, 1e-13, 2000, w, &result, &err);
    gsl_integration_qaws_table_free(t);
    gsl_integration_workspace_free(w);
    EXPECT_TRUE(status == 0 || err < 1e-13) << "QAWS status " << status << ", error " << err;
    return result;
}
}  // namespace

TEST(Kernel, BothCylindersPhysicalSignEachOwnRate) {
    const kernel k1 = kernel::tangential(both_rough());
    ASSERT_EQ(k1.terms().size(), 2u);
    const double z = 0.1;
    // E1: each term decays with its own A; E2: sign + for z > 0 (added compliance).
    const double expected = 0.5 * std::exp(-2.0 * z) + 0.25 * std::exp(-7.0 * z);
    EXPECT_NEAR(k1(z), expected, tol::reordered);
    EXPECT_NEAR(k1(-z), -expected, tol::reordered);
    EXPECT_GT(k1(z), 0.0);
    EXPECT_DOUBLE_EQ(k1.max_rate(), 7.0);
}

TEST(Kernel, ZeroAmplitudeTermsAreLeftOut) {
    const kernel k2 = kernel::normal(both_rough());
    ASSERT_EQ(k2.terms().size(), 1u);  // cylinder 2 normal is smooth
    EXPECT_TRUE(kernel::normal(roughness{}).empty());
    EXPECT_TRUE(kernel::tangential(roughness{}).empty());
}

TEST(Kernel, DifferenceCancelsEqualKernels) {
    roughness r;
    r.cylinder1.tangential = r.cylinder1.normal = {0.5, 0.5};
    EXPECT_TRUE(kernel::normal(r).minus(kernel::tangential(r)).empty());
    const kernel d = kernel::normal(both_rough()).minus(kernel::tangential(both_rough()));
    for (double z : {-0.7, 0.05, 0.4})
        EXPECT_NEAR(d(z), kernel::normal(both_rough())(z) - kernel::tangential(both_rough())(z), tol::reordered);
}

TEST(Kernel, StretchedIsRhoKOfRhoZ) {
    const kernel k = kernel::tangential(both_rough());
    const double rho = 0.37;
    for (double z : {-0.9, 0.2, 1.7}) EXPECT_NEAR(k.stretched(rho)(z), rho * k(rho * z), tol::reordered);
}

class Moments : public ::testing::TestWithParam<double> {};

TEST_P(Moments, AgreeWithAdaptiveQuadratureSplitAtTheJump) {
    const double A = GetParam();
    const kernel k(std::vector<exponential_term>{{0.8, A}, {-0.3, 0.5 * A + 1.0}});
    const int count = 40;
    kernel_moments moments(k, count);
    for (double r : {-2.0, -1.0, -0.999, -0.31, 0.0, 0.5, 0.9999, 1.0, 1.3}) {
        const auto I = moments.at(r);
        for (int j : {0, 1, 7, 20, 39}) {
            auto g = [&](double eta) {
                const double t = std::acos(eta);
                const double u = std::fabs(std::sin(t)) < 1e-300 ? (j + 1) : std::sin((j + 1) * t) / std::sin(t);
                return u * (eta == r ? 0.0 : k(eta - r));
            };
            const double lo = std::max(-1.0, std::min(1.0, r));
            const double exact = adaptive(g, -1.0, lo) + adaptive(g, lo, 1.0);
            EXPECT_NEAR(I[j], exact, tol::against_adaptive) << "A = " << A << ", r = " << r << ", j = " << j;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Rates, Moments, ::testing::Values(0.0, 0.5, 5.0, 50.0));

TEST(KernelSweep, AgreesWithMomentsAtSortedPoints) {
    // The two-sided recurrence (kernel_sweep) and the split moments (kernel_moments) are two
    // routes to the same integrals: a U-series g against K at many points, some repeated,
    // some at the ends, clustered like the stick-zone points of a small c0.
    const kernel k(std::vector<exponential_term>{{0.7, 3.0}, {-0.2, 40.0}, {0.4, 0.0}});
    const std::vector<double> b{0.3, -1.2, 0.5, 0.05, -0.3, 0.2, 0.01, -0.07};
    const std::vector<double> points{1.0, 0.999, 0.5, 0.5, 0.1, -0.2, -0.9, -0.9001, -0.95, -1.0};
    const int degree = static_cast<int>(b.size()) - 1;
    const auto swept =
        sweep(k, points, 1, degree, [&](double theta, double* out) { *out = u_series(b, std::cos(theta)); });
    kernel_moments moments(k, static_cast<int>(b.size()));
    for (std::size_t m = 0; m < points.size(); ++m)
        EXPECT_NEAR(swept[m], moments.integrate(b, points[m]), tol::short_sum) << "x = " << points[m];
}

TEST(KernelSweep, LagrangeBasisMatchesTheProductFormula) {
    // Off the nodes, l_k(x) = prod_{j != k} (x - eta_j)/(eta_k - eta_j): wrong barycentric
    // weights would pass a test on the nodes or of the partition of unity, not this one.
    const gauss_chebyshev rule(11);
    const lagrange_basis basis(rule);
    std::vector<double> l(rule.n);
    for (double theta : {0.05, 0.3, 1.234, 2.0, 3.1}) {
        basis(theta, l.data());
        const double x = std::cos(theta);
        for (int k = 0; k < rule.n; ++k) {
            double product = 1.0;
            for (int j = 0; j < rule.n; ++j)
                if (j != k) product *= (x - rule.nodes[j]) / (rule.nodes[k] - rule.nodes[j]);
            EXPECT_NEAR(l[k], product, tol::interpolation) << "theta = " << theta << ", k = " << k;
        }
    }
    basis(3 * M_PI / (rule.n + 1), l.data());  // on node 2: the unit vector
    for (int i = 0; i < rule.n; ++i) EXPECT_EQ(l[i], i == 2 ? 1.0 : 0.0);
}

TEST(KernelSweep, RejectsUnsortedPoints) {
    const kernel k(std::vector<exponential_term>{{1.0, 1.0}});
    auto one = [](double, double* out) { *out = 1.0; };
    EXPECT_THROW(sweep(k, {0.1, 0.2}, 1, 0, one), numerical_error);
    EXPECT_THROW(sweep(k, {1.5}, 1, 0, one), numerical_error);
}

TEST(USeriesTable, AgreesWithTheSeriesWithinItsBound) {
    // The tabulated pressure sqrt(1 - r^2) sum b_j U_j(r) against the series summed by Clenshaw, for
    // coefficients that fall algebraically (a rough layer's pressure: none below rounding) and
    // n from just above a panel's 25 terms to 300, at points uniform in theta and next to both ends.
    // The two may differ by the table's bound (at most eps B by construction) and the series' own
    // rounding (n eps B); a panel misplaced or a bound too small shows as far more.
    for (int n : {26, 64, 128, 300}) {
        std::vector<double> b(n);
        double l1 = 0.0;
        for (int j = 0; j < n; ++j) {
            b[j] = (j == 0 ? 0.64 : 0.0) + (j % 2 == 0 ? 0.3 : -0.3) / std::pow(1.0 + j, 3.5) + 1e-6 * std::sin(j);
            l1 += std::fabs(b[j]);
        }
        const u_series_table table(b);
        EXPECT_LE(table.error_bound(), GSL_DBL_EPSILON * l1) << "n = " << n;
        std::vector<double> r;
        for (int i = 0; i <= 3000; ++i) r.push_back(std::cos(M_PI * i / 3000.0 + 1e-4 * std::sin(7.0 * i)));
        for (double d : {1e-3, 1e-8, 1e-13, 1e-16}) r.insert(r.end(), {1.0 - d, -1.0 + d});
        double worst = 0.0;
        for (double x : r) {
            // sqrt((1 - x)(1 + x)): 1 - x^2 would lose eps/(1 - x^2) relative next to the ends.
            const double series = u_series(b, x) * std::sqrt(std::max(0.0, (1.0 - x) * (1.0 + x)));
            worst = std::max(worst, std::fabs(table(x) - series));
        }
        EXPECT_LE(worst, table.error_bound() + n * GSL_DBL_EPSILON * l1)
            << "n = " << n << ", " << table.panels() << " panels";
    }
    EXPECT_THROW(u_series_table(std::vector<double>{}), numerical_error);
}

TEST(USeriesTable, PanelBoundHoldsOnCoarsePanels) {
    // The Bernstein-ellipse bound of u_series_table::panel_bound against the measured error of
    // theta_panels' interpolant where it is far above rounding: coarse panels (bounds from 1e-3 to
    // 1e-11) of a series with all |b_j| equal (the largest P for its B) and of a falling one. The
    // measured error must not exceed the bound; a bound without the growth e^{n y} fails here.
    const int n = 128;
    for (int falling = 0; falling < 2; ++falling) {
        std::vector<double> b(n);
        double l1 = 0.0;
        for (int j = 0; j < n; ++j) {
            b[j] = (j % 3 == 1 ? -1.0 : 1.0) / (falling ? std::pow(1.0 + j, 2.0) : 1.0);
            l1 += std::fabs(b[j]);
        }
        for (int panels : {24, 32, 40}) {
            theta_panels table(panels);
            const int size = theta_panels::degree + 1;
            std::vector<double> values(static_cast<std::size_t>(panels) * size);
            // P = sum b_j sin((j+1) theta) term by term, at theta = acos r of the r evaluated (r's own
            // rounding moves theta by eps/sin theta next to the ends, and P with it).
            auto sines = [&b](double theta) {
                double sum = 0.0;
                for (int k = n; k-- > 0;) sum += b[k] * std::sin((k + 1) * theta);
                return sum;
            };
            for (int j = 0; j < panels; ++j)
                for (int i = 0; i < size; ++i) values[j * size + i] = sines(table.node(j, i));
            table.set_values(values);
            const double bound = u_series_table::panel_bound(n, M_PI / panels) * l1;
            double worst = 0.0;
            for (int i = 1; i < 4000; ++i) {
                const double r = std::cos(M_PI * i / 4000.0);
                worst = std::max(worst, std::fabs(table(r) - sines(std::acos(r))));
            }
            EXPECT_LE(worst, bound + n * GSL_DBL_EPSILON * l1) << panels << " panels, falling " << falling;
            EXPECT_GT(worst, 1e-30);
        }
    }
    EXPECT_THROW(theta_panels(0), numerical_error);
    EXPECT_THROW(theta_panels(3).set_values(std::vector<double>(3 * theta_panels::degree)), numerical_error);
}

TEST(ConvolutionTable, AgreesWithSweepAndMoments) {
    // The table of D(r) = int sqrt(1 - eta^2) phi(eta) K(eta - r) d eta (G of (3.25)) against two
    // other routes at points that are not its nodes: the two-sided recurrence at sorted points
    // (kernel_sweep) and the split moments (kernel_moments). Coefficients of a pressure-like
    // series (decaying, alternating) of n = 8, 64 and 200 terms; rates from 0 to 300.
    for (int n : {8, 64, 200}) {
        std::vector<double> b(n);
        for (int j = 0; j < n; ++j) b[j] = (j % 3 == 1 ? -1.0 : 1.0) * 0.8 / (1.0 + j * j) + 1e-3 * std::sin(j);
        for (double A : {0.0, 0.5, 3.0, 40.0, 300.0}) {
            const kernel k(std::vector<exponential_term>{{0.7, A}, {-0.2, 0.25 * A}, {0.4, 0.0}});
            const convolution_table table(k, b);
            EXPECT_LE(table.error_bound(), 1e-15 * table.scale());
            std::vector<double> points{1.0, -1.0};
            for (int i = 0; i < 301; ++i)
                points.push_back(std::cos(0.01 + 3.1 * std::sqrt(i / 300.0) * std::sqrt(i / 300.0)));
            std::sort(points.begin(), points.end(), std::greater<double>());
            const auto swept =
                sweep(k, points, 1, n - 1, [&](double theta, double* out) { *out = u_series(b, std::cos(theta)); });
            kernel_moments moments(k, n);
            double worst = 0.0;
            for (std::size_t m = 0; m < points.size(); ++m) {
                const double t = table(points[m]);
                worst = std::max(worst, std::fabs(t - swept[m]));
                EXPECT_NEAR(t, swept[m], 4e-15 * table.scale())
                    << "n = " << n << ", A = " << A << ", r = " << points[m];
                if (m % 10 == 0) {
                    EXPECT_NEAR(t, moments.integrate(b, points[m]), 4e-15 * table.scale())
                        << "n = " << n << ", A = " << A << ", r = " << points[m];
                }
            }
            // Measured: 2.6e-16 to 1.3e-15 of the size bound (the rounding of the routes), with
            // representation bounds of 6e-19 to 9e-17.
            EXPECT_GT(worst, 0.0);
        }
    }
}

TEST(ConvolutionTable, BatchedIsTheScalarOne) {
    // The points of a stick zone and of a slip grid at once (G of (3.25) per trial c0), in
    // batches that do not fill the last group of four: the scalar values, bit for bit.
    std::vector<double> b{0.3, -1.2, 0.5, 0.05, -0.3, 0.2, 0.01, -0.07, 0.4};
    const convolution_table table(kernel(std::vector<exponential_term>{{0.7, 3.0}, {-0.2, 0.5}}), b);
    std::vector<double> r;
    for (int i = 0; i < 23; ++i) r.push_back(std::cos(0.137 * i));
    r.push_back(1.5);  // clamped to 1
    for (std::size_t count : {std::size_t{1}, std::size_t{3}, r.size()}) {
        std::vector<double> out(count);
        table(r.data(), out.data(), count);
        for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(out[i], table(r[i])) << "count " << count << ", r = " << r[i];
    }
    EXPECT_EQ(table(1.5), table(1.0));
}

TEST(ConvolutionTable, BatchedUSeriesIsTheScalarOne) {
    std::vector<double> b{0.3, -1.2, 0.5, 0.05, -0.3, 0.2, 0.01, -0.07, 0.4};
    std::vector<double> x, out(21);
    for (int i = 0; i < 21; ++i) x.push_back(std::cos(0.15 * i));
    u_series(b, x.data(), out.data(), x.size());
    for (int i = 0; i < 21; ++i) EXPECT_EQ(out[i], u_series(b, x[i]));
}

TEST(KernelMoments, ClosedFormAtTheEnds) {
    // integrate_at_end (modified Bessel functions, Miller's recurrence) against the split
    // Gauss-Legendre moments at r = +-1, for rates from 0 to 2000 and 8 or 200 coefficients; the rates
    // below 1e-4 take the power series, those below about 1e-40 overflowed the recurrence (NaN).
    for (int n : {8, 200}) {
        std::vector<double> b(n);
        for (int j = 0; j < n; ++j) b[j] = (j % 3 == 1 ? -1.0 : 1.0) * 0.8 / (1.0 + j) + 1e-3 * std::cos(j);
        for (double A : {0.0, 1e-300, 1e-100, 1e-40, 1e-9, 9e-5, 1e-4, 1e-3, 0.5, 3.0, 40.0, 300.0, 2000.0}) {
            const kernel k(std::vector<exponential_term>{{0.7, A}, {-0.2, 2.0 * A}});
            kernel_moments moments(k, n);
            for (double end : {1.0, -1.0}) {
                const double exact = moments.integrate(b, end);
                EXPECT_NEAR(integrate_at_end(k, b, end), exact, 2e-15 * (1.0 + std::fabs(exact)))
                    << "n = " << n << ", A = " << A << ", end = " << end;
            }
        }
    }
    EXPECT_THROW(integrate_at_end(kernel(), {1.0}, 0.5), numerical_error);
}

TEST(KernelOperator, ServesEveryRateOfItsLayout) {
    // An operator built for the normal kernel's rate integrates every rate up to the reach of its
    // sweep's layout (kernel_sweep::same_layout_rate), with the values, bit for bit, of an operator
    // built for that rate alone: the tangential solver then shares the normal problem's workspace
    // for a K1* of another rate (unequal kernels), instead of building a second one. A rate beyond
    // the reach is refused by the sweep; the paper's node sum takes any rate.
    const gauss_chebyshev rule(64);
    const kernel normal(std::vector<exponential_term>{{0.5, 0.5}});
    const kernel tangential(std::vector<exponential_term>{{0.8, 1.5}, {0.3, 3.0}});
    const kernel steep(std::vector<exponential_term>{{1.0, 60.0}});
    const kernel_operator shared(rule, method::product, normal.max_rate());
    EXPECT_EQ(shared.max_rate(), kernel_sweep::same_layout_rate(rule.n - 1, normal.max_rate()));
    EXPECT_GE(shared.max_rate(), tangential.max_rate());
    EXPECT_LT(shared.max_rate(), steep.max_rate());
    matrix_ptr a = make_matrix(rule.n + 1, rule.n), b = make_matrix(rule.n + 1, rule.n);
    gsl_matrix_set_zero(a.get());
    gsl_matrix_set_zero(b.get());
    shared.add_to(a.get(), tangential);
    kernel_operator(rule, method::product, tangential.max_rate()).add_to(b.get(), tangential);
    for (int m = 0; m <= rule.n; ++m)
        for (int j = 0; j < rule.n; ++j)
            ASSERT_EQ(gsl_matrix_get(a.get(), m, j), gsl_matrix_get(b.get(), m, j)) << m << ", " << j;
    EXPECT_THROW(shared.add_to(a.get(), steep), numerical_error);
    EXPECT_TRUE(std::isinf(kernel_operator(rule, method::paper, normal.max_rate()).max_rate()));
}

TEST(SweepCache, SharedWorkspaceGivesTheSameOperator) {
    // Two normal kernels whose rates differ but need the same workspace (the trial widths of a
    // width search): the operators from one cache equal, bit for bit, those built alone; a rate
    // that needs a longer rule gets a workspace of its own.
    const gauss_chebyshev rule(64);
    sweep_cache cache;
    auto matrix_of = [&rule](const kernel& k, sweep_cache* c) {
        matrix_ptr a = make_matrix(rule.n + 1, rule.n);
        gsl_matrix_set_zero(a.get());
        kernel_operator(rule, method::product, k.max_rate(), c).add_to(a.get(), k);
        return a;
    };
    const kernel first(std::vector<exponential_term>{{1.2, 2.06}}), second(std::vector<exponential_term>{{1.3, 2.1}});
    const kernel steep(std::vector<exponential_term>{{1.3, 40.0}});
    EXPECT_EQ(kernel_sweep::same_layout_rate(rule.n - 1, 2.06), kernel_sweep::same_layout_rate(rule.n - 1, 2.1));
    EXPECT_LT(kernel_sweep::same_layout_rate(rule.n - 1, 2.1), 40.0);
    const auto shared_first = cache.get(rule, first.max_rate());
    EXPECT_EQ(cache.get(rule, second.max_rate()), shared_first);
    EXPECT_NE(cache.get(rule, steep.max_rate()), shared_first);
    for (const kernel* k : {&first, &second, &steep}) {
        const matrix_ptr alone = matrix_of(*k, nullptr), shared = matrix_of(*k, &cache);
        for (int m = 0; m <= rule.n; ++m)
            for (int j = 0; j < rule.n; ++j)
                ASSERT_EQ(gsl_matrix_get(shared.get(), m, j), gsl_matrix_get(alone.get(), m, j)) << m << ", " << j;
    }
}

TEST(KernelSweep, LagrangeOperatorIntegratesEachSegmentToRounding) {
    // The product-integration operator (kernel_operator: the Lagrange basis swept at the
    // collocation points, kernel_sweep.cpp's rule of base_order + ceil(1.5 A L) Gauss-Legendre
    // points per segment) against the same integrals on segments four times shorter (a rule whose
    // truncation error is 4^(2q) times smaller), for n = 16 ... 256 and rates from the plain jump
    // to the resolution limit. The integrals are at most pi/2 in size; what the two may differ by
    // is rounding. Measured: 7 points per segment leave 1.3e-14 at A = 0, n = 16 (6 points 3.9e-12);
    // 9 points and more, 3.3e-16.
    for (int n : {16, 64, 256}) {
        const gauss_chebyshev rule(n);
        const lagrange_basis basis(rule);
        const batch_basis_values values(
            [&basis](const double*, const double* eta, std::size_t count, double* out) { basis(eta, count, out); });
        const double limit = 2.0 * (n + 1) * (n + 1) / (M_PI * M_PI);  // A h^2/2 = 1 (check_resolution)
        for (double A : {0.0, 0.5, 30.0, limit}) {
            const kernel k(std::vector<exponential_term>{{1.0, A}});
            matrix_ptr a = make_matrix(rule.n + 1, rule.n);
            gsl_matrix_set_zero(a.get());
            kernel_operator(rule, method::product, A).add_to(a.get(), k);
            const std::vector<double> fine = kernel_sweep(rule.collocation, n, 4 * n, A, values).apply(k);
            double worst = 0.0;
            for (int m = 0; m <= n; ++m)
                for (int j = 0; j < n; ++j)
                    worst = std::max(
                        worst, std::fabs(gsl_matrix_get(a.get(), m, j) - fine[static_cast<std::size_t>(m) * n + j]));
            EXPECT_LE(worst, 8.0 * GSL_DBL_EPSILON) << "n = " << n << ", A = " << A;
        }
    }
}
