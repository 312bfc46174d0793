// SPDX-License-Identifier: GPL-3.0-or-later
// Newton's method in the ends of k stick zones [s_i, c_i] (docs/formulation.md 7(e), step 2; 7(g) for
// the one-parameter limit; 8(g) and 8(j) item 3 for dissimilar rollers): the unknowns are each zone's
// midpoint m_i and, as its length,
//   u_i = log rho_i  (`log_length`: the zones of one slip direction, whose residuals are relative and
//                    keep their digits as the zone collapses at gross sliding, 7(e)), or
//   rho_i itself     (the blended zones of 8(g), 8(j)),
// rho_i = (c_i - s_i)/2; the residuals F(zones) are the caller's (the load's gap, one entry condition
// per stick zone, xi continuity between them). The Jacobian by differences: with log_length 1e-6 rho
// in m (backward where that stays inside [-1, 1]) and -1e-6 in u; else -1e-7 rho in both. Steps halved
// (damped_newton) to keep -1 < s_1 < c_1 < s_2 < ... < c_k <= 1; it stops after a full step whose size
// (sum |dm| + rho |du|, or sum |dm| + |d rho|, in r) is below `tolerance`. Empty when it does not
// converge. Shared by every zone search (zone_solver's operators, the five zones) through ends_newton
// (problems/zone_newton.hpp: the residuals per structure, the rounding limits a search met).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "roughroll/numerics/damped_newton.hpp"

namespace roughroll {

// One stick zone of a Newton iterate: its ends and half-length (exp u with log_length, not (c - s)/2).
struct stick_span {
    double start, end, rho;
};

// The Newton iterations from the zones `from` to a root of `residual` (empty where the zones leave the family
// the residuals describe), in (m, log rho) with `log_length`, else (m, rho); `rounding`: the ends' rounding at
// the last residual's zones (damped_newton's), empty: below `tolerance`; damped_newton's result (why it stopped).
// The last call of `residual` is at the root. `kept`: a Jacobian carried between solves (damped_newton.hpp).
newton_result interval_newton(
    const std::function<std::optional<std::vector<double>>(const std::vector<stick_span>&)>& residual,
    const std::vector<stick_span>& from, bool log_length, int max_iterations, double tolerance,
    const std::function<double()>& rounding, newton_jacobian* kept = nullptr);

}  // namespace roughroll
