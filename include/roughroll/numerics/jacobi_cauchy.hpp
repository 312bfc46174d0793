// SPDX-License-Identifier: GPL-3.0-or-later
// Cauchy transforms on a Jacobi weight w(t) = (1 - t)^a (1 + t)^b with a + b != 1 (docs/formulation.md 8(y)).
// Where the two sides of a stick zone slip in opposite directions at full coupling (the blended stick zones: the
// driven three zones and five zones' stick zones) the exponents of 8(l)'s table are a = 1/2 - eps_out and
// b = 1/2 + eps_in with eps_in = -eps_out, so a + b = 1 - 2 eps_out, and the local coefficient of the stick equation
// (H - k(t))[q] varies along the zone (the blend's k S(t), 8(l)): 8(v)'s polynomial identity (a + b = 1, constant
// k) does not hold. What holds for any a, b: for psi of degree <= n - 1 and the n-point Gauss-Jacobi rule of w,
//   (1/pi) PV int w psi/(tau - x) d tau = psi(x) C_0(x) + (1/pi) sum_k W_k [psi(t_k) - psi(x)]/(t_k - x)   (exact),
// C_0(x) = (1/pi) PV int w/(tau - x) d tau, in closed form below (8(y)).
#pragma once

#include <vector>

#include <gsl/gsl_matrix.h>

#include "roughroll/numerics/gauss_jacobi.hpp"

namespace roughroll {

// C_0(x) = (1/pi) PV int_{-1}^{1} (1 - tau)^a (1 + tau)^b/(tau - x) d tau for real x, |x| != 1, 0 < a, b < 1
// (8(y): Gauss's hypergeometric function, by gsl_sf_hyperg_2F1 with its argument in [0, 1/2] inside the interval
// and in (0, 1) outside). For a + b = 1 it is 8(v)'s (X(x) - x - 1 + 2a)/sin(pi a) outside and
// cot(pi a) w(x) - (x + 1 - 2a)/sin(pi a) inside.
double jacobi_weight_cauchy(double a, double b, double x);

// The collocation of (H - k(x))[w psi] - xi on the weight w = (1 - t)^a (1 + t)^b (8(y)): psi by its values psi_k at the
// zeros t_k of P_n^(a,b) (rule, Gauss weights W_k), n + 1 collocation points x_m. Row m of the n columns is
//   (1/pi) W_k/(t_k - x_m) + l_k(x_m) D(x_m),   D(x) = C_0(x) - k(x) w(x) - (1/pi) sum_j W_j/(t_j - x),
// l_k the Lagrange basis of the nodes (barycentric, the weights (-1)^k sqrt((1 - t_k^2) W_k) of Gauss-Jacobi nodes):
// exact for psi of degree <= n - 1 at every point. The points: the zeros of P_{n+1}^(-a,-b), 8(v)'s points, where
// D = 0 when a + b = 1 and k = cot(pi a) (the matrix is then 8(v)'s); chosen over Chebyshev points by the model
// problem's convergence (8(y), tests/test_jacobi_cauchy.cpp).
struct jacobi_cauchy_collocation {
    jacobi_cauchy_collocation(int n, double a, double b);

    gauss_jacobi rule;
    std::vector<double> collocation;  // n + 1 points, ascending
    std::vector<double> barycentric;  // the Lagrange basis' weights of the rule's nodes

    // Adds the n columns of (H - k)[w psi] at the points to rows 0..n of `m`; k_at_points: k(x_m).
    void add_to(gsl_matrix* m, const std::vector<double>& k_at_points) const;
    // l_0(x) .. l_{n-1}(x) of the rule's nodes; x not a node.
    std::vector<double> lagrange(double x) const;
};

}  // namespace roughroll
