// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 10: an error estimate that never under-reports. Over a grid of stiff layers (T up to
// 1e6, A from 1e-3 to 30, on either cylinder, in either direction, so that the kernels are
// unequal), the unequal-kernel scene of data/, and loads from near full stick to near gross
// sliding (Q/f from 1e-9 to 1 - 1e-15), every method at a coarse n either refuses the point
// (resolution_error) or reports estimates of P_H/P2, c0 and xi that are not below the
// difference from the same method at 4n (2n where 4n's Brent search meets a singular system).
// The finer solution is a second, independent computation: no value of the coarse one enters it.
// Coarse n = 32 keeps the finer solutions affordable (n = 128): the levels of the estimates
// are then 8, 16, 32, far from the asymptotic range for many of these layers, which is
// where an estimate is tempted to under-report.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/point_estimate.hpp"

using namespace roughroll;

namespace {
constexpr double friction = 0.3;
const double loads[] = {1e-9, 1e-6, 0.5, 1.0 - 1e-9, 1.0 - 1e-15};  // Q/f

struct layer_scene {
    std::string name;
    roughness surfaces;
};

std::vector<layer_scene> scenes() {
    std::vector<layer_scene> out;
    const char* where[] = {"cyl1_normal", "cyl2_normal", "cyl1_tangential", "cyl2_tangential"};
    for (double T : {1e2, 1e6})
        for (double A : {1e-3, 1.0, 30.0})
            for (int w = 0; w < 4; ++w) {
                roughness r;
                roughness_term& layer = w == 0   ? r.cylinder1.normal
                                        : w == 1 ? r.cylinder2.normal
                                        : w == 2 ? r.cylinder1.tangential
                                                 : r.cylinder2.tangential;
                layer = {T, A};
                char name[64];
                std::snprintf(name, sizeof name, "T%g_A%g_%s", T, A, where[w]);
                out.push_back({name, r});
            }
    roughness u;  // data/unequal-kernels.toml
    u.cylinder1.tangential = {1.0, 0.5};
    u.cylinder1.normal = {0.5, 1.0};
    u.cylinder2.tangential = {0.3, 2.0};
    u.cylinder2.normal = {0.8, 0.5};
    out.push_back({"unequal_kernels", u});
    roughness e;  // Fig. 2a, curve 3
    e.cylinder1.tangential = e.cylinder1.normal = {1.0, 0.5};
    out.push_back({"fig2a_T1", e});
    return out;
}

struct tally {
    int checked = 0, refused = 0, flagged = 0;
};

// Every load of every scene for one method: honest or refused.
tally honest_or_refused(method how, int n, int fine_n) {
    tally t;
    for (const layer_scene& sc : scenes()) {
        std::optional<contact> coarse, fine;  // fine: rebuilt per load (cheap next to its points)
        try {
            coarse.emplace(sc.surfaces, friction, solver_options{n, how});
        } catch (const error&) {  // resolution_error, or a singular system: exit 2 either way
            t.refused += static_cast<int>(std::size(loads));
            continue;
        }
        for (double ratio : loads) {
            const double Q = ratio * friction;
            std::optional<error_estimate> e;
            tangential_solution s{};
            try {
                s = coarse->point(Q);
                e = coarse->estimate(s);
            } catch (const error&) {
                ++t.refused;
                continue;
            }
            SCOPED_TRACE(sc.name + ", " + to_string(how) + ", Q/f = " + std::to_string(ratio));
            if (!s.checks.hold()) {
                // A flagged point is not the model's solution: no level difference bounds its error.
                EXPECT_FALSE(e.has_value()) << "an estimate on a point whose checks fail";
                ++t.flagged;
                continue;
            }
            EXPECT_TRUE(e.has_value()) << "neither an estimate nor a refusal";
            if (!e) continue;
            // The finer solution at fine_n, or at fine_n/2 (at least 2n) where the
            // Brent search at fine_n meets a system singular to working precision (the
            // one-parameter limit very near gross sliding: a refusal there, not a number).
            // The finer solution on the same zone path as s (docs/formulation.md section 7): the
            // general search where s came from it, else the paper's single zone. Near gross
            // sliding the search can fail at one n and succeed at another; the point is then
            // reported on the single zone with its checks failed (flagged), and its estimate is
            // that of the single-zone problem, which is what it must bound.
            const zone_search path = s.layout.general() ? zone_search::general : zone_search::single;
            std::optional<tangential_solution> sf;
            for (int m : {fine_n, fine_n / 2}) {
                try {
                    fine.emplace(sc.surfaces, friction, solver_options{m, how, path});
                    sf = fine->point(Q);
                    break;
                } catch (const error& x) {
                    if (m == fine_n / 2) ADD_FAILURE() << "the finer solution is refused: " << x.what();
                }
            }
            if (!sf) continue;
            ++t.checked;
            EXPECT_LE(std::fabs(coarse->normal().lambda - fine->normal().lambda), e->lambda)
                << "P_H/P2 " << coarse->normal().lambda << " against " << fine->normal().lambda << " (" << e->against
                << ")";
            EXPECT_LE(std::fabs(s.c0() - sf->c0()), e->c0)
                << "c0 " << s.c0() << " against " << sf->c0() << " (" << e->against << ")";
            EXPECT_LE(std::fabs(s.xi - sf->xi), e->xi)
                << "xi " << s.xi << " against " << sf->xi << " (" << e->against << ")";
        }
    }
    std::printf("%s: %d points checked, %d refused, %d flagged (no estimate)\n", to_string(how).c_str(), t.checked,
                t.refused, t.flagged);
    return t;
}
}  // namespace

// Each method must answer a fair share of the grid: an estimator that refuses everything
// would pass the comparison trivially. A flagged point (checks failed) is answered, without an
// estimate.
int answered(const tally& t) { return t.checked + t.flagged; }
TEST(HonestEstimates, Product) { EXPECT_GE(answered(honest_or_refused(method::product, 32, 128)), 60); }
TEST(HonestEstimates, Extrapolated) { EXPECT_GE(answered(honest_or_refused(method::extrapolated, 32, 128)), 60); }
TEST(HonestEstimates, Paper) { EXPECT_GE(answered(honest_or_refused(method::paper, 32, 128)), 40); }
TEST(HonestEstimates, OneParameter) { EXPECT_GE(answered(honest_or_refused(method::one_parameter, 32, 128)), 40); }

// The case that set the bounded rule's floor of twice the last difference: product integration
// at n = 96 on a normal layer T = 1e6, A = 30, rho = 3 over 24, 48, 96, and the error 1.8 times
// |d2| against n = 384. Its inequalities fail there (the checks report it), so contact::estimate
// gives no estimate for the point; the rule itself is checked on the levels' values.
TEST(HonestEstimates, StiffNormalLayerSlowsDown) {
    roughness r;
    r.cylinder2.normal = {1e6, 30.0};
    const double Q = 0.5 * friction;
    contact at96(r, friction, solver_options{96, method::product});
    const tangential_solution s = at96.point(Q);
    EXPECT_FALSE(s.checks.hold());
    try {  // refused (level 192 shows c0 moving by 4e-3), or answered without an estimate
        EXPECT_FALSE(at96.estimate(s).has_value()) << "a flagged point carries no estimate";
    } catch (const resolution_error&) {
    }
    contact at24(r, friction, solver_options{24, method::product}),
        at48(r, friction, solver_options{48, method::product});
    contact fine(r, friction, solver_options{384, method::product});
    const tangential_solution s24 = at24.point(Q), s48 = at48.point(Q), sf = fine.point(Q);
    int bounded = 0;
    auto check = [&bounded](const three_levels& v, double finer, const char* what) {
        const error_bound b = bound_error(v, 4, reported_value{2, false}, 0.0);
        ASSERT_TRUE(b.resolved) << what;
        bounded += !b.asymptotic;
        EXPECT_LE(std::fabs(v.finest - finer), b.value) << what << ": ratio " << b.ratio;
    };
    check({at24.normal().lambda, at48.normal().lambda, at96.normal().lambda}, fine.normal().lambda, "P_H/P2");
    check({s24.c0(), s48.c0(), s.c0()}, sf.c0(), "c0");
    check({s24.xi, s48.xi, s.xi}, sf.xi, "xi");
    EXPECT_GT(bounded, 0) << "the case of the bounded rule";
}

namespace {
// A point (roughness r, friction f, load Q) and its reference: c0 and xi of a finer route a, and
// their distances to those of a second finer route b (the spread).
struct referenced_point {
    roughness r;
    double f, Q;
    double c0, xi, spread_c0, spread_xi;
};
// r as roughness{{tangential, normal} of cylinder 1, {tangential, normal} of cylinder 2}, each
// term {T, A} ({} is a smooth surface in that direction).
referenced_point two_routes(const roughness& r, double f, double Q, solver_options a, solver_options b) {
    contact ca(r, f, a), cb(r, f, b);
    const tangential_solution sa = ca.point(Q), sb = cb.point(Q);
    return {r, f, Q, sa.c0(), sa.xi, std::fabs(sa.c0() - sb.c0()), std::fabs(sa.xi - sb.xi)};
}
// Whether the contact at options o answers the point honestly: refused (resolution_error), or an
// estimate of c0 and xi that is not below the distance to the reference (the distance reduced by
// the two routes' own disagreement, so that only a true under-report fails).
bool honest_or_refused_at(const referenced_point& ref, solver_options o) {
    SCOPED_TRACE(to_string(o.how) + " at n = " + std::to_string(o.nodes()));
    try {
        contact c(ref.r, ref.f, o);
        const tangential_solution s = c.point(ref.Q);
        const std::optional<error_estimate> e = c.estimate(s);
        if (!e) {
            EXPECT_FALSE(s.checks.hold()) << "neither an estimate nor a refusal";
            return false;
        }
        std::printf("%s n = %d: c0 %.16g +- %.2g (reference %.16g, spread %.2g), xi %.16g +- %.2g (%s)\n",
                    to_string(o.how).c_str(), o.nodes(), s.c0(), e->c0, ref.c0, ref.spread_c0, s.xi, e->xi,
                    e->against.c_str());
        EXPECT_LE(std::fabs(s.c0() - ref.c0) - ref.spread_c0, e->c0) << e->against;
        EXPECT_LE(std::fabs(s.xi - ref.xi) - ref.spread_xi, e->xi) << e->against;
        return true;
    } catch (const resolution_error& x) {
        std::printf("%s n = %d: refused: %s\n", to_string(o.how).c_str(), o.nodes(), x.what());
        return false;
    }
}
}  // namespace

// Issue 23, 1: c0 near full stick, where 1 - c0 = 3.3e-10 is the quantity that converges (at
// order 2 here) and levels 8, 16 agree by chance to 1.4e-13 while n = 16 is 4.8e-12 (1.4 % of
// 1 - c0) from the limit: the three levels read as "bounded" and level 2n must confirm them.
// The estimate had been 3.3e-13 for extrapolated at n = 16.
TEST(HonestEstimates, NearFullStickConfirmedOnAFourthLevel) {
    const referenced_point ref = two_routes(roughness{{{}, {0.411, 0.00071}}, {{0.001, 0.001}, {10.0, 0.3}}}, 0.05,
                                            5e-11, solver_options{768, method::product},
                                            solver_options{512, method::extrapolated});
    EXPECT_LT(ref.spread_c0, 1e-13);
    honest_or_refused_at(ref, solver_options{16, method::extrapolated});
    for (int n : {16, 32, 64}) honest_or_refused_at(ref, solver_options{n, method::product});
}

// Issue 23, 1: the one-parameter limit at its default n = 128 with thin layers (2T/A^2 = 0.002):
// its c0 error passes near zero at n = 64 (+1.4e-7 at 64, +3.3e-7 at 96, +1.6e-7 at 128,
// 1.2e-8 at 256), so 32, 64, 128 read as order 2 with an estimate of 1.4e-8, 11 times below the
// error. Level 2n confirms every one-parameter estimate. References: n = 768 and 512.
TEST(HonestEstimates, OneParameterConfirmedOnAFourthLevel) {
    const referenced_point ref = two_routes(roughness{{{0.001, 1.0}, {0.001, 1.0}}, {}}, 0.3, 0.15,
                                            solver_options{768, method::one_parameter},
                                            solver_options{512, method::one_parameter});
    for (int n : {64, 128, 256}) honest_or_refused_at(ref, solver_options{n, method::one_parameter});
}

// Issue 23, 1: a point whose checks fail had carried an estimate as if it bounded its error (the
// one-parameter limit with eps1 = 2 T/A^2 = 0.1 tangential, eps2 = 0.3 normal at Q/f = 0.9999,
// n = 128: xi +- 1.3e-5, while the general zones at n = 256 are 7.2e-4 away). Now the point
// reports no estimate, and says why, in the JSON and the text.
TEST(HonestEstimates, FlaggedPointSaysWhyItHasNoEstimate) {
    const scene sc = parse_scene(
        "friction = 0.3\nQ = 0.29997\n[cylinder1.tangential]\nT = 0.05\nA = 1\n"
        "[cylinder1.normal]\nT = 0.15\nA = 1\n[solver]\nmethod = \"one-parameter\"\nn = 128\n",
        "flagged.toml");
    const scene_point p = solve_point(sc, std::nullopt);
    ASSERT_FALSE(p.solution.checks.hold());
    EXPECT_FALSE(p.estimate.has_value());
    const nlohmann::json j = to_json(p.report());
    EXPECT_TRUE(j["error_estimate"].is_null());
    ASSERT_TRUE(j["error_estimate_absent"].is_string());
    EXPECT_NE(j["error_estimate_absent"].get<std::string>().find("checks (3.3)-(3.4) fail"), std::string::npos);
    std::ostringstream text;
    write_summary(text, p.report());
    EXPECT_NE(text.str().find("error estimate      none: the checks (3.3)-(3.4) fail"), std::string::npos)
        << text.str();
}

// Session 25 audit F3: the general zone search's stick start was printed (text, JSON, curve) without an estimate, while
// c0 beside it had one: the one-parameter point near gross sliding (eps1 = 0.1, eps2 = 0.3, Q/f = 0.9999) answered at
// n = 256 with its start 5.6e-6 from n = 1000's, and the one-parameter point with beta_D = 0.1 braked at Q/f = -0.5 3.4e-6
// off. Now the start is estimated by c0's rule (docs/formulation.md 7(e) "The start's estimate"): level n's difference
// from level n/2 ("against" n/2) and the floor, the one-parameter limit's confirmed on 2n, 'extrapolated' against its
// companion n/2. Checked (i) against a stored reference (n = 1000 for the one-parameter scenes, n = 512 'extrapolated'
// for data/leading-slip.toml's general zone; solved once, at 68a7c7d): the estimate holds the distance plus the
// reference's own estimate (measured estimate / that sum: 1.94, 1.96, 3.8); (ii) against the point at n/2 solved alone
// (the same zones): the estimate holds at least their difference, so dropping the start's row or halving its estimate
// fails here (the differences 4.5e-6, 3.4e-6, 3.1e-9 against floors below 1e-9). About 7 s CPU.
TEST(HonestEstimates, GeneralZoneStartCarriesItsEstimate) {
    const std::string near_sliding =
        "friction = 0.3\nQ = 0.29997\n[cylinder1.tangential]\nT = 0.05\nA = 1\n"
        "[cylinder1.normal]\nT = 0.15\nA = 1\n[solver]\nmethod = \"one-parameter\"\n";
    const std::string braked =
        "friction = 0.05\nQ = -0.025\nbeta_d = 0.1\n[cylinder1.tangential]\nT = 0.1\nA = 1\n"
        "[cylinder1.normal]\nT = 0.1\nA = 1\n[solver]\nmethod = \"one-parameter\"\n";
    const std::string leading_slip =  // data/leading-slip.toml, the search forced
        "friction = 0.3\nQ = 0.2997\n[cylinder1.tangential]\nT = 3.5613\nA = 1.65266\n[cylinder1.normal]\n"
        "T = 0.112749\nA = 1.75668\n[cylinder2.tangential]\nT = 3.33641\nA = 6.08721\n[cylinder2.normal]\n"
        "T = 0.0338885\nA = 1.17053\n[solver]\nzones = \"general\"\n";
    struct at_n {
        std::string text;
        int n;
        double reference, reference_estimate;  // the start at the reference's n, and its own estimate
    };
    for (const at_n& c : {at_n{near_sliding, 512, -0.9785977006007887, 1.1837359088298435e-06},
                          at_n{braked, 512, -0.8402211927904901, 8.912405943469425e-07},
                          at_n{leading_slip, 128, -0.9858629065794314, 7.763402507306271e-10}}) {
        SCOPED_TRACE(c.text.substr(0, 30) + " n = " + std::to_string(c.n));
        const scene_point p = solve_point(parse_scene(c.text + "n = " + std::to_string(c.n) + "\n", "s.toml"), std::nullopt);
        const scene_point half =
            solve_point(parse_scene(c.text + "n = " + std::to_string(c.n / 2) + "\n", "s.toml"), std::nullopt);
        ASSERT_TRUE(p.solution.layout.general());
        ASSERT_TRUE(same_zones(p.solution.layout, half.solution.layout));
        ASSERT_TRUE(p.estimate.has_value());
        EXPECT_GE(p.estimate->start, std::fabs(p.solution.start() - c.reference) + c.reference_estimate);
        const double change = std::fabs(p.solution.start() - half.solution.start());
        EXPECT_GT(change, 1e-9);  // above the floor: a halved estimate falls below it
        EXPECT_GE(p.estimate->start, change);
        // printed beside c0's, in the JSON and the text
        const nlohmann::json j = to_json(p.report());
        EXPECT_EQ(j["error_estimate"]["stick_start"].get<double>(), p.estimate->start);
        std::ostringstream text;
        write_summary(text, p.report());
        EXPECT_NE(text.str().find(", stick start " + shortest(p.estimate->start) + ", xi "), std::string::npos)
            << text.str();
    }
}

// Five zones (free rolling of data/aluminium-on-steel.toml, Johnson's level, f = 0.05): the second stick zone's ends are
// printed among the zones, and c0's and the start's estimates are each the larger of the two zones' (zone_ends_table);
// the text says so (session 25 audit F3: they read as the first zone's alone).
TEST(HonestEstimates, FiveZonesTextNamesTheSecondZonesEnds) {
    scene sc = read_scene(std::string(ROUGHROLL_DATA) + "/aluminium-on-steel.toml");
    override_solver(sc, 128, std::nullopt);
    const scene_point p = solve_point(sc, load_given(0.0));
    ASSERT_EQ(p.solution.layout.stick_zones(), 2u);
    ASSERT_TRUE(p.estimate.has_value());
    std::ostringstream text;
    write_summary(text, p.report());
    EXPECT_NE(text.str().find(", c0 and the second stick zone's end " + shortest(p.estimate->c0) +
                              ", stick start and the second stick zone's start " + shortest(p.estimate->start) +
                              ", xi "),
              std::string::npos)
        << text.str();
}

// Two under-reports of the random-scene study (validation/estimate_grid.py, seed 1), each failing
// on the previous rule. (i) paper at n = 16 near gross sliding on the general zone search: c0's
// ratio 50 over 4, 8, 16 read as order 2 (estimate 8.5e-8), then a sign change (error 5.1e-7): an
// observed order far above the method's is confirmed on 2n as well. (ii) extrapolated at n = 32
// near full stick: xi's levels show order 4 over 8, 16, 32, and the error changes sign beyond 32,
// so Richardson's value moves away from the limit (error 6.3e-14 against an estimate of 5.0e-14,
// its shift from level 32): its estimate is twice the shift.
TEST(HonestEstimates, RandomSceneUnderReports) {
    const referenced_point paper_16 =
        two_routes(roughness{{{27.28, 0.1198}, {0.0236, 0.7614}}, {}}, 0.114, 0.11399999999863202,
                   solver_options{512, method::product, zone_search::general},
                   solver_options{256, method::extrapolated, zone_search::general});
    honest_or_refused_at(paper_16, solver_options{16, method::paper, zone_search::general});
    const referenced_point extrapolated_32 =
        two_routes(roughness{{{0.01045, 0.02533}, {}}, {{0.006697, 1.974}, {0.00266, 0.003794}}}, 0.1055,
                   0.0001459065, solver_options{512, method::product}, solver_options{256, method::extrapolated});
    EXPECT_TRUE(honest_or_refused_at(extrapolated_32, solver_options{32, method::extrapolated}));
}

// The one estimate rule (problems/point_estimate.hpp) on made-up levels of product integration at
// n = 64 (16, 32, 64): xi and c0 that do not converge visibly there (d1 = d2), and at order 4 over
// 32, 64, 128. Level 2n is solved once for both; a point whose checks fail gets no second chance,
// and the refusal names the structure; full coupling bounds by twice the larger level change.
TEST(HonestEstimates, OneRuleForEveryStructure) {
    const auto level = [](double v) {
        tangential_solution t{};
        t.xi = v;
        t.layout = one_stick_zone(-1.0, v);  // c0 = v
        return estimate_level{t, 1.0};
    };
    const std::array<estimate_level, 3> levels{level(1.0), level(2.0), level(3.0)};
    const std::vector<estimated_quantity> table{
        {"xi", value_xi, 0.0, 0.0, false, true, &error_estimate::xi},
        {"c0", value_c0, 0.0, 0.0, false, true, &error_estimate::c0}};
    int solved = 0;
    const auto finer = [&]() -> std::optional<estimate_level> {
        ++solved;
        return level(3.0 + 1.0 / 16.0);
    };
    estimate_point p{method::product, 64, 2, estimate_structure::paper, false, true, "Q", 0.25};

    const error_estimate e = estimate_from_levels(table, levels, finer, p);
    EXPECT_EQ(solved, 1) << "level 2n is solved once for every quantity that asks for it";
    const error_bound b = bound_error({2.0, 3.0, 3.0 + 1.0 / 16.0}, 4, reported_value{1, false}, 0.0);
    ASSERT_TRUE(b.resolved);
    EXPECT_EQ(e.xi, b.value);
    EXPECT_EQ(e.c0, b.value);
    EXPECT_NE(e.against.find("n/2 (levels n/4, n/2, n; n/2, n, 2n where n/4 fell short"), std::string::npos)
        << e.against;

    p.structure = estimate_structure::dissimilar;
    p.checks_hold = false;
    solved = 0;
    try {
        estimate_from_levels(table, levels, finer, p);
        ADD_FAILURE() << "levels that do not converge visibly must refuse the point";
    } catch (const resolution_error& why) {
        EXPECT_EQ(std::string(why.what())
                      .rfind("no honest error estimate for method 'product' at n = 64 (dissimilar "
                             "rollers): xi does not converge visibly over the levels n = 16, 32, 64",
                             0),
                  0u)
            << why.what();
    }
    EXPECT_EQ(solved, 0) << "no second chance for a point whose checks fail";

    // Full coupling (8(e), 8(q) "Changes that do not fall"): equal changes (d1 = d2) show no convergence and refuse;
    // changes falling by 4 per doubling give twice the larger; by 4/3 the geometric rest 2 |d2|/(d1/d2 - 1).
    p.structure = estimate_structure::full_coupling;
    try {
        estimate_from_levels(table, levels, finer, p);
        ADD_FAILURE() << "full coupling's levels whose changes do not fall must refuse the point";
    } catch (const resolution_error& why) {
        EXPECT_NE(std::string(why.what()).find("xi does not converge visibly over the levels n = 16, 32, 64"),
                  std::string::npos)
            << why.what();
    }
    const auto full_estimate = [&](double coarsest, double middle, double finest) {
        return estimate_from_levels(table, {level(coarsest), level(middle), level(finest)}, finer, p);
    };
    const error_estimate c = full_estimate(1.0, 3.0, 3.5);
    EXPECT_EQ(c.xi, 4.0);  // twice the larger of |3 - 1| and |3.5 - 3|
    EXPECT_TRUE(c.bounded);
    EXPECT_EQ(c.against.rfind("levels n/4, n/2, n (dissimilar rollers, full coupling", 0), 0u) << c.against;
    EXPECT_DOUBLE_EQ(full_estimate(1.0, 2.0, 2.75).xi, 2.0 * 0.75 / (1.0 / 0.75 - 1.0));  // 4.5, not 2
}

// Level 2n, once solved for one quantity, confirms every other (point_estimate.cpp): made-up levels
// of product at n = 64 where c0 shows order 4 over 16, 32, 64 (differences 1.6, 0.1: ratio 16) and
// xi only 2 (so xi asks for level 128); over 32, 64, 128 c0 alternates and grows (0.1, -0.2), which
// refuses the point. The previous rule checked c0 on 128 only where c0 itself asked for it.
TEST(HonestEstimates, FourthLevelConfirmsEveryQuantity) {
    const auto level = [](double xi, double c0) {
        tangential_solution t{};
        t.xi = xi;
        t.layout = one_stick_zone(-1.0, c0);
        return estimate_level{t, 1.0};
    };
    const std::array<estimate_level, 3> levels{level(1.0, 0.0), level(2.0, 1.6), level(2.5, 1.7)};
    const std::vector<estimated_quantity> table{
        {"c0", value_c0, 0.0, 0.0, false, true, &error_estimate::c0},
        {"xi", value_xi, 0.0, 0.0, false, true, &error_estimate::xi}};
    double finer_c0 = 1.5;
    int solved = 0;
    const auto finer = [&]() -> std::optional<estimate_level> {
        ++solved;
        return level(2.6, finer_c0);
    };
    const estimate_point p{method::product, 64, 2, estimate_structure::paper, false, true, "Q", 0.25};
    try {
        estimate_from_levels(table, levels, finer, p);
        ADD_FAILURE() << "c0 alternating and growing on n/2, n, 2n must refuse the point";
    } catch (const resolution_error& why) {
        EXPECT_NE(std::string(why.what()).find("c0 does not converge visibly over n = 32, 64, 128"), std::string::npos)
            << why.what();
    }
    EXPECT_EQ(solved, 1);
    // Where c0 converges on 32, 64, 128 too, its estimate is the larger of the two.
    finer_c0 = 1.7 + 0.1 / 16.0;
    const error_estimate e = estimate_from_levels(table, levels, finer, p);
    const error_bound from_16 = bound_error({0.0, 1.6, 1.7}, 4, reported_value{2, false}, 0.0);
    const error_bound from_32 = confirm_error({1.6, 1.7, finer_c0}, 4, false, 0.0);
    ASSERT_TRUE(from_16.resolved && from_32.resolved);
    EXPECT_EQ(e.c0, std::max(from_16.value, from_32.value));
    EXPECT_NE(e.against.find("confirmed on n/2, n, 2n"), std::string::npos) << e.against;
}

// The two under-reports of the estimate grid's seed 2 (validation/estimate_grid_cases.txt, tag
// grid-s2-under; docs/performance.md "The estimate grid re-run"), references product n = 1000 and
// extrapolated n = 512. (i) product at n = 16 near full stick: c0 +- 1.3e-12 from 4, 8, 16 (ratio
// 13.9), 2.0e-12 from both routes; level 32 was solved for P_H/P2 only, and c0 over 8, 16, 32
// alternates and grows: refused now. (ii) product at n = 32 near gross sliding (1 - |Q|/f = 8.8e-10):
// xi +- 6.7e-16, 1.1e-15 from both routes: the zone's root of Q(c0) = f + rho int q carries ulp(f),
// which moves xi by eps f/(pi rho) (docs/formulation.md 7(d)), 4.4e-14 here.
TEST(HonestEstimates, EstimateGridSeed2UnderReports) {
    const solver_options product_1000{1000, method::product}, extrapolated_512{512, method::extrapolated};
    const referenced_point full_stick = two_routes(roughness{{{}, {0.001466, 0.09828}}, {{}, {13.34, 0.1058}}}, 0.2675,
                                                   1.0847125e-10, product_1000, extrapolated_512);
    EXPECT_LT(full_stick.spread_c0, 1e-13);
    honest_or_refused_at(full_stick, solver_options{16, method::product});
    const referenced_point gross_sliding = two_routes(roughness{{{0.06776, 2.548}, {}}, {{0.06183, 0.02073}, {}}},
                                                      0.01883, 0.0188299999834296, product_1000, extrapolated_512);
    EXPECT_LT(gross_sliding.spread_xi, 1e-16);
    EXPECT_TRUE(honest_or_refused_at(gross_sliding, solver_options{32, method::product}));
}

// The zone ends' floor is their levels' Newton resolution (docs/formulation.md 8(q), "The estimates' floor of the zone
// ends"): made-up levels of Johnson's five zones with the stick start's changes of free rolling over n = 250, 500, 1000
// (-4.8e-12, 6.55e-11, which refused the point at n = 1000 before). Where every level met Newton's tolerance the floor
// is zone_ends_floor's 2 zone_end_resolution, and those changes are no convergence: refused. Where level n stopped at its
// rounding 4e-9 (eps/rcond of its zone systems), the floor carries it: answered, the estimate at least twice that
// rounding, so a level's distance from its root (up to the rounding) is inside it.
TEST(HonestEstimates, ZoneEndsFloorIsTheLevelsNewtonResolution) {
    const auto level = [](double start, double resolution) {
        tangential_solution t{};
        t.layout = one_stick_zone(start, 0.4953535486);
        t.ends_resolution = resolution;
        return estimate_level{t, 1.0};
    };
    const double s = -0.6891857193;
    const double floor = 2.0 * zone_end_resolution;
    const std::vector<estimated_quantity> table{
        {"the stick zone's start", value_start, floor, floor, false, true, &error_estimate::start, true}};
    const auto finer = []() -> std::optional<estimate_level> { return std::nullopt; };
    const estimate_point p{method::product, 1000, 2, estimate_structure::dissimilar, false, true, "Q", 0.0};
    const std::array<estimate_level, 3> tolerance{level(s, zone_end_resolution),
                                                  level(s - 4.8e-12, zone_end_resolution),
                                                  level(s - 4.8e-12 + 6.55e-11, zone_end_resolution)};
    EXPECT_THROW(estimate_from_levels(table, tolerance, finer, p), resolution_error);
    EXPECT_EQ(newton_floor_excess({&tolerance[0].solution, &tolerance[1].solution, &tolerance[2].solution}), 0.0)
        << "levels at Newton's tolerance: zone_ends_floor's floor, bit for bit";
    const std::array<estimate_level, 3> rounded{level(s, zone_end_resolution), level(s - 4.8e-12, 8.6e-10),
                                                level(s - 4.8e-12 + 6.55e-11, 4e-9)};
    const error_estimate e = estimate_from_levels(table, rounded, finer, p);
    EXPECT_GE(e.start, 2.0 * 4e-9);
    EXPECT_LE(e.start, 2.0 * 4e-9 + floor + 6.55e-11);
}

// Johnson's five zones of free rolling (data/aluminium-on-steel.toml, Q = 0) at n = 1000, whose Newton stops at its
// rounding floor (eps/rcond 4e-9 of the zone systems): refused before ("the stick zone's start does not converge
// visibly over the levels n = 250, 500, 1000", changes -4.8e-12, 6.55e-11, against a floor of 2e-11), answered with the
// levels' resolution in the floor. Against the point at n = 512 (levels 128, 256, 512; level 512 at its rounding
// 9.2e-10), a second solution at other nodes: every zone end within the sum of both estimates.
TEST(HonestEstimates, JohnsonFiveZonesAnsweredAtTheirRoundingFloor) {
    const auto at = [](int n) {
        scene sc = read_scene(ROUGHROLL_DATA "/aluminium-on-steel.toml");
        override_solver(sc, n, std::nullopt);
        return solve_point(sc, 0.0);
    };
    std::optional<scene_point> fine, coarse;
    try {
        fine = at(1000);
        coarse = at(512);
    } catch (const resolution_error& e) {
        FAIL() << e.what();
    }
    ASSERT_TRUE(fine->estimate && coarse->estimate);
    const tangential_solution &a = fine->solution, &b = coarse->solution;
    ASSERT_EQ(a.layout.stick_zones(), 2);
    EXPECT_GT(a.ends_resolution, zone_end_resolution) << "Newton at n = 1000 stopped at its rounding";
    const error_estimate &ea = *fine->estimate, &eb = *coarse->estimate;
    std::printf(
        "n 1000 - 512: start %.3g (estimates %.3g, %.3g), c0 %.3g (%.3g, %.3g), start2 %.3g, end2 %.3g; "
        "resolution %.3g\n",
        a.start() - b.start(), ea.start, eb.start, a.c0() - b.c0(), ea.c0, eb.c0, a.start2() - b.start2(),
        a.end2() - b.end2(), a.ends_resolution);
    EXPECT_GE(ea.start, 2.0 * (a.ends_resolution - zone_end_resolution));
    EXPECT_LE(std::fabs(a.start() - b.start()), ea.start + eb.start);
    EXPECT_LE(std::fabs(a.c0() - b.c0()), ea.c0 + eb.c0);
    EXPECT_LE(std::fabs(a.start2() - b.start2()), ea.start + eb.start);
    EXPECT_LE(std::fabs(a.end2() - b.end2()), ea.c0 + eb.c0);
    EXPECT_LE(std::fabs(a.xi - b.xi), ea.xi + eb.xi);
}

// Session 26's audit F1 (docs/performance.md "A fall faster than the order at a zone end"): the rough pair at Johnson's
// level driven at Q/f = 0.9, n = 256 (the default answer): the stick start changes 1.89e-6, then 1.1e-9 over n = 64,
// 128, 256 (ratio 1700: level 128 lies 1.5e-9 from the limit by chance) and the rule read the last change as level
// 256's error, +- 1.45e-9 against 2.63e-9 from n = 768 and 1000 (which agree to 1.8e-11; stored from `point
// data/aluminium-on-steel-rough.toml --Q-over-f 0.9 --n N --json`, session 26). A zone end's estimate is now at least
// nine times the least envelope its change before shows, 9 |d1|/(2^p + 4^p): 6.3e-8. Fails on the rule before. Then the
// rule on made-up levels: ratios 1700 and 60 on c0 of Johnson's level (not xi, an integral, nor the paper's problem, which
// confirms on level 2n).
TEST(HonestEstimates, ZoneEndFallingFasterThanItsOrderIsChance) {
    const double start_768 = -0.9626483378330352, start_1000 = -0.9626483378514137;
    scene sc = read_scene(ROUGHROLL_DATA "/aluminium-on-steel-rough.toml");
    override_solver(sc, 256, std::nullopt);
    const scene_point at = solve_point(sc, 0.9 * sc.friction);
    ASSERT_TRUE(at.estimate.has_value());
    const double distance =
        std::max(std::fabs(at.solution.start() - start_768), std::fabs(at.solution.start() - start_1000));
    std::printf("start %.16f, distance from n = 768/1000 %.3g, estimate %.3g\n", at.solution.start(), distance,
                at.estimate->start);
    ASSERT_GT(distance, 1e-9);  // the point the audit measured
    EXPECT_GE(at.estimate->start, distance + std::fabs(start_768 - start_1000));

    const auto level = [](double v) {
        tangential_solution t{};
        t.xi = v;
        t.layout = one_stick_zone(-1.0, v);  // c0 = v
        return estimate_level{t, 1.0};
    };
    const std::vector<estimated_quantity> table{
        {"xi", value_xi, 0.0, 0.0, false, true, &error_estimate::xi},
        {"c0", value_c0, 0.0, 0.0, false, true, &error_estimate::c0, true}};
    const auto none = []() -> std::optional<estimate_level> { return std::nullopt; };
    const estimate_point p{method::product, 64, 2, estimate_structure::dissimilar, false, true, "Q", 0.25};
    const error_estimate e = estimate_from_levels(table, {level(0.0), level(0.5), level(0.5 + 0.5 / 1700)}, none, p);
    EXPECT_DOUBLE_EQ(e.c0, 9.0 * 0.5 / (16.0 + 256.0));
    EXPECT_EQ(e.xi, (0.5 + 0.5 / 1700) - 0.5);  // the rule's |d2| (asymptotic), no floor
    // Review R15: the floor at every ratio (a max), not only beyond 2^(p+2) = 64: at ratio 60 it is above |d2| = 0.5/60.
    const error_estimate f = estimate_from_levels(table, {level(0.0), level(0.5), level(0.5 + 0.5 / 60)}, none, p);
    EXPECT_DOUBLE_EQ(f.c0, 9.0 * 0.5 / (16.0 + 256.0));
}
