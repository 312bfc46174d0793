// SPDX-License-Identifier: GPL-3.0-or-later
// The one-parameter (Winkler-layer) model of the paper's reference [2]: the limit
// t^(i) -> 0 of the two-parameter model, T, A -> infinity with 2T/A^2 fixed
// (docs/formulation.md, "The one-parameter limit"). Each kernel term acting on a smooth p
// tends to (2T/A^2) p', so with the compliances
//   eps_i = sum over the cylinders of 2 T_beta^(i) / (A_beta^(i))^2   (i = 1 tangential, 2 normal)
// the consistent problem becomes singular integro-differential:
//   normal:     (1/pi) int p(eta)/(eta - r) d eta + eps2 p'(r) = -(2/pi) lambda r,  int p = 1
//   tangential: (1/pi) int q(tau)/(tau - t) d tau + (eps1/rho) q'(t) = xi + f G(r(t)),
//               rho int q = Q - f,  G(r) = (2/pi) lambda r + (eps2 - eps1) p'(r),
// on the stick zone [-1, c0], r = rho (t + 1) - 1 (E4). With eps > 0 the tractions vanish at
// the ends of their intervals. p = sum_j b_j sin((j+1) theta), r = cos theta, i.e. p =
// sqrt(1 - r^2) sum_j b_j U_j(r): the representation of normal_solution (4.1), so its b,
// pressure() and the output code apply unchanged; likewise q and psi_b.
//
// Collocation (Glauert type): each equation multiplied by sin theta at the n + 1 points of
// (4.7), theta_m = (m - 1/2) pi/(n + 1), for n coefficients and one more unknown: gamma_0n
// (normal, the regularising unknown of (4.2), zero by symmetry) and xi (tangential, fixed by
// the solvability condition). c0 for a given Q by Brent (tangential_problem, Q(1) = 0 exactly).
//
// Dissimilar rollers at Johnson's level (docs/formulation.md 8(s)): the stick equation gains Dundurs'
// forcing b p on its right side, b = sgn(Q) beta_D in the |Q| frame (the mirror of 8(h)), and the
// slip velocity likewise; the structures with one stick zone and slip in the direction of Q are
// solved, the checks (3.3)-(3.4) unchanged.
#pragma once

#include <optional>
#include <vector>

#include "roughroll/numerics/linear_system.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// eps1 (tangential) and eps2 (normal): the compliances of the Winkler layers in the units
// of (3.19), eps = mu/(2 (1 - nu) a k) (docs/formulation.md 2(c)).
struct compliances {
    double tangential = 0.0;  // eps1
    double normal = 0.0;      // eps2
};

// sum_beta 2 T/A^2 per direction; a term with T = 0 contributes nothing. Throws input_error
// for a term with T > 0 and A = 0 (no t -> 0 limit: the kernel does not decay), or with
// T, A negative or not finite.
compliances one_parameter_compliances(const roughness& r);

// The normal problem of the limit alone (lambda, b, gamma_0n), n coefficients: the solver's
// normal solution, and load_ratio's for method::one_parameter. Throws input_error for a
// negative or non-finite eps2.
normal_solution one_parameter_normal(double eps2, int n);

// Explicit workspace for one (eps1, eps2, f, n): the normal problem is solved on
// construction and shared by every point of a creep curve. The tangential problem's members
// (solve, at_stick_end, load, traction, slip_velocity, check: tangential_problem.hpp) on the Glauert system.
class one_parameter_solver final : public tangential_problem {
public:
    // beta_d: Dundurs' beta_D of 8(a) at Johnson's level (0: the paper's problem, exactly).
    one_parameter_solver(const compliances& eps, double f, int n, double beta_d = 0.0);
    one_parameter_solver(const roughness& r, double f, int n, double beta_d = 0.0)
        : one_parameter_solver(one_parameter_compliances(r), f, n, beta_d) {}

    const normal_solution& normal() const override { return normal_; }
    const compliances& eps() const { return eps_; }
    double beta_d() const { return beta_d_; }

    // The stick equation on the zone [start, c0] with slip on both sides in the direction of Q
    // (docs/formulation.md 7(g), 8(s)): r = start + rho (t + 1), rho = (c0 - start)/2; the |Q| branch
    // with Dundurs' forcing b (forcing_at(Q)), unchecked, Q = f + rho (pi/2) psi_b[0]. solve() is start = -1.
    tangential_solution solve_on_zone(double start, double c0, double forcing);

    double pressure_slope(double r) const;                         // p'(r) on [-1, 1]
    double G(double r) const;                                      // G(r) = (2/pi) lambda r + (eps2 - eps1) p'(r)
    std::vector<double> G(const std::vector<double>& r) override;  // at points of [-1, 1], in any order
    // E = eps1 q'(start+) of a stick-zone solution: xi + b p(start) + f G(start) - H[q](-1), H[q](-1) =
    // sum_j (-1)^j c_j (7(g), 8(s)). The entry condition is E = 0; at start = -1, E <= 0 is (3.3).
    double entry_velocity(const tangential_solution& s) const;
    // The Glauert system as the one zone search's operator (zone_operators.cpp) for the |Q| problem
    // with Dundurs' forcing b (forcing_at(Q) of the loads it is asked); refers to this solver.
    stick_zone_operator zone_operator(double forcing = 0.0);
    // w = b p + f G, the slip velocity of gross sliding less xi (7(d), 8(g)).
    double sliding_velocity(double forcing, double r) const;

private:
    tangential_solution on_zone(double start, double c0, double forcing, bool) override {
        return solve_on_zone(start, c0, forcing);
    }
    tangential_solution full_stick(double forcing) override;     // with Dundurs' forcing: p1 odd (8(s))
    tangential_solution gross_sliding(double forcing) override;  // refused where G(-1) is infinite
    std::vector<double> slip_velocity_magnitude(const tangential_solution& s, const std::vector<double>& r) override;
    double check_rounding(const tangential_solution& s) override;
    std::optional<double> exact_full_stick_load() const override { return 0.0; }  // p1 odd at full stick (8(s))

    compliances eps_;
    std::vector<double> sin_;  // sin theta_m, m = 0..n
    std::vector<double> cos_;  // cos((j+1) theta_m), row-major (n+1) x n
    dense_system tangential_system_;
    normal_solution normal_;
};

}  // namespace roughroll
