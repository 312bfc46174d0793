// SPDX-License-Identifier: GPL-3.0-or-later
// The weighted U-series of a traction, p(r) = sqrt(1 - r^2) sum_{j<n} b_j U_j(r) ((4.1), the
// pressure), tabulated so that a value costs O(1) instead of the n steps of Clenshaw's recurrence:
// W of the blended stick zone (8(g)) integrates p adaptively, hundreds of thousands of values per
// zone solve, where the rough layers' pressure has n terms that do not fall below rounding.
//
// In theta = acos r, p = P(theta) = sum_j b_j sin((j+1) theta), entire; on the ellipse E_rho around a
// panel of half-length h, |Im t| <= y = h (rho - 1/rho)/2 and |sin((j+1) t)| <= cosh((j+1) y), so
// |P| <= M = B e^{n y}, B = sum |b_j|, and the interpolant of theta_panels.hpp is within
// min_rho 4 M rho^-N/(rho - 1) of P (docs/formulation.md, "The pressure in W once per zone solve").
// The panel count makes that bound at most eps B, eps = 2.2e-16: below the rounding of the series
// itself (Clenshaw's recurrence rounds at about n eps B).
#pragma once

#include <vector>

#include "roughroll/numerics/theta_panels.hpp"

namespace roughroll {

class u_series_table {
public:
    // Throws numerical_error when b is empty or not finite.
    explicit u_series_table(const std::vector<double>& b);

    double operator()(double r) const { return table_(r); }  // p(r), r clamped to [-1, 1]
    int panels() const { return table_.panels(); }
    double error_bound() const { return bound_; }  // on |p - table|, absolute

    // The bound of the class comment for n coefficients with B = 1, panels of length `length`.
    static double panel_bound(int n, double length);

private:
    theta_panels table_;
    double bound_ = 0.0;
};

}  // namespace roughroll
