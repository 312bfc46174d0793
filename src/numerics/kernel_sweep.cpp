// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/kernel_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define ROUGHROLL_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define ROUGHROLL_VECTOR_CLONES
#endif

namespace roughroll {

namespace {
// Each piece between neighbouring points is cut into segments of at most pi/(degree+2)
// in theta, over which g_v (degree <= `degree` in cos theta) turns by at most half a
// period. q Gauss-Legendre points integrate exp(i omega t) on [-1, 1] with the error
// 2^(2q+1) (q!)^4 / ((2q+1) ((2q)!)^3) omega^(2q), here omega = pi/2: 6e-18 for q = 9, below
// rounding (3e-15 for q = 8). Measured against segments four times shorter, for n = 16 ... 512
// and rates up to the resolution limit: 9 points agree to rounding (3.3e-16), 7 leave 1.3e-14
// and 6 leave 4e-12 (test KernelSweep.LagrangeOperatorIntegratesEachSegmentToRounding); the 12
// used before cost a third more.
// exp(-A |cos theta - x|) changes by at most A times the segment: segments are also kept
// below 24/A, and the order grows with A times the segment, to at most base_order + 36.
constexpr int base_order = 9;
int segment_order(double rate, double length) { return base_order + static_cast<int>(std::ceil(1.5 * rate * length)); }
double longest_segment(int degree, double max_rate) {
    return max_rate > 0.0 ? std::min(M_PI / (degree + 2), 24.0 / max_rate) : M_PI / (degree + 2);
}

// The inner sums of apply(): acc_left[v] += sum_j e_left[j] g[j][v], acc_right likewise, each
// value summing its points in their order, in blocks of values held in registers. On x86-64
// also compiled for AVX2 (chosen at run time): wider registers, the same operations (no FMA
// contraction: AVX2 does not imply FMA), so the same values bit for bit.
typedef double four __attribute__((vector_size(32)));  // four doubles: one AVX2 register

// Unaligned loads and stores through memcpy (no vector passes a function boundary by value).
void load(four& v, const double* p) { std::memcpy(&v, p, sizeof v); }
void store(double* p, const four& v) { std::memcpy(p, &v, sizeof v); }

ROUGHROLL_VECTOR_CLONES
void accumulate_piece(const double* g, std::size_t width, std::size_t nodes, const double* e_left,
                      const double* e_right, double* acc_left, double* acc_right) {
    constexpr std::size_t block = 16;
    std::size_t v0 = 0;
    for (; v0 + block <= width; v0 += block) {
        four l0, l1, l2, l3, r0, r1, r2, r3;
        load(l0, acc_left + v0), load(l1, acc_left + v0 + 4), load(l2, acc_left + v0 + 8);
        load(l3, acc_left + v0 + 12);
        load(r0, acc_right + v0), load(r1, acc_right + v0 + 4), load(r2, acc_right + v0 + 8);
        load(r3, acc_right + v0 + 12);
        for (std::size_t j = 0; j < nodes; ++j) {
            const double* gj = g + j * width + v0;
            four g0, g1, g2, g3;
            load(g0, gj), load(g1, gj + 4), load(g2, gj + 8), load(g3, gj + 12);
            const double el = e_left[j], er = e_right[j];
            l0 += el * g0;
            l1 += el * g1;
            l2 += el * g2;
            l3 += el * g3;
            r0 += er * g0;
            r1 += er * g1;
            r2 += er * g2;
            r3 += er * g3;
        }
        store(acc_left + v0, l0);
        store(acc_left + v0 + 4, l1);
        store(acc_left + v0 + 8, l2);
        store(acc_left + v0 + 12, l3);
        store(acc_right + v0, r0);
        store(acc_right + v0 + 4, r1);
        store(acc_right + v0 + 8, r2);
        store(acc_right + v0 + 12, r3);
    }
    for (; v0 < width; ++v0)
        for (std::size_t j = 0; j < nodes; ++j) {
            const double gj = g[j * width + v0];
            acc_left[v0] += e_left[j] * gj;
            acc_right[v0] += e_right[j] * gj;
        }
}
}  // namespace

kernel_sweep::kernel_sweep(const std::vector<double>& points, int width, int degree, double max_rate,
                           const basis_values& values)
    : kernel_sweep(
          points, width, degree, max_rate,
          batch_basis_values([&values, width](const double* theta, const double*, std::size_t count, double* out) {
              for (std::size_t i = 0; i < count; ++i) values(theta[i], out + i * width);
          })) {}

kernel_sweep::kernel_sweep(const std::vector<double>& points, int width, int degree, double max_rate,
                           const batch_basis_values& values)
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
    const double longest = longest_segment(degree, max_rate);
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
    std::vector<double> thetas(total);
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
                thetas[p] = theta;
            }
        }
    }
    values(thetas.data(), c_.data(), total, g_.data());
}

double kernel_sweep::same_layout_rate(int degree, double max_rate) {
    const double longest = longest_segment(degree, max_rate);
    if (max_rate <= 0.0 || longest != M_PI / (degree + 2)) return max_rate;
    // The order base_order + ceil(1.5 A longest) stays while 1.5 A longest <= order - base_order; a hair below
    // that bound, checked, so that rounding never changes the order.
    const int order = segment_order(max_rate, longest);
    const double reach = std::min((order - base_order) / (1.5 * longest) * (1.0 - 1e-12), 24.0 / longest);
    if (!(reach >= max_rate) || longest_segment(degree, reach) != longest || segment_order(reach, longest) != order)
        return max_rate;
    return reach;
}

std::vector<double> kernel_sweep::apply(const kernel& k) const {
    if (k.max_rate() > max_rate_)
        throw numerical_error("kernel_sweep: the kernel decays faster than the rule was built for");
    const std::size_t count = points_.size();
    const std::size_t width = static_cast<std::size_t>(width_);
    const auto& x = points_;
    const auto& terms = k.terms();
    const std::size_t nt = terms.size();
    std::vector<double> out(count * width, 0.0);
    if (nt == 0 || count == 0) return out;
    // One pass over the quadrature points for every term and both sides (the basis values,
    // count x width of them, are the memory traffic): piece i lies between x_{i-1} and x_i.
    // Left of x_m (eta > x_m, pieces 0..m): + T exp(-A (eta - x_m)), accumulated as the pass
    // goes. Right of x_m (eta < x_m, pieces m+1..M): - T exp(-A (x_m - eta)); each piece's
    // part, referred to its left end x_{i-1}, is kept and the recurrence runs backwards after.
    std::vector<double> left(nt * width, 0.0), right((count + 1) * nt * width, 0.0), e_left, e_right;
    for (std::size_t i = 0; i <= count; ++i) {
        const bool has_left = i<count, has_right = i> 0;
        double* piece_right = &right[i * nt * width];
        const std::size_t lo = first_[i], nodes = first_[i + 1] - lo;
        for (std::size_t t = 0; t < nt; ++t) {
            const double A = terms[t].A;
            // exp(-A (x_{i-1} - x_i)): the left sums' decay across this piece (none before the first)
            const double across = has_left && has_right ? std::exp(-A * (x[i - 1] - x[i])) : 0.0;
            if (has_left) {
                double* acc = &left[t * width];
                for (std::size_t v = 0; v < width; ++v) acc[v] *= across;
            }
            // The weights of this piece's points, then the sums over them in blocks of `block`
            // values held in registers (each value still sums its points in their order). Inside
            // the contact the two weights of a point multiply to w^2 exp(-A (x_{i-1} - x_i)): one
            // exponential per point, the other weight a division, while that product is far from
            // underflow (A (x_{i-1} - x_i) <= 600; the division rounds twice more, at eps).
            e_left.resize(nodes);
            e_right.resize(nodes);
            if (has_left && has_right && A * (x[i - 1] - x[i]) <= 600.0) {
                for (std::size_t j = 0; j < nodes; ++j) {
                    const std::size_t p = lo + j;
                    e_left[j] = w_[p] * std::exp(-A * (c_[p] - x[i]));
                }
                for (std::size_t j = 0; j < nodes; ++j) e_right[j] = w_[lo + j] * w_[lo + j] * across / e_left[j];
            } else {
                for (std::size_t j = 0; j < nodes; ++j) {
                    const std::size_t p = lo + j;
                    e_left[j] = has_left ? w_[p] * std::exp(-A * (c_[p] - x[i])) : 0.0;
                    e_right[j] = has_right ? w_[p] * std::exp(-A * (x[i - 1] - c_[p])) : 0.0;
                }
            }
            accumulate_piece(&g_[lo * width], width, nodes, e_left.data(), e_right.data(), &left[t * width],
                             &piece_right[t * width]);
        }
        if (has_left) {
            for (std::size_t t = 0; t < nt; ++t) {
                const double* acc = &left[t * width];
                for (std::size_t v = 0; v < width; ++v) out[i * width + v] += terms[t].T * acc[v];
            }
        }
    }
    for (std::size_t t = 0; t < nt; ++t) {
        std::vector<double> acc(width, 0.0);
        for (std::size_t m = count; m-- > 0;) {
            const double decay = m + 1 == count ? 0.0 : std::exp(-terms[t].A * (x[m] - x[m + 1]));
            const double* piece = &right[((m + 1) * nt + t) * width];
            for (std::size_t v = 0; v < width; ++v) {
                acc[v] = acc[v] * decay + piece[v];
                out[m * width + v] -= terms[t].T * acc[v];
            }
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

namespace {
// l_k at four points, one k at a time: t[k] = beta_k/(x - eta_k) and the sums, in the scalar
// formula's order for each point (AVX2 clone on x86-64: the same operations, four wide).
ROUGHROLL_VECTOR_CLONES
void lagrange_block(const double* beta, const double* nodes, int n, const double* x, double* t, double* sum) {
    four xs;
    load(xs, x);
    four total = {0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < n; ++k) {
        const four v = beta[k] / (xs - nodes[k]);
        store(t + 4 * k, v);
        total += v;
    }
    store(sum, total);
}
}  // namespace

void lagrange_basis::operator()(const double* x, std::size_t count, double* out) const {
    constexpr std::size_t block = 4;
    const int n = rule_.n;
    std::vector<double> t(static_cast<std::size_t>(n) * block);
    for (std::size_t first = 0; first < count; first += block) {
        const std::size_t width = std::min(block, count - first);
        double xs[block];
        for (std::size_t i = 0; i < block; ++i) xs[i] = x[first + std::min(i, width - 1)];
        double sums[block];
        lagrange_block(beta_.data(), rule_.nodes.data(), n, xs, t.data(), sums);
        for (std::size_t i = 0; i < width; ++i) {
            double* row = out + (first + i) * n;
            const double sum = sums[i];
            if (!std::isfinite(sum)) {  // on a node (the unit vector), or next to one
                const auto hit = std::find(rule_.nodes.begin(), rule_.nodes.end(), xs[i]);
                if (hit != rule_.nodes.end()) {
                    std::fill(row, row + n, 0.0);
                    row[hit - rule_.nodes.begin()] = 1.0;
                } else {
                    (*this)(std::acos(xs[i]), row);
                }
                continue;
            }
            const double scale = 1.0 / sum;
            for (int k = 0; k < n; ++k) row[k] = t[k * block + i] * scale;
        }
    }
}

}  // namespace roughroll
