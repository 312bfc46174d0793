// SPDX-License-Identifier: GPL-3.0-or-later
// W's Cauchy part on the weighted pressure of five zones (kinks_blend::weighted_part, docs/formulation.md 8(x) "W's
// routes") next to a cut and across the band within which main (to session 21) declined the point to the adaptive
// route (dissimilar_zones::cauchy_by_quadrature, which erred by 2.5e-11 there at n = 1000, f = 0.2, so that W jumped by
// that where a point crossed the band's edge and the five zones' Newton cycled). A pressure of the shape of that state:
// p on w_N with k_E = -beta_D f, two stick zones on the square-root weight whose q carries a 1000-term series
// (coefficients falling like j^-2.5, as psi's next to the entry at f = 0.2), the plateau of 8(x) between them, and the
// blend's ends a few 1e-9 off the kinks' ends (an alternation's step). Against GSL's QAGS of W's definition on the
// pieces between s, c, 1, r and every kink's end, each cut again in 16 equal parts and the outer ones
// graded towards the piece's ends (independent of the tables).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "quadpack_common.hpp"
#include "roughroll/numerics/blend_plateau.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

using namespace roughroll;

namespace {
constexpr int n = 1000;
constexpr double beta_d = 0.1438337, f = 0.2;
// The kinks' zones (the source's ends) and the blends' (the next step's, 1e-9 .. 3e-9 away).
constexpr double s1k = -0.98483838432, c1k = 0.97527798693, s2k = 0.99291937343, c2k = 0.99844743400;

double theta(double eta, double s, double c) {
    if (eta <= s) return 0.0;
    if (eta >= c) return 1.0;
    const double t = std::clamp((eta - s) / (0.5 * (c - s)) - 1.0, -1.0, 1.0);
    return 0.5 + M_1_PI * (std::asin(t) + t * std::sqrt(1.0 - t * t));
}

const pressure_kinks& weighted_pressure() {
    static const pressure_kinks k = [] {
        pressure_kinks p;
        p.set_weight(-beta_d * f);
        std::vector<double> b1, b2;
        for (int j = 0; j < n; ++j) {
            b1.push_back(1e-2 * std::cos(0.9 * j) / std::pow(1.0 + j, 2.5));
            b2.push_back(4e-3 * std::sin(0.7 * j + 0.3) / std::pow(1.0 + j, 2.5));
        }
        b1[0] += 0.05;
        b2[0] += 0.03;
        p.add_weighted_zone(n, beta_d, 1.0, s1k, c1k, 0.5, [&](double t) { return u_series(b1, t); });
        p.add_weighted_zone(n, beta_d, 1.0, s2k, c2k, 0.5, [&](double t) { return u_series(b2, t); });
        p.add_weighted_plateau(beta_d, 1.0, f, blend_plateau(s1k, c1k, s2k, c2k), {0.62, 0.1}, {-0.3, -1.5});
        p.set_series({0.64, 0.01, -0.02, 0.004, 1e-3, -5e-4});
        return p;
    }();
    return k;
}

// (1/pi) [int_s^1 (g(eta) - g(r))/(eta - r) + g(r) log((1 - r)/(r - s))], g = p H, by QAGS on the pieces between
// s, c, 1, r and the kinks' ends, each in 16 parts, graded geometrically towards both ends; the sum in long double.
double reference(double r, double s, double c) {
    const pressure_kinks& k = weighted_pressure();
    const auto g = [&](double eta) { return k(eta) * theta(eta, s, c); };
    const bool inside = r > s && r < 1.0;
    const double gr = inside ? g(r) : 0.0;
    const std::function<double(double)> integrand = [&](double eta) { return eta == r ? 0.0 : (g(eta) - gr) / (eta - r); };
    std::vector<double> ends{s, c, 1.0};
    if (inside) ends.push_back(r);
    for (const double e : k.ends())
        if (e > s && e < 1.0) ends.push_back(e);
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    constexpr int parts = 16;
    const quadpack_common::interval_workspace w(2000);
    const gsl_function fn = quadpack_common::function_of(integrand);
    long double total = inside ? static_cast<long double>(gr) * std::log((1.0 - r) / (r - s)) : 0.0L;
    double estimate = 0.0;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        // The piece in `parts` equal parts, the outer two again in parts shrinking by 4 towards the piece's ends, down
        // to 1e-14 (r lies 1e-10 or more from every cut; 1e-17 at r): each end's singular point (a kink's root, the pole
        // mirrored from r nearby) then lies within a part's length of it, where QAGS converges in a few bisections.
        const double a = ends[i], e = ends[i + 1], step = (e - a) / parts;
        std::vector<double> at{a, e};
        for (int j = 1; j < parts; ++j) at.push_back(a + step * j);
        for (double h = 0.25 * step; h > (a == r || e == r ? 1e-17 : 1e-14); h *= 0.25) {
            at.push_back(a + h);
            at.push_back(e - h);
        }
        std::sort(at.begin(), at.end());
        at.erase(std::unique(at.begin(), at.end()), at.end());
        for (std::size_t j = 0; j + 1 < at.size(); ++j) {
            if (!(at[j + 1] > at[j]) || at[j] < a || at[j + 1] > e) continue;
            double result = 0.0, error = 0.0;
            gsl_integration_qags(&fn, at[j], at[j + 1], 1e-18, 1e-14, w.limit, w.w, &result, &error);
            total += result;
            estimate += error;
        }
    }
    EXPECT_LT(estimate, 1e-13) << "reference at r = " << r;  // QUADPACK's own (pessimistic) estimate
    return static_cast<double>(total / M_PI);
}

// W's Cauchy part by kinks_blend (the program's route), empty where it declines.
std::optional<double> rule(double r, double s, double c) {
    const std::optional<kinks_blend> b = weighted_pressure().blend(s, c);
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
// collocation points sit once an alternation settles: within 1e-13 of the reference at points just inside and just
// outside the band and nearer (down to 1e-10), and the step across the band's edge as the reference's to 1e-13.
// (Within about 1e-11 of a kink p's own rounding, about 1e-15 in its 1000-term sums, over eta - r limits any route,
// this one and QUADPACK's alike, to about 1e-12.)
// Main declined the inner points (empty here; in dissimilar_zones::W the adaptive route, 2.5e-11 off).
TEST(WRoute, FirstBlendNextToTheSecondZonesKinkAgainstQuadpack) {
    gsl_set_error_handler_off();
    const double s = s1k + 2e-9, c = c1k - 1e-9;
    const double edge = band(s2k - c, c2k - s2k);  // the pieces [c, s2k] and [s2k, c2k]
    std::printf("band %.3g\n", edge);
    double worst = 0.0;
    const auto at = [&](double r) -> std::optional<double> {
        const std::optional<double> w = rule(r, s, c);
        EXPECT_TRUE(w) << "r - s2k = " << r - s2k << ": declined";
        if (!w) return std::nullopt;
        const double ref = reference(r, s, c), error = *w - ref;
        std::printf("r - s2k %+.3e  W %.17g  W - reference %+.2e\n", r - s2k, *w, error);
        EXPECT_LT(std::fabs(error), 1e-13) << "r - s2k = " << r - s2k;
        worst = std::max(worst, std::fabs(error));
        return error;
    };
    for (const double side : {1.0, -1.0}) {
        const auto inner = at(s2k + side * edge * (1.0 - 1e-3)), outer = at(s2k + side * edge * (1.0 + 1e-3));
        if (inner && outer) {
            EXPECT_LT(std::fabs(*inner - *outer), 1e-13) << "W's step across the band's edge on side " << side
                                                         << " differs from the reference's";
        }
    }
    for (const double d : {3.4e-9, -1e-10}) at(s2k + d);
    std::printf("worst %.2g\n", worst);
}

// The second zone's blend (W2), its ends 3e-9 and 1e-9 off the kinks' (a group of two cuts each), at points of both
// zones: inside the first zone (n-term series there: main's M-point rule aliased it by 5e-12), between the blend's
// start and the kink's, and next to both ends.
TEST(WRoute, SecondBlendAtBothZonesAgainstQuadpack) {
    gsl_set_error_handler_off();
    const double s = s2k - 3e-9, c = c2k + 1e-9;
    double worst = 0.0;
    for (const double r : {0.1, s2k - 1.5e-9, c2k - 4e-10}) {
        const std::optional<double> w = rule(r, s, c);
        EXPECT_TRUE(w) << "r = " << r << ": declined";
        if (!w) continue;
        const double error = *w - reference(r, s, c);
        std::printf("r %.17g  W - reference %+.2e\n", r, error);
        EXPECT_LT(std::fabs(error), 1e-13) << "r = " << r;
        worst = std::max(worst, std::fabs(error));
    }
    std::printf("worst %.2g\n", worst);
}

// int_s^c p H, the first zone's part of the five zones' load (dissimilar_zones::load_under_H), by the tables' rule
// (kinks_blend::zone_load) within 1e-13 of QAGS on the pieces between s, the kinks' ends and c, each in 256 parts
// graded (cosine) towards its ends. Main took it by end_quadrature (GSL's 21-point rule on pieces of 16 periods of
// q's series), which erred by -8.0e-12 here with its own estimate 4.2e-13 (session 22).
TEST(WRoute, FirstZonesLoadAgainstQuadpack) {
    gsl_set_error_handler_off();
    const pressure_kinks& k = weighted_pressure();
    for (const auto& [s, c] : {std::pair{s1k + 2e-9, c1k - 1e-9}, std::pair{s2k - 3e-9, c2k + 1e-9}}) {
        const std::optional<kinks_blend> b = k.blend(s, c);
        ASSERT_TRUE(b);
        const std::optional<double> load = b->zone_load();
        ASSERT_TRUE(load);
        const std::function<double(double)> integrand = [&](double eta) { return k(eta) * theta(eta, s, c); };
        std::vector<double> cuts{s, c};
        for (const double e : k.ends())
            if (e > s && e < c) cuts.push_back(e);
        std::sort(cuts.begin(), cuts.end());
        constexpr int parts = 256;
        const quadpack_common::interval_workspace w(2000);
        const gsl_function fn = quadpack_common::function_of(integrand);
        long double total = 0.0L;
        double estimate = 0.0;
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
            for (int j = 0; j < parts; ++j) {
                const double a = cuts[i], e = cuts[i + 1];
                const double lo = j == 0 ? a : a + (e - a) * (0.5 - 0.5 * std::cos(M_PI * j / parts));
                const double hi = j + 1 == parts ? e : a + (e - a) * (0.5 - 0.5 * std::cos(M_PI * (j + 1) / parts));
                double result = 0.0, error = 0.0;
                gsl_integration_qags(&fn, lo, hi, 1e-18, 1e-14, w.limit, w.w, &result, &error);
                total += result;
                estimate += error;
            }
        EXPECT_LT(estimate, 1e-13);
        std::printf("[%.11f, %.11f]: int p H %.17g, - reference %+.2e\n", s, c, *load, *load - static_cast<double>(total));
        EXPECT_LT(std::fabs(*load - static_cast<double>(total)), 1e-13) << "zone [" << s << ", " << c << "]";
    }
}
