// SPDX-License-Identifier: GPL-3.0-or-later
// The finite Hilbert transform of a weighted U-series, c(x) = cauchy_u_series(b, x) (quadrature.hpp),
// tabulated so that a value costs an acos or a log and a panel's 25 terms instead of n: full coupling's
// p_q^0 = beta_D sqrt(1 - r^2) sum_Z a_Z c_Z(t_Z(r)) (pressure_kinks.hpp, docs/formulation.md 8(l) step 0)
// is read by every quadrature of W and of int p H, tens of thousands of values per alternation step.
//
//   |x| < 1, x = cos phi:        c = -sum_j b_j cos((j+1) phi), entire in phi: theta_panels on [0, pi];
//   |x| >= 1, x = +-cosh w:      c = -sum_j b_j (+-1)^(j+1) e^(-(j+1) w), entire in w: panels on [0, w_top];
//   |x| > cosh w_top:            the series itself, stopped where its rest is below eps B / 4.
// On the ellipse E_rho (half-axes y imaginary, x real) around a panel of half-length h each term is at most
// |b_j| e^((j+1) y) in phi and |b_j| e^((j+1) max(0, x - h)) in w (the panel nearest w = 0 is the worst), so
// |c| <= M = B e^(n y), resp. B e^(n max(0, x - h)), B = sum |b_j|, and the interpolant is within
// min_rho 4 M rho^-N/(rho - 1) of c (theta_panels.hpp; docs/formulation.md 8(o), "p_q^0 tabulated").
// The panel counts make that at most eps B: below the series' own rounding (about n eps B).
#pragma once

#include <vector>

#include "roughroll/numerics/theta_panels.hpp"

namespace roughroll {

class cauchy_u_table {
public:
    // w_top: the outer panels' reach, x up to cosh(3) = 10.07; beyond, |z| = e^(-w) < 0.05 and the series
    // stops within about 12 terms.
    static constexpr double w_top = 3.0;

    // Throws numerical_error when b is empty or not finite.
    explicit cauchy_u_table(const std::vector<double>& b);

    double operator()(double x) const;  // c(x), any x
    double error_bound() const { return bound_; }  // on |c - table|, absolute (tables and the stopped series)
    int inner_panels() const { return inside_.panels(); }
    int outer_panels() const { return outer_panels_; }

    // The bounds of the class comment for n coefficients with B = 1: inner panels of length `length`
    // in phi, outer ones in w.
    static double inner_bound(int n, double length);
    static double outer_bound(int n, double length);

private:
    double outer(double w, int side) const;  // side 0: x >= 1, 1: x <= -1
    double beyond(double x) const;

    std::vector<double> b_;
    std::vector<double> tail_;  // tail_[j] = sum_{k >= j} |b_k|
    theta_panels inside_;
    int outer_panels_ = 0;
    double outer_length_ = 0.0;
    std::vector<double> outer_[2];  // outer_panels_ x (degree + 1) Chebyshev-T coefficients per side
    double bound_ = 0.0;
};

}  // namespace roughroll
