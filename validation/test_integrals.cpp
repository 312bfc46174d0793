// SPDX-License-Identifier: GPL-3.0-or-later
// The integrals of dissimilar rollers' blended zones and what their errors reach (session 17, review items F3, F4, T2
// of session 16): the accepted quadrature error held on a sum of pieces, not on each piece (within_accepted,
// docs/formulation.md 8(p) "Free rolling at f = 0.2").
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"

#include "aluminium_on_steel.hpp"
#include "command_output.hpp"

using namespace roughroll;

// Pieces whose errors are each within the whole limit but whose sum is not (the old rule accepted each piece at
// 1e-10, so 32 pieces of W's cut carried up to 3.2e-9): the pieces above their share are asked again at it, and the
// sum's error is within the limit. A piece asked at its share answers with a smaller error (another route) or throws.
TEST(Integrals, PiecesShareTheAcceptedErrorOfTheirSum) {
    constexpr double limit = 1e-10;
    constexpr std::size_t count = 8;
    std::vector<int> asked(count, 0);
    const auto piece = [&](std::size_t i, double accepted) {
        ++asked[i];
        // At the whole limit: 0.9 of it on the odd pieces (their sum 3.6 limits), 1e-14 on the even ones. At a share:
        // a fifth of the share (the qags route's).
        const double error = accepted >= limit ? (i % 2 ? 0.9 * limit : 1e-14) : 0.2 * accepted;
        return quadrature_value{1.0 + (accepted >= limit ? 0.0 : 1e-12), error};
    };
    const quadrature_value sum = within_accepted(count, limit, piece);
    EXPECT_LE(sum.error, limit);
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(asked[i], i % 2 ? 2 : 1) << i;  // only those above the share
    EXPECT_DOUBLE_EQ(sum.value, 8.0 + 4e-12);

    // Within the limit as a sum: each piece once, the values as they came (bit for bit those of before).
    std::fill(asked.begin(), asked.end(), 0);
    const quadrature_value within = within_accepted(count, limit, [&](std::size_t i, double accepted) {
        ++asked[i];
        return quadrature_value{0.1 * static_cast<double>(i), accepted / (2.0 * count)};
    });
    EXPECT_LE(within.error, limit);
    EXPECT_EQ(within.value,
              0.0 + 0.1 + 0.2 + 0.30000000000000004 + 0.4 + 0.5 + 0.6000000000000001 + 0.7000000000000001);
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(asked[i], 1) << i;

    // A piece that cannot meet its share throws, as integrate_piece does: the sum is never reported above the limit.
    EXPECT_THROW(within_accepted(count, limit,
                                 [&](std::size_t, double accepted) -> quadrature_value {
                                     if (accepted < limit) throw numerical_error("the piece's share not met");
                                     return {1.0, 0.5 * limit};
                                 }),
                 numerical_error);
}
