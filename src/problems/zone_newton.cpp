// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_newton.hpp"

#include <string>

#include "roughroll/base/text.hpp"
#include "roughroll/numerics/damped_newton.hpp"

namespace roughroll {

void rounding_limits::note(const newton_result& stop, double tolerance) {
    if (stop.stop != newton_stop::rounding_limit || (met_ && stop.rounding <= rounding_)) return;
    met_ = true;
    rounding_ = stop.rounding;
    tolerance_ = tolerance;
}

void rounding_limits::note(const rounding_limits& other) {
    if (other.met_ && !(met_ && other.rounding_ <= rounding_)) *this = other;
}

std::string rounding_limits::refusal() const {
    // The rounding is eps/rcond of the zone systems (ends_newton), which grows with n (1.5e-10, 8.6e-10, 4.0e-9 at
    // n = 250, 500, 1000 on free rolling of the pair, docs/formulation.md 8(q)): a smaller n lowers it, whether n was
    // given or the ladder's. The user's tolerance does not change it (the ends' tolerance is fixed); where a lower
    // rung of the ladder answered with an estimate above it, the ladder's line says to raise it (level_ladder.cpp).
    return "the zone ends are not resolved at this n: the rounding of their systems (" + significant(rounding_, 3) +
           " of the half-width) passes " + shortest(newton_options{}.rounding_cap) + " times their tolerance " +
           shortest(tolerance_) + " and grows with n; give a smaller n";
}

}  // namespace roughroll
