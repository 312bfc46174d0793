// SPDX-License-Identifier: GPL-3.0-or-later
// The error estimate of a point from three levels of its discretisation (docs/performance.md, "How
// the error estimates are made"): one rule for every zone structure. A structure gives a table of
// its quantities (P_H/P2, the creep, the zone ends or the load, each with its rounding floors), its
// solutions on the three levels, and level 2n on demand; the rule bounds each quantity by
// numerics/error_bound.hpp, gives the second chance and the confirmation one level finer, names the
// levels used, and refuses the point (resolution_error) where they do not converge visibly.
#pragma once

#include <array>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/coupling_summary.hpp"
#include "roughroll/problems/error_estimate.hpp"
#include "roughroll/problems/normal_solution.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

// The rounding floors of an estimate at n nodes, n eps times the size of the terms each quantity is
// computed from: |P_H/P2| for P_H/P2, |xi| + f K for xi with K = max(1, P_H/P2, sum |T| of a kernel)
// (the right-hand side f G of (4.4), and the kernel terms that cancel to xi; on the paper's zone plus
// eps f/(pi rho), the load's rounding ulp(f) times d xi/dQ = 1/(pi rho), formulation 7(d)), min(K'/rho,
// 2 sqrt(K'/(n eps))) with K' = max(1, P_H/P2) for c0 (the rounding of Q(c0) of (4.5) divided by
// Carter's slope |dQ/dc0| = f rho, or the square-root inversion near gross sliding), f K' for Q.
// For the point s with level-n values `own` (s itself, or the level-n solution of an extrapolated
// s), P_H/P2 = `lambda` as reported, friction `f`, `strength` the larger kernel's sum |T|.
struct rounding_floors {
    double lambda, c0, xi, Q;
};
rounding_floors floors_at(int n, const tangential_solution& s, const tangential_solution& own, double lambda, double f,
                          double strength);

// The floor of the ends of dissimilar rollers' zones at m nodes (formulation 8(m)): c0's floor
// `c0_floor`, twice Newton's resolution zone_end_resolution (the difference of two levels carries
// both), and near gross sliding the entry condition's rounding moved by rho/|b_0| (entry_ends_floor).
double zone_ends_floor(int m, double c0_floor, const tangential_solution& s, double lambda, double f, double strength);

// What a floor of zone ends over `levels` gains where a level's Newton stopped at its rounding (docs/formulation.md 8(q),
// "The estimates' floor of the zone ends"): each level's ends lie within its ends_resolution, so a difference of two
// carries up to twice the largest; zone_ends_floor has twice zone_end_resolution, so twice the excess over it (0 where
// every level met the tolerance).
double newton_floor_excess(std::initializer_list<const tangential_solution*> levels);

// The structures whose estimates differ in rule or in name: the paper's problem (beta_D = 0, every
// zone search, the one-parameter limit), dissimilar rollers at Johnson's level (three or five zones,
// level n reported, not extrapolated), and at full coupling (8(e): twice the larger of the last two
// level changes, no asymptotic rule; 8(q): three times the last change, at least a 2^p-th of the one before,
// where the changes contract and the kinks are carried and resolved).
enum class estimate_structure { paper, dissimilar, full_coupling };

// What a table reads off a level's solution: its accessors (the second stick zone's ends are the
// layout's, tangential_solution::start2, end2).
using solution_value = double (*)(const tangential_solution&);
inline double value_xi(const tangential_solution& s) { return s.xi; }
inline double value_c0(const tangential_solution& s) { return s.c0(); }
inline double value_Q(const tangential_solution& s) { return s.Q; }
inline double value_start(const tangential_solution& s) { return s.start(); }
inline double value_start2(const tangential_solution& s) { return s.start2(); }
inline double value_end2(const tangential_solution& s) { return s.end2(); }

// One row of a structure's table: a quantity, read off each level's solution (`value`; nullptr:
// the level's P_H/P2), its rounding floors at the finest of the three levels and at 2n (the second
// chance's finest level), and the error_estimate member it is folded into (the largest of the
// quantities folded into one member).
struct estimated_quantity {
    const char* name;
    solution_value value;
    double floor;
    double finer_floor;
    bool extrapolated;   // reported as Richardson's value of levels n and n/2
    bool second_chance;  // bounded from n/2, n, 2n where n/4, n/2, n give no estimate
    double error_estimate::*out;
    // A zone end of Newton's: where a level's Newton stopped at its rounding above zone_end_resolution, the floor (which
    // has twice zone_end_resolution, zone_ends_floor) gains twice the excess of the levels' largest resolution
    // (newton_floor_excess).
    bool newton_end = false;
};

// Whether q is an end of the second stick zone (five zones), read off by the layout's accessors start2, end2: folded into
// c0's or the start's member, it is named there as its own (error_estimate::c0_second_zone, start_second_zone).
inline bool of_second_zone(const estimated_quantity& q) { return q.value == value_start2 || q.value == value_end2; }

// A level's solution on the structure of the point, and the level's P_H/P2.
struct estimate_level {
    tangential_solution solution;
    double lambda;
};

// The point estimated, as the rule and its refusal name it.
struct estimate_point {
    method how;
    int n;
    int self;  // level n's index among the three: 2 (n/4, n/2, n), 1 (n/2, n, 2n), 0 (n, 2n, 4n)
    estimate_structure structure;
    bool richardson;   // its creep and c0 are Richardson's values: the estimate is against level n
    bool checks_hold;  // its inequalities (3.3)-(3.4) hold: the second chance is given
    const char* at;    // the input a refusal names, "Q" or "c0"
    double at_value;
    // Full coupling with the pressure's and the blends' kinks carried (smooth rollers, 8(r)): where every zone also
    // holds two nodes of the coarsest level, the levels' changes are read by the three-level rule (8(q)).
    bool kinks_carried = false;
    // Full coupling on rough rollers (layers on either cylinder): changes of opposite sign outside the three-level rule
    // are confirmed on level 2n (8(q) "Changes of opposite sign"); smooth rollers keep their measured rules.
    bool rough = false;
    // n given by the caller, not a ladder's rung: a refusal at n < max_nodes may then advise leaving n out (on a rung
    // the ladder already tries the larger n, and its line would advise what the user did).
    bool n_given = true;
    // A ladder's rung (level_store::fails_tolerance): whether an estimate fails the ladder's tolerance. Where changes of
    // opposite sign would be confirmed on level 2n and the estimate from n/4, n/2, n already fails it, level 2n is not
    // solved (a confirmation only raises an estimate, or refuses it: the rung cannot answer either way), and the
    // estimate is marked a lower bound (error_estimate::lower_bound); `lower_bound` then tells peak_from_levels.
    std::function<bool(const error_estimate&)> fails_tolerance = nullptr;
    bool lower_bound = false;
    // Full coupling on smooth rollers: level n/8 on the structure of level n's point (held by the level store or solved;
    // empty where it cannot be), asked only where a zone end's changes over n/4, n/2, n are clean: its second ratio
    // checks the rest of the Richardson level (richardson_end). Unset: no zone end is extrapolated.
    std::function<std::optional<estimate_level>()> coarser = nullptr;
};

// The order p of the levels' error, ~ C n^-p, for method `how` (error_bound's rule, and each level's start from the
// two below it, collocation_model::point): 4 where the levels are product integration's ('product', 'extrapolated'),
// 2 for the paper's node sum and the one-parameter limit.
int order_of(method how);

// The fewest nodes of the m-point Gauss-Chebyshev rule (cos(k pi/(m + 1))) inside one zone of s (from -1 through
// the zone ends to 1): below two the zone's ends fall between the same nodes and their changes with n are not
// convergence (8(q) "The three-level rule at full coupling").
// With `widen`, each zone widened by it at both ends (inside [-1, 1]): a bound for every s' whose ends lie within widen
// of s's, whose zones lie inside those (may_take_three_level).
double fewest_zone_nodes(const tangential_solution& s, int m, double widen = 0.0);

// The table of dissimilar rollers' estimate (contact's, estimate_levels.cpp; rule (a')'s, changes_before_point):
// P_H/P2 (its levels Richardson's where `lambda_extrapolated`), xi, the stick zone's ends with floor `ends` (`finer_ends`
// one level finer), and with `two_zones` the second stick zone's ends, their bounds folded into c0's and the start's
// (each reported bound the larger of the two zones', formulation 7 "What c0 means").
std::vector<estimated_quantity> zone_ends_table(const rounding_floors& floor, double ends, double finer_ends,
                                                bool lambda_extrapolated, bool two_zones);

// 8(q) rule (a'): what the full-coupling estimate of rung m (levels m/4, m/2, m) holds for certain from its levels m/4
// (`quarter`) and m/2 (`half`), solved before its point (point_model::levels_before) and read again by its estimate:
// every branch of the rule (coupled_bound) gives each quantity at least k |x_{m/2} - x_{m/4}|, k = 3/2^p where rung m
// may take the three-level rule, else 2 (a stall or a non-finite level gives no estimate at all). Those changes, less
// rule (a)'s noise (the floor at m and 4 times the alternation's tolerance; here a margin only, the levels being the
// rung's own), each the largest of the quantities folded into one member as the estimate folds them. The second stick
// zone's ends where both levels have five zones (the rung's point then has them too: its levels are solved on the
// structure of its Johnson's point, which its alternation keeps).
level_changes changes_before_point(const estimate_level& quarter, const estimate_level& half, int m, double f,
                                   double strength);
// The full-coupling rule's bound (coupled_bound: twice the larger change, or their geometric rest; unresolved where the
// changes stall) of a quantity over three rungs that are no estimate's levels: a checks margin of the reported points
// (the ladder's settled failure, docs/formulation.md 8(q) "A failure the levels settle").
error_bound coupled_change_bound(const three_levels& v, double floor);
// Whether rung m's point, each of its zone ends within `delta` of `half`'s (level m/2's), can have every zone two nodes
// of level m/4 wide (the three-level rule's test, takes_three_level): the zones of `half` widened by delta at each end
// inside (-1, 1). Never without the pressure's kinks, which only smooth rollers carry (`smooth`).
bool may_take_three_level(const tangential_solution& half, int m, double delta, bool smooth);

// The estimate from the three levels (coarsest first). Per quantity: error_bound's rule; where the
// three levels show no estimate, a second chance on n/2, n, 2n (only for a point whose checks hold,
// and only where those show at least order p - 1, since three pre-asymptotic levels of a very stiff
// layer can look convergent by chance); for the paper's problem, where they show less than the
// method's order or a ratio beyond 2^(p+2), and always for the one-parameter limit, level 2n
// confirms (the larger of the two bounds). `finer`: level 2n, solved on the first call that needs
// it; empty where n is not the finest level or 2n cannot be solved. Throws resolution_error where
// no honest estimate is found.
error_estimate estimate_from_levels(const std::vector<estimated_quantity>& table,
                                    const std::array<estimate_level, 3>& levels,
                                    const std::function<std::optional<estimate_level>()>& finer,
                                    const estimate_point& point);

// The peak pressure's estimate at level n (pressure_peak, normal_solution.hpp) from the peaks `peaks` of the pressures
// of the three levels (coarsest first) whose normal solutions the point's estimate solved: no solve of its own. The
// rule of the point's other quantities on the same levels (error_bound's; at full coupling twice the larger change
// with its geometric tail, 8(e), not 8(q)'s three-level rule), with floors: for r twice the largest resolution of a level's position (the golden section's band, pressure_peak),
// for p the pressure's rounding at the finest level. Where the levels show no order, twice the larger of the two
// changes, plus the changes from level n up to the finest (docs/performance.md "The peak pressure's estimate"): no
// refusal. Where the changes change sign with the last above the floor, level 2n's peak (`finer`, solved on demand)
// confirms (8(e) "The peak confirmed on level 2n"), on every structure but full coupling of smooth rollers: off full
// coupling by the paper's confirmation on n/2, n, 2n, without refusal (where level 2n is not at hand or shows no order,
// twice the larger change as above); at full coupling on rough rollers as the other quantities' (8(q) "Changes of
// opposite sign"), and as theirs, the peak is refused (resolution_error) where level 2n cannot be solved or n/2, n, 2n
// show no estimate: a ladder's rung then climbs. Not confirmed where point.lower_bound (the estimate is a lower bound
// already) or 2n > max_nodes (8(q)'s limit). Off full coupling also where the three levels are not doublings (n not a
// multiple of 4) or their changes fall faster than 2^p: confirmed there on the level above them (`finer`: 2n, or 4n
// where level n is their middle; 8(e) "The peak on levels that are not doublings").
// `slopes_r`: at full coupling the position's bound from two levels' pressures (peak_position_from_slopes), the
// estimate of r where it is the larger (with r's floor); 0 elsewhere.
peak_error peak_from_levels(const std::array<pressure_peak, 3>& peaks, const estimate_point& point,
                            const std::function<std::optional<pressure_peak>()>& finer, double slopes_r = 0.0);
// The peak position's bound at full coupling (docs/formulation.md 8(e), "The peak's position from the slopes"): level
// n's pressure `level` with its peak at r, and the pressure `other` of the level next to it (n/2, or 2n where n is the
// coarsest): share times the largest slope of their difference over a node spacing of the coarser level around r, over
// the least curvature of level n's pressure there (share 1/(rho - 1) where level n is the finer, 1/(1 - 1/rho) where the
// coarser, rho = 1.3). Where a zone end of `ends` lies in that window, at least `ends_estimate` (the ends' own estimate:
// the peak may sit at the end's kink); 0 (no bound) where the pressure is not concave on it and no end lies there.
double peak_position_from_slopes(const normal_solution& level, int level_n, const normal_solution& other, int other_n,
                                 double r, const std::vector<double>& ends, double ends_estimate);
// Whether peak_from_levels asks `finer` (level 2n) of these peaks at this point, point.lower_bound aside.
bool peak_asks_level_two_n(const std::array<pressure_peak, 3>& peaks, const estimate_point& point);
// Full coupling's measured values at one level's point (docs/formulation.md 8(e), "The measured values' estimates"): the
// offset e = x_c/a and gamma_0n of its pressure (normal_solution), Johnson's P_H/P2 and the peak pressure's change at
// the same P2 of its alternation (coupling_summary).
coupling_values reading_of(const normal_solution& pressure, const coupling_summary& alternation);
// Their estimates from the levels' readings by the peak value's rule (peak_from_levels: at full coupling twice the
// larger change with the geometric tail, plus the changes above level n; changes of opposite sign confirmed on level
// 2n, `finer`, only where the point's estimate solved it: a printed value solves no level and refuses nothing, NaN
// instead), each with the floor of its levels' rounding; offset e's alternation share is the caller's
// (estimate_levels.cpp). gamma_0n and the peak's change: NaN (their alternation share is not bounded, 8(e)).
coupling_values coupling_from_levels(const std::array<coupling_values, 3>& levels, const estimate_point& point,
                                     const std::function<std::optional<coupling_values>()>& finer);
// The same for a point of the general zone search whose estimate is the difference from level n/2 (contact::estimate):
// the peak's difference from `coarse`'s, with the floors above at n nodes.
peak_error peak_from_difference(const pressure_peak& level, const pressure_peak& coarse, int n);

// One Richardson level of order 2 for a zone end at full coupling (docs/formulation.md 8(q), "One Richardson level for
// the zone ends"), from its levels n/4, n/2, n (`v`) and n/8 (`eighth`, empty where it is not at hand); `noise` the floor
// of a difference of two levels (the estimate's floor of the ends and the alternation's tolerance, as the carried
// changes'), `order` the method's p. The end's changes d0 = x_{n/4} - x_{n/8}, d1 = x_{n/2} - x_{n/4},
// d2 = x_n - x_{n/2} are clean order 2 where |d2| is at least ends_clean_changes times the noise, 3 <= d0/d1 <= 5 and
// 3 <= d1/d2 <= 5 (one sign, falling 3 to 5 times per doubling) and |d1/d2 - 4| <= |d0/d1 - 4| (the rest beyond C/k^2
// falls at least as fast as the changes: r >= d1/d2 >= 3 for a geometric rest); there the value x_n + d2/3 and its error
// max(2 |delta|, |d2|/2^p) + 3 noise, delta = (4 d2 - d1)/3 the change of the Richardson values from n/2 to n.
// Elsewhere empty, never a smaller estimate: the end keeps level n's value and its own estimate.
inline constexpr double ends_least_ratio = 3.0, ends_most_ratio = 5.0, ends_clean_changes = 4.0;
// Whether changes d_coarse, d_fine (the finer last) fall 3 to 5 times with the finer at least ends_clean_changes times
// the noise: the first test of richardson_end, on n/4, n/2, n (asked before level n/8 is).
bool ends_clean_ratio(double d_coarse, double d_fine, double noise);
std::optional<zone_end_value> richardson_end(std::optional<double> eighth, const three_levels& v, double noise,
                                             int order);

// The first words of every refusal of an estimate: "no honest error estimate for method 'M' at
// n = N (the structure): ".
std::string no_honest_estimate(method how, int n, estimate_structure structure);

}  // namespace roughroll
