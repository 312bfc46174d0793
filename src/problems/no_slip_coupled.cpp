// SPDX-License-Identifier: GPL-3.0-or-later
// The no-slip limit at full coupling: docs/formulation.md 8(p) (smooth, closed form) and 8(t) (the polynomial
// identity of the fundamental function and the collocation with layers). Equations in the header.
#include "roughroll/problems/no_slip_coupled.hpp"

#include <cfloat>
#include <cmath>
#include <string>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/model/dissimilar.hpp"
#include "roughroll/numerics/chebyshev_projection.hpp"
#include "roughroll/numerics/linear_system.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

namespace {

using cplx = std::complex<double>;

// gamma_m of G(u) = ((1 + u)/(1 - u))^(2 i eps): (1 - u^2) G' = 4 i eps G (8(t)).
std::vector<cplx> joukowski_gammas(double epsilon, int count) {
    std::vector<cplx> g(static_cast<std::size_t>(count) + 1, cplx(0.0));
    g[0] = 1.0;
    if (count >= 1) g[1] = cplx(0.0, 4.0 * epsilon);
    for (int m = 1; m < count; ++m)
        g[m + 1] = (cplx(0.0, 4.0 * epsilon) * g[m] + static_cast<double>(m - 1) * g[m - 1]) / static_cast<double>(m + 1);
    return g;
}

// The Laurent coefficients y_k of X T_j in u (8(t)) and from them R_{T_j} (coefficients of T_0 .. T_{j+1}) and int w T_j.
struct fundamental_images {
    std::vector<std::vector<cplx>> r;  // r[j][k]: T_k's coefficient in R_{T_j}
    std::vector<cplx> load;            // int_{-1}^1 w T_j
};

fundamental_images images_of(double epsilon, int n) {
    const std::vector<cplx> g = joukowski_gammas(epsilon, 2 * n + 8);
    const auto gamma = [&g](int m) { return m < 0 ? cplx(0.0) : g[static_cast<std::size_t>(m)]; };
    const auto y = [&gamma](int k, int j) {
        return 0.25 * (gamma(k + j + 1) + gamma(k - j + 1) - gamma(k + j - 1) - gamma(k - j - 1));
    };
    const double ch = std::cosh(M_PI * epsilon);
    fundamental_images out;
    for (int j = 0; j <= n; ++j) {
        std::vector<cplx> rj(static_cast<std::size_t>(j) + 2);
        rj[0] = y(0, j);
        for (int k = 1; k <= j + 1; ++k) rj[static_cast<std::size_t>(k)] = 2.0 * y(-k, j);
        out.r.push_back(std::move(rj));
        out.load.push_back(-M_PI * (y(1, j) - y(-1, j)) / (2.0 * ch));
    }
    return out;
}

// w(r) = sqrt((1 + r)(1 - r)) exp(i eps log((1 + r)/(1 - r))) from the distances to the edges (no cancellation near them).
cplx fundamental_w(double epsilon, double plus, double minus) {
    if (!(plus > 0.0 && minus > 0.0)) return 0.0;
    return std::sqrt(plus * minus) * std::polar(1.0, epsilon * (std::log(plus) - std::log(minus)));
}

// Tanh-sinh nodes on [a, b]: x = tanh((pi/2) sinh t), t = k h, |t| <= 4.5, h = 1/32 (8(t): the edges' complex powers are
// integrable end singularities; halving h or widening t changed no digit of lambda or xi).
struct ts_node {
    double from_a, to_b, weight;  // eta - a, b - eta, the weight on [a, b]
};

std::vector<ts_node> ts_nodes(double a, double b) {
    constexpr double h = 1.0 / 32.0, t_max = 4.5;
    std::vector<ts_node> nodes;
    const int count = static_cast<int>(t_max / h);
    for (int k = -count; k <= count; ++k) {
        const double t = k * h, u = M_PI_2 * std::sinh(t);
        const double c = std::cosh(u);
        const double weight = h * M_PI_2 * std::cosh(t) / (c * c) * (b - a) / 2.0;
        const double plus = 2.0 / (1.0 + std::exp(-2.0 * u)), minus = 2.0 / (1.0 + std::exp(2.0 * u));  // 1 + x, 1 - x
        if (weight > 0.0) nodes.push_back({(b - a) * plus / 2.0, (b - a) * minus / 2.0, weight});
    }
    return nodes;
}

// T_0 .. T_count at x.
void chebyshev_values(double x, int count, std::vector<double>& t) {
    t.assign(static_cast<std::size_t>(count) + 1, 0.0);
    t[0] = 1.0;
    if (count >= 1) t[1] = x;
    for (int k = 1; k < count; ++k) t[k + 1] = 2.0 * x * t[k] - t[k - 1];
}

// int_{-1}^1 w(eta) T_j(eta) K(eta - r) d eta for j = 0 .. n, both kernels at once (8(t)); split at the kernel's jump.
void layer_images(double epsilon, double r, int n, const kernel& k1, const kernel& k2, std::vector<cplx>& i1,
                  std::vector<cplx>& i2) {
    i1.assign(static_cast<std::size_t>(n) + 1, 0.0);
    i2.assign(static_cast<std::size_t>(n) + 1, 0.0);
    std::vector<double> t;
    for (const bool left : {true, false}) {
        const double a = left ? -1.0 : r, b = left ? r : 1.0;
        for (const ts_node& node : ts_nodes(a, b)) {
            // 1 + eta, 1 - eta and eta - r from the distances to the piece's ends.
            const double plus = left ? node.from_a : 1.0 + r + node.from_a;
            const double minus = left ? 1.0 - r + node.to_b : node.to_b;
            const double z = left ? -node.to_b : node.from_a;
            if (z == 0.0) continue;  // the kernel's jump, a set of measure zero
            const cplx w = fundamental_w(epsilon, plus, minus) * node.weight;
            if (w == 0.0) continue;
            chebyshev_values(left ? -1.0 + plus : 1.0 - minus, n, t);
            const cplx w1 = k1.empty() ? cplx(0.0) : w * k1(z), w2 = k2.empty() ? cplx(0.0) : w * k2(z);
            for (int j = 0; j <= n; ++j) {
                i1[static_cast<std::size_t>(j)] += w1 * t[static_cast<std::size_t>(j)];
                i2[static_cast<std::size_t>(j)] += w2 * t[static_cast<std::size_t>(j)];
            }
        }
    }
}

}  // namespace

double bufler_epsilon(double beta_d) { return std::log((1.0 - beta_d) / (1.0 + beta_d)) / (2.0 * M_PI); }

namespace {
// sum phi_j T_j(r) by numerics/chebyshev_projection's Clenshaw sum, on the real and imaginary parts.
cplx complex_chebyshev_sum(const std::vector<cplx>& phi, double r) {
    std::vector<double> re(phi.size()), im(phi.size());
    for (std::size_t j = 0; j < phi.size(); ++j) {
        re[j] = phi[j].real();
        im[j] = phi[j].imag();
    }
    return {chebyshev_sum(re, r), chebyshev_sum(im, r)};
}
}  // namespace

cplx no_slip_coupled_solution::F(double r) const {
    if (!(std::fabs(r) < 1.0)) return 0.0;
    return fundamental_w(epsilon, 1.0 + r, 1.0 - r) * complex_chebyshev_sum(phi, r);
}

cplx no_slip_coupled_solution::F_near_leading_edge(double x) const {
    return fundamental_w(epsilon, x, 2.0 - x) * complex_chebyshev_sum(phi, -1.0 + x);
}

double no_slip_coupled_solution::crossing(double f) const {
    if (!(f > 0.0 && std::isfinite(f))) throw input_error("the crossing of the no-slip limit needs a friction f > 0");
    // g = |p1| - f p at r = -1 + x, in u = log x: negative at the centre (p1 = 0), positive once |p1|/p passes f, and
    // then through the zone where p < 0 (8(p), "The edges"), whose length in u is pi/|eps|: a scan from the centre in
    // steps of 1/4 cannot pass it; bisection in u to rounding.
    const auto g = [this, f](double u) {
        const cplx v = F_near_leading_edge(std::exp(u));
        return std::fabs(v.imag()) - f * v.real();
    };
    const double u_min = std::log(1e-300);
    double inside = 0.0, outside = inside;
    for (;;) {
        outside = inside - 0.25;
        if (outside < u_min) return 0.0;
        if (g(outside) >= 0.0) break;
        inside = outside;
    }
    for (int i = 0; i < 200 && inside - outside > 4.0 * DBL_EPSILON * std::fabs(outside); ++i) {
        const double mid = 0.5 * (inside + outside);
        (g(mid) >= 0.0 ? outside : inside) = mid;
    }
    return std::exp(0.5 * (inside + outside));
}

no_slip_coupled_solution no_slip_coupled(double beta_d, const kernel& tangential, const kernel& normal, int n) {
    check_beta_d(beta_d);
    if (beta_d == 0.0)
        throw input_error("full coupling: beta_d = 0 is the uncoupled problem (docs/formulation.md 8(d))");
    if (n < 0 || n > 1000) throw input_error("no-slip limit at full coupling: n = " + std::to_string(n) + " must be 0 .. 1000");
    const double epsilon = bufler_epsilon(beta_d), ch = std::cosh(M_PI * epsilon);
    const fundamental_images images = images_of(epsilon, n);
    const bool layers = !tangential.empty() || !normal.empty();

    // Unknowns: Re c_0..c_n, Im c_0..c_n, lambda e, xi (lambda = 1); rows: the real and imaginary parts at the n + 2
    // zeros of T_{n+2} (8(t)).
    const int m_count = n + 2, c_count = n + 1;
    dense_system system(static_cast<std::size_t>(2 * m_count));
    gsl_matrix* A = system.matrix();
    gsl_vector* b = system.rhs();
    gsl_matrix_set_zero(A);
    std::vector<double> t;
    std::vector<cplx> i1, i2;
    for (int m = 0; m < m_count; ++m) {
        const double r = std::cos((2.0 * m + 1.0) * M_PI / (2.0 * m_count));
        chebyshev_values(r, n + 1, t);
        if (layers) layer_images(epsilon, r, n, tangential, normal, i1, i2);
        const std::size_t re = static_cast<std::size_t>(m), im = static_cast<std::size_t>(m_count + m);
        for (int j = 0; j < c_count; ++j) {
            cplx rj = 0.0;  // R_{T_j}(r)
            const std::vector<cplx>& coefficients = images.r[static_cast<std::size_t>(j)];
            for (std::size_t k = 0; k < coefficients.size(); ++k) rj += coefficients[k] * t[k];
            const cplx k2j = layers ? i2[static_cast<std::size_t>(j)] : cplx(0.0);
            const cplx k1j = layers ? i1[static_cast<std::size_t>(j)] : cplx(0.0);
            const std::size_t a_col = static_cast<std::size_t>(j), b_col = static_cast<std::size_t>(c_count + j);
            // c_j = a + i b: Re(-c R/ch) + K2[Re(c w T_j)]  and  Im(-c R/ch) + K1[Im(c w T_j)].
            gsl_matrix_set(A, re, a_col, -rj.real() / ch + k2j.real());
            gsl_matrix_set(A, re, b_col, rj.imag() / ch - k2j.imag());
            gsl_matrix_set(A, im, a_col, -rj.imag() / ch + k1j.imag());
            gsl_matrix_set(A, im, b_col, -rj.real() / ch + k1j.real());
        }
        gsl_matrix_set(A, re, static_cast<std::size_t>(2 * c_count), 2.0 / M_PI);  // lambda e
        gsl_matrix_set(A, im, static_cast<std::size_t>(2 * c_count + 1), 1.0);     // xi
        gsl_vector_set(b, re, -2.0 / M_PI * r);
        gsl_vector_set(b, im, 0.0);
    }
    const gsl_vector* x = system.solve("no-slip limit at full coupling (docs/formulation.md 8(t))");

    no_slip_coupled_solution s;
    s.beta_d = beta_d;
    s.epsilon = epsilon;
    cplx load = 0.0;
    for (int j = 0; j < c_count; ++j) {
        const cplx c(gsl_vector_get(x, static_cast<std::size_t>(j)), gsl_vector_get(x, static_cast<std::size_t>(c_count + j)));
        s.phi.push_back(c);
        load += c * images.load[static_cast<std::size_t>(j)];
    }
    // int p = Re(int F) = 1 fixes the scale: lambda = 1/int p at lambda = 1 (the problem is linear in (F, lambda, xi)).
    const double p_load = load.real();
    if (!(std::isfinite(p_load) && p_load > 0.0))
        throw numerical_error("no-slip limit at full coupling: the pressure carries no load (docs/formulation.md 8(t))");
    for (cplx& c : s.phi) c /= p_load;
    s.load_ratio = 1.0 / p_load;
    s.offset = gsl_vector_get(x, static_cast<std::size_t>(2 * c_count));  // lambda e at lambda = 1 is e
    s.xi = gsl_vector_get(x, static_cast<std::size_t>(2 * c_count + 1)) / p_load;
    s.tangential_load = -load.imag() / p_load;
    return s;
}

normal_solution no_slip_normal(const no_slip_coupled_solution& limit, int n, method how) {
    gauss_chebyshev rule(n);
    std::vector<double> phi(static_cast<std::size_t>(n));
    // (4.1): p = phi sqrt(1 - r^2), sqrt(1 - r^2) from (1 - r)(1 + r) (no cancellation near the edges).
    for (int k = 0; k < n; ++k) {
        const double r = rule.nodes[static_cast<std::size_t>(k)];
        phi[static_cast<std::size_t>(k)] = limit.pressure(r) / std::sqrt((1.0 - r) * (1.0 + r));
    }
    std::vector<double> b = u_coefficients(rule, phi);
    const double lambda = limit.load_ratio, e = limit.offset;
    // (D1)'s traction term beta_D p1 of this pressure (normal_solution::tangential_term); the limit copied, not referred to.
    std::function<double(double)> term = [limit](double r) { return limit.beta_d * limit.traction(r); };
    return {std::move(rule), how,     std::move(phi), std::move(b), lambda, M_2_PI * lambda * e, 1.0, nullptr,
            std::move(term), e,       nullptr};
}

}  // namespace roughroll
