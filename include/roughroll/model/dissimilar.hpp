// SPDX-License-Identifier: GPL-3.0-or-later
// Dissimilar rollers: Dundurs' coupling parameter and the level of coupling (docs/formulation.md
// section 8). With C = (1 - nu1)/mu1 + (1 - nu2)/mu2,
//   beta_D = ((1 - 2 nu1)/mu1 - (1 - 2 nu2)/mu2) / (2 C)                    8(a), roller 1 = cylinder1
// enters the tangential problem as the forcing beta_D p of (D2),
//   v = xi - L1[p1] + beta_D p,                                             8(c)
// and the normal problem as beta_D p1 (D1), which Johnson's approximation drops (8(e)).
// For mu_i > 0 and -1 < nu_i <= 1/2, |beta_D| < 3/4 (the bound (1 - 2 nu)/(2 (1 - nu)) of one
// roller against a rigid one tends to 3/4 as nu -> -1): a dimensionless scene's beta_D must obey it.
#pragma once

#include <string>

namespace roughroll {

// johnson: the pressure uncoupled from the tangential traction (one normal solve, 8(e));
// full: the alternation of 8(e) (full_coupling), the width of a physical scene following the load.
enum class coupling_level { johnson, full };

std::string to_string(coupling_level c);
coupling_level coupling_from_string(const std::string& name);  // "johnson", "full"; else input_error

// The bound of 8(a): |beta_D| < 3/4 for every material pair.
constexpr double beta_d_bound = 0.75;

struct dissimilar {
    double beta_d = 0.0;  // Dundurs' beta_D in Johnson's sign (8(a)); 0: the paper's problem, exactly
    coupling_level coupling = coupling_level::johnson;
};

// Throws input_error (one line) unless beta_d is finite with |beta_d| < 3/4.
void check_beta_d(double beta_d);

}  // namespace roughroll
