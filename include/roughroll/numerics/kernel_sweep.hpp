// SPDX-License-Identifier: GPL-3.0-or-later
// Product integration of the kernel against many functions at many points in O(q n^2):
//   out(m, v) = int_{-1}^{1} g_v(eta) sqrt(1 - eta^2) K(eta - x_m) d eta,
// for points x_0 >= x_1 >= ... in [-1, 1] and functions g_v given through their values.
//
// Each term T exp(-A |eta - x|) sgn(eta - x) is separable on either side of x, so the
// integrals obey a two-sided recurrence between neighbouring points:
//   L_m = exp(-A (x_{m-1} - x_m)) L_{m-1} + int_{theta_{m-1}}^{theta_m} g sin^2 exp(-A (cos - x_m)) d theta
// (and R_m likewise from the other end), with theta = acos(eta) and only factors <= 1,
// so it is stable for any A. Between neighbouring points nothing jumps, and short
// Gauss-Legendre rules integrate each piece to rounding. The same integrals as
// kernel_moments (product method, (4.2), (4.4); G of (3.25), E8), at a fraction of the cost.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

// values(theta, out): writes g_v(cos theta), v < width, into out[0..width).
using basis_values = std::function<void(double theta, double* out)>;
// The same for count points at once, theta[i] and eta[i] = cos theta[i]: g_v(eta[i]) into
// out[i * width + v].
using batch_basis_values = std::function<void(const double* theta, const double* eta, std::size_t count, double* out)>;

// A workspace for fixed points and functions: the quadrature points of every piece and
// the basis values there are computed once, and apply() integrates any kernel whose rates
// do not exceed max_rate (the tangential problem's stretched kernels rho K1*(rho z), one
// per trial c0). `degree` bounds the degree of the g_v in eta (it sets the quadrature).
// Throws numerical_error when the points are not sorted or leave [-1, 1].
class kernel_sweep {
public:
    kernel_sweep(const std::vector<double>& points, int width, int degree, double max_rate, const basis_values& values);
    kernel_sweep(const std::vector<double>& points, int width, int degree, double max_rate,
                 const batch_basis_values& values);

    // points.size() x width values, row-major.
    std::vector<double> apply(const kernel& k) const;

    // The largest rate whose workspace (quadrature order and segment length) is the one built
    // for max_rate with this degree: a workspace built for it serves every rate up to it with
    // the same points, bit for bit (sweep_cache, collocation.hpp). max_rate itself when the
    // segments shrink with the rate.
    static double same_layout_rate(int degree, double max_rate);

private:
    std::vector<double> points_;
    int width_;
    double max_rate_;
    std::vector<std::size_t> first_;  // piece i owns quadrature points [first_[i], first_[i+1])
    std::vector<double> c_, w_, g_;   // cos(theta), weight, basis values at each quadrature point
};

// One-off: kernel_sweep(points, width, degree, k.max_rate(), values).apply(k).
std::vector<double> sweep(const kernel& k, const std::vector<double>& points, int width, int degree,
                          const basis_values& values);

// The Lagrange basis of the nodes eta_k of a Gauss-Chebyshev rule, by the barycentric
// formula with weights (-1)^k sin^2(theta_k) (the nodes are the zeros of U_n).
class lagrange_basis {
public:
    explicit lagrange_basis(const gauss_chebyshev& rule);
    void operator()(double theta, double* out) const;  // l_k(cos theta), k < n
    // At count points x[i] (= cos theta), out[i * n + k] = l_k(x[i]): the same values, bit for
    // bit, with several points side by side (the sweep's set-up, once per operator).
    void operator()(const double* x, std::size_t count, double* out) const;

private:
    const gauss_chebyshev& rule_;
    std::vector<double> beta_;
};

}  // namespace roughroll
