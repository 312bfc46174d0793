// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/level_ladder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/contact_internals.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/point_estimate.hpp"

namespace roughroll {

std::vector<int> ladder_rungs(method how) {
    std::vector<int> rungs;
    for (int n = default_nodes(how); n < max_nodes; n *= 2) rungs.push_back(n);
    rungs.push_back(max_nodes);
    return rungs;
}

std::vector<int> spectral_rungs(method how) { return {default_nodes(how) / 4, default_nodes(how) / 2}; }

tolerance_check check_estimate(const tangential_solution& s, double lambda, const error_estimate& e, double tol,
                               double strength) {
    // The rounding floors at the largest n (docs/performance.md "How the error estimates are made",
    // as contact's floors at n = max_nodes): below them no rung can bring an estimate.
    const double K = std::max(1.0, std::fabs(lambda));
    const double size = std::max(K, strength);  // xi's terms: f G of (4.4) and the kernel terms
    const double n_eps = rounding_floor(max_nodes, K);
    const double rho = s.rho();
    // With the edge layers neglected (formulation 8(n)) the ends are the edges, within the layers'
    // thickness: relative to the half-width.
    const double end_scale = s.layout.layers_neglected() ? 1.0 : 0.0;
    const double zone_end_floor =
        std::min(rho > 0.0 ? n_eps / rho : std::numeric_limits<double>::infinity(), 2.0 * std::sqrt(n_eps));
    struct quantity {
        const char* name;
        double estimate, scale, floor;
    };
    const quantity quantities[] = {
        {"P_H/P2", e.lambda, std::fabs(lambda), rounding_floor(max_nodes, lambda)},
        // the slip zone [c0, 1] (issue 23, 1), and [-1, start]; the second zone's ends on the same scales
        {e.c0_second_zone ? "the second stick zone's end" : "c0", e.c0, std::max(1.0 - s.c0(), end_scale),
         zone_end_floor},
        {e.start_second_zone ? "the second stick zone's start" : "stick start", e.start,
         std::max(1.0 + s.start(), end_scale), zone_end_floor},
        {"xi", e.xi, std::fabs(s.xi), rounding_floor(max_nodes, std::fabs(s.xi) + s.f * size)},
        {"Q", e.Q, std::fabs(s.Q), rounding_floor(max_nodes, s.f * K)},
    };
    // A zero estimate (the quantity given, not computed) is within any tolerance; a NaN one is not.
    const double inf = std::numeric_limits<double>::infinity();
    tolerance_check worst{0.0, "P_H/P2", e.lambda, 0.0, 0.0, {}};
    double answering = 0.0;
    std::string answering_quantity;
    for (const quantity& q : quantities) {
        const double allowed = std::max(tol * std::fabs(q.scale), q.floor);
        const double ratio = q.estimate == 0.0     ? 0.0
                             : !(q.estimate > 0.0) ? inf
                             : allowed > 0.0       ? q.estimate / allowed
                                                   : inf;
        const double relative = q.scale != 0.0 ? q.estimate / std::fabs(q.scale) : inf;
        if (ratio > worst.ratio) worst = {ratio, q.name, q.estimate, relative, 0.0, {}};
        const double needs = q.estimate > 0.0 ? relative : inf;
        if (!(q.estimate <= q.floor) && (needs > answering || answering_quantity.empty())) {
            answering = std::max(answering, needs);
            answering_quantity = q.name;
        }
    }
    worst.answering = answering;
    worst.answering_quantity = answering_quantity;
    return worst;
}

level_ladder::level_ladder(const solver_options& options, const roughness& surfaces, rung_factory make)
    : rungs_(ladder_rungs(options.how)),
      tolerance_(options.tolerance.value_or(default_tolerance)),
      strength_(std::max(kernel::tangential(surfaces).strength(), kernel::normal(surfaces).strength())),
      smooth_(!kernel::layered(surfaces)),
      order_(order_of(options.how)),
      how_(options.how),
      flagged_final_(options.zones == zone_search::single),
      make_(std::move(make)),
      levels_(std::make_shared<level_store>()),
      spectral_levels_(std::make_shared<level_store>()) {
    check_tolerance(tolerance_, "the tolerance");
}

level_store::tolerance_test level_ladder::tolerance_test() const {
    // check()'s test by value.
    return [tolerance = tolerance_, strength = strength_](const tangential_solution& s, double lambda,
                                                          const error_estimate& e) {
        return check_estimate(s, lambda, e, tolerance, strength).ratio > 1.0;
    };
}

level_ladder::level_ladder(const solver_options& options, const roughness& surfaces,
                           const std::function<std::unique_ptr<contact>(int n)>& make)
    : level_ladder(options, surfaces, [make](int n, const std::shared_ptr<level_store>&) { return make(n); }) {
    shared_ = false;
}

bool level_ladder::answers(const contact& c, const tangential_solution& s,
                           const std::optional<error_estimate>& e) const {
    if (!s.checks.hold()) return flagged_final_;
    return e && check(c, s, *e).ratio <= 1.0;
}

tolerance_check level_ladder::check(const contact& c, const tangential_solution& s, const error_estimate& e) const {
    return check_estimate(s, c.normal().lambda, e, tolerance_, strength_);
}

contact& level_ladder::at(int n) {
    std::unique_ptr<contact>& c = built_[n];
    if (!c) c = make_(n, levels_);
    return *c;
}

std::unique_ptr<contact> level_ladder::release(int n) {
    at(n);
    std::unique_ptr<contact> c = std::move(built_[n]);
    built_.erase(n);
    return c;
}

namespace {

// An estimate the refusal names as the best reached, in two digits rounded up: a bound stays a bound when printed, and
// the digits beyond two are noise (the advice beside it rounds the same way, rounded_up).
std::string bound_text(double x) {
    return x > 0.0 && std::isfinite(x) ? significant(rounded_up(x, 2), 2) : significant(x, 2);
}

// A relative size the ladder says a rung's estimate reaches "at least" (rules (a), (a'), (b) of 8(q)), in three
// digits rounded down: rounded to the nearest it could claim more than is certain (rung 1000's certain 1.0494e-5
// read 1.05e-5, above its estimate 1.04945e-5).
std::string at_least(double x) {
    if (!(x > 0.0) || !std::isfinite(x)) return significant(x, 3);
    const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2.0);
    return significant(std::floor(x * (1.0 - 1e-12) / unit) * unit, 3);
}

error_estimate scaled_changes(const level_changes& c, double factor) {
    error_estimate e{factor * c.lambda, factor * c.c0, factor * c.xi, 0.0, "", false, factor * c.start};
    e.c0_second_zone = c.c0_second_zone;
    e.start_second_zone = c.start_second_zone;
    return e;
}

}  // namespace

std::optional<std::string> settled_failure(const std::array<failed_rung, 3>& r, double Q, double f) {
    // The margins' convergence is the zone ends' (the checks fail next to them, 8(r)): erratic at order 1, so one change
    // bounds nothing (8(q) "A fall faster than the ends' order"); three rungs take the estimates' own rule at full
    // coupling, of the three-levels kind (no contraction read), on the same zones only (same_zones: each stick or slip
    // in the same direction, as the levels of an estimate are compared, 7(e)).
    for (const failed_rung& x : r)
        if (!same_zones(x.layout, r[0].layout)) return std::nullopt;
    struct margin {
        const char* name;
        double traction_checks::*value;
        double traction_checks::*rounding;  // null: none (the pressure's)
    };
    const margin margins[] = {{"stick", &traction_checks::stick_margin, &traction_checks::stick_rounding},
                              {"slip", &traction_checks::slip_margin, &traction_checks::slip_rounding},
                              {"p", &traction_checks::pressure_margin, nullptr}};
    for (const margin& m : margins) {
        double rounding = 0.0;
        bool below = true;
        for (const failed_rung& x : r) {
            below = below && x.checks.*m.value < 0.0;
            if (m.rounding) rounding = std::max(rounding, x.checks.*m.rounding);
        }
        if (!below) continue;
        const error_bound e =
            coupled_change_bound({r[0].checks.*m.value, r[1].checks.*m.value, r[2].checks.*m.value}, rounding);
        if (!e.resolved || !(r[2].checks.*m.value + e.value < 0.0)) continue;
        const bool pressure = m.rounding == nullptr;
        return "full coupling at Q/f = " + shortest(Q / f) + ": the coupled " +
               (pressure ? std::string("pressure turns negative") : std::string("zones fail the checks (3.3)-(3.4)")) +
               " at n = " + std::to_string(r[0].n) + ", " + std::to_string(r[1].n) + " and " + std::to_string(r[2].n) +
               " alike (" + m.name + " margin " + significant(r[0].checks.*m.value, 3) + ", " +
               significant(r[1].checks.*m.value, 3) + ", " + significant(r[2].checks.*m.value, 3) +
               ": below zero by more than their changes' bound, docs/formulation.md 8(q)), so no larger n answers it: " +
               coupled_failure_cause(pressure) + "; " + coupled_failure_advice(pressure);
    }
    return std::nullopt;
}

std::string unconverged_everywhere(int first, int second, double Q, double f) {
    // docs/formulation.md 8(q), "An alternation that converges at no level": two rungs n, 2n whose points and levels
    // n/4 .. 2n all stop without converging (measured: beta_d = 0.7, f = 0.3, Q/f = -0.5 at every level from 8 to 1000),
    // so the climb stops there; no claim on a larger n, which the user may still give.
    return "full coupling at Q/f = " + shortest(Q / f) + ": the alternation between the normal and tangential problems "
           "converges at none of n = " + std::to_string(first / 4) + ", " + std::to_string(first / 2) + ", " +
           std::to_string(first) + " and " + std::to_string(second) +
           " (docs/formulation.md 8(e), 8(q)), so no larger n was tried: " + alternation_failure_advice() +
           ", and --n " + std::to_string(2 * second) + " or more tries a larger n at full coupling";
}

level_ladder::outlook level_ladder::beyond(const answer& a, const contact& c, std::size_t i) const {
    // Full coupling (docs/formulation.md 8(q)): each later rung's estimate from rung i's level changes.
    // (a) The next rung, when it doubles n (levels n/2, n, 2n), has an estimate of at least twice
    // |x_n - x_{n/2}| (less both levels' noise), exactly, or where its levels may take the three-level rule
    // (8(q) "The three-level rule at full coupling") 3/2^p of it (changes.next_factor); it fails the
    // tolerance where that exceeds it by more than the scale's own move to that rung (at most half its
    // estimate: tol/2 relative) and 1 %.
    // (b) Where a zone end converges at order 1 (five zones and the driven three zones' entry while the
    // pressure's kinks are not carried: rough rollers, 8(o)), rung m's estimate is at least twice its
    // change from m/4 to m/2, 4 C/m with C/n the order-1 constant of rung i: a tenth of it is certain
    // (8(q)). With the kinks and the blends' kinks carried (smooth rollers, 8(r)) the ends converge at
    // order 2 to 4.5, where that tenth is certain only while (m/n)^(p-1) <= 5 2^p (m/n <= 6.3 at
    // order 3, 3.9 at 4.5; the ladder's largest is 7.8): no order-1 law there, only (a).
    outlook o;
    const coupled_changes& changes = *a.estimate->changes;
    const int n = rungs_[i];
    const bool order_one = !c.normal().kinks && (a.solution.layout.stick_zones() == 2 || a.solution.layout.opposite());
    for (std::size_t j = i + 1; j < rungs_.size(); ++j) {
        const int m = rungs_[j];
        std::optional<tolerance_check> certain;
        if (j == i + 1 && m == 2 * n) {
            const tolerance_check t = check(c, a.solution, scaled_changes(changes.last, changes.next_factor));
            if (t.ratio * (1.0 - 0.5 * tolerance_) > 1.01) certain = t;
        }
        if (order_one && !certain) {
            level_changes ends = changes.order_one;
            ends.lambda = ends.xi = 0.0;  // P_H/P2 and xi converge faster (8(e)): no order-1 law for them
            const tolerance_check t = check(c, a.solution, scaled_changes(ends, 0.1 * 4.0 * n / m));
            if (t.ratio > 1.0) certain = t;
        }
        o.fails.push_back(certain.has_value());
        o.at_least.push_back(certain.value_or(tolerance_check{}));
    }
    return o;
}

std::optional<tolerance_check> level_ladder::before_point(contact& c, double Q, std::size_t i) {
    // 8(q) rule (a'). Rung m's estimate reads its levels m/4, m/2 as solved here (their points kept: the same levels,
    // not solved again), and every branch of the rule gives each quantity E >= k |x_{m/2} - x_{m/4}| (coupled_bound:
    // three times at least a 2^p-th of it where the changes contract under the three-level rule, else twice the
    // larger change; a stall, no estimate). Rung m answers only where E <= max(tol s_m, r), and its scale s_m is
    // within |x_m - x_{m/2}| <= E/2 of level m/2's s: so E (1 - tol/2) <= max(tol s, r), which fails where
    // k |x_{m/2} - x_{m/4}| (1 - tol/2) > max(tol s, r), with 1 % more, as (a). k = 2 unless rung m may take the
    // three-level rule; that needs the kinks (smooth rollers) and every zone of its point two nodes of level m/4
    // wide, and a point that answers has each end within E/2 <= max(tol s, r)/(2 - tol) of level m/2's: its zones
    // lie inside level m/2's widened by that, so where those hold fewer nodes no answering point takes the rule.
    const int m = rungs_[i];
    const std::vector<estimate_level> levels = contact_internals::levels_before(c, Q);
    if (levels.size() != 2) return std::nullopt;  // levels m/4, m/2 (no finer level fits: climb's test), or none
    const estimate_level& half = levels[1];
    const level_changes changes = changes_before_point(levels[0], half, m, c.friction(), strength_);
    const auto certain_part = [&](double k) {
        return check_estimate(half.solution, half.lambda, scaled_changes(changes, k), tolerance_, strength_);
    };
    // The largest allowed move of a zone end (c0's and the start's members: e / ratio of a unit estimate).
    error_estimate unit{0.0, 1.0, 0.0, 0.0, "", false, 1.0};
    unit.start = 0.0;
    const double allowed_c0 = 1.0 / check_estimate(half.solution, half.lambda, unit, tolerance_, strength_).ratio;
    unit.c0 = 0.0;
    unit.start = 1.0;
    const double allowed_start = 1.0 / check_estimate(half.solution, half.lambda, unit, tolerance_, strength_).ratio;
    const double delta = 1.01 * std::max(allowed_c0, allowed_start) / (2.0 - tolerance_);
    const bool three_level = may_take_three_level(half.solution, m, delta, smooth_);
    const tolerance_check t = certain_part(three_level ? std::ldexp(3.0, -order_) : 2.0);
    if (t.ratio * (1.0 - 0.5 * tolerance_) > 1.01) return t;
    return std::nullopt;
}

level_ladder::answer level_ladder::climb(const solve_rung& solve, std::size_t from, std::optional<double> Q) {
    struct best_reached {
        tolerance_check check;
        int n;
    };
    std::optional<best_reached> best;
    // The rungs' estimates see the tolerance during the climb alone (level_store::fails_tolerance): a contact's estimate
    // asked at any other time (a curve's first rows, a released contact) confirms as without a ladder.
    struct tolerance_seen {
        level_store& store;
        tolerance_seen(level_store& s, level_store::tolerance_test test) : store(s) {
            store.set_tolerance_test(std::move(test));
        }
        tolerance_seen(const tolerance_seen&) = delete;
        tolerance_seen& operator=(const tolerance_seen&) = delete;
        ~tolerance_seen() { store.set_tolerance_test({}); }
    };
    const tolerance_seen seen(*levels_, tolerance_test());
    // Rungs whose estimate is a lower bound (error_estimate::lower_bound: level 2n not solved where it would have
    // confirmed, the tolerance failed without it), with their points: confirmed only where the climb is refused and
    // one may be the best estimate reached, which the refusal names and advises to accept.
    struct lower_bound {
        int n;
        tangential_solution solution;
        double ratio;  // its check's: the confirmed estimate's is at least this
    };
    std::vector<lower_bound> lower_bounds;
    std::string last_reason, skipped, beyond_all;
    std::string not_solved;       // rule (a') refused a rung before its point (said after the best estimate reached)
    bool advised_last = false;    // the last rung tried refused the point with a line that says what to change
    bool rounding_limit = false;  // the last rung tried met the ends' rounding limit, which grows with n: no rung above
    int last_n = rungs_.back();   // the last rung tried
    std::vector<bool> skip(rungs_.size(), false);
    std::vector<failed_rung> failed;  // the rungs before, each in turn, whose points failed the checks at full coupling
    std::vector<int> unconverged;     // the rung before, where its point's and levels' alternations did not converge
    for (std::size_t i = from; i < rungs_.size() && beyond_all.empty() && !rounding_limit; ++i) {
        const int n = rungs_[i];
        if (skip[i]) continue;
        std::vector<failed_rung> failed_before = std::exchange(failed, {});
        const std::vector<int> unconverged_before = std::exchange(unconverged, {});
        advised_last = false;
        last_n = n;
        try {
            contact& c = at(n);
            // Full coupling's rule (a') for a rung no rung below predicts (it does not double the one before):
            // its levels first, its point not solved where their change alone fails the tolerance (8(q)).
            // At such a rung (the top: no level above it fits, so its levels are n/4, n/2), flagged answers aside.
            if (Q && !flagged_final_ && i > 0 && n != 2 * rungs_[i - 1] && 2 * n > max_nodes) {
                if (const std::optional<tolerance_check> t = before_point(c, *Q, i)) {
                    const std::string least = at_least(t->relative);
                    const std::string why = "its estimate of " + t->quantity + " is at least " + least +
                                            " relative (full coupling, from its levels n = " + std::to_string(n / 4) +
                                            ", " + std::to_string(n / 2) + ", docs/formulation.md 8(q))";
                    not_solved += "; n = " + std::to_string(n) + " was not solved: " + why;
                    last_reason = "not solved: " + why + "; a tolerance above " + least +
                                  " (solver.tolerance, --tolerance) may answer it, or coupling = \"johnson\"";
                    advised_last = true;
                    continue;
                }
            }
            answer a = solve(c, n);
            if (!a.solution.checks.hold() && flagged_final_) return a;
            if (!a.solution.checks.hold()) {
                last_reason = "the checks (3.3)-(3.4) fail";
                continue;
            }
            if (!a.estimate) {
                last_reason = "no error estimate (no three levels fit)";
                continue;
            }
            const tolerance_check t = check(c, a.solution, *a.estimate);
            if (a.estimate->lower_bound) {
                // Never within the tolerance (stop-s23.md "Seen in the read"; 8(q) "Level 2n on a ladder"). An estimate is
                // a lower bound only where the store's test (tolerance_test(): check_estimate by value, with this ladder's
                // tolerance_ and strength_, which nothing assigns after construction) said it fails, at the same s (solve
                // passes the s it returns to contact::estimate) and the same P_H/P2 (contact::normal, unchanged: a lower
                // bound solves no level 2n, for the table nor for the peak, so nothing is solved between that test and
                // this check). The test was shown either e itself (estimate_from's peak branch: e.peak, which
                // check_estimate does not read, set after) or estimate_from_levels' `unconfirmed`, which equals e in
                // every member check_estimate reads (lambda, c0, start, xi, Q and the second-zone flags): where
                // fails_before_finer holds, every erratic quantity takes the lower-bound branch (asked once, cached),
                // the paper's confirmation and the second chance are not asked at full coupling, level 2n is not solved
                // (so the loop's confirmation of the rest does not run), and each quantity's bound is the same
                // coupled_bound of the same levels and floor, folded in the same order; zone_ends is not read. The
                // same arithmetic gives the same ratio, > 1. A violated invariant of the code, not a refusal: a bug.
                if (t.ratio <= 1.0)
                    throw std::logic_error("level_ladder: a lower bound within the tolerance at n = " +
                                           std::to_string(n) + " (" + t.quantity + ": estimate " +
                                           shortest(t.estimate) + ", tolerance " + shortest(tolerance_) + ")");
                lower_bounds.push_back({n, a.solution, t.ratio});
            } else {
                if (t.ratio <= 1.0) return a;
                if (!best || t.ratio < best->check.ratio) best = best_reached{t, n};
            }
            last_reason.clear();
            if (!a.estimate->changes || i + 1 == rungs_.size()) continue;
            // Full coupling: no rung above can answer (refused now), or the next one cannot and its
            // own changes could not tell a later rung (the one after it does not double its n): not solved.
            const outlook o = beyond(a, c, i);
            const auto failing = std::count(o.fails.begin(), o.fails.end(), true);
            if (static_cast<std::size_t>(failing) == o.fails.size()) {
                const tolerance_check& next = o.at_least.front();
                beyond_all =
                    "no larger n can meet it (full coupling's estimate holds at least a share of the last level "
                    "change, and where the pressure's kinks are not carried its zone ends converge at order 1: at n "
                    "= " +
                    std::to_string(rungs_[i + 1]) + " " + next.quantity + " at least " + at_least(next.relative) +
                    " relative; docs/formulation.md 8(q))";
            } else if (o.fails.front() && (i + 2 == rungs_.size() || rungs_[i + 2] != 2 * rungs_[i + 1])) {
                skip[i + 1] = true;
                const tolerance_check& next = o.at_least.front();
                skipped = "; n = " + std::to_string(rungs_[i + 1]) + " was not solved: its estimate of " +
                          next.quantity + " is at least " + at_least(next.relative) +
                          " relative (full coupling, from the levels up to n = " + std::to_string(n) +
                          ", docs/formulation.md 8(q))";
            }
        } catch (const beyond_method_error&) {  // no rung can: its own line says what to change
            throw;
        } catch (const alternation_error& e) {  // as resolution_error, unless two rungs show it at every level (8(q))
            last_reason = one_line(e.what());
            advised_last = true;
            if (e.levels_too() && !unconverged_before.empty() && unconverged_before.back() * 2 == n) {
                if (Q && i + 1 < rungs_.size())
                    throw resolution_error(unconverged_everywhere(unconverged_before.back(), n, *Q, at(n).friction()));
            }
            if (e.levels_too()) unconverged = {n};
        } catch (const failed_checks_error& e) {  // as resolution_error, unless three rungs settle it (8(q))
            last_reason = one_line(e.what());
            advised_last = true;
            failed_before.push_back({n, e.checks(), e.layout()});
            const std::size_t k = failed_before.size();
            if (Q && k >= 3 && i + 1 < rungs_.size())
                if (std::optional<std::string> why = settled_failure(
                        {failed_before[k - 3], failed_before[k - 2], failed_before[k - 1]}, *Q, at(n).friction()))
                    throw beyond_method_error(*why);
            failed = std::move(failed_before);
        } catch (const rounding_limit_error& e) {  // its line says what to change; a larger n rounds worse
            last_reason = one_line(e.what());
            advised_last = rounding_limit = true;
        } catch (const unadvised_refusal& e) {  // this rung cannot answer, and its line names no change
            last_reason = one_line(e.what());
        } catch (const resolution_error& e) {  // this rung cannot answer: the next may; its line says what to change
            last_reason = one_line(e.what());
            advised_last = true;
        }
    }
    // A lower bound below the best estimate reached may hide a better one: confirmed now (its level 2n solved, the
    // ladder's test off), as its rung's estimate would have been without the test. Its refusal leaves it out.
    levels_->set_tolerance_test({});
    for (const lower_bound& l : lower_bounds) {
        if (best && l.ratio >= best->check.ratio) continue;
        try {
            contact& c = at(l.n);
            const std::optional<error_estimate> e = c.estimate(l.solution);
            if (e) {
                const tolerance_check t = check(c, l.solution, *e);
                if (!best || t.ratio < best->check.ratio) best = best_reached{t, l.n};
            }
        } catch (const beyond_method_error&) {
            throw;
        } catch (const resolution_error& e) {  // refused on level 2n: no estimate reached there
            if (l.n == last_n) {  // the climb ended at this rung (rule (b)): its refusal is the last reason
                last_reason = one_line(e.what());
                advised_last = true;
            }
        }
    }
    // The rounding limit ends the climb at the rung that met it: no rung above was tried. Its line advises a smaller
    // n; a larger tolerance helps only where a lower rung answered with an estimate above it (`best`), said there.
    const std::string top = std::to_string(rounding_limit ? last_n : rungs_.back());
    std::string msg = "no n up to " + top + " meets the tolerance " + shortest(tolerance_) + " (relative)";
    if (best) {
        const double relative = best->check.relative;
        // The least tolerance that accepts the best rung's answer (check_estimate), where one in (0, 1) does.
        // Rounded up before it is compared with 1: 0.995 would be advised as 1, which no tolerance may be.
        const double accepted = best->check.answering > 0.0 ? rounded_up(best->check.answering, 2) : 0.0;
        msg +=
            ": the best estimate reached is " + best->check.quantity + " +- " + bound_text(best->check.estimate) +
            (std::isfinite(relative) ? " (" + bound_text(relative) + " relative)" : std::string(" (of a zero value)")) +
            " at n = " + std::to_string(best->n) + (beyond_all.empty() ? skipped + not_solved : ", and " + beyond_all) +
            (rounding_limit ? ", and at n = " + std::to_string(last_n) + " " + last_reason : std::string()) +
            // The tolerance only: n given is not the ladder's route (free rolling at a given n takes the edge layers
            // neglected where the ladder solved the five zones, docs/formulation.md 8(n)), so "--n N" would not give
            // the answer named here (session 25 audit F2).
            "; raise the tolerance (solver.tolerance, --tolerance" +
            (accepted > 0.0 && accepted < 1.0
                 ? "; a tolerance of " + significant(accepted, 2) + " (" + best->check.answering_quantity +
                       "'s relative estimate) answers at n = " + std::to_string(best->n) + " or below"
                 : std::string()) +
            "), or try another method" +
            (skipped.empty() && beyond_all.empty() && not_solved.empty() ? "" : " or coupling = \"johnson\"");
    } else {
        msg += ": no n gave an answer whose checks hold with an error estimate (at n = " + std::to_string(last_n) +
               ": " + last_reason + skipped + ")" +
               (advised_last ? "" : "; give n to see that point, or try another method or zone search");
    }
    throw resolution_error(msg);
}

std::optional<level_ladder::answer> level_ladder::below_first(double Q) {
    // docs/formulation.md 8(q), "Rungs below the first". The braked three zones of smooth rollers at full coupling
    // (one slip direction at both edges: Q beta_D < 0, 8(g), (h)) are solved with the stick zone and the pressure on
    // their Jacobi weights (8(v), 8(w)), where every level change from n = 16 on is at rounding or far above the
    // distance from n = 1000 (the estimates bound it by factors 3 to 10^7: the braked pair Q/f = -0.75 and the strong
    // scene beta_D = 0.3, f = 0.2, Q/f = -0.75 at n = 16 .. 128, 8(q)'s table): such a point may answer at a rung below
    // the first. The rung's own estimate decides, as at any rung; a braked point whose stick zone is not on its Jacobi
    // weight (five zones near free rolling, a zone at an edge, gross sliding) is left to the rungs from the first,
    // untouched (these rungs' levels are their own: spectral_levels_). Free rolling and the driven side (Q beta_D >= 0)
    // are five_zones_below_first's.
    if (flagged_final_ || !smooth_) return std::nullopt;
    const contact& first = at(rungs_.front());
    const dissimilar& m = first.materials();
    if (m.coupling != coupling_level::full || !(std::fabs(Q) < first.friction())) return std::nullopt;
    if (!(Q * m.beta_d < 0.0)) return shared_ ? five_zones_below_first(Q) : std::nullopt;
    for (const int n : spectral_rungs(how_)) {
        try {
            std::unique_ptr<contact>& c = built_[n];
            if (!c) c = make_(n, spectral_levels_);
            tangential_solution s = c->point(Q);
            if (!(s.weight_a > 0.0) || !s.checks.hold()) break;  // not the spectral structure: the climb decides
            std::optional<error_estimate> e = c->estimate(s);
            if (e && check(*c, s, *e).ratio <= 1.0) return answer{std::move(s), std::move(e), n};
        } catch (const beyond_method_error&) {
            throw;
        } catch (const resolution_error&) {
            // Safe to drop: nothing of these rungs reaches the climb (their own store and contacts), which solves its
            // rungs as without them and refuses, where it does, with its own line.
            break;
        } catch (const numerical_error&) {
            break;
        }
    }
    return std::nullopt;
}

std::optional<level_ladder::answer> level_ladder::five_zones_below_first(double Q) {
    // docs/formulation.md 8(q), "Rungs below the first": free rolling and the driven side (Q beta_D >= 0) of smooth
    // rollers at full coupling. Their five zones on the pressure's weight (8(x)) converge fast enough that free rolling
    // of the pair at f = 0.05 meets the default tolerance at n = 64 (stick start +- 2.4e-5, 7.7e-5 of 1 + s; its
    // distance from n = 1000 7.6e-7): rung n_0/2 is tried, on the climb's own store (level_store), so that where it
    // does not answer (the driven point, whose thin second stick zone needs n = 256) the climb's rung n_0 takes its
    // levels n_0/4, n_0/2 as solved here and only level n_0/8 was added. Rung n_0/4 is not tried: free rolling fails
    // (3.4) at n = 32 (8(r)), after levels 8 and 16. Tried only where the rungs share their levels (a factory of n
    // alone shares none: there a rung that does not answer would cost its three levels). Only five zones answer here, with their checks holding and
    // their estimate within the tolerance; any other structure is left to the climb. (A ladder that tried rung n_0/2
    // for a braked load first keeps that contact, on its own store: right, only not shared.)
    const int n = spectral_rungs(how_).back();
    try {
        contact& c = at(n);
        tangential_solution s = c.point(Q);
        if (s.layout.stick_zones() != 2 || !s.checks.hold()) return std::nullopt;
        std::optional<error_estimate> e = c.estimate(s);
        if (e && check(c, s, *e).ratio <= 1.0) return answer{std::move(s), std::move(e), n};
    } catch (const beyond_method_error&) {
        throw;
    } catch (const resolution_error&) {
        // The climb solves its rungs and refuses, where it does, with its own line; the levels made here that it
        // asks for again are the store's, as a lower rung's would be.
    } catch (const numerical_error&) {
    }
    return std::nullopt;
}

level_ladder::answer level_ladder::point(double Q, std::size_t from) {
    // A point that no rung can answer, as the first rung's contact that can be built tells before any
    // solve: refused at once. (A rung that cannot be built is refused by the climb as before.)
    for (std::size_t i = from; i < rungs_.size(); ++i) {
        std::optional<std::string> why;
        try {
            why = at(rungs_[i]).beyond_every_n(Q, rungs_.back(), tolerance_);
        } catch (const resolution_error&) {
            continue;
        }
        if (why) throw resolution_error(*why);
        break;
    }
    if (from == 0)
        if (std::optional<answer> a = below_first(Q)) return std::move(*a);
    return climb(
        [Q](contact& c, int n) {
            tangential_solution s = c.point(Q);
            std::optional<error_estimate> e = c.estimate(s);
            return answer{std::move(s), std::move(e), n};
        },
        from, Q);
}

level_ladder::answer level_ladder::at_stick_end(double c0, std::size_t from) {
    return climb(
        [c0](contact& c, int n) {
            contact::swept_point p = c.at_stick_end(c0);
            return answer{std::move(p.solution), std::move(p.estimate), n};
        },
        from);
}

std::vector<curve_point> ladder_curve(level_ladder& ladder, const std::vector<double>& loads, int points, bool sweep,
                                      std::vector<int>& n_used, const std::function<void()>& before_row) {
    const int first = ladder.rungs().front();
    contact& c = ladder.at(first);
    // A row no rung can answer is refused before any solve, with point()'s line (contact::beyond_every_n).
    std::vector<bool> at_once;
    const refusal_before_solve beyond = [&](double Q) {
        std::optional<std::string> why = c.beyond_every_n(Q, ladder.rungs().back(), ladder.tolerance());
        at_once.push_back(why.has_value());
        return why;
    };
    std::vector<curve_point> rows =
        sweep ? swept_curve(c, points, before_row, beyond) : creep_curve(c, loads, before_row, beyond);
    const double f = c.friction();
    n_used.assign(rows.size(), first);
    // Swept in c0 (beta_D = 0); dissimilar rollers' swept curve is continued at the given loads (swept_curve).
    const bool in_c0 = sweep && c.materials().beta_d == 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        curve_point& row = rows[i];
        if (!row.is_refused() && ladder.answers(c, row.solution, row.estimate)) continue;
        if (!in_c0 && at_once.at(i)) {
            n_used[i] = 0;
            continue;
        }
        // What the row was given: its load, or on a swept curve its stick end (swept_curve's c0s).
        const double given =
            in_c0 ? (i + 1 == rows.size() ? -1.0 : 2.0 * (1.0 - static_cast<double>(i) / (points - 1)) - 1.0)
                  : loads[i];
        try {
            level_ladder::answer a = in_c0 ? ladder.at_stick_end(given, 1) : ladder.point(given, 1);
            const carter_point smooth = carter(a.solution.Q, f);
            row = curve_point{std::move(a.solution), smooth, std::move(a.estimate), {}};
            n_used[i] = a.n;
        } catch (const resolution_error& e) {  // no rung answers this row: a refused row, the curve goes on
            if (!in_c0) {
                row = refused_load(given, f, e);
            } else {
                curve_point refused = refused_load(0.0, f, e);  // its shape; then what a swept row was given
                refused.solution.Q = std::nan("");
                refused.solution.layout = one_stick_zone(refused.solution.start(), given);  // c0 = given
                refused.smooth = carter_point{given, carter_at_stick_end(given, f).xi};
                refused.refused = "curve point at c0 = " + shortest(given) + ": " + one_line(e.what());
                row = std::move(refused);
            }
            n_used[i] = 0;
        }
    }
    return rows;
}

}  // namespace roughroll
