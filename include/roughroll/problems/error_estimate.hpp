// SPDX-License-Identifier: GPL-3.0-or-later
// The error estimate of a point, per quantity, as contact::estimate returns it and the reports print
// it (docs/performance.md, "How the error estimates are made"). A value, apart from its rule
// (point_estimate.hpp): part of the public interface (roughroll.hpp).
#pragma once

#include <optional>
#include <string>

namespace roughroll {

// Full coupling's level changes (docs/formulation.md 8(q)), one per field of error_estimate (each the
// largest over the zone ends folded into it, as the estimate folds them).
struct level_changes {
    double lambda = 0.0, c0 = 0.0, xi = 0.0, start = 0.0;
    bool c0_second_zone = false, start_second_zone = false;  // as error_estimate's: whose end the largest is
};
struct coupled_changes {
    level_changes last;  // |x_n - x_{n/2}| less both levels' noise: `next_factor` times it is in the estimate at 2n
    level_changes order_one;  // min(|x_n - x_{n/2}|, |x_{n/2} - x_{n/4}|/2) less the noise: C/n where x_k = x + C/k
    // The certain share of rung 2n's estimate in |x_n - x_{n/2}| (8(q) rule (a)): 2 where the levels n/2, n, 2n can only
    // take twice the larger change, 3/2^p where they may take the three-level rule (three times at least a 2^p-th of
    // the change before: 8(q) "The three-level rule at full coupling").
    double next_factor = 2.0;
};

// The peak pressure's estimates (pressure_peak of normal_solution.hpp, at level n): its position r and its value p in
// units of P2/a, from the normal solutions of the levels the point's estimate already solved (point_estimate.hpp,
// peak_from_levels; docs/performance.md "The peak pressure's estimate").
// `centre`: the pressure at the centre, p(0) in units of P2/a, by the same rule from the same levels' p(0)
// (docs/formulation.md 2(j), "The SI values' estimates").
struct peak_error {
    double r, p;
    double centre;
};

// Full coupling's four measured values (coupling_summary, and normal_solution's gamma_0n; docs/formulation.md 8(e), "The
// measured values' estimates"): the offset e = x_c/a, gamma_0n, Johnson's P_H/P2 and the peak pressure's relative change
// at the same P2. Both what one level measured (point_estimate.hpp, reading_of) and their estimates from the point's
// levels (error_estimate::coupling, coupling_from_levels; NaN where a value has none).
struct coupling_values {
    double offset, gamma, lambda_johnson, peak_change;
};

// Full coupling's zone ends by one Richardson level of order 2 (docs/formulation.md 8(q), "One Richardson level for the
// zone ends"), each end on its own: where its changes over the levels n/4, n/2, n fall at order 2 cleanly, its value from
// levels n/2 and n, x_n + (x_n - x_{n/2})/3, and that value's estimate (`extrapolated`); elsewhere level n's value and
// its own estimate (the one folded into c0's or the start's member). Values beside the point's: its zones, traction,
// creep and the ends it reports (tangential_solution; error_estimate::c0, start) stay level n's.
struct zone_end_value {
    double value, error;
    bool extrapolated;
};
struct zone_end_values {
    // The second stick zone's ends for five zones only.
    std::optional<zone_end_value> c0, start, end2, start2;
};

// The error estimate of a point, per quantity. Every estimate comes from three levels of the same
// plain discretisation (the method itself; product integration for method::extrapolated): n/4,
// n/2, n where n/2 is in the asymptotic range and n/4 can be solved, else n/2, n, 2n, else n, 2n,
// 4n. The observed ratio of the two differences decides (numerics/error_bound.hpp): where it shows
// the method's order, the classic estimates (the difference from n/2, about 2^p - 1 times the
// error at n; for method::extrapolated the difference from level n); where it shows a lower order,
// a bound from the observed ratio; where the levels do not converge visibly, no estimate: the point
// is refused (resolution_error). Each estimate includes a rounding floor (floors_at below).
struct error_estimate {
    double lambda;  // P_H/P2
    double c0;      // 0 for a point of a curve swept in c0 (c0 is then the input)
    double xi;
    double Q;             // 0 for a point at a given Q (Q is then the input)
    std::string against;  // the levels used, e.g. "n/2 (levels n/4, n/2, n)"
    bool bounded;         // a quantity converged below the method's order: bound from the observed ratio
    double start = 0.0;   // the stick zone's start, for dissimilar rollers (docs/formulation.md 8); else 0
    // Full coupling on levels n/4, n/2, n: the changes behind the estimate, which bound the next rungs'
    // estimates (level_ladder, docs/formulation.md 8(q)); empty for every other rule.
    std::optional<coupled_changes> changes = std::nullopt;
    // The peak pressure's position and value; empty where the point's estimate has no levels (the edge layers
    // neglected). Not among the quantities the ladder's tolerance asks for (level_ladder.hpp), and a refusal only where
    // its changes of opposite sign cannot be confirmed on level 2n (docs/formulation.md 8(q) "Changes of opposite sign").
    std::optional<peak_error> peak = std::nullopt;
    // Five zones (two stick zones): c0's estimate is the larger of the main zone's end and the second zone's end, the
    // start's of the two zones' starts (formulation 7 "What c0 means"); true where the second zone's is the larger, so
    // that a refusal names the zone end a user sees (level_ladder's check_estimate), not the member it is folded into.
    bool c0_second_zone = false;
    bool start_second_zone = false;
    // A ladder's rung whose estimate from n/4, n/2, n already fails the ladder's tolerance where its changes of opposite
    // sign would be confirmed on level 2n (8(q) "Changes of opposite sign"; rough rollers at full coupling): level 2n
    // was not solved, so every member is only a lower bound of the estimate (a confirmation raises it or refuses). The
    // rung cannot answer; the ladder confirms it only to name it as the best estimate reached. Such an estimate never
    // leaves level_ladder::climb (the store's test is set during the climb alone): no printer reads this member.
    bool lower_bound = false;
    // Full coupling on smooth rollers, levels n/4, n/2, n: each zone end by one Richardson level where its changes are
    // clean order 2, else level n's with its own estimate (zone_end_values); empty for every other rule. Not read by the
    // ladder's tolerance (level_ladder's check_estimate reads c0 and start, level n's): an answer's n is chosen as before.
    std::optional<zone_end_values> zone_ends = std::nullopt;
    // Full coupling on levels (not the edge layers' closed form): its measured values' estimates (coupling_values).
    std::optional<coupling_values> coupling = std::nullopt;
};

}  // namespace roughroll
