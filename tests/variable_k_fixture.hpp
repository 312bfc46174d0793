// SPDX-License-Identifier: GPL-3.0-or-later
// The variable-k weight's five zones with 8(x)'s continuous k (docs/formulation.md 8(z), "A varying k"), as
// tests/test_variable_k_weight_s21.cpp, tests/test_variable_k_weight_s22.cpp, bench/variable_k_weight_cost.cpp and
// bench/variable_k_weight_rebuild.cpp set them up (one definition: the same values bit for bit in all four); and the
// f = 0.2 state that tests/test_w_route_s22.cpp and tests/test_exact_weight_s23.cpp share (two_tenths_ends, psi_terms).
// Header-only, for tests and benches.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "roughroll/problems/pressure_kinks.hpp"

namespace variable_k_fixture {

// Free rolling's five zones (slip -, stick, slip +, stick, slip -) with a thin second stick zone (0.0055 long), and
// k0 = beta_D f at f = 0.2 (8(z), "The cost").
inline const std::vector<double> free_rolling_ends{-1.0, -0.7, 0.3, 0.5, 0.5055, 1.0};
constexpr double free_rolling_k0 = 0.0288;

// The piecewise constant k of those zones: -k0, 0, +k0, 0, -k0.
inline std::vector<double> piecewise_k(double k0) { return {-k0, 0.0, k0, 0.0, -k0}; }

// x's coordinate on [l, r] mapped to [-1, 1].
inline double t_of(double x, double l, double r) { return std::clamp((2.0 * x - l - r) / (r - l), -1.0, 1.0); }

// 8(x)'s continuous k on the five zones of ends e_0 = -1 < e_1 < ... < e_5 = 1: -k0 on the edges' slip zones, +k0 on
// the reversed one, and across the stick zones the blend k0 S_3 = k0 (2 Theta_3 - 1) (8(r)), rising on the first,
// falling on the second: no jump anywhere. The entries of the slip zones are empty (k constant there: the k given
// beside it).
inline std::vector<std::function<double(double)>> blended(const std::vector<double>& e, double k0) {
    return {{},
            [=](double x) { return k0 * (2.0 * roughroll::blend_theta3(t_of(x, e[1], e[2])) - 1.0); },
            {},
            [=](double x) { return k0 * (1.0 - 2.0 * roughroll::blend_theta3(t_of(x, e[3], e[4]))); },
            {}};
}

// Free rolling of the pair at full coupling, f = 0.2: the stick zones' ends s1, c1, s2, c2 (the source's, the kinks'; a
// 0.0055-long second zone 0.0016 from the edge).
constexpr std::array<double, 4> two_tenths_ends{-0.98483838432, 0.97527798693, 0.99291937343, 0.99844743400};

// The two stick zones' psi as n-term U-series: coefficients falling like j^-2.5, as psi's next to the entry at f = 0.2.
inline std::array<std::vector<double>, 2> psi_terms(int n) {
    std::array<std::vector<double>, 2> b;
    for (int j = 0; j < n; ++j) {
        b[0].push_back(1e-2 * std::cos(0.9 * j) / std::pow(1.0 + j, 2.5));
        b[1].push_back(4e-3 * std::sin(0.7 * j + 0.3) / std::pow(1.0 + j, 2.5));
    }
    b[0][0] += 0.05;
    b[1][0] += 0.03;
    return b;
}

}  // namespace variable_k_fixture
