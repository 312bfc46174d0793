// SPDX-License-Identifier: GPL-3.0-or-later
// One scene's rolling contact: the normal problem solved once (Hertz's closed form
// when the normal kernel is empty) and shared by every creep point of a curve.
//
// With method::extrapolated the contact holds two product-integration levels, n and n/2,
// and reports P_H/P2, c0 and xi by Richardson's rule for order 4, (16 v_n - v_{n/2})/15;
// the distributions (pressure, tractions, checks) are those of level n. Its error estimate
// adds a third level (n/4) to check that the order is 4 (error_estimate, point_estimate.hpp).
//
// The zones of each point are found as options.zones says (zone_search, docs/formulation.md
// section 7): the paper's single zone, and zone_solver's general search where it fails its
// checks (automatic) or always (general). Both levels of an extrapolation take the same path;
// a point of the general path (start > -1) is reported at level n, not extrapolated, with
// the difference from n/2 as its estimate.
//
// With method::one_parameter the contact solves the limit t -> 0 of the model instead
// (one_parameter_solver, docs/formulation.md "The one-parameter limit"): same solutions,
// same conventions, no two-parameter tangential solver.
//
// The model of the points (the paper's, its one-parameter limit, dissimilar rollers at Johnson's
// level or at full coupling) is chosen once (point_model.hpp: paper_model.cpp, dissimilar_model.cpp)
// and keeps its levels at other n; the contact chooses among them: Richardson's lambda in contact.cpp,
// the error estimate's levels and table in estimate_levels.cpp (its rule: point_estimate.hpp), the
// points of a curve swept in c0 in swept_point.cpp.
//
// Its state (the model, its levels, the caches) is contact::impl (src/problems/contact_impl.hpp), behind
// a pointer: this header names only the public values (roughroll.hpp), not the solvers. Move-only, as
// the model it owns.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/model/dissimilar.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/coupling_summary.hpp"
#include "roughroll/problems/error_estimate.hpp"
#include "roughroll/problems/normal_solution.hpp"
#include "roughroll/problems/tangential_solution.hpp"

namespace roughroll {

class normal_cache;  // problems/normal_problem.hpp (a cache the caller may pass; nullptr: none)

class contact {
public:
    // `materials`: Dundurs' beta_D and the coupling level of dissimilar rollers (docs/formulation.md
    // section 8); the default beta_D = 0 is the paper's problem, solved by exactly the same calls.
    // `cache`: the normal problems of the scene solved before (the width search's, whose last
    // trial is the width found: normal_problem.hpp), for this level and its companion; the
    // contact keeps copies, not the cache. (A ladder's rungs, which share their levels, are built by
    // contact_internals::with_levels.)
    contact(const roughness& surfaces, double f, const solver_options& options, const dissimilar& materials = {},
            normal_cache* cache = nullptr);
    contact(contact&&) noexcept;
    contact& operator=(contact&&) noexcept;
    ~contact();

    // The normal solution as reported (lambda extrapolated for method::extrapolated). At full
    // coupling of dissimilar rollers (docs/formulation.md 8(e)) the pressure depends on Q: after a
    // point, the coupled pressure of that point at level n (not extrapolated); before, Johnson's.
    const normal_solution& normal() const;
    // What the alternation of full coupling measured at the last point (offset e, iterations,
    // contraction, pressure change); nullptr at Johnson's level and before a point.
    const coupling_summary* coupling() const;
    double friction() const;

    tangential_solution point(double Q);
    // point(Q) on a curve continued in the load (swept_curve of dissimilar rollers): `previous`, the
    // curve's previous answered row of this contact, starts the zone search (its three zones' ends, or
    // its five zones' ends, Newton's start on each level); where that start does not reach a zone
    // structure whose checks hold, the point's own search answers. The same point to Newton's
    // resolution (validation/test_dissimilar_curve.cpp).
    tangential_solution continued_point(double Q, const tangential_solution& previous);
    const dissimilar& materials() const;

    // A caller's hook, called before each level's solve (and each step of full coupling's
    // alternation) of point(), continued_point(), estimate() and at_stick_end(), and before the
    // general zone search of distribution() (method::extrapolated, level n again): what it throws
    // ends the solve there (the Python module raises KeyboardInterrupt on Ctrl-C). The contact's
    // caches are then as after any failed solve: a later point solves again. Every call reaches the
    // model and its levels with this hook, also a level another rung of a ladder made
    // (level_store.hpp); normal(), coupling(), beyond_every_n(), traction(), slip_velocity() and
    // distributions() solve nothing and call no hook.
    void set_checkpoint(std::function<void()> hook);

    // The solution whose distributions (tractions, slip velocity) belong with s: s itself,
    // or for method::extrapolated the level-n solution at the same Q, whose c0 and xi are
    // level n's (within the error estimate of the extrapolated ones).
    tangential_solution distribution(const tangential_solution& s);

    // The point whose stick zone ends at c0 in [-1, 1], Q = Q(c0) of (4.5): no root search,
    // a creep curve swept in c0. With its estimate (same rules as estimate(), same refusal).
    // Also refused (resolution_error) at an inner c0: Q(c0) outside [0, f], or Q +- its
    // estimate reaching outside [0, f] (no physical point; docs/robustness.md).
    struct swept_point {
        tangential_solution solution;
        std::optional<error_estimate> estimate;
    };
    swept_point at_stick_end(double c0);

    // The estimate for a solution s of this contact (solves the other two levels at s.Q, and level
    // 2n where those show less than the method's order, or for the one-parameter limit always).
    // Throws resolution_error when the levels give no honest estimate (point_estimate.hpp).
    // Empty when s fails its checks (3.3)-(3.4) (no level difference bounds the error of such an
    // answer: it is not the model's solution; the levels are still solved, and refuse the point
    // where they do not converge) or when no three levels fit in [min_nodes, max_nodes] (never
    // for n >= 8).
    std::optional<error_estimate> estimate(const tangential_solution& s);
    // A term estimate() and at_stick_end() add to every estimate they return, given the point, its pressure, what full
    // coupling's alternation measured there (coupling(): null off full coupling), the estimate and whether the point is
    // swept (at_stick_end's: its c0 given, its Q estimated): a physical scene's width error, which the levels (all at
    // this contact's width) cannot see (docs/formulation.md 2(j) "The width's error"; io/scene_point.cpp). None by
    // default.
    using estimate_term = std::function<void(const tangential_solution&, const normal_solution&,
                                             const coupling_summary*, error_estimate&, bool swept)>;
    void set_estimate_term(estimate_term term);

    // Why no n up to `top` can answer the point at Q within the relative `tolerance` (the ladder's,
    // problems/level_ladder.hpp), decided before any solve: one line saying what to change; empty
    // where a rung may answer. Free rolling of smooth rollers at Johnson's level whose edge layers are
    // too thin for n = top (docs/formulation.md 8(n), "Beyond every n").
    std::optional<std::string> beyond_every_n(double Q, int top, double tolerance) const;

    // p1(r) of (3.15) and the slip velocity v(r) of (3.6) (0 on the stick zone; NaN where not resolved,
    // as distributions() says) for a solution d of this contact as returned by distribution(), for every method.
    double traction(const tangential_solution& d, double r);
    double slip_velocity(const tangential_solution& d, double r);
    std::vector<double> slip_velocity(const tangential_solution& d, const std::vector<double>& r);

    // The distributions of d (as distribution() returns it) at each r of `grid`: the pressure
    // p of (4.1), the traction p1 of (3.15), the slip velocity v of (3.6), 0 on the stick zone
    // [start, c0] (3.2), NaN where it is not resolved (the trailing edge layer of a point with its
    // layers neglected, docs/formulation.md 8(n)). Throws numerical_error naming r where any other
    // value is not finite.
    struct distribution_row {
        double r, p, p1, v;
        bool stick;
    };
    std::vector<distribution_row> distributions(const tangential_solution& d, const std::vector<double>& grid);

private:
    // The library's own access to the solvers behind a contact (problems/contact_internals.hpp, not installed).
    friend struct contact_internals;
    struct impl;  // src/problems/contact_impl.hpp
    explicit contact(std::unique_ptr<impl> state);
    std::unique_ptr<impl> impl_;
};

// A swept curve (swept_curve): in c0 for beta_D = 0, continued in the load for dissimilar rollers at
// Johnson's level; input_error at coupling "full" (its alternation keeps no start from a previous row).
void check_sweepable(const dissimilar& materials);

}  // namespace roughroll
