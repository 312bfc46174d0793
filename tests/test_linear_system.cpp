// SPDX-License-Identifier: GPL-3.0-or-later
// The dense system's refined solve (numerics/linear_system.hpp): on a matrix near the last one
// factorised it gives the fresh LU solution to rounding (the LU route is the independent
// reference); a far matrix falls back to a fresh factorisation (the same solution bit for bit);
// a singular one is refused as a fresh factorisation refuses it. solve() alone keeps no
// factorisation to refine on: the first solve_near() factorises.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gsl/gsl_machine.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/linear_system.hpp"
#include "tolerance.hpp"

using namespace roughroll;

namespace {
constexpr std::size_t order = 65;

// A(t) = C + t K: a Cauchy-like C (as the benchmark's bm_lu and the Cauchy term of (4.4)) and a
// smooth kernel K = exp(-|x_i - x_j|) on [-1, 1]; its solutions move smoothly with t, as a sweep's.
void assemble(dense_system& s, double t) {
    for (std::size_t i = 0; i < order; ++i) {
        const double xi = -1.0 + 2.0 * static_cast<double>(i) / (order - 1);
        gsl_vector_set(s.rhs(), i, 1.0 + xi * xi);
        for (std::size_t j = 0; j < order; ++j) {
            const double xj = -1.0 + 2.0 * static_cast<double>(j) / (order - 1);
            const double cauchy = i == j ? 2.0 : 1.0 / (static_cast<double>(i) - static_cast<double>(j) + 0.5);
            gsl_matrix_set(s.matrix(), i, j, cauchy + t * std::exp(-std::fabs(xi - xj)));
        }
    }
}

// The quadruple-precision reference: GCC's __float128 where the target has it (x86-64), else long double (quad on
// aarch64; on a target where it is neither, the reference is weaker than the bound it checks).
#if defined(__SIZEOF_FLOAT128__)
using quad = __float128;
#else
using quad = long double;
#endif
quad magnitude(quad v) { return v < 0 ? -v : v; }

std::vector<double> copy(const gsl_vector* x) {
    std::vector<double> v(x->size);
    for (std::size_t i = 0; i < x->size; ++i) v[i] = gsl_vector_get(x, i);
    return v;
}

double largest(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m = std::max(m, std::fabs(x));
    return m;
}
}  // namespace

TEST(DenseSystem, RefinedSolveAgreesWithTheFreshFactorisation) {
    dense_system swept(order), fresh(order);
    assemble(swept, 0.0);
    swept.solve_near("first");  // no factorisation to refine on: a fresh one
    EXPECT_FALSE(swept.refined());
    double factor_rcond = swept.rcond();  // of the factorisation refined on
    int refined = 0;
    for (int k = 1; k <= 20; ++k) {  // a sweep in t, steps of 0.02
        const double t = 0.02 * k;
        assemble(swept, t);
        const std::vector<double> near = copy(swept.solve_near("swept"));
        refined += swept.refined();
        assemble(fresh, t);
        const std::vector<double> direct = copy(fresh.solve("fresh"));
        // Both solve A x = b with backward error at rounding: they differ by the condition
        // number times eps at most (1/rcond is its estimate, of U).
        const double tolerance = tol::solve_rounding / fresh.rcond() * largest(direct);
        for (std::size_t i = 0; i < order; ++i)
            EXPECT_NEAR(near[i], direct[i], tolerance) << "t = " << t << ", i = " << i;
        if (swept.refined()) {
            // cond(A) <= cond(M) (1 + q)/(1 - q), q <= 1/2: the estimate is below the
            // factorisation's and at least a third of it.
            EXPECT_LE(swept.rcond(), factor_rcond);
            EXPECT_GE(swept.rcond(), factor_rcond / 3.0);
        } else {
            factor_rcond = swept.rcond();  // a fresh factorisation, refined on from here
        }
    }
    EXPECT_GE(refined, 15);  // the path under test is taken
    // solve() and then solve_near(): the matrix assembled over the first factorisation, a fresh one.
    dense_system plain(order);
    assemble(plain, 0.0);
    plain.solve("plain");
    assemble(plain, 0.02);
    plain.solve_near("near");
    EXPECT_FALSE(plain.refined());
}

TEST(DenseSystem, FarMatrixFallsBackToAFreshFactorisation) {
    dense_system swept(order), fresh(order);
    assemble(swept, 0.0);
    swept.solve_near("first");
    assemble(swept, 0.02);
    swept.solve_near("near");
    ASSERT_TRUE(swept.refined());
    // A far jump: the kernel 200 times stronger; M^{-1} A is far from the identity.
    assemble(swept, 200.0);
    const std::vector<double> far = copy(swept.solve_near("far"));
    EXPECT_FALSE(swept.refined());
    assemble(fresh, 200.0);
    const std::vector<double> direct = copy(fresh.solve("fresh"));
    for (std::size_t i = 0; i < order; ++i) EXPECT_EQ(far[i], direct[i]);  // the same route
    EXPECT_EQ(swept.rcond(), fresh.rcond());
}

TEST(DenseSystem, SingularNearMatrixIsRefused) {
    dense_system s(order);
    assemble(s, 0.0);
    s.solve_near("first");
    assemble(s, 0.02);
    s.solve_near("near");
    ASSERT_TRUE(s.refined());
    assemble(s, 0.0);
    for (std::size_t j = 0; j < order; ++j) gsl_matrix_set(s.matrix(), 1, j, gsl_matrix_get(s.matrix(), 0, j));
    EXPECT_THROW(s.solve_near("singular"), numerical_error);
}

// solve_factorised(): the matrix of the last solve() with a new right side, on its kept factors,
// gives bit for bit the solution and rcond of a fresh factorisation of the same matrix (the smooth
// tangential and normal problems of full coupling, whose matrices do not change between solves).
// Once the matrix is asked for again (assembly), or after solve_near(), no factors are held.
TEST(DenseSystem, FactorisedSolveIsTheFreshSolve) {
    dense_system kept(order), fresh(order);
    assemble(kept, 0.3);
    EXPECT_FALSE(kept.holds_factors());
    kept.solve("first");
    ASSERT_TRUE(kept.holds_factors());
    for (int k = 1; k <= 3; ++k) {
        assemble(fresh, 0.3);
        for (std::size_t i = 0; i < order; ++i) {
            const double b = std::cos(1.7 * k * static_cast<double>(i)) + k;
            gsl_vector_set(kept.rhs(), i, b);
            gsl_vector_set(fresh.rhs(), i, b);
        }
        const std::vector<double> again = copy(kept.solve_factorised("again"));
        const std::vector<double> lu = copy(fresh.solve("fresh"));
        EXPECT_EQ(again, lu) << k;
        EXPECT_EQ(kept.rcond(), fresh.rcond()) << k;
    }
    kept.matrix();
    EXPECT_FALSE(kept.holds_factors());
    EXPECT_THROW(kept.solve_factorised("assembled"), numerical_error);
    assemble(kept, 0.3);
    kept.solve("second");
    kept.clear();
    EXPECT_THROW(kept.solve_factorised("cleared"), numerical_error);
    assemble(kept, 0.3);
    kept.solve_near("near");
    EXPECT_FALSE(kept.holds_factors());
}

// The a posteriori rounding bound (docs/formulation.md 8(w), "The solve's rounding, a posteriori") on the Pascal matrix
// of order 10, P_ij = binomial(i + j, i) (kappa about 1e10), with integer x* and b = P x* exact in doubles: the
// computed solution's error is known exactly. Each component's bound holds and lies within 10 times the error of the
// worst component (the bound is the refinement's dx, to first order the error itself).
TEST(DenseSystem, RoundingBoundHoldsOnThePascalMatrix) {
    constexpr std::size_t m = 10;
    dense_system s(m);
    s.keep_matrix();
    std::vector<double> exact(m);
    for (std::size_t j = 0; j < m; ++j) exact[j] = static_cast<double>(j % 3) - 1.0 + static_cast<double>(j);
    for (std::size_t i = 0; i < m; ++i) {
        double b = 0.0;
        for (std::size_t j = 0; j < m; ++j) {
            double c = 1.0;  // binomial(i + j, i)
            for (std::size_t k = 1; k <= i; ++k) c = c * static_cast<double>(j + k) / static_cast<double>(k);
            gsl_matrix_set(s.matrix(), i, j, std::round(c));
            b += std::round(c) * exact[j];
        }
        gsl_vector_set(s.rhs(), i, b);
    }
    const std::vector<double> x = copy(s.solve("pascal"));
    double worst = 0.0;
    for (std::size_t i = 0; i < m; ++i) worst = std::max(worst, std::fabs(x[i] - exact[i]));
    ASSERT_GT(worst, 1e-9);  // an ill-conditioned solve: the error is there to bound
    for (std::size_t i = 0; i < m; ++i) {
        SCOPED_TRACE(i);
        const double bound = s.rounding_bound(i, 0.0);
        EXPECT_GE(bound, std::fabs(x[i] - exact[i]));
        EXPECT_LE(bound, 10.0 * worst);
    }
    dense_system plain(m);  // no kept matrix: no bound
    gsl_matrix_set_identity(plain.matrix());
    plain.solve("identity");
    EXPECT_THROW(plain.rounding_bound(0, 0.0), numerical_error);
}

// Ill-conditioned by its columns' scales only, as the exact weight's collocation (8(z): columns W_j/(t_j - x_m), the
// weights W_j falling towards the ends): A(0.3) above times D = diag(2^-(j mod 40)), kappa about 1e12 while each x_i
// is determined to a few eps of itself. The reference is the solve in quadruple precision (`quad` above, Gaussian
// elimination with partial pivoting, its error about 1e-32 relative; x86's long double, 5e-20, missed the bound's
// tightness). Each bound holds, and lies below 1e-3 of the a priori
// 2 eps |x_i| / rcond that the floors read before this bound (docs/formulation.md 8(w)).
TEST(DenseSystem, RoundingBoundOfGradedColumnsIsFarBelowTheAPrioriFloor) {
    dense_system s(order);
    s.keep_matrix();
    assemble(s, 0.3);
    std::vector<quad> a(order * order), b(order);
    for (std::size_t i = 0; i < order; ++i) {
        b[i] = gsl_vector_get(s.rhs(), i);
        for (std::size_t j = 0; j < order; ++j) {
            const double v = std::ldexp(gsl_matrix_get(s.matrix(), i, j), -static_cast<int>(j % 40));
            gsl_matrix_set(s.matrix(), i, j, v);
            a[i * order + j] = v;
        }
    }
    for (std::size_t k = 0; k < order; ++k) {  // quadruple-precision elimination, partial pivoting
        std::size_t p = k;
        for (std::size_t i = k + 1; i < order; ++i)
            if (magnitude(a[i * order + k]) > magnitude(a[p * order + k])) p = i;
        for (std::size_t j = 0; j < order; ++j) std::swap(a[k * order + j], a[p * order + j]);
        std::swap(b[k], b[p]);
        for (std::size_t i = k + 1; i < order; ++i) {
            const quad l = a[i * order + k] / a[k * order + k];
            for (std::size_t j = k; j < order; ++j) a[i * order + j] -= l * a[k * order + j];
            b[i] -= l * b[k];
        }
    }
    std::vector<quad> reference(order);
    for (std::size_t i = order; i-- > 0;) {
        quad t = b[i];
        for (std::size_t j = i + 1; j < order; ++j) t -= a[i * order + j] * reference[j];
        reference[i] = t / a[i * order + i];
    }
    const std::vector<double> x = copy(s.solve("graded columns"));
    ASSERT_LT(s.rcond(), 1e-10);
    for (std::size_t i = 0; i < order; ++i) {
        SCOPED_TRACE(i);
        const double bound = s.rounding_bound(i, 0.0);
        EXPECT_GE(bound, static_cast<double>(magnitude(x[i] - reference[i])));
        EXPECT_LT(bound, 1e-3 * 2.0 * GSL_DBL_EPSILON * std::fabs(x[i]) / s.rcond());
    }
}

// The same graded system with its rows reversed: partial pivoting picks the same pivots, so the factors, x and dx are the
// same and so must each bound be (to the rounding of its sum's order). The factors' backward error is of P A, in the
// factors' row order, and pairs with P y (y = A^{-T} e_i): paired with y itself (A's order) the bound changed under
// the permutation (session 27 review R1).
TEST(DenseSystem, RoundingBoundDoesNotDependOnTheRowOrder) {
    dense_system s(order), reversed(order);
    s.keep_matrix();
    reversed.keep_matrix();
    assemble(s, 0.3);
    for (std::size_t i = 0; i < order; ++i) {
        gsl_vector_set(reversed.rhs(), order - 1 - i, gsl_vector_get(s.rhs(), i));
        for (std::size_t j = 0; j < order; ++j) {
            const double v = std::ldexp(gsl_matrix_get(s.matrix(), i, j), -static_cast<int>(j % 40));
            gsl_matrix_set(s.matrix(), i, j, v);
            gsl_matrix_set(reversed.matrix(), order - 1 - i, j, v);
        }
    }
    const std::vector<double> x = copy(s.solve("graded columns")), xr = copy(reversed.solve("reversed rows"));
    for (std::size_t i = 0; i < order; ++i) {
        SCOPED_TRACE(i);
        ASSERT_EQ(x[i], xr[i]);
        const double a = s.rounding_bound(i, 0.0), b = reversed.rounding_bound(i, 0.0);
        EXPECT_NEAR(a, b, 4.0 * GSL_DBL_EPSILON * a);
    }
}
