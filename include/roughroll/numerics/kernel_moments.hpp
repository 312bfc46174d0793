// SPDX-License-Identifier: GPL-3.0-or-later
// Moments of the roughness kernel against the Chebyshev-U basis, for the product method
// ((4.2), (4.4)) and G of (3.25) (E8): the kernel of model/kernel.hpp integrated exactly
// across its jump.
#pragma once

#include <vector>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

// Moments I_j(r) = int_{-1}^{1} U_j(eta) sqrt(1 - eta^2) K(eta - r) d eta, j < count,
// for any real r. With eta = cos(theta) the integrand is sin((j+1) theta) sin(theta)
// K(cos theta - r), analytic on each side of the jump at theta = acos(r); the
// integral is split there and each piece done by Gauss-Legendre (gsl_integration_fixed).
// A workspace keeps the Gauss-Legendre rule of its order.
class kernel_moments {
public:
    // `count` moments; the rule's order grows with count and with the kernel's max rate.
    kernel_moments(const kernel& k, int count);
    // With the Gauss-Legendre rule of moments_rule(count), built once by the caller.
    kernel_moments(const kernel& k, int count, const gauss_legendre& rule);
    static gauss_legendre moments_rule(int count);

    const std::vector<double>& at(double r);  // I_0..I_{count-1} at r
    // int_{-1}^{1} (sum_j b_j U_j(eta)) sqrt(1 - eta^2) K(eta - r) d eta
    double integrate(const std::vector<double>& b, double r);

private:
    void add_piece(double theta_lo, double theta_hi, double r, double side);
    void add_segment(double theta_lo, double theta_hi, double r, double side);

    kernel k_;
    int count_;
    gauss_legendre rule_;
    std::vector<double> moments_;
};

// int_{-1}^{1} (sum_j b_j U_j(eta)) sqrt(1 - eta^2) K(eta - end) d eta at end = 1 or -1 (the
// stick-zone operator at the ends of its interval, for the slip velocity), in closed form: with
// int_{-1}^{1} U_j(eta) sqrt(1 - eta^2) e^{A eta} d eta = pi (j + 1) I_{j+1}(A)/A (from
// sin((j+1) t) sin t = [cos(j t) - cos((j+2) t)]/2 and int_0^pi cos(m t) e^{A cos t} dt = pi I_m(A)),
// a term T exp(-A |z|) sgn z gives -T pi sum_j b_j (j+1) e^{-A} I_{j+1}(A)/A at end = 1 and
// T pi sum_j (-1)^j b_j (j+1) e^{-A} I_{j+1}(A)/A at end = -1 (U_j(-eta) = (-1)^j U_j(eta));
// A = 0 gives -+T pi b_0/2. e^{-A} I_m(A) by Miller's backward recurrence, normalised by
// e^{-A} (I_0(A) + 2 sum_m I_m(A)) = 1.
double integrate_at_end(const kernel& k, const std::vector<double>& b, double end);

}  // namespace roughroll
