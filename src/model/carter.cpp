// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/model/carter.hpp"

#include <cmath>

#include <gsl/gsl_math.h>

namespace roughroll {

carter_point carter(double Q, double f) {
    const double rho = std::sqrt(1.0 - std::fabs(Q) / f);  // (1 + c0)/2
    // 1 - sqrt(1 - x) written as x/(1 + sqrt(1 - x)): no cancellation for small Q/f.
    const double one_minus_rho = (std::fabs(Q) / f) / (1.0 + rho);
    return {2.0 * rho - 1.0, std::copysign(M_2_PI * f * one_minus_rho, Q)};
}

carter_stick_end carter_at_stick_end(double c0, double f) {
    const double rho = 0.5 * (1.0 + c0);
    return {f * (1.0 - rho) * (1.0 + rho), M_2_PI * f * (1.0 - rho)};
}

}  // namespace roughroll
