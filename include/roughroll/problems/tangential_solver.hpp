// SPDX-License-Identifier: GPL-3.0-or-later
// The collocation of (4.4)-(4.5): the stick equation of the tangential problem (tangential_problem.hpp) on a
// stick zone [start, c0], r = start + rho (t + 1), rho = (c0 - start)/2 (E4; the paper's zone start = -1),
// q = psi(t) sqrt(1 - t^2) (4.1), discretised on the Gauss-Chebyshev rule of the normal solution, nodes
// eta_k, weights w_k, collocation points s_m (4.6)-(4.7):
//   sum_k [(1/pi) w_k/(eta_k - s_m) + kappa^rho_mk] psi_k - xi = f G(r(s_m)) + b p(r(s_m)),  m = 1..n+1  (4.4), E5, E6
//   Q(c0) = f + rho sum_k w_k psi_k                                                             (4.5)
//   G(r) = (2/pi) lambda r + int_{-1}^{1} p(eta) [K2* - K1*](eta - r) d eta                     (3.25), E8
// for the n + 1 unknowns psi_k, xi; kappa^rho the kernel term of rho K1*(rho z) (E6; docs/formulation.md 3,
// paper or product method), b Dundurs' forcing (0 but for dissimilar rollers, 8(e)). The Cauchy part is
// c0-independent (kept once per solver), and so is G (tabulated once). Off the stick zone the slip velocity
// (3.6) is xi + f G - L1[q0], L1 evaluated outside its interval in closed form.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/convolution_table.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/kernel_moments.hpp"
#include "roughroll/numerics/linear_system.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// The collocation of (4.4)-(4.5) on the Gauss-Chebyshev rule of the normal solution; the driver (root search in c0,
// special loads, mirror, traction, checks) is tangential_problem's.
class tangential_solver final : public tangential_problem {
public:
    // The normal solution is shared by every point of a creep curve. When both kernels
    // are empty, solve() takes Carter's closed form unless `closed_form` is false (the
    // validation of the scheme itself).
    tangential_solver(const normal_solution& normal, const kernel& k1, const kernel& k2, double f,
                      bool closed_form = true);
    // The solver keeps a reference to the normal solution: a temporary would dangle.
    tangential_solver(normal_solution&&, const kernel&, const kernel&, double, bool = true) = delete;

    // (4.4)-(4.5) on a stick zone [start, c0] inside (-1, 1], slip (in the direction of Q) on both sides:
    // r = start + rho (t + 1), rho = (c0 - start)/2 (E4); start = -1 is the paper's zone. Unchecked, for the zone
    // solver (zone_solver.hpp), whose solutions carry the start. `forcing`: Dundurs' sigma beta_D of 8(e), added as
    // forcing * p(r) to the right side xi + f G (dissimilar_zones.hpp); 0 leaves the system as it was. `extra`: values
    // added to the right side at the n + 1 collocation points r_m = start + rho (s_m + 1) (the blended stick zone of
    // 8(g)); s.Q is then f + rho int q still, for the caller to correct.
    // `near` = true: a sweep's next system, solved by refinement on the last factorisation where that
    // converges (dense_system::solve_near; at_stick_end's route), false: a fresh LU.
    tangential_solution solve_on_zone(double start, double c0, double forcing = 0.0,
                                      const std::vector<double>* extra = nullptr, bool near = false);

    // The n + 1 collocation points r_m = start + rho (s_m + 1) of the zone [start, c0] (E4).
    std::vector<double> collocation_points(double start, double c0) const;
    double G(double r);                                            // (3.25)
    std::vector<double> G(const std::vector<double>& r) override;  // at points of [-1, 1], in any order

    const normal_solution& normal() const override { return normal_; }
    double rounding(double xi) const;  // the margins' rounding floor at the creep xi (7(d))
    // The collocation of (4.4) as the one zone search's operator (zone_operators.cpp); refers to this solver.
    stick_zone_operator zone_operator();

    // Full coupling's local term (docs/formulation.md 8(v)): G holds beta_D p1 of the alternation's source, whose part
    // k q_source (k = sigma beta_D f, `source_q` its stick traction in the |Q| frame) is the local -k q of the stick
    // equation (H - k)[q] = ... (8(l)). Given it, a zone solved with Dundurs' forcing and no `extra` (the braked three
    // zones) takes -k q into the operator on the Jacobi weight (1 - t)^a (1 + t)^(1 - a), cot(pi a) = k, and
    // -k q_source off the right side; its solution holds Jacobi coefficients (tangential_solution::weight_a). Smooth
    // tangential compliance only (K1* empty): the layer term on that weight is not built.
    // The source's zone [source_start, source_end]: its q is read at the same t of the zone solved (below).
    void couple_locally(std::function<double(double)> source_q, double source_start, double source_end);
    // The Jacobi zone's rules and factors of another solver of the same n (the alternation's previous step): they
    // depend on n and the exponent only, so the steps share them instead of rebuilding them (bit for bit the same).
    void share_jacobi(const tangential_solver& other) { jacobi_ = other.jacobi_; }
    // The solve's Gauss-Jacobi rules (full_coupling: one set per solve, which the pressure's weighted kinks of the same
    // n and exponent read too): the Jacobi zone takes its rules of n and 4 n nodes from it instead of building them.
    void share_rules(std::shared_ptr<jacobi_rule_set> rules) { rules_ = std::move(rules); }

private:
    tangential_solution on_zone(double start, double c0, double forcing, bool near) override {
        return solve_on_zone(start, c0, forcing, nullptr, near);
    }
    std::vector<double> slip_velocity_magnitude(const tangential_solution& s, const std::vector<double>& r) override;
    double check_rounding(const tangential_solution& s) override { return rounding(s.xi); }
    std::optional<double> search_start(double magnitude) const override;

    const normal_solution& normal_;
    kernel k1_, dk_;     // K1*, and K2* - K1* (empty when equal: then G = (2/pi) lambda r)
    matrix_ptr cauchy_;  // the c0-independent Cauchy part of (4.4)
    dense_system system_;
    std::shared_ptr<const kernel_operator> k1_operator_;  // rho K1*(rho z) for every trial c0, rho <= 1
    std::optional<convolution_table> g_table_;            // the kernel part of G (3.25), once per solver

    // 8(v): the braked zone on the Jacobi weight.
    struct jacobi_zone;
    tangential_solution solve_on_jacobi(double start, double c0, double forcing);
    jacobi_zone& jacobi_for(double a);
    std::function<double(double)> source_q_;
    double source_start_ = 0.0, source_end_ = 0.0;
    std::shared_ptr<jacobi_zone> jacobi_;
    std::shared_ptr<jacobi_rule_set> rules_;  // null: the zone builds its own rules
    // psi of the last solution asked off its zone, at the rule's nodes and the far rule's (the checks ask the slip
    // velocity one point at a time).
    struct jacobi_values_cache {
        std::vector<double> c, at_nodes, at_far;
        double a = 0.0;
    } outside_;
};

}  // namespace roughroll
