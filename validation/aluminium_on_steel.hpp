// SPDX-License-Identifier: GPL-3.0-or-later
// Bentall and Johnson's pair in the validation tests: aluminium (roller 1, shear modulus 23 GPa,
// Poisson's ratio 0.31) on steel (82 GPa, 0.28), the pair of scripts/reproduce.
#pragma once

#include <cmath>

#include "roughroll/model/roughness.hpp"

// Dundurs' beta_D, docs/formulation.md 8(a): ((1 - 2 nu1)/mu1 - (1 - 2 nu2)/mu2) / (2 C),
// C = (1 - nu1)/mu1 + (1 - nu2)/mu2; written out here, not taken from the library's
// physical_scene, so that the tests do not share its arithmetic.
inline const double beta_al_st = [] {
    const double C = 0.69 / 23.0 + 0.72 / 82.0;
    return (0.38 / 23.0 - 0.44 / 82.0) / (2.0 * C);
}();

// The complete-slip limit of free rolling, docs/formulation.md 8(f): 2 phi + sin 2 phi = pi/2 by bisection (not the
// library's complete_slip_creep), xi_0 = -(2/pi) cos(phi) beta_D.
inline double complete_slip_limit() {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (2.0 * mid + std::sin(2.0 * mid) < M_PI_2 ? lo : hi) = mid;
    }
    return -2.0 / M_PI * std::cos(lo) * beta_al_st;
}

// The rough pair's layer (data/aluminium-on-steel-rough.toml) on roller 1 at its half-width (`roughroll point ... --json`,
// si.roughness_at_a at n = 64; tests/rough_pair.hpp has it at a = a_H), in the tests of its free rolling.
inline roughroll::roughness rough_pair_at_a() {
    roughroll::roughness r;
    r.cylinder1.tangential = {1.3075704137706388, 1.441667910063425};
    r.cylinder1.normal = {4.748527233939407, 5.419389822743732};
    return r;
}
