// SPDX-License-Identifier: GPL-3.0-or-later
// The plateau of two blended stick zones (numerics/blend_plateau.hpp, docs/formulation.md 8(p) "The step carried
// across thin stick zones"): its closed-form Hilbert transform against GSL's Cauchy principal value (QAWC) of the
// plateau itself, Theta_3 against the quadrature of its derivative (16/(5 pi)) (1 - t^2)^(5/2), and the moments
// against QAGS; on zones as thin as five zones' at f = 1e-6 (1.8e-5) and as wide as at f = 0.05.
#include <cmath>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/blend_plateau.hpp"

namespace {
using roughroll::blend_plateau;

struct workspace {
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(2000);
    ~workspace() { gsl_integration_workspace_free(w); }
};

// One piece of B in its own variable: a ramp in its zone's t (Theta_3 rising, or 1 - Theta_3 falling), since
// d eta/(eta - r) = d tau/(tau - t), so that a zone 1.8e-5 thin is integrated at the scale of [-1, 1] (in eta its
// points' rounding, 1e-16 absolute, would be 1e-11 in t); the plateau between the zones is 1.
struct piece {
    int kind;      // 0: rising ramp, 1: plateau, 2: falling ramp
    double x;      // the Cauchy point in the piece's variable
    double shift;  // subtracted from the ramp (its value at x, where x lies inside)
};
double ramp(int kind, double u) { return kind == 0 ? blend_plateau::theta3(u) : 1.0 - blend_plateau::theta3(u); }
double piece_at(double u, void* p) {
    const piece& q = *static_cast<const piece*>(p);
    return ramp(q.kind, u) - q.shift;
}
double piece_over(double u, void* p) { return piece_at(u, p) / (u - static_cast<const piece*>(p)->x); }

// (1/pi) PV int B(eta)/(eta - r) piece by piece between the zone ends: the ramps by QAWC (the piece holding r) or
// QAGS, the plateau's constant by its logarithm; no closed form of the program enters (the ramps' Theta_3 is checked
// by its derivative above).
double hilbert_by_quadrature(const blend_plateau& b, double r, gsl_integration_workspace* w) {
    const double m1 = 0.5 * (b.start1() + b.end1()), rho1 = 0.5 * (b.end1() - b.start1());
    const double m2 = 0.5 * (b.start2() + b.end2()), rho2 = 0.5 * (b.end2() - b.start2());
    const double length = b.start2() - b.end1();
    const piece pieces[3] = {{0, (r - m1) / rho1, 0.0}, {1, (r - b.end1()) / length, 0.0}, {2, (r - m2) / rho2, 0.0}};
    const double lo[3] = {-1.0, 0.0, -1.0};
    double total = 0.0;
    for (const piece& p0 : pieces) {
        piece p = p0;
        const double a = lo[p.kind];
        double value = 0.0, error = 0.0;
        if (p.kind == 1) {
            // The constant 1 between the zones: PV int_c1^s2 d eta/(eta - r) = log|(s2 - r)/(c1 - r)| (the textbook
            // transform of an indicator, from the distances themselves: r lies 1e-8 from an end).
            total += std::log(std::fabs((b.start2() - r) / (b.end1() - r)));
            continue;
        }
        if (p.x > a && p.x < 1.0) {
            // QAWC of the ramp less its value at x (QAWC loses digits where x lies next to an end and the ramp is 1
            // there), plus that value's transform log|(1 - x)/(1 + x)|.
            p.shift = ramp(p.kind, p.x);
            gsl_function F{&piece_at, &p};
            EXPECT_EQ(gsl_integration_qawc(&F, a, 1.0, p.x, 1e-14, 1e-13, 2000, w, &value, &error), GSL_SUCCESS);
            value += p.shift * std::log((1.0 - p.x) / (1.0 + p.x));
        } else {
            gsl_function F{&piece_over, &p};
            EXPECT_EQ(gsl_integration_qags(&F, a, 1.0, 1e-14, 1e-13, 2000, w, &value, &error), GSL_SUCCESS);
        }
        total += value;
    }
    return total / M_PI;
}
}  // namespace

TEST(BlendPlateau, ThetaThreeIsTheIntegralOfItsDerivative) {
    gsl_set_error_handler_off();
    workspace ws;
    gsl_function d{[](double t, void*) { return 16.0 / (5.0 * M_PI) * std::pow(1.0 - t * t, 2.5); }, nullptr};
    for (const double t : {-1.0, -0.9, -0.3, 0.0, 0.2, 0.77, 1.0}) {
        double value = 0.0, error = 0.0;
        if (t > -1.0) {
            ASSERT_EQ(gsl_integration_qags(&d, -1.0, t, 1e-15, 1e-13, 2000, ws.w, &value, &error), GSL_SUCCESS);
        }
        EXPECT_NEAR(blend_plateau::theta3(t), value, 1e-14) << t;
    }
}

TEST(BlendPlateau, HilbertTransformAgainstPrincipalValueQuadrature) {
    gsl_set_error_handler_off();
    workspace ws;
    // Five zones' stick zones of the pair at f = 1e-6 (8(p)), at f = 0.05 (wide), and a driven layout whose second
    // zone lies 5e-4 from the edge.
    const std::vector<std::vector<double>> layouts{{-0.4038767, -0.4038584, 0.4040687, 0.4040870},
                                                   {-0.68, -0.49, 0.31, 0.52},
                                                   {-0.93, -0.75, 0.99919, 0.99953}};
    for (const auto& given : layouts) {
        // The ends on a grid of 2^-24, the points' t with few bits: every r = m + rho t, r - m, c - r exact, so that
        // the closed form and the quadrature see the same t (a zone 1.8e-5 wide would otherwise turn r's rounding
        // into 1e-11 in t, 1e-9 in H next to an end: conditioning, not an error of either).
        std::vector<double> z(4);
        for (int i = 0; i < 4; ++i) z[i] = std::ldexp(std::round(std::ldexp(given[i], 24)), -24);
        const blend_plateau b(z[0], z[1], z[2], z[3]);
        const double rho1 = 0.5 * (z[1] - z[0]), rho2 = 0.5 * (z[3] - z[2]);
        std::vector<double> points{-0.999, -0.5, 0.0, 0.6, 0.9999};
        for (const double t : {-3.0, -1.25, -1023.0 / 1024.0, -0.5, 0.0, 0.375, 127.0 / 128.0, 1025.0 / 1024.0, 1.5, 40.0}) {
            points.push_back(0.5 * (z[0] + z[1]) + rho1 * t);
            points.push_back(0.5 * (z[2] + z[3]) + rho2 * t);
        }
        for (const double r : points) {
            if (!(std::fabs(r) < 1.0)) continue;
            SCOPED_TRACE(r);
            const double exact = b.hilbert(r), numeric = hilbert_by_quadrature(b, r, ws.w);
            EXPECT_NEAR(exact, numeric, 2e-12 * (1.0 + std::fabs(numeric))) << z[0] << " " << z[3];
        }
        // The moments int B eta^k: the ramps in their zone variables by QAGS, the plateau's int eta^k exactly.
        for (int k = 0; k < 3; ++k) {
            struct power {
                int kind, k;
                double m, rho;
            };
            double total = (std::pow(z[2], k + 1) - std::pow(z[1], k + 1)) / (k + 1);
            const power ramps[2] = {{0, k, 0.5 * (z[0] + z[1]), rho1}, {2, k, 0.5 * (z[2] + z[3]), rho2}};
            for (const power& p : ramps) {
                gsl_function G{[](double u, void* q) {
                                   const auto& s = *static_cast<const power*>(q);
                                   return s.rho * ramp(s.kind, u) * std::pow(s.m + s.rho * u, s.k);
                               },
                               const_cast<power*>(&p)};
                double value = 0.0, error = 0.0;
                ASSERT_EQ(gsl_integration_qags(&G, -1.0, 1.0, 1e-16, 1e-13, 2000, ws.w, &value, &error), GSL_SUCCESS);
                total += value;
            }
            EXPECT_NEAR(b.moment(k), total, 1e-14) << k;
        }
    }
}

// Only the moments k = 0, 1, 2 are derived (8(p)); any other k is a typed error, not a NaN carried into p_q^0's load
// (it was NaN before: review S8 of session 14).
TEST(BlendPlateau, MomentBeyondTheSecondIsATypedError) {
    const blend_plateau b(-0.4, -0.2, 0.3, 0.5);
    for (const int k : {-1, 3, 7}) {
        SCOPED_TRACE(k);
        try {
            (void)b.moment(k);
            ADD_FAILURE() << "no error";
        } catch (const roughroll::numerical_error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("k = " + std::to_string(k)), std::string::npos) << what;
        }
    }
    EXPECT_TRUE(std::isfinite(b.moment(2)));
}
