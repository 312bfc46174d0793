// SPDX-License-Identifier: GPL-3.0-or-later
// Results as the user reads them: one creep point as JSON or text, a creep curve as CSV.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "roughroll/problems/contact.hpp"
#include "roughroll/model/physical_scene.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/problems/creep_curve.hpp"

namespace roughroll {

// The paper roughroll implements: every JSON output carries it as "reference" (how to cite
// roughroll itself: CITATION.cff; the paper and the other sources: docs/references.bib).
inline constexpr const char* paper_reference =
    "V. Pauk, M. Wo\u017aniak, Rolling contact of long elastic cylinders with surface roughness described by a "
    "two parameter model (roughroll solves its corrected formulation, docs/formulation.md)";

// roughroll's version, X.Y.Z of the VERSION file (the build systems pass it in): `roughroll
// --version` prints it, every JSON output carries it as "version", and every CSV the program
// writes starts with the line "# roughroll X.Y.Z", so that a result names the code that made it.
const char* version();

// A load ratio Q/f for a label or a progress line: `digits` significant digits, or more where
// fewer would print a ratio below 1 in magnitude as +-1, gross sliding (Q/f = 1 - 1e-9 is
// "0.999999999", not "1"); shortest round-trip digits at most.
std::string ratio_text(double q, int digits);

struct point_report {
    std::string label;
    const normal_solution& normal;
    const tangential_solution& solution;
    double seconds;  // wall time of the normal and tangential solves
    std::optional<error_estimate> estimate;
    std::optional<si_point> si;  // a physical scene's results in SI units
    // Full coupling of dissimilar rollers (docs/formulation.md 8(e)): what the alternation measured;
    // empty at Johnson's level.
    std::optional<coupling_summary> coupling = std::nullopt;
};

nlohmann::json to_json(const point_report& r);
// The zones of docs/formulation.md section 7 from r = -1 to 1, as the point's text prints them:
// "slip- [-1, -0.81], stick [-0.81, 0.69], slip+ [0.69, 0.92], ...".
std::string zones_text(const tangential_solution& s);
void write_summary(std::ostream& out, const point_report& r);

// Header Q,Q_over_f,c0,xi,xi_over_f,xi_carter,c0_carter,checks_hold,c0_error_estimate,
// xi_error_estimate,Q_error_estimate (empty without an estimate; the c0 estimate is 0 on a
// curve swept in c0, the Q estimate 0 on a curve at given loads),zones (the number of stick and
// slip zones),stick_start (-1 in the paper's structure); shortest round-trip digits.
// For a physical scene (`si` given: its scene and each row's contact width, one width for all
// rows but where the width follows the tangential load) the columns P1_N_per_m,xi1,xi1_carter follow, and after status
// P1_N_per_m_error_estimate,xi1_error_estimate (estimate_si, io/si_estimate.hpp: the row's estimates scaled; empty
// without; a refused row's given P1 = Q P2 an exact 0 at a given load). The column status is `ok` or `refused`: a refused
// row (curve_point, contact.hpp) has only its given load Q with Q_over_f and Carter's columns
// (P1_N_per_m and xi1_carter too), or its given c0 on a swept curve; every other field is empty.
struct si_context {
    physical_scene scene;
    std::vector<contact_width> widths;  // one per row of the curve
};
// `nodes`: each row's n (scene_curve::nodes: the ladder's rung), in the column n (empty where 0 or
// not given).
void write_curve_csv(std::ostream& out, const std::vector<curve_point>& curve,
                     const std::optional<si_context>& si = std::nullopt, const std::vector<int>& nodes = {});

// The `#` lines `roughroll curve` writes before write_curve_csv's header, as the traction CSV
// has them: "# roughroll X.Y.Z", the scene (its file and label), how the curve was solved
// (f, method, n, zone search, given loads or swept in c0), and each column's meaning and unit
// (the SI columns' too when `physical`). Every line starts with '#': CSV readers skip them.
struct curve_header {
    std::string scene_path;
    std::string label;
    double friction;
    solver_options solver;  // n = 0: the ladder chose each row's n (column n) for solver.tolerance
    bool swept;             // loads Q(c0) of a sweep in c0, else the curve's given loads
    bool physical;          // the columns P1_N_per_m, xi1, xi1_carter follow
    bool continued;         // dissimilar rollers swept: the given loads, each row from the previous row's zones
};
void write_curve_header(std::ostream& out, const curve_header& h);

}  // namespace roughroll
