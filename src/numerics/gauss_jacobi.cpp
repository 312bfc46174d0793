// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/gauss_jacobi.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

gauss_jacobi::gauss_jacobi(int n_, double a_, double b_) : n(n_), a(a_), b(b_), recurrence(a_, b_, std::max(n_, 1)) {
    gsl_guard();
    if (n < 1 || !(a > -1.0) || !(b > -1.0))
        throw numerical_error("cannot build a Gauss-Jacobi rule of " + std::to_string(n) + " nodes with exponents " +
                              std::to_string(a) + ", " + std::to_string(b));
    // GSL's Jacobi type has the weight (b - x)^alpha (x - a)^beta on [a, b]: alpha is the exponent at +1.
    const std::unique_ptr<gsl_integration_fixed_workspace, decltype(&gsl_integration_fixed_free)> w(
        gsl_integration_fixed_alloc(gsl_integration_fixed_jacobi, static_cast<std::size_t>(n), -1.0, 1.0, a, b),
        gsl_integration_fixed_free);
    if (!w) throw numerical_error("Gauss-Jacobi rule of " + std::to_string(n) + " nodes: GSL could not build it");
    const double* x = gsl_integration_fixed_nodes(w.get());
    const double* wt = gsl_integration_fixed_weights(w.get());
    nodes.assign(x, x + n);
    weights.assign(wt, wt + n);
    for (int k = 0; k < n; ++k)
        if (!(std::isfinite(nodes[k]) && std::isfinite(weights[k]) && weights[k] > 0.0 && std::fabs(nodes[k]) < 1.0))
            throw numerical_error("Gauss-Jacobi rule of " + std::to_string(n) + " nodes: a node or weight is not valid");
}

jacobi_collocation::jacobi_collocation(int n, double a) : rule(n, a, 1.0 - a) {
    // 8(v): the points are the zeros of P_{n+1}^(-a, -b), the nodes of the rule of that weight (-a, -b > -1).
    collocation = gauss_jacobi(n + 1, -a, a - 1.0).nodes;
}

jacobi_collocation::jacobi_collocation(const gauss_jacobi& rule_) : rule(rule_) {
    collocation = gauss_jacobi(rule.n + 1, -rule.a, rule.a - 1.0).nodes;  // as above: b = 1 - a
}

std::shared_ptr<const gauss_jacobi> jacobi_rule_set::rule(int n, double a, double b) {
    for (const std::shared_ptr<const gauss_jacobi>& r : rules_)
        if (r->n == n && r->a == a && r->b == b) return r;
    rules_.push_back(std::make_shared<const gauss_jacobi>(n, a, b));
    return rules_.back();
}

double jacobi_weight(double a, double b, double t) {
    return std::pow(std::max(0.0, 1.0 - t), a) * std::pow(std::max(0.0, 1.0 + t), b);
}

namespace {

// DLMF 18.9.1-18.9.2: P_1 = (a + 1) + (a + b + 2)(x - 1)/2 = A_0 x + B_0 and, for j >= 1,
// 2 (j+1)(j+a+b+1)(2j+a+b) P_{j+1} = (2j+a+b+1) [(2j+a+b+2)(2j+a+b) x + a^2 - b^2] P_j
//                                    - 2 (j+a)(j+b)(2j+a+b+2) P_{j-1},
// P_{j+1} = (A_j x + B_j) P_j - C_j P_{j-1}. The one place the coefficients are computed: the tables of
// jacobi_recurrence and the sums of jacobi_values and jacobi_series give the same bits.
struct recurrence_step {
    double A, B, C;
};
inline recurrence_step recurrence_at(double a, double b, int j) {
    if (j == 0) return {0.5 * (a + b + 2.0), 0.5 * (a - b), 0.0};
    const double s = 2.0 * j + a + b;
    const double inv = 1.0 / (2.0 * (j + 1.0) * (j + a + b + 1.0) * s);
    return {(s + 1.0) * (s + 2.0) * s * inv, (s + 1.0) * (a * a - b * b) * inv, 2.0 * (j + a) * (j + b) * (s + 2.0) * inv};
}

// The coefficients' two sources, the same bits (recurrence_at): a table of them, or each computed when needed.
struct tabulated {
    const jacobi_recurrence& table;
    recurrence_step operator()(int j) const {
        const std::size_t i = static_cast<std::size_t>(j);
        return {table.A[i], table.B[i], table.C[i]};
    }
};
struct computed {
    double a, b;
    recurrence_step operator()(int j) const { return recurrence_at(a, b, j); }
};

// P_0(x) .. P_{count-1}(x) into out by the recurrence with the coefficients of `step`.
template <class Steps>
void values_of(const Steps& step, double x, int count, double* out) {
    if (count <= 0) return;
    out[0] = 1.0;
    if (count == 1) return;
    const recurrence_step first = step(0);
    out[1] = first.A * x + first.B;
    for (int j = 1; j + 1 < count; ++j) {
        const recurrence_step r = step(j);
        out[j + 1] = (r.A * x + r.B) * out[j] - r.C * out[j - 1];
    }
}

// sum_j c_j P_{j+shift}(x) (shift 0 or 1) by the recurrence with the coefficients of `step`: the one series routine
// of every Jacobi sum (jacobi_series, jacobi_recurrence::series and series_shifted, jacobi_cauchy_outside's psi(x)).
template <class Steps>
double series_of(const Steps& step, const std::vector<double>& c, double x, int shift) {
    if (c.empty()) return 0.0;
    const recurrence_step first = step(0);
    double prev = 1.0, cur = first.A * x + first.B;  // P_{k-1}, P_k
    int k = 1;
    double sum = c[0] * (shift == 0 ? prev : cur);  // c_0 * 1 is c_0, bit for bit
    for (std::size_t j = 1; j < c.size(); ++j) {
        for (; k < static_cast<int>(j) + shift; ++k) {
            const recurrence_step r = step(k);
            const double next = (r.A * x + r.B) * cur - r.C * prev;
            prev = cur;
            cur = next;
        }
        sum += c[j] * cur;
    }
    return sum;
}

}  // namespace

jacobi_recurrence::jacobi_recurrence(double a_, double b_, int count) : a(a_), b(b_) {
    const int m = std::max(count, 1);
    A.resize(m);
    B.resize(m);
    C.resize(m);
    for (int j = 0; j < m; ++j) {
        const recurrence_step r = recurrence_at(a, b, j);
        A[j] = r.A;
        B[j] = r.B;
        C[j] = r.C;
    }
}

void jacobi_recurrence::values(double x, int count, double* out) const { values_of(tabulated{*this}, x, count, out); }

void jacobi_values(double a, double b, double x, int count, double* out) { values_of(computed{a, b}, x, count, out); }

double jacobi_series(const std::vector<double>& c, double a, double b, double x) {
    return series_of(computed{a, b}, c, x, 0);
}

double jacobi_recurrence::series(const std::vector<double>& c, double x) const {
    return series_of(tabulated{*this}, c, x, 0);
}

double jacobi_recurrence::series_shifted(const std::vector<double>& c, double x) const {
    return series_of(tabulated{*this}, c, x, 1);
}

std::vector<double> jacobi_coefficients(const gauss_jacobi& rule, const std::vector<double>& values) {
    // O(n) per node by the rule's own table (no division per term).
    const int n = rule.n;
    std::vector<double> c(n, 0.0), h(n, 0.0), p(n);
    for (int k = 0; k < n; ++k) {
        rule.recurrence.values(rule.nodes[k], n, p.data());
        const double wv = rule.weights[k] * values[k];
        for (int j = 0; j < n; ++j) {
            c[j] += wv * p[j];
            h[j] += rule.weights[k] * p[j] * p[j];
        }
    }
    for (int j = 0; j < n; ++j) c[j] /= h[j];
    return c;
}

double jacobi_cauchy_outside(const std::vector<double>& c, const gauss_jacobi& rule,
                             const std::vector<double>& psi_nodes, const gauss_jacobi& far,
                             const std::vector<double>& psi_far, double x, const jacobi_recurrence* table) {
    // 8(v), "Off the zone". rho = |x| + sqrt(x^2 - 1) is the parameter of the Bernstein ellipse through x: the
    // M-point rule integrates psi/(tau - x) with an error of order rho^(-2M), below rounding where rho^(2M) > 1e17.
    const double ax = std::fabs(x);
    const double rho = ax + std::sqrt((ax - 1.0) * (ax + 1.0));
    if (2.0 * far.n * std::log(rho) > 39.0) {
        double sum = 0.0;
        for (int k = 0; k < far.n; ++k) sum += far.weights[k] * psi_far[k] / (far.nodes[k] - x);
        return M_1_PI * sum;
    }
    // Nearer: psi(tau) = psi(x) + (tau - x) r(tau) with r of degree n - 2, which the rule integrates exactly, and
    // (1/pi) int w/(tau - x) = C_0(x) = (X(x) - x - 1 + 2a)/sin(pi a), X = (x - 1)^a (x + 1)^b continued from
    // above the cut (X ~ x at infinity: -|x - 1|^a |x + 1|^b for x < -1), for a + b = 1 (8(v)). Here rho < e^(39/(2M)),
    // so |x| stays below about 1.2 and psi(x) below rho^n |c| (no cancellation worth the name in either part).
    const double a = rule.a, b = rule.b;
    const double psi_x = table ? series_of(tabulated{*table}, c, x, 0) : jacobi_series(c, a, b, x);  // the same bits
    double sum = 0.0;
    for (int k = 0; k < rule.n; ++k) sum += rule.weights[k] * (psi_nodes[k] - psi_x) / (rule.nodes[k] - x);
    const double X = std::copysign(std::pow(std::fabs(x - 1.0), a) * std::pow(std::fabs(x + 1.0), b), x);
    const double c0 = (X - x - 1.0 + 2.0 * a) / std::sin(M_PI * a);
    return M_1_PI * sum + psi_x * c0;
}

}  // namespace roughroll
