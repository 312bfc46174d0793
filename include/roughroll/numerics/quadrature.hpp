// SPDX-License-Identifier: GPL-3.0-or-later
// Gauss-Chebyshev quadrature of the second kind, (4.6)-(4.7), and the
// Chebyshev-U series that interpolates a function known at its nodes.
//
// The unknowns of (4.1) are phi(r) = p(r)/sqrt(1 - r^2) at the nodes eta_k,
// the zeros of U_n. Their interpolant is the degree n-1 polynomial
//   phi(x) = sum_{j<n} b_j U_j(x),  b_j = (2/pi) sum_k w_k phi(eta_k) U_j(eta_k),
// which the quadrature (exact to degree 2n-1 against sqrt(1 - x^2)) gives
// without error. Everything that needs p between the nodes (the kernel
// integrals of the product method, G of (3.25), the checks (3.3)-(3.4)) uses it.
#pragma once

#include <cstddef>
#include <vector>

#include "roughroll/numerics/gauss_chebyshev.hpp"  // the rule (installed: normal_solution holds one)

namespace roughroll {

// Gauss-Legendre nodes and weights on [-1, 1], by gsl_integration_fixed (Golub-Welsch).
// Not gsl_integration_glfixed: that is exact only at its tabulated orders and loses
// about 1e-11 at others (66, 200), which the kernel-moment test detects. Not
// gsl_integration_fixed either (Golub-Welsch, slow): Newton on the recurrence (quadrature.cpp).
struct gauss_legendre {
    explicit gauss_legendre(int order);

    std::vector<double> nodes;
    std::vector<double> weights;
};

// Coefficients b_0..b_{n-1} of the interpolant of `values` (given at the nodes).
std::vector<double> u_coefficients(const gauss_chebyshev& rule, const std::vector<double>& values);

// The length of b without its exact trailing zeros (at least 1 for b not empty; Hertz: 1 of n):
// through them Clenshaw's recurrence stays +0 exactly, so u_series skips them, bit for bit.
std::size_t significant_terms(const std::vector<double>& b);

// sum_j b_j U_j(x), by Clenshaw's recurrence.
double u_series(const std::vector<double>& b, double x);
// The same at count points x[i] into out[i], the points interleaved so that the recurrences
// run side by side (each value is the one u_series(b, x[i]) gives, bit for bit).
void u_series(const std::vector<double>& b, const double* x, double* out, std::size_t count);

// The finite Hilbert transform of the weighted series, for any x not +-1:
//   (1/pi) int_{-1}^{1} sqrt(1-t^2) sum_j b_j U_j(t) / (t - x) dt
//     = -sum_j b_j T_{j+1}(x)                        for |x| < 1 (principal value),
//     = -sum_j b_j z^{j+1},  z = x - sgn(x) sqrt(x^2-1)  for |x| > 1.
double cauchy_u_series(const std::vector<double>& b, double x);
// The same at count points x[i] into out[i], the recurrences of points on one side of |x| = 1 run
// side by side (each value is the one cauchy_u_series(b, x[i]) gives, bit for bit).
void cauchy_u_series(const std::vector<double>& b, const double* x, double* out, std::size_t count);

}  // namespace roughroll
