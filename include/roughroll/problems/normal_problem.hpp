// SPDX-License-Identifier: GPL-3.0-or-later
// The normal problem (3.19)-(3.20) with a = a_H, discretised by (4.2)-(4.3), (4.6)-(4.7):
//   gamma_0n + sum_k [(1/pi) w_k/(eta_k - s_m) + kernel_mk] phi_k + (2/pi) lambda s_m = 0,
//   sum_k w_k phi_k = 1,
// for the n + 2 unknowns phi(eta_k), gamma_0n and lambda = P_H/P2 (E9 for gamma_0n).
// Dissimilar rollers at full coupling (docs/formulation.md 8(c), 8(e)) solve (D1),
//   L2[p](r) + beta_D p1(r) = -(2/pi) lambda (r + e),
// with a known beta_D p1 moved to the right side at the collocation points: the same matrix,
// right side -beta_D p1(s_m), and gamma_0n = (2/pi) lambda e absorbs the offset e.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/linear_system.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/normal_solution.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

namespace roughroll {

// Explicit workspace: the (n+2)x(n+2) system, allocated once per n.
class normal_solver {
public:
    normal_solver(int n, method how);
    // `cache`: product-integration workspaces shared with other solves at this n (collocation.hpp).
    normal_solution solve(const kernel& k2, sweep_cache* cache = nullptr);
    // (D1) of docs/formulation.md 8(c) at full coupling: `coupled`(r) = beta_D p1(r) known, with
    // square-root kinks at `kinks` (the zone ends), its Chebyshev projection on the right side;
    // the solution carries it and its offset e.
    normal_solution solve(const kernel& k2, const std::function<double(double)>& coupled,
                          const std::vector<double>& kinks, sweep_cache* cache = nullptr);
    // The same with the pressure's kinks carried by `explicit_kinks` (docs/formulation.md 8(l) step 0; smooth
    // rollers, k2 empty): p = phi sqrt(1 - r^2) + p_q^0, the right side beta_D (p1 - q) (coupled minus
    // explicit_kinks->removed), the load row 1 - int p_q^0, e = pi (gamma_0n - C)/(2 lambda), and the solution's
    // gamma is gamma_0n - C = (2/pi) lambda e (its meaning without the kinks). The solution keeps
    // `coupled` as its tangential term (G = -L1[p] still gains beta_D p1: (D1) holds for the whole p).
    normal_solution solve(const kernel& k2, const std::function<double(double)>& coupled,
                          const std::vector<double>& kinks, sweep_cache* cache,
                          std::shared_ptr<const pressure_kinks> explicit_kinks);

    // Plan C of docs/formulation.md 8(w) (smooth rollers, one slip direction at both edges: the braked three zones,
    // gross sliding): k_E = sigma beta_D f p moved into the operator, (H + k_E)[w_N phi] on the Jacobi collocation of
    // a_N = 1/2 + atan(k_E)/pi (8(v)'s identity), p = w_N phi + p_q. `weighted` holds the weight and the zones' p_q
    // (pressure_kinks::set_weight, add_weighted_zone); `source_pressure` is the pressure beta_D p1 was taken with: the
    // right side is beta_D p1 - k_E p_source - beta_D q (zero at the fixed point of the braked three zones but for q's
    // interpolation). The solution's U-series is zero and `kinks` carries the whole pressure (its series set here).
    normal_solution solve_weighted(const std::function<double(double)>& coupled,
                                   const std::function<double(double)>& source_pressure,
                                   const std::vector<double>& kinks, std::shared_ptr<pressure_kinks> weighted);

private:
    struct weighted_system;
    std::shared_ptr<weighted_system> weighted_;
    gauss_chebyshev rule_;
    method how_;
    dense_system system_;
    bool smooth_factors_ = false;  // system_ holds the factors of the matrix without K2
};

// Two pressures near a peak r of p_a (docs/formulation.md 8(e), "The peak's position from the slopes"): on
// [r - w, r + w] (inside the contact), sampled at most `step` apart, the largest slope of p_a - p_b (each secant of two
// neighbouring samples) and the least curvature -p_a'' (each second difference); the position's bound reads both
// (point_estimate.hpp, peak_position_from_slopes).
struct peak_slopes {
    double slope_change;  // max |(p_a - p_b)'|
    double curvature;     // min -p_a''
};
peak_slopes slopes_near(const normal_solution& a, const normal_solution& b, double r, double w, double step);

// The smooth solution of Hertz, lambda = 1, phi = 2/pi, exact for every n.
normal_solution hertz_solution(int n, method how);

// The normal problems of one scene solved at a few widths (a width search, then the contact at
// the width found): their product-integration workspaces per n (sweep_cache), and the solutions
// themselves, so that the problem for the same kernel, n and method (the contact at the search's
// last trial width) is the solution found before, not a second solve. One per search, not
// shared between threads.
class normal_cache {
public:
    // A copy of the solution kept for (k2, n, how), else solved and kept.
    normal_solution solve(const kernel& k2, int n, method how);

private:
    struct entry {
        kernel k2;
        int n;
        method how;
        normal_solution solution;
    };
    sweep_cache sweeps_;
    std::vector<entry> solved_;
};

// Hertz's closed form when k2 is empty, the solver otherwise (through `cache` when given).
normal_solution solve_normal(const kernel& k2, int n, method how, normal_cache* cache = nullptr);

}  // namespace roughroll
