// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_solver.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/root_search.hpp"
#include "roughroll/problems/zone_newton.hpp"
#include "roughroll/problems/zone_start.hpp"

namespace roughroll {

namespace {
// Below this 1 - |Q|/f the search starts from the operator's model zone near gross sliding (7(e), 7(g)).
constexpr double near_sliding = 1e-4;
constexpr double end_tolerance = 1e-15;  // zone ends by Brent, absolute in r
constexpr int brent_iterations = 200;
// find_zones' continuations (8(j) 4a): in the load f/8, halved down to f/1024 (the slip+ zone closing near the
// braked transition); in the forcing factors 2^(1/4), halved in the exponent down to 2^(1/64).
constexpr double load_step = 1.0 / 8.0, smallest_load_step = 1.0 / 1024.0;  // times f
constexpr double forcing_step = 0.25, smallest_forcing_step = 1.0 / 64.0;   // in log2 of the forcing

// The stick zones [s, c(s)] that carry a load |Q| < f (7(e) step 3; 7(g); 8(g)). For a start s the end c(s) is
// the root of the load's excess
//   e(c) = Q(s, c) - |Q|  on (s, 1],   e(s) > 0 (no stick zone: the slip zones carry more than |Q|),
// falling as the zone grows, by Brent to 1e-15 in r. Along the family the entry condition E(s) of the zone
// [s, c(s)] (psi(-1) = 0 of 7(b), v(s-) = 0 of 7(g)) vanishes at the answer: trial starts are scanned for its
// sign changes, and a bracket is solved by Newton from the zone interpolated between its trials (ends_newton),
// else by Brent on s (each start with its own end: nested Brent). The family is the operator's zones with c(s):
using zone_end = std::function<std::optional<double>(double start)>;  // empty where no end carries |Q|

struct zone_trial {
    double start, end, entry;
};

// The end c in (start, 1] with excess(c) = 0, where excess(start) > 0 > excess(1); empty where no end carries
// the load. `near`: the end of a nearby start, tried first on a bracket of half-width 1e-3.
std::optional<double> stick_zone_end(const std::function<double(double)>& excess, double start,
                                     std::optional<double> near) {
    const char* what = "Brent search for the stick zone's end";
    if (near) {
        const double lo = std::max(start, *near - 1e-3), hi = std::min(1.0, *near + 1e-3);
        if (lo < hi && excess(lo) > 0.0 && excess(hi) < 0.0)
            return brent_root(excess, lo, hi, end_tolerance, 0.0, brent_iterations, what).x;
    }
    if (!(excess(start) > 0.0 && excess(1.0) < 0.0)) return std::nullopt;
    return brent_root(excess, start, 1.0, end_tolerance, 0.0, brent_iterations, what).x;
}

// Whether E changes sign between two trials (an unknown, NaN, entry counts as positive).
bool brackets_entry(const zone_trial& lo, const zone_trial& hi) { return !(lo.entry <= 0.0) != !(hi.entry <= 0.0); }

// The trials at `starts`, in order, after `trials`. `to_first_bracket`: stop after the first trial whose entry
// changes sign against the one before (brackets_entry), and at a start without a zone; else every start is tried,
// one without a zone skipped. A zone that fails to solve (numerical_error) is a fault either way, not "no zone".
std::vector<zone_trial> scan_starts(const stick_zone_operator& op, const zone_end& end_of,
                                    std::vector<zone_trial> trials, const std::vector<double>& starts,
                                    bool to_first_bracket) {
    for (const double start : starts) {
        std::optional<zone_trial> t;
        if (const auto end = end_of(start)) t = zone_trial{start, *end, op.entry(op.solve(start, *end))};
        if (!t) {
            if (to_first_bracket) break;
            continue;
        }
        trials.push_back(*t);
        if (to_first_bracket && trials.size() > 1 && brackets_entry(trials[trials.size() - 2], trials.back())) break;
    }
    return trials;
}

// The zone of a bracket [lo, hi] of E: `newton` from the interpolated zone (from hi's where lo's entry is
// unknown), else Brent on the start; numerical_error where Brent fails or a start has no zone.
tangential_solution zone_in_bracket(const stick_zone_operator& op, const zone_end& end_of, const zone_trial& lo,
                                    const zone_trial& hi, const zone_newton_from& newton) {
    const double w = std::isnan(lo.entry) ? 1.0 : lo.entry / (lo.entry - hi.entry);
    if (auto s = newton(lo.start + w * (hi.start - lo.start), lo.end + w * (hi.end - lo.end))) return *s;
    const auto end = [&](double start) {
        const auto c = end_of(start);
        if (!c)
            throw numerical_error(
                "zone search: no stick zone carries the load inside a bracket of its entry condition");
        return *c;
    };
    const root r =
        brent_root([&](double start) { return op.entry(op.solve(start, end(start))); }, lo.start, hi.start,
                   end_tolerance, 0.0, brent_iterations, "Brent search for the stick zone's start");
    tangential_solution s = op.solve(r.x, end(r.x));
    s.iterations = r.iterations;
    return s;
}

// A search's |Q| solution as the point at Q: general where its stick zone starts inside the contact, the mirror
// for Q < 0 (apply_load_sign, `what` naming the search). Its checks (3.3)-(3.4), made in the |Q| frame, are Q's: the
// mirror changes the signs of p1 and v together.
tangential_solution searched_point(tangential_solution s, double Q, const char* what) {
    s.layout.route = s.start() > -1.0 ? zone_route::general : zone_route::single;
    apply_load_sign(s, Q, what);
    return s;
}

// Newton in the zone ends at |Q| (zone_newton), its stops at the rounding limit noted in `met`: empty where it does
// not converge, or stops at the rounding limit; the caller falls back to Brent, or to its next start.
zone_newton_from newton_at(const stick_zone_operator& op, double magnitude, rounding_limits& met) {
    return [&op, magnitude, &met](double start, double end) { return zone_newton(op, magnitude, {start, end}, met); };
}

// The zone of the first of `trials`' brackets that answers: each bracket a start of the search, its zone offered to
// `roots` with its checks made (first_holding, zone_start.hpp); true where one answers, or where the scan to the first
// bracket (not zone_search_method::every_bracket) solved its one bracket, which ends the search either way.
bool bracketed(const stick_zone_operator& op, const zone_end& end_of,
                               const std::vector<zone_trial>& trials, double magnitude,
                               first_holding<tangential_solution>& roots, rounding_limits& met) {
    const bool every = op.method.every_bracket;
    for (std::size_t k = 1; k < trials.size(); ++k) {
        if (!brackets_entry(trials[k - 1], trials[k])) continue;
        rounding_limits here;  // where this bracket's Newton stopped at the rounding limit
        std::optional<tangential_solution> s;
        try {
            s = zone_in_bracket(op, end_of, trials[k - 1], trials[k], newton_at(op, magnitude, here));
        } catch (const numerical_error&) {
            met.note(here);
            // A bracket that fails to solve: the next one may answer. The scan to the first bracket has no next one:
            // its fault is the search's, except where Newton stopped here at the rounding limit (8(q)), which is "no
            // root from here" to every route: Brent's fault after it is that rounding's, so the bracket gives no zone
            // (the limit noted in `met`), and where no other route answers, find refuses with the limit's line.
            if (!every && !here.met()) throw;
            continue;
        }
        met.note(here);
        s->checks = op.check(*s);
        if (roots.offer(*std::move(s)) || !every) return true;  // the scan to the first bracket has this one only
    }
    return false;
}

// The general search at |Q| = magnitude; single_end: the paper's zone's c0 at this load, when it was solved
// (saves one search). Empty where the scan ends on no bracket: no zone of the structure carries |Q|, or none is
// found where a Newton of the search stopped at the rounding limit (noted in `met`). Every start (the zone from the
// leading edge, the near-sliding model, the coarser level's zone, the brackets of the scan and below it) gives a root
// with its checks made, judged by one rule (first_holding, zone_start.hpp, docs/formulation.md 7(k)): the first whose
// checks hold answers, else the first found (the caller refuses it or reports it with its failed checks).
std::optional<tangential_solution> general_search(const stick_zone_operator& op, double magnitude, const std::vector<double>& ends,
                                    std::optional<double> single_end, rounding_limits& met) {
    const double f = op.f;
    const zone_search_method& method = op.method;
    // Q(start, c0) - |Q| falls from the empty zone's load (c0 = start) as the zone grows (7(c)), in the
    // operator's form (its excess).
    std::optional<double> last_end = single_end;
    const zone_end end_of = [&](double start) {
        const auto c = stick_zone_end(
            [&](double c0) {
                if (c0 <= start) return op.empty_load(start) - magnitude;
                return op.excess(op.solve(start, c0), magnitude);
            },
            start, method.chained_ends ? last_end : std::nullopt);
        if (c) last_end = c;
        return c;
    };
    // The paper's zone first: if E <= 0 at start = -1 it is the answer (7(b), 7(g)).
    std::optional<double> edge_end = single_end;
    if (!edge_end && method.edge == edge_zone::needed) {
        edge_end = end_of(-1.0);
        if (!edge_end) {
            std::ostringstream msg;
            msg.precision(17);
            msg << method.name << ": no stick zone from the leading edge carries |Q|/f = " << magnitude / f;
            throw numerical_error(msg.str());
        }
    }
    first_holding<tangential_solution> roots;
    const auto answers = [&](tangential_solution s) {
        s.checks = op.check(s);
        return roots.offer(std::move(s));
    };
    double at_edge_entry = std::numeric_limits<double>::quiet_NaN();  // unknown: the scan decides
    if (edge_end) {
        tangential_solution at_edge = op.solve(-1.0, *edge_end);
        at_edge_entry = op.entry(at_edge);
        if (at_edge_entry <= 0.0 && answers(std::move(at_edge))) return std::move(roots).result();
    }
    // r*, where G is least: the stick zone straddles it and collapses onto it at gross sliding (7(d)).
    std::optional<double> point;
    const auto least_point = [&] {
        if (!point) point = op.gross_sliding().c0();
        return *point;
    };
    // Near gross sliding: from the operator's model zone at r*, before the coarse level's guess,
    // which rounding makes no better.
    if (op.near_sliding && f - magnitude <= near_sliding * f)
        if (auto s = op.near_sliding(magnitude, least_point(), newton_at(op, magnitude, met)); s && answers(*s))
            return std::move(roots).result();
    // Newton from the coarse level's zone when extrapolating. It may find another zone that solves both conditions but
    // not the inequalities (seen near s = 0.97 while it wandered): then the scan goes on.
    if (ends.size() == 2 && ends[0] > -1.0)
        if (auto s = zone_newton(op, magnitude, ends, met); s && answers(*s))
            return std::move(roots).result();
    // Else bracket the entry condition along the family of zones [s, c(s)] that carry |Q|
    // (7(e), zone_end above), the zone from the leading edge (where the structure has one) first.
    std::vector<double> starts;
    if (method.clustered) {
        for (int k = 1; k < method.scan; ++k) starts.push_back(-std::cos(M_PI * k / method.scan));
    } else {
        // Starts inside (-1, 1) only: the zone from the leading edge is the opening trial's. Where r* = -1 (the
        // one-parameter limit near gross sliding, 7(g)) every start of the scan to r* would be the edge, each zone
        // [-1, c] there too short to solve (singular at Q/f = 1 - 1e-12): no start, no zone of the structure.
        const double top = method.scan_to_least_point ? least_point() : 1.0;
        for (int k = 1; k <= method.scan; ++k)
            if (const double start = -1.0 + (top + 1.0) * k / method.scan; start > -1.0 && start < 1.0)
                starts.push_back(start);
    }
    std::vector<zone_trial> opening;
    if (method.edge != edge_zone::absent) opening.push_back({-1.0, edge_end.value_or(-1.0), at_edge_entry});
    std::vector<zone_trial> trials = scan_starts(op, end_of, opening, starts, !method.every_bracket);
    if (bracketed(op, end_of, trials, magnitude, roots, met)) return std::move(roots).result();
    // No start carrying |Q| opens the pass for the clustered scan alone (its first start 4.8e-3 off the edge, the
    // blended zones' 8(g)), as before e51a784: a scan up to r* = -1 has no first start to read. Whatever the reason
    // no start carries |Q|: its empty zone carrying less (near gross sliding, below), or its zone to the edge [s, 1]
    // still carrying more (three zones slipping one way at large f and small |Q/f|, whose leading slip zone is
    // 0.54 t(kappa) thick, 8(n) "Beyond every n" item 7: 1.7e-4 at f = 0.4, inside the first start's 4.8e-3).
    const bool none_carries = method.clustered && !starts.empty() && trials.empty();
    if (method.every_bracket && !roots.any() && (!trials.empty() || none_carries)) {
        // The stick zone of dissimilar rollers can start closer to the leading edge than the scan's first start,
        // 1 - cos(pi/32) = 4.8e-3 off it: near gross sliding it closes on the edge as 7(d)'s does, 1 + s ~
        // (1 - |Q|/f)^(2/3), and a leading slip zone can be thin (8(j) item 11). Where no bracket answered: starts
        // halving their distance to the edge, down to 1e-12, below `top`, the scan's first trial (the last trial of
        // these brackets) or, where no start carries |Q|, its first start; each
        // bracket solved as it is found, from the top down. With the leading slip against Q (8(g)) the empty zone at
        // s carries f (1 - 2 int_-1^s p), below |Q| from 1 + s ~ (1 - |Q|/f)^(2/3) on, so that near gross sliding no
        // start of the scan carries |Q| (from Q/f = 0.99960 on Hertz's pressure; docs/robustness.md); the answer's
        // 1 + s is about a third of that bound (Hertz's pressure), and halving steps skip no such interval. Only
        // where nothing answered, so that no other answer changes.
        std::optional<zone_trial> above;
        if (!trials.empty()) above = trials.front();
        for (double gap = 0.5 * (1.0 + (above ? above->start : starts.front())); gap > 1e-12; gap *= 0.5) {
            const std::vector<zone_trial> at = scan_starts(op, end_of, {}, {-1.0 + gap}, false);
            if (at.empty()) continue;
            if (above)
                if (bracketed(op, end_of, {at.front(), *above}, magnitude, roots, met)) return std::move(roots).result();
            above = at.front();
        }
    }
    // A root whose checks fail, for the caller to refuse. Where the scan ends on no bracket, no zone of this structure
    // carries the load (not a numerical fault): zones = "auto" answers with the paper's zone and its failed checks
    // where that zone exists (contact::zones_for), dissimilar_zones::solve tries its other structure, a curve refuses
    // the row (docs/robustness.md).
    return std::move(roots).result();
}
}  // namespace

std::optional<tangential_solution> zone_newton(const stick_zone_operator& op, double Q, const std::vector<double>& ends,
                                               rounding_limits& met, newton_jacobian* kept) {
    // No input reaches this: every caller passes a layout's ends (review R23 of session 27: a programming error).
    if (ends.size() % 2 != 0)
        throw std::invalid_argument("zone search: Newton's start needs a start and an end per stick zone");
    std::vector<stick_span> from;
    for (std::size_t k = 0; k + 1 < ends.size(); k += 2) from.push_back({ends[k], ends[k + 1], 0.0});
    using systems_of = std::function<std::optional<tangential_solution>(const std::vector<stick_span>&)>;
    const systems_of one = [&op](const std::vector<stick_span>& z) -> std::optional<tangential_solution> {
        return op.solve(z[0].start, z[0].end);
    };
    // The operator's residuals (ends_newton): relative for the zones of one slip direction (7(e), 7(g)), absolute for
    // the blended zones of 8(g) and the five zones (8(j) item 3).
    return ends_newton<tangential_solution>(op.systems ? op.systems : one, op.newton_entry, Q, op.f, from,
                                            op.method.relative_load, zone_newton_iterations, op.method.newton_tolerance,
                                            met, kept);
}

std::optional<tangential_solution> find_zones(const zone_operator_at& op_of, double Q, double forcing,
                                              const std::vector<zone_start<tangential_solution>>& starts,
                                              rounding_limits& met) {
    using base = zone_start<tangential_solution>::base;
    // A path that the later starts declaring one share (shared_after) stopped: those are skipped, a start of its own
    // (five zones' complete-slip start, 8(f)) is still tried.
    bool shared_failed = false;
    constexpr std::size_t own_path = std::numeric_limits<std::size_t>::max();
    return search_from<tangential_solution>(starts, [&](const zone_start<tangential_solution>& start) {
        start_verdict<tangential_solution> verdict;
        std::optional<tangential_solution>& s = verdict.root;
        if (shared_failed && start.shared_after != own_path) return verdict;
        if (start.from == base::search) {
            // Its own starts judged by the same rule inside it: its result is the search's.
            s = general_search(op_of(forcing), Q, start.ends, start.edge_end, met);
            verdict.ends_search = true;
            return verdict;
        }
        double load = Q, at_forcing = forcing;  // where s is, nominally (Newton's load differs by its residual)
        bool newton = start.from != base::solved;  // s is a Newton root here, unchecked
        if (start.from == base::ends) {
            s = zone_newton(op_of(forcing), Q, start.ends, met);
        } else if (start.from == base::solved) {
            s = start.solved;
            load = s->Q;
            at_forcing = s->forcing;
        } else {
            bool holds = false;
            load = start.load;
            at_forcing = start.forcing;
            s = op_of(at_forcing).seed(load, holds, met);
            // Not these zones: the other structure answers Q.
            if (holds && load == Q) return start_verdict<tangential_solution>{std::nullopt, true};
        }
        std::vector<zone_leg> path = start.path;
        path.push_back({zone_parameter::load, Q});
        const double f = op_of(at_forcing).f;
        for (std::size_t leg = 0; s && leg < path.size(); ++leg) {
            const bool in_load = path[leg].parameter == zone_parameter::load;
            double& at = in_load ? load : at_forcing;
            s = continued(*s, at, path[leg].target, in_load ? load_step * f : forcing_step,
                          in_load ? smallest_load_step * f : smallest_forcing_step, !in_load,
                          [&](double next, const tangential_solution& p) {
                              newton = true;
                              return zone_newton(op_of(in_load ? p.forcing : next), in_load ? next : load,
                                                 p.layout.stick_ends(), met);
                          });
            if (!s && leg >= start.shared_after) shared_failed = true;
            at = path[leg].target;
        }
        // The checks of the root only: a continuation's steps read none (before session 28 each step made them).
        if (s && newton) s->checks = op_of(at_forcing).check(*s);
        return verdict;
    });
}

zone_solver::zone_solver(stick_zone_operator op) : op_(std::move(op)) {}

double zone_solver::entry_coefficient(const tangential_solution& s) {
    if (s.weight_a > 0.0) return jacobi_series(s.psi_b, s.weight_a, s.weight_b, -1.0);  // 8(v): sum_j c_j P_j^(a,b)(-1)
    return s.psi_b.empty() ? 0.0 : u_series(s.psi_b, -1.0);  // psi(-1) = sum_j b_j U_j(-1)
}

std::optional<tangential_solution> zone_solver::find(double Q, bool force_general, const std::vector<double>& ends) {
    rounding_limits met;
    std::optional<tangential_solution> s = find(Q, force_general, ends, met);
    if (!s && met.met()) throw rounding_limit_error(met.refusal());
    return s;
}

std::optional<tangential_solution> zone_solver::find(double Q, bool force_general, const std::vector<double>& ends,
                                                     rounding_limits& met) {
    if (!ends.empty() && ends.size() != 2)  // a layout of another structure: a programming error (R23)
        throw std::invalid_argument("zone search: Newton's start needs the stick zone's two ends");
    const double magnitude = load_magnitude(Q, op_.f);
    const std::optional<tangential_solution> single = op_.paper_zone(Q, force_general && magnitude != 0.0);
    if (single && (magnitude == 0.0 || (!force_general && single->checks.hold()))) return *single;
    const std::optional<double> single_end = single ? std::optional<double>(single->c0()) : std::nullopt;
    check_load_resolvable(magnitude, op_.f);
    if (magnitude == op_.f) {
        tangential_solution s = searched_point(op_.gross_sliding(), Q, op_.method.name);
        s.checks = op_.check(s);
        return s;
    }
    std::optional<tangential_solution> s = find_zones([this](double) { return op_; }, magnitude, 0.0,
                                                      {zone_start<tangential_solution>::searching(ends, single_end)}, met);
    if (s) s = searched_point(*std::move(s), Q, op_.method.name);
    return s;
}

tangential_solution zone_solver::solve(double Q, bool force_general, const std::vector<double>& ends) {
    if (std::optional<tangential_solution> s = find(Q, force_general, ends)) return *std::move(s);
    throw resolution_error(op_.method.refusal);
}

}  // namespace roughroll
