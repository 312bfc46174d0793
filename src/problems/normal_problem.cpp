// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/normal_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/chebyshev_projection.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/least_value.hpp"

namespace roughroll {

namespace {
// p(r) of (4.1) from the U-series' value `series` at r (Clenshaw's, defined at any r): phi(r) sqrt(1 - r^2), + p_q^0(r)
// with the kinks (docs/formulation.md 8(l) step 0); 0 outside the contact. The scalar and the batched pressure's one
// finishing step, so that they agree bit for bit.
double finished_pressure(const normal_solution& s, double series, double r) {
    if (std::fabs(r) >= 1.0) return 0.0;
    const double smooth = series * std::sqrt(1.0 - r * r);
    return s.kinks ? smooth + (*s.kinks)(r) : smooth;
}
}  // namespace

double normal_solution::pressure(double r) const { return finished_pressure(*this, u_series(b, r), r); }

double normal_solution::projected_minus_hilbert(double r) const {
    // The collocation (4.2) without K2*: -H[phi sqrt(1 - r^2)] = -sum b_j T_{j+1} is a polynomial of degree n, equal to
    // gamma_0n + (2/pi) lambda r + P_n[...] at n + 1 points, so everywhere; H[p_q^0] = -removed + C (8(l) step 0), and
    // gamma_0n - C = (2/pi) lambda e (solve() below).
    // On the weight w_N (8(w), 8(x)) the collocation is (H + k_E)[w_N phi] = -gamma' - (2/pi) lambda r - P_n[R] at n + 1
    // points, and (H + k_E)[w_N phi] is a polynomial of degree n (8(v)'s identity), so everywhere: -H[p] gains k_E p.
    const double term = chebyshev_sum(projected, r) + (kinks ? kinks->removed(r) : 0.0) +
                        (kinks && kinks->weighted() ? kinks->weight_k() * pressure(r) : 0.0);
    return M_2_PI * lambda * (r + offset) + term;
}

std::vector<double> normal_solution::pressure(const std::vector<double>& r) const {
    std::vector<double> p(r.size());
    u_series(b, r.data(), p.data(), r.size());
    for (std::size_t i = 0; i < r.size(); ++i) p[i] = finished_pressure(*this, p[i], r[i]);
    return p;
}

pressure_peak peak_of(const normal_solution& s) {
    // The least value of -p; -p is 0 at both edges, so no edge is the answer.
    const auto minus_p = [&s](double r) { return -s.pressure(r); };
    const least_value least = least_on_contact(
        [&s](const std::vector<double>& r) {
            // The batched Clenshaw, bit for bit the scalar: the 2001 samples are most of the cost of a level's peak.
            std::vector<double> v = s.pressure(r);
            for (double& x : v) x = -x;
            return v;
        },
        minus_p, 2001, true, "peak pressure");
    const double r = least.r, p = -least.value;
    // Near a smooth peak p falls by |p''| d^2/2 at a distance d, so the points whose pressures lie within the
    // rounding delta = 16 eps p of the peak's fill d <= sqrt(2 delta/|p''|), and the golden section cannot choose
    // among them. The fall is measured at h = 1e-4 on either side (|p''| h^2/2 where p is smooth: its second
    // difference is within 1e-8 relative for Hertz's, far below what matters here); the smaller fall gives the
    // wider band, d = h sqrt(delta/fall). At a kink (full coupling's p_q^0, 8(l)) the fall is linear and this d
    // the larger, so never below the band; where p does not fall at h the band is at least h.
    constexpr double h = 1e-4;
    const double fall = std::min(p - s.pressure(r - h), p - s.pressure(r + h));
    const double rounding = 16.0 * GSL_DBL_EPSILON * p;
    const bool weighted = s.kinks && s.kinks->weighted() && s.rcond > 0.0;
    return {r, p, fall > 0.0 ? h * std::sqrt(rounding / fall) : h,
            weighted ? GSL_DBL_EPSILON * std::fabs(p) / s.rcond : 0.0, s.pressure(0.0)};
}

peak_slopes slopes_near(const normal_solution& a, const normal_solution& b, double r, double w, double step) {
    // Samples every `step` on [r - w, r + w] inside the contact, both ends included.
    const double from = std::max(r - w, -1.0 + step), to = std::min(r + w, 1.0 - step);
    const int count = std::max(2, static_cast<int>(std::ceil((to - from) / step)));
    std::vector<double> x(static_cast<std::size_t>(count) + 1);
    for (int i = 0; i <= count; ++i) x[i] = from + (to - from) * i / count;
    const double h = (to - from) / count;
    const std::vector<double> pa = a.pressure(x), pb = b.pressure(x);
    peak_slopes out{0.0, std::numeric_limits<double>::infinity()};
    for (int i = 0; i < count; ++i)
        out.slope_change = std::max(out.slope_change, std::fabs((pa[i + 1] - pb[i + 1]) - (pa[i] - pb[i])) / h);
    for (int i = 1; i < count; ++i)
        out.curvature = std::min(out.curvature, -(pa[i + 1] - 2.0 * pa[i] + pa[i - 1]) / (h * h));
    return out;
}

normal_solver::normal_solver(int n, method how) : rule_(n), how_(how), system_(static_cast<std::size_t>(n) + 2) {}

normal_solution normal_solver::solve(const kernel& k2, sweep_cache* cache) { return solve(k2, nullptr, {}, cache); }

normal_solution normal_solver::solve(const kernel& k2, const std::function<double(double)>& coupled,
                                     const std::vector<double>& kinks, sweep_cache* cache) {
    return solve(k2, coupled, kinks, cache, nullptr);
}

normal_solution normal_solver::solve(const kernel& k2, const std::function<double(double)>& coupled,
                                     const std::vector<double>& kinks, sweep_cache* cache,
                                     std::shared_ptr<const pressure_kinks> explicit_kinks) {
    check_resolution(k2, rule_, how_, "K2* (normal kernel)");
    const int n = rule_.n;
    auto kernel_term = std::make_shared<const kernel_operator>(rule_, how_, k2.max_rate(), cache);
    // Without K2 (smooth normal compliance) the matrix does not depend on the solve: the factors of
    // the last solve are kept, and the alternation of full coupling (8(e)) changes only the right side.
    const bool same_matrix = k2.empty() && smooth_factors_ && system_.holds_factors();
    gsl_vector* rhs = system_.rhs();
    if (same_matrix) {
        gsl_vector_set_zero(rhs);
    } else {
        system_.clear();
        gsl_matrix* a = system_.matrix();
        // Rows 0..n: collocation (4.2). Columns 0..n-1: phi_k; n: gamma_0n; n+1: lambda.
        add_cauchy_term(a, rule_);
        kernel_term->add_to(a, k2);
        for (int m = 0; m <= n; ++m) {
            gsl_matrix_set(a, m, n, 1.0);
            gsl_matrix_set(a, m, n + 1, M_2_PI * rule_.collocation[m]);
        }
        // Row n+1: the load (4.3).
        for (int k = 0; k < n; ++k) gsl_matrix_set(a, n + 1, k, rule_.weights[k]);
    }
    // With p_q^0 (8(l) step 0): int sqrt(1 - r^2) phi = 1 - int p_q^0.
    gsl_vector_set(rhs, n + 1, explicit_kinks ? 1.0 - explicit_kinks->load() : 1.0);
    // (D1): the known beta_D p1 on the right side (docs/formulation.md 8(e) item 3), as its
    // Chebyshev projection of degree n at s_m, not its values there (chebyshev_projection.hpp).
    std::vector<double> c;  // the projection's coefficients, kept in the solution for -H[p] (8(u))
    if (coupled) {
        // 8(l) step 0: beta_D (p1 - q), the q that p_q^0 carries taken out (its kinks are p_q^0's).
        const pressure_kinks* pk = explicit_kinks.get();
        const std::function<double(double)> right =
            pk ? std::function<double(double)>([&coupled, pk](double r) { return coupled(r) - pk->removed(r); })
               : coupled;
        c = chebyshev_projection(right, kinks, n);
        for (int m = 0; m <= n; ++m) gsl_vector_set(rhs, m, -chebyshev_sum(c, rule_.collocation[m]));
    }

    const gsl_vector* x = same_matrix ? system_.solve_factorised("normal problem (4.2)-(4.3)")
                                      : system_.solve("normal problem (4.2)-(4.3)");
    smooth_factors_ = k2.empty();
    normal_solution s{rule_,
                      how_,
                      std::vector<double>(n),
                      {},
                      gsl_vector_get(x, n + 1),
                      gsl_vector_get(x, n),
                      system_.rcond(),
                      std::move(kernel_term),
                      {},
                      0.0,
                      nullptr};
    for (int k = 0; k < n; ++k) s.phi[k] = gsl_vector_get(x, k);
    s.b = u_coefficients(rule_, s.phi);
    if (coupled) {
        s.tangential_term = coupled;
        // Without K2* the collocation is a polynomial identity (projected_minus_hilbert); with it, at the points only.
        if (k2.empty()) s.projected = std::move(c);
        // gamma_0n = (2/pi) lambda e (8(c)), + C of H[p_q^0] = -beta_D q + C with p_q^0 (8(l) step 0): C is
        // taken out, so that gamma keeps its meaning (2/pi) lambda e for the whole p, as printed before.
        if (explicit_kinks) s.gamma -= explicit_kinks->constant();
        s.offset = M_PI * s.gamma / (2.0 * s.lambda);
        s.kinks = std::move(explicit_kinks);
    }
    return s;
}

struct normal_solver::weighted_system {
    weighted_system(int n, double a_) : a(a_), colloc(n, a_), system(static_cast<std::size_t>(n) + 2) {}
    double a;
    jacobi_collocation colloc;
    dense_system system;
};

normal_solution normal_solver::solve_weighted(const std::function<double(double)>& coupled,
                                              const std::function<double(double)>& source_pressure,
                                              const std::vector<double>& kinks, std::shared_ptr<pressure_kinks> weighted) {
    if (!weighted || !weighted->weighted())
        throw numerical_error("full coupling: the weighted normal solve (docs/formulation.md 8(w)) without its weight");
    const int n = rule_.n;
    // The solution on the weight: p is weighted's (its series set), nothing on the kernel's side (8(w)).
    const auto on_weight = [&](std::vector<double> psi, double lambda, double gamma, double rcond) {
        normal_solution s{rule_,
                          how_,
                          std::move(psi),
                          std::vector<double>(n, 0.0),
                          lambda,
                          gamma,
                          rcond,
                          std::make_shared<const kernel_operator>(rule_, how_, 0.0, nullptr),
                          coupled,
                          0.0,
                          std::move(weighted)};
        s.offset = M_PI * s.gamma / (2.0 * s.lambda);
        return s;
    };
    if (weighted->variable()) {
        // The five zones on the exact weight of 8(z) ("Wired"): it carries the whole (D1), nothing on the right side.
        // No projection is kept, so 8(u)'s G_H reads G's formula (dissimilar_zones::blended_G): -H[p] of this discrete
        // p differs from it by beta_D sign (q - q_n) only, which moved the ends by at most 1.6e-9 at n = 128 (8(z)).
        const pressure_kinks::variable_result v = weighted->solve_variable();
        normal_solution s = on_weight(v.psi, v.lambda, v.gamma, v.rcond);
        s.lambda_rounding = v.lambda_rounding;
        return s;
    }
    const double a = weighted->weight_a(), k_e = weighted->weight_k();
    if (!weighted_ || weighted_->a != a) weighted_ = std::make_shared<weighted_system>(n, a);
    weighted_system& w = *weighted_;
    // The matrix is the same at every step (a_N fixed by the scene): factorised once.
    if (!w.system.holds_factors()) {
        gsl_matrix* m = w.system.matrix();
        gsl_matrix_set_zero(m);
        // Rows 0..n: (H + k_E)[w_N phi](x_m) + gamma' + (2/pi) lambda x_m = -(right side)(x_m), exact for phi of
        // degree n - 1 (8(v)); columns 0..n-1 phi at the rule's nodes, n gamma' = gamma_0n + C, n+1 lambda.
        add_cauchy_term(m, w.colloc);
        for (int i = 0; i <= n; ++i) {
            gsl_matrix_set(m, i, n, 1.0);
            gsl_matrix_set(m, i, n + 1, M_2_PI * w.colloc.collocation[i]);
        }
        // Row n+1: int w_N phi = sum W_k phi_k (exact) = 1 - int p_q.
        for (int k = 0; k < n; ++k) gsl_matrix_set(m, n + 1, k, w.colloc.rule.weights[k]);
    }
    gsl_vector* rhs = w.system.rhs();
    gsl_vector_set_zero(rhs);
    gsl_vector_set(rhs, n + 1, 1.0 - weighted->load());
    std::vector<double> c;  // the projection's coefficients, kept for -H[p] (projected_minus_hilbert, 8(u), 8(x))
    if (coupled) {
        const pressure_kinks* pk = weighted.get();
        const std::function<double(double)> right = [&coupled, &source_pressure, pk, k_e](double r) {
            return coupled(r) - pk->removed(r) - (source_pressure ? k_e * source_pressure(r) : 0.0);
        };
        c = chebyshev_projection(right, kinks, n);
        for (int i = 0; i <= n; ++i) gsl_vector_set(rhs, i, -chebyshev_sum(c, w.colloc.collocation[i]));
    }
    const gsl_vector* x = w.system.holds_factors() ? w.system.solve_factorised("normal problem on the weight w_N (8(w))")
                                                   : w.system.solve("normal problem on the weight w_N (8(w))");
    std::vector<double> phi(n);
    for (int k = 0; k < n; ++k) phi[k] = gsl_vector_get(x, k);
    weighted->set_series(jacobi_coefficients(w.colloc.rule, phi));
    const double lambda = gsl_vector_get(x, n + 1), gamma = gsl_vector_get(x, n) - weighted->constant();
    normal_solution s = on_weight(std::move(phi), lambda, gamma, w.system.rcond());
    s.projected = std::move(c);
    return s;
}

normal_solution hertz_solution(int n, method how) {
    // phi = 2/pi (Hertz, lambda = 1): the U-series is b_0 = 2/pi and nothing else, exactly (its
    // transform from the node values, u_coefficients, left rounding of up to 1.6e-15 in every b_j
    // at n = 128, which every evaluation of p then summed over n terms).
    gauss_chebyshev rule(n);
    std::vector<double> phi(n, M_2_PI);
    std::vector<double> b(n, 0.0);
    b[0] = M_2_PI;
    return {std::move(rule), how, std::move(phi), std::move(b), 1.0, 0.0, 1.0, nullptr, {}, 0.0, nullptr};
}

namespace {
bool same_terms(const kernel& a, const kernel& b) {
    const auto& x = a.terms();
    const auto& y = b.terms();
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!(x[i].T == y[i].T && x[i].A == y[i].A)) return false;
    return true;
}
}  // namespace

normal_solution normal_cache::solve(const kernel& k2, int n, method how) {
    for (const entry& e : solved_)
        if (e.n == n && e.how == how && same_terms(e.k2, k2)) return e.solution;
    solved_.push_back({k2, n, how, normal_solver(n, how).solve(k2, &sweeps_)});
    return solved_.back().solution;
}

normal_solution solve_normal(const kernel& k2, int n, method how, normal_cache* cache) {
    if (k2.empty()) return hertz_solution(n, how);
    return cache ? cache->solve(k2, n, how) : normal_solver(n, how).solve(k2);
}

}  // namespace roughroll
