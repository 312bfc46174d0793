// SPDX-License-Identifier: GPL-3.0-or-later
// The starts of a zone search as data (issue 24, item 3): each start a base layout and a path of continuations
// from it to the load asked, tried in order by one loop (search_from, below; find_zones, zone_solver.hpp), each
// giving a verdict (its root, whether the search ends there), the first root whose checks hold the answer
// (first_holding, the acceptance every zone search shares). The strategies, and the docs/formulation.md section each
// comes from:
//   - the coarser level's layout: Newton from its ends at the load (8(j) 9; at full coupling the previous iterate's,
//     8(e); a caller's continuation in f is this start from the previous f's ends, since by 8(h) the ends move
//     with beta_D/f alone: 8(j) 4a, 8(n));
//   - a layout already solved, continued in the load Q: a curve's previous row (8(j) 10);
//   - the driven three zones at a load (the leading slip against Q, 8(g); 8(j) 4a "Starting ends"): their stick
//     zone the first, the second where their v turns negative; three zones whose v stays positive up to the edge
//     at the load asked are its answer, not five zones (8(j) 4), and end the search;
//   - a scan of such loads Q/f = k/8 above Q, each continued in Q down to Q (8(j) 4a (1)): on the braked side
//     through free rolling, which every start reaches alike, so that a stop there is the transition to three
//     zones (8(j) 4a "The braked side") and ends the search;
//   - continuation in the forcing beta_D/f at fixed f (8(j) 4a (2)), the continuation in f of 8(h) (the ends
//     depend on beta_D/f alone): the scan's three zones give starts for beta_D/f in [1, 6]; outside, free rolling
//     there (2.875 or 1.5) continued in beta_D/f, then in Q (factors 2^(1/4): 2^(1/2) met, at f = 0.2, another
//     root whose checks fail).
//   - the one stick zone's own search (zone_solver.cpp's general search: the zone from the leading edge, the
//     near-sliding asymptote of 7(d)-(e), Newton from the coarser level's zone, the scan of stick-zone starts and its
//     brackets), its roots judged by the same rule inside it: five zones never reach gross sliding (three zones take
//     over, 8(j) 4, 4a) and their scan is one of loads, not of starts.
// Every list is tried by one driver, find_zones (zone_solver.hpp), each start in its operator's frame.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace roughroll {

// The parameter a leg of a continuation moves: the load Q, or the forcing |beta_D| at fixed f (beta_D/f, 8(h)).
enum class zone_parameter { load, forcing };

struct zone_leg {
    zone_parameter parameter;
    double target;
};

template <class S>
struct zone_start {
    enum class base { ends, solved, three_zones, search };
    base from;
    std::vector<double> ends{};  // `ends`, `search`: Newton's start at the load asked (the coarser level's layout)
    std::optional<S> solved{};   // `solved`: a layout at its own load (a curve's previous row)
    double load = 0.0;           // `three_zones`: their load, and
    double forcing = 0.0;        // their forcing (|beta_D|, or another on a continuation in beta_D/f)
    std::optional<double> edge_end{};  // `search`: the end of the paper's zone at the load, where it was solved
    // The legs after the base; every path then ends with a leg in the load to the load asked.
    std::vector<zone_leg> path{};
    // Legs after which the path is every later start's too (free rolling): a failure past them skips every later start
    // that declares it (find_zones); a start without a path of its own (the default) is still tried.
    std::size_t shared_after = std::numeric_limits<std::size_t>::max();

    static zone_start at_ends(std::vector<double> e) { return {base::ends, std::move(e)}; }
    static zone_start continuing(S s) { return {base::solved, {}, std::move(s)}; }
    static zone_start three_zones_at(double load, double forcing) { return {base::three_zones, {}, {}, load, forcing}; }
    static zone_start searching(std::vector<double> e, std::optional<double> edge_end) {
        return {base::search, std::move(e), {}, 0.0, 0.0, edge_end};
    }
};

// What one start of a zone search gave (docs/formulation.md 7(k)): its root (empty: none from here; the next start is
// tried), and whether the search ends after it (a stop: the transition to another structure, a path every later start
// shares), whatever the root.
template <class S>
struct start_verdict {
    std::optional<S> root{};
    bool ends_search = false;
};

// The acceptance of every zone search (docs/formulation.md 7(k)): roots offered in the order of their starts (five
// zones' starts, the one stick zone's brackets, dissimilar rollers' two three-zone structures), each with its checks
// (3.3)-(3.4) made; the first whose checks hold answers, and a root whose checks fail stands only where no later start
// gives one that holds (the first such, for the caller to refuse or to report with its failed checks).
template <class S>
class first_holding {
public:
    // True where `s` answers (the search ends with it).
    bool offer(S s) {
        if (s.checks.hold()) {
            answer_ = std::move(s);
            return true;
        }
        if (!failing_) failing_ = std::move(s);
        return false;
    }
    bool any() const { return answer_ || failing_; }
    // The answer, else the first root whose checks fail, else nothing.
    std::optional<S> result() && { return answer_ ? std::move(answer_) : std::move(failing_); }

private:
    std::optional<S> answer_, failing_;
};

// The starts tried in order by `attempt(start)` (a start_verdict<S>), until a root whose checks hold or a verdict that
// ends the search: first_holding's result.
template <class S, class Start, class Attempt>
std::optional<S> search_from(const std::vector<Start>& starts, const Attempt& attempt) {
    first_holding<S> roots;
    for (const Start& start : starts) {
        start_verdict<S> verdict = attempt(start);
        if (verdict.root && roots.offer(std::move(*verdict.root))) break;
        if (verdict.ends_search) break;
    }
    return std::move(roots).result();
}

// From `at` to `to` by `solve(next, previous)`: steps of `largest` (in log2 of the parameter where `geometric`),
// halved where `solve` finds nothing, down to `smallest`, doubled again after a success; the solution at `to`,
// empty where the steps run out before it.
template <class S, class Solve>
std::optional<S> continued(S s, double at, double to, double largest, double smallest, bool geometric,
                           const Solve& solve) {
    const double direction = to < at ? -1.0 : 1.0;
    double step = largest;
    while (at != to && step >= smallest) {
        double next = geometric ? at * std::pow(2.0, direction * step) : at + direction * step;
        if ((next - to) * direction > 0.0) next = to;
        if (std::optional<S> t = solve(next, s)) {
            s = std::move(*t);
            at = next;
            step = std::min(2.0 * step, largest);
        } else {
            step *= 0.5;
        }
    }
    if (at != to) return std::nullopt;
    return s;
}

}  // namespace roughroll
