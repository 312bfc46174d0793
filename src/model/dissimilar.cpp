// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/model/dissimilar.hpp"

#include <cmath>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll {

std::string to_string(coupling_level c) { return c == coupling_level::johnson ? "johnson" : "full"; }

coupling_level coupling_from_string(const std::string& name) {
    if (name == "johnson") return coupling_level::johnson;
    if (name == "full") return coupling_level::full;
    throw input_error("unknown coupling '" + echo(name) + "' (use \"johnson\" or \"full\")");
}

void check_beta_d(double beta_d) {
    // docs/formulation.md 8(a): no material pair gives |beta_D| >= 3/4.
    if (!(std::isfinite(beta_d) && std::fabs(beta_d) < beta_d_bound))
        throw input_error(
            "beta_d = " + shortest(beta_d) +
            " must be finite with |beta_d| < 0.75 (no material pair gives more; docs/formulation.md 8(a))");
}

}  // namespace roughroll
