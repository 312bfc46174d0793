// SPDX-License-Identifier: GPL-3.0-or-later
// P_H/P2 = lambda of a scene without its tangential problem (3.20), (4.5): for the root search in the
// contact width of a physical scene (contact_width.hpp), by exactly the calls contact makes.
#pragma once

#include <functional>

#include "roughroll/model/dissimilar.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/normal_problem.hpp"

namespace roughroll {

// P_H/P2 alone, exactly as contact(surfaces, f, options).normal().lambda reports it (the same
// calls, the same extrapolation), for every method, without the tangential solver: for a
// root search in the contact width. The extrapolated method's asymptotic-range condition is
// checked on the normal kernel only (the tangential kernel does not enter P_H/P2).
// `cache`: the normal problems shared with the other trials of a width search and its contact.
double load_ratio(const roughness& surfaces, const solver_options& options, normal_cache* cache = nullptr);

// P_H/P2 on the cheap level of `options`: the method's plain discretisation at n/2 (product
// integration for `extrapolated`, the one-parameter normal problem for `one_parameter`). Its
// root in the contact width starts the width search at the scene's method (find_width), whose
// answer is load_ratio's root, not this one's. Throws resolution_error when n/2 < min_nodes or
// the kernel is beyond the level's resolution.
double coarse_load_ratio(const roughness& surfaces, const solver_options& options, normal_cache* cache = nullptr);

// P_H/P2 of dissimilar rollers at full coupling (docs/formulation.md 8(c), 8(e)): lambda =
// 1 - int p J - beta_D int p1 r/sqrt(1 - r^2) of the converged alternation at the load Q, as
// contact(surfaces, f, options, materials).point(Q) leaves it in contact::normal() (level n).
// It depends on Q through p1: the width of a physical scene follows the tangential load too.
// `checkpoint`: contact::set_checkpoint's hook for the point solved.
double coupled_load_ratio(const roughness& surfaces, double f, const solver_options& options,
                          const dissimilar& materials, double Q, normal_cache* cache = nullptr,
                          const std::function<void()>& checkpoint = {});

}  // namespace roughroll
