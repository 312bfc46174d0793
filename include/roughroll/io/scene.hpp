// SPDX-License-Identifier: GPL-3.0-or-later
// Scene files (TOML): the inputs of one rolling contact, checked strictly.
//
//   label = "Fig. 2a, curve 2"   # optional, names the scene in outputs
//   friction = 0.3               # f in [min_friction, max_friction] (required)
//   Q = 0.15                     # P1/P2, optional (the command line may give it)
//   # Q_over_f = 0.5             # or the load as Q/f in [-1, 1] (not both; P1 in N/m for a physical scene)
//   [cylinder1.tangential]       # T_1^(1), A_1^(1) of (3.26)
//   T = 0.5
//   A = 0.5
//   [cylinder1.normal]           # T_1^(2), A_1^(2)
//   T = 0.5
//   A = 0.5
//   # [cylinder2.tangential], [cylinder2.normal] likewise; a missing table is smooth
//   beta_d = 0.14                # Dundurs' beta_D, |beta_d| < 0.75 (dimensionless scenes; docs/formulation.md 8)
//   coupling = "johnson"         # or "full": the level of coupling of dissimilar rollers (8(e))
//   [solver]
//   n = 128                      # Gauss-Chebyshev nodes, in [min_nodes, max_nodes]
//   method = "extrapolated"      # or "product", "paper", "one-parameter" (the limit t -> 0)
//
// A physical scene gives one material (E, nu) or one per cylinder: shear_modulus (Pa) and
// poisson in [cylinder1] and [cylinder2] (roller 1 = cylinder1), from which C and beta_D follow
// (docs/formulation.md 8(a)); beta_d itself is then not a key.
//
// Every key and table not listed above is an error naming it; so is a wrong type,
// a non-finite or negative T or A, a table with T or A missing, an f outside
// [min_friction, max_friction], a non-finite Q or |Q| > f, a nonzero number written below
// the smallest normal double (base/text.hpp), and for a physical scene any derived value
// (a_H, T, A, k, t, the SI scales) beyond double precision (physical_scene.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "roughroll/numerics/method.hpp"
#include "roughroll/model/dissimilar.hpp"
#include "roughroll/model/physical_scene.hpp"
#include "roughroll/model/roughness.hpp"

namespace roughroll {

// The friction coefficients a scene may give: the range validation/test_stiff.cpp shows the
// solver resolves (G of (3.25) does not involve f, so xi/f depends on Q/f alone; beyond it,
// f itself loses digits: a subnormal f gave xi/f = 1.0 for 1.32).
constexpr double min_friction = 1e-12;
constexpr double max_friction = 1e12;

// A load as its user gives it (a scene key, a command-line option, a Python keyword): Q = P1/P2
// of (3.22), its ratio Q/f to the friction (xi/f depends on Q/f alone), or P1 in N/m (a physical
// scene's, Q = P1/P2).
// A plain number is a Q, as the library's callers have always given it.
enum class load_kind { Q, Q_over_f, P1 };
struct load_given {
    load_kind kind = load_kind::Q;
    double value = 0.0;
    load_given(double Q) : value(Q) {}  // NOLINT(google-explicit-constructor): a number is a Q
    load_given(load_kind k, double v) : kind(k), value(v) {}
};

struct scene {
    std::string label;
    double friction = 0.0;
    std::optional<double> Q;
    // Set when the scene gives its load as Q/f: Q is then Q_over_f f, and follows a friction
    // given on the command line (override_friction).
    std::optional<double> Q_over_f;
    roughness surfaces;
    solver_options solver;
    dissimilar materials;  // beta_D and the coupling level (docs/formulation.md 8); beta_D = 0: the paper's
    // Set for a physical scene; `surfaces` are then those at a = a_H(P2) until the
    // contact width is found (find_width), and Q is P1/P2 when P1 is given.
    std::optional<physical_scene> physical;
    // The files read: the scene file (read_scene) and the profile CSVs of its
    // micro-geometries. An output must not overwrite one of them.
    std::vector<std::string> files;
};

// Parses scene text; `source` names it in messages ("data/fig2a-T0.5.toml"), `base_dir`
// resolves a relative profile_csv of a micro-geometry. Throws input_error with one line:
// "<source>: <what is wrong>".
scene parse_scene(std::string_view text, const std::string& source, const std::filesystem::path& base_dir = ".");

// Reads and parses a scene file; a missing, unreadable or non-regular file is an input_error.
scene read_scene(const std::string& path);

// The load to solve for: `override` (the command line's --Q, --Q-over-f or --P1, the Python
// keywords Q=, Q_over_f=, P1=) if given, else the scene's Q; Q = (Q/f) f, or P1/P2 of a physical
// scene. Throws input_error with one line (naming the load as the scene keys Q, Q_over_f, P1)
// when no load is given, when it is not finite, when |Q| > f, |Q/f| > 1 or |P1| > f P2 (the
// cylinders slide), and for P1 in a dimensionless scene or at contact_width = "hertz" (whose
// model carries P2/lambda, not P2).
double load_of(const scene& s, const std::optional<load_given>& override);

// The command line's --friction over the scene's friction (nothing when not given), checked
// as the scene's key is: in [min_friction, max_friction]. The load is checked against it by
// load_of, so a scene's Q above the new f is refused there (--Q may give another). A scene
// that gives Q_over_f keeps its ratio: its Q becomes Q_over_f times the new f.
// `name`: how the caller spells it in the one-line refusal ("friction" from Python).
void override_friction(scene& s, std::optional<double> friction, const std::string& name = "--friction");

}  // namespace roughroll
