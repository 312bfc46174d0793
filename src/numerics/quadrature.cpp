// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

void check_node_count(int n) {
    if (n < min_nodes || n > max_nodes) {
        throw input_error("n = " + std::to_string(n) + " is outside the supported range [" + std::to_string(min_nodes) +
                          ", " + std::to_string(max_nodes) + "]");
    }
}

gauss_chebyshev::gauss_chebyshev(int n_) : gauss_chebyshev((check_node_count(n_), n_), unchecked{}) {}

gauss_chebyshev gauss_chebyshev::transform(int n) {
    if (n < min_nodes || n > max_transform_nodes)
        throw numerical_error("a transform's Gauss-Chebyshev rule of " + std::to_string(n) + " nodes is outside [" +
                              std::to_string(min_nodes) + ", " + std::to_string(max_transform_nodes) + "]");
    return gauss_chebyshev(n, unchecked{});
}

gauss_chebyshev::gauss_chebyshev(int n_, unchecked) : n(n_) {
    nodes.resize(n);
    weights.resize(n);
    collocation.resize(n + 1);
    const double h = M_PI / (n + 1);
    for (int k = 1; k <= n; ++k) {
        const double s = std::sin(k * h);
        nodes[k - 1] = std::cos(k * h);
        weights[k - 1] = h * s * s;
    }
    for (int m = 1; m <= n + 1; ++m) collocation[m - 1] = std::cos((2 * m - 1) * M_PI / (2.0 * n + 2.0));
}

gauss_legendre::gauss_legendre(int order) {
    // Golub-Welsch (gsl_integration_fixed) costs O(order^2) with a large constant and was 14 %
    // of a creep point; Newton's iteration on P_order by its three-term recurrence, from
    // Tricomi's asymptotic start cos(pi (i - 1/4)/(order + 1/2)), converges to rounding in
    // 3-4 steps per node (O(order^2) in all): nodes and weights w = 2/((1 - x^2) P'(x)^2),
    // symmetric about 0.
    gsl_guard();  // as every entry point that may precede GSL calls (base/error.hpp)
    if (order <= 0 || order > 100000)
        throw numerical_error("cannot build a Gauss-Legendre rule of order " + std::to_string(order));
    nodes.assign(order, 0.0);
    weights.assign(order, 0.0);
    const int half = (order + 1) / 2;
    // P_k = a_k x P_{k-1} - b_k P_{k-2}, a_k = (2k - 1)/k, b_k = (k - 1)/k: the divisions once.
    std::vector<double> a(order + 1, 0.0), bk(order + 1, 0.0);
    for (int k = 2; k <= order; ++k) {
        a[k] = (2.0 * k - 1.0) / k;
        bk[k] = (k - 1.0) / k;
    }
    for (int i = 1; i <= half; ++i) {
        double x = std::cos(M_PI * (i - 0.25) / (order + 0.5));
        double dp = 0.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = x;  // P_0, P_1
            for (int k = 2; k <= order; ++k) {
                const double p2 = a[k] * x * p1 - bk[k] * p0;
                p0 = p1;
                p1 = p2;
            }
            const double p = order == 1 ? x : p1;
            const double pm1 = order == 1 ? 1.0 : p0;  // P_{order-1}
            dp = order * (x * p - pm1) / (x * x - 1.0);
            const double dx = p / dp;
            x -= dx;
            if (std::fabs(dx) <= 1e-16) break;
        }
        // P'(x) at the converged node, for the weight.
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= order; ++k) {
            const double p2 = a[k] * x * p1 - bk[k] * p0;
            p0 = p1;
            p1 = p2;
        }
        dp = order == 1 ? 1.0 : order * (x * p1 - p0) / (x * x - 1.0);
        const double w = 2.0 / ((1.0 - x * x) * dp * dp);
        nodes[i - 1] = -x;
        nodes[order - i] = x;
        weights[i - 1] = weights[order - i] = w;
    }
    if (order % 2 == 1) nodes[half - 1] = 0.0;
}

std::vector<double> u_coefficients(const gauss_chebyshev& rule, const std::vector<double>& values) {
    // b_j = (2/pi) sum_k w_k phi_k U_j(eta_k), with w_k U_j(eta_k) = h sin(t_k) sin((j+1) t_k),
    // h = pi/(n+1): sin((j+1) t_k) by the recurrence s_{j+1} = 2 cos(t_k) s_j - s_{j-1}.
    const int n = rule.n;
    const double h = M_PI / (n + 1);
    // Blocks of nodes advance together (the recurrences are independent chains); each b_j
    // still sums its terms in the order of k.
    constexpr int block = 4;
    std::vector<double> b(n, 0.0);
    for (int first = 0; first < n; first += block) {
        const int width = std::min(block, n - first);
        double two_cos[block] = {}, scale[block] = {}, s_prev[block] = {}, s[block] = {};
        for (int i = 0; i < width; ++i) {
            const int k = first + i;
            const double t = (k + 1) * h, sin_t = std::sin(t);
            two_cos[i] = 2.0 * rule.nodes[k];
            scale[i] = M_2_PI * h * sin_t * values[k];
            s[i] = sin_t;
        }
        for (int j = 0; j < n; ++j) {
            double bj = b[j];
            for (int i = 0; i < width; ++i) bj += scale[i] * s[i];
            b[j] = bj;
            for (int i = 0; i < block; ++i) {
                const double next = two_cos[i] * s[i] - s_prev[i];
                s_prev[i] = s[i];
                s[i] = next;
            }
        }
    }
    return b;
}

std::size_t significant_terms(const std::vector<double>& b) {
    std::size_t size = b.size();
    while (size > 1 && b[size - 1] == 0.0) --size;
    return size;
}

double u_series(const std::vector<double>& b, double x) {
    // Clenshaw: y_j = b_j + 2x y_{j+1} - y_{j+2}; U-series sum is y_0.
    double y1 = 0.0, y2 = 0.0;
    for (auto j = significant_terms(b); j-- > 0;) {
        const double y0 = b[j] + 2.0 * x * y1 - y2;
        y2 = y1;
        y1 = y0;
    }
    return y1;
}

void u_series(const std::vector<double>& b, const double* x, double* out, std::size_t count) {
    // Clenshaw's recurrence is a chain of dependent operations: blocks of points advance
    // together, in the order of the scalar version, so the compiler can vectorise across them.
    constexpr std::size_t block = 8;
    for (std::size_t first = 0; first < count; first += block) {
        const std::size_t width = std::min(block, count - first);
        double two_x[block] = {}, y1[block] = {}, y2[block] = {};
        for (std::size_t i = 0; i < width; ++i) two_x[i] = 2.0 * x[first + i];
        for (auto j = significant_terms(b); j-- > 0;) {
            const double bj = b[j];
            for (std::size_t i = 0; i < block; ++i) {
                const double y0 = bj + two_x[i] * y1[i] - y2[i];
                y2[i] = y1[i];
                y1[i] = y0;
            }
        }
        for (std::size_t i = 0; i < width; ++i) out[first + i] = y1[i];
    }
}

double cauchy_u_series(const std::vector<double>& b, double x) {
    double sum = 0.0;
    if (std::fabs(x) < 1.0) {
        // T_{j+1}(x) by the three-term recurrence, stable on [-1, 1].
        double t_prev = 1.0, t = x;  // T_0, T_1
        for (double bj : b) {
            sum += bj * t;
            const double t_next = 2.0 * x * t - t_prev;
            t_prev = t;
            t = t_next;
        }
    } else {
        const double z = x - std::copysign(std::sqrt(x * x - 1.0), x);
        double zp = z;
        for (double bj : b) {
            sum += bj * zp;
            zp *= z;
        }
    }
    return -sum;
}

void cauchy_u_series(const std::vector<double>& b, const double* x, double* out, std::size_t count) {
    // As u_series above: blocks of points outside (-1, 1), or inside it, advance together, each in the
    // order of the scalar version; a block with points on both sides takes the scalar version.
    constexpr std::size_t block = 8;
    for (std::size_t first = 0; first < count; first += block) {
        const std::size_t width = std::min(block, count - first);
        bool outside = true, inside = true;
        for (std::size_t i = 0; i < width; ++i) {
            const bool in = std::fabs(x[first + i]) < 1.0;
            outside = outside && !in;
            inside = inside && in;
        }
        if (inside) {  // the T recurrences side by side (the points of a zone inside it)
            double two_x[block] = {}, t_prev[block] = {}, t[block] = {}, sum[block] = {};
            for (std::size_t i = 0; i < width; ++i) {
                two_x[i] = 2.0 * x[first + i];
                t_prev[i] = 1.0;
                t[i] = x[first + i];
            }
            for (double bj : b) {
                for (std::size_t i = 0; i < block; ++i) {
                    sum[i] += bj * t[i];
                    const double t_next = two_x[i] * t[i] - t_prev[i];
                    t_prev[i] = t[i];
                    t[i] = t_next;
                }
            }
            for (std::size_t i = 0; i < width; ++i) out[first + i] = -sum[i];
            continue;
        }
        if (!outside) {
            for (std::size_t i = 0; i < width; ++i) out[first + i] = cauchy_u_series(b, x[first + i]);
            continue;
        }
        double z[block] = {}, zp[block] = {}, sum[block] = {};
        for (std::size_t i = 0; i < width; ++i) {
            const double xi = x[first + i];
            z[i] = zp[i] = xi - std::copysign(std::sqrt(xi * xi - 1.0), xi);
        }
        for (double bj : b) {
            for (std::size_t i = 0; i < block; ++i) {
                sum[i] += bj * zp[i];
                zp[i] *= z[i];
            }
        }
        for (std::size_t i = 0; i < width; ++i) out[first + i] = -sum[i];
    }
}

}  // namespace roughroll
