// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/one_parameter.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/model/dissimilar.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

namespace {
// sum_j b_j T_{j+1}(x) for |x| <= 1, by Clenshaw's recurrence on a_k = b_{k-1}, a_0 = 0.
// It is minus the Cauchy transform (1/pi) int sqrt(1-t^2) sum b_j U_j(t)/(t - x) dt
// (docs/formulation.md Section 3), and defined at x = +-1 too.
double t_series_shifted(const std::vector<double>& b, double x) {
    double y1 = 0.0, y2 = 0.0;
    for (std::size_t k = b.size(); k >= 1; --k) {
        const double y = b[k - 1] + 2.0 * x * y1 - y2;
        y2 = y1;
        y1 = y;
    }
    return x * y1 - y2;
}

void add_compliance(double& eps, const roughness_term& term, const char* what) {
    if (!term.present()) return;
    if (!(std::isfinite(term.T) && std::isfinite(term.A) && term.T > 0.0 && term.A >= 0.0)) {
        std::ostringstream msg;
        msg << what << ": T = " << shortest(term.T) << ", A = " << shortest(term.A) << " must be finite, T > 0, A >= 0";
        throw input_error(msg.str());
    }
    if (term.A == 0.0) {
        std::ostringstream msg;
        msg << what << ": T = " << shortest(term.T) << " with A = 0 has no one-parameter limit (2T/A^2 is infinite: "
            << "the kernel T sgn z does not decay); use method 'product' or 'extrapolated'";
        throw input_error(msg.str());
    }
    eps += 2.0 * term.T / (term.A * term.A);  // docs/formulation.md 2(c), "The one-parameter limit"
    if (!std::isfinite(eps)) throw input_error(std::string(what) + ": the compliance 2T/A^2 is not finite");
}
}  // namespace

compliances one_parameter_compliances(const roughness& r) {
    compliances eps;
    add_compliance(eps.tangential, r.cylinder1.tangential, "cylinder 1, tangential roughness");
    add_compliance(eps.tangential, r.cylinder2.tangential, "cylinder 2, tangential roughness");
    add_compliance(eps.normal, r.cylinder1.normal, "cylinder 1, normal roughness");
    add_compliance(eps.normal, r.cylinder2.normal, "cylinder 2, normal roughness");
    return eps;
}

normal_solution one_parameter_normal(double eps2, int n) {
    if (!(std::isfinite(eps2) && eps2 >= 0.0)) throw input_error("the normal compliance eps2 must be finite and >= 0");
    gsl_guard();
    gauss_chebyshev rule(n);  // throws input_error outside [min_nodes, max_nodes]
    // "The one-parameter limit", normal problem: gamma + H[p] + eps2 p' + (2/pi) lambda r = 0, with
    // H[sin((j+1) theta)] = -cos((j+1) theta) and d/dr sin((j+1) theta) = -(j+1) cos((j+1) theta)/sin theta,
    // multiplied by -sin theta at the points theta_m = (m + 1/2) pi/(n + 1) of (4.7):
    //   sum_j b_j cos((j+1) theta_m) [sin theta_m + eps2 (j+1)] - gamma sin theta_m
    //     - (2/pi) lambda cos theta_m sin theta_m = 0,     (pi/2) b_0 = int p = 1   (3.20).
    // Columns 0..n-1: b_j; n: gamma_0n (zero by symmetry, (4.8)); n+1: lambda.
    dense_system system(static_cast<std::size_t>(n) + 2);
    system.clear();
    gsl_matrix* a = system.matrix();
    gsl_vector* rhs = system.rhs();
    for (int m = 0; m <= n; ++m) {
        const double theta = (m + 0.5) * M_PI / (n + 1), sin_m = std::sin(theta);
        for (int j = 0; j < n; ++j) gsl_matrix_set(a, m, j, std::cos((j + 1) * theta) * (sin_m + eps2 * (j + 1)));
        gsl_matrix_set(a, m, n, -sin_m);
        gsl_matrix_set(a, m, n + 1, -M_2_PI * rule.collocation[m] * sin_m);
    }
    gsl_matrix_set(a, n + 1, 0, M_PI_2);
    gsl_vector_set(rhs, n + 1, 1.0);
    const gsl_vector* x = system.solve("one-parameter normal problem");
    std::vector<double> b(n);
    for (int j = 0; j < n; ++j) b[j] = gsl_vector_get(x, j);
    std::vector<double> phi(n);
    for (int k = 0; k < n; ++k) phi[k] = u_series(b, rule.nodes[k]);
    return normal_solution{std::move(rule),
                           method::one_parameter,
                           std::move(phi),
                           std::move(b),
                           gsl_vector_get(x, n + 1),
                           gsl_vector_get(x, n),
                           system.rcond(),
                           nullptr,
                           {},
                           0.0,
                           nullptr};
}

one_parameter_solver::one_parameter_solver(const compliances& eps, double f, int n, double beta_d)
    : tangential_problem(f, n, beta_d, false, "one-parameter tangential problem", "one-parameter Brent search for c0"),
      eps_(eps),
      tangential_system_((check_node_count(n), static_cast<std::size_t>(n) + 1)),
      normal_(one_parameter_normal(eps.normal, n)) {
    if (!(std::isfinite(eps.tangential) && eps.tangential >= 0.0))
        throw input_error("the tangential compliance eps1 must be finite and >= 0");
    check_beta_d(beta_d);
    // 8(s): a stick zone reaches a contact edge only because eps1 q' governs the traction there; without a
    // tangential layer the edges slip as for half-spaces (8(g)), a structure this limit does not build.
    if (beta_d != 0.0 && eps.tangential == 0.0)
        throw input_error("method 'one-parameter' with beta_d != 0 needs a tangential layer (eps1 > 0): without one "
                          "the contact edges slip as for half-spaces (docs/formulation.md 8(g), 8(s)); use method "
                          "'product' or 'extrapolated'");
    // The c0-independent parts of the stick equation's rows: sin phi_m and cos((j+1) phi_m).
    sin_.resize(n_ + 1);
    cos_.resize(static_cast<std::size_t>(n_ + 1) * n_);
    for (int m = 0; m <= n_; ++m) {
        const double phi = (m + 0.5) * M_PI / (n_ + 1);
        sin_[m] = std::sin(phi);
        for (int j = 0; j < n_; ++j) cos_[static_cast<std::size_t>(m) * n_ + j] = std::cos((j + 1) * phi);
    }
}

double one_parameter_solver::pressure_slope(double r) const {
    if (eps_.normal == 0.0) {
        // Hertz, p = (2/pi) sqrt(1 - r^2) (the solver's b is (2/pi, 0, ...) exactly): infinite at +-1.
        return -M_2_PI * r / std::sqrt(std::max(0.0, 1.0 - r * r));
    }
    // From the normal equation itself: eps2 p' = -(2/pi) lambda r - gamma - H[p], H[p] = -sum b_j T_{j+1}.
    // Bounded on [-1, 1], and at the collocation points the derivative of the series exactly, so that
    // the tangential problem at c0 = 1 is solved by q = -f p (Q(1) = 0 to rounding).
    return (-M_2_PI * normal_.lambda * r - normal_.gamma + t_series_shifted(normal_.b, r)) / eps_.normal;
}

double one_parameter_solver::G(double r) const {
    // (3.25) in the limit: int p (K2* - K1*)(eta - r) d eta -> (eps2 - eps1) p'(r).
    const double linear = M_2_PI * normal_.lambda * r;
    if (eps_.normal == eps_.tangential) return linear;
    return linear + (eps_.normal - eps_.tangential) * pressure_slope(r);
}

double one_parameter_solver::sliding_velocity(double forcing, double r) const {
    return forcing == 0.0 ? f_ * G(r) : forcing * normal_.pressure(r) + f_ * G(r);  // 8(s), as 8(g)
}

tangential_solution one_parameter_solver::solve_on_zone(double start, double c0, double forcing) {
    // "The one-parameter limit", stick equation: H[q] + (eps1/rho) q'(t) = xi + b p(r(t)) + f G(r(t)) with
    // q = sum_j c_j sin((j+1) phi), t = cos phi, multiplied by -sin phi at the points of (4.7):
    //   sum_j c_j cos((j+1) phi_m) [sin phi_m + (eps1/rho)(j+1)] + xi sin phi_m = -(b p(r_m) + f G(r_m)) sin phi_m,
    // on the stick zone [start, c0], r = start + rho (t + 1) (docs/formulation.md 7(g); the
    // paper's zone is start = -1, E4); b is Dundurs' forcing of the |Q| problem (8(s), (D2) at Johnson's level).
    const double rho = 0.5 * (c0 - start);
    const double stiffness = eps_.tangential / rho;
    gsl_matrix* a = tangential_system_.matrix();
    gsl_vector* rhs = tangential_system_.rhs();
    for (int m = 0; m <= n_; ++m) {
        for (int j = 0; j < n_; ++j)
            gsl_matrix_set(a, m, j, cos_[static_cast<std::size_t>(m) * n_ + j] * (sin_[m] + stiffness * (j + 1)));
        gsl_matrix_set(a, m, n_, sin_[m]);
        const double r = start + rho * (normal_.rule.collocation[m] + 1.0);  // E4
        gsl_vector_set(rhs, m, -sliding_velocity(forcing, r) * sin_[m]);     // E5, 8(s)
    }
    std::ostringstream context;
    context.precision(17);
    context << "one-parameter tangential problem on the stick zone [" << start << ", " << c0 << "]";
    const gsl_vector* x = tangential_system_.solve(context.str());
    std::vector<double> psi_b(n_);
    for (int j = 0; j < n_; ++j) psi_b[j] = gsl_vector_get(x, j);
    const double Q = f_ + rho * M_PI_2 * psi_b[0];  // (3.22): rho int q = Q - f, int q = (pi/2) c_0
    return zone_solution(f_, start, c0, gsl_vector_get(x, n_), Q, std::move(psi_b), tangential_system_.rcond(),
                         forcing);
}

tangential_solution one_parameter_solver::full_stick(double forcing) {
    // q = -f p, xi = 0 (H[p] + eps1 p' = -G on the whole contact), as for tangential_solver. With
    // Dundurs' forcing the stick traction is p1 = f p + q, odd (8(s): H + eps1 d/dr maps odd onto even
    // functions and b p is even), so Q = 0 again, from the system on the whole contact.
    if (forcing == 0.0) return tangential_problem::full_stick(forcing);
    tangential_solution s = solve_on_zone(-1.0, 1.0, forcing);
    s.Q = 0.0;  // int p1 = 0 by parity; the sum f + (pi/2) c_0 is that to rounding
    return s;
}

tangential_solution one_parameter_solver::gross_sliding(double forcing) {
    // G(-1) first: with eps2 = 0 < eps1 it is -infinity for either form of gross sliding, which the least point's
    // samples would call a numerical fault.
    if (!std::isfinite(G(-1.0)))
        throw input_error(
            "one-parameter model with eps2 = 0 < eps1: the creep at the onset of gross sliding "
            "(|Q| = f) is unbounded (Hertz's pressure slope is infinite at r = -1); a load |Q| < f has a finite one");
    return tangential_problem::gross_sliding(forcing);
}

std::vector<double> one_parameter_solver::G(const std::vector<double>& r) {
    std::vector<double> g(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) g[i] = G(r[i]);
    return g;
}

std::vector<double> one_parameter_solver::slip_velocity_magnitude(const tangential_solution& s,
                                                                  const std::vector<double>& r) {
    // (3.6) in the limit: v = xi - (H[p1] + eps1 p1') with p1 = f p + q. On the slip zone p1 = f p, and
    // H[p] + eps1 p' = -G by the normal equation, so v = xi + f G(r) - H[q](r), H[q] outside the stick
    // interval (|t| > 1: cauchy_u_series, no principal value; t < -1 on a slip zone [-1, start)); plus
    // Dundurs' b p of (D2) (8(s)).
    const double rho = s.rho();
    std::vector<double> v(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
        const double hq =
            s.psi_b.empty() || rho == 0.0 ? 0.0 : cauchy_u_series(s.psi_b, (r[i] - s.start()) / rho - 1.0);
        v[i] = s.sign * s.xi + sliding_velocity(s.forcing, r[i]) - hq;
    }
    return v;
}

double one_parameter_solver::check_rounding(const tangential_solution& s) {
    // (3.3) to the rounding of the collocation solution, as tangential_solver::rounding: the terms of
    // the right-hand side xi + f G, of size |xi| + f max(1, P_H/P2), cancel to q; (3.4) likewise.
    // Dundurs' b p adds |b| max p to that size (8(s); p is even and largest at r = 0).
    const double size =
        std::fabs(s.xi) + f_ * std::max(1.0, std::fabs(normal_.lambda)) + std::fabs(s.forcing) * normal_.pressure(0.0);
    return stick_system_floor(n_, size) / f_;
}

}  // namespace roughroll
