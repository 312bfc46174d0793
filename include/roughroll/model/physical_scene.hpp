// SPDX-License-Identifier: GPL-3.0-or-later
// Physical scenes: materials, radii and loads in SI units, the roughness as the stiffness
// k, t of (2.10), and the way from them to the dimensionless problem and back.
//   mu = E / (2 (1 + nu)),  R = R1 R2 / (R1 + R2)                       (quasi-identical materials)
//   C = 2 (1 - nu)/mu, or (1 - nu1)/mu1 + (1 - nu2)/mu2 for a material per cylinder (docs/formulation.md 8(a))
//   beta_D = ((1 - 2 nu1)/mu1 - (1 - 2 nu2)/mu2) / (2 C)                 (8(a); 0 for one material)
//   a_H^2 = 2 C R P / pi                                                (3.27), Hertz's half-width for a load P
//   T = a / (4 C t),   A = a alpha,   alpha = sqrt(k / (2 t))            (3.26)
//   xi1 = C P2 xi / a,   c = c0 a,   p2(x1) = P2 p(x1/a) / a            (the dimensionless variables of Sec. 3)
// With one material C = 2 (1 - nu)/mu and these are the paper's formulas.
// The paper fixes a = a_H and computes lambda = P_H/P2. With a given load P2 the model's
// half-width a solves  lambda(T(a), A(a)) = (a / a_H(P2))^2  (docs/formulation.md, "A given
// load"): the normal equation (3.19) with P2 normalised to 1 has the coefficient (a/a_H)^2.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "roughroll/model/roughness.hpp"

namespace roughroll {

// One direction of one surface: k (Pa/m) and t (Pa m) of (2.10). t = 0 (no term) is smooth.
struct stiffness {
    double k = 0.0;
    double t = 0.0;

    bool present() const { return t != 0.0; }
};

struct surface_stiffness {
    stiffness tangential;  // i = 1
    stiffness normal;      // i = 2
};

// How the half-width a is chosen.
//   given_load: the a at which the model carries exactly P2 (the default).
//   hertz:      the paper's a = a_H(P2); the model then carries P2 / lambda.
enum class width_rule { given_load, hertz };

// The bulk material of one roller (docs/formulation.md 8(a)).
struct material {
    double mu = 0.0;  // shear modulus, Pa
    double nu = 0.0;  // Poisson's ratio, in (-1, 1/2]
};

struct physical_scene {
    double E = 0.0;   // Young's modulus, Pa (one material for both rollers; 0 with `materials`)
    double nu = 0.0;  // Poisson's ratio (one material)
    // A material per roller, roller 1 = cylinder1 (docs/formulation.md 8(a)); empty: E, nu for both.
    std::optional<std::array<material, 2>> materials;
    double R1 = 0.0;  // radii, m (one of them may be infinite: a roller on a plane)
    double R2 = 0.0;
    double P2 = 0.0;           // normal load per unit length, N/m
    std::optional<double> P1;  // tangential load per unit length, N/m (else the scene's Q)
    surface_stiffness cylinder1, cylinder2;
    width_rule width = width_rule::given_load;

    double shear_modulus() const { return E / (2.0 * (1.0 + nu)); }  // of the one material
    double radius() const;                                           // R of (3.1)
};

// C of docs/formulation.md 8(a), the combined compliance that replaces 2 (1 - nu)/mu everywhere
// (checked: an over- or underflow is an input_error naming the material keys).
double compliance(const physical_scene& s);
// Dundurs' beta_D of 8(a) in Johnson's sign (roller 1 = cylinder1): 0 for one material.
double dundurs_beta(const physical_scene& s);

// Every function below checks what it makes: a value beyond double precision (an
// overflow, or an underflow of a width or scale to 0 or a subnormal) is an input_error
// naming the scene keys it comes from, never an inf or NaN handed on.

// (3.27): the Hertz half-width for the load P (N/m); also checks the scales P/a_H and
// P/(a_H mu) by which to_si returns to SI units.
double hertz_half_width(const physical_scene& s, double P);

// (3.26) inverted: the k, t whose T, A at half-width a are `term`. For T, A written in a
// physical scene (they are taken at a = a_H(P2), the paper's width). `name` is the term's
// dotted key ("cylinder1.tangential") for the messages.
stiffness stiffness_of(const physical_scene& s, const roughness_term& term, double a, const std::string& name = "");

// (3.26): T and A of every term at half-width a (an overflow names the term's k or t).
roughness roughness_at(const physical_scene& s, double a);

bool smooth(const physical_scene& s);

struct contact_width {
    double a;        // the model's half-width, m
    double a_hertz;  // Hertz's half-width for P2, m
    double lambda;   // P_H/P2 at a: (a / a_H)^2 for the given load
    double load;     // the load the model carries at a, N/m (P2 for given_load)
    int iterations;  // width-search steps: secant at the cheap level and polish, or Brent (0: no search)
};

// A dimensionless point in SI units.
struct si_point {
    double a, a_hertz, c;  // m
    double P_H;            // the Hertz load of width a, N/m (lambda P2)
    double P2, P1;         // N/m
    double xi1;            // creep ratio
    double xi1_carter;     // Carter's creep for the same loads on smooth cylinders (width a_H)
    double p_scale;        // Pa per unit of the dimensionless p, p1: P2/a
    int width_iterations;  // of the width search
    roughness surfaces;    // T, A of (3.26) at the half-width a
    double creep_scale;    // C P2/a: xi1 = creep_scale xi (the SI estimates scale by it, io/si_estimate.hpp)
    width_rule width;      // how a was chosen: given_load (a follows lambda) or hertz (a = a_H, the load follows)
};

si_point to_si(const physical_scene& s, const contact_width& w, double Q, double f, double c0, double xi);

}  // namespace roughroll
