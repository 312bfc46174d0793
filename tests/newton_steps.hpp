// SPDX-License-Identifier: GPL-3.0-or-later
// What the damped Newton's tests give every problem (test_damped_newton, test_kept_jacobian, test_fcspeed_s18):
// forward differences of -1e-7 and a step measured as the sum of |dx_j| (the zone ends' unit, zone_newton.hpp).
#pragma once

#include <cmath>
#include <vector>

#include "roughroll/numerics/damped_newton.hpp"

inline roughroll::newton_problem with_steps(roughroll::newton_problem p) {
    p.difference_step = [](const std::vector<double>&, std::size_t) { return -1e-7; };
    p.step_size = [](const std::vector<double>&, const std::vector<double>& dx) {
        double sum = 0.0;
        for (double d : dx) sum += std::fabs(d);
        return sum;
    };
    return p;
}
