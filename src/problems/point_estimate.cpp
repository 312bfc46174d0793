// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/point_estimate.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/normal_problem.hpp"

namespace roughroll {

rounding_floors floors_at(int n, const tangential_solution& s, const tangential_solution& own, double lambda, double f,
                          double strength) {
    // The size of the terms of (4.4)-(4.5): the pressure's scale P_H/P2 (through G) and the
    // kernels' strength sum |T| (a near-constant kernel T exp(-A |z|), A << 1, multiplies
    // int q = O(f) by T, and those terms cancel to xi: a tangential layer T = 100, A = 1e-3
    // loses 1e-13 absolute in xi = 3e-8 at n = 128).
    const double size = std::max({1.0, std::fabs(lambda), strength});          // for xi
    const double n_eps = rounding_floor(n, std::max(1.0, std::fabs(lambda)));  // for c0 and Q
    // c0: Q(c0) of (4.5) rounds to about n eps f K (an O(f) sum whose terms grow with G of
    // (3.25)); near gross sliding Q = f (1 - rho^2) (Carter), so c0 = 2 rho - 1 moves by
    // min(n eps K/rho, 2 sqrt(n eps K)), K = max(1, P_H/P2). On the paper's single zone the
    // special loads Q = 0 and |Q| = f are solved without a system (c0 = 1, -1 exactly); the
    // general search's zone at |Q| = f (the least G) is computed.
    const bool special = !s.layout.general() && (s.Q == 0.0 || std::fabs(s.Q) == f);
    double c0_floor = special ? 0.0 : std::min(n_eps / own.rho(), 2.0 * std::sqrt(n_eps));
    double xi_floor = rounding_floor(n, std::fabs(own.xi) + f * size);
    if (!special && !own.layout.general() && own.rho() > 0.0) {
        // The paper's zone is the root of Q(c0) = f + rho int q (4.5), which rounds to ulp(f) <= eps f
        // whatever the sum's own rounding (times rho, small), and xi moves with the load as
        // d xi/dQ = 1/(pi rho): Carter's exactly, every rough pair's near gross sliding, where
        // f - |Q| ~ rho^2 and xi - xi_gs ~ rho (docs/formulation.md 7(d), "The paper's zone near gross
        // sliding"). So xi carries eps f/(pi rho), above n eps (|xi| + f K) only near gross sliding
        // (1 - |Q|/f = 8.8e-10, rho = 3e-5: 4.4e-14 against 2.3e-16 at n = 32).
        xi_floor += DBL_EPSILON * f / (M_PI * own.rho());
    }
    if (own.layout.general() && !own.psi_b.empty() && own.rho() > 0.0) {
        // A zone of the general search (docs/formulation.md 7(d), 7(e)): xi, b_0 and psi(-1) are
        // read off (4.4), whose terms of size |xi| + f K they cancel (stick_system_floor). The
        // ends solve the load in the gap form rho (pi/2) b_0 = |Q| - f and the entry condition
        // psi(-1)/|b_0| = 0, both relative to b_0, which near gross sliding vanishes like
        // f G'' rho^2/2: the ends move by rho times the floor over |b_0| (the residuals of 7(d)
        // have slopes 2 and 3 in gamma and log rho, which the factor 1 covers).
        const double system = stick_system_floor(n, std::fabs(own.xi) + f * size);
        xi_floor = std::max(xi_floor, system);
        c0_floor = std::max(c0_floor, own.rho() * system / std::fabs(own.psi_b[0]));
        if (own.forcing != 0.0) {
            // Dissimilar rollers' zones solve the load as the absolute residual Q' - |Q| of an O(f) sum (8(g):
            // f + rho int q, and where the zone is blended 2 f int_H p - 2 f beside it), not in the gap form: Q'
            // rounds to eps S_Q, S_Q = 5 f blended (layout.opposite()), f else, and xi moves with the load as
            // d xi/dQ = 1/(pi rho) as on the paper's zone above (docs/formulation.md 8(m), "The creep's floor near
            // gross sliding").
            xi_floor += DBL_EPSILON * (own.layout.opposite() ? 5.0 : 1.0) * f / (M_PI * own.rho());
        }
    }
    if (own.layout.stick_zones() > 1 && own.zone_systems) {
        // Five zones (docs/formulation.md 8(j)): each stick zone has its own system (zone_system(k)), and xi is read
        // off (4.4) of each as off the general search's one zone above (7(d), 7(e)), cancelling terms of size
        // |xi| + f K: the same floor (stick_system_floor), which the point's empty psi_b had left out. Their ends are
        // Newton's, whose recorded resolution is their floor (zone_ends_floor, newton_floor_excess). Free rolling of
        // data/aluminium-on-steel.toml at f = 1e-6, n = 1000 had been refused on xi's level changes 6.7e-16, -2.8e-14
        // (1.5 times n eps |xi|, 0.19 times this floor; formulation 8(q) "Five zones' xi at its rounding").
        xi_floor = std::max(xi_floor, stick_system_floor(n, std::fabs(own.xi) + f * size));
    }
    return {rounding_floor(n, lambda), c0_floor, xi_floor, f * n_eps};
}

double zone_ends_floor(int m, double c0_floor, const tangential_solution& s, double lambda, double f, double strength) {
    // Each level's ends are Newton's within zone_end_resolution where it met that tolerance (where it
    // stopped at its rounding, the rule adds the excess: newton_floor_excess), so the difference of two levels
    // carries up to twice that: below it, a difference is that noise, not a ratio (free rolling of
    // data/aluminium-on-steel.toml at n = 512 had been refused on -1.6e-13, -1.08e-11). Near gross
    // sliding the entry condition's rounding moves the ends by rho/|b_0| times it (formulation 8(m),
    // entry_ends_floor; the braked pair at Q = -0.049999 had been refused on -5.3e-11, -4.1e-10), at
    // the finest level used: m = the three levels' finest, or 2n for the second chance.
    const double terms = std::fabs(s.xi) + std::fabs(s.forcing) * std::max(1.0, std::fabs(lambda)) +
                         f * std::max({1.0, std::fabs(lambda), strength});
    return c0_floor + 2.0 * zone_end_resolution +
           (s.psi_b.empty() ? 0.0 : entry_ends_floor(m, terms, s.rho(), s.psi_b[0]));
}

double newton_floor_excess(std::initializer_list<const tangential_solution*> levels) {
    double resolution = zone_end_resolution;
    for (const tangential_solution* s : levels) resolution = std::max(resolution, s->ends_resolution);
    return 2.0 * (resolution - zone_end_resolution);
}

double fewest_zone_nodes(const tangential_solution& s, int m, double widen) {
    // Nodes cos(k pi/(m + 1)) inside [a, b]: (acos a - acos b)(m + 1)/pi.
    std::vector<double> ends = s.layout.stick_ends();
    ends.insert(ends.begin(), -1.0);
    ends.push_back(1.0);
    double fewest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        const double a = std::clamp(ends[i] - widen, -1.0, 1.0), b = std::clamp(ends[i + 1] + widen, -1.0, 1.0);
        fewest = std::min(fewest, (std::acos(a) - std::acos(b)) * (m + 1) / M_PI);
    }
    return fewest;
}

std::vector<estimated_quantity> zone_ends_table(const rounding_floors& floor, double ends, double finer_ends,
                                                bool lambda_extrapolated, bool two_zones) {
    using est = error_estimate;
    std::vector<estimated_quantity> table = {
        {"P_H/P2", nullptr, floor.lambda, floor.lambda, lambda_extrapolated, false, &est::lambda},
        {"xi", value_xi, floor.xi, floor.xi, false, true, &est::xi},
        {"c0", value_c0, ends, finer_ends, false, true, &est::c0, true},
        {"the stick zone's start", value_start, ends, finer_ends, false, true, &est::start, true}};
    if (two_zones) {
        table.push_back({"the second stick zone's end", value_end2, ends, finer_ends, false, true, &est::c0, true});
        table.push_back(
            {"the second stick zone's start", value_start2, ends, finer_ends, false, true, &est::start, true});
    }
    return table;
}

std::string no_honest_estimate(method how, int n, estimate_structure structure) {
    const char* const named[] = {"", " (dissimilar rollers)", " (dissimilar rollers, full coupling)"};
    return "no honest error estimate for method '" + to_string(how) + "' at n = " + std::to_string(n) +
           named[static_cast<int>(structure)] + ": ";
}

bool ends_clean_ratio(double d_coarse, double d_fine, double noise) {
    const double ratio = d_coarse / d_fine;
    return std::fabs(d_fine) >= ends_clean_changes * noise && ratio >= ends_least_ratio && ratio <= ends_most_ratio;
}

std::optional<zone_end_value> richardson_end(std::optional<double> eighth, const three_levels& v, double noise,
                                             int order) {
    // x_k = x + C/k^2 + e_k: the Richardson values R_k = x_k + (x_k - x_{k/2})/3 remove C/k^2, and delta = R_n - R_{n/2}.
    // Where the rest e_k falls geometrically by r per doubling, R_n - x = delta/(r - 1). The rest moves each ratio of
    // changes off 4 by (ratio - 4) = -e (r - 1)(r - 4)/d at the level pair's finer change d, so from (n/8, n/4, n/2) to
    // (n/4, n/2, n) |ratio - 4| is multiplied by d1/(r d2) = (d1/d2)/r: it does not grow only where r >= d1/d2 >= 3
    // (8(q) "One Richardson level for the zone ends"). Checked, not assumed: both ratios in [3, 5] and the second no
    // farther from 4 than the first; then 2 |delta| holds R_n - x four times over (r - 1 >= 2). A slow rest (r = 1.2 at
    // 0.66 of C/n^2: ratios 3.96 then 3.88, |R_n - x| = 2.5 times the rule's estimate) is refused. Level n/8 not at hand:
    // refused too. Three levels show one ratio only, so a ratio near 4 by chance (the erratic part of 8(q) cancelling in
    // delta) is what |d2|/2^p guards: the rest taken at least a method's-order step of the last change, as the
    // three-level rule's |d1|/2^p (8(q)). Measured against n = 1000 in 8(q). Noise: each level's end lies within
    // s = noise/2 of its discrete solution; R carries 5s/3, delta up to 10s/3, so an observed delta may be short by
    // 5 noise/3 and 2 |delta| by 10 noise/3: with 3 noise added the estimate still holds |delta_true| + 5 noise/6 (r >= 2)
    // wherever delta_true lies (2.5 noise needed). The check asks |d2| >= 4 noise (|d1| >= 12 noise, |d0| >= 36 noise)
    // so that the ratios are the changes', not the noise's.
    if (!eighth) return std::nullopt;
    const double d0 = v.coarsest - *eighth, d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    if (!ends_clean_ratio(d0, d1, noise) || !ends_clean_ratio(d1, d2, noise)) return std::nullopt;
    if (!(std::fabs(d1 / d2 - 4.0) <= std::fabs(d0 / d1 - 4.0))) return std::nullopt;
    const double delta = (4.0 * d2 - d1) / 3.0;
    const double error = std::max(2.0 * std::fabs(delta), std::ldexp(std::fabs(d2), -order)) + 3.0 * noise;
    if (!std::isfinite(error)) return std::nullopt;
    return zone_end_value{v.finest + d2 / 3.0, error, true};
}

int order_of(method how) { return level_of(how) == method::product ? 4 : 2; }

namespace {

// The three-level rule at full coupling (8(q)): the estimate's multiple of the last change where the changes contract.
constexpr double coupled_contracting_share = 3.0;

// The order of a zone end at full coupling (8(q) "A fall faster than the ends' order"): each level places the end at an
// erratic fraction of its node spacing, so the ends' errors fall as 1/n, not as the method's 2^p per doubling (issue 24:
// "the zone ends converge at order 1"); the three-level rule's chance floor |d1|/2^p takes this order for them.
constexpr int coupled_end_order = 1;
int coupled_order(const estimated_quantity& q, int order) { return q.newton_end ? coupled_end_order : order; }

// A zone end's error at level n where its changes fell faster than the method's order allows (docs/performance.md "A
// fall faster than the order at a zone end"): each level places the end at an erratic fraction of its envelope,
// e_k = sigma_k C k^-p with |sigma_k| <= 1 (8(q) "A fall faster than the ends' order", at order p), so
// |d1| = |e_{n/2} - e_{n/4}| <= C n^-p (2^p + 4^p): the change d1 shows the envelope at level n at least
// |d1|/(2^p + 4^p). A small d2 is two errors that agree and shows nothing. Nine times that least envelope, as 8(q)'s
// three-level rule takes at order 1 (there 3 |d1|/2 = 9 |d1|/(2 + 4)).
double end_chance_floor(const three_levels& v, int order) {
    return 9.0 * std::fabs(v.middle - v.coarsest) / (std::ldexp(1.0, order) + std::ldexp(1.0, 2 * order));
}

// Folds quantity q's `value` into its member of e (the larger of the quantities folded into one member; a NaN, folded
// or already there, stays: std::max(0, NaN) is 0, an estimate every tolerance accepts, session 17 review L1) and, where
// it is the larger, records whose zone end the member's value is.
void fold_estimate(error_estimate& e, const estimated_quantity& q, double value) {
    const double before = e.*q.out;
    if (!(before < value || (std::isnan(value) && !std::isnan(before)))) return;
    e.*q.out = value;
    if (q.out == &error_estimate::c0) e.c0_second_zone = of_second_zone(q);
    if (q.out == &error_estimate::start) e.start_second_zone = of_second_zone(q);
}

// The refusal of quantity `name` whose levels `used`, from coarsest_n nodes, gave no estimate.
[[noreturn]] void refuse(const estimate_point& p, const char* name, const three_levels& used, int coarsest_n) {
    std::ostringstream msg;
    msg.precision(3);
    msg << no_honest_estimate(p.how, p.n, p.structure) << name;
    if (!std::isfinite(used.middle - used.coarsest) || !std::isfinite(used.finest - used.middle)) {
        msg << " is not finite on its levels";
        throw resolution_error(msg.str());
    }
    const bool paper = p.structure == estimate_structure::paper;
    msg << " does not converge visibly over " << (paper ? "n = " : "the levels n = ") << coarsest_n << ", "
        << 2 * coarsest_n << ", " << 4 * coarsest_n << " (differences " << used.middle - used.coarsest << ", "
        << used.finest - used.middle << ") at " << p.at << " = " << shortest(p.at_value);  // the user's input, exactly
    // A larger n helps only where its levels fit below max_nodes (the finest is n, or 2n above).
    if (paper)
        msg << (p.n < max_nodes ? "; increase n, or the scene is beyond the method's reach"
                                : "; the scene is beyond the method's reach at the largest n");
    else if (p.n < max_nodes && !p.n_given)  // a ladder's rung: the ladder goes on to the larger n itself
        msg << "; a larger n (at most " << max_nodes << ") may converge";
    else if (p.n < max_nodes)  // the ladder may answer below n too (levels that wobble at n converge below, 8(q))
        msg << "; another n may converge: a larger n (solver.n, --n; at most " << max_nodes
            << "), or leave n out and the ladder of levels tries n up to " << max_nodes;
    else if (p.n_given)  // levels 250, 500, 1000 may wobble where a smaller n's converge (8(q)): the ladder tries them
        msg << "; n is at its largest: a smaller n may converge (leave n out and the ladder of levels tries n up to "
            << max_nodes << ")";
    else
        msg << "; n is at its largest, so the load is beyond the method's reach";
    throw resolution_error(msg.str());
}

// The full-coupling estimate of level n from the changes d1 = x_{n/2} - x_{n/4}, d2 = x_n - x_{n/2} (docs/formulation.md
// 8(e), 8(q) "The three-level rule at full coupling"). Twice the larger change (8(e)), unless `three_level`: the kinks
// carried and every zone holding two nodes of level n/4, where the ends fall 4 to 22 times per doubling but
// erratically, changing sign. There, where the changes contract visibly (d1/d2 >= 2, or <= -4 across a sign change, as
// error_bound's order-2 contraction), three times the last change, but never below three times a 2^p-th of the one
// before, p the quantity's order (`order`: coupled_order, 1 for a zone end): a faster fall than that order is a change
// small by chance (the driven exit at Q/f = 0.9, n = 128: d1/d2 = -192, its distance from n = 1000 13 times |d2|; the
// start at Q/f = 0.85, n = 256: d1/d2 = 13, 5.7 times max(|d2|, |d1|/16) off, 8(q) "A fall faster than the ends'
// order", where 3 max(|d2|, |d1|/2) is derived as nine times the least order-1 envelope each change shows). Measured
// against n = 1000 on 43 such changes, the distance was at most 1.51 times max(|d2|, |d1|/2^4): the factor 3 leaves 2
// for the reference's own error. Never asymptotic.
// Twice the larger change bounds what follows only where the changes fall fast enough. For changes of one sign falling
// by r = d2/d1 per doubling, the geometric rest is T = |d2| r/(1 - r); the estimate is at least 2T (the factor 2 as for
// the larger change), which exceeds 2|d1| only for r > 0.62 (order below 0.7). Where 1/1.2 < r < 1.2 above the floor
// the changes keep their size (free rolling at f = 1e-6: the same change 1.3e-7 per doubling from n = 32 to 512, a
// drift like log n, 8(q) "Changes that do not fall") and the levels give no estimate: unresolved, as where a level is
// not finite. Changes that grow more than that are the pre-asymptotic kind measured in 8(q)'s table (the driven
// exit's -7.2e-8, -2.5e-7, then -7.8e-8, -4.6e-9): twice the larger, as before.
error_bound coupled_bound(const three_levels& v, double floor, bool three_level, int order) {
    const double d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    const double ratio = d1 / d2;
    constexpr double least_fall = 1.2;
    const bool contracts = three_level && (ratio >= 2.0 || ratio <= -4.0);
    const bool one_sign = ratio > 0.0 && std::fabs(d2) > floor;
    const bool stalls = one_sign && ratio > 1.0 / least_fall && ratio < least_fall;
    const double tail =
        one_sign && ratio >= least_fall ? std::fabs(d2) / (ratio - 1.0) : 0.0;  // |d2| r/(1 - r), r = 1/ratio
    const double value =
        contracts ? coupled_contracting_share * std::max(std::fabs(d2), std::ldexp(std::fabs(d1), -order)) + floor
                  : 2.0 * std::max({std::fabs(d1), std::fabs(d2), tail}) + floor;
    const bool resolved = std::isfinite(value) && !stalls;
    return {resolved ? value : 0.0, ratio, false, resolved};
}

// The second chance's bound of level n from n/2, n, 2n (v) where the last change d2 is within the floor F of those levels
// (docs/formulation.md 8(j), "A last change within the floor"): its sign and size are rounding, so the observed ratio
// means nothing (the rough pair's free rolling at n = 384: -1.52e-8, then 4.57e-10 within F = 4.0e-9 had been refused
// as an oscillation). The discretisation change it hides is at most h = |d2| + F, and the one before is at least
// |d1| - F (d1 carries rounding too). Where |d1| - F >= 2h, the levels contract into the floor at least as an order-1
// method's, and the rule assumes they go on so (|e_2n| <= |e_n|/2); then |e_n| <= |e_2n - e_n| + |e_2n| gives
// |e_n| <= 2h, and level n's own rounding adds F: 2h + F (Richardson's value moves |d1|/(2^p - 1) more). Both changes
// within F: bound_error's rounding branch. Else (F < |d1| < 2h + F) no estimate.
error_bound within_floor_bound(const three_levels& v, int order, bool extrapolated, double floor) {
    const double d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    if (std::fabs(d1) <= floor) return bound_error(v, order, reported_value{1, extrapolated}, floor);
    const double hidden = std::fabs(d2) + floor;
    const double shift = extrapolated ? std::fabs(d1) / (std::ldexp(1.0, order) - 1.0) : 0.0;
    const double value = shift + 2.0 * hidden + floor;
    const bool resolved = std::fabs(d1) - floor >= 2.0 * hidden && std::isfinite(value);
    return {resolved ? value : 0.0, d1 / d2, false, resolved};
}

// 8(q) "The three-level rule at full coupling": the kinks carried, and every zone two nodes wide at level n/4.
constexpr double resolved_zone = 2.0;
bool takes_three_level(const std::array<estimate_level, 3>& levels, const estimate_point& p) {
    return p.structure == estimate_structure::full_coupling && p.kinks_carried &&
           fewest_zone_nodes(levels[p.self].solution, p.n >> p.self) >= resolved_zone;
}

// The floors of the peak's estimate from levels whose finest has `finest_n` nodes: each level's position lies within
// its resolution of its pressure's maximum (the golden section cannot choose among pressures equal to rounding,
// pressure_peak), so a difference of two levels carries twice the largest; the value is the pressure at the position,
// a sum of n U-terms (n eps p), and the golden section's 16 eps p (pressure_peak) on each of two levels.
// The centre's p(0) is a sum of the same n U-terms, with the same solve's rounding (its eps |p|/rcond at the peak's
// |p| >= |p(0)|); its golden-section term (none: r = 0 is given) kept, 32 eps, so that one floor serves both values.
peak_error peak_floors(std::initializer_list<pressure_peak> peaks, int finest_n) {
    double resolution = 0.0, scale = 0.0, solve = 0.0, centre = 0.0;
    for (const pressure_peak& k : peaks) {
        resolution = std::max(resolution, k.r_resolution);
        scale = std::max(scale, std::fabs(k.p));
        centre = std::max(centre, std::fabs(k.centre));
        solve = std::max(solve, k.p_rounding);  // the weighted pressure's solve (normal_solution.hpp, 8(w))
    }
    return {2.0 * resolution, rounding_floor(finest_n, scale) + 32.0 * DBL_EPSILON * scale + 2.0 * solve,
            rounding_floor(finest_n, centre) + 32.0 * DBL_EPSILON * centre + 2.0 * solve};
}
}  // namespace

error_bound coupled_change_bound(const three_levels& v, double floor) { return coupled_bound(v, floor, false, 1); }

namespace {
// Whether the peak's r or p over the three levels v (floor: their floor) is confirmed on level 2n: level n the finest,
// 2n within max_nodes, changes of opposite sign with the last above the floor; every structure but full coupling on
// smooth rollers (whose changes of opposite sign were measured bounded by twice the larger, 8(q)). Off full coupling
// error_bound's rule takes alternating changes contracting 4 times or more as 2 |d2|, which a last change small by
// chance makes no bound (session 26 audit F5, docs/formulation.md 8(e) "The peak confirmed on level 2n": product
// integration's peak value of data/fig2a-T1.toml at n = 192, changes +2.9e-8, -2.9e-11 over 48, 96, 192, lay 6.9e-11
// from n = 1000 against 5.9e-11), as the paper's c0, xi and P_H/P2 are confirmed there (estimate_from_levels).
// Off full coupling also on the level above the three (2n, or 4n where level n is their middle) where their ratio is
// no order: the levels are not doublings (n/4 -> n/2 of odd n/2, or odd n; the ratio of an order-p error is then above
// 2^p), or the changes fall faster than 2^p per level (docs/formulation.md 8(e) "The peak on levels that are not
// doublings": the peak value of data/fig2a-T1.toml at n = 14 over 3, 7, 14, ratio 36, lay 2.77e-5 from n = 1000
// against 2.44e-5).
bool peak_confirms(const three_levels& v, double floor, const estimate_point& p) {
    const double d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    if (p.structure == estimate_structure::full_coupling && !p.rough) return false;
    if (!(std::fabs(d2) > floor)) return false;
    const bool alternating = p.self == 2 && d1 * d2 < 0.0;
    if (p.structure == estimate_structure::full_coupling) return alternating && 2 * p.n <= max_nodes;
    const int finest = p.n << (2 - p.self);
    if (p.self == 0 || 2 * finest > max_nodes) return false;
    const bool doublings = (p.n >> p.self) << 2 == finest;
    const bool too_fast = std::fabs(d1) > std::ldexp(1.0, order_of(p.how)) * std::fabs(d2);
    return alternating || !doublings || too_fast;
}
}  // namespace

bool peak_asks_level_two_n(const std::array<pressure_peak, 3>& peaks, const estimate_point& p) {
    const peak_error floor = peak_floors({peaks[0], peaks[1], peaks[2]}, p.n << (2 - p.self));
    return peak_confirms({peaks[0].r, peaks[1].r, peaks[2].r}, floor.r, p) ||
           peak_confirms({peaks[0].p, peaks[1].p, peaks[2].p}, floor.p, p);
}

double peak_position_from_slopes(const normal_solution& level, int level_n, const normal_solution& other, int other_n,
                                 double r, const std::vector<double>& ends, double ends_estimate) {
    // docs/formulation.md 8(e), "The peak's position from the slopes": p_n'(r_n) = 0 = p'(r*), so
    // |r_n - r*| = |e_n'(r_n)|/|p''| (e_n = p_n - p, p'' between them), and the slope error e_n' oscillates with the
    // nodes: its value at r_n is erratic, its largest over a node spacing of the coarser level is not. With the levels'
    // slope difference d' = e_n' - e_m' and the envelope of e' falling at least rho = 1.3 times per doubling (the least
    // measured 1.37, 64 to 128; 1.6 to 2.5 from n = 96 on), max |e_n'| <= max |d'|/(rho - 1) where level n is the finer
    // (m = n/2), max |d'|/(1 - 1/rho) where it is the coarser (m = 2n). The window must hold r* (widened to the bound;
    // where it reaches the whole contact without holding it, no localisation: the contact's width 2). A zone end in the
    // window may place the peak at its kink, which then converges as the end: there the larger of the slopes' bound and
    // the ends' estimate `ends_estimate` (the ends' alone where p_n is not concave on the window).
    constexpr double rho = 1.3;
    const double share = level_n > other_n ? 1.0 / (rho - 1.0) : 1.0 / (1.0 - 1.0 / rho);
    const double width = std::sqrt(std::max(0.0, 1.0 - r * r));
    const double step = M_PI * width / (16.0 * (std::max(level_n, other_n) + 1));  // 16 samples per finer spacing
    double w = M_PI * width / (std::min(level_n, other_n) + 1);                    // one coarser node spacing
    // Each sample of p_a - p_b rounds to both n-term sums (rounding_floor): a secant carries twice that over its step.
    const double scale = std::fabs(level.pressure(r));
    const double rounding = 2.0 * (rounding_floor(level_n, scale) + rounding_floor(other_n, scale)) / step;
    for (int widening = 0;; ++widening) {
        const bool end_inside =
            std::any_of(ends.begin(), ends.end(), [&](double end) { return std::fabs(end - r) <= w + step; });
        const peak_slopes at = slopes_near(level, other, r, w, step);
        const double bound = share * (at.slope_change + rounding) / at.curvature;
        if (!(at.curvature > 0.0) || !std::isfinite(bound)) return end_inside ? ends_estimate : 0.0;
        if (bound <= w) return end_inside ? std::max(bound, ends_estimate) : bound;
        if (w >= 2.0 || widening == 8) return 2.0;
        w = std::min(bound, 2.0);
    }
}

namespace {
// Level 2n's value of a quantity, with the floor of n/2, n, 2n (value_from_levels).
struct finer_value {
    double value, floor;
};

// The peak value's rule (docs/formulation.md 8(e), 8(q)) for one value over the levels v with floor `floor` (its
// `name` for a refusal), level 2n's value from `finer` where the changes alternate (peak_confirms); peak_from_levels'
// three values and full coupling's measured values (coupling_from_levels) alike. A value only printed
// (`printed_only`: the pressure at the centre, full coupling's measured values) neither solves a level nor refuses the
// point: `finer` gives level 2n only where the point's estimate solved it already, and where the rule would need level
// 2n without it, or refuse, the value has no estimate (NaN, printed null).
double value_from_levels(const three_levels& v, double floor, const estimate_point& p, const char* name,
                         const std::function<std::optional<finer_value>()>& finer, bool printed_only = false) {
    const double none = std::numeric_limits<double>::quiet_NaN();
    const int order = order_of(p.how);
    const bool coupled = p.structure == estimate_structure::full_coupling;
    // Changes of opposite sign (peak_confirms). At full coupling on rough rollers (estimate_from_levels): level 2n's
    // rule on n/2, n, 2n bounds level 2n, and level n (its middle) is farther by |x_2n - x_n|; the larger of the two
    // estimates. As the table's quantities, refused where level 2n cannot be solved or n/2, n, 2n give no estimate
    // (a ladder's rung climbs): the three levels' rule is no bound there (8(q) "Changes of opposite sign"). Not
    // confirmed where the estimate is a lower bound already (p.lower_bound: level 2n not solved, the rung cannot
    // answer).
    const double d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    // Off full coupling (8(e) "The peak confirmed on level 2n") the peak is never refused: where level 2n cannot be
    // solved, the rule of levels without a visible order (below), twice the larger change; on n/2, n, 2n the
    // paper's confirmation (confirm_error, as estimate_from_levels' for the table), bounding level n, their
    // middle, and where that shows no order either, the same rule on them.
    const double fine_bound = [&]() {
        if (p.lower_bound || !peak_confirms(v, floor, p)) return 0.0;
        const std::optional<finer_value> above = finer();
        if (!above && printed_only) return none;
        // Level n's value: the middle of n/2, n, 2n; at p.self == 1 (n/2, n, 2n the three, 4n above) their coarsest,
        // |x_2n - x_n| from the middle that confirm_error bounds.
        const double level_n = p.self == 2 ? v.finest : v.middle;
        if (!above && !coupled)
            return 2.0 * std::max(std::fabs(d1), std::fabs(d2)) + std::fabs(v.finest - level_n) + floor;
        if (!above) refuse(p, name, v, p.n >> p.self);
        const three_levels fine{v.middle, v.finest, above->value};
        const double f = above->floor;
        const double up = std::fabs(fine.finest - fine.middle);
        if (!coupled) {
            const error_bound fb = confirm_error(fine, order, false, f);
            return fb.resolved ? fb.value + std::fabs(fine.middle - level_n)
                               : 2.0 * std::max(std::fabs(fine.middle - fine.coarsest), up) +
                                     std::fabs(fine.finest - level_n) + f;
        }
        const error_bound fb = coupled_bound(fine, f, false, order);
        if (!fb.resolved && printed_only) return none;
        if (!fb.resolved) refuse(p, name, fine, p.n >> (p.self - 1));
        return fb.value + up;
    }();
    if (std::isnan(fine_bound)) return none;
    // Level n is levels[self]; the coupled rule bounds the finest level: level n is farther by its changes above.
    const double own = p.self == 0 ? v.coarsest : p.self == 1 ? v.middle : v.finest;
    const double above = std::fabs(v.finest - own);
    // At full coupling twice the larger change, with the geometric tail (coupled_bound without 8(q)'s three-level
    // rule): the peak value of Q/f = -0.75 (data/aluminium-on-steel.toml, coupling = "full") at n = 128 changes
    // -2.5e-7, +1.4e-8 over 32, 64, 128, whose three times 1.6e-8 (4.7e-8) fell short of its distance 5.7e-8 from
    // n = 1000 (validation/test_pressure_peak_estimate.cpp).
    const error_bound b = coupled ? coupled_bound(v, floor, false, order)
                                  : bound_error(v, order, reported_value{p.self, false}, floor);
    if (b.resolved) return std::max(b.value + (coupled ? above : 0.0), fine_bound);
    // No visible order (the peak is not refused): twice the larger change, plus the changes above level n.
    return std::max(2.0 * std::max(std::fabs(d1), std::fabs(d2)) + above + floor, fine_bound);
}
}  // namespace

peak_error peak_from_levels(const std::array<pressure_peak, 3>& peaks, const estimate_point& p,
                            const std::function<std::optional<pressure_peak>()>& finer, double slopes_r) {
    const peak_error floor = peak_floors({peaks[0], peaks[1], peaks[2]}, p.n << (2 - p.self));
    std::optional<pressure_peak> above_peak;
    bool above_tried = false;
    const auto bound = [&](double pressure_peak::*x, double peak_error::*member, const char* name, bool printed_only) {
        const three_levels v{peaks[0].*x, peaks[1].*x, peaks[2].*x};
        return value_from_levels(
            v, floor.*member, p, name,
            [&]() -> std::optional<finer_value> {
                // A printed-only value reads level 2n where the peak's r or p asked it (evaluated before it), no more.
                if (!above_tried && !printed_only) above_peak = finer();
                above_tried = above_tried || !printed_only;
                if (!above_peak) return std::nullopt;
                return finer_value{(*above_peak).*x,
                                   peak_floors({peaks[1], peaks[2], *above_peak}, p.n << (3 - p.self)).*member};
            },
            printed_only);
    };
    // The position's bound from the slopes (peak_position_from_slopes, full coupling), where larger.
    // The pressure at the centre by the value's rule on the levels' p(0) (docs/formulation.md 2(j), "The SI values'
    // estimates"): the same levels, floors and confirmation, at no solve of its own.
    // (Braced: r, p, then the centre, in that order.)
    return {std::max(bound(&pressure_peak::r, &peak_error::r, "the peak pressure's position", false),
                     slopes_r > 0.0 ? slopes_r + floor.r : 0.0),
            bound(&pressure_peak::p, &peak_error::p, "the peak pressure", false),
            bound(&pressure_peak::centre, &peak_error::centre, "the pressure at the centre", true)};
}

coupling_values reading_of(const normal_solution& pressure, const coupling_summary& alternation) {
    return {pressure.offset, pressure.gamma, alternation.lambda_johnson, alternation.peak_pressure_change};
}

coupling_values coupling_from_levels(const std::array<coupling_values, 3>& levels, const estimate_point& p,
                                     const std::function<std::optional<coupling_values>()>& finer) {
    // The levels' rounding, sums of n terms of their size, on each of two levels (docs/formulation.md 8(e), "The
    // measured values' estimates"); the alternation's share is added by the caller where it is bounded
    // (estimate_levels.cpp, as P_H/P2's).
    const auto floor_of = [](std::initializer_list<double> values, int n) {
        double scale = 1.0;
        for (const double x : values) scale = std::max(scale, std::fabs(x));
        return 2.0 * rounding_floor(n, scale);
    };
    std::optional<coupling_values> above;
    bool above_tried = false;
    const auto bound = [&](double coupling_values::*x, const char* name) {
        const three_levels v{levels[0].*x, levels[1].*x, levels[2].*x};
        const double floor = floor_of({v.coarsest, v.middle, v.finest}, p.n << (2 - p.self));
        return value_from_levels(
            v, floor, p, name,
            [&]() -> std::optional<finer_value> {
                if (!above_tried) above = finer();  // level 2n where the point's estimate solved it; else empty
                above_tried = true;
                if (!above) return std::nullopt;
                return finer_value{(*above).*x, floor_of({v.middle, v.finest, (*above).*x}, 2 * p.n)};
            },
            true);
    };
    // gamma_0n = (2/pi) lambda e + C and the peak's change move with C and the peak too, whose distances from the
    // alternation's fixed point it does not bound (8(e)): no estimate (NaN, printed null), none computed.
    const double none = std::numeric_limits<double>::quiet_NaN();
    return {bound(&coupling_values::offset, "the offset e"), none,
            bound(&coupling_values::lambda_johnson, "P_H/P2 at Johnson's level"), none};
}

peak_error peak_from_difference(const pressure_peak& level, const pressure_peak& coarse, int n) {
    const peak_error floor = peak_floors({level, coarse}, n);
    return {std::fabs(level.r - coarse.r) + floor.r, std::fabs(level.p - coarse.p) + floor.p,
            std::fabs(level.centre - coarse.centre) + floor.centre};
}

level_changes changes_before_point(const estimate_level& quarter, const estimate_level& half, int m, double f,
                                   double strength) {
    // The table of contact's estimate (estimate_levels.cpp) at full coupling, with its floors at level m taken at
    // level m/2's solution (only a margin here: subtracting more leaves less certain).
    const tangential_solution& s = half.solution;
    const rounding_floors floor = floors_at(m, s, s, half.lambda, f, strength);
    const double ends = zone_ends_floor(m, floor.c0, s, half.lambda, f, strength);
    const std::vector<estimated_quantity> table = zone_ends_table(
        floor, ends, ends, false, quarter.solution.layout.stick_zones() == 2 && s.layout.stick_zones() == 2);
    error_estimate last{0.0, 0.0, 0.0, 0.0, "", false};
    for (const estimated_quantity& q : table) {
        const double a = q.value ? q.value(quarter.solution) : quarter.lambda;
        const double b = q.value ? q.value(s) : half.lambda;
        const double noise = q.floor + (q.newton_end ? newton_floor_excess({&quarter.solution, &s}) : 0.0) +
                             4.0 * coupling_end_tolerance;
        // A NaN change stays NaN (fold_estimate keeps it): the check then finds no tolerance it meets, as the
        // estimate, which refuses a level that is not finite.
        const double d = std::fabs(b - a);
        fold_estimate(last, q, std::isnan(d) ? d : std::max(d - noise, 0.0));
    }
    return level_changes{last.lambda, last.c0, last.xi, last.start, last.c0_second_zone, last.start_second_zone};
}

bool may_take_three_level(const tangential_solution& half, int m, double delta, bool smooth) {
    if (!smooth) return false;  // kinks_of carries no kinks on rough rollers: no three-level rule
    // A zone of the point lies inside the zone of level m/2 widened by delta, so it holds no more nodes of level m/4.
    return !(fewest_zone_nodes(half, m / 4, delta) < resolved_zone);
}

error_estimate estimate_from_levels(const std::vector<estimated_quantity>& table,
                                    const std::array<estimate_level, 3>& levels,
                                    const std::function<std::optional<estimate_level>()>& finer,
                                    const estimate_point& p) {
    const int order = order_of(p.how);
    const int coarsest_n = p.n >> p.self;
    const bool coupled = p.structure == estimate_structure::full_coupling;
    const bool three_level = takes_three_level(levels, p);
    // Three levels that look converged can still be pre-asymptotic (docs/performance.md, "How the
    // error estimates are made", the fourth level): where they show less than the method's order,
    // and always for the one-parameter limit, whose c0 error changes with c0's place among the nodes
    // and can pass near zero at one level, level 2n confirms: the estimate is also bounded from
    // n/2, n, 2n, and the point is refused where those do not converge visibly.
    const bool always_confirm = p.how == method::one_parameter;
    // An observed order far above the method's (ratio beyond 2^(p+2)) is no sign of the asymptotic
    // range either: a coarsest level far off, or a middle level that lies near the limit by chance
    // (paper at n = 16 near gross sliding: ratio 50 over 4, 8, 16, then a sign change and 6 times
    // the estimate at 32).
    const double too_fast = std::ldexp(1.0, order + 2);
    std::optional<estimate_level> above;
    bool above_tried = false;
    const auto finer_level = [&]() -> const estimate_level* {
        if (!above_tried) above = finer();
        above_tried = true;
        return above ? &*above : nullptr;
    };
    const auto value = [](const estimated_quantity& q, const estimate_level& l) {
        return q.value ? q.value(l.solution) : l.lambda;
    };
    // The floor of q over three levels: a zone end's carries their Newton resolution (newton_floor_excess).
    const auto floor_over = [](const estimated_quantity& q, double floor, const estimate_level& a,
                               const estimate_level& b, const estimate_level& c) {
        return floor + (q.newton_end ? newton_floor_excess({&a.solution, &b.solution, &c.solution}) : 0.0);
    };
    error_estimate e{0.0, 0.0, 0.0, 0.0, "", false};
    bool second_chance = false, confirmed = false;
    // Level 2n confirms quantity q's bound b from n/4, n/2, n on n/2, n, 2n (error_bound.hpp): the
    // larger of the two estimates, or the refusal where n/2, n, 2n do not converge visibly. The floor
    // is the one of those levels' finest, 2n.
    const auto confirm_on_finer = [&](const estimated_quantity& q, const estimate_level& a, const error_bound& b) {
        const three_levels fine{value(q, levels[1]), value(q, levels[2]), value(q, a)};
        const double fine_floor = floor_over(q, q.finer_floor, levels[1], levels[2], a);
        // At full coupling the rule of n/4, n/2, n on n/2, n, 2n: it bounds level 2n, and level n (the middle one
        // there) is farther by |x_2n - x_n|.
        error_bound fb = coupled ? coupled_bound(fine, fine_floor, false, order)
                                 : confirm_error(fine, order, q.extrapolated, fine_floor);
        if (coupled) fb.value += std::fabs(fine.finest - fine.middle);
        if (!fb.resolved) refuse(p, q.name, fine, 2 * coarsest_n);
        fb.value = std::max(fb.value, b.value);
        fb.asymptotic = fb.asymptotic && b.asymptotic;
        confirmed = true;
        return fb;
    };
    // A ladder's rung (point.fails_tolerance): whether the estimate from n/4, n/2, n alone, every quantity's rule
    // without level 2n, already fails the ladder's tolerance. A confirmation only raises an estimate (the larger of the
    // two) or refuses it, so such a rung cannot answer whatever level 2n gives: level 2n is not solved for it (8(q)
    // "Changes of opposite sign": the rough pair braked at Q/f = -0.99, --tolerance 1e-5, rung 256's level 512, 2.6 s of
    // the climb's 17.9 s CPU, rung 512 then skipped by rule (a)). Asked once, where a confirmation is first needed.
    std::optional<bool> fails_unconfirmed;
    const auto fails_before_finer = [&]() {
        if (!fails_unconfirmed) {
            error_estimate unconfirmed{0.0, 0.0, 0.0, 0.0, "", false};
            bool resolved = true;
            for (const estimated_quantity& q : table) {
                const three_levels v{value(q, levels[0]), value(q, levels[1]), value(q, levels[2])};
                const error_bound b =
                    coupled_bound(v, floor_over(q, q.floor, levels[0], levels[1], levels[2]), three_level,
                                  coupled_order(q, order));
                resolved = resolved && b.resolved;
                fold_estimate(unconfirmed, q, b.value);
            }
            // A quantity without an estimate is refused below, as without the ladder's test.
            fails_unconfirmed = coupled && resolved && p.fails_tolerance && p.fails_tolerance(unconfirmed);
        }
        return *fails_unconfirmed;
    };
    bool lower_bound = false;
    std::vector<bool> on_finer(table.size(), false);  // checked on n/2, n, 2n
    std::vector<error_bound> bounds;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const estimated_quantity& q = table[i];
        const three_levels v{value(q, levels[0]), value(q, levels[1]), value(q, levels[2])};
        const double floor = floor_over(q, q.floor, levels[0], levels[1], levels[2]);
        // Full coupling (8(e)): the errors change sign between levels, so no asymptotic rule holds; where the kinks are
        // carried and resolved, the three-level rule of 8(q) (coupled_bound).
        error_bound b = coupled ? coupled_bound(v, floor, three_level, coupled_order(q, order))
                                : bound_error(v, order, reported_value{p.self, q.extrapolated}, floor);
        const bool rounding = std::fabs(v.finest - v.middle) <= floor;  // the ratio then means nothing
        const bool confirm = p.structure == estimate_structure::paper && b.resolved &&
                             (always_confirm || !b.asymptotic || (std::fabs(b.ratio) > too_fast && !rounding));
        const bool chance = !coupled && !b.resolved && p.checks_hold && q.second_chance;
        // A zone end of the structures that confirm nothing on level 2n (Johnson's level): a fall faster than the
        // method's order is a middle level near the limit by chance (as the paper's problem's too fast ratio, which
        // confirms), so the last change tells nothing of level n's error; the estimate is at least nine times the least
        // envelope the change before shows (end_chance_floor; docs/performance.md "A fall faster than the order at a zone
        // end"). A max over every ratio (below about 30 the floor is under |d2| and changes nothing), so that a smaller
        // last change never gives a smaller estimate.
        if (!coupled && !confirm && q.newton_end && b.resolved && !rounding)
            b.value = std::max(b.value, end_chance_floor(v, order) + floor);
        // Full coupling on rough rollers (smooth rollers' changes of opposite sign were measured bounded, 8(q)),
        // changes of opposite sign above the floor: the levels are not yet where twice the larger
        // change bounds what follows (8(q) "Changes of opposite sign": the rough pair braked
        // at Q/f = -0.99, stick start -1.2e-6, +1.0e-7 over n = 32, 64, 128, then -3.2e-6 to 256; level 128 lies
        // 5.2e-6 from n = 1000 against its estimate 2.3e-6). Level 2n confirms; where it cannot be
        // solved, no estimate. Above n = max_nodes/2 no level 2n exists: the rule of three levels stands there, the
        // limit 8(q) states. A ladder's rung that fails its tolerance without level 2n does not solve it
        // (fails_before_finer): its estimate is a lower bound, and rung 2n solves that level as its own point.
        const bool erratic = coupled && p.rough && !three_level && b.resolved && !rounding &&
                             2 * p.n <= max_nodes && (v.middle - v.coarsest) * (v.finest - v.middle) < 0.0;
        if (erratic && p.self == 2 && fails_before_finer()) {
            lower_bound = true;
        } else if (erratic) {
            const estimate_level* a = p.self == 2 ? finer_level() : nullptr;
            if (a != nullptr) {
                b = confirm_on_finer(q, *a, b);
                on_finer[i] = true;
            } else {
                b.resolved = false;
            }
        } else if (confirm) {
            if (const estimate_level* a = finer_level()) {
                b = confirm_on_finer(q, *a, b);
                on_finer[i] = true;
            }
        } else if (chance) {
            // A second chance where n/4 is still pre-asymptotic for this quantity (the second stick
            // zone's end of data/aluminium-on-steel-rough.toml at n = 64 over 16, 32, 64): n/2, n, 2n,
            // accepted only where they show at least order p - 1, or where the last change is within the floor and
            // the one before contracts into it (within_floor_bound).
            if (const estimate_level* a = finer_level()) {
                const three_levels fine{v.middle, v.finest, value(q, *a)};
                const double fine_floor = floor_over(q, q.finer_floor, levels[1], levels[2], *a);
                if (std::fabs(fine.finest - fine.middle) <= fine_floor) {
                    b = within_floor_bound(fine, order, q.extrapolated, fine_floor);
                } else {
                    b = bound_error(fine, order, reported_value{1, q.extrapolated}, fine_floor);
                    if (!(b.ratio >= std::ldexp(1.0, order - 1))) b.resolved = false;
                }
                second_chance = second_chance || b.resolved;
                if (!b.resolved) refuse(p, q.name, fine, 2 * coarsest_n);
                on_finer[i] = true;
            }
        }
        if (!b.resolved) refuse(p, q.name, v, coarsest_n);
        bounds.push_back(b);
    }
    // Level 2n, once solved for one quantity, confirms every other: the levels n/4, n/2, n can show
    // one quantity the method's order by chance while another's fell short (product at n = 16 near
    // full stick: c0's ratio 13.9 over 4, 8, 16, level 32 solved for P_H/P2, and c0 over 8, 16, 32
    // alternating and growing, -1.2e-12, +1.3e-12, with its error 1.54 times the estimate from
    // 4, 8, 16).
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (above && !on_finer[i]) bounds[i] = confirm_on_finer(table[i], *above, bounds[i]);
        fold_estimate(e, table[i], bounds[i].value);
        e.bounded = e.bounded || !bounds[i].asymptotic;
    }
    static const char* const names[] = {"n/4", "n/2", "n", "2n", "4n"};
    const int first = 2 - p.self;  // index of the coarsest level's name
    const std::string levels_used =
        std::string("levels ") + names[first] + ", " + names[first + 1] + ", " + names[first + 2];
    if (coupled && p.self == 2) {
        // What the next rungs can be told (docs/formulation.md 8(q)): level 2n's estimate, on n/2, n, 2n,
        // is at least twice |x_n - x_{n/2}|, with both levels solved again there to the alternation's
        // tolerance (and their differences to the floor); the order-1 constant C/n, the smaller of the
        // last change and half the one before (a change small by chance gives the smaller prediction).
        error_estimate last{0.0, 0.0, 0.0, 0.0, "", false}, order_one{0.0, 0.0, 0.0, 0.0, "", false};
        for (std::size_t i = 0; i < table.size(); ++i) {
            const estimated_quantity& q = table[i];
            const double d1 = std::fabs(value(q, levels[1]) - value(q, levels[0]));
            const double d2 = std::fabs(value(q, levels[2]) - value(q, levels[1]));
            const double noise = floor_over(q, q.floor, levels[0], levels[1], levels[2]) + 4.0 * coupling_end_tolerance;
            fold_estimate(last, q, std::max(d2 - noise, 0.0));
            fold_estimate(order_one, q, std::max(std::min(d2, 0.5 * d1) - noise, 0.0));
        }
        const auto changes_of = [](const error_estimate& x) {
            return level_changes{x.lambda, x.c0, x.xi, x.start, x.c0_second_zone, x.start_second_zone};
        };
        // Rung 2n's coarsest level is n/2: where it may take the three-level rule (its zones from level n's ends, with
        // a tenth to spare, so that a doubt gives the smaller share), only 3/2^p of |x_n - x_{n/2}| is certain.
        const bool next_three_level =
            p.kinks_carried && fewest_zone_nodes(levels[2].solution, p.n / 2) >= 0.9 * resolved_zone;
        e.changes = coupled_changes{changes_of(last), changes_of(order_one),
                                    next_three_level ? std::ldexp(coupled_contracting_share, -order) : 2.0};
        // One Richardson level for the zone ends (8(q), "One Richardson level for the zone ends"): smooth rollers, whose
        // five zones on the exact weight (8(z)) converge at order 2 (the tangential side's blended stick zones on the
        // square-root weight, 8(y)); each end where its own changes are clean, with the noise of the changes above.
        // Rough rollers (changes of opposite sign confirmed on level 2n, never measured at order 2) are left out. A point
        // with a zone under two nodes of level n/4 (the three-level rule's test, takes_three_level) keeps level n's ends:
        // they fall between the same nodes, and a clean ratio there is chance (the driven Q/f = +0.75's trailing zone,
        // 0.38 nodes of level 128: s2 falls 3.87 times from 256 to 512, then 17.6 times to 1000; its value would be
        // 1.7e-8 from n = 1000's against an estimate of 1.2e-8).
        if (!p.rough) {
            const bool resolved = fewest_zone_nodes(levels[2].solution, p.n / 4) >= resolved_zone;
            // Level n/8, asked once and only for an end clean over n/4, n/2, n (its second ratio, richardson_end).
            std::optional<estimate_level> eighth;
            bool eighth_asked = false;
            const auto eighth_level = [&]() -> const estimate_level* {
                if (!eighth_asked && p.coarser) eighth = p.coarser();
                eighth_asked = true;
                return eighth ? &*eighth : nullptr;
            };
            zone_end_values x;
            for (std::size_t i = 0; i < table.size(); ++i) {
                const estimated_quantity& q = table[i];
                if (!q.newton_end) continue;
                const three_levels v{value(q, levels[0]), value(q, levels[1]), value(q, levels[2])};
                const double noise =
                    floor_over(q, q.floor, levels[0], levels[1], levels[2]) + 4.0 * coupling_end_tolerance;
                const estimate_level* const below =
                    resolved && ends_clean_ratio(v.middle - v.coarsest, v.finest - v.middle, noise) ? eighth_level()
                                                                                                    : nullptr;
                const std::optional<zone_end_value> r =
                    below ? richardson_end(value(q, *below), v, noise, order) : std::nullopt;
                std::optional<zone_end_value>& to = q.value == value_c0      ? x.c0
                                                    : q.value == value_start ? x.start
                                                    : q.value == value_end2  ? x.end2
                                                                             : x.start2;
                // Not clean: level n's value with its own bound, the one folded into its member (never smaller).
                to = r ? *r : zone_end_value{v.finest, bounds[i].value, false};
            }
            e.zone_ends = x;
        }
    }
    if (coupled) {
        e.against =
            levels_used +
            (three_level ? " (dissimilar rollers, full coupling: level n, three times the last level "
                           "change where the changes contract, else twice the larger of the two"
                         : " (dissimilar rollers, full coupling: level n, twice the larger of the "
                           "last two level changes") +
            (confirmed    ? "; confirmed on n/2, n, 2n where they changed sign)"
             : lower_bound ? "; above the tolerance before level 2n's confirmation where they changed sign: a lower "
                             "bound)"
                           : ")");
        e.lower_bound = lower_bound;
        return e;
    }
    // Against what: Richardson's value's level n, else level n's neighbour n/2 (or 2n).
    const char* const head = p.richardson ? "level n" : p.self == 2 ? "n/2" : "2n";
    const char* const kind =
        p.structure == estimate_structure::dissimilar ? "dissimilar rollers: level n, not extrapolated; " : "";
    e.against = std::string(head) + " (" + kind + levels_used +
                (second_chance ? "; n/2, n, 2n where n/4 fell short" : "") +
                (confirmed ? "; confirmed on n/2, n, 2n" : "") + (e.bounded ? "; observed order below " : "; order ") +
                std::to_string(order) + (e.bounded ? ": bounded)" : " observed)");
    return e;
}

}  // namespace roughroll
