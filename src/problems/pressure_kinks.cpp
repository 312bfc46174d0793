// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/pressure_kinks.hpp"

#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

void pressure_kinks::add_zone(const gauss_chebyshev& rule, double beta_d, double sign, double start, double c0,
                              const std::vector<double>& psi_b) {
    if (!(start > -1.0 && start < c0 && c0 < 1.0))
        throw numerical_error(
            "full coupling: a stick zone of the pressure's kinks is not inside the contact "
            "(docs/formulation.md 8(l))");
    zone z{start, 0.5 * (c0 - start), beta_d * sign, {}};
    std::vector<double> g(static_cast<std::size_t>(rule.n));
    // int q r/sqrt(1 - r^2) dr and int q/sqrt(1 - r^2) dr over the zone: rho int sqrt(1 - t^2) g(t) (r, 1) dt,
    // by the rule's Gauss weights for sqrt(1 - t^2) (4.6), exact for the expansion g_n of degree n - 1 times r.
    double first = 0.0, zeroth = 0.0;
    for (int i = 0; i < rule.n; ++i) {
        const double r = start + z.rho * (rule.nodes[i] + 1.0);
        g[i] = u_series(psi_b, rule.nodes[i]) / std::sqrt(1.0 - r * r);
        first += rule.weights[i] * g[i] * r;
        zeroth += rule.weights[i] * g[i];
    }
    z.b = u_coefficients(rule, g);
    load_ += z.amplitude * z.rho * first;
    constant_ += z.amplitude * z.rho * zeroth * M_1_PI;
    zones_.push_back(std::move(z));
}

double pressure_kinks::operator()(double r) const {
    if (!(std::fabs(r) < 1.0)) return 0.0;
    double h = 0.0;  // H[q/sqrt(1 - r^2)]: the zone variable's Cauchy integral (d eta/(eta - r) = d tau/(tau - t))
    for (const zone& z : zones_) h += z.amplitude * cauchy_u_series(z.b, (r - z.start) / z.rho - 1.0);
    return std::sqrt(1.0 - r * r) * h;
}

double pressure_kinks::removed(double r) const {
    double sum = 0.0;
    for (const zone& z : zones_) {
        const double t = (r - z.start) / z.rho - 1.0;
        if (!(std::fabs(t) < 1.0)) continue;
        sum += z.amplitude * std::sqrt((1.0 - r * r) * (1.0 - t * t)) * u_series(z.b, t);
    }
    return sum;
}

double pressure_kinks::load() const { return load_; }
double pressure_kinks::constant() const { return constant_; }

std::vector<double> pressure_kinks::ends() const {
    std::vector<double> e;
    for (const zone& z : zones_) {
        e.push_back(z.start);
        e.push_back(z.start + 2.0 * z.rho);
    }
    return e;
}

}  // namespace roughroll
