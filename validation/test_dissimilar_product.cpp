// Dissimilar rollers solved by the product (docs/formulation.md section 8, Johnson's approximation):
//   beta_D = 0 is the paper's problem by exactly the same calls, at both coupling levels, for every
//   method, smooth and rough (8(d)); equal materials written per cylinder are the one-material scene.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/problems/contact.hpp"

using namespace roughroll;

namespace {

roughness rough_scene() {
    // Fig. 2(a)-like: a tangential and a normal layer on cylinder 1, unequal kernels.
    return roughness{{{1.0, 0.5}, {0.5, 2.0}}, {}};
}

}  // namespace

// 8(d): beta_D = 0, either coupling level, is today's problem: the same numbers to the bit for
// every method, smooth and rough, at loads of both signs and at the special loads.
TEST(DissimilarProduct, BetaZeroIsTodaysProblemForEveryMethod) {
    for (const roughness& r : {roughness{}, rough_scene()}) {
        for (method how : {method::paper, method::product, method::extrapolated, method::one_parameter}) {
            const solver_options options{how == method::one_parameter ? 64 : 32, how};
            for (const coupling_level level : {coupling_level::johnson, coupling_level::full}) {
                contact today(r, 0.3, options);
                contact zero(r, 0.3, options, dissimilar{0.0, level});
                EXPECT_EQ(today.normal().lambda, zero.normal().lambda);
                for (double Q : {-0.2, 0.0, 0.1, 0.3}) {
                    const tangential_solution a = today.point(Q), b = zero.point(Q);
                    EXPECT_EQ(a.xi, b.xi) << to_string(how) << " Q = " << Q;
                    EXPECT_EQ(a.c0, b.c0) << to_string(how) << " Q = " << Q;
                    EXPECT_EQ(a.start, b.start);
                    const auto ea = today.estimate(a), eb = zero.estimate(b);
                    ASSERT_EQ(ea.has_value(), eb.has_value());
                    if (ea) {
                        EXPECT_EQ(ea->xi, eb->xi);
                    }
                }
            }
        }
    }
}

// 8(a), 8(d): equal materials per cylinder (beta_D = 0, C = 2 (1 - nu)/mu) give the one-material
// scene's point to rounding, smooth and with a layer, in SI units too.
TEST(DissimilarProduct, EqualMaterialsPerCylinderAreTheOneMaterialScene) {
    const std::string common = "R1 = 0.05\nR2 = 0.05\nP2 = 1e5\nfriction = 0.3\nQ = 0.1\n[solver]\nn = 32\n";
    const std::string layer = "[cylinder1.tangential]\nk = 4e14\nt = 1.5e6\n";
    for (const std::string& rough : {std::string(), layer}) {
        const scene one = parse_scene("E = 208e9\nnu = 0.3\n" + common + rough, "one.toml");
        const scene pair = parse_scene(common + rough +
                                           "[cylinder1]\nshear_modulus = 80e9\npoisson = 0.3\n"
                                           "[cylinder2]\nshear_modulus = 80e9\npoisson = 0.3\n",
                                       "pair.toml");
        ASSERT_EQ(pair.materials.beta_d, 0.0);
        const scene_point a = solve_point(one, std::nullopt), b = solve_point(pair, std::nullopt);
        EXPECT_NEAR(a.solution.xi, b.solution.xi, 1e-13);
        EXPECT_NEAR(a.solution.c0, b.solution.c0, 1e-12);
        const auto sa = a.report().si, sb = b.report().si;
        ASSERT_TRUE(sa && sb);
        EXPECT_NEAR(sa->xi1, sb->xi1, 1e-12 * std::fabs(sa->xi1));
        EXPECT_NEAR(sa->a, sb->a, 1e-13 * sa->a);
    }
}
