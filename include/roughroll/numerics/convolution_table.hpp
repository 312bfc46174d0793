// SPDX-License-Identifier: GPL-3.0-or-later
// The convolution of a kernel with a weighted Chebyshev-U series, tabulated once so that it
// costs O(1) per point (G of (3.25), E8, whose points move with c0 while the function does not):
//   D(r) = int_{-1}^{1} sqrt(1 - eta^2) phi(eta) K(eta - r) d eta,  phi = sum_{j<n} b_j U_j,
// for K = sum_i T_i exp(-A_i |z|) sgn z and any r in [-1, 1].
//
// In theta = acos r, with g(t) = phi(cos t) sin^2 t = sum_j b_j sin((j+1) t) sin t,
//   D = sum_i T_i (L_i - R_i),  L(theta) = int_0^theta g(t) exp(-A (cos t - cos theta)) dt,
//                               R(theta) = int_theta^pi g(t) exp(-A (cos theta - cos t)) dt,
// both analytic in theta (the kernel's jump and the square roots of the ends are absorbed).
// [0, pi] is cut into P equal panels; on each, L and R advance from the panel's end by
// Chebyshev-Lobatto spectral integration of g exp(...) (the factors <= 1 carried between
// panels, as in kernel_sweep), and D is kept as a Chebyshev series of degree N in theta.
//
// The representation error is bounded (docs/formulation.md, "G once per contact") by the
// Bernstein-ellipse theorem (Trefethen, Approximation Theory and Approximation Practice,
// Thm 8.2): on an ellipse E_rho around a panel of half-length h, |Im t| <= y = h (rho - 1/rho)/2
// and |Re t - centre| <= x = h (rho + 1/rho)/2, |g| <= B e^{(n+1) y} with B = sum |b_j|, and
// each exponential factor is at most exp(A (h + x + cosh y - 1)); P is chosen so that the
// bound is below eps = 2.2e-16 times the size bound pi B sum |T_i| of D.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/theta_panels.hpp"

namespace roughroll {

class convolution_table {
public:
    // Throws numerical_error when no panel count up to a million meets the bound (rates far
    // beyond any discretisation's resolution: check_resolution refuses those first).
    convolution_table(const kernel& k, const std::vector<double>& b);

    double operator()(double r) const;  // D(r), r clamped to [-1, 1]
    // D(r[i]) into out[i], i < count: the scalar value bit for bit, four points' Clenshaw
    // recurrences interleaved (each alone is a chain of 24 dependent steps).
    void operator()(const double* r, double* out, std::size_t count) const;
    int panels() const { return table_.panels(); }
    // The bound on |D - table| (absolute), and the size bound pi B sum |T| it is compared with.
    double error_bound() const { return bound_; }
    double scale() const { return scale_; }

    // The bound of the class comment for n coefficients of l1-norm B = 1 and one term of
    // |T| = 1 with rate A, panels of length `length` (in theta); minimised over rho.
    static double panel_bound(int n, double rate, double length);
    // The fewest panels whose panel_bound is below eps for degree n and rate A; throws numerical_error beyond a
    // million panels.
    static int panels_for(int n, double rate);

private:
    theta_panels table_;  // D in theta (theta_panels.hpp)
    double bound_ = 0.0, scale_ = 0.0;
};

}  // namespace roughroll
