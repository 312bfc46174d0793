// SPDX-License-Identifier: GPL-3.0-or-later
// An error bound for one quantity from three levels of a discretisation, n_0, 2 n_0, 4 n_0
// nodes (docs/performance.md, "How the error estimates are made"). With the differences
//   d1 = v_1 - v_0,   d2 = v_2 - v_1,   rho = d1/d2,
// a method of order p has rho -> 2^p in its asymptotic range, where the error of v_2 is
// d2/(2^p - 1) and Richardson's value v_2 + d2/(2^p - 1) is better still. The rule:
//   - the observed ratio is at least 0.7 * 2^p (observed order >= p - 1/2): the classic
//     estimates hold, |d2| for v_2 (an overestimate by about 2^p - 1) and 2 |d2|/(2^p - 1)
//     for Richardson's value (its distance from v_2 plus v_2's own error, about as much);
//   - 1.5 <= |rho| < 0.7 * 2^p (observed order below the assumed one), or rho negative (the
//     error changes sign between levels) with |rho| >= min(4, 0.7 * 2^p) (it still contracts
//     at least as an order-2 method's): the error of v_2 is at most |d2| max(2, 2/(|rho| - 1)) (a
//     geometric tail with ratio min(|rho|, 2^p), times 2 for safety), the error of v_1 at
//     most |d2| plus that, of v_0 at most |d1| plus that; Richardson's value is bounded by
//     its distance from v_2 plus the error of v_2;
//   - |rho| < 1.5, or rho negative and |rho| below that (the levels do not converge, or not
//     visibly): no honest estimate from these levels. contact gives a second chance one level
//     finer (n/2, n, 2n) where the solution's inequalities hold, accepted only where that ratio
//     shows at least order p - 1; else it refuses the point.
// Level v_0 reported (the levels n, 2n, 4n) is never estimated below twice the larger difference: |e_0| <= |d1| + |e_1|
// with |e_1| <= |e_0|/2 where the levels converge visibly (docs/formulation.md 8(e), "Level n the coarsest").
// In the first case Richardson's value is also bounded by its change from the pair below,
// |2^p d2 - d1|/(2^p - 1) = |d2| |2^p - rho|/(2^p - 1): where the coarsest level is itself
// pre-asymptotic and rho only happens to lie near 2^p, that change is large.
// A rounding floor is added to every estimate, and differences at or below it are read as
// rounding, not as a ratio.
#pragma once

namespace roughroll {

struct three_levels {
    double coarsest;  // v_0 at n_0 nodes
    double middle;    // v_1 at 2 n_0
    double finest;    // v_2 at 4 n_0
};

// Which value the estimate is for: one of the levels, or Richardson's value from level
// `index` and the one below it (index 1 or 2).
struct reported_value {
    int index;          // 0, 1, 2
    bool extrapolated;  // Richardson's (2^p v_index - v_{index-1})/(2^p - 1)
};

struct error_bound {
    double value;     // the estimate, rounding floor included (0 when !resolved)
    double ratio;     // d1/d2, observed (infinite when d2 = 0)
    bool asymptotic;  // the observed order is within 1/2 of p (or both differences are rounding)
    bool resolved;    // false: no honest estimate from these levels
};

error_bound bound_error(const three_levels& v, int order, reported_value which, double rounding_floor);

// The bound of the middle level (or Richardson's value from it and the coarsest, `extrapolated`)
// from n/2, n, 2n, where n/4, n/2, n already gave an estimate that this fourth level confirms
// (contact's estimates, docs/performance.md "A fourth level confirms"): bound_error's rule, and
// where that sees no visible order, levels that alternate without growing (d1 d2 < 0,
// |d2| <= |d1|: level n within twice the wider step of the limit) or that still shrink too slowly
// to show an order (1 < d1/d2 < 1.5: the bounded rule's tail |d2| (1 + 2/(r - 1))); levels that
// grow stay unresolved.
error_bound confirm_error(const three_levels& v, int order, bool extrapolated, double rounding_floor);

// Where no asymptotic rule holds (full coupling of dissimilar rollers, docs/formulation.md 8(e): the
// zone ends converge at order 1 or less, erratically, and the errors change sign between levels, as
// the exponents at the edges and zone ends shift with the coupling; P_H/P2 and xi at order 2 against
// gross sliding's closed form): twice the larger of the last two level changes, plus the rounding
// floor, for the finest level. Measured against n = 512 and the closed form
// (FullCoupling.EstimatesBoundTheError, .GrossSlidingAgainstTheClosedForm); bound_error's rule
// under-reported there (a stick start's error 2.7e-4 estimated at 1.2e-4). Never asymptotic;
// unresolved only where a level is not finite.
error_bound change_bound(const three_levels& v, double rounding_floor);

// The rounding floor of a quantity computed by a dense solve of order about n (LU with
// partial pivoting, whose backward error is a small multiple of n eps in practice; the
// growth factors of these diagonally dominated Cauchy systems are O(1)) or a sum of n terms:
// n * DBL_EPSILON * scale, `scale` the size of the terms the quantity is computed from.
double rounding_floor(int n, double scale);

// The rounding floor of what is read off the solution of a stick-zone system (4.4) whose
// right-hand side xi + f G is made of terms of size `scale` that the traction q cancels to its
// own, much smaller, size (near gross sliding, docs/formulation.md 7(d)): q, psi(-1), b_0 and
// the creep carry rounding_floor(n, scale) times the growth of the solve, measured up to 3.7
// over n = 16..512 at 1 - |Q|/f = 1e-6..1e-15 (scene T = 100, A = 1, where the spread over n is
// rounding alone); the floor takes twice that, 8.
double stick_system_floor(int n, double scale);

// The rounding floor of zone ends fixed by the entry condition psi(-1) = 0 (7(b); the dissimilar
// zones of 8(g)), near gross sliding (docs/formulation.md 8(m)): psi(-1) = sum_j b_j U_j(-1) with
// |U_j(-1)| = j + 1 weighs the rounding of the n coefficients, each about eps `scale` (`scale` the
// size of the terms of the right-hand side the traction cancels), by up to n: eps scale n (n + 1)/2
// (measured 0.3 to 0.4 of it, growing like n^2, on Bentall and Johnson's braked pair). The
// entry condition's slope in the start is (3/2)|b_0|/rho, b_0 ~ -f G'' rho^2/2 (7(d)), so the ends
// move by rho/|b_0| times that rounding (the factor 2/3 kept as margin): 1/rho as the stick zone
// shrinks. 0 where b_0 is 0 or rho is not positive (no such zone).
double entry_ends_floor(int n, double scale, double rho, double b0);

}  // namespace roughroll
