// SPDX-License-Identifier: GPL-3.0-or-later
// The truncated Chebyshev series of a function with square-root kinks at known points
// (docs/formulation.md 8(e), "The coupled right side"):
//   P_N g(r) = sum_{j<=N} c_j T_j(r),  c_j = (2 - delta_j0)/pi int_0^pi g(cos t) cos(j t) dt.
// Full coupling puts beta_D p1 on the right side of the normal problem (D1); p1 has square-root
// kinks at the zone ends, where the interpolant at the collocation points converges like n^-1/2
// next to them and its low coefficients (lambda and e come from c_1 and c_0) only like n^-3/2,
// erratically as the nodes pass the kinks. The projection's coefficients are exact up to the
// quadrature, and the collocation of the projected right side is Galerkin's method for the
// Cauchy term: lambda and e are then exact for the traction given.
//
// Quadrature: [0, pi] cut at t_k = acos(kink_k); on each piece [a, b], t = (a + b)/2 - (b - a)/2 cos u,
// u in [0, pi], turns a square root at either end of the piece into a smooth function of u
// (t - a ~ u^2), integrated by Gauss-Legendre with 2N + 32 points per piece (the phase of
// cos(j t) is at most N pi over a piece: twice that many points resolve it).
#pragma once

#include <functional>
#include <vector>

namespace roughroll {

// c_0 .. c_N of g on [-1, 1]; `kinks` in (-1, 1), in any order (others ignored).
std::vector<double> chebyshev_projection(const std::function<double(double)>& g, const std::vector<double>& kinks,
                                         int N);

// sum_j c_j T_j(r), Clenshaw's recurrence.
double chebyshev_sum(const std::vector<double>& c, double r);

}  // namespace roughroll
