// SPDX-License-Identifier: GPL-3.0-or-later
// The plateau of two blended stick zones and its finite Hilbert transform in closed form (docs/formulation.md
// 8(p), "The step carried across thin stick zones"). Five zones' traction is p1 = sigma (f p S + q) with
// S = -1 + 2 H1 - 2 H2 (8(j)); after the kinks carried by pressure_kinks the pressure's series still sees
// beta_D sigma f p (2 B - 1) on (D1)'s right side, with the plateau
//   B(r) = 0 (r < s1),  Theta_3(t1) on [s1, c1],  1 on (c1, s2),  1 - Theta_3(t2) on [s2, c2],  0 (r > c2),
// t_i = (r - m_i)/rho_i, m_i = (s_i + c_i)/2, rho_i = (c_i - s_i)/2, and Theta_3 the blend of 8(r):
//   Theta_3(t) = 1/2 + arcsin(t)/pi + sqrt(1 - t^2) P(t),   P = (45 U_1 - 9 U_3 + U_5)/(60 pi).
// A stick zone thinner than the node spacing makes B a step for the series (8(p): a log peak of the pressure that
// grows by (J/pi) ln 2 per doubling of n). Its transform, H[g](r) = (1/pi) PV int g(eta) d eta/(eta - r), is
//   H[B](r) = (1/pi) (log(rho2/rho1) - acosh+(|t1|) + acosh+(|t2|)) + C(t1) - C(t2),
// acosh+(x) = acosh(x) for x > 1 and 0 inside the zone, C(t) = cauchy_u_series of P (the sqrt(1 - t^2) P part),
// from H[arcsin] = (1/2) log|1 - t^2| - L(t)/pi, L(t) = int log|tau - t|/sqrt(1 - tau^2) = pi (acosh+(|t|) - log 2),
// the logarithms at the zone ends cancelling between the ramps and the plateau. Checked against GSL's QAWC
// (tests/test_blend_plateau.cpp); carried by full_coupling where a stick zone is thinner than every n's node spacing
// (pressure_kinks::add_plateau; 8(p), "Where the plateau is carried").
#pragma once

namespace roughroll {

class blend_plateau {
public:
    // The zones [s1, c1] (B rising) and [s2, c2] (B falling), -1 < s1 < c1 <= s2 < c2 < 1.
    blend_plateau(double s1, double c1, double s2, double c2);

    double operator()(double r) const;  // B(r)
    double hilbert(double r) const;     // H[B](r), any r not at a zone end of a one-sided acosh (finite there too)
    // int B eta^k d eta, k = 0, 1, 2 (closed form: int Theta_3 = 1, int t Theta_3 = 7/16, int t^2 Theta_3 = 1/3 on
    // [-1, 1], the odd parts of Theta_3 - 1/2 integrating to 0 against even powers). Any other k is a
    // numerical_error (no moment beyond the second is derived).
    double moment(int k) const;

    double start1() const { return s1_; }
    double end1() const { return c1_; }
    double start2() const { return s2_; }
    double end2() const { return c2_; }

    static double theta3(double t);  // Theta_3(t), |t| <= 1

private:
    double s1_, c1_, s2_, c2_, m1_, rho1_, m2_, rho2_;
    double log_ratio_;           // log(rho2/rho1)/pi
    double moments_[3];          // int B eta^k, k = 0, 1, 2
};

}  // namespace roughroll
