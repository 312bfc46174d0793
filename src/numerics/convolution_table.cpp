// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/convolution_table.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/theta_panels.hpp"

namespace roughroll {

namespace {
constexpr int degree = theta_panels::degree;
constexpr int max_panels = 1000000;

}  // namespace

double convolution_table::panel_bound(int n, double rate, double length) {
    // For B = sum |b_j| = 1 and |T| = 1 (docs/formulation.md, "G once per contact"):
    //   integration of h = g exp(...) on each panel, accumulated over the panels of L and of R
    //   (carried with factors <= 1) and interpolated (Lebesgue constant of the Lobatto points):
    //     Lambda_N 2 pi min_rho 4 M_h rho^-N/(rho - 1),  M_h = e^{(n+1) y} E_A;
    //   interpolation of L - R on a panel: 2 min_rho 4 M_L rho^-N/(rho - 1),
    //     M_L = E_A (pi + (h + x + y) M_h),
    //   with E_A = exp(A (h + x + cosh y - 1)), h = length/2, y and x the ellipse's half-axes.
    const double h = 0.5 * length;
    const double lebesgue = 2.0 / M_PI * std::log(degree + 1.0) + 1.0;
    const auto e_a = [rate, h](double y, double x) { return std::exp(rate * (h + x + std::cosh(y) - 1.0)); };
    const auto m_h = [n, &e_a](double y, double x) { return std::exp((n + 1) * y) * e_a(y, x); };
    const double best_h = theta_panels::ellipse_bound(h, m_h);
    const double best_l = theta_panels::ellipse_bound(
        h, [h, &e_a, &m_h](double y, double x) { return e_a(y, x) * (M_PI + (h + x + y) * m_h(y, x)); });
    return lebesgue * 2.0 * M_PI * best_h + 2.0 * best_l;
}

int convolution_table::panels_for(int n, double rate) {
    // From about 8/(n + 1 + A) long panels, finer until the bound of the representation (relative to the size
    // bound pi B sum |T|) is below eps.
    int panels = std::max(1, static_cast<int>(std::ceil(M_PI * (n + 1 + rate) / 8.0)));
    while (!(panel_bound(n, rate, M_PI / panels) <= M_PI * DBL_EPSILON)) {
        if (panels >= max_panels)
            throw numerical_error("convolution_table: no panel count meets the representation bound (rate too large)");
        panels = std::min(max_panels, panels + std::max(1, panels / 4));
    }
    return panels;
}

convolution_table::convolution_table(const kernel& k, const std::vector<double>& b) {
    const int n = static_cast<int>(b.size());
    const double rate = k.max_rate();
    double strength = 0.0, l1 = 0.0;
    for (const auto& term : k.terms()) strength += std::fabs(term.T);
    for (double bj : b) l1 += std::fabs(bj);
    scale_ = M_PI * l1 * strength;
    const int panels = panels_for(n, rate);
    const double relative = panel_bound(n, rate, M_PI / panels);
    table_ = theta_panels(panels);
    const double length = table_.length();
    bound_ = relative * l1 * strength;

    const int size = degree + 1;
    const std::vector<double> integrate = theta_panels::integration_matrix();
    const double h = 0.5 * length;
    // The nodes of every panel (panel j, point i at index j * size + i), cos(theta) and g there.
    const std::size_t count = static_cast<std::size_t>(panels) * size;
    std::vector<double> c(count), g(count);
    for (int j = 0; j < panels; ++j)
        for (int i = 0; i < size; ++i) c[j * size + i] = std::cos(table_.node(j, i));
    u_series(b, c.data(), g.data(), count);
    for (std::size_t p = 0; p < count; ++p) g[p] *= 1.0 - c[p] * c[p];  // phi sin^2

    std::vector<double> d(count, 0.0), w(size), grow(size), integral(size);
    auto integrate_panel = [&](const double* values) {
        for (int i = 0; i < size; ++i) {
            double sum = 0.0;
            for (int m = 0; m < size; ++m) sum += integrate[i * size + m] * values[m];
            integral[i] = h * sum;
        }
    };
    for (const auto& term : k.terms()) {
        const double A = term.A;
        // L, forward from theta = 0 (r = 1), where it is 0.
        double carried = 0.0;
        for (int j = 0; j < panels; ++j) {
            const double* cj = &c[j * size];
            const double cos_a = std::cos(j * length);
            for (int i = 0; i < size; ++i) {
                grow[i] = std::exp(A * (cos_a - cj[i]));  // >= 1, at most exp(A length)
                w[i] = g[j * size + i] * grow[i];
            }
            integrate_panel(w.data());
            for (int i = 0; i < size; ++i) d[j * size + i] += term.T * (carried + integral[i]) / grow[i];
            carried = (carried + integral[degree]) / grow[degree];
        }
        // R, backward from theta = pi (r = -1), where it is 0.
        carried = 0.0;
        for (int j = panels; j-- > 0;) {
            const double* cj = &c[j * size];
            const double cos_b = std::cos((j + 1) * length);
            for (int i = 0; i < size; ++i) {
                grow[i] = std::exp(A * (cj[i] - cos_b));
                w[i] = g[j * size + i] * grow[i];
            }
            integrate_panel(w.data());
            for (int i = 0; i < size; ++i)
                d[j * size + i] -= term.T * (carried + integral[degree] - integral[i]) / grow[i];
            carried = (carried + integral[degree]) / grow[0];
        }
    }
    table_.set_values(d);
}

double convolution_table::operator()(double r) const { return table_(r); }

void convolution_table::operator()(const double* r, double* out, std::size_t count) const { table_(r, out, count); }

}  // namespace roughroll
