// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/cut_convolution.hpp"

#include <algorithm>
#include <cmath>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/convolution_table.hpp"

namespace roughroll {

namespace {
// Cuts closer than this to each other or to an edge are one: a piece shorter than it holds nothing to integrate.
constexpr double cut_apart = 1e-12;
}  // namespace

cut_convolution::cut_convolution(const kernel& k, const values& g, const std::vector<double>& cuts, int oscillation,
                                 double narrowest) {
    if (!(narrowest > 0.0) || oscillation < 0)
        throw numerical_error("cut_convolution: the narrowest length must be positive and the degree not negative");
    std::vector<double> inner;
    for (const double c : cuts)
        if (c > -1.0 + cut_apart && c < 1.0 - cut_apart) inner.push_back(c);
    std::sort(inner.begin(), inner.end());
    cuts_.push_back(-1.0);
    for (const double c : inner)
        if (c - cuts_.back() > cut_apart) cuts_.push_back(c);
    cuts_.push_back(1.0);
    const std::size_t count = cuts_.size() - 1;
    constexpr int degree = theta_panels::degree;
    const int size = degree + 1;
    const double rate = k.max_rate();

    // Per piece: its panels (convolution_table's rule for the degree and rate the piece sees in u), the local
    // x = cos u at every node, and g dr/du = g h sin u there (dr = -h sin u du; L and R run in u as in theta).
    std::vector<std::vector<double>> x(count), w(count), d(count);
    for (std::size_t p = 0; p < count; ++p) {
        const double m = 0.5 * (cuts_[p] + cuts_[p + 1]), h = 0.5 * (cuts_[p + 1] - cuts_[p]);
        const int n = static_cast<int>(std::ceil(oscillation * std::max(1.0, std::sqrt(h / narrowest))));
        const double piece_rate = rate * h;
        const int panels = convolution_table::panels_for(n, piece_rate);
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

    const std::vector<double> integrate = theta_panels::integration_matrix();
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
