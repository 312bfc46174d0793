// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/theta_panels.hpp"

#include <algorithm>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

double theta_panels::lobatto(int i) { return -std::cos(M_PI * i / degree); }

std::vector<double> theta_panels::values_to_coefficients() {
    std::vector<double> c((degree + 1) * (degree + 1));
    for (int k = 0; k <= degree; ++k)
        for (int i = 0; i <= degree; ++i) {
            const int m = degree - i;  // s_i = cos(m pi/N)
            double w = 2.0 / degree * std::cos(M_PI * k * m / degree);
            if (m == 0 || m == degree) w *= 0.5;
            if (k == 0 || k == degree) w *= 0.5;
            c[k * (degree + 1) + i] = w;
        }
    return c;
}

// Values at the points -> int_{-1}^{s_i} of their interpolant: the coefficients of the
// antiderivative, int T_k = T_{k+1}/(2(k+1)) - T_{k-1}/(2(k-1)) (k >= 2), int T_1 = T_2/4,
// int T_0 = T_1, made zero at s = -1, evaluated at the points.
std::vector<double> theta_panels::integration_matrix() {
    const std::vector<double> to_coefficients = values_to_coefficients();
    const int size = degree + 1;
    std::vector<double> q(size * size);
    for (int col = 0; col < size; ++col) {
        std::vector<double> c(degree + 3, 0.0), big(degree + 2, 0.0);
        for (int k = 0; k <= degree; ++k) c[k] = to_coefficients[k * size + col];
        big[1] = c[0] - 0.5 * c[2];
        for (int k = 2; k <= degree + 1; ++k) big[k] = (c[k - 1] - c[k + 1]) / (2.0 * k);
        double at_minus_one = 0.0;
        for (int k = 1; k <= degree + 1; ++k) at_minus_one += (k % 2 == 0 ? 1.0 : -1.0) * big[k];
        big[0] = -at_minus_one;
        for (int i = 0; i < size; ++i) {
            double sum = 0.0;
            for (int k = 0; k <= degree + 1; ++k) sum += big[k] * std::cos(M_PI * k * (degree - i) / degree);
            q[i * size + col] = sum;
        }
    }
    return q;
}

double theta_panels::ellipse_bound(double half_length, const std::function<double(double y, double x)>& modulus) {
    // min over a grid of rho of 4 M rho^-N/(rho - 1), M the bound on the ellipse of half-axes
    // y = h (rho - 1/rho)/2 (imaginary) and x = h (rho + 1/rho)/2 (real) around the panel.
    double best = HUGE_VAL;
    for (double rho = 1.05; rho < 1e4; rho *= 1.05) {
        const double y = 0.5 * half_length * (rho - 1.0 / rho), x = 0.5 * half_length * (rho + 1.0 / rho);
        best = std::min(best, 4.0 * modulus(y, x) * std::pow(rho, -degree) / (rho - 1.0));
    }
    return best;
}

theta_panels::theta_panels(int panels) : panels_(panels), length_(M_PI / panels) {
    if (panels < 1) throw numerical_error("theta_panels: the panel count must be positive");
}

double theta_panels::node(int j, int i) const {
    return i == degree ? (j + 1) * length_ : j * length_ + (lobatto(i) + 1.0) * 0.5 * length_;
}

void theta_panels::set_values(const std::vector<double>& values) {
    const int size = degree + 1;
    if (values.size() != static_cast<std::size_t>(panels_) * size)
        throw numerical_error("theta_panels: one value per node expected");
    const std::vector<double> to_c = values_to_coefficients();
    coefficients_.assign(values.size(), 0.0);
    for (int j = 0; j < panels_; ++j)
        for (int k = 0; k < size; ++k) {
            double sum = 0.0;
            for (int i = 0; i < size; ++i) sum += to_c[k * size + i] * values[j * size + i];
            coefficients_[j * size + k] = sum;
        }
}

theta_panels::panel_point theta_panels::locate(double r) const {
    const double theta = std::acos(std::max(-1.0, std::min(1.0, r)));
    const int j = std::min(panels_ - 1, static_cast<int>(theta / length_));
    return {&coefficients_[static_cast<std::size_t>(j) * (degree + 1)], 2.0 * (theta - j * length_) / length_ - 1.0};
}

double theta_panels::operator()(double r) const {
    // The batched route's operations for one lane, without its lanes (W's quadrature takes single
    // values by the hundred thousand).
    const auto [c, s] = locate(r);
    return panel_sum(c, s);
}

void theta_panels::operator()(const double* r, double* out, std::size_t count) const {
    constexpr std::size_t lanes = 4;
    for (std::size_t first = 0; first < count; first += lanes) {
        const std::size_t width = std::min(lanes, count - first);
        // Only the lanes holding points: a single point (the scalar operator) costs one recurrence.
        panel_point p[lanes];
        for (std::size_t i = 0; i < width; ++i) p[i] = locate(r[first + i]);
        // Clenshaw for sum_k c_k T_k(s), the lanes' steps interleaved.
        double y1[lanes] = {}, y2[lanes] = {};
        for (int k = degree; k >= 1; --k)
            for (std::size_t i = 0; i < width; ++i) {
                const double y0 = p[i].c[k] + 2.0 * p[i].s * y1[i] - y2[i];
                y2[i] = y1[i];
                y1[i] = y0;
            }
        for (std::size_t i = 0; i < width; ++i) out[first + i] = p[i].c[0] + p[i].s * y1[i] - y2[i];
    }
}

}  // namespace roughroll
