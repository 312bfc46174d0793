// SPDX-License-Identifier: GPL-3.0-or-later
// The ladder of levels for a point (free rolling by default) of aluminium on steel with every rung's contact stopped
// at its first level's solve (the contacts' checkpoint, called before every level's solve): the refusals the ladder
// decides before any solve (docs/formulation.md 8(n) "Beyond every n", "Rough rollers: beyond every n" and item 7)
// are asserted by the levels solved, not by time. Shared by validation/test_ladder_refusals.cpp,
// test_rough_free_rolling_s24.cpp and test_loaded_leading_zone_s29.cpp. Header-only.
#pragma once

#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "aluminium_on_steel.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/level_ladder.hpp"

namespace ladder_first_solve {

// Thrown by the checkpoint: a level was about to be solved.
struct level_solved : std::runtime_error {
    level_solved() : std::runtime_error("a level was solved") {}
};

struct ladder_run {
    std::string refusal;  // the resolution_error's line; empty when the ladder started a solve
    int rungs_built = 0;  // contacts the factory made
    bool solved = false;  // a level's solve was started
};

// The point at load Q (free rolling by default) at friction f on rollers with `layers`, at coupling `level`, tolerance
// `tol` (empty: the default).
inline ladder_run run(double f, const roughroll::roughness& layers, roughroll::coupling_level level,
                      std::optional<double> tol = std::nullopt, double Q = 0.0) {
    using namespace roughroll;
    ladder_run r;
    solver_options options;
    options.tolerance = tol;
    level_ladder ladder(options, layers, [&](int n) {
        ++r.rungs_built;
        auto c = std::make_unique<contact>(layers, f, solver_options{n, options.how, options.zones, tol},
                                           dissimilar{beta_al_st, level});
        c->set_checkpoint([] { throw level_solved(); });
        return c;
    });
    try {
        ladder.point(Q);
        ADD_FAILURE() << "f = " << f << ": answered without a solve";
    } catch (const resolution_error& e) {
        r.refusal = e.what();
    } catch (const level_solved&) {
        r.solved = true;
    }
    return r;
}

// The friction a refusal names, "below about X" (the rule's edge, 8(n)), where it names one.
inline std::optional<double> named_friction(const std::string& refusal) {
    const std::string key = "below about ";
    const std::size_t at = refusal.find(key);
    if (at == std::string::npos) return std::nullopt;
    return std::strtod(refusal.c_str() + at + key.size(), nullptr);
}

}  // namespace ladder_first_solve
