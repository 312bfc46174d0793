// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/tangential_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

namespace {
// The resolution check before any workspace is sized by the kernel's rate.
const kernel& resolved(const kernel& k, const normal_solution& normal) {
    check_resolution(k, normal.rule, normal.how, "K1* (tangential kernel)");
    return k;
}

// The c0-independent part of the stick system (4.4) on a rule: the Cauchy term, and in column n -1, since -xi moves to
// the left of (4.4) (on the square-root weight, and on the Jacobi weight of 8(v)).
template <class Rule>
void stick_matrix(gsl_matrix* a, const Rule& rule, int n) {
    gsl_matrix_set_zero(a);
    add_cauchy_term(a, rule);
    for (int m = 0; m <= n; ++m) gsl_matrix_set(a, m, n, -1.0);
}

// The solution on the stick zone [start, c0] with Dundurs' forcing b from the system's unknowns x (psi_k at the rule's
// n nodes, then xi in entry n): Q = f + rho int psi (3.22), int psi by the rule's weights (E4, 8(v)); psi's
// coefficients by `coefficients` (U, or Jacobi on 8(v)'s weight).
template <class Coefficients>
tangential_solution zone_of(const gsl_vector* x, const std::vector<double>& weights, const Coefficients& coefficients,
                            double f, double start, double c0, double forcing, double rcond) {
    const double rho = 0.5 * (c0 - start);
    std::vector<double> psi(weights.size());
    double load = 0.0;
    for (std::size_t k = 0; k < weights.size(); ++k) {
        psi[k] = gsl_vector_get(x, k);
        load += weights[k] * psi[k];
    }
    return zone_solution(f, start, c0, gsl_vector_get(x, weights.size()), f + rho * load, coefficients(psi), rcond,
                         forcing);
}
}  // namespace

tangential_solver::tangential_solver(const normal_solution& normal, const kernel& k1, const kernel& k2, double f,
                                     bool closed_form)
    : tangential_problem(f, normal.rule.n, 0.0, closed_form && k1.empty() && k2.empty(), "tangential problem",
                         "root search for c0"),
      normal_(normal),
      k1_(resolved(k1, normal)),
      dk_(k2.minus(k1)),
      cauchy_(make_matrix(static_cast<std::size_t>(n_) + 1, static_cast<std::size_t>(n_) + 1)),
      system_(static_cast<std::size_t>(n_) + 1),
      k1_operator_(normal.kernel_term && k1.max_rate() <= normal.kernel_term->max_rate()
                       ? normal.kernel_term
                       : std::make_shared<const kernel_operator>(normal.rule, normal.how, k1.max_rate())) {
    stick_matrix(cauchy_.get(), normal_.rule, n_);
}

std::vector<double> tangential_solver::G(const std::vector<double>& r) {
    // (3.25): the kernel difference integrated on the interpolant of phi, split at its jump
    // (E8), so that G, and with it Q(c0), is continuous in c0. G does not depend on c0: its
    // kernel part is tabulated once per solver (convolution_table.hpp; its representation
    // error is bounded below eps times its size, docs/formulation.md "G once per contact").
    std::vector<double> g(r.size());
    for (std::size_t m = 0; m < r.size(); ++m) g[m] = M_2_PI * normal_.lambda * r[m];
    // Full coupling (docs/formulation.md 8(e) item 2): G = -L1[p] of the pressure solving (D1),
    // (2/pi) lambda (r + e) + beta_D p1 + int p (K2* - K1*), with p1 itself, kinks and all, not the
    // polynomial -L1 of the discrete p (which is the projection of that and smooths the kinks at the
    // zone ends, where the ends are decided: measured in 8(e), the ends then converge no better).
    if (normal_.tangential_term)
        for (std::size_t m = 0; m < r.size(); ++m)
            g[m] += M_2_PI * normal_.lambda * normal_.offset + normal_.tangential_term(r[m]);
    if (dk_.empty()) return g;
    if (!g_table_) g_table_.emplace(dk_, normal_.b);
    std::vector<double> table(r.size());
    (*g_table_)(r.data(), table.data(), r.size());
    for (std::size_t m = 0; m < r.size(); ++m) g[m] += table[m];
    return g;
}

double tangential_solver::G(double r) { return G(std::vector<double>{r}).front(); }

std::vector<double> tangential_solver::collocation_points(double start, double c0) const {
    const double rho = 0.5 * (c0 - start);
    std::vector<double> r(normal_.rule.collocation.size());
    for (std::size_t m = 0; m < r.size(); ++m) r[m] = rho * (normal_.rule.collocation[m] + 1.0) + start;  // E4
    return r;
}

// The braked zone's Jacobi collocation (docs/formulation.md 8(v)) for one exponent a: its rule, the rule of 4 n nodes
// for the Cauchy transform off the zone, and its system, whose matrix (H - k on the weight, the -xi column) is the
// same for every zone and every step of the alternation: factorised once.
// Its two rules come from the solve's jacobi_rule_set where one is given (share_rules): the pressure's weighted kinks
// (8(w)) take the same two.
struct tangential_solver::jacobi_zone {
    jacobi_zone(int n, double a_, jacobi_rule_set& rules)
        : a(a_), colloc(*rules.rule(n, a_, 1.0 - a_)), far(rules.rule(4 * n, a_, 1.0 - a_)),
          system(static_cast<std::size_t>(n) + 1) {}
    double a;
    jacobi_collocation colloc;
    std::shared_ptr<const gauss_jacobi> far;
    dense_system system;
};

void tangential_solver::couple_locally(std::function<double(double)> source_q, double source_start, double source_end) {
    source_q_ = std::move(source_q);
    source_start_ = source_start;
    source_end_ = source_end;
}

tangential_solver::jacobi_zone& tangential_solver::jacobi_for(double a) {
    if (!jacobi_ || jacobi_->a != a || jacobi_->colloc.rule.n != n_) {
        jacobi_rule_set own;  // no set shared: the rules for this zone alone
        jacobi_ = std::make_shared<jacobi_zone>(n_, a, rules_ ? *rules_ : own);
    }
    return *jacobi_;
}

tangential_solution tangential_solver::solve_on_jacobi(double start, double c0, double forcing) {
    // 8(v): (H - k)[w psi] - xi = f G + b p - k q_source at the n + 1 zeros x_m of P_{n+1}^(-a,-b), k = b f the local
    // coefficient of q in f G's beta_D p1 (8(e): p1 = sigma (f p + q), b = sigma beta_D), cot(pi a) = k.
    const double k = forcing * f_, a = 0.5 - std::atan(k) / M_PI;
    const double rho = 0.5 * (c0 - start);
    jacobi_zone& z = jacobi_for(a);
    const int n = n_;
    if (!z.system.holds_factors()) stick_matrix(z.system.matrix(), z.colloc, n);
    std::vector<double> r(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) r[i] = start + rho * (z.colloc.collocation[i] + 1.0);  // E4
    const std::vector<double> g = G(r), p = normal_.pressure(r);
    gsl_vector* rhs = z.system.rhs();
    // k q_source is taken at the same t on the source's zone: at the fixed point the same zone, and while the ends lag
    // the part of G's k q_source left on the right side, k (q_source(r) - q_source(r_source(t))), keeps the source's
    // one-sided terms at the source's ends where the pressure's kinks of step 0 sit (8(v), "The lag").
    const double source_rho = 0.5 * (source_end_ - source_start_);
    for (int i = 0; i <= n; ++i) {
        const double at_t = source_start_ + source_rho * (z.colloc.collocation[i] + 1.0);
        gsl_vector_set(rhs, i, f_ * g[i] + forcing * p[i] - k * source_q_(at_t));
    }
    std::ostringstream context;
    context.precision(17);
    context << "tangential problem (4.4) on the Jacobi weight (docs/formulation.md 8(v)) at c0 = " << c0
            << ", stick zone from " << start;
    const gsl_vector* x = z.system.holds_factors() ? z.system.solve_factorised(context.str()) : z.system.solve(context.str());
    tangential_solution s = zone_of(
        x, z.colloc.rule.weights,
        [&](const std::vector<double>& psi) { return jacobi_coefficients(z.colloc.rule, psi); }, f_, start, c0, forcing,
        z.system.rcond());
    s.weight_a = a;
    s.weight_b = 1.0 - a;
    return s;
}

tangential_solution tangential_solver::solve_on_zone(double start, double c0, double forcing,
                                                     const std::vector<double>* extra, bool near) {
    if (source_q_ && !extra && forcing != 0.0 && k1_.empty()) return solve_on_jacobi(start, c0, forcing);
    // The stick zone [start, c0]: r = start + rho (t + 1), rho = (c0 - start)/2 (E4 with the
    // zone's own start; docs/formulation.md 7(b)). The paper's zone has start = -1.
    const double rho = 0.5 * (c0 - start);
    const auto& rule = normal_.rule;
    // Without K1 (smooth tangential compliance) the matrix is the Cauchy part alone, the same for
    // every zone: its factors are kept from the first solve, and each later solve (Newton's steps,
    // the alternation of full coupling, 8(e)) changes only the right side (dense_system::solve_factorised).
    const bool same_matrix = k1_.empty() && !near && system_.holds_factors();
    if (!same_matrix) {
        gsl_matrix* a = system_.matrix();
        gsl_check(gsl_matrix_memcpy(a, cauchy_.get()), "tangential problem: copy of the Cauchy term");
        k1_operator_->add_to(a, k1_.stretched(rho));  // E6
    }
    gsl_vector* rhs = system_.rhs();
    const std::vector<double> r = collocation_points(start, c0);
    const std::vector<double> g = G(r);
    for (int m = 0; m <= n_; ++m) gsl_vector_set(rhs, m, f_ * g[m]);  // E5
    if (forcing != 0.0) {  // Dundurs' term of (D2), docs/formulation.md 8(e): xi + sigma beta_D p + f G
        const std::vector<double> p = normal_.pressure(r);  // at full coupling every zone solve of Newton's steps
        for (int m = 0; m <= n_; ++m) gsl_vector_set(rhs, m, gsl_vector_get(rhs, m) + forcing * p[m]);
    }
    if (extra)
        for (int m = 0; m <= n_; ++m) gsl_vector_set(rhs, m, gsl_vector_get(rhs, m) + (*extra)[m]);
    std::ostringstream context;
    context.precision(17);
    context << "tangential problem (4.4) at c0 = " << c0;
    if (start != -1.0) context << ", stick zone from " << start;
    // near: refined on the last factorisation when it converges (linear_system.hpp), the same
    // solution to rounding.
    const gsl_vector* x = same_matrix ? system_.solve_factorised(context.str())
                          : near      ? system_.solve_near(context.str())
                                      : system_.solve(context.str());
    return zone_of(
        x, rule.weights, [&](const std::vector<double>& psi) { return u_coefficients(rule, psi); }, f_, start, c0,
        forcing, system_.rcond());
}

std::optional<double> tangential_solver::search_start(double magnitude) const { return carter(magnitude, f_).c0; }

namespace {
// L1[q0] at a point of a slip zone, in the stick variable |t| > 1: the Cauchy transform of
// the U-series, plus the kernel terms. For t > 1, tau - t < 0 on the whole stick zone and each
// term T' exp(-A' (t - tau)) factors as exp(-A' (t - 1)) times its integral at t = 1; for
// t < -1 (the leading slip zone of docs/formulation.md 7) likewise exp(-A' (-1 - t)) times
// its integral at t = -1. So the kernel part costs two integrals per term, whatever the
// number of points, each in closed form (integrate_at_end, kernel_moments.hpp).
class stick_operator_outside {
public:
    stick_operator_outside(const kernel& stretched_k1, const std::vector<double>& psi_b) : psi_b_(psi_b) {
        for (const auto& term : stretched_k1.terms()) {
            const kernel one({term});
            at_ends_.push_back({term.A, integrate_at_end(one, psi_b, 1.0), integrate_at_end(one, psi_b, -1.0)});
        }
    }

    // L1[q0] at the points t[i] into out[i]: the Cauchy transforms summed for all points at once
    // (cauchy_u_series, bit for bit the scalar one), then the kernel terms in the same order.
    void operator()(const double* t, double* out, std::size_t count) const {
        cauchy_u_series(psi_b_, t, out, count);
        for (std::size_t i = 0; i < count; ++i)
            for (const auto& e : at_ends_)
                out[i] += t[i] > 0.0 ? e.at_one * std::exp(-e.rate * (t[i] - 1.0))
                                     : e.at_minus_one * std::exp(-e.rate * (-1.0 - t[i]));
    }

private:
    struct end_values {
        double rate, at_one, at_minus_one;  // A', the kernel integral at t = 1 and at t = -1
    };
    const std::vector<double>& psi_b_;
    std::vector<end_values> at_ends_;
};
}  // namespace

std::vector<double> tangential_solver::slip_velocity_magnitude(const tangential_solution& s,
                                                               const std::vector<double>& r) {
    // v = xi + f G(r) - L1[q0](r) for the |Q| problem, (3.6) with (3.15), at sorted points
    // of the slip zones, where L1 is the stick-zone operator evaluated outside its interval.
    std::vector<double> v = G(r);
    const double rho = s.rho();
    std::vector<double> l(r.size(), 0.0);
    if (s.weight_a > 0.0 && !s.psi_b.empty() && rho > 0.0) {
        // 8(v), "Off the zone": H[w psi] outside the zone (K1* is empty on this route).
        const jacobi_zone& z = jacobi_for(s.weight_a);
        const gauss_jacobi& rule = z.colloc.rule;
        if (outside_.a != s.weight_a || outside_.c != s.psi_b) {
            outside_.a = s.weight_a;
            outside_.c = s.psi_b;
            outside_.at_nodes.resize(rule.n);
            outside_.at_far.resize(z.far->n);
            for (int i = 0; i < rule.n; ++i)
                outside_.at_nodes[i] = jacobi_series(s.psi_b, s.weight_a, s.weight_b, rule.nodes[i]);
            for (int i = 0; i < z.far->n; ++i)
                outside_.at_far[i] = jacobi_series(s.psi_b, s.weight_a, s.weight_b, z.far->nodes[i]);
        }
        const std::vector<double>&at_nodes = outside_.at_nodes, &at_far = outside_.at_far;
        // G stays whole here, k q_source included: off the zone q = 0, and at the alternation's fixed point q_source = q,
        // so the slip velocity is the stick equation's; while the ends lag it reads as the old route's did.
        for (std::size_t i = 0; i < r.size(); ++i) {
            const double t = (r[i] - s.start()) / rho - 1.0;
            l[i] = std::fabs(t) >= 1.0 ? jacobi_cauchy_outside(s.psi_b, rule, at_nodes, *z.far, at_far, t) : 0.0;
        }
    } else if (!(s.psi_b.empty() || rho == 0.0)) {
        std::vector<double> t(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) t[i] = (r[i] - s.start()) / rho - 1.0;
        stick_operator_outside(k1_.stretched(rho), s.psi_b)(t.data(), l.data(), t.size());
    }
    for (std::size_t i = 0; i < r.size(); ++i) {
        v[i] = s.sign * s.xi + f_ * v[i] - l[i];
        if (s.forcing != 0.0) v[i] += s.forcing * normal_.pressure(r[i]);  // (D2), docs/formulation.md 8(e)
    }
    return v;
}

double tangential_solver::rounding(double xi) const {
    // (3.3) to rounding (docs/formulation.md 7(d)): q solves (4.4), whose right-hand side
    // xi + f G is made of terms of size |xi| + f K (K = max(1, P_H/P2, sum |T|), the terms of G of
    // (3.25)) that q cancels to its own size (stick_system_floor). Near gross sliding q is that
    // small itself and the margin is rounding (measured -3.0e-11 at Q/f = 1 - 1e-12, n = 256,
    // T = 100, A = 1: floor 6.5e-11), where a wrong structure fails by far more (-0.09 for the
    // paper's zone there, -1.1e-3 in the one-parameter limit of section 6). (3.4) likewise: the slip
    // velocity (3.6) is what is left of the same terms off the stick zone (measured -2e-12 .. -5e-11
    // on the general search's right zones), so it carries the same floor.
    return stick_system_floor(
               n_, std::fabs(xi) + f_ * std::max({1.0, std::fabs(normal_.lambda), k1_.strength(), dk_.strength()})) /
           f_;
}

}  // namespace roughroll
