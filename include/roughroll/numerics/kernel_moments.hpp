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

}  // namespace roughroll
