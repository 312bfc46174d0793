// SPDX-License-Identifier: GPL-3.0-or-later
// The Gauss-Jacobi rules of one full-coupling solve, built once and shared by the tangential solver's Jacobi zone
// (docs/formulation.md 8(v)) and the pressure's weighted kinks (8(w)): the shared rule is the one a fresh construction
// gives, bit for bit, a rule is built once per (n, a, b) and never handed out for another key, and the collocation
// made from a shared rule is the one made from (n, a).
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/problems/pressure_kinks.hpp"

using namespace roughroll;

namespace {
void expect_same_bits(const gauss_jacobi& x, const gauss_jacobi& y) {
    ASSERT_EQ(x.n, y.n);
    EXPECT_EQ(x.a, y.a);
    EXPECT_EQ(x.b, y.b);
    EXPECT_EQ(x.nodes, y.nodes);  // exact: the same construction, not a tolerance
    EXPECT_EQ(x.weights, y.weights);
    EXPECT_EQ(x.recurrence.A, y.recurrence.A);
    EXPECT_EQ(x.recurrence.B, y.recurrence.B);
    EXPECT_EQ(x.recurrence.C, y.recurrence.C);
}
}  // namespace

TEST(JacobiRuleSet, OneRulePerKeyBitForBitAFreshOne) {
    jacobi_rule_set set;
    const int n = 24;
    const double a = 0.5 - std::atan(0.3) / M_PI;  // a braked exponent (8(v): cot(pi a) = k)
    const auto r = set.rule(n, a, 1.0 - a), far = set.rule(4 * n, a, 1.0 - a);
    EXPECT_EQ(set.rule(n, a, 1.0 - a), r);  // the same object: built once
    EXPECT_EQ(set.rule(4 * n, a, 1.0 - a), far);
    expect_same_bits(*r, gauss_jacobi(n, a, 1.0 - a));
    expect_same_bits(*far, gauss_jacobi(4 * n, a, 1.0 - a));
    // Another n or an exponent one ulp away is another rule, never the cached one.
    const double a_next = std::nextafter(a, 1.0);
    const auto other = set.rule(n, a_next, 1.0 - a_next);
    EXPECT_NE(other, r);
    EXPECT_EQ(other->a, a_next);
    EXPECT_NE(set.rule(n + 1, a, 1.0 - a), r);
    EXPECT_NE(set.rule(n, a, 0.5), r);
}

TEST(JacobiRuleSet, CollocationOfASharedRuleIsTheCollocationOfNAndA) {
    jacobi_rule_set set;
    const int n = 32;
    const double a = 0.5 + std::atan(0.2) / M_PI;
    const jacobi_collocation shared(*set.rule(n, a, 1.0 - a)), own(n, a);
    expect_same_bits(shared.rule, own.rule);
    EXPECT_EQ(shared.collocation, own.collocation);
}

TEST(JacobiRuleSet, WeightedKinksTakeTheSetsRulesWithTheSameBits) {
    // 8(w): a weighted kink zone built with the solve's rules and without them gives the same p_q, load and constant.
    const int n = 24;
    const double beta = 0.05, f = 0.3, k_e = -beta * f, a_z = 0.5 - std::atan(0.25) / M_PI;
    const auto psi = [](double t) { return 1.0 + 0.3 * t - 0.2 * t * t; };
    jacobi_rule_set set;
    pressure_kinks with, without;
    with.set_weight(k_e);
    without.set_weight(k_e);
    with.add_weighted_zone(n, beta, -1.0, -0.3, 0.6, a_z, psi, nullptr, &set);
    without.add_weighted_zone(n, beta, -1.0, -0.3, 0.6, a_z, psi);
    EXPECT_EQ(with.load(), without.load());
    EXPECT_EQ(with.constant(), without.constant());
    for (const double r : {-0.99, -0.5, -0.3001, 0.0, 0.25, 0.5999, 0.61, 0.9})
        EXPECT_EQ(with.kink_part(r), without.kink_part(r)) << "at r = " << r;
    // The set now holds the zone's two rules: the tangential solver asking for them gets these, not new ones.
    const auto r = set.rule(n, a_z, 1.0 - a_z);
    EXPECT_EQ(set.rule(n, a_z, 1.0 - a_z), r);
    expect_same_bits(*r, gauss_jacobi(n, a_z, 1.0 - a_z));
}
