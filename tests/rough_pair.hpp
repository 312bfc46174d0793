// SPDX-License-Identifier: GPL-3.0-or-later
// The rough aluminium-on-steel pair of the full-coupling tests, in dimensionless form.
#pragma once

#include "roughroll/model/roughness.hpp"

namespace roughroll_test {

constexpr double beta_pair = 0.143834;  // aluminium on steel (docs/formulation.md 8(a))

// data/aluminium-on-steel-rough.toml's layer at a = a_H (its header): roller 1, (T, A) = (1.08, 1.19) tangential,
// (3.9, 4.5) normal; roller 2 smooth.
inline roughroll::roughness rough_pair() {
    roughroll::roughness r;
    r.cylinder1.tangential = {1.08, 1.19};
    r.cylinder1.normal = {3.9, 4.5};
    return r;
}

}  // namespace roughroll_test
