// SPDX-License-Identifier: GPL-3.0-or-later
// Gauss-Jacobi rules and Jacobi series for a stick zone's traction at full coupling (docs/formulation.md 8(v)).
// Near a stick zone's exit the traction behaves like (1 - t)^(1/2 - eps_out), near its entry like
// (1 + t)^(1/2 + eps_in) (8(l), the table of exponents; eps = atan(sigma beta_D f)/pi). Writing
//   q = w psi,   w(t) = (1 - t)^a (1 + t)^b,   psi = sum_j c_j P_j^(a,b)(t)
// carries them. Where a + b = 1 (one slip direction on both sides: the braked three zones) the identity
//   (1/pi) PV int w P_j^(a,b)/(tau - t) d tau - cot(pi a) w P_j^(a,b)(t) = -(2/sin(pi a)) P_{j+1}^(-a,-b)(t)
// (8(l) item 2) makes the node sum (1/pi) sum_k W_k psi(t_k)/(t_k - x_m), t_k the zeros of P_n^(a,b) with
// their weights W_k and x_m the n + 1 zeros of P_{n+1}^(-a,-b), equal to (H - cot(pi a))[w psi](x_m) for every
// psi of degree <= n - 1 (8(v)): the Gauss-Chebyshev collocation of section 3 is its case a = b = 1/2.
#pragma once

#include <memory>
#include <vector>

namespace roughroll {

// The three-term recurrence of P_j^(a,b) (DLMF 18.9.1-18.9.2) with its coefficients tabulated once,
// P_{j+1} = (A_j x + B_j) P_j - C_j P_{j-1} (P_0 = 1, P_1 = A_0 x + B_0): no division per term. Its coefficients are
// computed in one place (gauss_jacobi.cpp), which jacobi_values and jacobi_series use too: a series summed by either
// route gives the same bits. Up to `count` terms (P_0 .. P_count).
struct jacobi_recurrence {
    jacobi_recurrence(double a, double b, int count);
    double a, b;
    std::vector<double> A, B, C;
    void values(double x, int count, double* out) const;                  // P_0(x) .. P_{count-1}(x), count <= A.size() + 1
    double series(const std::vector<double>& c, double x) const;          // sum_j c_j P_j(x)
    double series_shifted(const std::vector<double>& c, double x) const;  // sum_j c_j P_{j+1}(x)
};

// Nodes and weights of sum_k W_k g(t_k) = int_{-1}^{1} (1 - t)^a (1 + t)^b g(t) dt, exact for deg g <= 2n - 1,
// by gsl_integration_fixed_jacobi (Golub-Welsch); nodes ascending. a, b > -1. With the recurrence of its P_j^(a,b)
// up to P_n (O(n), for jacobi_coefficients).
struct gauss_jacobi {
    gauss_jacobi(int n, double a, double b);

    int n;
    double a, b;
    jacobi_recurrence recurrence;
    std::vector<double> nodes;
    std::vector<double> weights;
};

// The collocation of (H - cot(pi a)) on the weight (1 - t)^a (1 + t)^(1 - a), 0 < a < 1 (8(v)): the rule of
// P_n^(a, 1-a) and the n + 1 collocation points, the zeros of P_{n+1}^(-a, a-1) (ascending).
struct jacobi_collocation {
    jacobi_collocation(int n, double a);
    explicit jacobi_collocation(const gauss_jacobi& rule);  // of a rule built already (b = 1 - a): copied, not rebuilt

    gauss_jacobi rule;
    std::vector<double> collocation;
};

// The Gauss-Jacobi rules of one solve, each built once and shared by whoever is handed the set: full coupling's
// braked three zones (8(v), 8(w)) need the rules of n and 4 n nodes of the weight (1 - t)^a (1 + t)^(1 - a) both in
// the tangential solver's Jacobi zone and in the pressure's weighted kinks, with the same n and a. A rule depends on
// (n, a, b) only, so the shared one is bit for bit the rule either would build. An explicit workspace (not thread
// safe: one per solve), keyed by the exact exponents.
class jacobi_rule_set {
public:
    std::shared_ptr<const gauss_jacobi> rule(int n, double a, double b);

private:
    std::vector<std::shared_ptr<const gauss_jacobi>> rules_;
};

// (1 - t)^a (1 + t)^b on [-1, 1].
double jacobi_weight(double a, double b, double t);

// P_0^(a,b)(x) .. P_{count-1}^(a,b)(x) into out, by the recurrence of jacobi_recurrence, its coefficients computed
// term by term (no table, no allocation); any real x.
void jacobi_values(double a, double b, double x, int count, double* out);

// sum_j c_j P_j^(a,b)(x), as jacobi_recurrence::series (no allocation).
double jacobi_series(const std::vector<double>& c, double a, double b, double x);

// The coefficients c_0..c_{n-1} of the degree n - 1 interpolant of `values` given at the rule's nodes:
// c_j = sum_k W_k v_k P_j(t_k) / h_j, h_j = sum_k W_k P_j(t_k)^2 (both exact: degree <= 2n - 2); P_j(t_k) by the
// rule's recurrence table, O(n) per node.
std::vector<double> jacobi_coefficients(const gauss_jacobi& rule, const std::vector<double>& values);

// (1/pi) int_{-1}^{1} w(tau) psi(tau)/(tau - x) d tau for |x| > 1, psi the series c on the rule's weight with
// a + b = 1 (8(v), "Off the zone"), psi_nodes its values at the rule's nodes. `far` is a rule of the same weight
// with more nodes (4 n), psi_far psi's values at its nodes, used where it is exact to rounding; nearer the zone
// the polynomial part by the rule itself and psi(x) C_0(x) in closed form. `table`: the recurrence of the rule's
// weight tabulated (jacobi_recurrence of a and b, at least c.size() terms), which sums psi(x) with the same bits as
// without it, only faster (pressure_kinks keeps one per zone); null: each coefficient computed.
double jacobi_cauchy_outside(const std::vector<double>& c, const gauss_jacobi& rule,
                             const std::vector<double>& psi_nodes, const gauss_jacobi& far,
                             const std::vector<double>& psi_far, double x, const jacobi_recurrence* table = nullptr);

}  // namespace roughroll
