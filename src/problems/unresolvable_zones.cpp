// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/unresolvable_zones.hpp"

#include <cmath>

#include "roughroll/base/text.hpp"
#include "roughroll/numerics/root_search.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"

namespace roughroll {

namespace {
// docs/formulation.md 8(f), "Below the rounding": free rolling whose stick zones are narrower than this many of W's
// breakpoint separations (breakpoint_apart) is not searched, per coupling level: below the least widths answered before
// (Bentall and Johnson's pair, 18.34 f wide: Johnson's level answered f = 3e-10, 5.5 separations, and ran for minutes
// at 2e-10 and below; full coupling answered 1e-10, 1.8 separations, and ran for minutes at 3e-11 and below). Between
// these edges and f = 1e-9 a point is answered or runs for minutes by chance (8(f)); from 1e-9 to 5e-9 every f measured
// answers. The rough pair's free rolling (data/aluminium-on-steel-rough.toml) gave no answer within 11-14 s CPU at
// f = 1e-9, 1e-8, 1e-7 and 1e-6 either: its advice says so.
constexpr double johnson_separations = 5.0, full_separations = 1.0;
// The least f named as answering free rolling (measured: 1e-9 .. 5e-9 answer at both levels).
constexpr double free_rolling_answered = 1e-9;
// 8(m), "Driven, next to sliding": the least 1 - |Q|/f on the driven side (Q beta_D > 0) that is searched (1 - 1e-13
// answers at f = 0.05; 1 - 7e-14, 5e-14, 4e-14, 1e-14 exit in the quadrature of W, 1 - 1e-15 and one ulp are refused after
// 38 s), four ulps of 1 inside 1e-13 so that --Q-over-f 0.9999999999999 (a gap of 9.992e-14 after Q = (Q/f) f at
// f = 1e-3) is not refused.
constexpr double driven_sliding_gap = 1e-13 - 4.0 * 0x1p-52;

// 8(m), "Full coupling next to sliding": the least 1 - |Q|/f on the driven side (Q beta_D > 0) that the alternation
// is asked (the braked side is refused at the alternation's first sign, full_coupling.cpp: one ulp answers at f = 0.3).
// Measured, not derived: the alternation's lambda, e, xi change per step by 1e-11 .. 7e-11 at
// 1 - |Q|/f = 1e-9 and 6e-11 .. 2.6e-10 at 1e-10 (n = 64, 128; f = 0.02, 0.05, 0.1), growing as the gap falls, against
// its 1e-12, and no n measured answered from 1e-9 down to 1e-13 (the ladder: 6.9 s CPU at 1e-9, 19 s and 14 s at
// 1e-12 and 1e-13 ending in the quadrature's own text); 1e-8 answers at n = 64 and 128 (f = 0.05, 0.1): the edge is
// put a tenth above 1e-9, so that --Q-over-f 0.999999999 is refused whatever Q = (Q/f) f rounds to (9.999999717e-10
// at f = 0.05, 9.99999861e-10 at f = 0.3).
constexpr double driven_full_gap = 1.1e-9;

// The width of each stick zone of free rolling near complete slip on Hertz's pressure, 4 f p/(pi |beta_D p'|) at the
// edge r* = sin(phi) of the central band, 2 phi + sin(2 phi) = pi/2 (8(f)): 4 f cos^2(phi)/(pi |beta_D| sin(phi)),
// 18.34 f for the pair (measured: 18.34 f at f = 1e-5 .. 1e-9).
double complete_slip_zone_width(double beta_d, double f) {
    const double phi = brent_root([](double t) { return 2.0 * t + std::sin(2.0 * t) - 0.5 * M_PI; }, 0.0, 0.5 * M_PI,
                                  1e-15, 0.0, 200, "complete slip on Hertz's pressure: the edge of the central band")
                           .x;
    const double c = std::cos(phi);
    return 4.0 * f * c * c / (M_PI * std::fabs(beta_d) * std::sin(phi));
}

std::optional<std::string> below_the_breakpoints(const dissimilar& materials, bool rough, double f, double Q) {
    if (Q != 0.0) return std::nullopt;
    const double separations = materials.coupling == coupling_level::johnson ? johnson_separations : full_separations;
    const double width = complete_slip_zone_width(materials.beta_d, f);
    if (!(width < separations * breakpoint_apart)) return std::nullopt;
    return "free rolling of dissimilar rollers (beta_d = " + significant(materials.beta_d, 3) + ") at f = " +
           shortest(f) + ": near complete slip its two stick zones are about " + significant(width, 2) +
           " of the half-width wide, below " + shortest(separations) + " times the " + shortest(breakpoint_apart) +
           " at which the integrals of its zones cut their breakpoints (docs/formulation.md 8(f)); a friction f of at "
           "least " + shortest(free_rolling_answered) + " (friction, --friction) " +
           (rough ? "is searched, though rough rollers' free rolling was not answered within minutes up to f = 1e-6"
                  : "answers it");
}

std::optional<std::string> driven_next_to_sliding(const dissimilar& materials, double f, double Q) {
    const double gap = 1.0 - std::fabs(Q) / f;
    if (!(Q * materials.beta_d > 0.0 && gap < driven_sliding_gap)) return std::nullopt;
    // The slip zone at the leading edge carries at most gap/2 of the load (8(m)): on Hertz's pressure,
    // (2/pi) sqrt(2) (2/3) d^(3/2) = gap/2 bounds its thickness d.
    const double edge = std::pow(3.0 * M_PI * gap / (8.0 * M_SQRT2), 2.0 / 3.0);
    // Gross sliding alone is named: 1 - 1e-13 does not answer at f = 1e-3 (old main: no answer in 43.8 s CPU), nor at full
    // coupling (more than 10 s CPU; 1 - 1e-12 likewise, 1 - 1e-11 its alternation's refusal).
    return "dissimilar rollers at Q/f = " + shortest(Q / f) + ": next to sliding on the driven side the stick zone " +
           "lies within about " + significant(edge, 2) + " of the leading edge, too close for the integrals of its " +
           "zones (docs/formulation.md 8(m)); Q/f = " + shortest(Q > 0.0 ? 1.0 : -1.0) + " (gross sliding) answers";
}

// Full coupling, driven next to sliding (8(m), "Full coupling next to sliding"): the alternation's values do not settle
// below driven_full_gap, where Johnson's level may still answer (it does at f = 0.05, without the alternation).
std::optional<std::string> driven_full_next_to_sliding(const dissimilar& materials, double f, double Q) {
    const double gap = 1.0 - std::fabs(Q) / f;
    if (!(materials.coupling == coupling_level::full && Q * materials.beta_d > 0.0 && gap < driven_full_gap))
        return std::nullopt;
    return "full coupling at Q/f = " + shortest(Q / f) + " (1 - |Q|/f = " + significant(gap, 2) +
           "): driven next to sliding, where the alternation's lambda, e and xi change by more than its "
           "1e-12 at every step, the more the nearer sliding (docs/formulation.md 8(m), 8(e)); coupling = "
           "\"johnson\" may answer it (it does at f = 0.05 down to 1 - |Q|/f = 1e-13), 1 - |Q|/f of at "
           "least 1e-8 may answer at full coupling, and Q/f = " +
           shortest(Q > 0.0 ? 1.0 : -1.0) + " (gross sliding) answers";
}
}  // namespace

std::optional<std::string> unresolvable_zones(const dissimilar& materials, bool rough, double f, double Q) {
    if (materials.beta_d == 0.0 || !(std::fabs(Q) < f)) return std::nullopt;
    if (std::optional<std::string> why = below_the_breakpoints(materials, rough, f, Q)) return why;
    if (std::optional<std::string> why = driven_next_to_sliding(materials, f, Q)) return why;
    return driven_full_next_to_sliding(materials, f, Q);
}

}  // namespace roughroll
