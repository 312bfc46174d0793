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

// Values at the points -> int_{-1}^{s_i} of their interpolant: the coefficients of the
// antiderivative, int T_k = T_{k+1}/(2(k+1)) - T_{k-1}/(2(k-1)) (k >= 2), int T_1 = T_2/4,
// int T_0 = T_1, made zero at s = -1, evaluated at the points.
std::vector<double> integration_matrix(const std::vector<double>& to_coefficients) {
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

convolution_table::convolution_table(const kernel& k, const std::vector<double>& b) {
    const int n = static_cast<int>(b.size());
    const double rate = k.max_rate();
    double strength = 0.0, l1 = 0.0;
    for (const auto& term : k.terms()) strength += std::fabs(term.T);
    for (double bj : b) l1 += std::fabs(bj);
    scale_ = M_PI * l1 * strength;
    // The panel count: from about 8/(n + 1 + A) long panels, finer until the bound of the
    // representation (relative to the size bound pi B sum |T|) is below eps.
    int panels = std::max(1, static_cast<int>(std::ceil(M_PI * (n + 1 + rate) / 8.0)));
    double relative = panel_bound(n, rate, M_PI / panels);
    while (!(relative <= M_PI * DBL_EPSILON)) {
        if (panels >= max_panels)
            throw numerical_error("convolution_table: no panel count meets the representation bound (rate too large)");
        panels = std::min(max_panels, panels + std::max(1, panels / 4));
        relative = panel_bound(n, rate, M_PI / panels);
    }
    table_ = theta_panels(panels);
    const double length = table_.length();
    bound_ = relative * l1 * strength;

    const int size = degree + 1;
    const std::vector<double> integrate = integration_matrix(theta_panels::values_to_coefficients());
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

namespace roughroll {

namespace {
// Cuts closer than this to each other or to an edge are one: a piece shorter than it holds nothing to integrate.
constexpr double cut_apart = 1e-12;
}  // namespace

cut_convolution::cut_convolution(const kernel& k, const values& g, const std::vector<double>& cuts, int oscillation,
                                 double narrowest) {
    if (!(narrowest > 0.0) || oscillation < 0)
        throw numerical_error("cut_convolution: the degree and the narrowest length must be positive");
    std::vector<double> inner;
    for (const double c : cuts)
        if (c > -1.0 + cut_apart && c < 1.0 - cut_apart) inner.push_back(c);
    std::sort(inner.begin(), inner.end());
    cuts_.push_back(-1.0);
    for (const double c : inner)
        if (c - cuts_.back() > cut_apart) cuts_.push_back(c);
    cuts_.push_back(1.0);
    const std::size_t count = cuts_.size() - 1;
    const int size = degree + 1;
    const double rate = k.max_rate();

    // Per piece: its panels (convolution_table's rule for the degree and rate the piece sees in u), the local
    // x = cos u at every node, and g dr/du = g h sin u there (dr = -h sin u du; L and R run in u as in theta).
    std::vector<std::vector<double>> x(count), w(count), d(count);
    for (std::size_t p = 0; p < count; ++p) {
        const double m = 0.5 * (cuts_[p] + cuts_[p + 1]), h = 0.5 * (cuts_[p + 1] - cuts_[p]);
        const int n = static_cast<int>(std::ceil(oscillation * std::max(1.0, std::sqrt(h / narrowest))));
        const double piece_rate = rate * h;
        int panels = std::max(1, static_cast<int>(std::ceil(M_PI * (n + 1 + piece_rate) / 8.0)));
        while (!(convolution_table::panel_bound(n, piece_rate, M_PI / panels) <= M_PI * DBL_EPSILON)) {
            if (panels >= max_panels)
                throw numerical_error("cut_convolution: no panel count meets the representation bound (rate too large)");
            panels = std::min(max_panels, panels + std::max(1, panels / 4));
        }
        pieces_.emplace_back(panels);
        const std::size_t nodes = static_cast<std::size_t>(panels) * size;
        x[p].resize(nodes);
        w[p].resize(nodes);
        d[p].assign(nodes, 0.0);
        std::vector<double> r(nodes);
        for (int j = 0; j < panels; ++j)
            for (int i = 0; i < size; ++i) {
                const std::size_t q = static_cast<std::size_t>(j) * size + i;
                x[p][q] = std::cos(pieces_[p].node(j, i));
                r[q] = std::clamp(m + h * x[p][q], -1.0, 1.0);
            }
        g(r.data(), w[p].data(), nodes);
        for (std::size_t q = 0; q < nodes; ++q) w[p][q] *= h * std::sqrt((1.0 - x[p][q]) * (1.0 + x[p][q]));
    }

    const std::vector<double> integrate = integration_matrix(theta_panels::values_to_coefficients());
    std::vector<double> v(size), grow(size), integral(size);
    const auto integrate_panel = [&](double half) {
        for (int i = 0; i < size; ++i) {
            double sum = 0.0;
            for (int m = 0; m < size; ++m) sum += integrate[i * size + m] * v[m];
            integral[i] = half * sum;
        }
    };
    for (const auto& term : k.terms()) {
        // L(r) = int_r^1 g exp(-A (eta - r)): forward in u from r = 1 (piece by piece downwards), as in
        // convolution_table; `carried` is L at the panel's start, the factors <= 1.
        double carried = 0.0;
        for (std::size_t p = count; p-- > 0;) {
            const double A = term.A * 0.5 * (cuts_[p + 1] - cuts_[p]), length = pieces_[p].length();
            for (int j = 0; j < pieces_[p].panels(); ++j) {
                const double* xj = &x[p][static_cast<std::size_t>(j) * size];
                const double* wj = &w[p][static_cast<std::size_t>(j) * size];
                double* dj = &d[p][static_cast<std::size_t>(j) * size];
                const double cos_a = std::cos(j * length);
                for (int i = 0; i < size; ++i) {
                    grow[i] = std::exp(A * (cos_a - xj[i]));
                    v[i] = wj[i] * grow[i];
                }
                integrate_panel(0.5 * length);
                for (int i = 0; i < size; ++i) dj[i] += term.T * (carried + integral[i]) / grow[i];
                carried = (carried + integral[degree]) / grow[degree];
            }
        }
        // R(r) = int_{-1}^r g exp(-A (r - eta)): backward in u from r = -1 (piece by piece upwards).
        carried = 0.0;
        for (std::size_t p = 0; p < count; ++p) {
            const double A = term.A * 0.5 * (cuts_[p + 1] - cuts_[p]), length = pieces_[p].length();
            for (int j = pieces_[p].panels(); j-- > 0;) {
                const double* xj = &x[p][static_cast<std::size_t>(j) * size];
                const double* wj = &w[p][static_cast<std::size_t>(j) * size];
                double* dj = &d[p][static_cast<std::size_t>(j) * size];
                const double cos_b = std::cos((j + 1) * length);
                for (int i = 0; i < size; ++i) {
                    grow[i] = std::exp(A * (xj[i] - cos_b));
                    v[i] = wj[i] * grow[i];
                }
                integrate_panel(0.5 * length);
                for (int i = 0; i < size; ++i) dj[i] -= term.T * (carried + integral[degree] - integral[i]) / grow[i];
                carried = (carried + integral[degree]) / grow[0];
            }
        }
    }
    for (std::size_t p = 0; p < count; ++p) pieces_[p].set_values(d[p]);
}

std::size_t cut_convolution::piece_of(double r) const {
    const auto above = std::upper_bound(cuts_.begin() + 1, cuts_.end() - 1, r);
    return static_cast<std::size_t>(above - cuts_.begin()) - 1;
}

double cut_convolution::operator()(double r) const {
    const double clamped = std::clamp(r, -1.0, 1.0);
    const std::size_t p = piece_of(clamped);
    const double m = 0.5 * (cuts_[p] + cuts_[p + 1]), h = 0.5 * (cuts_[p + 1] - cuts_[p]);
    return pieces_[p](std::clamp((clamped - m) / h, -1.0, 1.0));
}

void cut_convolution::operator()(const double* r, double* out, std::size_t count) const {
    for (std::size_t i = 0; i < count; ++i) out[i] = (*this)(r[i]);
}

int cut_convolution::panels() const {
    int sum = 0;
    for (const theta_panels& t : pieces_) sum += t.panels();
    return sum;
}

}  // namespace roughroll
