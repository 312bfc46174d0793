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
// The members are defined by idea: the points and their zone structures in contact.cpp, the error
// estimate's levels and table in estimate_levels.cpp (its rule: point_estimate.hpp), the points of a
// curve swept in c0 in swept_point.cpp.
#pragma once

#include <memory>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/model/dissimilar.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/one_parameter.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/zone_solver.hpp"

namespace roughroll {

class contact {
public:
    // `materials`: Dundurs' beta_D and the coupling level of dissimilar rollers (docs/formulation.md
    // section 8); the default beta_D = 0 is the paper's problem, solved by exactly the same calls.
    // `cache`: the normal problems of the scene solved before (the width search's, whose last
    // trial is the width found: normal_problem.hpp), for this level and its companion; the
    // contact keeps copies, not the cache.
    contact(const roughness& surfaces, double f, const solver_options& options, const dissimilar& materials = {},
            normal_cache* cache = nullptr);

    // The normal solution as reported (lambda extrapolated for method::extrapolated). At full
    // coupling of dissimilar rollers (docs/formulation.md 8(e)) the pressure depends on Q: after a
    // point, the coupled pressure of that point at level n (not extrapolated); before, Johnson's.
    const normal_solution& normal() const;
    // What the alternation of full coupling measured at the last point (offset e, iterations,
    // contraction, pressure change); nullptr at Johnson's level and before a point.
    const coupling_summary* coupling() const;
    // The two-parameter tangential solver; for method::one_parameter there is none: throws
    // input_error (use traction() and slip_velocity() below, which serve every method).
    tangential_solver& tangential();
    double friction() const { return f_; }

    tangential_solution point(double Q);

    // A caller's hook, called before each level's solve (and each step of full coupling's
    // alternation) of point(), estimate() and at_stick_end(): what it throws ends the solve there
    // (the Python module raises KeyboardInterrupt on Ctrl-C). The contact's caches are then as
    // after any failed solve: a later point solves again.
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

    // Why no n up to `top` can answer the point at Q within the relative `tolerance` (the ladder's,
    // problems/level_ladder.hpp), decided before any solve: one line saying what to change; empty
    // where a rung may answer. Free rolling of smooth rollers at Johnson's level whose edge layers are
    // too thin for n = top (docs/formulation.md 8(n), "Beyond every n").
    std::optional<std::string> beyond_every_n(double Q, int top, double tolerance) const;

    // p1(r) of (3.15) and the slip velocity v(r) of (3.6) (0 on the stick zone) for a
    // solution d of this contact as returned by distribution(), for every method.
    double traction(const tangential_solution& d, double r);
    double slip_velocity(const tangential_solution& d, double r);
    std::vector<double> slip_velocity(const tangential_solution& d, const std::vector<double>& r);

    // The distributions of d (as distribution() returns it) at each r of `grid`: the pressure
    // p of (4.1), the traction p1 of (3.15), the slip velocity v of (3.6), 0 on the stick zone
    // [start, c0] (3.2). Throws numerical_error naming r where a value is not finite.
    struct distribution_row {
        double r, p, p1, v;
        bool stick;
    };
    std::vector<distribution_row> distributions(const tangential_solution& d, const std::vector<double>& grid);

private:
    // The solution at c0 of this contact's own level (no extrapolation, no estimate).
    // near: refined on the last factorisation (dense_system::solve_near) while sweeping_near_.
    tangential_solution level_at_stick_end(double c0, bool checked, bool near);
    swept_point swept_at(double c0);  // at_stick_end's point, by the route sweeping_near_ picks
    // at_stick_end's refusal (resolution_error) of a load Q(c0) (with `error`: its interval
    // Q +- error) outside [0, f] at an inner c0.
    void refuse_load_outside(const tangential_solution& s, std::optional<double> error) const;
    // The point at Q of this contact's own level: cached, so that the levels of an estimate
    // and the coarse level of an extrapolation are solved once per Q.
    // `checked`: with the checks (3.3)-(3.4) (a point reported), or without (a level of an
    // extrapolation or an estimate).
    // `guess`: a c0 near the root (the level below's), where the root search starts.
    const tangential_solution& level_point(double Q, bool checked, std::optional<double> guess = std::nullopt,
                                           std::optional<double> slope = std::nullopt);
    // estimate() before its check of s's inequalities: the levels' estimate, or its refusal.
    std::optional<error_estimate> levels_estimate(const tangential_solution& s);
    int nodes() const { return options_.nodes(); }
    const normal_solution& normal_level() const;  // this level's own (lambda not extrapolated)
    method level_method() const;                  // product for extrapolated, else the method itself
    bool build_levels();                          // the two other levels of the estimate; false when none fit
    double kernel_strength() const;               // the larger kernel's sum |T|, for the rounding floors
    kernel widest_kernel() const;                 // one term at either kernel's largest rate: the resolution both need
    // The estimate from the three levels' solutions (s of this contact, level-n values `own`): the
    // table of s's structure, the rule of point_estimate.hpp, level 2n solved where it asks.
    error_estimate estimate_from(const tangential_solution& s, const tangential_solution& own,
                                 const std::array<tangential_solution, 3>& at_levels, bool swept);
    // The solution of `level` (an estimate level, or level 2n) on the structure of s: at own's c0
    // for a curve swept in c0, else at s's load on s's zone path (the paper's single zone, the
    // general search, or dissimilar rollers' three zones, five zones or full coupling, each from
    // s's zone ends). resolution_error where the level has no such solution.
    tangential_solution structure_level(contact& level, const tangential_solution& s, const tangential_solution& own,
                                        bool swept);
    // The point at Q of this contact's own level by zone_solver's general search (docs/formulation.md
    // section 7), started from `guess` (the coarse level's zone) when given.
    tangential_solution general_point(double Q, std::optional<zone_guess> guess = std::nullopt);
    // The paper's single zone s where it holds (or options_.zones says "single"); else the
    // general search's answer where it holds its checks (or options_.zones says "general");
    // else s, its checks failed. `coarse`: the coarse level's point, for the guesses.
    tangential_solution zones_for(double Q, tangential_solution s, const tangential_solution* coarse);

    roughness surfaces_;
    solver_options options_;
    double f_;
    dissimilar materials_;
    std::unique_ptr<contact> companion_;                  // method::extrapolated: the coarse level n/2 (product)
    std::vector<std::unique_ptr<contact>> owned_levels_;  // estimate levels not otherwise held
    std::array<contact*, 3> levels_{};                    // the estimate's levels, coarsest first; nullptr: this one
    bool levels_built_ = false;
    bool sweeping_near_ = true;                  // false: at_stick_end's second, fresh-LU route for a refused point
    std::unique_ptr<contact> finer_;             // level 2n: the second chance of a ratio that fails
    void make_finer(int m);                      // finer_ at m = 2n nodes, made once (with this contact's checkpoint)
    std::unique_ptr<normal_solution> normal_;    // owned here, referenced by the solver
    std::unique_ptr<normal_solution> reported_;  // extrapolated lambda, or empty
    std::unique_ptr<tangential_solver> tangential_;
    std::unique_ptr<zone_solver> zones_;  // the general search, on tangential_
    // Dissimilar rollers (beta_D != 0, docs/formulation.md 8): the zones of Johnson's level, on
    // tangential_; every point is reported at level n (not extrapolated), estimated on three levels.
    std::unique_ptr<dissimilar_zones> dissimilar_;
    std::optional<tangential_solution> last_dissimilar_;  // this level's last point
    const tangential_solution& dissimilar_level_point(double Q, std::optional<zone_guess> guess, bool opposite);
    tangential_solution dissimilar_point(double Q);  // Johnson's, then coupled_ where it is set
    // Free rolling of smooth rollers at Johnson's level whose neglected edge layers bound xi's change
    // within the tolerance (docs/formulation.md 8(n)): answered by the no-slip solution.
    bool layers_negligible(double Q) const;
    // The edge layers' bound on xi relative to the no-slip creep for free rolling of smooth rollers at
    // Johnson's level (8(n)), computed once; empty for any other pair or level.
    std::optional<double> free_rolling_layers_;
    std::optional<double> layers_bound(double Q) const { return Q == 0.0 ? free_rolling_layers_ : std::nullopt; }
    tangential_solution johnson_point(double Q);     // Johnson's level, the estimate's levels first
    // Five zones (docs/formulation.md 8(j)) at Q on this level, from `ends` (s1, c1, s2, c2: the
    // coarser level's) when given and Newton converges from them, else without a guess; nullptr when
    // none is found. Cached as last_five_.
    const five_zone_solution* five_level_point(double Q, const std::vector<double>* ends);
    std::optional<five_zone_solution> last_five_;  // this level's last five-zone point
    double last_five_load_ = 0.0;                  // the load it was asked for
    // Full coupling (docs/formulation.md 8(e); materials_.coupling == full, beta_D != 0): the
    // alternation from Johnson's point on this level, cached per Q (coupled_load_).
    std::unique_ptr<full_coupling> coupled_;
    std::optional<double> coupled_load_;  // the load of coupled_'s last point; empty: none solved
    tangential_solution coupled_point_;
    // Johnson's point at Q of this level near `near` (another level's point: its ends start Newton).
    tangential_solution johnson_level_point(double Q, const tangential_solution& near);
    // The fully coupled point at Q of this level from Johnson's point `johnson` of this level;
    // `checked` as full_coupling::solve (the cache keeps a checked point for an unchecked call).
    const tangential_solution& coupled_level_point(double Q, const tangential_solution& johnson, bool checked);
    bool coupled_checked_ = false;
    // The zones workspace a solution of this contact is evaluated with (the coupled one after a
    // point at full coupling).
    dissimilar_zones& zones_of_point();
    std::unique_ptr<one_parameter_solver> limit_;          // method::one_parameter: the only solver
    std::unique_ptr<zone_solver> limit_zones_;            // its general search (docs/formulation.md 7(g))
    std::optional<tangential_solution> last_fine_;         // level n of the last extrapolated point
    std::optional<tangential_solution> last_coarse_;       // level n/2 of the last general-path point
    std::optional<tangential_solution> last_level_point_;  // level_point's cache
    bool last_level_point_checked_ = false;
    std::function<void()> checkpoint_;
    void checkpoint() const {
        if (checkpoint_) checkpoint_();
    }
};

// A curve swept in c0 (contact::at_stick_end) is the paper's single zone: input_error for dissimilar rollers (8(g)).
void check_sweepable(const dissimilar& materials);

}  // namespace roughroll
