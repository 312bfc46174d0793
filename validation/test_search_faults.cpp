// SPDX-License-Identifier: GPL-3.0-or-later
// A numerical fault of the general zone search (docs/formulation.md 7(e)) as the user reads it (review S6): under
// zones = "auto" (the paper's zone failed its checks) or "general", the point's refusal names what failed in the
// scene's terms (the load, n, the paper's zone's margins, the search for a stick zone between two slip zones) and what
// to change (another n; zones = "single"), and no code: no function, algorithm or internal step. The search's own line
// stays nested in the numerical_error (std::nested_exception) for a caller that wants it. Before, the search's line
// reached the user as it was, e.g. "Brent search for the stick zone's start did not converge in 200 iterations".
// The scene fails its paper's zone near gross sliding (zone_scenes::tangential_dominates_a, Q/f = 1 - 1e-3), so that
// the point runs the general search; its fault is injected at the search's checkpoint, the last of the point's.
#include <exception>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/problems/contact.hpp"
#include "zone_scenes.hpp"

using namespace roughroll;

namespace {
constexpr double f = 0.3, Q = (1.0 - 1e-3) * f;
// What zone_in_bracket's Brent throws where it does not converge (numerics/root_search.cpp).
const std::string internal_line = "Brent search for the stick zone's start did not converge in 200 iterations";

// The point at Q under `zones`, the checkpoint's call `fault_at` throwing the internal line; and how many calls.
std::pair<tangential_solution, int> point(zone_search zones, int fault_at) {
    solver_options options{64, method::product};
    options.zones = zones;
    contact p(zone_scenes::tangential_dominates_a(), f, options);
    int calls = 0;
    p.set_checkpoint([&] {
        if (++calls == fault_at) throw numerical_error(internal_line);
    });
    tangential_solution s = p.point(Q);
    return {std::move(s), calls};
}

// The refusal's line and the line nested in it, where the search faults at its checkpoint.
std::pair<std::string, std::string> fault_lines(zone_search zones) {
    const auto [answer, calls] = point(zones, 0);
    EXPECT_TRUE(answer.layout.general() && answer.checks.hold());
    try {
        point(zones, calls);
        ADD_FAILURE() << "answered";
    } catch (const numerical_error& e) {  // a fault stays a fault, not "no zone" nor the paper's zone
        try {
            std::rethrow_if_nested(e);
        } catch (const numerical_error& inner) {
            return {e.what(), inner.what()};
        }
        return {e.what(), ""};
    }
    return {};
}

// `n`: the nodes the line names; `single_advised`: zones = "single" is advised (not where the paper's zone faulted
// too).
void expect_the_users_terms(const std::string& line, int n = 64, bool single_advised = true) {
    for (const char* code : {"Brent", "Newton", "zone_solver", "find_general", "zones_for", "::", "did not converge",
                             "stick zone's start", "iterations"})
        EXPECT_EQ(line.find(code), std::string::npos) << code << " in: " << line;
    EXPECT_EQ(line.rfind("at Q/f = " + shortest(Q / f) + " ", 0), 0u) << line;
    EXPECT_NE(line.find("the search for a stick zone between two slip zones"), std::string::npos) << line;
    EXPECT_NE(line.find("failed numerically at n = " + std::to_string(n)), std::string::npos) << line;
    EXPECT_NE(line.find("another n may get through"), std::string::npos) << line;
    EXPECT_EQ(line.find("zones = \"single\" (solver.zones, --zones) reports the paper's zone") != std::string::npos,
              single_advised)
        << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
}
}  // namespace

TEST(SearchFaults, AutoSaysWhatFailedAndWhatToChange) {
    const auto [line, inner] = fault_lines(zone_search::automatic);
    expect_the_users_terms(line);
    EXPECT_NE(line.find("the paper's stick zone from the leading edge fails the checks (3.3)-(3.4) (margins: stick "),
              std::string::npos)
        << line;
    EXPECT_NE(line.find(" with its failed checks"), std::string::npos) << line;
    EXPECT_EQ(inner, internal_line);
}

TEST(SearchFaults, GeneralSaysWhatFailedAndWhatToChange) {
    const auto [line, inner] = fault_lines(zone_search::general);
    expect_the_users_terms(line);
    EXPECT_NE(line.find("(zones = \"general\")"), std::string::npos) << line;
    EXPECT_EQ(inner, internal_line);
}

// The one-parameter limit's paper's zone can fail numerically where the general zone does not (its c0 tends to -1
// near gross sliding when eps2 > eps1, docs/formulation.md 7(g)): the point then runs the general search, whose fault
// is worded as every other caller's (review S2: it reached the user as the search's own line). Every checkpoint
// throws: the paper's zone's, then the search's.
TEST(SearchFaults, PaperZoneFaultThenSearchFaultSaysWhatFailed) {
    roughness r;  // 2T/A^2 = 0.2 in both directions on cylinder 1 (the limit takes 2T/A^2 only)
    r.cylinder1.normal = {0.1, 1.0};
    r.cylinder1.tangential = {0.1, 1.0};
    contact p(r, f, solver_options{128, method::one_parameter});
    p.set_checkpoint([] { throw numerical_error(internal_line); });
    try {
        p.point(Q);
        ADD_FAILURE() << "answered";
    } catch (const numerical_error& e) {
        const std::string line = e.what();
        expect_the_users_terms(line, 128, false);
        EXPECT_NE(line.find("the paper's stick zone from the leading edge and the search for a stick zone between two "
                            "slip zones both failed numerically"),
                  std::string::npos)
            << line;
        try {
            std::rethrow_if_nested(e);
            ADD_FAILURE() << "no line nested";
        } catch (const numerical_error& inner) {
            EXPECT_EQ(std::string(inner.what()), internal_line);
        }
    }
}
