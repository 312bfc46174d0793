// SPDX-License-Identifier: GPL-3.0-or-later
// The variable-k weight's cheaper rebuild (docs/formulation.md 8(z), "The cost", session 22): I_c by product integration
// on its cached panels against session 21's route (the panels near x halved towards it, a evaluated afresh), and the
// economical discretisation, whose grading towards the ends next to a varying k now stops where m is resolved,
// against the dense one (every end graded to 2^-16 of its zone, count + 24 points per panel), on 8(x)'s blended five
// zones, a varying k next to a jump and a k whose derivative jumps at the zone ends (m ~ d log d there).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/numerics/blend_plateau.hpp"
#include "roughroll/numerics/variable_k_weight.hpp"

using namespace roughroll;

namespace {
// Free rolling's five zones (slip -, stick, slip +, stick, slip -) with a thin second stick zone, k0 = beta_D f at f = 0.2.
const std::vector<double> ends{-1.0, -0.7, 0.3, 0.5, 0.5055, 1.0};
const double k0 = 0.0288;

// x's coordinate on [l, r] mapped to [-1, 1].
double t_of(double x, double l, double r) { return std::clamp((2.0 * x - l - r) / (r - l), -1.0, 1.0); }

// 8(x)'s continuous k: the blend k0 S_3 = k0 (2 Theta_3 - 1) of 8(r) across the stick zones.
std::vector<std::function<double(double)>> blended() {
    return {{},
            [](double x) { return k0 * (2.0 * blend_plateau::theta3(t_of(x, ends[1], ends[2])) - 1.0); },
            {},
            [](double x) { return k0 * (1.0 - 2.0 * blend_plateau::theta3(t_of(x, ends[3], ends[4]))); },
            {}};
}

// k linear across the stick zones: continuous, its derivative jumps at all four interior ends (a_c ~ d there, m ~ d log d).
std::vector<std::function<double(double)>> linear() {
    return {{}, [](double x) { return k0 * t_of(x, ends[1], ends[2]); }, {},
            [](double x) { return -k0 * t_of(x, ends[3], ends[4]); }, {}};
}

struct named_weight {
    const char* name;
    std::vector<double> k;
    std::vector<std::function<double(double)>> varying;
};
// The blend; the blend with k = 0.15 on the reversed slip zone (a jump at both its ends, next to the varying k: both
// parts of a = a_pc + a_c at the same ends); the linear k.
std::vector<named_weight> cases() {
    return {{"blended", {-k0, 0.0, k0, 0.0, -k0}, blended()},
            {"next to a jump", {-k0, 0.0, 0.15, 0.0, -k0}, blended()},
            {"linear", {-k0, 0.0, k0, 0.0, -k0}, linear()}};
}

// Points on and off every zone: inside each zone, and 1e-3 .. 1e-12 of the zone from each end on both sides.
std::vector<double> probes() {
    std::vector<double> x;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        const double l = ends[i], r = ends[i + 1];
        for (double f : {0.013, 0.1, 0.31, 0.5, 0.77, 0.9, 0.987}) x.push_back(l + f * (r - l));
        for (double d : {1e-3, 1e-6, 1e-9, 1e-12}) {
            x.push_back(l + d * (r - l));
            x.push_back(r - d * (r - l));
        }
    }
    return x;
}
}  // namespace

TEST(VariableKWeightS22, IcByProductIntegrationAgreesWithQuadrature) {
    // I_c = int (a_c(t) - a_c(x))/(t - x) dt is what m carries (8(z), "A varying k"); product integration on a_c's
    // interpolant replaces the fresh quadrature near x. Both routes share the panels' far sums only: near x one
    // integrates a_c's degree-19 interpolant exactly, the other re-samples a on panels halved towards x.
    for (const named_weight& c : cases()) {
        const variable_k_weight w(ends, c.k, c.varying);
        double worst = 0.0, top = 0.0;
        for (double x : probes()) {
            worst = std::max(worst, std::fabs(w.i_c(x) - w.i_c_by_quadrature(x)));
            top = std::max(top, std::fabs(w.i_c(x)));
        }
        std::printf("%-15s I_c: product integration against quadrature %.1e (max |I_c| %.2f)\n", c.name, worst, top);
        EXPECT_LT(worst, 5e-14);
        EXPECT_GT(top, 1e-3);  // not a vacuous comparison
    }
}

TEST(VariableKWeightS22, GradingFromMAgreesWithTheDenseRoute) {
    // The economical route grades towards an end next to a varying k only until a panel's rule and its halves' agree
    // (8(z), "The cost"); the dense route grades to 2^-16 of the zone everywhere. Nodes and points (in [-1, 1]) to 1e-13,
    // weights within 1e-11 of the largest (the Christoffel sum's rounding, as in test_variable_k_weight_s21), at
    // n = 32 .. 128, the five zones' working range (at n = 256 the points next to a jump differ by 1.2e-13 with either
    // grading, 1.5e-13 with the economical route graded to 2^-16: the rounding of the dense route's points, whose defect is
    // 4.6e-11 there). The blend needs no grading at all, the linear k (m ~ d log d) about as deep as the dense route.
    for (const named_weight& c : cases()) {
        const variable_k_weight w(ends, c.k, c.varying);
        for (int n : {32, 64, 128}) {
            const variable_k_collocation cheap(w, n), dense(w, n, discretisation::dense);
            double node = 0.0, bulk = 0.0, top = 0.0, point = 0.0;
            for (int j = 0; j < n; ++j) {
                const double W = dense.rule().weights[j];
                node = std::max(node, std::fabs(cheap.rule().nodes[j] - dense.rule().nodes[j]));
                bulk = std::max(bulk, std::fabs(cheap.rule().weights[j] - W));
                top = std::max(top, W);
            }
            for (int m = 0; m <= n; ++m) point = std::max(point, std::fabs(cheap.points()[m] - dense.points()[m]));
            double alpha = 0.0;
            for (int j = 0; j < n; ++j)
                alpha = std::max(alpha, std::fabs(cheap.recurrence().alpha[j] - dense.recurrence().alpha[j]));
            const std::size_t few = discretisation_size(w.weight(), n),
                              many = discretisation_size(w.weight(), n, discretisation::dense);
            std::printf("%-15s n = %3d: nodes %.1e, points %.1e, weights %.1e of the largest, alpha %.1e; "
                        "discretisation %zu of %zu points\n",
                        c.name, n, node, point, bulk / top, alpha, few, many);
            EXPECT_LT(node, 1e-13);
            EXPECT_LT(point, 1e-13);
            EXPECT_LT(bulk, 1e-11 * top);
            EXPECT_LT(few, many);
        }
    }
}
