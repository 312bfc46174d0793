// SPDX-License-Identifier: GPL-3.0-or-later
// The weight of (H - k(x)) with a piecewise constant or varying k, its Gauss rule and its exact collocation
// (docs/formulation.md 8(z)). H[g](x) = (1/pi) PV int g(t) dt/(t - x) on [-1, 1].
//
// Zones -1 = x_0 < x_1 < ... < x_M = 1, k = k_i on (x_{i-1}, x_i), k_i = cot(pi a_i), 0 < a_i < 1. With
// X(z) = (z + 1) exp(int a(t) dt/(t - z)) (Muskhelishvili, Singular integral equations, sections 78-79; DLMF 1.9 for
// the branches) the boundary values on the cut are X_+- = w e^{+- i pi a}, w = prod_j |x - x_j|^{e_j},
//   e_0 = 1 - a_1 (left edge),  e_j = a_j - a_{j+1} (zone end j),  e_M = a_M (right edge),
// and Plemelj gives, for every polynomial P, with the weight  w_k(x) = sin(pi a(x)) w(x) = w/sqrt(1 + k^2),
//   (H - k)[w_k P] = -Pi_P,   Pi_P the polynomial part of X(z) P(z) at infinity (degree deg P + 1),
// e.g. (H - k)[w_k] = -(x + 1 - mu_0), mu_0 = int a. So the n-point Gauss rule of w_k (nodes t_j, weights W_j) and the
// n + 1 zeros x_m of the degree n + 1 orthogonal polynomial of the dual weight w_d = sin(pi a)/w make
//   (1/pi) sum_j W_j psi(t_j)/(t_j - x_m) = (H - k)[w_k psi](x_m)     for deg psi <= n - 1, exactly (8(z)):
// the Gauss-Jacobi collocation of 8(v) is the case M = 1. The rules come from the weights' three-term recurrences by a
// discretised Stieltjes procedure (Gautschi, Orthogonal polynomials: computation and approximation, 2004, 2.2.3) on a
// measure of Gauss-Jacobi panels graded towards every zone end, then Golub-Welsch; the masses int w_k and int w_d have
// closed forms (8(z)) that check the discretisation at construction.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/gsl_handles.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/linear_system.hpp"

namespace roughroll {

// A weight c_i m(x) prod_j |x - x_j|^{e_j} on zone i of [-1, 1]: e_j > -1, c_i > 0, m > 0 continuous and analytic
// inside each zone (empty: m = 1). Where m is set its zone ends are where it may be only finitely smooth: the panels of
// the discretisation are graded towards them (to 2^-16 of the zone), towards every end, or only towards the ends
// flagged in `rough` (8(z), "The cost": m is analytic at an end both of whose zones have a constant k), and there only
// as deep as m needs (a panel's rule against its halves').
struct piecewise_power_weight {
    std::vector<double> ends;       // x_0 = -1 < ... < x_M = 1
    std::vector<double> exponents;  // e_0 .. e_M
    std::vector<double> factors;    // c_1 .. c_M (index i - 1)
    std::function<double(double)> smooth;
    std::vector<char> rough;        // empty, or one flag per end: m finitely smooth there (graded)

    double operator()(double x) const;  // 0 outside [-1, 1]; at an end x_j with e_j != 0: its limit (0 or inf)
    int zone_of(double x) const;        // 0 .. M - 1, the zone holding x (an interior end: the zone to its right)
};

// A memo's hash of a point x: its bits, mixed (std::hash<double> hashes its bytes; with it variable_k_weight's memo of m
// took a tenth of the wired free rolling point, session 24). -0 and +0 are equal keys: one hash.
struct double_bits_hash {
    std::size_t operator()(double x) const {
        std::uint64_t u = 0;
        if (x != 0.0) std::memcpy(&u, &x, sizeof u);
        return static_cast<std::size_t>((u * 0x9E3779B97F4A7C15ull) >> 32);
    }
};

// The monic recurrence pi_{j+1} = (x - alpha_j) pi_j - beta_j pi_{j-1}, beta_0 = int w (Gautschi's convention).
struct orthogonal_recurrence {
    std::vector<double> alpha, beta;
};

// alpha_0 .. alpha_{count-1}, beta_0 .. beta_{count-1} of a piecewise power weight, by the Stieltjes procedure on its
// discretisation by Gauss-Jacobi panels, each panel at most as long as its distance from every zone end that is not
// one of its own ends (the other factors are analytic there, within a Bernstein ellipse of parameter above 5.8). The
// inner products of degree <= 2 count - 1 are then those of the weight to rounding. `economical` (8(z), "The cost"):
// a panel [u, v] gets 24 + ceil(2 count (acos u - acos v)/pi) points (a polynomial of degree 2 count - 1 turns
// through that degree times the panel's Chebyshev angle there), rounded up to a multiple of 8, at most count + 24, and m is
// graded only towards the `rough` ends, halving the panel that touches one while its rule and its two halves' disagree
// by more than 1e-14 of its mass (in the mass and in the moment of T_{2 count - 1}; session 22); `dense`: count + 24
// points on every panel and m graded towards every zone end to 2^-16 of the zone (the construction of session 21, kept
// as the reference of tests/test_variable_k_weight_s21.cpp and _s22.cpp).
enum class discretisation { economical, dense };
orthogonal_recurrence recurrence_of(const piecewise_power_weight& w, int count,
                                    discretisation how = discretisation::economical);
// The number of discretisation points recurrence_of would use (the cost's measure; bench/variable_k_weight_cost.cpp).
std::size_t discretisation_size(const piecewise_power_weight& w, int count,
                                discretisation how = discretisation::economical);

// The n-point Gauss rule of a recurrence with at least n terms (Golub-Welsch by implicit QL, O(n^2)): nodes ascending.
struct gauss_rule {
    std::vector<double> nodes, weights;
};
gauss_rule gauss_rule_of(const orthogonal_recurrence& r, int n);

// The weight of (H - k) for a piecewise constant k (above), or for a k that varies smoothly inside some zones (8(z),
// "A varying k"): there a = a_pc + a_c, a_pc piecewise constant with a's jumps, a_c continuous with a_c(-1) = 0, and
//   w = (1 - x)^{a(1)} (1 + x)^{1 - a(-1)} prod_{0<j<M} |x - x_j|^{a(x_j-) - a(x_j+)} m(x),
//   m = (1 - x)^{a_c(x) - a_c(1)} (1 + x)^{-a_c(x)} exp(I_c(x)),  I_c(x) = int (a_c(t) - a_c(x))/(t - x) dt  (bounded;
//   closed form on the zones of constant k, graded Gauss-Legendre panels where k varies, with product integration on
//   a_c's interpolant on the panels near x: 8(z), "The cost").
class variable_k_weight {
public:
    // ends: x_0 = -1 < x_1 < ... < x_M = 1; k: M finite values.
    variable_k_weight(std::vector<double> ends, std::vector<double> k);
    // The same with k_i(x) = varying[i](x) on the zones whose entry is set (smooth on the closed zone); k[i] unused there.
    variable_k_weight(std::vector<double> ends, std::vector<double> k,
                      std::vector<std::function<double(double)>> varying);

    const std::vector<double>& ends() const { return weight_.ends; }
    const std::vector<double>& k() const { return k_; }
    const std::vector<double>& a() const { return a_; }  // a_i = 1/2 - atan(k_i)/pi
    // The exponents e_0 .. e_M of w at the zone ends (8(z)): the weight's local powers, as 8(l)'s table has them.
    const std::vector<double>& exponents() const { return weight_.exponents; }
    const piecewise_power_weight& weight() const { return weight_; }  // w_k = sin(pi a) w
    const piecewise_power_weight& dual() const { return dual_; }      // w_d = sin(pi a)/w

    double operator()(double x) const { return weight_(x); }
    double k_at(double x) const;
    double a_at(double x) const { return 0.5 - std::atan(k_at(x)) / M_PI; }
    double mu0() const { return mu0_; }  // int a
    double mu1() const { return mu1_; }  // int a t
    // int w_k = pi (mu_0 + mu_1 - mu_0^2/2) (8(z): X's expansion at infinity); int w_d = pi.
    double mass() const;
    // (H - k)[w_k](x) = -(x + 1 - mu_0) (8(z)); H[w_k](x) = k(x) w_k(x) - (x + 1 - mu_0) inside, off the zone ends.
    double hilbert_of_weight(double x) const;
    // I_c(x) = int (a_c(t) - a_c(x))/(t - x) dt (above; 0 where k is constant everywhere) as m uses it: the cached
    // panels' Gauss-Legendre sums, and product integration on a_c's Legendre interpolant on the panels nearer x than
    // their length (8(z), "The cost"). `i_c_by_quadrature`: session 21's route (the panels near x halved towards it with
    // a_c evaluated afresh), the reference of tests/test_variable_k_weight_s22.cpp.
    double i_c(double x) const;
    double i_c_by_quadrature(double x) const;

private:
    std::vector<double> k_, a_;  // a_: a on each zone at its left end
    std::vector<std::function<double(double)>> varying_;
    std::vector<double> a_pc_;  // the piecewise constant part where k varies
    double a_c_right_ = 0.0;    // a_c(1)
    piecewise_power_weight weight_, dual_;
    double mu0_ = 0.0, mu1_ = 0.0;
    // a_c on zone i as (1/2 - a_pc) - atan(k)/pi: rounded to |a_c| ~ k/pi, not to a ~ 1/2 (product integration's
    // interpolant amplifies that noise, 8(z) "The cost"); a constant offset cancels in I_c.
    std::vector<double> a_c_offset_;  // 1/2 - a_pc per zone
    double a_c_on(std::size_t i, double x) const {
        return varying_[i] ? a_c_offset_[i] - std::atan(varying_[i](x)) / M_PI : a_[i] - a_pc_[i];
    }
    double a_c(double x) const { return a_c_on(static_cast<std::size_t>(weight_.zone_of(x)), x); }
    double m_of(double x) const;  // m(x) above
    struct factors {
        double sine, m;  // sin(pi a(x)), m(x)
    };
    factors factors_at(double x) const;  // memoised (memo_; not thread safe, as the workspace below)
    mutable std::unordered_map<double, factors, double_bits_hash> memo_;
    double i_c_at(double x, double ax) const;  // I_c(x) with ax = a_c(x)
    struct panel_set {                  // 20-point Gauss-Legendre panels, a_c cached at their nodes
        std::vector<double> u, v;       // the panels
        std::vector<double> t, w, a;    // nodes, weights, a_c(t) (20 per panel)
        std::vector<double> c;          // a_c's Legendre coefficients on each panel (20 per panel): product integration
    };
    struct zone_rule {                  // where k varies: panels graded to 2^-4 of the zone towards its ends (the sums),
        panel_set coarse, fine;         // and each again: the end panels graded to 2^-16, the others quartered (for x
        std::vector<std::size_t> fine_begin, fine_end;  // near them: product integration); per coarse panel, its fine
    };
    std::vector<zone_rule> rules_;      // per zone, empty where k is constant
    double panel_part(const panel_set& s, std::size_t p, double x, double ax) const;
    void build_rules();
    integration_workspace_ptr workspace_;  // QAGS's, for mu_0 and mu_1 where k varies (not thread safe)
    struct fixed_rule {                    // n-point Gauss-Legendre on [-1, 1]
        int n = 0;
        std::vector<double> nodes, weights;
    };
    fixed_rule legendre_;                  // the panels' rule of I_c
    std::vector<double> transform_;        // its values -> Legendre coefficients (20 x 20)

public:
    // The weights hold this object's address (m where k varies): not copied, not moved.
    variable_k_weight(const variable_k_weight&) = delete;
    variable_k_weight& operator=(const variable_k_weight&) = delete;
};

// The collocation of (H - k)[w_k psi] - xi = g (8(z)) with psi by its values psi_j at the n nodes of w_k's Gauss rule,
// collocated at the n + 1 zeros of the dual weight's orthogonal polynomial of degree n + 1. The matrix depends on the
// weight and n only: factorised once (a workspace per collocation, not thread safe), each right side two triangular
// solves. `solve`: the n + 1 unknowns psi_j, xi (the solvability constant of the bounded solution, index -1).
// `solve_loaded`: (H - k)[w_k psi] - xi - lambda h = g with the side condition int w_k psi = load (the pressure's form
// of (D1), h = x: lambda and the load), n + 2 unknowns psi_j, xi, lambda.
class variable_k_collocation {
public:
    // Keeps a reference to `weight`, which must outlive it.
    variable_k_collocation(const variable_k_weight& weight, int n, discretisation how = discretisation::economical);

    int n() const { return n_; }
    const gauss_rule& rule() const { return rule_; }
    const std::vector<double>& points() const { return points_; }  // n + 1, ascending
    const orthogonal_recurrence& recurrence() const { return recurrence_; }
    // max_m |D(x_m)|, D(x) = (H - k)[w_k](x) - (1/pi) sum_j W_j/(t_j - x): zero at the points in exact arithmetic (8(z));
    // the constructor refuses (numerical_error) above 1e-9 of max(1, max_m |x_m + 1 - mu_0|).
    double point_defect() const { return defect_; }

    struct solution {
        std::vector<double> psi;  // at the nodes
        double xi = 0.0, lambda = 0.0;
        // solve_loaded: the a posteriori bound on lambda's rounding (dense_system::rounding_bound; 8(w), "The solve's
        // rounding, a posteriori"); 0 from solve.
        double lambda_rounding = 0.0;
    };
    solution solve(const std::vector<double>& g_at_points);
    solution solve_loaded(const std::vector<double>& g_at_points, const std::vector<double>& h_at_points, double load);

    // psi(x) of the degree n - 1 interpolant of values at the nodes, through the orthonormal polynomials (any real x).
    double interpolate(const std::vector<double>& psi, double x) const;
    // H[w_k psi](x) for |x| < 1 not a node: the node sum plus psi(x) D(x) (exact for deg psi <= n - 1).
    double hilbert(const std::vector<double>& psi, double x) const;
    double load(const std::vector<double>& psi) const;  // int w_k psi = sum_j W_j psi_j
    double rcond() const;  // of the last solve's LU (0 before any)
    // interpolate() in two parts (the wired pressure's, 8(z)): the orthonormal coefficients once (O(n^2)), then O(n) per x.
    std::vector<double> coefficients(const std::vector<double>& psi) const;
    double series(const std::vector<double>& c, double x) const;  // c from coefficients()

private:
    const variable_k_weight& weight_;
    int n_;
    orthogonal_recurrence recurrence_;
    gauss_rule rule_;
    std::vector<double> points_;
    double defect_ = 0.0;
    std::unique_ptr<dense_system> plain_, loaded_;
    std::vector<double> loaded_h_;  // the h the loaded system was factorised with
    std::vector<double> root_beta_;  // sqrt(beta_j) of the recurrence, for series()
    void assemble(gsl_matrix* m) const;
};

}  // namespace roughroll
