// SPDX-License-Identifier: GPL-3.0-or-later
// What full coupling's alternation (full_coupling.hpp, docs/formulation.md 8(e)) measured at a point,
// as contact::coupling returns it and the reports print it. A value, apart from the alternation:
// part of the public interface (roughroll.hpp).
#pragma once

#include <vector>

namespace roughroll {

// What the alternation measured, for the report of a point.
struct coupling_summary {
    int iterations = 0;           // normal solves after the start (Johnson's point or a coarser level's coupling)
    int start_level = 0;          // n of the coarser level whose converged coupling started it; 0: Johnson's point
    double offset = 0.0;          // e = x_c/a of 8(c)
    double lambda_johnson = 0.0;  // P_H/P2 of Johnson's level
    // The relative change of the physical peak pressure from Johnson's level at the same rollers and
    // normal load P2: p_phys = p P2/a with a^2 proportional to P_H = lambda P2, so
    // (p_max/p_max,J) sqrt(lambda_J/lambda) - 1 (docs/formulation.md 8(e)).
    double peak_pressure_change = 0.0;
    double contraction = 0.0;     // the largest ratio of successive changes after the first two steps
    std::vector<double> changes;  // the largest change of lambda, e, xi per step (the ends' apart)
    std::vector<double> end_changes;  // the largest change of the zone ends per step (0 at gross sliding)
    // The cost of the five zones' Newton over the steps (damped_newton.hpp, newton_jacobian): systems solved
    // (the zone ends' residuals, differences included) and Jacobians by differences; 0 for three zones.
    int newton_residuals = 0;
    int newton_jacobians = 0;
};

}  // namespace roughroll
