// SPDX-License-Identifier: GPL-3.0-or-later
// The ends of one stick zone by Newton (docs/formulation.md 7(e), step 2; 7(g) for the
// one-parameter limit): in the zone's midpoint m and u = log rho, rho the half-length, on
//   F_0 = log(-rho (pi/2) psi_0 / (f - |Q|))   (the load's gap f - Q(s, c) = -rho int q, relative),
//   F_1 = the entry condition at s (the caller's: psi(-1)/|psi_0|, or q'(s) in the one-parameter limit),
// both relative, so that they keep their digits as the zone collapses at gross sliding. The Jacobian
// by forward differences (1e-6 rho in m, on the side inside [-1, 1]; 1e-6 in u), steps halved to
// keep -1 < s < c <= 1 (damped_newton). Shared by zone_solver and one_parameter_zones.
#pragma once

#include <functional>
#include <optional>

#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// `solve_on_zone(s, c)`: the system on the stick zone [s, c]; `entry`: F_1 of its solution; `gap`:
// f - |Q| > 0. Stops after a full step below `tolerance` in r. Empty when it does not converge.
std::optional<tangential_solution> zone_ends_newton(
    const std::function<tangential_solution(double, double)>& solve_on_zone,
    const std::function<double(const tangential_solution&)>& entry, double gap, double start, double c0,
    int max_iterations, double tolerance);

}  // namespace roughroll
