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
// The a-posteriori check of the degree (cut_convolution.hpp, docs/formulation.md 8(o) "The degree, checked"): a
// piece's summed tail of g dr/du at most this fraction of pi max |g dr/du|.
constexpr double tail_tolerance = 1e-13;
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
    // Beyond this degree (about 2.6 10^4 panels per piece, 6.6 10^5 values of g) the piece is refused.
    constexpr int max_degree = 1 << 16;

    // Per piece: its panels (convolution_table's rule for the degree and rate the piece sees in u), the local
    // x = cos u at every node, and g dr/du = g h sin u there (dr = -h sin u du; L and R run in u as in theta).
    std::vector<std::vector<double>> x(count), w(count), d(count);
    std::vector<double> r;
    const auto fill = [&](std::size_t p, int panels) {
        const double m = 0.5 * (cuts_[p] + cuts_[p + 1]), h = 0.5 * (cuts_[p + 1] - cuts_[p]);
        pieces_[p] = theta_panels(panels);
        const std::size_t nodes = static_cast<std::size_t>(panels) * size;
        x[p].resize(nodes);
        w[p].resize(nodes);
        r.resize(nodes);
        for (int j = 0; j < panels; ++j)
            for (int i = 0; i < size; ++i) {
                const std::size_t q = static_cast<std::size_t>(j) * size + i;
                x[p][q] = std::cos(pieces_[p].node(j, i));
                r[q] = std::clamp(m + h * x[p][q], -1.0, 1.0);
            }
        g(r.data(), w[p].data(), nodes);
        for (std::size_t q = 0; q < nodes; ++q) w[p][q] *= h * std::sqrt((1.0 - x[p][q]) * (1.0 + x[p][q]));
    };
    // The a-posteriori check of the degree (the class comment): over the panels of piece p, the largest of the last
    // three Chebyshev coefficients of g dr/du's interpolant times the panel's half-length in u, summed (L and R
    // accumulate each panel's integral once, with factors <= 1).
    const std::vector<double> to_coefficients = theta_panels::values_to_coefficients();
    const auto tail_of = [&](std::size_t p) {
        double sum = 0.0;
        for (int j = 0; j < pieces_[p].panels(); ++j) {
            const double* wj = &w[p][static_cast<std::size_t>(j) * size];
            double tail = 0.0;
            for (int k = degree - 2; k <= degree; ++k) {
                double c = 0.0;
                for (int i = 0; i < size; ++i) c += to_coefficients[k * size + i] * wj[i];
                tail = std::max(tail, std::fabs(c));
            }
            sum += 0.5 * pieces_[p].length() * tail;
        }
        return sum;
    };
    pieces_.resize(count);
    std::vector<int> degrees(count);
    double scale = 0.0;
    for (std::size_t p = 0; p < count; ++p) {
        const double h = 0.5 * (cuts_[p + 1] - cuts_[p]);
        degrees[p] = static_cast<int>(std::ceil(oscillation * std::max(1.0, std::sqrt(h / narrowest))));
        fill(p, convolution_table::panels_for(degrees[p], rate * h));
        for (const double v : w[p]) scale = std::max(scale, std::fabs(v));
    }
    // A piece whose sum is above tail_tolerance pi max |g dr/du| (the largest over all pieces at their first panels:
    // the size the integrals, and so D, are measured against) takes twice the degree (and panel_bound's panels for
    // it) until it is below; refused beyond max_degree. Where no piece is raised the table is the one of the degree
    // estimate alone, bit for bit.
    for (std::size_t p = 0; p < count; ++p) {
        const double h = 0.5 * (cuts_[p + 1] - cuts_[p]);
        double tail = tail_of(p);
        while (!(tail <= tail_tolerance * M_PI * scale)) {
            if (2 * degrees[p] > max_degree)
                throw numerical_error(
                    "full coupling: the layer terms of the pressure's kinks (rough rollers) are not resolved by a "
                    "table of any size (docs/formulation.md 8(o)); try another n");
            degrees[p] *= 2;
            fill(p, convolution_table::panels_for(degrees[p], rate * h));
            tail = tail_of(p);
        }
        worst_tail_ = std::max(worst_tail_, scale > 0.0 ? tail / (M_PI * scale) : 0.0);
    }

    for (std::size_t p = 0; p < count; ++p) d[p].assign(w[p].size(), 0.0);
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
