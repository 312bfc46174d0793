// SPDX-License-Identifier: GPL-3.0-or-later
// Creep curves with a refused point (contact.hpp, curve_point; io/output.hpp, write_curve_csv):
// a point without an honest error estimate is a refused row, and the curve goes on past it.
// The scene: a very stiff normal layer (cylinder 2, T = 1e6, A = 1; docs/performance.md) with
// method product at n = 16, where some loads have levels 4, 8, 16 that do not converge visibly
// (refused) and others are answered. What each row must be is decided independently of the
// curve: the same load (or c0) solved alone on a fresh contact, refused or answered.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gsl/gsl_machine.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_solver.hpp"
#include "roughroll/problems/creep_curve.hpp"
#include "tolerance.hpp"

using namespace roughroll;

namespace {
constexpr double f = 0.3;

roughness stiff_layer() {
    roughness r;
    r.cylinder2.normal = {1e6, 1.0};
    return r;
}

contact fresh() { return contact(stiff_layer(), f, solver_options{16, method::product}); }

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    return cells;
}
}  // namespace

// Every row as the load solved alone: the same numbers where answered, a refused row (its load,
// NaN for the rest, the alone-solve's reason) where the alone-solve refuses.
TEST(Curve, RefusedPointIsARowAndTheCurveGoesOn) {
    const std::vector<double> loads = curve_loads(7, f);  // the program's `curve --points 7`
    contact c = fresh();
    const std::vector<curve_point> curve = creep_curve(c, loads);
    ASSERT_EQ(curve.size(), loads.size());
    int refused = 0, answered = 0;
    for (std::size_t i = 0; i < loads.size(); ++i) {
        const curve_point& row = curve[i];
        contact alone = fresh();
        std::string why;
        tangential_solution s{};
        std::optional<error_estimate> e;
        try {
            s = alone.point(loads[i]);
            e = alone.estimate(s);
        } catch (const resolution_error& x) {
            why = x.what();
        }
        if (!why.empty()) {
            ++refused;
            ASSERT_TRUE(row.is_refused()) << "Q = " << loads[i];
            EXPECT_EQ(row.refused,
                      "curve point at Q = " + shortest(loads[i]) + " (Q/f = " + shortest(loads[i] / f) + "): " + why);
            EXPECT_EQ(row.solution.Q, loads[i]);
            EXPECT_TRUE(std::isnan(row.solution.c0()));
            EXPECT_TRUE(std::isnan(row.solution.xi));
            EXPECT_FALSE(row.solution.checks.hold());
            EXPECT_FALSE(row.estimate.has_value());
            EXPECT_EQ(row.smooth.xi, carter(loads[i], f).xi);  // the closed form at the given load
        } else {
            ++answered;
            ASSERT_FALSE(row.is_refused()) << row.refused;
            EXPECT_EQ(row.solution.c0(), s.c0());
            EXPECT_EQ(row.solution.xi, s.xi);
            // A row whose checks fail carries no estimate, as the point alone (contact::estimate).
            ASSERT_EQ(row.estimate.has_value(), e.has_value());
            EXPECT_EQ(e.has_value(), s.checks.hold());
            if (e) {
                EXPECT_EQ(row.estimate->xi, e->xi);
            }
        }
    }
    // The scene must exercise both kinds of rows, or this test proves nothing.
    EXPECT_GE(refused, 1);
    EXPECT_GE(answered, 2);
}

TEST(Curve, SweptRefusedPointKeepsItsStickEnd) {
    contact c = fresh();
    const std::vector<curve_point> curve = swept_curve(c, 5);  // c0 = 1, 0.5, 0, -0.5, -1
    int refused = 0;
    for (const curve_point& row : curve) {
        if (!row.is_refused()) continue;
        ++refused;
        const double c0 = row.solution.c0();
        EXPECT_TRUE(std::isnan(row.solution.Q));
        EXPECT_TRUE(std::isnan(row.solution.xi));
        // Carter's columns at the same c0 (the load was not found): Carter's load there,
        // f (1 - rho^2), taken back through carter(Q, f) gives the same stick end and creep.
        const double rho = 0.5 * (1.0 + c0);
        const carter_point back = carter(f * (1.0 - rho * rho), f);
        EXPECT_EQ(row.smooth.c0, c0);
        EXPECT_NEAR(row.smooth.c0, back.c0, tol::few_roundings);
        EXPECT_NEAR(row.smooth.xi, back.xi, tol::few_roundings);
        contact alone = fresh();
        try {
            alone.at_stick_end(c0);
            ADD_FAILURE() << "c0 = " << c0 << " is answered alone but refused on the curve";
        } catch (const resolution_error& x) {
            EXPECT_EQ(row.refused, "curve point at c0 = " + shortest(c0) + ": " + std::string(x.what()));
        }
    }
    EXPECT_GE(refused, 1);
}

// A load Q(c0) outside [0, f] is no physical point (contact::at_stick_end): such a row, and
// one whose Q +- its estimate reaches outside [0, f], is refused; no row is answered with
// Q outside [0, f], and Carter's columns are finite in every row. Which c0 give a load
// outside is decided independently: the level n solver alone (tangential_solver, method
// product, no estimate and no refusal), whose Q(c0) is what the curve would have printed.
TEST(Curve, SweptLoadOutsideZeroToFIsRefused) {
    const roughness r = stiff_layer();
    const normal_solution normal = solve_normal(kernel::normal(r), 16, method::product);
    tangential_solver level(normal, kernel::tangential(r), kernel::normal(r), f);
    contact c = fresh();
    const std::vector<curve_point> curve = swept_curve(c, 5);  // c0 = 1, 0.5, 0, -0.5, -1
    int outside = 0;
    for (const curve_point& row : curve) {
        const double c0 = row.solution.c0();
        EXPECT_TRUE(std::isfinite(row.smooth.c0) && std::isfinite(row.smooth.xi)) << "c0 = " << c0;
        const double Q = level.at_stick_end(c0, false).Q;
        if (!(Q >= 0.0 && Q <= f)) {
            ++outside;
            EXPECT_TRUE(row.is_refused()) << "c0 = " << c0 << ": Q(c0) = " << Q << " answered";
            EXPECT_NE(row.refused.find("Q(c0) = " + shortest(Q) + " lies outside [0, f]"), std::string::npos)
                << row.refused;
        }
        if (row.is_refused()) continue;
        EXPECT_EQ(row.solution.Q, Q);  // method product: the level's own load
        ASSERT_TRUE(row.estimate.has_value());
        if (c0 == 1.0 || c0 == -1.0) {  // full stick and gross sliding: Q = 0 and f exactly
            EXPECT_EQ(row.solution.Q, c0 == 1.0 ? 0.0 : f);
            continue;
        }
        EXPECT_GE(row.solution.Q - row.estimate->Q, 0.0) << "c0 = " << c0;
        EXPECT_LE(row.solution.Q + row.estimate->Q, f) << "c0 = " << c0;
    }
    EXPECT_GE(outside, 2);  // Q = -28.8 at c0 = 0.5 and 10.9 at c0 = 0 before this rule
}

// The same at n = 64: the loads inside [0, f] whose estimate reaches outside are refused too.
TEST(Curve, SweptLoadWhoseIntervalLeavesZeroToFIsRefused) {
    contact c(stiff_layer(), f, solver_options{64, method::product});
    const std::vector<curve_point> curve = swept_curve(c, 9);
    int interval = 0;
    for (const curve_point& row : curve) {
        if (row.refused.find("(its error estimate) reaches outside [0, f]") != std::string::npos) ++interval;
        if (row.is_refused()) continue;
        // Only the ends are answered in this scene, with their exact loads.
        EXPECT_TRUE(row.solution.c0() == 1.0 || row.solution.c0() == -1.0) << "c0 = " << row.solution.c0();
        EXPECT_EQ(row.solution.Q, row.solution.c0() == 1.0 ? 0.0 : f);
    }
    EXPECT_GE(interval, 1);
}

// The checks of a swept point (tangential_solver::check): the stick zone's margin of (3.3),
// whose U-series are summed for the whole grid at once, equals the scalar route bit for bit:
// min over the 200 Chebyshev points of [start, c0] of (f p(r) - |p1(r)|)/f, with
// normal_solution::pressure and tangential_solver::traction one point at a time.
TEST(Curve, SweptChecksEqualTheScalarRoute) {
    roughness r;  // Fig. 2a, curve 3 (docs/performance.md)
    r.cylinder1.tangential = r.cylinder2.tangential = r.cylinder1.normal = r.cylinder2.normal = {1.0, 1.0};
    for (const int n : {32, 128}) {
        const normal_solution normal = solve_normal(kernel::normal(r), n, method::product);
        tangential_solver level(normal, kernel::tangential(r), kernel::normal(r), f);
        for (const double c0 : {0.98, 0.5, 0.0, -0.5, -0.97}) {
            const tangential_solution s = level.at_stick_end(c0, true);
            double margin = std::numeric_limits<double>::infinity();
            for (int i = 0; i < 200; ++i) {
                const double x = std::cos(M_PI * (i + 0.5) / 200);
                const double at = 0.5 * (s.start() + s.c0()) + 0.5 * (s.c0() - s.start()) * x;
                margin = std::min(margin, (f * normal.pressure(at) - std::fabs(level.traction(s, at))) / f);
            }
            EXPECT_EQ(s.checks.stick_margin, margin) << "n = " << n << ", c0 = " << c0;
            EXPECT_TRUE(s.checks.hold()) << "n = " << n << ", c0 = " << c0;
        }
    }
}

// A sweep's systems refined on the previous factorisation (dense_system::solve_near) give the
// load, creep and distribution of the fresh LU route to rounding, equal and unequal kernels.
TEST(Curve, SweptRefinedSolvesAgreeWithFreshFactorisations) {
    roughness equal;  // Fig. 2a, curve 3
    equal.cylinder1.tangential = equal.cylinder2.tangential = equal.cylinder1.normal =
        equal.cylinder2.normal = {1.0, 1.0};
    roughness unequal = equal;
    unequal.cylinder1.tangential = {1.0, 0.5};
    unequal.cylinder2.normal = {0.8, 0.5};
    for (const roughness& r : {equal, unequal}) {
        const normal_solution normal = solve_normal(kernel::normal(r), 128, method::product);
        tangential_solver swept(normal, kernel::tangential(r), kernel::normal(r), f);
        tangential_solver fresh(normal, kernel::tangential(r), kernel::normal(r), f);
        double largest = 0.0;
        for (int i = 1; i < 50; ++i) {
            const double c0 = 1.0 - 2.0 * i / 50.0;
            const tangential_solution a = swept.at_stick_end(c0, false, true);
            const tangential_solution b = fresh.at_stick_end(c0, false, false);
            // The solutions differ by the condition number times eps at most; Q = f + rho int q
            // loses f/Q of that to cancellation near full stick.
            const double rounding = tol::solve_rounding / b.rcond;
            EXPECT_NEAR(a.xi, b.xi, rounding * std::fabs(b.xi)) << "c0 = " << c0;
            EXPECT_NEAR(a.Q, b.Q, rounding * f) << "c0 = " << c0;
            ASSERT_EQ(a.psi_b.size(), b.psi_b.size());
            for (std::size_t j = 0; j < a.psi_b.size(); ++j)
                EXPECT_NEAR(a.psi_b[j], b.psi_b[j], rounding * std::fabs(b.psi_b[0])) << "c0 = " << c0 << ", j = " << j;
            largest = std::max(largest, std::fabs(a.xi - b.xi) / std::fabs(b.xi));
        }
        EXPECT_GT(largest, 0.0);  // the refined route was taken (a fresh LU each time would agree bit for bit)
    }
}

// Bad input still aborts the curve at once: a load above f is an input_error, not a row.
TEST(Curve, BadInputStillAborts) {
    contact c = fresh();
    EXPECT_THROW(creep_curve(c, {f * 5.0 / 9.0, 1.5 * f}), input_error);
    EXPECT_THROW(swept_curve(c, 1), input_error);
}

// The CSV: every row as wide as the header; a refused row has its load, Carter's columns and
// status refused, every computed field empty (never a plausible number).
TEST(Curve, CsvMarksRefusedRows) {
    const std::vector<double> loads = curve_loads(7, f);
    contact c = fresh();
    const std::vector<curve_point> curve = creep_curve(c, loads);
    int refused = 0;
    for (const curve_point& row : curve) refused += row.is_refused() ? 1 : 0;
    ASSERT_GE(refused, 1);
    ASSERT_LT(refused, 7);
    std::ostringstream out;
    write_curve_csv(out, curve);
    std::istringstream in(out.str());
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = split(line);
    ASSERT_EQ(header.back(), "status");
    std::vector<std::vector<std::string>> rows;
    while (std::getline(in, line)) rows.push_back(split(line));
    ASSERT_EQ(rows.size(), loads.size());
    const auto column = [&](const char* name) {
        for (std::size_t k = 0; k < header.size(); ++k)
            if (header[k] == name) return k;
        ADD_FAILURE() << "no column " << name;
        return header.size();
    };
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::vector<std::string>& r = rows[i];
        ASSERT_EQ(r.size(), header.size()) << "row " << i;
        EXPECT_EQ(r[column("Q")], shortest(loads[i]));
        EXPECT_EQ(r[column("xi_carter")], shortest(carter(loads[i], f).xi));
        if (curve[i].is_refused()) {
            EXPECT_EQ(r.back(), "refused");
            for (const char* name : {"c0", "xi", "xi_over_f", "checks_hold", "c0_error_estimate", "xi_error_estimate",
                                     "Q_error_estimate", "zones", "stick_start", "zone_path"})
                EXPECT_EQ(r[column(name)], "") << name;
        } else {
            EXPECT_EQ(r.back(), "ok");
            EXPECT_EQ(r[column("xi")], shortest(curve[i].solution.xi));
            EXPECT_EQ(r[column("zone_path")], "single");  // the paper's zone (docs/formulation.md 7(i))
        }
    }
}

// A physical scene's columns on a refused row: P1 = Q P2 and Carter's xi1 of the given load,
// xi1 (the refused creep) empty. The units come from data/steel-rollers.toml's materials; the
// rows from the stiff layer's curve (write_curve_csv only converts them).
TEST(Curve, CsvPhysicalColumnsOfRefusedRows) {
    scene s = parse_scene(
        "E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 1.0e5\nfriction = 0.3\n"
        "[cylinder1.normal]\nk = 8.0e14\nt = 1.5e6\n",
        "steel.toml", ".");
    const std::optional<contact_width> width = settle_width(s);
    ASSERT_TRUE(width.has_value());
    contact c = fresh();
    const std::vector<double> loads = curve_loads(7, f);
    const std::vector<curve_point> curve = creep_curve(c, loads);
    std::ostringstream out;
    write_curve_csv(out, curve, si_context{*s.physical, std::vector<contact_width>(curve.size(), *width)});
    std::istringstream in(out.str());
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = split(line);
    ASSERT_EQ(header.size(), 22u);
    ASSERT_EQ(header[13], "stick_start_error_estimate");  // after stick_start (session 26)
    ASSERT_EQ(header[15], "P1_N_per_m");
    ASSERT_EQ(header[18], "n");  // each row's n (empty: not given to write_curve_csv)
    ASSERT_EQ(header[19], "status");
    ASSERT_EQ(header[20], "P1_N_per_m_error_estimate");  // after status (session 27: no column moves)
    ASSERT_EQ(header[21], "xi1_error_estimate");
    int refused = 0;
    for (std::size_t i = 0; std::getline(in, line); ++i) {
        const std::vector<std::string> r = split(line);
        ASSERT_EQ(r.size(), header.size()) << line;
        EXPECT_EQ(std::stod(r[15]), loads[i] * 1.0e5);
        EXPECT_NE(r[17], "");  // Carter's xi1 of the given load
        if (r[19] == "refused") {
            ++refused;
            EXPECT_EQ(r[16], "") << "xi1 of a refused row";
            EXPECT_EQ(r[13], "") << "the start's estimate of a refused row";
            EXPECT_EQ(r[20], "0") << "the given load's P1 = Q P2, exact";
            EXPECT_EQ(r[21], "") << "xi1's estimate of a refused row";
        } else {
            EXPECT_EQ(r[19], "ok");
            EXPECT_EQ(
                r[16],
                shortest(to_si(*s.physical, *width, loads[i], f, curve[i].solution.c0(), curve[i].solution.xi).xi1));
            EXPECT_EQ(r[13], curve[i].estimate ? shortest(curve[i].estimate->start) : std::string());
        }
    }
    EXPECT_GE(refused, 1);
}
