// SPDX-License-Identifier: GPL-3.0-or-later
// The zone search where its Newton stops at the ends' rounding limit (newton_stop::rounding_limit, docs/formulation.md
// 8(q), "The stop's reason"): to each route the stop is "no root from here", and the search goes on to its next route
// (the scan of starts, the bracket's Brent, the next bracket); only where no route answers does it refuse, and then
// with the limit's line, not "no zone". Checked on a made-up stick-zone operator (stick_zone_operator.hpp, the value
// zone_solver is generic over) whose zones [s, c] carry Q(s, c) = f (1 - (c - s)) and have the entry condition
// E = s - s*, in closed form: the answer is s = s*, c = s* + 1 - |Q|/f. Newton's entry residual carries a rounding of
// 1e-8 (a fixed function of the ends' bits) and the systems rcond 1e-9, so eps/rcond = 2.2e-7 of the half-width,
// 2.2e4 times the ends' tolerance 1e-11, beyond the cap of 1000 (the real zone systems reach 4e-9 at n = 1000): Newton
// stops at the limit from every start, while Brent on the clean entry condition finds s* to 1e-15. Before, the stop
// was a rounding_limit_error thrown from the first Newton, past the scan and Brent: the point was refused.
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/level_ladder.hpp"
#include "roughroll/problems/stick_zone_operator.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_newton.hpp"
#include "roughroll/problems/zone_solver.hpp"
#include "../tests/rounding_jitter.hpp"

using namespace roughroll;

namespace {
constexpr double f = 0.3, Q = 0.1;
constexpr double answer_start = -0.49;  // s*, off the scan's starts -1 + 2k/32

// The made-up operator: systems of condition `rcond`, the entry condition's root at `root`, `scan` trial starts;
// every_bracket: the scan of every bracket (dissimilar rollers' way) instead of the first.
stick_zone_operator made_up(double rcond, double root, int scan, bool every_bracket) {
    stick_zone_operator op;
    op.f = f;
    op.paper_zone = [](double, bool) { return std::nullopt; };
    op.solve = [rcond, root](double s, double c) {
        return zone_solution(f, s, c, 0.0, f * (1.0 - (c - s)), {s - root}, rcond);
    };
    op.excess = [](const tangential_solution& t, double magnitude) { return t.Q - magnitude; };
    op.empty_load = [](double) { return f; };
    op.entry = [](const tangential_solution& t) { return t.psi_b[0]; };
    op.newton_entry = [](const tangential_solution& t) { return t.psi_b[0] + jitter(t.start() + 2.0 * t.c0(), 1e-8); };
    op.gross_sliding = []() -> tangential_solution { throw numerical_error("not reached: no scan to r*"); };
    op.check = [](const tangential_solution&) { return traction_checks{1.0, 1.0, 1.0, 0.0, 0.0, true, true, true}; };
    op.method.name = "the made-up zone search";
    op.method.refusal = "no made-up zone carries the load";
    op.method.scan = scan;
    op.method.every_bracket = every_bracket;
    op.method.edge = edge_zone::absent;
    op.method.relative_load = false;  // the blend's residuals, whose Newton is told the systems' rounding
    op.method.newton_tolerance = 1e-11;
    return op;
}

void expect_the_answer(const tangential_solution& s) {
    EXPECT_NEAR(s.start(), answer_start, 1e-13);
    EXPECT_NEAR(s.c0(), answer_start + 1.0 - Q / f, 1e-13);
    EXPECT_NEAR(s.Q, Q, 1e-13);
}
}  // namespace

TEST(RoundingLimit, NewtonStopsThereOnTheMadeUpZones) {
    // The premise: from a zone near the answer the ends' Newton stops at the limit, noted; well conditioned (rcond
    // 1e-3, a rounding of 2.2e-13) the same jitter leaves it without a root, no limit noted.
    const auto newton = [](const stick_zone_operator& op, rounding_limits& met) {
        return ends_newton<tangential_solution>(
            [&op](const std::vector<stick_span>& z) -> std::optional<tangential_solution> {
                return op.solve(z[0].start, z[0].end);
            },
            op.newton_entry, Q, f, {{-0.48, 0.18, 0.0}}, false, zone_newton_iterations, 1e-11, met);
    };
    rounding_limits met, none;
    EXPECT_FALSE(newton(made_up(1e-9, answer_start, 32, false), met));
    EXPECT_TRUE(met.met());
    EXPECT_FALSE(newton(made_up(1e-3, answer_start, 32, false), none));
    EXPECT_FALSE(none.met());
}

TEST(RoundingLimit, TheBracketsBrentAnswersWhereNewtonStopsThere) {
    // The scan to the first bracket: Newton in the bracket stops at the limit, Brent on the start answers.
    EXPECT_NO_THROW(expect_the_answer(zone_solver(made_up(1e-9, answer_start, 32, false)).solve(Q)));
    // The same from a guess: Newton from it first (the limit), then the scan and Brent.
    EXPECT_NO_THROW(expect_the_answer(zone_solver(made_up(1e-9, answer_start, 32, false))
                                          .solve(Q, false, {-0.45, -0.45 + 1.0 - Q / f})));
    // Every bracket (dissimilar rollers' scan), which went on after a numerical fault only: the same answer.
    EXPECT_NO_THROW(expect_the_answer(zone_solver(made_up(1e-9, answer_start, 32, true)).solve(Q)));
    // The search as one route of a larger one: the answer, the limit met on the way noted.
    rounding_limits met;
    const std::optional<tangential_solution> s =
        zone_solver(made_up(1e-9, answer_start, 32, false)).find(Q, false, {}, met);
    ASSERT_TRUE(s);
    expect_the_answer(*s);
    EXPECT_TRUE(met.met());
}

TEST(RoundingLimit, RefusedWithTheLimitOnlyWhereEveryRouteFails) {
    // Two trial starts (0 and 1, the latter outside): the scan brackets nothing, so Newton from the guess is the only
    // route that could answer. At the limit, nothing is found: the refusal names the limit and what lowers it.
    const std::vector<double> guess{-0.45, -0.45 + 1.0 - Q / f};
    try {
        zone_solver(made_up(1e-9, answer_start, 2, false)).solve(Q, false, guess);
        ADD_FAILURE() << "no refusal";
    } catch (const rounding_limit_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("the zone ends are not resolved at this n"), std::string::npos) << what;
        EXPECT_NE(what.find("give a smaller n"), std::string::npos) << what;
        EXPECT_EQ(what.find("made-up"), std::string::npos) << what;
    }
    EXPECT_THROW(zone_solver(made_up(1e-9, answer_start, 2, false)).find(Q, false, guess), rounding_limit_error);
    // As a route of a larger search: empty, the limit noted for the caller's refusal.
    rounding_limits met;
    EXPECT_FALSE(zone_solver(made_up(1e-9, answer_start, 2, false)).find(Q, false, guess, met));
    EXPECT_TRUE(met.met());
    // Without the limit (well conditioned: Newton merely fails), the same search ends on "no zone", not the limit.
    try {
        zone_solver(made_up(1e-3, answer_start, 2, false)).solve(Q, false, guess);
        ADD_FAILURE() << "no refusal";
    } catch (const rounding_limit_error& e) {
        ADD_FAILURE() << "the limit where it was not met: " << e.what();
    } catch (const resolution_error& e) {
        EXPECT_EQ(std::string(e.what()), "no made-up zone carries the load");
    }
    rounding_limits none;
    EXPECT_FALSE(zone_solver(made_up(1e-3, answer_start, 2, false)).find(Q, false, guess, none));
    EXPECT_FALSE(none.met());
}

// The scan to the first bracket where Newton in the bracket stops at the limit and Brent on the start then faults (a
// zone system singular near the answer, made up: the entry throws within 0.005 of s*, where no trial start lies): the
// limit is "no root from here" to Brent's route too, and the refusal keeps the limit's line (review S1: the fault was
// re-raised, the limit's advice lost). Without the limit (rcond 1e-3: Newton merely fails) the fault stays a fault.
TEST(RoundingLimit, BrentsFaultAfterTheLimitKeepsTheLimitsLine) {
    const auto faulting = [](double rcond) {
        stick_zone_operator op = made_up(rcond, answer_start, 32, false);
        op.entry = [](const tangential_solution& t) {
            if (std::fabs(t.start() - answer_start) < 0.005) throw numerical_error("made-up singular zone system");
            return t.psi_b[0];
        };
        return op;
    };
    try {
        zone_solver(faulting(1e-9)).solve(Q);
        ADD_FAILURE() << "answered";
    } catch (const rounding_limit_error& e) {
        EXPECT_NE(std::string(e.what()).find("give a smaller n"), std::string::npos) << e.what();
    } catch (const error& e) {
        ADD_FAILURE() << "not the limit's line: " << e.what();
    }
    // As a route of a larger search: empty, the limit noted.
    rounding_limits met;
    EXPECT_FALSE(zone_solver(faulting(1e-9)).find(Q, false, {}, met));
    EXPECT_TRUE(met.met());
    EXPECT_THROW(zone_solver(faulting(1e-3)).solve(Q), numerical_error);
}

// What the limit's refusal advises (review S5): the rounding eps/rcond grows with n and the zone ends' tolerance is
// fixed, so the line names a smaller n, given or the ladder's, and not the user's tolerance, which does not change it.
// Only where a lower rung of the ladder answered with an estimate above the tolerance does a larger tolerance help
// (the ladder then stops at that rung): the ladder's line says so there, names the rung that met the limit as the
// last one tried, and does not claim that the rungs above it were tried. Before, the refusal advised "a larger
// tolerance" even at the ladder's first rung and for a given n, and the ladder's line read "no n up to 1000" after
// a limit met at n = 256, with the limit left out.
namespace {
std::string limit_line() {
    rounding_limits met;
    met.note(newton_result{newton_stop::rounding_limit, std::nullopt, 2.2e-7}, 1e-11);
    return met.refusal();
}

// The ladder on the paper's problem of a rough roller (layers eps = 0.1 at A = 1: estimates of about 4e-10, not the
// smooth rollers' zero; f = 0.3, Q = 0.15) with `tolerance`, whose rungs from `limit_at` on meet the rounding limit at
// their first solve (the contact's checkpoint); its refusal line.
std::string ladder_line(double tolerance, int limit_at) {
    solver_options options;
    options.tolerance = tolerance;
    roughness rough;
    rough.cylinder1.normal = rough.cylinder1.tangential = {0.1, 1.0};
    level_ladder ladder(options, rough, [limit_at, rough](int n) {
        auto c = std::make_unique<contact>(rough, 0.3, solver_options{n});
        if (n >= limit_at) c->set_checkpoint([] { throw rounding_limit_error(limit_line()); });
        return c;
    });
    try {
        ladder.point(0.15);
        ADD_FAILURE() << "answered";
    } catch (const resolution_error& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(RoundingLimit, AdviceNamesOnlyWhatTheUserCanChange) {
    const std::string line = limit_line();
    EXPECT_EQ(line,
              "the zone ends are not resolved at this n: the rounding of their systems (2.2e-07 of the half-width) "
              "passes 1000 times their tolerance 1e-11 and grows with n; give a smaller n");
    // At the ladder's first rung: no rung below it to stop at, no tolerance to raise.
    const std::string first = ladder_line(1e-6, 128);
    EXPECT_EQ(first, "no n up to 128 meets the tolerance 1e-06 (relative): no n gave an answer whose checks hold with "
                     "an error estimate (at n = 128: " + line + ")");
    // At the second rung, after the first answered with an estimate above a tolerance of 1e-13: raise the tolerance
    // (the first rung then answers), or give a smaller n; the climb ended at n = 256.
    const std::string second = ladder_line(1e-13, 256);
    EXPECT_EQ(second.rfind("no n up to 256 meets the tolerance 1e-13 (relative): the best estimate reached is ", 0), 0u)
        << second;
    EXPECT_NE(second.find(" at n = 128, and at n = 256 " + line + "; raise the tolerance (solver.tolerance, "
                          "--tolerance"),
              std::string::npos)
        << second;
    EXPECT_EQ(second.find("give n to accept"), std::string::npos) << second;  // F2: the tolerance only
}
