// SPDX-License-Identifier: GPL-3.0-or-later
// contact's error estimate (contact.hpp): the three levels of the level method, level 2n where the
// rule asks for it, each on the zone structure of the point, and the structure's table of quantities
// for the one rule of point_estimate.hpp.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

#include "contact_impl.hpp"

namespace roughroll {

double contact::impl::kernel_strength() const {
    return std::max(kernel::tangential(surfaces_).strength(), kernel::normal(surfaces_).strength());
}

namespace {
// Full coupling's measured values on the edge layers' closed form (8(t), smooth rollers' free rolling; docs/formulation.md
// 8(e) "The measured values' estimates"), given the point's estimate `e` of its P_H/P2 `lambda` and peak. Johnson's
// P_H/P2 of smooth rollers is Hertz's 1 exactly (2(c): J = 0), so |lambda_J - 1| is its distance (as gamma_0n's off full
// coupling). The model's peak change (pi/2) p_max / sqrt(lambda) - 1 (coupling_summary.hpp with p_max,J = 2/pi,
// lambda_J = 1) rises with p_max and falls with lambda, so it lies between its values at the ends of their intervals (the
// reported peak `peak` within e.peak->p, lambda within e.lambda): the larger distance of those from the printed change,
// plus its rounding. The offset e and gamma_0n: none (8(t) bounds the pressure; e is an integral of the traction, (c)).
coupling_values closed_form_coupling(const coupling_summary& c, double lambda, double peak, const error_estimate& e) {
    const double none = std::numeric_limits<double>::quiet_NaN();
    double change = none;
    if (e.peak && e.lambda < lambda) {
        const double low = M_PI_2 * (peak - e.peak->p) / std::sqrt(lambda + e.lambda) - 1.0;
        const double high = M_PI_2 * (peak + e.peak->p) / std::sqrt(lambda - e.lambda) - 1.0;
        change = std::max(std::fabs(high - c.peak_pressure_change), std::fabs(c.peak_pressure_change - low)) +
                 8.0 * DBL_EPSILON * (1.0 + std::fabs(c.peak_pressure_change));
    }
    return {none, none, std::fabs(c.lambda_johnson - 1.0), change};  // exact: Sterbenz, lambda_J near 1
}
}  // namespace

std::optional<error_estimate> contact::impl::estimate(const tangential_solution& s) {
    // The edge layers neglected (8(n); at full coupling 8(t)): no levels, the layers' bound (the closed form has no n).
    if (s.layout.layers_neglected()) {
        const bool full = materials_.coupling == coupling_level::full;
        const neglected_layers layers = neglected_layers_at(materials_.beta_d, f_, full);
        const double lambda = normal().lambda;
        const layers_estimate bound = neglected_layers_estimate(layers, s.xi, lambda, nodes());
        error_estimate e{bound.lambda,
                         bound.c0,
                         bound.xi,
                         0.0,
                         full ? "the model with its edge layers: their bound (no levels; the no-slip limit at full "
                                "coupling in closed form, formulation 8(t))"
                              : "the model with its edge layers: their bound (no levels; the no-slip solution in "
                                "closed form, formulation 8(n))",
                         false,
                         bound.start};
        // The peak (8(t), "The peak pressure"; 8(n): Hertz's): the closed form's is at r = 0 with p = (2/pi)
        // lambda cosh(pi eps) (eps = 0 at Johnson's level), lambda the reported P_H/P2. The reported peak is
        // that of the reported pressure (the closed form at the nodes, its U interpolant between them:
        // no_slip_normal; Hertz's at Johnson's level), so its distance from the closed form's is known, not
        // estimated; the model's peak lies within the layers' peak bounds of the closed form's (0 at
        // Johnson's level: the pressure is Hertz's). Floors: the reported pressure's rounding, a sum of n
        // U-terms and the golden section's 16 eps p (pressure_peak), and the closed form's few eps.
        const pressure_peak reported = peak_of(normal());
        const double eps = full ? bufler_epsilon(materials_.beta_d) : 0.0;
        const double exact = M_2_PI * lambda * std::cosh(M_PI * eps);
        // The centre: the closed form's p(0) is its peak, `exact`, and the model's p(0) lies within the layers' bound
        // of it (8(t): D(0) <= the peak's bound, which is D(r) at the peak's bound r >= 0, or the bound U of |p - p_ns|
        // anywhere; 0 at Johnson's level).
        e.peak = peak_error{std::fabs(reported.r) + layers.peak_r_bound,
                            std::fabs(reported.p - exact) + layers.peak_p_bound + rounding_floor(nodes(), exact) +
                                32.0 * DBL_EPSILON * exact,
                            std::fabs(reported.centre - exact) + layers.peak_p_bound + rounding_floor(nodes(), exact) +
                                32.0 * DBL_EPSILON * exact};
        if (full && surfaces_.smooth())
            if (const coupling_summary* c = model_->coupling()) e.coupling = closed_form_coupling(*c, lambda, reported.p, e);
        return e;
    }
    // The levels' differences measure how a solution of the discrete equations moves with n; where
    // (3.3)-(3.4) fail, the answer is not the model's solution at any n, and they bound nothing.
    // They are still solved: where they do not converge the point is refused, as any other.
    std::optional<error_estimate> e;
    if (reported_ && s.layout.general() && model_->structure() == estimate_structure::paper) {
        // A point of the general path is level n itself, not extrapolated: the difference from
        // n/2 (on the same path), with the rounding floor of every estimate.
        const tangential_solution coarse = companion_->like(s, options_.how, nodes());
        require_same_zones(coarse, nodes() / 2, s);
        // The floors of every estimate; c0's near gross sliding, where the zone shrinks to a
        // point, is the one validation/test_honest_estimates.cpp needs (5e-12 at Q/f = 1 - 1e-15).
        const rounding_floors floor = floors_at(nodes(), s, s, normal().lambda, f_, kernel_strength());
        // The zone's ends, the start beside c0 (7(e) "The start's estimate"), each within Newton's resolution and the
        // entry's rounding at both levels (zone_ends_floor, as the levels' rule below).
        const double ends = zone_ends_floor(nodes(), floor.c0, s, normal().lambda, f_, kernel_strength()) +
                            newton_floor_excess({&s, &coarse});
        e = error_estimate{std::fabs(reported_->lambda - model_->normal().lambda) + floor.lambda,
                           std::fabs(s.c0() - coarse.c0()) + ends,
                           std::fabs(s.xi - coarse.xi) + floor.xi,
                           0.0,
                           "n/2 (general zone search: level n, not extrapolated)",
                           false,
                           std::fabs(s.start() - coarse.start()) + ends};
        e->peak = peak_from_difference(peak_of_level(*model_), peak_of_level(*companion_), nodes());
    } else if (build_levels()) {
        // Three levels of the level method on the structure of s (for dissimilar rollers the reported
        // values are level n's; for the paper's problem those of its distributions).
        const tangential_solution own = distribution(s);
        std::array<tangential_solution, 3> at{};
        for (int i = 0; i < 3; ++i) at[i] = levels_[i] ? levels_[i]->like(s, options_.how, nodes()) : own;
        if (s.layout.general() && model_->structure() == estimate_structure::paper)
            for (int i = 0; i < 3; ++i)
                if (levels_[i]) require_same_zones(at[i], (*levels_[i]).nodes(), s);
        e = estimate_from(s, own, at, false);
    }
    if (!s.checks.hold()) return std::nullopt;
    return e;
}

void contact::impl::require_same_zones(const tangential_solution& level, int m, const tangential_solution& s) const {
    // docs/formulation.md 7(e) "Unlike zones are not compared": the general search of another level may find another
    // structure (a leading slip zone at one n, none at another); the difference of their ends is then no discretisation
    // error, and no estimate is made from it. A larger n may find the same zones at its levels (the ladder tries it).
    if (same_zones(level.layout, s.layout)) return;
    std::string msg = no_honest_estimate(options_.how, nodes(), model_->structure()) + "level " + std::to_string(m) +
                      " finds the zones " + zones_kinds(level.layout) + " where level n finds " +
                      zones_kinds(s.layout) + " at Q = " + shortest(s.Q) +
                      ", and unlike zones are not compared (docs/formulation.md 7(e))";
    const bool n_given = store_ == nullptr;  // a ladder's rung: the ladder goes on to the larger n itself
    if (nodes() >= max_nodes)
        msg += n_given ? "; n is at its largest: a smaller n may find the same zones (leave n out and the ladder of "
                         "levels tries n up to " + std::to_string(max_nodes) + ")"
                       : "; n is at its largest, so the load is beyond the method's reach";
    else
        msg += n_given ? "; another n may find the same zones: a larger n (solver.n, --n; at most " +
                             std::to_string(max_nodes) + "), or leave n out and the ladder of levels tries n up to " +
                             std::to_string(max_nodes)
                       : "; a larger n (at most " + std::to_string(max_nodes) + ") may find the same zones";
    throw resolution_error(msg);
}

pressure_peak contact::impl::peak_of_level(const point_model& level) {
    // Full coupling's pressure is the level's last point's (8(e)): found each time. Every other level's pressure is
    // fixed by the surfaces and n (level n's as reported: Richardson's P_H/P2 leaves its b, so its peak).
    if (level.structure() == estimate_structure::full_coupling) return peak_of(level.normal());
    const auto known = peaks_.find(level.nodes());
    if (known != peaks_.end()) return known->second;
    return peaks_.emplace(level.nodes(), peak_of(level.normal())).first->second;
}

bool contact::impl::build_levels() {
    if (levels_built_) return levels_[0] || levels_[1];
    levels_built_ = true;
    const method how = level_of(options_.how);
    const int n = nodes();
    // Three levels n_0, 2 n_0, 4 n_0 containing n: n/4, n/2, n, else n/2, n, 2n (for
    // extrapolated, Richardson's value from the middle levels), else n, 2n, 4n. First the
    // first of them whose coarsest level is in the asymptotic range (the one-parameter limit
    // has no kernel to resolve: its ratio alone decides), then the first that can be solved.
    const int coarsest[] = {n / 4, n / 2, n};
    const int count = companion_ ? 2 : 3;
    for (bool require_range : {true, false}) {
        for (int i = 0; i < count; ++i) {
            const int m = coarsest[i];
            if (m < min_nodes || (n << i) > max_nodes) continue;
            if (require_range && how != method::one_parameter && !in_asymptotic_range(widest_kernel(), m, how))
                continue;
            std::array<held, 3> at{};
            bool ok = true;
            for (int k = 0; k < 3 && ok; ++k) {
                if (k == 2 - i) continue;  // this contact's own level
                try {
                    at[k] = level(k < 2 - i ? n >> (2 - i - k) : n << (k - 2 + i));
                } catch (const resolution_error&) {  // the kernels beyond its resolution
                    ok = false;
                }
            }
            if (ok) {
                levels_ = at;
                return true;
            }
        }
    }
    return false;
}

error_estimate contact::impl::estimate_from(const tangential_solution& s, const tangential_solution& own,
                                            const std::array<tangential_solution, 3>& at, bool swept) {
    int self = 0;
    while (levels_[self]) ++self;
    const estimate_structure structure = model_->structure();
    const bool paper = structure == estimate_structure::paper;
    const double lambda = normal().lambda, strength = kernel_strength();
    const int finest_n = levels_[2] ? (*levels_[2]).nodes() : nodes();
    rounding_floors floor = floors_at(finest_n, s, own, lambda, f_, strength);
    // Full coupling's weighted pressure (docs/formulation.md 8(w)) is spectral: its levels agree to the dense solve's
    // rounding, which the difference of two levels carries twice. On the exact weight of 8(z) that rounding is bounded
    // a posteriori (8(w), "The solve's rounding, a posteriori"): the solve's bound, and the alternation's distance from
    // its fixed point (8(w), "The alternation's share"; changes within n eps of the values are rounding, no ratio read
    // from them); the driven pair at Q/f = 0.75: 4.4e-15 .. 5.8e-15 at n = 16 .. 512, where the a priori
    // eps |lambda| / rcond (rcond of the factor U, about 1/kappa) was 4.2e-13 .. 2.3e-9. Elsewhere (w_N of 8(x)), and
    // where the alternation's contraction reads 1 or more, the a priori floor.
    const double n_eps_lambda = floor.lambda;
    // The same share for full coupling's offset e, of the stop's group (lambda, e, xi): its measured value's estimate
    // (docs/formulation.md 8(e), "The measured values' estimates"), added below. The same walk reads each level's
    // measured values (reading_of; all three or none).
    double offset_share = 0.0;
    std::array<coupling_values, 3> readings{};
    bool read = structure == estimate_structure::full_coupling;
    for (int i = 0; i < 3; ++i) {
        const point_model& level = levels_[i] ? *levels_[i] : *model_;
        const normal_solution& p = level.normal();
        const coupling_summary* alternation = level.coupling();
        read = read && alternation != nullptr;
        if (alternation) readings[i] = reading_of(p, *alternation);
        if (!(p.kinks && p.kinks->weighted() && p.rcond > 0.0)) continue;
        const double band = rounding_floor(level.nodes(), std::max({1.0, std::fabs(p.lambda), std::fabs(p.offset),
                                                                    std::fabs(own.xi) + f_ * std::fabs(p.lambda)}));
        const double distance = p.lambda_rounding > 0.0 && alternation
                                    ? coupling_fixed_point_distance(*alternation, band, p.lambda_rounding)
                                    : std::numeric_limits<double>::infinity();
        // The a posteriori share adds to n eps |lambda| (floors_at: the sums that assemble the load, 8(w)).
        floor.lambda = std::isfinite(distance)
                           ? std::max(floor.lambda, n_eps_lambda + 2.0 * distance)
                           : std::max(floor.lambda, 2.0 * DBL_EPSILON * std::fabs(p.lambda) / p.rcond);
        offset_share = std::max(offset_share, std::isfinite(distance)
                                                  ? 2.0 * distance
                                                  : 2.0 * DBL_EPSILON * std::max(1.0, std::fabs(p.offset)) / p.rcond);
    }
    // The structure's table: P_H/P2, xi, then the paper's c0 (or Q on a curve swept in c0), or the
    // ends of dissimilar rollers' stick zones, which carry Newton's resolution too (dissimilar_zones.hpp).
    using q = estimated_quantity;
    using est = error_estimate;
    std::vector<q> table;
    if (paper) {
        const bool x = reported_ != nullptr;  // Richardson's values, all three
        table = {{"P_H/P2", nullptr, floor.lambda, floor.lambda, x, true, &est::lambda},
                 {"xi", value_xi, floor.xi, floor.xi, x, true, &est::xi},
                 swept ? q{"Q", value_Q, floor.Q, floor.Q, x, true, &est::Q}
                       : q{"c0", value_c0, floor.c0, floor.c0, x, true, &est::c0}};
        // The general search's stick zone inside the contact (7; its route is general exactly where it starts inside):
        // both ends are Newton's in the load and entry conditions (7(d)), so each level's ends lie within Newton's
        // resolution and the entry's rounding, as dissimilar rollers' (zone_ends_floor, newton_end); the start is
        // estimated by c0's rule beside it (docs/formulation.md 7(e) "The start's estimate"). The paper's zone starts
        // at r = -1 exactly: no row. The levels have s's zones (require_same_zones).
        if (!swept && s.layout.general()) {
            const double ends = zone_ends_floor(finest_n, floor.c0, s, lambda, f_, strength);
            const double finer_ends = zone_ends_floor(2 * nodes(), floor.c0, s, lambda, f_, strength);
            table.back() = {"c0", value_c0, ends, finer_ends, x, true, &est::c0, true};
            table.push_back({"the stick zone's start", value_start, ends, finer_ends, x, true, &est::start, true});
        }
    } else {
        const double ends = zone_ends_floor(finest_n, floor.c0, s, lambda, f_, strength);
        const double finer_ends = zone_ends_floor(2 * nodes(), floor.c0, s, lambda, f_, strength);
        // Level n is reported, not extrapolated; P_H/P2 as reported (Richardson's for 'extrapolated',
        // level n's at full coupling: contact::normal), with no second chance.
        table = zone_ends_table(floor, ends, finer_ends,
                                reported_ != nullptr && structure != estimate_structure::full_coupling,
                                s.layout.stick_zones() == 2);
    }
    std::array<estimate_level, 3> levels;
    for (int i = 0; i < 3; ++i) levels[i] = {at[i], (levels_[i] ? *levels_[i] : *model_).normal().lambda};
    // Level 2n on the structure of s, where n is the finest level. A search that finds no zone
    // there leaves no fourth level; for the paper's single zone a numerical fault is one.
    const auto finer = [&]() -> std::optional<estimate_level> {
        const int m = 2 * nodes();
        if (levels_[2] || m > max_nodes) return std::nullopt;
        std::optional<estimate_level> l;
        try {
            // At own's c0 on a curve swept in c0, else on the structure of s (its point first: at full
            // coupling it sets the pressure).
            const held finer_level = level(m);
            l = estimate_level{swept ? finer_level->at_stick_end(own.c0(), false, sweeping_near_)
                                     : finer_level->like(s, options_.how, nodes()),
                               (*finer_level).normal().lambda};
        } catch (const resolution_error&) {
            return std::nullopt;
        } catch (const numerical_error&) {
            if (!s.layout.general() && paper) throw;
            return std::nullopt;
        } catch (const error&) {
            if (paper) throw;
            return std::nullopt;
        }
        // Level 2n confirms on s's zones only: another structure there is refused, not compared (require_same_zones).
        if (paper && s.layout.general()) require_same_zones(l->solution, m, s);
        return l;
    };
    estimate_point point{
        options_.how,       nodes(),           self, structure, reported_ != nullptr && paper, own.checks.hold(),
        swept ? "c0" : "Q", swept ? s.c0() : s.Q};
    // 8(q) "The three-level rule at full coupling": smooth rollers only. Rough rollers carry the kinks with the layer
    // terms (8(o)), but their stick start still converges erratically, up to 2.9 times max(|d2|, |d1|/4) from n = 1000
    // (the rule was measured to 1.51 on smooth rollers): they keep twice the larger change.
    point.kinks_carried = structure == estimate_structure::full_coupling && normal().kinks != nullptr &&
                          !normal().kinks->layered();
    point.rough = structure == estimate_structure::full_coupling && !surfaces_.smooth();
    point.n_given = store_ == nullptr;  // a ladder's rungs share its level_store (level_ladder.hpp)
    // Level n/8 for the zone ends' second ratio (8(q) "One Richardson level for the zone ends"): smooth rollers at full
    // coupling on n/4, n/2, n only (the ends extrapolated there); held by the store on a ladder (rung n/2's coarsest is
    // n/8), else solved on the structure of s as level 2n is (n/8 nodes), at most once per estimate; n a multiple of 8
    // so that n/8 halves n/4 (the ratios are of doublings).
    if (point.kinks_carried && !point.rough && self == 2 && nodes() % 8 == 0 && nodes() / 8 >= min_nodes)
        point.coarser = [this, &s, swept, &own]() -> std::optional<estimate_level> {
            try {
                const held eighth = level(nodes() / 8);
                return estimate_level{swept ? eighth->at_stick_end(own.c0(), false, sweeping_near_)
                                            : eighth->like(s, options_.how, nodes()),
                                      (*eighth).normal().lambda};
            } catch (const error&) {  // resolution_error, numerical_error among them: no second ratio, no extrapolation
                return std::nullopt;
            }
        };
    // The ladder's tolerance, where a confirmation on level 2n would be asked of a rung that cannot answer without it
    // (level_store::fails_tolerance, 8(q) "Changes of opposite sign").
    if (store_ && store_->fails_tolerance())
        point.fails_tolerance = [this, &s, fails = store_->fails_tolerance()](const error_estimate& x) {
            return fails(s, normal().lambda, x);
        };
    // Level 2n solved once, for the table and the peak alike (its pressure read before another level is solved).
    std::optional<std::optional<estimate_level>> above;
    std::optional<pressure_peak> above_peak;
    std::optional<coupling_values> above_reading;  // full coupling's measured values on level 2n
    const auto finer_once = [&]() -> std::optional<estimate_level> {
        if (!above) {
            above = finer();
            if (*above) above_peak = peak_of_level(*level(2 * nodes()));
            if (*above && structure == estimate_structure::full_coupling) {
                const held two_n = level(2 * nodes());
                if (const coupling_summary* c = (*two_n).coupling()) above_reading = reading_of((*two_n).normal(), *c);
            }
        }
        return *above;
    };
    error_estimate e = estimate_from_levels(table, levels, finer_once, point);
    // The peak pressure from the same levels' pressures (no solve; a curve swept in c0 prints no peak). Level n's is
    // the reported pressure's: at full coupling model_'s at s, else its pressure, whose position Richardson's
    // extrapolation of P_H/P2 does not move (contact::normal).
    if (!swept) {
        std::array<pressure_peak, 3> peaks;
        for (int i = 0; i < 3; ++i) peaks[i] = peak_of_level(levels_[i] ? *levels_[i] : *model_);
        // Level 2n not solved for the table (a lower bound): nor for the peak. Nor for the peak alone where the table's
        // estimate already fails the ladder's tolerance: a lower bound as well (full coupling's level 2n, a point's
        // solve; off full coupling the peak's level 2n is a normal problem alone, solved). Right only while the peak is
        // not read by the tolerance (check_estimate): e.peak is not set yet when the test is asked.
        if (structure == estimate_structure::full_coupling && !e.lower_bound && !above && point.fails_tolerance &&
            peak_asks_level_two_n(peaks, point) && point.fails_tolerance(e))
            e.lower_bound = true;
        point.lower_bound = e.lower_bound;
        // At full coupling the position also from the slopes of level n's pressure and its neighbour's (n/2, or 2n
        // where n is the coarsest), around level n's peak (8(e), "The peak's position from the slopes").
        double slopes_r = 0.0;
        if (structure == estimate_structure::full_coupling) {
            const int next = self == 0 ? 1 : self - 1;
            const point_model& own_level = levels_[self] ? *levels_[self] : *model_;
            const point_model& next_level = levels_[next] ? *levels_[next] : *model_;
            std::vector<double> ends = at[self].layout.stick_ends();
            for (const double end : at[next].layout.stick_ends()) ends.push_back(end);
            slopes_r = peak_position_from_slopes(own_level.normal(), own_level.nodes(), next_level.normal(),
                                                 next_level.nodes(), peaks[self].r, ends, std::max(e.c0, e.start));
        }
        // Level 2n's peak: at full coupling its point's pressure (the table's level 2n); every other structure's
        // pressure does not depend on the load, so only its normal problem is solved (once per contact, peak_of_level;
        // docs/formulation.md 8(e) "The peak confirmed on level 2n"), and none where it cannot be. There the level above
        // the three: 2n, or 4n where level n is their middle (8(e) "The peak on levels that are not doublings").
        const auto finer_peak = [&]() -> std::optional<pressure_peak> {
            if (structure == estimate_structure::full_coupling) {
                finer_once();
                return above_peak;
            }
            if (2 * finest_n > max_nodes) return std::nullopt;
            try {
                return peak_of_level(*level(2 * finest_n));
            } catch (const error&) {
                return std::nullopt;
            }
        };
        e.peak = peak_from_levels(peaks, point, finer_peak, slopes_r);
        // Full coupling's measured values (offset e, gamma_0n, Johnson's P_H/P2, the peak's change) from the same
        // levels' points, by the peak value's rule (docs/formulation.md 8(e), "The measured values' estimates").
        if (read) {
            // Level 2n only where the table or the peak solved it: a printed value solves nothing (value_from_levels).
            e.coupling = coupling_from_levels(readings, point, [&]() -> std::optional<coupling_values> {
                return above && *above ? above_reading : std::nullopt;
            });
            // The alternation's share, as P_H/P2's floor above (8(w), "The alternation's share"): e is of the stop's
            // group (lambda, e, xi), so each level on the weight adds twice its distance from its fixed point
            // (coupling_fixed_point_distance), or the a priori 2 eps max(1, |e|)/rcond (offset_share). gamma_0n and the
            // peak's change have none (coupling_from_levels). Johnson's P_H/P2 is no iterate of it (its own normal
            // solve): its levels' rule alone.
            e.coupling->offset += offset_share;
        }
    }
    return e;
}

}  // namespace roughroll
