// Dissimilar rollers in Johnson's approximation (docs/formulation.md section 8): the pressure of
// the uncoupled normal problem, and the tangential problem (D2) with Dundurs' forcing,
//   v(r) = xi - L1[p1](r) + beta_D p(r);  stick: v = 0, |p1| <= f p;  slip: p1 = sigma f p, sigma v > 0;
//   int p1 = Q                                                                          8(c), 8(e)
#pragma once

#include "roughroll/model/dissimilar.hpp"
#include "roughroll/numerics/method.hpp"

namespace roughroll {

// What a contact with these materials and options can solve: beta_D finite with |beta_D| < 3/4;
// for beta_D != 0, not method 'one-parameter' (its edge behaviour, 8(g), is not derived), not
// zones 'single' (the paper's zone is never the answer, 8(g)), and not coupling 'full' (not
// built). Each refusal is one input_error line.
void check_dissimilar(const dissimilar& materials, const solver_options& options);

}  // namespace roughroll
