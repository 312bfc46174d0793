// SPDX-License-Identifier: GPL-3.0-or-later
// The micro-geometry of a rough surface layer, Section 2 of the paper: the layer
//   Omega = {(x1, x2): h0(x1) < x2 < H}                                        (2.1)
// of mean thickness H over an l-periodic profile h0, the l-periodic micro-shape function h,
// and the decay function d(x2) on (0, H) with d(0) = 1, d(H) = 0, d' < 0.
// These value types and shape functions feed the averages (2.6)-(2.9) of
// roughness_parameters.hpp. SI units throughout: Pa for lambda0, mu0; m for H, l, x1, x2, h0.
// Formulas of every built-in shape: docs/roughness-parameters.md.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace roughroll {

// The layer's material and size: Lame constants lambda0, mu0 (Pa) of the isotropic layer
// (2.11)-(2.14), its mean thickness H (m) and the period l (m) of its roughness.
struct layer {
    double lambda0 = 0.0;
    double mu0 = 0.0;
    double H = 0.0;
    double l = 0.0;
};

// h0(x1), the profile of the layer's lower boundary (2.1):
//   flat      h0 = 0
//   sine      h0 = (delta/2) (1 - cos(2 pi x1/l))            peak delta at x1 = l/2
//   sawtooth  h0 = delta x1/l on [0, l), repeated             jump from delta to 0 at x1 = l
//   measured  a periodic cubic spline through samples (profile_csv.hpp)
enum class profile_kind { flat, sine, sawtooth, measured };

// Samples of one period of a measured profile, x1 strictly increasing from 0, below l, with
// the line of the file each came from (so a violated condition names the line).
struct profile_samples {
    std::string source;  // the file they were read from, for messages
    std::vector<double> x1;
    std::vector<double> h0;
    std::vector<int> lines;
};

struct profile {
    profile_kind kind = profile_kind::flat;
    double delta = 0.0;        // m; sine and sawtooth only
    profile_samples measured;  // measured only
};

// h(x1), the micro-shape function of (2.3)-(2.5); only its derivative h_1 enters (2.11)-(2.14),
// and only up to a factor (the averages are homogeneous of degree 0 in h):
//   sine      h = l sin(2 pi x1/l),  h_1 = 2 pi cos(2 pi x1/l)
enum class micro_shape_kind { sine };

// d(x2) on [0, H] of (2.6)-(2.8):
//   linear     d = 1 - x2/H
//   quadratic  d = (1 - x2/H)^2
//   cosine     d = cos(pi x2/(2H))
enum class decay_kind { linear, quadratic, cosine };

// The factor multiplying the corrector term <a3 h_1>^2/<a h_1^2> of k^(2) in (2.12)
// (docs/formulation.md, erratum E11):
//   derived  (lambda0/(lambda0 + 2mu0))^2          eliminating V_1 from the paper's (2.3)-(2.5)
//                                                  with the isotropic C_ijkl (the default)
//   printed  ((lambda0 + mu0)/(lambda0 + 2mu0))^2  as printed in the paper, for comparison
enum class normal_factor { derived, printed };

struct micro_geometry {
    layer material;
    profile bottom;
    micro_shape_kind shape = micro_shape_kind::sine;
    decay_kind decay = decay_kind::linear;
    normal_factor factor_2_12 = normal_factor::derived;
};

const char* to_string(profile_kind kind);
const char* to_string(micro_shape_kind kind);
const char* to_string(decay_kind kind);
const char* to_string(normal_factor kind);

// The ratio whose square is the factor of (2.12): lambda0/(lambda0 + 2mu0) (derived) or
// (lambda0 + mu0)/(lambda0 + 2mu0) (printed). The one place both the value of k^(2) and its
// error estimate take it from.
double normal_factor_ratio(normal_factor kind, double lambda0, double mu0);

// d(x2) and d'(x2) = dd/dx2 of a built-in decay, for 0 <= x2 <= H (through the two below,
// with u = (H - x2)/H: d = dhat(u), d' = -dhat_u(u)/H).
double decay_value(decay_kind kind, double x2, double H);
double decay_slope(decay_kind kind, double x2, double H);

// The same decay in the dimensionless depth below the top of the layer, u = (H - x2)/H in
// [0, 1]: dhat(u) = d(H (1 - u)) and dhat_u(u) = d dhat/du = -H d'(x2). Free of H and exact as
// u -> 0 (the top, where 1 - x2/H would cancel):
//   linear     dhat = u,             dhat_u = 1
//   quadratic  dhat = u^2,           dhat_u = 2u
//   cosine     dhat = sin(pi u/2),   dhat_u = (pi/2) cos(pi u/2)
// The layer integrals (2.6)-(2.8) are integrated in u (roughness_parameters.hpp).
double decay_value_from_top(decay_kind kind, double u);
double decay_slope_from_top(decay_kind kind, double u);

// h_1(x1) = dh/dx1 of a built-in micro-shape (dimensionless).
double micro_shape_slope(micro_shape_kind kind, double x1, double l);

// h0(x1) of a profile, for any x1 (reduced to [0, l) by periodicity). A measured profile is
// the periodic cubic spline of GSL (gsl_interp_cspline_periodic) through its samples and the
// closing point (l, h0 at 0); the function owns the spline. Not thread-safe (the spline's
// lookup accelerator is shared).
class profile_function {
public:
    profile_function(const profile& p, double l);
    ~profile_function();
    profile_function(profile_function&&) noexcept;
    profile_function& operator=(profile_function&&) noexcept;
    profile_function(const profile_function&) = delete;
    profile_function& operator=(const profile_function&) = delete;

    double operator()(double x1) const;

    // Where the quadrature over one period [0, l] must split: 0, l and, for a measured
    // profile, every knot (the spline is one cubic per interval). The sawtooth's jump is at
    // 0 = l, an end of the period, so it needs no interior break.
    const std::vector<double>& breakpoints() const { return breaks_; }

    // The extreme values of h0 over one period and where they are: exact for every kind
    // (for a measured profile the extremes of each cubic piece, from the roots of its
    // derivative: the spline can overshoot its samples). For the sawtooth the maximum is the
    // supremum delta, approached as x1 -> l.
    struct extreme {
        double value;
        double x1;
    };
    extreme minimum() const;
    extreme maximum() const;

    // A measured profile's spline on its knot interval [x0, x0 + width] (knot intervals
    // i = 0 .. breakpoints().size() - 2) as the cubic in t = (x1 - x0)/width in [0, 1]
    //   h0 = c[0] + t (c[1] + t (c[2] + t c[3])),
    // from the knot values and the spline's slopes at both knots (Hermite form: a cubic is
    // fixed by them, so this is the spline's own piece, up to rounding). Measured profiles only
    // (numerical_error otherwise): the averages integrate piece by piece (piecewise_averages.hpp).
    struct cubic {
        double x0, width;
        double c[4];
        double operator()(double t) const { return c[0] + t * (c[1] + t * (c[2] + t * c[3])); }
    };
    cubic piece(std::size_t i) const;

    struct spline;  // the GSL spline of a measured profile (opaque)

private:
    profile_kind kind_;
    double delta_;
    double l_;
    std::vector<double> breaks_;
    std::unique_ptr<spline> spline_;
};

// The paper's conditions, each violated one a one-line message naming it:
//   the layer: lambda0 >= 0, mu0 > 0, H > 0, l > 0, all finite, and the scales of k and t,
//     mu0/H to (lambda0 + 2 mu0)/H and mu0 H to (lambda0 + 2 mu0) H, within 1e3 of the
//     limits of double precision (DBL_MIN, DBL_MAX): steel moduli with H = 1e-300 m would
//     give k = 7.7e310 Pa/m, which overflows;
//   the profile: 0 <= h0 < H everywhere (for sine and sawtooth: 0 <= delta < H; for a
//     measured profile on every sample, naming its file and line, and on the spline between
//     them, which can overshoot);
//   the decay: d(0) = 1, d(H) = 0, d' < 0 on (0, H) (decay_violations).
// Empty when all hold.
std::vector<std::string> condition_violations(const micro_geometry& g);

// Throws input_error with the first of condition_violations, if any.
void check_conditions(const micro_geometry& g);

// The layer's part of condition_violations that names no value out of range by itself: H with mu0 and
// lambda0 putting k ~ mu0/H or t ~ mu0 H of (2.11)-(2.14) beyond double precision (a reader prefixes
// its file and keys). Empty when they fit, or when a value is itself invalid (condition_violations).
std::string layer_range_violation(const layer& m);

// The decay conditions for any d: d(0) = 1 and d(H) = 0 to 1e-12, and d' < 0 at 1000 interior
// points of (0, H) (a sampled check: built-in decays pass it exactly; a function given here
// is a test's or a future user's). `name` names the decay in the messages.
std::vector<std::string> decay_violations(const std::function<double(double)>& d,
                                          const std::function<double(double)>& d_slope, double H,
                                          const std::string& name);

}  // namespace roughroll
