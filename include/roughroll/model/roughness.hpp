// SPDX-License-Identifier: GPL-3.0-or-later
// Dimensionless roughness parameters of the two-parameter model, (3.26):
//   T_beta^(i) = a mu / (8 (1 - nu) t_beta^(i)),   A_beta^(i) = a alpha_beta^(i),
// i = 1 tangential, i = 2 normal; beta = 1, 2 the cylinder.
// T = 0 means the term is absent (a smooth surface in that direction).
#pragma once

namespace roughroll {

// One cylinder, one direction: the pair (T, A) of (3.26).
struct roughness_term {
    double T = 0.0;
    double A = 0.0;

    bool present() const { return T != 0.0; }
};

// One cylinder: its tangential (i = 1) and normal (i = 2) terms.
struct cylinder_roughness {
    roughness_term tangential;
    roughness_term normal;
};

// Both cylinders. A default-constructed value is two smooth cylinders.
struct roughness {
    cylinder_roughness cylinder1;
    cylinder_roughness cylinder2;

    bool smooth() const {
        return !cylinder1.tangential.present() && !cylinder1.normal.present() && !cylinder2.tangential.present() &&
               !cylinder2.normal.present();
    }
};

}  // namespace roughroll
