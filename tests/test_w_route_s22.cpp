// SPDX-License-Identifier: GPL-3.0-or-later
// W's Cauchy part on the weighted pressure of five zones (kinks_blend::weighted_part, docs/formulation.md 8(x) "W's
// routes") next to a cut and across the band within which main (to session 21) declined the point to the adaptive
// route (dissimilar_zones::cauchy_by_quadrature, which erred by 2.5e-11 there at n = 1000, f = 0.2, so that W jumped by
// that where a point crossed the band's edge and the five zones' Newton cycled). A pressure of the shape of that state:
// p on w_N with k_E = -beta_D f, two stick zones on the square-root weight whose q carries a 1000-term series
// (coefficients falling like j^-2.5, as psi's next to the entry at f = 0.2), and the blend's ends a few 1e-9 off the
// kinks' ends (an alternation's step). (Until session 25 it carried 8(x)'s Hermite plateau between them too,
// pressure_kinks::add_weighted_plateau, which no solver used since session 23 and which is gone.) Session 25 (8(z), "W next
// to a thin zone"): the same pressure with the driven pair's shape, a second zone 3.3e-4 long beside a reversed slip
// 1.5 long, whose long piece W's fixed cuts grade towards the short one. Against GSL's QAGS of W's definition on the
// pieces between s, c, 1, r and every kink's end, each cut again in 64 equal parts and the outer ones graded towards the
// piece's ends (independent of the tables), every QUADPACK status checked (session 22's review, W2).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <new>
#include <optional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "quadpack_common.hpp"
#include "variable_k_fixture.hpp"
#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/pressure_kinks.hpp"
#include "roughroll/problems/tangential_solver.hpp"

using namespace roughroll;

namespace {
constexpr int n = 1000;
constexpr double beta_d = 0.1438337, f = 0.2;
// The kinks' zones (the source's ends) and the blends' (the next step's, 1e-9 .. 3e-9 away).
constexpr double s1k = variable_k_fixture::two_tenths_ends[0], c1k = variable_k_fixture::two_tenths_ends[1],
                 s2k = variable_k_fixture::two_tenths_ends[2], c2k = variable_k_fixture::two_tenths_ends[3];

double theta(double eta, double s, double c) {
    if (eta <= s) return 0.0;
    if (eta >= c) return 1.0;
    const double t = std::clamp((eta - s) / (0.5 * (c - s)) - 1.0, -1.0, 1.0);
    return 0.5 + M_1_PI * (std::asin(t) + t * std::sqrt(1.0 - t * t));
}

// `terms`: the zones' series and rules (W's M = 10 sqrt(terms) + 48).
pressure_kinks pressure_on(const std::array<double, 4>& ends, int terms) {
    pressure_kinks p;
    p.set_weight(-beta_d * f);
    const std::array<std::vector<double>, 2> b = variable_k_fixture::psi_terms(terms);
    const std::vector<double>&b1 = b[0], &b2 = b[1];
    p.add_weighted_zone(terms, beta_d, 1.0, ends[0], ends[1], 0.5, [&](double t) { return u_series(b1, t); });
    p.add_weighted_zone(terms, beta_d, 1.0, ends[2], ends[3], 0.5, [&](double t) { return u_series(b2, t); });
    p.set_series({0.64, 0.01, -0.02, 0.004, 1e-3, -5e-4});
    return p;
}

const pressure_kinks& weighted_pressure() {
    static const pressure_kinks k = pressure_on(variable_k_fixture::two_tenths_ends, n);
    return k;
}

// The driven pair's five zones at full coupling (Q/f = +0.75, f = 0.05, the default point, answered at n = 64): the
// second stick zone [0.99920, 0.99953], 3.3e-4 long and 4.7e-4 from the edge, after a reversed slip 1.5 long.
constexpr std::array<double, 4> driven_ends{-0.86859392, -0.50949028, 0.99920165, 0.99952993};
const pressure_kinks& driven_pressure() {
    static const pressure_kinks k = pressure_on(driven_ends, 64);
    return k;
}

// QUADPACK's answer on one part, its status checked (review of session 22, W2): GSL_SUCCESS only. A part asks no more than
// double precision gives there (asked less, GSL stops with GSL_EROUND or GSL_ESING, its error "may be under-estimated":
// 684 + 226 of the 2127 calls of session 22's reference, which asked 1e-18 on parts down to 1e-14 long).
struct quadpack_sum {
    long double value = 0.0L;
    double estimate = 0.0;  // QUADPACK's own estimates, summed
    void add(const gsl_function& fn, double lo, double hi, double absolute,
             const quadpack_common::interval_workspace& w) {
        double result = 0.0, error = 0.0;
        const int status = gsl_integration_qags(&fn, lo, hi, absolute, 1e-13, w.limit, w.w, &result, &error);
        EXPECT_EQ(status, GSL_SUCCESS) << gsl_strerror(status) << " on [" << lo << ", " << hi << "], asked " << absolute
                                       << ", estimate " << error;
        value += result;
        estimate += error;
    }
};

// The cuts of a piece [a, e]: `parts` equal parts (q's n-term series turns about n/2 times across a zone: 64 parts of a
// long piece leave QAGS a few turns each; with 4 GK21's estimates summed to 1.4e-13 beside a sum 2.7e-12 off, with 16
// the reference was 2e-14 off at the band's edge, with 64 3e-15, as with 256), the outer ones again in parts shrinking
// by 4 towards both ends down to 1e-11 (a root or the pole mirrored from r lies within a part's length of its end; GSL
// bisects a part no further than 100 eps |eta|, 2e-14 here: parts of 1.5e-14 ended in GSL_ESING).
std::vector<double> part_cuts(double a, double e, int parts) {
    const double step = (e - a) / parts;
    std::vector<double> at{a, e};
    for (int j = 1; j < parts; ++j) at.push_back(a + step * j);
    for (double h = 0.25 * step; h > 1e-11; h *= 0.25) {
        at.push_back(a + h);
        at.push_back(e - h);
    }
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    return at;
}

// (1/pi) [int_s^1 (g(eta) - g(r))/(eta - r) + g(r) log((1 - r)/(r - s))], g = p H, by QAGS on the pieces between
// s, c, 1, r and the kinks' ends (pressure_kinks::ends: the kinks' roots to the bit, where kink_part changes from the
// zone's form to the form off it: the first double off a zone is c0 itself, the first on it start's successor), each cut
// by part_cuts (64 equal parts where longer than 1e-6); the sum in long double. What a part asks (absolute; relative
// 1e-13): 1e-16; near r p's rounding (about 1e-15 in its 1000-term sums) over eta - r, 1e-15 int d eta/|eta - r| on the
// part (to r's rounding where it ends at r); on a part ending at a kink's root e, its B sqrt|eta - e| (B < 0.01 here)
// over eta - r on the narrowest part GSL bisects to (2e-14): 4e-23/|r - e|, 4e-13 at 1e-10 from a kink.
quadpack_sum reference(double r, double s, double c, const pressure_kinks& k = weighted_pressure()) {
    const auto g = [&](double eta) { return k(eta) * theta(eta, s, c); };
    const bool inside = r > s && r < 1.0;
    const double gr = inside ? g(r) : 0.0;
    const std::function<double(double)> integrand = [&](double eta) {
        return eta == r ? 0.0 : (g(eta) - gr) / (eta - r);
    };
    std::vector<double> ends{s, c, 1.0};
    if (inside) ends.push_back(r);
    const std::vector<double> kinks = k.ends();
    for (const double e : kinks)
        if (e > s && e < 1.0) ends.push_back(e);
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    const quadpack_common::interval_workspace w(2000);
    const gsl_function fn = quadpack_common::function_of(integrand);
    // The part ending at 1 by QAWS with the weight (1 - eta)^a_N of p (8(w): p = w_N times a function smooth at 1 off
    // the zones), a_N = 1/2 + atan(k_E)/pi, k_E = -beta_D f: QAGS met that root over eta - r in GSL_ESING at 1 - r =
    // 1.5e-9 (W4); its g(r) part in closed form, -g(r) log((1 - r)/(u - r)).
    const double a_n = 0.5 + std::atan(-beta_d * f) / M_PI;
    const std::unique_ptr<gsl_integration_qaws_table, void (*)(gsl_integration_qaws_table*)> edge(
        gsl_integration_qaws_table_alloc(0.0, a_n, 0, 0), gsl_integration_qaws_table_free);
    if (!edge) throw std::bad_alloc();
    quadpack_sum sum;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        const std::vector<double> at = part_cuts(ends[i], ends[i + 1], ends[i + 1] - ends[i] > 1e-6 ? 64 : 1);
        for (std::size_t j = 0; j + 1 < at.size(); ++j) {
            const double u = at[j], v = at[j + 1];
            double absolute = 1e-16;
            if (inside) {
                const double span = u == r || v == r ? std::log((v - u) / (DBL_EPSILON * std::fabs(r)))
                                                     : std::fabs(std::log((v - r) / (u - r)));
                absolute = std::max(absolute, 1e-15 * span);
                for (const double e : kinks)
                    if (u == e || v == e) absolute = std::max(absolute, 4e-23 / std::fabs(r - e));
            }
            if (v == 1.0) {  // p's (1 - eta)^a_N: QAWS (below)
                // QAWS's rule takes the ends; at 1 the limit, to rounding the value one double below.
                const std::function<double(double)> smooth = [&](double eta) {
                    const double x = std::min(eta, std::nextafter(1.0, 0.0));
                    return g(x) / (std::pow(1.0 - x, a_n) * (x - r));
                };
                gsl_function fs = quadpack_common::function_of(smooth);
                double result = 0.0, error = 0.0;
                // p's rounding there over eta - r >= 1e-9: 1e-15 asked (at 1 - r = 1.5e-9 QAWS stopped at 2.7e-16 on
                // [1 - 2.3e-11, 1] in GSL_EROUND when asked 1e-16).
                const int status = gsl_integration_qaws(&fs, u, v, edge.get(), std::max(absolute, 1e-15), 1e-13,
                                                        w.limit, w.w, &result, &error);
                EXPECT_EQ(status, GSL_SUCCESS) << gsl_strerror(status) << " (QAWS) on [" << u << ", 1], asked "
                                               << absolute << ", estimate " << error;
                sum.value += result - (inside ? static_cast<long double>(gr) * std::log((1.0 - r) / (u - r)) : 0.0L);
                sum.estimate += error;
                continue;
            }
            sum.add(fn, u, v, absolute, w);
        }
    }
    if (inside) sum.value += static_cast<long double>(gr) * std::log((1.0 - r) / (r - s));
    sum.value /= M_PI;
    sum.estimate /= M_PI;
    EXPECT_LT(sum.estimate, 1e-12) << "reference at r = " << r;  // QUADPACK's own (pessimistic) estimate
    return sum;
}

// int_lo^hi p H for the blend of [s, c] by QAGS on the pieces between lo, hi and the kinks' ends (part_cuts, 64 equal
// parts where longer than 1e-6; every status checked), its estimate below 1e-13.
double load_reference(double lo, double hi, double s, double c) {
    const pressure_kinks& k = weighted_pressure();
    const std::function<double(double)> integrand = [&](double eta) { return k(eta) * theta(eta, s, c); };
    std::vector<double> cuts{lo, hi};
    for (const double e : k.ends())
        if (e > lo && e < hi) cuts.push_back(e);
    std::sort(cuts.begin(), cuts.end());
    const quadpack_common::interval_workspace w(2000);
    const gsl_function fn = quadpack_common::function_of(integrand);
    quadpack_sum sum;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const std::vector<double> at = part_cuts(cuts[i], cuts[i + 1], cuts[i + 1] - cuts[i] > 1e-6 ? 64 : 1);
        for (std::size_t j = 0; j + 1 < at.size(); ++j) sum.add(fn, at[j], at[j + 1], 1e-16, w);
    }
    EXPECT_LT(sum.estimate, 1e-13) << "the load's reference on [" << lo << ", " << hi << "]";
    return static_cast<double>(sum.value);
}

// W's Cauchy part by kinks_blend (the program's route), empty where it declines.
std::optional<double> rule(double r, double s, double c, const pressure_kinks& k = weighted_pressure()) {
    const std::optional<kinks_blend> b = k.blend(s, c);
    EXPECT_TRUE(b);
    return b ? (*b)(r, theta(r, s, c)) : std::nullopt;
}

// The band within which main declined a point next to the cut between pieces of lengths `left` and `right`
// (pressure_kinks::blend: 4 (88/M^2)^2 times the longer, M = 10 sqrt(n) + 48).
double band(double left, double right) {
    const double m = std::ceil(10.0 * std::sqrt(static_cast<double>(n))) + 48.0;
    return 4.0 * std::pow(88.0 / (m * m), 2) * std::max(left, right);
}
}  // namespace

// Zone 1's blend (W1) at points next to the second zone's entry kink s2k, the cut where the second zone's first
// collocation points sit once an alternation settles: within 1e-13 of the reference (plus the reference's own estimate,
// 1e-14 .. 1.6e-14 but 1.5e-13 at 1e-10 from the kink: p's root over eta - r, see reference()) at points just inside and
// just outside the band and nearer (down to 1e-10), and the step across the band's edge as the reference's to 1e-13
// (plus both estimates). (Within about 1e-11 of a kink p's own rounding, about 1e-15 in its 1000-term sums, over
// eta - r limits any route, this one and QUADPACK's alike, to about 1e-12.)
// Main declined the inner points (empty here; in dissimilar_zones::W the adaptive route, 2.5e-11 off).
TEST(WRoute, FirstBlendNextToTheSecondZonesKinkAgainstQuadpack) {
    gsl_set_error_handler_off();
    const double s = s1k + 2e-9, c = c1k - 1e-9;
    const double edge = band(s2k - c, c2k - s2k);  // the pieces [c, s2k] and [s2k, c2k]
    std::printf("band %.3g\n", edge);
    double worst = 0.0;
    // W - reference and the reference's estimate.
    const auto at = [&](double r) -> std::optional<std::pair<double, double>> {
        const std::optional<double> w = rule(r, s, c);
        EXPECT_TRUE(w) << "r - s2k = " << r - s2k << ": declined";
        if (!w) return std::nullopt;
        const quadpack_sum ref = reference(r, s, c);
        const double error = *w - static_cast<double>(ref.value);
        std::printf("r - s2k %+.3e  W %.17g  W - reference %+.2e (its estimate %.1e)\n", r - s2k, *w, error,
                    ref.estimate);
        EXPECT_LT(std::fabs(error), 1e-13 + ref.estimate) << "r - s2k = " << r - s2k;
        worst = std::max(worst, std::fabs(error));
        return std::pair{error, ref.estimate};
    };
    for (const double side : {1.0, -1.0}) {
        const auto inner = at(s2k + side * edge * (1.0 - 1e-3)), outer = at(s2k + side * edge * (1.0 + 1e-3));
        if (inner && outer) {
            EXPECT_LT(std::fabs(inner->first - outer->first), 1e-13 + inner->second + outer->second)
                << "W's step across the band's edge on side " << side << " differs from the reference's";
        }
    }
    for (const double d : {3.4e-9, -1e-10}) at(s2k + d);
    std::printf("worst %.2g\n", worst);
}

// The second zone's blend (W2), its ends 3e-9 and 1e-9 off the kinks' (a group of two cuts each), at points of both
// zones: inside the first zone (n-term series there: main's M-point rule aliased it by 5e-12), between the blend's
// start and the kink's, and next to both ends; within 1e-13 plus the reference's estimate.
TEST(WRoute, SecondBlendAtBothZonesAgainstQuadpack) {
    gsl_set_error_handler_off();
    const double s = s2k - 3e-9, c = c2k + 1e-9;
    double worst = 0.0;
    for (const double r : {0.1, s2k - 1.5e-9, c2k - 4e-10}) {
        const std::optional<double> w = rule(r, s, c);
        EXPECT_TRUE(w) << "r = " << r << ": declined";
        if (!w) continue;
        const quadpack_sum ref = reference(r, s, c);
        const double error = *w - static_cast<double>(ref.value);
        std::printf("r %.17g  W - reference %+.2e (its estimate %.1e)\n", r, error, ref.estimate);
        EXPECT_LT(std::fabs(error), 1e-13 + ref.estimate) << "r = " << r;
        worst = std::max(worst, std::fabs(error));
    }
    std::printf("worst %.2g\n", worst);
}

// int_s^c p H, the first zone's part of the five zones' load (dissimilar_zones::load_under_H), by the tables' rule
// (kinks_blend::zone_load) within 1e-13 of QAGS on the pieces between s, the kinks' ends and c (load_reference). Main
// took it by end_quadrature (GSL's 21-point rule on pieces of 16 periods of q's series), which erred by -8.0e-12 here
// with its own estimate 4.2e-13 (session 22).
TEST(WRoute, FirstZonesLoadAgainstQuadpack) {
    gsl_set_error_handler_off();
    const pressure_kinks& k = weighted_pressure();
    for (const auto& [s, c] : {std::pair{s1k + 2e-9, c1k - 1e-9}, std::pair{s2k - 3e-9, c2k + 1e-9}}) {
        const std::optional<kinks_blend> b = k.blend(s, c);
        ASSERT_TRUE(b);
        const std::optional<double> load = b->zone_load();
        ASSERT_TRUE(load);
        const double total = load_reference(s, c, s, c);
        std::printf("[%.11f, %.11f]: int p H %.17g, - reference %+.2e\n", s, c, *load, *load - total);
        EXPECT_LT(std::fabs(*load - total), 1e-13) << "zone [" << s << ", " << c << "]";
    }
}

// The same load through the five zones' system (review of session 22, W1): dissimilar_zones::load_under_H's hook to
// kinks_blend::zone_load (on the weighted pressure, its U-series zero) is what five_zone_system's load takes,
//   Q = sign (f (-1 + 2 int p H1 - 2 int p H2) + (Q_1 - f) + (Q_2 - f))   (8(j); Q_k = f + rho_k int q_k),
// so Q less its zones' parts gives int p H1 - int p H2, against QAGS of int_s^1 p H for both blends (load_reference,
// p H = p beyond c). On this pressure with a 64-point normal rule (end_quadrature's pieces follow the normal solution's
// n) the hook's old route, end_quadrature, is 7.9e-12 off (the gate `weighted()` negated: measured); the
// reference's estimate is below 1e-13 and the loads within 1e-13 of it.
TEST(WRoute, FiveZoneLoadThroughTheHookAgainstQuadpack) {
    gsl_set_error_handler_off();
    normal_solution normal = hertz_solution(64, method::product);
    std::fill(normal.b.begin(), normal.b.end(), 0.0);  // the weighted pressure carries the whole p (8(w))
    std::fill(normal.phi.begin(), normal.phi.end(), 0.0);
    normal.kinks = std::make_shared<const pressure_kinks>(weighted_pressure());
    tangential_solver solver(normal, kernel{}, kernel{}, f);
    dissimilar_zones zones(solver, kernel{}, beta_d);
    const double s1 = s1k + 2e-9, c1 = c1k - 1e-9, s2 = s2k - 3e-9, c2 = c2k + 1e-9;
    const tangential_solution five = zones.five_zone_system(s1, c1, s2, c2, beta_d);
    const double difference = (five.sign * five.Q - (five.zone_system(0).Q - f) - (five.zone_system(1).Q - f) + f) / (2.0 * f);
    const double expected = load_reference(s1, 1.0, s1, c1) - load_reference(s2, 1.0, s2, c2);
    std::printf("int p H1 - int p H2 %.17g, - reference %+.2e\n", difference, difference - expected);
    EXPECT_LT(std::fabs(difference - expected), 1e-13);
}

// Next to the edge r = 1 (review of session 22, W4): the last group of cuts ends at r = 1 (near_part's right == none:
// its part [r, 1] is graded towards r only, and meets (1 - eta)^a_N at 1 in one graded_points-point piece). Its band is
// 4 (88/M^2)^2 (1 - c2k) = 2.7e-9 here; points at 1 - r = 1.5e-9 and 2.5e-9 (inside it, above the 1e-9 within which
// the rule declines) for both blends, within 1e-13 plus the reference's estimate. Measured: 7.3e-14 at most (the
// reference's estimates 2e-15 .. 1.1e-14); fails without near_part (3.9e-13) and with graded_points 8 (2.2e-12).
TEST(WRoute, NextToTheTrailingEdgeAgainstQuadpack) {
    gsl_set_error_handler_off();
    double worst = 0.0;
    for (const auto& [s, c] : {std::pair{s1k + 2e-9, c1k - 1e-9}, std::pair{s2k - 3e-9, c2k + 1e-9}})
        for (const double d : {1.5e-9, 2.5e-9}) {
            const double r = 1.0 - d;
            const std::optional<double> w = rule(r, s, c);
            EXPECT_TRUE(w) << "1 - r = " << d << ": declined";
            if (!w) continue;
            const quadpack_sum ref = reference(r, s, c);
            const double error = *w - static_cast<double>(ref.value);
            std::printf("zone [%.11f, %.11f], 1 - r %.1e: W %.17g, W - reference %+.2e (its estimate %.1e)\n", s, c, d,
                        *w, error, ref.estimate);
            EXPECT_LT(std::fabs(error), 1e-13 + ref.estimate) << "1 - r = " << d;
            worst = std::max(worst, std::fabs(error));
        }
    std::printf("worst %.2g\n", worst);
}

// W next to a thin zone (8(z), "W next to a thin zone", session 25): on the driven pair's shape the first zone's blend
// has the piece [c1, s2] 1.5 long beside the second zone's [s2, c2], 3.3e-4 long, and W's fixed cuts grade the long piece
// towards s2 (l, 3 l, 7 l, ... from it, l the short piece's length). The points of the second zone then take the tables'
// rule: no point from its first hundredth to its last is next to a cut (kinks_blend::near). Ungraded, the long piece's
// band (4 (88/M^2)^2 of 1.5: 1.7e-4 at n = 64, M = 128, half the zone) covered the zone's points near s2, and its group
// of cuts (s2, c2, 1) the rest: every such point took near_part (measured: the driven point at n = 64 asked it 2152
// times, free rolling 71; 1.69 s against 0.25 s). W (n = 64) at the zone's points, at s2 + 1e-9 (near, as before) and
// next to c2, and of the second zone's blend at the first zone's middle, within 1e-13 plus the reference's
// own estimate of QUADPACK's (reference: QAGS on the pieces between s, c, 1, r and the kinks' ends, independent of the
// cuts). Fails with short_piece_ratio = 1e300 (no grading: the zone's points near).
TEST(WRoute, ThinZonesPointsByTheTablesAgainstQuadpack) {
    gsl_set_error_handler_off();
    const pressure_kinks& k = driven_pressure();
    const double s1 = driven_ends[0] + 2e-9, c1 = driven_ends[1] - 1e-9, s2 = driven_ends[2], c2 = driven_ends[3];
    const std::optional<kinks_blend> first = k.blend(s1, c1);
    ASSERT_TRUE(first);
    for (const double x : {0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99}) {
        const double r = s2 + x * (c2 - s2);
        EXPECT_FALSE(first->near(r)) << "the second zone's point at " << x << " of it takes near_part";
    }
    EXPECT_TRUE(first->near(s2 + 1e-9));  // next to the kink: the graded rule, as before
    double worst = 0.0;
    const auto check = [&](double r, double s, double c) {
        const std::optional<double> w = rule(r, s, c, k);
        EXPECT_TRUE(w) << "r = " << r << ": declined";
        if (!w) return;
        const quadpack_sum ref = reference(r, s, c, k);
        const double error = *w - static_cast<double>(ref.value);
        std::printf("blend [%.8f, %.8f], r %.17g: W - reference %+.2e (its estimate %.1e)\n", s, c, r, error, ref.estimate);
        EXPECT_LT(std::fabs(error), 1e-13 + ref.estimate) << "r = " << r;
        worst = std::max(worst, std::fabs(error));
    };
    for (const double x : {0.01, 0.5, 0.99}) check(s2 + x * (c2 - s2), s1, c1);
    check(s2 + 1e-9, s1, c1);
    check(c2 + 1e-6, s1, c1);
    check(0.5 * (driven_ends[0] + driven_ends[1]), s2 - 3e-9, c2 + 1e-9);
    std::printf("worst %.2g\n", worst);
}
