#include "roughroll/numerics/kernel_moments.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

namespace {
// Gauss-Legendre order for `count` moments: sin((j+1) theta) has up to count/2
// oscillations per half of [0, pi]; 36 more points integrate exp(-x) over x in [0, 24]
// to rounding, so a piece is cut into segments over which A |cos theta - r| changes by at
// most 24. The margins are set by the moment test against adaptive quadrature (QAWS).
constexpr double segment_decay = 24.0;
}  // namespace

gauss_legendre kernel_moments::moments_rule(int count) { return gauss_legendre(count + 36); }

kernel_moments::kernel_moments(const kernel& k, int count) : kernel_moments(k, count, moments_rule(count)) {}

kernel_moments::kernel_moments(const kernel& k, int count, const gauss_legendre& rule)
    : k_(k), count_(count), rule_(rule), moments_(count) {}

void kernel_moments::add_piece(double lo, double hi, double r, double side) {
    // side = sgn(eta - r) on this piece: the kernel without its jump.
    if (hi <= lo) return;
    const double span = k_.max_rate() * (hi - lo) / segment_decay;
    const int segments = span < 1.0 ? 1 : static_cast<int>(std::min(std::ceil(span), 1e7));
    for (int sgm = 0; sgm < segments; ++sgm)
        add_segment(lo + (hi - lo) * sgm / segments, lo + (hi - lo) * (sgm + 1) / segments, r, side);
}

void kernel_moments::add_segment(double lo, double hi, double r, double side) {
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    for (std::size_t q = 0; q < rule_.nodes.size(); ++q) {
        const double theta = mid + half * rule_.nodes[q];
        const double s = std::sin(theta), c = std::cos(theta);
        // The kernel with its sign fixed by the side: no sgn() evaluated at the jump.
        double kv = 0.0;
        const double d = std::fabs(c - r);
        for (const auto& t : k_.terms()) kv += t.T * std::exp(-t.A * d);
        const double weight = half * rule_.weights[q] * s * side * kv;
        // sin((j+1) theta) by the recurrence s_{j+1} = 2 cos(theta) s_j - s_{j-1}.
        double sj_prev = 0.0, sj = s;
        for (int j = 0; j < count_; ++j) {
            moments_[j] += weight * sj;
            const double next = 2.0 * c * sj - sj_prev;
            sj_prev = sj;
            sj = next;
        }
    }
}

const std::vector<double>& kernel_moments::at(double r) {
    std::fill(moments_.begin(), moments_.end(), 0.0);
    if (k_.empty()) return moments_;
    if (r >= 1.0) {
        add_piece(0.0, M_PI, r, -1.0);  // eta - r < 0 everywhere
    } else if (r <= -1.0) {
        add_piece(0.0, M_PI, r, +1.0);
    } else {
        const double theta_r = std::acos(r);
        add_piece(0.0, theta_r, r, +1.0);   // eta = cos(theta) > r
        add_piece(theta_r, M_PI, r, -1.0);  // eta < r
    }
    return moments_;
}

double kernel_moments::integrate(const std::vector<double>& b, double r) {
    const auto& m = at(r);
    double sum = 0.0;
    const auto count = std::min(b.size(), m.size());
    for (std::size_t j = 0; j < count; ++j) sum += b[j] * m[j];
    return sum;
}

}  // namespace roughroll
