// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_solver.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/zone_family.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {
// Below this 1 - |Q|/f the search starts from the operator's model zone near gross sliding (7(e), 7(g)).
constexpr double near_sliding = 1e-4;
}  // namespace

zone_solver::zone_solver(stick_zone_operator op) : op_(std::move(op)) {}

double zone_solver::entry_coefficient(const tangential_solution& s) {
    return s.psi_b.empty() ? 0.0 : u_series(s.psi_b, -1.0);  // psi(-1) = sum_j b_j U_j(-1)
}

zone_newton_from zone_solver::newton(double magnitude) {
    return [this, magnitude](double start, double end) {
        // The operator's residuals (ends_newton): relative for the zones of one slip direction (7(e), 7(g)),
        // absolute for the blended zones of 8(g). Empty when it does not converge: the caller falls back to Brent.
        return ends_newton<tangential_solution>(
            [this](const std::vector<stick_span>& z) -> std::optional<tangential_solution> {
                return op_.solve(z[0].start, z[0].end);
            },
            op_.newton_entry, magnitude, op_.f, {{start, end, 0.0}}, op_.method.relative_load, zone_newton_iterations,
            op_.method.newton_tolerance);
    };
}

std::optional<zone_solver::found> zone_solver::bracketed(const zone_family& zones,
                                                         const std::vector<zone_trial>& trials, double magnitude,
                                                         std::optional<tangential_solution>& first) {
    const bool every = op_.method.every_bracket;
    for (std::size_t k = 1; k < trials.size(); ++k) {
        if (!brackets_entry(trials[k - 1], trials[k])) continue;
        std::optional<tangential_solution> s;
        try {
            s = zone_in_bracket(zones, trials[k - 1], trials[k], newton(magnitude));
        } catch (const numerical_error&) {
            if (!every) throw;
            continue;  // a bracket that fails to solve: the next one may answer
        }
        // The scan to the first bracket ends on it: its zone answers, checked by the caller.
        if (!every) return found{*s, false, false};
        s->checks = op_.check(*s);
        if (s->checks.hold()) return found{*s, true, false};
        if (!first) first = s;
    }
    return std::nullopt;
}

zone_solver::found zone_solver::general(double magnitude, std::optional<zone_guess> guess,
                                        std::optional<double> single_end) {
    const double f = op_.f;
    const zone_search_method& method = op_.method;
    // Q(start, c0) - |Q| falls from the empty zone's load (c0 = start) as the zone grows (7(c)), in the
    // operator's form (its excess).
    std::optional<double> last_end = single_end;
    const zone_family zones{[&](double start) {
                                const auto c = stick_zone_end(
                                    [&](double c0) {
                                        if (c0 <= start) return op_.empty_load(start) - magnitude;
                                        return op_.excess(op_.solve(start, c0), magnitude);
                                    },
                                    start, method.chained_ends ? last_end : std::nullopt);
                                if (c) last_end = c;
                                return c;
                            },
                            op_.solve, op_.entry};
    // The paper's zone first: if E <= 0 at start = -1 it is the answer (7(b), 7(g)).
    std::optional<double> edge_end = single_end;
    if (!edge_end && method.edge == edge_zone::needed) {
        edge_end = zones.end(-1.0);
        if (!edge_end) {
            std::ostringstream msg;
            msg.precision(17);
            msg << method.name << ": no stick zone from the leading edge carries |Q|/f = " << magnitude / f;
            throw numerical_error(msg.str());
        }
    }
    double at_edge_entry = std::numeric_limits<double>::quiet_NaN();  // unknown: the scan decides
    if (edge_end) {
        tangential_solution at_edge = op_.solve(-1.0, *edge_end);
        at_edge_entry = op_.entry(at_edge);
        if (at_edge_entry <= 0.0) return {at_edge, false, false};
    }
    // r*, where G is least: the stick zone straddles it and collapses onto it at gross sliding (7(d)).
    std::optional<double> point;
    const auto least_point = [&] {
        if (!point) point = op_.gross_sliding().c0();
        return *point;
    };
    // Near gross sliding: from the operator's model zone at r*, before the coarse level's guess,
    // which rounding makes no better.
    if (op_.near_sliding && f - magnitude <= near_sliding * f)
        if (auto s = op_.near_sliding(magnitude, least_point(), newton(magnitude))) return {*s, false, false};
    // Newton from the coarse level's zone when extrapolating.
    if (guess && guess->start > -1.0)
        if (auto s = newton(magnitude)(guess->start, guess->c0)) return {*s, false, true};
    // Else bracket the entry condition along the family of zones [s, c(s)] that carry |Q|
    // (7(e), zone_family.hpp), the zone from the leading edge (where the structure has one) first.
    std::vector<double> starts;
    if (method.clustered) {
        for (int k = 1; k < method.scan; ++k) starts.push_back(-std::cos(M_PI * k / method.scan));
    } else {
        const double top = method.scan_to_least_point ? least_point() : 1.0;
        for (int k = 1; k <= method.scan; ++k)
            if (const double start = -1.0 + (top + 1.0) * k / method.scan; start < 1.0) starts.push_back(start);
    }
    std::vector<zone_trial> opening;
    if (method.edge != edge_zone::absent) opening.push_back({-1.0, edge_end.value_or(-1.0), at_edge_entry});
    const std::vector<zone_trial> trials = scan_starts(zones, opening, starts, !method.every_bracket);
    std::optional<tangential_solution> first;
    if (auto s = bracketed(zones, trials, magnitude, first)) return *s;
    if (method.every_bracket && !first && !trials.empty()) {
        // Near gross sliding the leading slip zone of dissimilar rollers thins below the clustered scan's
        // first start, 1 - cos(pi/32) = 4.8e-3 from the edge (the stick zone closes on the leading edge as
        // 7(d)'s does, its start 1 + s ~ (1 - |Q|/f)^(2/3)): starts geometrically closer to the edge, down to
        // 1e-12, before the first trial. Only where the scan found nothing, so that no other answer changes.
        std::vector<double> near_edge;
        for (double gap = 1e-12; gap < 1.0 + trials.front().start; gap *= 10.0) near_edge.push_back(-1.0 + gap);
        std::vector<zone_trial> edge = scan_starts(zones, {}, near_edge, false);
        edge.push_back(trials.front());
        if (auto s = bracketed(zones, edge, magnitude, first)) return *s;
    }
    if (first) return {*first, true, false};  // the caller refuses it: its checks fail
    // Where the scan ends on no bracket, no zone of this structure carries the load (not a numerical
    // fault): zones = "auto" answers with the paper's zone and its failed checks where that zone exists
    // (contact::zones_for), dissimilar_zones::solve tries its other structure, a curve refuses the row
    // (docs/robustness.md).
    throw resolution_error(method.refusal);
}

tangential_solution zone_solver::solve(double Q, bool force_general, std::optional<zone_guess> guess) {
    const double magnitude = load_magnitude(Q, op_.f);
    const std::optional<tangential_solution> single = op_.paper_zone(Q, force_general && magnitude != 0.0);
    if (single && (magnitude == 0.0 || (!force_general && single->checks.hold()))) return *single;
    const std::optional<double> single_end = single ? std::optional<double>(single->c0()) : std::nullopt;
    check_load_resolvable(magnitude, op_.f);
    const auto search = [&](std::optional<zone_guess> g) {
        if (magnitude == op_.f)
            return std::make_pair(searched_point(op_.gross_sliding(), Q, op_.method.name, op_.check), false);
        found z = general(magnitude, g, single_end);
        // The checks the scan made in the |Q| frame are Q's: the mirror changes the signs of p1 and v together.
        return std::make_pair(
            searched_point(std::move(z.zone), Q, op_.method.name, z.checked ? decltype(op_.check){} : op_.check),
            z.from_guess);
    };
    auto [s, from_guess] = search(guess);
    // Newton from a guess may find another zone that solves both conditions but not the
    // inequalities (seen near s = 0.97 while it wandered): then search without the guess.
    if (from_guess && !s.checks.hold()) s = search(std::nullopt).first;
    return s;
}

}  // namespace roughroll
