// SPDX-License-Identifier: GPL-3.0-or-later
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

namespace {
// e^{-A} I_m(A) for m = 0..count-1, A > 0, by Miller's backward recurrence
// I_{m-1} = (2m/A) I_m + I_{m+1} (stable downwards: I_m is the recurrence's minimal solution),
// started far above both count and the orders where e^{-A} I_m(A) is not negligible (about
// sqrt(A) beyond A's own scale), and normalised by e^{-A} (I_0 + 2 sum_{m>=1} I_m) = 1.
std::vector<double> scaled_bessel_i(int count, double A) {
    // A < 1e-4: the power series e^{-A} sum_k (A/2)^{2k+m}/(k!(k+m)!) (A&S 9.6.10), each term
    // at most (A/2)^2 = 2.5e-9 of the one before, so six terms are exact to rounding; below about
    // 1e-40 the recurrence's step 2m/A overflows its rescaling (tiny decay rates are valid input).
    if (A < 1e-4) {
        std::vector<double> out(count, 0.0);
        double lead = std::exp(-A);  // e^{-A} (A/2)^m / m!, underflowing to 0 gracefully
        for (int m = 0; m < count; ++m) {
            double term = lead, sum = 0.0;
            for (int k = 1; k <= 6 && term != 0.0; ++k) {
                sum += term;
                term *= (A / 2) * (A / 2) / (k * static_cast<double>(k + m));
            }
            out[m] = sum;
            lead *= (A / 2) / (m + 1);
        }
        return out;
    }
    const double scale = std::max(static_cast<double>(count), std::min(A, 1e6));
    const int start = count + 40 + static_cast<int>(std::ceil(std::sqrt(60.0 * scale)));
    std::vector<double> out(count, 0.0);
    double above = 0.0, here = 1e-280, sum = 0.0;  // I_{m+1}, I_m (unnormalised), I_0 + 2 sum I_m
    for (int m = start; m >= 0; --m) {
        if (m < count) out[m] = here;
        sum += m == 0 ? here : 2.0 * here;
        const double below = m > 0 ? 2.0 * m / A * here + above : 0.0;
        above = here;
        here = below;
        if (std::fabs(here) > 1e250) {  // rescale everything kept so far
            above *= 1e-250;
            here *= 1e-250;
            sum *= 1e-250;
            for (int j = std::max(m, 0); j < count; ++j) out[j] *= 1e-250;
        }
    }
    for (double& v : out) v /= sum;
    return out;
}
}  // namespace

double integrate_at_end(const kernel& k, const std::vector<double>& b, double end) {
    if (!(end == 1.0 || end == -1.0)) throw numerical_error("integrate_at_end: the end must be 1 or -1");
    const int n = static_cast<int>(b.size());
    double total = 0.0;
    for (const auto& term : k.terms()) {
        // sum_j (+-1)^j b_j (j + 1) e^{-A} I_{j+1}(A)/A: the moments of e^{A eta} (end = 1) or of
        // e^{-A eta} (end = -1), times e^{-A}.
        double sum = 0.0;
        if (term.A == 0.0) {
            sum = n > 0 ? 0.5 * b[0] : 0.0;
        } else {
            const std::vector<double> i = scaled_bessel_i(n + 2, term.A);
            for (int j = n; j-- > 0;) {
                const double sign = end < 0.0 && j % 2 == 1 ? -1.0 : 1.0;
                sum += sign * b[j] * (j + 1) * i[j + 1] / term.A;
            }
        }
        // eta - end has the sign -end on the whole interval.
        total += -end * term.T * M_PI * sum;
    }
    return total;
}

}  // namespace roughroll
