// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/collocation.hpp"

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/kernel_sweep.hpp"

namespace roughroll {

void add_cauchy_term(gsl_matrix* a, const gauss_chebyshev& rule) {
    const int n = rule.n;
    const double* w = rule.weights.data();
    const double* eta = rule.nodes.data();
    for (int m = 0; m <= n; ++m) {
        double* row = gsl_matrix_ptr(a, m, 0);
        const double s = rule.collocation[m];
        for (int k = 0; k < n; ++k) row[k] += M_1_PI * w[k] / (eta[k] - s);  // vectorised: no call per element
    }
}

void add_cauchy_term(gsl_matrix* a, const jacobi_collocation& rule) {
    const int n = rule.rule.n;
    const double* w = rule.rule.weights.data();
    const double* t = rule.rule.nodes.data();
    for (int m = 0; m <= n; ++m) {
        double* row = gsl_matrix_ptr(a, m, 0);
        const double x = rule.collocation[m];
        for (int k = 0; k < n; ++k) row[k] += M_1_PI * w[k] / (t[k] - x);
    }
}

namespace {
// The sweep of product integration at the collocation points of `rule`, the Lagrange basis of its
// nodes integrated against kernels of rates up to max_rate (kernel_sweep.hpp).
std::shared_ptr<const kernel_sweep> lagrange_sweep(const gauss_chebyshev& rule, double max_rate) {
    const lagrange_basis basis(rule);
    return std::make_shared<const kernel_sweep>(
        rule.collocation, rule.n, rule.n - 1, max_rate,
        batch_basis_values(
            [&basis](const double*, const double* eta, std::size_t count, double* out) { basis(eta, count, out); }));
}
}  // namespace

std::shared_ptr<const kernel_sweep> sweep_cache::get(const gauss_chebyshev& rule, double max_rate) {
    const double reach = kernel_sweep::same_layout_rate(rule.n - 1, max_rate);
    for (const entry& e : entries_)
        if (e.n == rule.n && e.reach == reach) return e.sweep;
    entries_.push_back({rule.n, reach, lagrange_sweep(rule, reach)});
    return entries_.back().sweep;
}

kernel_operator::kernel_operator(const gauss_chebyshev& rule, method how, double max_rate, sweep_cache* cache)
    : rule_(rule),
      how_(how),
      // The paper's node sum takes any rate; a sweep every rate up to the reach of its layout
      // (kernel_sweep::same_layout_rate), so that a second kernel of another rate, K1* beside
      // K2*, shares the workspace whenever it fits (tangential_solver), with the same values.
      max_rate_(how == method::paper ? HUGE_VAL : kernel_sweep::same_layout_rate(rule.n - 1, max_rate)) {
    // Product integration: int l_k(eta) sqrt(1 - eta^2) K(eta - s_m) d eta for the Lagrange
    // basis l_k of the nodes, the jump at eta = s_m integrated exactly (kernel_sweep.hpp).
    if (how != method::paper)  // product, and both levels of extrapolated
        sweep_ = cache ? cache->get(rule, max_rate) : lagrange_sweep(rule, max_rate_);
}

void kernel_operator::add_to(gsl_matrix* a, const kernel& kern) const {
    if (kern.empty()) return;
    const int n = rule_.n;
    if (how_ == method::paper) {
        for (int m = 0; m <= n; ++m)
            for (int k = 0; k < n; ++k)
                *gsl_matrix_ptr(a, m, k) += rule_.weights[k] * kern(rule_.nodes[k] - rule_.collocation[m]);
        return;
    }
    const std::vector<double> m_k = sweep_->apply(kern);
    for (int m = 0; m <= n; ++m) {
        double* row = gsl_matrix_ptr(a, m, 0);
        const double* add = &m_k[static_cast<std::size_t>(m) * n];
        for (int k = 0; k < n; ++k) row[k] += add[k];
    }
}

void add_kernel_term(gsl_matrix* a, const kernel& kern, const gauss_chebyshev& rule, method how) {
    if (!kern.empty()) kernel_operator(rule, how, kern.max_rate()).add_to(a, kern);
}

bool in_asymptotic_range(const kernel& k, int n, method how) {
    // A quarter of the refusal thresholds of check_resolution: measured on the stiff cases
    // (validation/test_stiff.cpp), the error falls at the method's order from there on.
    const double rate = k.max_rate(), h = M_PI / (n + 1);
    return how == method::paper ? rate * h <= 0.125 : rate * 0.5 * h * h <= 0.25;
}

void check_extrapolation_range(const kernel& k, int n, const char* which) {
    if (n / 2 >= min_nodes && in_asymptotic_range(k, n / 2, method::product)) return;
    const std::string advice =
        n < max_nodes && in_asymptotic_range(k, max_nodes / 2, method::product)
            ? "increase n (at most " + std::to_string(max_nodes) + ") or use method 'product'"
            : "use method 'product' (no n up to " + std::to_string(max_nodes) + " resolves them at n/2)";
    throw resolution_error("method 'extrapolated' with n = " + std::to_string(n) +
                           ": the coarse level n/2 is not in the asymptotic range of product integration for " + which +
                           "; " + advice);
}

void check_resolution(const kernel& k, const gauss_chebyshev& rule, method how, const char* what) {
    const double rate = k.max_rate();
    if (rate == 0.0) return;
    // Paper: the node sum samples exp(-A|z|) at the node spacing h = pi/(n+1) mid-contact;
    // beyond A h = 1/2 (two nodes per decay length) its error in P_H/P2 exceeds 1e-3 and
    // grows to O(1) (docs/performance.md). Product: the kernel is integrated exactly and
    // the error degrades gracefully; what it cannot do is resolve the end layers of width
    // 1/A once they are thinner than the first node spacing, about h^2/2.
    const double h = M_PI / (rule.n + 1);
    const bool resolved = how == method::paper ? rate * h <= 0.5 : rate * 0.5 * h * h <= 1.0;
    if (resolved) return;
    // In double: a rate up to the largest double must not overflow an int.
    const double needed =
        how == method::paper ? std::ceil(2.0 * M_PI * rate) - 1.0 : std::ceil(M_PI * std::sqrt(0.5 * rate)) - 1.0;
    const int n_needed = needed > max_nodes ? max_nodes + 1 : static_cast<int>(needed);
    std::ostringstream msg;
    msg << what << ": decay rate A = " << rate << " (width 1/A = " << 1.0 / rate
        << ") is below the resolution of method '" << to_string(how) << "' with n = " << rule.n
        << "; it needs n >= " << n_needed;
    if (n_needed > max_nodes) msg << ", beyond the largest supported n = " << max_nodes;
    throw resolution_error(msg.str());
}

}  // namespace roughroll
