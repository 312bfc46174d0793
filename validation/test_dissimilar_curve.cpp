// SPDX-License-Identifier: GPL-3.0-or-later
// Creep curves of dissimilar rollers over -f..f (docs/formulation.md 8(h), 8(j) items 4a and 9):
// aluminium on steel, f = 0.05, n = 32, Johnson's level. Each row is solved as contact::point
// would; five-zone rows start from the previous row's ends (continued in the load), a start only.
// Checked: the rows against points solved alone (to Newton's resolution where a start was used, to
// the bit where none was), the exchange of rollers xi(Q; beta) = -xi(-Q; -beta) on every row, the
// creep rising with the load, and no jump through the braked transition (five to three zones).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "aluminium_on_steel.hpp"
#include "../tests/tolerance.hpp"

using namespace roughroll;

namespace {
constexpr double f = 0.05;
const solver_options options{32, method::extrapolated};  // the CLI's default method

contact scene(double beta) { return contact(roughness{}, f, options, dissimilar{beta, coupling_level::johnson}); }
}  // namespace

// The default loads: -f..f for beta_D != 0 (the curve is not odd in Q), today's 0..f for beta_D = 0.
TEST(DissimilarCurve, LoadsCoverBothSigns) {
    const std::vector<double> loads = curve_loads(11, f, beta_al_st);
    ASSERT_EQ(loads.size(), 11u);
    EXPECT_EQ(loads.front(), -f);
    EXPECT_EQ(loads[5], 0.0);
    EXPECT_EQ(loads.back(), f);
    EXPECT_EQ(curve_loads(11, f, 0.0), curve_loads(11, f));
}

// The whole curve: every row answered with its checks and estimate, the creep rising with Q
// (more traction needs more creep, as on Carter's curve: dxi/dQ > 0, 8(g)), each row equal to the
// point solved alone, and the rollers exchanged give the mirror curve.
TEST(DissimilarCurve, RowsArePointsAndTheMirrorHolds) {
    const std::vector<double> loads = curve_loads(11, f, beta_al_st);
    contact c = scene(beta_al_st), e = scene(-beta_al_st);
    const std::vector<curve_point> rows = creep_curve(c, loads);
    std::vector<double> mirrored(loads.rbegin(), loads.rend());
    for (double& Q : mirrored) Q = -Q;
    const std::vector<curve_point> mirror = creep_curve(e, mirrored);  // -f..f again, the other order
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const curve_point& row = rows[i];
        ASSERT_FALSE(row.is_refused()) << row.refused;
        EXPECT_TRUE(row.solution.checks.hold()) << loads[i];
        EXPECT_TRUE(row.estimate.has_value()) << loads[i];
        const curve_point& other = mirror[rows.size() - 1 - i];
        ASSERT_FALSE(other.is_refused()) << other.refused;
        std::printf("Q/f = %+.1f: xi %.12f (%s), mirror %.1e\n", loads[i] / f, row.solution.xi,
                    row.solution.layout.stick_zones() == 2 ? "five zones" : "three", row.solution.xi + other.solution.xi);
        // The mirror curve is solved in the opposite order, from other starts: equal to Newton's resolution.
        EXPECT_NEAR(row.solution.xi, -other.solution.xi, tol::two_routes) << loads[i];
        EXPECT_NEAR(row.solution.c0(), other.solution.c0(), 1e-9) << loads[i];
        if (i > 0) {
            EXPECT_GT(row.solution.xi, rows[i - 1].solution.xi) << loads[i];
        }
    }
    EXPECT_GT(std::fabs(rows[3].solution.xi + rows[7].solution.xi), 1e-3);  // not odd in Q
    // Rows against points solved alone (a fresh contact: no previous row). A three-zone row uses no
    // start from the previous row: equal to the bit. A five-zone row started from the previous row's
    // ends is the same root to Newton's resolution (ends 1e-11, dissimilar_zones.hpp).
    for (const std::size_t i : {std::size_t{2}, std::size_t{5}, std::size_t{6}, std::size_t{8}, std::size_t{10}}) {
        contact alone = scene(beta_al_st);
        const tangential_solution s = alone.point(loads[i]);
        const tangential_solution& row = rows[i].solution;
        ASSERT_EQ(s.layout.stick_zones(), row.layout.stick_zones()) << loads[i];
        if (s.layout.stick_zones() != 2) {
            EXPECT_EQ(s.xi, row.xi) << loads[i];
            EXPECT_EQ(s.c0(), row.c0()) << loads[i];
        } else {
            EXPECT_NEAR(s.xi, row.xi, tol::two_routes) << loads[i];
            for (const auto& [a, b] : {std::pair{s.start(), row.start()}, std::pair{s.c0(), row.c0()},
                                       std::pair{s.start2(), row.start2()}, std::pair{s.end2(), row.end2()}})
                EXPECT_NEAR(a, b, 1e-9) << loads[i];
        }
        EXPECT_NEAR(alone.estimate(s)->xi, rows[i].estimate->xi, tol::two_routes) << loads[i];
    }
}

// Through the braked transition (8(j) 4a, Q/f in (-0.075, -0.0725)): five zones above, three below,
// the creep continuous: no step larger than 1.25 times the smallest over the window (the slope of
// dxi/dQ changes by a few per cent; a jump between structures would be a step of its own).
TEST(DissimilarCurve, ContinuousThroughTheBrakedTransition) {
    std::vector<double> loads;
    for (int k = 12; k <= 18; ++k) loads.push_back(-0.005 * k * f);  // Q/f = -0.06 .. -0.09
    contact c = scene(beta_al_st);
    const std::vector<curve_point> rows = creep_curve(c, loads);
    std::vector<double> steps;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        ASSERT_FALSE(rows[i].is_refused()) << rows[i].refused;
        EXPECT_EQ(rows[i].solution.layout.stick_zones() == 2, loads[i] > -0.074 * f) << loads[i];
        std::printf("Q/f = %.3f: xi %.9f (%s)\n", loads[i] / f, rows[i].solution.xi,
                    rows[i].solution.layout.stick_zones() == 2 ? "five" : "three");
        if (i > 0) steps.push_back(rows[i - 1].solution.xi - rows[i].solution.xi);  // falling Q: falling xi
    }
    const auto [low, high] = std::minmax_element(steps.begin(), steps.end());
    EXPECT_GT(*low, 0.0);
    EXPECT_LT(*high, 1.25 * *low);
}

namespace {
// Each row of a curve continued in the load (swept_curve, creep_curve with curve_rows::continued) against the point
// solved alone (a fresh contact: no previous row, the zone search from its own starts): the same structure, and the
// creep and the zone ends within the point's own error estimate (in fact to Newton's resolution, printed). Returns
// the largest |xi_row - xi_alone| over the rows.
double expect_rows_are_points(const std::vector<double>& loads, const std::vector<curve_point>& rows) {
    EXPECT_EQ(rows.size(), loads.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        contact alone = scene(beta_al_st);
        const tangential_solution s = alone.point(loads[i]);
        const std::optional<error_estimate> e = alone.estimate(s);
        const curve_point& row = rows[i];
        if (row.is_refused()) {
            ADD_FAILURE() << "Q/f = " << loads[i] / f << " refused on the swept curve, answered alone: " << row.refused;
            continue;
        }
        EXPECT_EQ(row.solution.Q, loads[i]);
        if (!e || !row.estimate) {
            ADD_FAILURE() << "Q/f = " << loads[i] / f << ": no estimate alone or on the curve";
            continue;
        }
        EXPECT_EQ(row.solution.layout.stick_zones(), s.layout.stick_zones()) << loads[i];
        EXPECT_EQ(row.solution.layout.opposite(), s.layout.opposite()) << loads[i];
        EXPECT_TRUE(row.solution.checks.hold()) << loads[i];
        const double d = std::fabs(row.solution.xi - s.xi);
        largest = std::max(largest, d);
        EXPECT_LE(d, e->xi) << loads[i];
        EXPECT_LE(std::fabs(row.solution.c0() - s.c0()), e->c0) << loads[i];
        EXPECT_LE(std::fabs(row.solution.start() - s.start()), std::max(e->start, e->c0)) << loads[i];
        if (s.layout.stick_zones() == 2) {
            EXPECT_LE(std::fabs(s.start2() - row.solution.start2()), std::max(e->start, e->c0)) << loads[i];
            EXPECT_LE(std::fabs(s.end2() - row.solution.end2()), std::max(e->start, e->c0)) << loads[i];
        }
        EXPECT_LE(d, row.estimate->xi) << loads[i];  // the row's own estimate covers the gap too
        std::printf("Q/f = %+.3f: %s, xi %.12f, alone %.1e apart (estimate %.1e)\n", loads[i] / f,
                    s.layout.stick_zones() == 2 ? "five zones" : s.layout.opposite() ? "three, opposite" : "three", s.xi,
                    d, e->xi);
    }
    return largest;
}
}  // namespace

// --sweep for dissimilar rollers (issue 24, 7): the curve over -f..f continued in the load, each row started from
// the previous row's zones (three zones as the zone search's guess, five zones by Newton from their ends), through
// gross sliding at -f, the three zones of a braked roller, the five zones around free rolling, the driven three
// zones with the leading slip against Q, and gross sliding at f.
TEST(DissimilarCurve, SweptRowsArePointsSolvedAlone) {
    contact c = scene(beta_al_st);
    const std::vector<curve_point> rows = swept_curve(c, 21);
    const double largest = expect_rows_are_points(curve_loads(21, f, beta_al_st), rows);
    std::printf("largest |xi_row - xi_alone| %.1e\n", largest);
}

// Where the structure changes between rows: five zones to the braked three zones (8(j) 4a, Q/f about -0.074) and
// the driven five zones to the three zones with the leading slip against Q (between Q/f = 0.7 and 0.8 at n = 32),
// in steps of 0.005 f and 0.01 f, both ways: a start of the other structure must end on the point's structure, never on another root.
TEST(DissimilarCurve, ContinuedThroughStructureChanges) {
    std::vector<double> braked, driven;
    for (int k = 12; k <= 18; ++k) braked.push_back(-0.005 * k * f);  // Q/f = -0.06 .. -0.09
    for (int k = 70; k <= 80; ++k) driven.push_back(0.01 * k * f);  // Q/f = 0.70 .. 0.80
    for (std::vector<double> loads : {braked, driven}) {
        for (int way = 0; way < 2; ++way) {
            if (way == 1) std::reverse(loads.begin(), loads.end());
            contact c = scene(beta_al_st);
            const std::vector<curve_point> rows = creep_curve(c, loads, {}, {}, 0, curve_rows::continued);
            int changes = 0;
            for (std::size_t i = 1; i < rows.size(); ++i)
                if (rows[i].solution.layout.zones.size() != rows[i - 1].solution.layout.zones.size()) ++changes;
            EXPECT_GE(changes, 1) << "the window must hold a change of structure";
            expect_rows_are_points(loads, rows);
        }
    }
}
