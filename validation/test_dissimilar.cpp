// SPDX-License-Identifier: GPL-3.0-or-later
// Dissimilar rollers (docs/formulation.md section 8), by the independent low-order route only
// (test_zones_low_order.hpp with the beta_D term of Johnson's approximation: pressure
// uncoupled, v = xi - L1[p1] + beta_D p). The product does not solve this problem yet; these
// tests check the derivation of section 8 against its closed forms and limits:
//   beta_D = 0: the existing route, unchanged;
//   f -> 0, Q = 0 (complete slip, 8(f)): -pi xi/(4 beta_D) -> cos(phi)/2 = 0.457386, with
//     2 phi + sin 2 phi = pi/2 (Bentall and Johnson's 0.457 kappa a/R, kappa = 2 beta_D);
//   f -> infinity (no slip, 8(f)): xi -> Q/pi - 4 beta_D/pi^2;
//   rollers exchanged (8(h)): (beta_D, Q) -> (-beta_D, -Q) gives (xi, p1, states) -> -(...);
//   free rolling: the five zones of 8(g), observed;
//   aluminium on steel, f = 0.05, free rolling: CONTACT's published creep.
#include <cmath>
#include <vector>

#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/problems/normal_problem.hpp"
#include "test_zones_low_order.hpp"

using namespace roughroll;

namespace {

// Dundurs' beta_D of 8(a) (Johnson's sign: roller 1 = cylinder1), from shear moduli and
// Poisson's ratios, and the combined compliance C = (1 - nu1)/mu1 + (1 - nu2)/mu2.
double dundurs_beta(double mu1, double nu1, double mu2, double nu2) {
    const double C = (1.0 - nu1) / mu1 + (1.0 - nu2) / mu2;
    return ((1.0 - 2.0 * nu1) / mu1 - (1.0 - 2.0 * nu2) / mu2) / (2.0 * C);
}

// The issue's pair: aluminium (roller 1) on steel.
const double beta_al_st = dundurs_beta(23.0, 0.31, 82.0, 0.28);

// The Bentall-Johnson constant of 8(f), from its defining equation 2 phi + sin 2 phi = pi/2
// (bisection to rounding; the left side is increasing).
double bentall_johnson_constant() {
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (2.0 * mid + std::sin(2.0 * mid) < M_PI_2 ? lo : hi) = mid;
    }
    return 0.5 * std::cos(0.5 * (lo + hi));
}

const normal_solution hertz = hertz_solution(8, method::product);

validation::grid_solution grid(double f, double Q, int N, double beta_d, const kernel& k1 = kernel{},
                               const normal_solution& normal = hertz) {
    return validation::solve_on_grid(normal, k1, f, Q, N, 0, beta_d);
}

std::vector<int> states_of(const validation::grid_solution& g) {
    std::vector<int> out;
    for (const auto& run : g.runs()) out.push_back(run.state);
    return out;
}

}  // namespace

// 8(a): the material pair of the issue, and the sign convention (the more compliant roller in
// the sense of (1 - 2 nu)/mu is roller 1: beta_D > 0; exchanged: the opposite sign).
TEST(Dissimilar, DundursBetaOfTheIssuesPair) {
    EXPECT_NEAR(beta_al_st, 0.143834, 5e-7);
    EXPECT_NEAR(2.0 * beta_al_st, 0.2877, 5e-5);  // CONTACT's kappa for this pair
    EXPECT_DOUBLE_EQ(dundurs_beta(82.0, 0.28, 23.0, 0.31), -beta_al_st);
    EXPECT_EQ(dundurs_beta(50.0, 0.3, 50.0, 0.3), 0.0);
    // An incompressible roller 1 (nu = 1/2) on steel: negative although roller 1 is far softer.
    // (A nearly incompressible one, nu = 0.4999 with mu = 1 MPa, is already positive.)
    EXPECT_GT(dundurs_beta(0.001, 0.4999, 82.0, 0.28), 0.0);
    EXPECT_LT(dundurs_beta(0.001, 0.5, 82.0, 0.28), 0.0);
}

// 8(d): beta_D = 0 is the existing route. The new term is guarded by beta_D != 0, so the default
// call and an explicit 0 run the same arithmetic (compared bit for bit); a tiny beta_D moves xi
// by O(beta_D) only (the term is continuous at 0, not a switch to another route), and at
// beta_D = 0 the route still meets Carter within its order-1 error (as ZonesGridRoute checks).
TEST(Dissimilar, BetaZeroIsTheExistingRouteBitForBit) {
    const kernel k1(std::vector<exponential_term>{{1.0, 0.5}});
    for (const kernel& k : {kernel{}, k1}) {
        for (double Q : {0.0, 0.15, -0.15}) {
            const auto a = validation::solve_on_grid(hertz, k, 0.3, Q, 100);
            const auto b = grid(0.3, Q, 100, 0.0, k);
            EXPECT_EQ(a.xi, b.xi);
            EXPECT_EQ(a.p1, b.p1);
            EXPECT_EQ(a.v, b.v);
            EXPECT_EQ(a.state, b.state);
            const auto c = grid(0.3, Q, 100, 1e-9, k);
            EXPECT_LT(std::fabs(c.xi - a.xi), 1e-8);
            EXPECT_NE(c.xi, a.xi);
        }
    }
    const double f = 0.3, Q = 0.5 * f;
    const double carter = 2.0 * f / M_PI * (1.0 - std::sqrt(1.0 - Q / f));
    EXPECT_NEAR(grid(f, Q, 200, 0.0).xi, carter, 2.0 * 1.2e-4);
}

// 8(f): the f -> 0 limit of free rolling, as the derivation prescribes: the complete-slip
// special case of the grid equations (p1 = f p sgn v, L1[p1] = O(f) dropped). It converges at
// order 1 in h to the closed form -(2/pi) cos(phi) beta_D, i.e. -pi xi/(4 beta_D) -> 0.457386,
// and reproduces the published three digits 0.457. Then the solved creep at finite f moves
// monotonically towards it as beta_D/f grows (5, 10, 20), its distance falling about like f.
TEST(Dissimilar, CompleteSlipLimitIsBentallJohnson) {
    const double constant = bentall_johnson_constant();
    EXPECT_NEAR(constant, 0.457386, 5e-7);
    std::vector<double> bound;
    for (int N : {1000, 2000, 4000, 8000, 16000}) {
        const validation::complete_slip limit = validation::complete_slip_creep(hertz, 0.0, 1.0, N);
        const double c = -M_PI * limit.xi_over_beta / 4.0;
        bound.push_back(M_PI * limit.resolution / 4.0);
        EXPECT_LT(std::fabs(c - constant), bound.back()) << N;
        // The opposite sign of beta_D gives the same constant (8(h)).
        EXPECT_EQ(validation::complete_slip_creep(hertz, 0.0, -1.0, N).xi_over_beta, limit.xi_over_beta);
        EXPECT_EQ(std::round(1000.0 * c), 457.0) << N;  // the published 0.457
    }
    // The resolution is O(h): it halves with h (order within 0.9..1.1), and ends below 1e-4,
    // so the grid resolves the published three digits (0.457386 +- 1e-4).
    for (std::size_t i = 1; i < bound.size(); ++i) {
        const double order = std::log2(bound[i - 1] / bound[i]);
        EXPECT_GT(order, 0.9) << i;
        EXPECT_LT(order, 1.1) << i;
    }
    EXPECT_LT(bound.back(), 1e-4);

    // The solved route at finite f approaches the limit (N = 200, beta_D = 0.143834).
    const double limit = -2.0 / M_PI * std::cos(std::acos(2.0 * constant)) * beta_al_st;
    std::vector<double> distance;
    for (double ratio : {5.0, 10.0, 20.0}) {
        const double xi = grid(beta_al_st / ratio, 0.0, 200, beta_al_st).xi;
        distance.push_back(xi - limit);
    }
    for (std::size_t i = 0; i < distance.size(); ++i) {
        EXPECT_GT(distance[i], 0.0);  // above the limit (less negative), as in 8(f)
        if (i > 0) {
            const double fall = distance[i - 1] / distance[i];  // f halves
            EXPECT_GT(fall, 1.6) << i;
            EXPECT_LT(fall, 2.6) << i;
        }
    }
}

// 8(f): no slip, f -> infinity at fixed Q: xi -> Q/pi - 4 beta_D/pi^2. At f = 50 every cell
// sticks (the edge zones of 8(g) are exponentially thin, far below a cell), so the grid solves
// the no-slip problem; its error falls at order about 0.8 (measured: 0.79, 0.81, 0.83 for
// N = 50..400, the logarithm of the beta_D term), and the closed form lies within twice the
// last change (the tail of such a sequence is 1.35 times the last change).
TEST(Dissimilar, NoSlipLimit) {
    for (double Q : {0.0, 0.05}) {
        const double expected = Q / M_PI - 4.0 * beta_al_st / (M_PI * M_PI);
        std::vector<double> xi, error;
        for (int N : {50, 100, 200}) {
            const auto g = grid(50.0, Q, N, beta_al_st);
            ASSERT_EQ(g.runs().size(), 1u) << N;
            EXPECT_EQ(g.runs()[0].state, 0);
            xi.push_back(g.xi);
            error.push_back(std::fabs(g.xi - expected));
        }
        for (std::size_t i = 1; i < error.size(); ++i) {
            const double order = std::log2(error[i - 1] / error[i]);
            EXPECT_GT(order, 0.6) << Q;
            EXPECT_LT(order, 1.2) << Q;
        }
        EXPECT_LT(error.back(), 2.0 * std::fabs(xi[2] - xi[1])) << Q;
    }
    // Free rolling between the two limits, monotone in f (N = 100): f = 50 (no slip on the
    // grid), 0.1, 0.05, 0.02, 0.01, each below the previous and above -(2/pi) cos(phi) beta_D.
    const double complete_slip = -2.0 / M_PI * std::cos(std::acos(2.0 * bentall_johnson_constant())) * beta_al_st;
    double previous = 0.0;
    for (double f : {50.0, 0.1, 0.05, 0.02, 0.01}) {
        const double xi = grid(f, 0.0, 100, beta_al_st).xi;
        EXPECT_LT(xi, previous) << f;
        EXPECT_GT(xi, complete_slip) << f;
        previous = xi;
    }
}

// 8(h): exchanging the rollers maps (beta_D, Q) to (-beta_D, -Q) and (xi, p1, v, states) to
// their negatives, with the same zone ends, smooth and with a rough layer. The grid equations
// are exactly odd under the map, so it holds to the bit. Q -> -Q at fixed beta_D is not a
// symmetry any more: the creep curve is not odd.
TEST(Dissimilar, RollersExchanged) {
    roughness layer;  // a rough layer on roller 1, the pressure its rough normal solution
    layer.cylinder1.tangential = {1.0, 0.5};
    layer.cylinder1.normal = {0.5, 1.0};
    const normal_solution rough = solve_normal(kernel::normal(layer), 32, method::product);
    const double f = 0.05;
    for (const bool smooth : {true, false}) {
        const kernel k = smooth ? kernel{} : kernel::tangential(layer);
        const normal_solution& normal = smooth ? hertz : rough;
        for (double Q : {0.75 * f, 0.0, -0.5 * f}) {
            const auto a = grid(f, Q, 100, beta_al_st, k, normal);
            const auto b = grid(f, -Q, 100, -beta_al_st, k, normal);
            EXPECT_EQ(a.xi, -b.xi) << Q;
            for (int i = 0; i < 100; ++i) {
                EXPECT_EQ(a.p1[i], -b.p1[i]) << i;
                EXPECT_EQ(a.state[i], -b.state[i]) << i;
            }
            if (Q != 0.0) {
                const auto mirror = grid(f, -Q, 100, beta_al_st, k, normal);
                EXPECT_GT(std::fabs(a.xi + mirror.xi), 1e-3) << Q;  // not odd in Q
            }
        }
    }
}

// 8(g), observed: free rolling of aluminium on steel at f = 0.05 has five zones, slip at both
// edges against sgn(beta_D), two stick zones and a reversed slip zone between them, at every
// grid; the zone ends settle to within two cells. Both edges slip whenever beta_D != 0 and
// the edge zones are wider than a cell.
TEST(Dissimilar, FreeRollingHasFiveZones) {
    std::vector<std::vector<validation::grid_solution::run>> all;
    for (int N : {100, 200}) {
        const auto g = grid(0.05, 0.0, N, beta_al_st);
        EXPECT_EQ(states_of(g), (std::vector<int>{-1, 0, 1, 0, -1})) << N;
        all.push_back(g.runs());
        double load = 0.0;
        for (double t : g.p1) load += g.h * t;
        EXPECT_NEAR(load, 0.0, 1e-14);
    }
    for (std::size_t z = 0; z + 1 < all.back().size(); ++z)
        EXPECT_NEAR(all[0][z].to, all[1][z].to, 2.0 * 2.0 / 100) << z;
    // With the rollers exchanged the edges slip forwards: the mirrored structure.
    EXPECT_EQ(states_of(grid(0.05, 0.0, 200, -beta_al_st)), (std::vector<int>{1, 0, -1, 0, 1}));
    // Tractive, roller 1 braked and driven (8(g) table): three zones.
    EXPECT_EQ(states_of(grid(0.05, -0.75 * 0.05, 200, beta_al_st)), (std::vector<int>{-1, 0, -1}));
    EXPECT_EQ(states_of(grid(0.05, 0.75 * 0.05, 200, beta_al_st)), (std::vector<int>{-1, 0, 1}));
}

// The issue's case (Bentall and Johnson's Fig. 9 pair, CONTACT's user guide): aluminium on
// steel, R1 = R2 = 50 mm (R = 25 mm), a = 0.1 mm, f = 0.05, free rolling. CONTACT (full
// coupling, 200 elements) gives |xi_1| = 0.000429. Here xi_1 = pi a xi/(2R) (2(b), lambda = 1).
// The route's error: the grid's (N = 200 against 100), Johnson's approximation (the neglected
// pressure change, relative |beta_D| f, 8(e)), and the rounding of the published figure.
// Sign: beta_D > 0, so xi_1 < 0: the aluminium roller's surface is the faster.
TEST(Dissimilar, AluminiumOnSteelFreeRollingAgainstContact) {
    const double a_over_R = 0.1 / 25.0;
    const double coarse = grid(0.05, 0.0, 100, beta_al_st).xi;
    const double fine = grid(0.05, 0.0, 200, beta_al_st).xi;
    const double xi1 = M_PI * a_over_R * fine / 2.0;
    const double grid_error = M_PI * a_over_R * std::fabs(fine - coarse) / 2.0;
    const double coupling = std::fabs(beta_al_st) * 0.05 * std::fabs(xi1);
    const double published = 0.000429, rounding = 0.5e-6;
    EXPECT_LT(xi1, 0.0);
    EXPECT_LT(std::fabs(std::fabs(xi1) - published), grid_error + coupling + rounding)
        << "xi_1 = " << xi1 << ", grid " << grid_error << ", coupling " << coupling;
    // And it lies strictly between the two limits of 8(f) in their dimensional form.
    EXPECT_LT(std::fabs(xi1), bentall_johnson_constant() * 2.0 * beta_al_st * a_over_R);
    EXPECT_GT(std::fabs(xi1), 2.0 / M_PI * beta_al_st * a_over_R);
}
