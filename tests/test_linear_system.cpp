// SPDX-License-Identifier: GPL-3.0-or-later
// The dense system's refined solve (numerics/linear_system.hpp): on a matrix near the last one
// factorised it gives the fresh LU solution to rounding (the LU route is the independent
// reference); a far matrix falls back to a fresh factorisation (the same solution bit for bit);
// a singular one is refused as a fresh factorisation refuses it. solve() alone keeps no
// factorisation to refine on: the first solve_near() factorises.
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
