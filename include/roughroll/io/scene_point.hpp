// SPDX-License-Identifier: GPL-3.0-or-later
// One creep point of a scene as the command line (`roughroll point`) and the Python module
// report it: the solver overrides checked like the scene file's, the contact width of a
// physical scene (docs/formulation.md 2(j)), the point of (3.21)-(3.22) for the load, its
// error estimate and its SI units. One implementation, so that both print the same numbers.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_width.hpp"
#include "roughroll/problems/creep_curve.hpp"

namespace roughroll {

// The command line's --n, --method, --zones and --tolerance (or the Python keywords n=, method=,
// zones=, tolerance=) over the scene's [solver] table: n checked against [min_nodes, max_nodes]
// (0 would otherwise mean the method's default), the method's and the zone search's names as the
// scene file's, the tolerance by check_tolerance. n and the tolerance replace each other (n fixes
// the nodes, the tolerance lets the ladder choose them: problems/level_ladder.hpp); giving both
// is an input_error.
void override_solver(scene& s, std::optional<int> n, const std::optional<std::string>& method_name,
                     const std::optional<std::string>& zones_name = std::nullopt,
                     std::optional<double> tolerance = std::nullopt);

// Whether the contact width of the scene depends on the tangential load: a physical scene of
// dissimilar rollers at full coupling, whose lambda = P_H/P2 has the term in p1 (docs/formulation.md
// 8(c), 8(e)). Its width is settled per load; every other scene's width serves every load.
bool width_follows_tangential_load(const scene& s);

// For a physical scene: the contact width for its load (find_width, with lambda as the
// scene's method reports it), and s.surfaces set to the roughness (3.26) at that width.
// Nothing for a dimensionless scene.
// `cache`: the search's product-integration workspaces, for a contact built at the width found.
// `Q`: the tangential load P1/P2, required when width_follows_tangential_load (lambda of the fully
// coupled point at Q, searched from the width of Johnson's level, which the pressure alone fixes:
// smooth rollers by the coupled load ratio alone, rough ones through a store of levels whose last
// point the contact at the width found takes; docs/formulation.md 2(j)); ignored otherwise.
// `checkpoint`: contact::set_checkpoint's hook for the coupled points of the search.
std::optional<contact_width> settle_width(scene& s, normal_cache* cache = nullptr,
                                          std::optional<double> Q = std::nullopt,
                                          const std::function<void()>& checkpoint = {});

// A physical scene's point in SI units (nothing for a dimensionless scene).
std::optional<si_point> si_of(const scene& s, const std::optional<contact_width>& w, const tangential_solution& t);

// Why no n the ladder tries (problems/level_ladder.hpp) can answer the point of s at the load Q within the
// scene's tolerance, decided before any solve and before a physical scene's width is settled: one line saying
// what to change (contact::beyond_every_n for the ladder's top rung); empty where a rung may answer, and
// where s gives n (no ladder). solve_point refuses such a point, and curve_of such a row, with this line.
std::optional<std::string> beyond_every_n(const scene& s, double Q);

// A solved point with everything its report refers to.
struct scene_point {
    scene settled;  // the scene, its surfaces at the contact width
    std::optional<contact_width> width;
    contact solved;
    tangential_solution solution;
    double
        seconds;  // wall time of the width search, the normal and the tangential solves (with the ladder: every rung tried, estimates included)
    std::optional<error_estimate> estimate;

    point_report report() const;  // what to_json and write_summary print (its n: the rung's, with the ladder)
};

// load_of(s, load), settle_width, the contact and its point for the load, and its estimate. Where
// the scene gives no n, the ladder chooses it (problems/level_ladder.hpp): the method's default n
// first (today's point where it meets the tolerance), then larger n, each rung with its own
// contact width; resolution_error when no rung meets the tolerance.
// `checkpoint`: called before each level's solve (contact::set_checkpoint); what it throws ends the solve.
scene_point solve_point(scene s, const std::optional<load_given>& load, const std::function<void()>& checkpoint = {});

// A creep curve of a scene: creep_curve at `loads` (curve_loads(points, ...) when none), or
// swept_curve of `points` when `sweep`, with each row's contact width for a physical scene.
struct scene_curve {
    scene settled;  // its surfaces at the (last) width settled
    std::vector<curve_point> rows;
    std::vector<contact_width> widths;  // a physical scene: one per row, else empty
    std::vector<int> nodes;             // each row's n (the ladder's rung; 0 for a refused row)
};
// One width for every row, settled once; where the width follows the tangential load
// (width_follows_tangential_load), a width per row, settled at the row's load. A row whose width
// search is refused (resolution_error) is a refused row; its width is Johnson's level's, which
// carries the same load P2 (a refused row reports only P1 and Carter's creep: both depend on P2 alone).
// `before_row`: as creep_curve's, called before each row (the CLI's progress line); `checkpoint`:
// called before each level's solve of a row (contact::set_checkpoint; the Python module's Ctrl-C).
// Where the scene gives no n, each row meets the tolerance (ladder_curve, problems/level_ladder.hpp;
// a row whose width follows the load climbs with its own widths).
scene_curve curve_of(scene s, const std::optional<std::vector<double>>& loads, int points, bool sweep,
                     const std::function<void()>& before_row = {}, const std::function<void()>& checkpoint = {});

}  // namespace roughroll
