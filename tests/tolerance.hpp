// SPDX-License-Identifier: GPL-3.0-or-later
// The tests' tolerances by name (issue 25, 8), as GSL's specfunc/test_sf.h: a ladder of
// rounding tolerances in units of DBL_EPSILON, and the decimal tolerances that recur in
// tests/ and validation/, each named for why it has its size. Values are those of the
// literals they replaced, never loosened; a tolerance used once stays beside its test.
// Included as "tolerance.hpp" from tests/, "../tests/tolerance.hpp" from validation/.
#ifndef ROUGHROLL_TESTS_TOLERANCE_HPP
#define ROUGHROLL_TESTS_TOLERANCE_HPP

#include <cfloat>

namespace tol {

// One rounding unit of double, and its square root (2^-26, GSL_SQRT_DBL_EPSILON, exact).
constexpr double eps = DBL_EPSILON;
constexpr double sqrt_eps = 1.4901161193847656e-08;

// GSL's ladder (TEST_TOL0 ... TEST_TOL6, TEST_SQRT_TOL0): each rung 8 times the one below.
constexpr double tol0 = 2.0 * eps;
constexpr double tol1 = 16.0 * eps;
constexpr double tol2 = 256.0 * eps;
constexpr double tol3 = 2048.0 * eps;
constexpr double tol4 = 16384.0 * eps;
constexpr double tol5 = 131072.0 * eps;
constexpr double tol6 = 1048576.0 * eps;
constexpr double sqrt_tol0 = 2.0 * sqrt_eps;

// A dense solve's answer: 8 eps over the reciprocal condition number (LAPACK's forward-error
// rule of thumb), the factor 8 for the few roundings of forming and substituting.
constexpr double solve_rounding = 8.0 * eps;

// The same quantity through arithmetic in another order, values below 1: under one rounding
// unit (0.45 eps), so the two are equal but for the last bit of a value below 1/2.
constexpr double reordered = 1e-16;

// A closed form of O(1) values in a handful of operations (sqrt, cos, a product): 4.5 eps.
constexpr double few_roundings = 1e-15;

// A sum of tens of O(1) terms (a quadrature rule, a short Chebyshev series): 45 eps.
constexpr double short_sum = 1e-14;

// An interpolant or product of degree tens reproducing its value at a point (Lagrange
// products, a Chebyshev series of a polynomial): rounding grows with the degree, 450 eps.
constexpr double interpolation = 1e-13;

// Against GSL's adaptive quadrature (QAGP, QAWS) asked for 1e-13: its request twice over, the
// second half for its own rounding and that of the routine under test.
constexpr double against_adaptive = 2e-13;

// A dense LU solve of size tens to a hundred on O(1) quantities against the value it must
// reproduce exactly (lambda = 1 of the smooth normal problem, the errata's closed forms):
// rounding grown by the condition number, 450 eps (measured 3e-16 at n + 1 = 33).
constexpr double dense_solve = 1e-13;

// The same solved point by two routes: a root search in c0 (to 1e-14 or 1e-15) against a closed
// form the method reproduces (Carter's at eps = 0), a sweep in c0, the same equations assembled
// another way, a physical scene against its dimensionless twin, Newton's five zones from other
// starts: the searches' tolerances times the slope of Q(c0), and the solves' rounding.
constexpr double two_routes = 1e-12;

// How far below zero a stick or slip margin ((3.3), (3.4)) may lie at a solved point whose
// zone ends sit where a margin vanishes: the rounding of the solve at n up to 128 (a fixed
// floor for the tests; the library computes its own per point, stick_rounding).
constexpr double margin_floor = 1e-12;

// Relative agreement of the roughness parameters (averages, k, t, alpha) with closed forms,
// printed references and the other averages rule: the outer
// quadratures' relative tolerance (roughness_parameters.hpp, outer_tolerance).
constexpr double roughness_integrals = 1e-12;

}  // namespace tol

#endif
