// SPDX-License-Identifier: GPL-3.0-or-later
// The ladder that chooses n (issue 24, 5; docs/performance.md "The ladder chooses n"): where a
// scene gives no n, a point is solved at the method's default n first and, where its checks
// (3.3)-(3.4) fail, its levels refuse it or an estimate is above the tolerance, again at the next
// rung (the default n doubled while below max_nodes, then max_nodes: 128, 256, 512, 1000 for
// `extrapolated` and `one-parameter`, 96, 192, 384, 768, 1000 for `product`, 200, 400, 800,
// 1000 for `paper`). The first rung that meets the tolerance answers, and reports its n; when
// none does, the point is refused (resolution_error) with the best estimate reached.
//
// A thin layer above contact: one contact per rung, built on first use by the caller's factory
// (a physical scene settles its contact width at each rung's n), kept for the next point of a
// curve. At the first rung the point is exactly contact::point and contact::estimate at the
// method's default n, so a point that meets the tolerance there is today's point, digit for digit.
//
// The rungs share their levels through the ladder's level_store (issue 24, 4; level_store.hpp): rung n
// solves n/4, n/2, n (and 2n where its estimate asks), rung 2n n/2, n, 2n (and 4n), so a level whose
// numbers do not depend on which rung asked first (point_model::shareable, the one-parameter limit) is
// solved once per climb and given to every rung after. Other models' levels start from the level below
// them, which differs between rungs: each rung solves them as its own, so that every rung's numbers are
// the ones it gives alone (docs/performance.md "The rungs share their levels").
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "roughroll/problems/level_store.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

// The n the ladder tries for a method, in order: default_nodes(how) doubled while below
// max_nodes, then max_nodes.
std::vector<int> ladder_rungs(method how);
// The rungs below the first that a point of the braked three zones at full coupling on smooth rollers may answer at
// (level_ladder::point; docs/formulation.md 8(q), "Rungs below the first"): default_nodes(how)/4, /2, in order.
std::vector<int> spectral_rungs(method how);

// A rung whose reported point at full coupling failed the checks (3.3)-(3.4): its n, the margins and the zones they
// are of (full_coupling.hpp, failed_checks_error).
struct failed_rung {
    int n;
    traction_checks checks;
    zone_layout layout;
};
// docs/formulation.md 8(q), "A failure the levels settle": three consecutive rungs (coarsest first) whose points have
// the same zones (same_zones) and fail the checks: a margin below zero at all three whose finest value plus the full-coupling rule's bound of
// the three (coupled_change_bound: twice the larger change, unresolved where they stall) and its rounding floor is still
// below zero. The refusal's line (no n answers, what does), or none.
std::optional<std::string> settled_failure(const std::array<failed_rung, 3>& rungs, double Q, double f);

// The refusal where the alternation of full coupling converged at no level of two rungs `first`, `second` = 2 first
// (their points and levels first/4 .. second), at load Q with friction f (docs/formulation.md 8(q), "An alternation
// that converges at no level").
std::string unconverged_everywhere(int first, int second, double Q, double f);

// How an estimate compares with the tolerance tol, quantity by quantity (docs/performance.md "The
// ladder chooses n"): a quantity v with estimate e and scale s is within it when
// e <= max(tol s, r), r its rounding floor at n = max_nodes (error_bound.hpp and contact's floors:
// no rung can do better; `strength`: the kernels' sum |T|, which enters xi's), with s = |P_H/P2| for P_H/P2, |xi| for xi, the slip zone's length 1 - c0 for c0 and
// 1 + start for the stick zone's start (the quantities that converge near full stick, issue 23),
// |Q| for Q(c0) of a swept point.
// Five zones name the second stick zone's ends where its estimate is the larger one folded into c0's or the start's
// (error_estimate::c0_second_zone, start_second_zone), with the same scale.
struct tolerance_check {
    double ratio;          // the largest e / max(tol s, r) over the quantities: within when <= 1
    std::string quantity;  // the quantity of that ratio ("xi", "c0", "the second stick zone's start", ...)
    double estimate;       // its estimate e
    double relative;       // e / s (infinite where s = 0)
    // The least tolerance within which every quantity is (e <= max(tol s, r) for each): the largest e/s of those above
    // their floor r; 0 where all are, infinite where one above its floor has s = 0 (or a NaN estimate).
    double answering = 0.0;
    std::string answering_quantity;  // the quantity whose e/s that is (empty where answering is 0)
};
tolerance_check check_estimate(const tangential_solution& s, double lambda, const error_estimate& e, double tol,
                               double strength = 0.0);

class level_ladder {
public:
    // `make(n)`: the contact of the scene at n nodes (the rung's own contact width for a physical scene).
    // `surfaces`: the scene's roughness (a physical scene's at any width: only the size of its kernels'
    // terms enters, through the rounding floors).
    // `options`: the method (its rungs), the tolerance (default_tolerance when empty) and the zone
    // search: with zone_search::single (the paper's zone, its checks reported and never acted on) a
    // point whose checks fail is answered, flagged, at the rung where it fails, as at a given n: no n
    // makes a wrong zone structure right.
    // With `levels`, the ladder's store, for contact_internals::with_levels: the rungs share their levels. A
    // factory of n alone builds rungs that share none (each solves its levels as its own).
    using rung_factory = std::function<std::unique_ptr<contact>(int n, const std::shared_ptr<level_store>& levels)>;
    level_ladder(const solver_options& options, const roughness& surfaces, rung_factory make);
    level_ladder(const solver_options& options, const roughness& surfaces,
                 const std::function<std::unique_ptr<contact>(int n)>& make);

    // A point answered at the rung `n`, with its estimate (within the tolerance).
    struct answer {
        tangential_solution solution;
        std::optional<error_estimate> estimate;
        int n;
    };
    // The point at Q: the first rung from `from` (an index into rungs()) whose point holds its checks
    // and whose estimate is within the tolerance. Throws resolution_error (one line: the best
    // estimate reached and its n, or why no rung gave one; what to change) when none does.
    // From the first rung (from = 0) a braked point at full coupling on smooth rollers first tries spectral_rungs(),
    // each answering only where its point's stick zone is on its Jacobi weight (8(v), 8(w): levels spectral), its
    // checks hold and its estimate is within the tolerance; those rungs share their levels with each other only, so
    // that where none answers the climb from the first rung is the one without them, digit for digit. Free rolling and
    // the driven side (Q beta_D >= 0) first try spectral_rungs().back() on the climb's own store, answering there only
    // with five zones (8(q), "Rungs below the first": five_zones_below_first).
    answer point(double Q, std::size_t from = 0);
    // The same for the point whose stick zone ends at c0 (contact::at_stick_end, a swept curve).
    answer at_stick_end(double c0, std::size_t from = 0);

    const std::vector<int>& rungs() const { return rungs_; }
    double tolerance() const { return tolerance_; }
    // check_estimate of a point of rung c with this ladder's tolerance: within it when ratio <= 1.
    tolerance_check check(const contact& c, const tangential_solution& s, const error_estimate& e) const;
    // Whether a point of rung c (with its estimate) answers: checks holding and every estimate within
    // the tolerance, or checks failing under zone_search::single.
    bool answers(const contact& c, const tangential_solution& s, const std::optional<error_estimate>& e) const;
    // The contact of rung n (built on first use).
    contact& at(int n);
    // Hands the contact of rung n over (built again if asked for later).
    std::unique_ptr<contact> release(int n);
    // The levels the rungs made and share (level_store::made counts them by n).
    const level_store& levels() const { return *levels_; }

private:
    using solve_rung = std::function<answer(contact&, int n)>;
    // check()'s test as the store gives it to the rungs' estimates (level_store::fails_tolerance): by value.
    level_store::tolerance_test tolerance_test() const;
    // `Q`: the load of a point (rule (a') asks the levels before a rung's point); empty for a swept point.
    answer climb(const solve_rung& solve, std::size_t from, std::optional<double> Q = std::nullopt);
    // Full coupling (docs/formulation.md 8(q)): for each rung above rung i, whether the point `a` of
    // rung i (contact c, refused by the tolerance) shows that its estimate cannot meet the tolerance,
    // and that estimate's certain part (twice rung i's last level changes).
    struct outlook {
        std::vector<bool> fails;
        std::vector<tolerance_check> at_least;
    };
    outlook beyond(const answer& a, const contact& c, std::size_t i) const;
    // Full coupling, rule (a') of 8(q): rung i, which no rung below predicts by (a) (it does not double the rung
    // before: 1000 after 512 or 768), has its levels n/4 and n/2 solved first (kept for its point); where the certain
    // part of its estimate in their change fails the tolerance, that part, and its point is not solved.
    std::optional<tolerance_check> before_point(contact& c, double Q, std::size_t i);
    // The point at Q from spectral_rungs(), where one answers it (point's comment); else nothing.
    std::optional<answer> below_first(double Q);
    // below_first's free rolling and driven side (Q beta_D >= 0): rung spectral_rungs().back() on the climb's store,
    // answering only with five zones.
    std::optional<answer> five_zones_below_first(double Q);

    std::vector<int> rungs_;
    double tolerance_;
    double strength_;     // the kernels' sum |T| (kernel::strength)
    bool smooth_;         // no roughness: the only scenes whose coupled pressure carries the kinks (8(q) rule (a'))
    int order_;           // the levels' order p (order_of)
    method how_;          // the method (spectral_rungs)
    bool flagged_final_;  // zone_search::single: a point whose checks fail is answered as it is
    bool shared_ = true;  // the rungs share their levels (a rung_factory's store); false for a factory of n alone
    rung_factory make_;
    std::shared_ptr<level_store> levels_;  // held by the rungs' contacts too (a released contact outlives the ladder)
    std::shared_ptr<level_store> spectral_levels_;  // spectral_rungs()' own (below_first)
    std::map<int, std::unique_ptr<contact>> built_;
};

// A creep curve whose rows each meet the tolerance (issue 24, 5): creep_curve at `loads` (or
// swept_curve of `points` when `sweep`) on the first rung, exactly as at the method's default n;
// then each row that does not meet the tolerance climbs from the second rung (level_ladder::point,
// at_stick_end); a row no rung answers is a refused row with the ladder's line. `n_used`: each
// row's n (0 for a refused row). `before_row`: as creep_curve's, before each row of the first pass.
std::vector<curve_point> ladder_curve(level_ladder& ladder, const std::vector<double>& loads, int points, bool sweep,
                                      std::vector<int>& n_used, const std::function<void()>& before_row = {});

}  // namespace roughroll
