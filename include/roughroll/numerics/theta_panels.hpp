// SPDX-License-Identifier: GPL-3.0-or-later
// A function of r in [-1, 1] kept as Chebyshev series in theta = acos r on P equal panels of
// [0, pi], the representation that convolution_table (G of (3.25)) and u_series_table (the
// pressure (4.1) in W of 8(g)) share. On panel j, theta in [j L, (j+1) L] with L = pi/P and
// s = 2 (theta - j L)/L - 1, f = sum_{k<=N} c_k T_k(s), N = degree, the interpolant of f's values at
// the panel's Chebyshev-Lobatto points (a discrete cosine transform). Its error is bounded by the
// Bernstein-ellipse theorem (Trefethen, Approximation Theory and Approximation Practice, Thm 8.2):
// for f analytic and |f| <= M inside the ellipse E_rho around a panel, 4 M rho^-N/(rho - 1)
// (docs/formulation.md, "G once per contact").
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace roughroll {

class theta_panels {
public:
    static constexpr int degree = 24;  // N: Chebyshev-Lobatto points 0..N per panel

    // Chebyshev-Lobatto points of [-1, 1], ascending: s_i = -cos(i pi/N) = cos((N - i) pi/N).
    static double lobatto(int i);
    // Values at the N + 1 points -> coefficients c_k of sum_k c_k T_k; row-major (N+1) x (N+1).
    static std::vector<double> values_to_coefficients();
    // Values at the N + 1 points -> int_{-1}^{s_i} of their interpolant at every point i; row-major (N+1) x (N+1)
    // (the spectral integration of convolution_table's L and R on a panel).
    static std::vector<double> integration_matrix();
    // The theorem's bound minimised over rho, for panels of half-length h: min_rho 4 M rho^-N/(rho - 1),
    // M = modulus(y, x) bounding f on the ellipse of half-axes y = h (rho - 1/rho)/2 (imaginary) and
    // x = h (rho + 1/rho)/2 (real).
    static double ellipse_bound(double half_length, const std::function<double(double y, double x)>& modulus);
    // sum_{k<=N} c_k T_k(s) of one panel's coefficients, Clenshaw's recurrence (cauchy_u_table's outer panels too).
    static double panel_sum(const double* c, double s) {
        double y1 = 0.0, y2 = 0.0;
        for (int k = degree; k >= 1; --k) {
            const double y0 = c[k] + 2.0 * s * y1 - y2;
            y2 = y1;
            y1 = y0;
        }
        return c[0] + s * y1 - y2;
    }

    theta_panels() = default;
    explicit theta_panels(int panels);  // throws numerical_error for panels < 1

    int panels() const { return panels_; }
    double length() const { return length_; }  // pi / panels
    // theta of point i of panel j (its end exactly at i = N).
    double node(int j, int i) const;
    // The series from f at the nodes, node (j, i) at values[j * (N + 1) + i]; throws
    // numerical_error unless there is one value per node.
    void set_values(const std::vector<double>& values);

    double operator()(double r) const;  // f(r), r clamped to [-1, 1]
    // f(r[i]) into out[i], i < count: the scalar value bit for bit, four points' Clenshaw
    // recurrences interleaved (each alone is a chain of N dependent steps).
    void operator()(const double* r, double* out, std::size_t count) const;

private:
    // The panel of r: its Chebyshev-T coefficients, and r's variable s in it, in [-1, 1].
    struct panel_point {
        const double* c;
        double s;
    };
    panel_point locate(double r) const;

    int panels_ = 0;
    double length_ = 0.0;
    std::vector<double> coefficients_;  // panels_ x (degree + 1), Chebyshev-T in the panel variable
};

}  // namespace roughroll
