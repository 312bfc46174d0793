// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/blend_plateau.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

namespace {
// P of Theta_3 = 1/2 + arcsin(t)/pi + sqrt(1 - t^2) P(t) in U_j (docs/formulation.md 8(r): P = t/pi minus the
// polynomial of blend_kinks, (33 t - 26 t^3 + 8 t^5)/(15 pi)).
const std::vector<double> plateau_p{0.0, 45.0 / (60.0 * M_PI), 0.0, -9.0 / (60.0 * M_PI), 0.0, 1.0 / (60.0 * M_PI)};

// The ramp's transform without its logarithms: -acosh+(|t|)/pi + C(t) (docs/formulation.md 8(p)).
double ramp_part(double t) {
    const double a = std::fabs(t);
    const double outer = a > 1.0 ? std::log(a + std::sqrt((a - 1.0) * (a + 1.0))) : 0.0;
    return -M_1_PI * outer + cauchy_u_series(plateau_p, t);
}
}  // namespace

blend_plateau::blend_plateau(double s1, double c1, double s2, double c2)
    : s1_(s1), c1_(c1), s2_(s2), c2_(c2), m1_(0.5 * (s1 + c1)), rho1_(0.5 * (c1 - s1)), m2_(0.5 * (s2 + c2)),
      rho2_(0.5 * (c2 - s2)), log_ratio_(M_1_PI * std::log(rho2_ / rho1_)) {
    if (!(-1.0 < s1 && s1 < c1 && c1 <= s2 && s2 < c2 && c2 < 1.0))
        throw numerical_error("full coupling: the plateau of two stick zones needs -1 < s1 < c1 <= s2 < c2 < 1 "
                              "(docs/formulation.md 8(p))");
    // Zone i contributes rho_i int Theta (m_i + rho_i t)^k dt with Theta = Theta_3 rising (zone 1) or 1 - Theta_3
    // falling (zone 2): int Theta = 1, int t Theta = +-7/16, int t^2 Theta = 1/3; the plateau int_{c1}^{s2} eta^k.
    const auto zone = [](int k, double m, double rho, double sign) {
        const double t1 = sign * 7.0 / 16.0, t2 = 1.0 / 3.0;
        if (k == 0) return rho;
        if (k == 1) return rho * (m + rho * t1);
        return rho * (m * m + 2.0 * m * rho * t1 + rho * rho * t2);
    };
    for (int k = 0; k < 3; ++k)
        moments_[k] = zone(k, m1_, rho1_, 1.0) + (std::pow(s2_, k + 1) - std::pow(c1_, k + 1)) / (k + 1) +
                      zone(k, m2_, rho2_, -1.0);
}

double blend_plateau::moment(int k) const {
    if (k < 0 || k > 2)
        throw numerical_error("blend_plateau: the moment int B eta^k is derived for k = 0, 1, 2 only (docs/formulation.md "
                              "8(p)), not k = " + std::to_string(k));
    return moments_[k];
}

double blend_plateau::theta3(double t) {
    return 0.5 + M_1_PI * std::asin(t) + std::sqrt((1.0 - t) * (1.0 + t)) * u_series(plateau_p, t);
}

double blend_plateau::operator()(double r) const {
    if (r <= s1_ || r >= c2_) return 0.0;
    if (r < c1_) return theta3(std::max(-1.0, std::min(1.0, (r - m1_) / rho1_)));
    if (r <= s2_) return 1.0;
    return 1.0 - theta3(std::max(-1.0, std::min(1.0, (r - m2_) / rho2_)));
}

double blend_plateau::hilbert(double r) const {
    return log_ratio_ + ramp_part((r - m1_) / rho1_) - ramp_part((r - m2_) / rho2_);
}


}  // namespace roughroll
