// SPDX-License-Identifier: GPL-3.0-or-later
// Full coupling's measured values with their estimates (error_estimate::coupling from point_estimate.hpp's
// coupling_from_levels; docs/formulation.md 8(e), "The measured values' estimates"; session 27 audit A4): the offset
// e = x_c/a and Johnson's P_H/P2 each bound their distance from a finer n's; gamma_0n's and the peak change's are none
// at full coupling (the alternation does not bound their share), printed null; off full coupling gamma_0n's estimate
// is |gamma_0n|, the model's gamma being 0.
#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "roughroll/base/text.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/problems/contact.hpp"
#include "aluminium_on_steel.hpp"

using namespace roughroll;

namespace {
const double f_pair = 0.05;  // data/aluminium-on-steel.toml's friction

struct measured {
    coupling_summary summary;
    double gamma;
    std::optional<error_estimate> estimate;
};

measured at(int n, double Q_over_f, bool estimated = true) {
    contact c(roughness{}, f_pair, solver_options{n, method::product}, {beta_al_st, coupling_level::full});
    const tangential_solution s = c.point(Q_over_f * f_pair);
    measured m{*c.coupling(), c.normal().gamma, std::nullopt};
    if (estimated) m.estimate = c.estimate(s);
    return m;
}
}  // namespace

// The braked pair (three zones) and the driven one (five zones) at n = 32, 64 against n = 512 (whose own distance from
// n = 1000 is below 1e-13 for each value: docs/formulation.md 8(e)). Zeroed, each estimate fails: the distances are
// above 0 (1e-15 .. 1e-12) but Johnson's P_H/P2, Hertz's 1 at every n, whose estimate is its floor.
TEST(CouplingEstimates, BoundTheDistanceFromAFinerN) {
    for (const double q : {-0.75, 0.75}) {
        const measured reference = at(512, q, false);
        for (const int n : {32, 64}) {
            SCOPED_TRACE("Q/f = " + std::to_string(q) + ", n = " + std::to_string(n));
            const measured m = at(n, q);
            ASSERT_TRUE(m.estimate && m.estimate->coupling);
            const coupling_values& e = *m.estimate->coupling;
            EXPECT_LE(std::fabs(m.summary.offset - reference.summary.offset), e.offset);
            EXPECT_LE(std::fabs(m.summary.lambda_johnson - reference.summary.lambda_johnson), e.lambda_johnson);
            EXPECT_TRUE(std::isnan(e.gamma));  // no estimate: C's and the peak's alternation share are not bounded
            EXPECT_TRUE(std::isnan(e.peak_change));
            EXPECT_GT(std::fabs(m.summary.offset - reference.summary.offset), 0.0);  // the case still tests
        }
    }
}

// What the JSON and the text print: coupling.error_estimate's three values and error_estimate.gamma, the estimate's;
// at Johnson's level (and for the paper's problem) gamma's estimate is |gamma_0n| and coupling has no error_estimate.
TEST(CouplingEstimates, Printed) {
    scene s = read_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml");
    s.materials.coupling = coupling_level::full;
    s.solver.n = 64;
    const scene_point full = solve_point(s, -0.75 * s.friction);
    ASSERT_TRUE(full.estimate && full.estimate->coupling);
    const coupling_values& e = *full.estimate->coupling;
    const nlohmann::json j = to_json(full.report());
    const nlohmann::json& printed = j.at("coupling").at("error_estimate");
    EXPECT_EQ(printed.at("offset_e").get<double>(), e.offset);
    EXPECT_EQ(printed.at("hertz_load_ratio_johnson").get<double>(), e.lambda_johnson);
    EXPECT_TRUE(printed.at("peak_pressure_change").is_null());
    EXPECT_TRUE(j.at("error_estimate").at("gamma").is_null());
    std::ostringstream text;
    write_summary(text, full.report());
    for (const double x : {e.offset, e.lambda_johnson})
        EXPECT_NE(text.str().find(shortest(x)), std::string::npos) << shortest(x) << "\n" << text.str();
    EXPECT_NE(text.str().find("gamma_0n none"), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("peak pressure change none"), std::string::npos) << text.str();

    s.materials.coupling = coupling_level::johnson;
    const scene_point johnson = solve_point(s, -0.75 * s.friction);
    ASSERT_TRUE(johnson.estimate);
    EXPECT_FALSE(johnson.estimate->coupling);
    const nlohmann::json jj = to_json(johnson.report());
    EXPECT_EQ(jj.at("error_estimate").at("gamma").get<double>(), std::fabs(jj.at("gamma").get<double>()));
    EXPECT_FALSE(jj.at("coupling").contains("error_estimate"));
}
