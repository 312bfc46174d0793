// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_family.hpp"

#include <algorithm>
#include <cmath>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/root_search.hpp"

namespace roughroll {

namespace {
constexpr double end_tolerance = 1e-15;  // zone ends, absolute in r
constexpr int brent_iterations = 200;

bool positive(double entry) { return !(entry <= 0.0); }
}  // namespace

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

std::vector<zone_trial> scan_starts(const zone_family& family, std::vector<zone_trial> trials,
                                    const std::vector<double>& starts, bool to_first_bracket) {
    for (const double start : starts) {
        std::optional<zone_trial> t;
        try {
            if (const auto end = family.end(start)) t = zone_trial{start, *end, family.entry(family.solve(start, *end))};
        } catch (const numerical_error&) {
            if (!to_first_bracket) throw;
        }
        if (!t) {
            if (to_first_bracket) break;
            continue;
        }
        trials.push_back(*t);
        if (to_first_bracket && trials.size() > 1 && brackets_entry(trials[trials.size() - 2], trials.back())) break;
    }
    return trials;
}

bool brackets_entry(const zone_trial& lo, const zone_trial& hi) { return positive(lo.entry) != positive(hi.entry); }

tangential_solution zone_in_bracket(const zone_family& family, const zone_trial& lo, const zone_trial& hi,
                                    const zone_newton_from& newton) {
    const double w = std::isnan(lo.entry) ? 1.0 : lo.entry / (lo.entry - hi.entry);
    if (auto s = newton(lo.start + w * (hi.start - lo.start), lo.end + w * (hi.end - lo.end))) return *s;
    const auto end = [&](double start) {
        const auto c = family.end(start);
        if (!c) throw numerical_error("zone search: no stick zone carries the load inside a bracket of its entry condition");
        return *c;
    };
    const root r = brent_root([&](double start) { return family.entry(family.solve(start, end(start))); }, lo.start,
                              hi.start, end_tolerance, 0.0, brent_iterations, "Brent search for the stick zone's start");
    tangential_solution s = family.solve(r.x, end(r.x));
    s.iterations = r.iterations;
    return s;
}

tangential_solution searched_point(tangential_solution s, double Q, const char* what,
                                   const std::function<traction_checks(const tangential_solution&)>& check) {
    s.layout.route = s.start() > -1.0 ? zone_route::general : zone_route::single;
    apply_load_sign(s, Q, what);
    if (check) s.checks = check(s);
    return s;
}

}  // namespace roughroll
