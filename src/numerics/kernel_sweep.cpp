#include "roughroll/numerics/kernel_sweep.hpp"

#include <algorithm>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

namespace {
// Each piece between neighbouring points is cut into segments of at most pi/(degree+2)
// in theta, over which g_v (degree <= `degree` in cos theta) turns by at most half a
// period; 12 Gauss-Legendre points integrate that to rounding (error ~ (pi/2)^24/24!).
// exp(-A |cos theta - x|) changes by at most A times the segment: segments are also kept
// below 24/A, and the order grows with A times the segment, to at most 48.
int segment_order(double rate, double length) { return 12 + static_cast<int>(std::ceil(1.5 * rate * length)); }
}  // namespace

kernel_sweep::kernel_sweep(const std::vector<double>& points, int width, int degree, double max_rate,
                           const basis_values& values)
    : points_(points), width_(width), max_rate_(max_rate) {
    const std::size_t count = points.size();
    for (std::size_t m = 0; m < count; ++m) {
        if (!(points[m] >= -1.0 && points[m] <= 1.0) || (m > 0 && points[m] > points[m - 1]))
            throw numerical_error("kernel_sweep: evaluation points must be sorted and lie in [-1, 1]");
    }
    // Breakpoints in theta: 0, acos(x_0), ..., acos(x_{M-1}), pi; piece i spans [b_i, b_{i+1}].
    std::vector<double> b(count + 2);
    b.front() = 0.0;
    b.back() = M_PI;
    for (std::size_t m = 0; m < count; ++m) b[m + 1] = std::acos(points[m]);
    const std::size_t pieces = count + 1;
    const double longest = max_rate > 0.0 ? std::min(M_PI / (degree + 2), 24.0 / max_rate) : M_PI / (degree + 2);
    const gauss_legendre rule(segment_order(max_rate, longest));
    const std::size_t q = rule.nodes.size();

    // Quadrature points of every piece: cos(theta), weight with sin^2 (sqrt(1 - eta^2) d eta
    // = sin^2 theta d theta), and the basis values; piece i owns points [first_[i], first_[i+1]).
    // The pieces between collocation points are exactly `longest` long: the small slack
    // keeps rounding from doubling their segments.
    std::vector<int> segments(pieces);
    first_.assign(pieces + 1, 0);
    for (std::size_t i = 0; i < pieces; ++i) {
        segments[i] = static_cast<int>(std::ceil((b[i + 1] - b[i]) / longest - 1e-9));
        first_[i + 1] = first_[i] + static_cast<std::size_t>(segments[i]) * q;
    }
    const std::size_t total = first_.back();
    c_.resize(total);
    w_.resize(total);
    g_.resize(total * width);
    for (std::size_t i = 0, p = 0; i < pieces; ++i) {
        const double length = b[i + 1] - b[i];
        for (int sgm = 0; sgm < segments[i]; ++sgm) {
            const double lo = b[i] + length * sgm / segments[i], hi = b[i] + length * (sgm + 1) / segments[i];
            const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
            for (std::size_t j = 0; j < q; ++j, ++p) {
                const double theta = mid + half * rule.nodes[j];
                const double s = std::sin(theta);
                c_[p] = std::cos(theta);
                w_[p] = half * rule.weights[j] * s * s;
                values(theta, &g_[p * width]);
            }
        }
    }
}

std::vector<double> kernel_sweep::apply(const kernel& k) const {
    if (k.max_rate() > max_rate_)
        throw numerical_error("kernel_sweep: the kernel decays faster than the rule was built for");
    const std::size_t count = points_.size();
    const int width = width_;
    const auto& x = points_;
    std::vector<double> out(count * width, 0.0), acc(width);
    for (const auto& term : k.terms()) {
        // Left of x_m (eta > x_m, theta < theta_m, pieces 0..m): + T exp(-A (eta - x_m)).
        std::fill(acc.begin(), acc.end(), 0.0);
        for (std::size_t m = 0; m < count; ++m) {
            const double decay = m == 0 ? 0.0 : std::exp(-term.A * (x[m - 1] - x[m]));
            for (int v = 0; v < width; ++v) acc[v] *= decay;
            for (std::size_t p = first_[m]; p < first_[m + 1]; ++p) {
                const double e = w_[p] * std::exp(-term.A * (c_[p] - x[m]));
                for (int v = 0; v < width; ++v) acc[v] += e * g_[p * width + v];
            }
            for (int v = 0; v < width; ++v) out[m * width + v] += term.T * acc[v];
        }
        // Right of x_m (eta < x_m, pieces m+1..M): - T exp(-A (x_m - eta)).
        std::fill(acc.begin(), acc.end(), 0.0);
        for (std::size_t m = count; m-- > 0;) {
            const double decay = m + 1 == count ? 0.0 : std::exp(-term.A * (x[m] - x[m + 1]));
            for (int v = 0; v < width; ++v) acc[v] *= decay;
            for (std::size_t p = first_[m + 1]; p < first_[m + 2]; ++p) {
                const double e = w_[p] * std::exp(-term.A * (x[m] - c_[p]));
                for (int v = 0; v < width; ++v) acc[v] += e * g_[p * width + v];
            }
            for (int v = 0; v < width; ++v) out[m * width + v] -= term.T * acc[v];
        }
    }
    return out;
}

std::vector<double> sweep(const kernel& k, const std::vector<double>& points, int width, int degree,
                          const basis_values& values) {
    if (k.empty()) return std::vector<double>(points.size() * width, 0.0);
    return kernel_sweep(points, width, degree, k.max_rate(), values).apply(k);
}

lagrange_basis::lagrange_basis(const gauss_chebyshev& rule) : rule_(rule), beta_(rule.n) {
    for (int k = 0; k < rule.n; ++k) {
        const double s = std::sin((k + 1) * M_PI / (rule.n + 1));
        beta_[k] = (k % 2 == 0 ? 1.0 : -1.0) * s * s;
    }
}

void lagrange_basis::operator()(double theta, double* out) const {
    const double x = std::cos(theta);
    const int n = rule_.n;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double d = x - rule_.nodes[k];
        if (d == 0.0) {  // on a node: the basis is the unit vector
            std::fill(out, out + n, 0.0);
            out[k] = 1.0;
            return;
        }
        out[k] = beta_[k] / d;
        sum += out[k];
    }
    const double scale = 1.0 / sum;
    for (int k = 0; k < n; ++k) out[k] *= scale;
}

}  // namespace roughroll
