// The roughness kernels (3.23)-(3.24), with errata E1 and E2:
//   K_i*(z) = [T_1^(i) exp(-A_1^(i) |z|) + T_2^(i) exp(-A_2^(i) |z|)] sgn z,
// i = 1 tangential, i = 2 normal. The overall sign is + (E2: roughness adds
// compliance), each exponent carries its own A (E1), a term with T = 0 is left out.
//
// A kernel is a list of exponential terms, so differences (K2* - K1* in G,
// (3.25)) and the stretched kernel of the tangential problem (E6) are kernels too.
#pragma once

#include <vector>

#include "roughroll/quadrature.hpp"
#include "roughroll/roughness.hpp"

namespace roughroll {

struct exponential_term {
    double T;  // amplitude (may be negative inside a difference of kernels)
    double A;  // decay rate, >= 0
};

class kernel {
public:
    kernel() = default;
    explicit kernel(std::vector<exponential_term> terms);

    // K1* (i = 1, tangential) and K2* (i = 2, normal) of a pair of cylinders.
    static kernel tangential(const roughness& r);
    static kernel normal(const roughness& r);

    bool empty() const { return terms_.empty(); }
    const std::vector<exponential_term>& terms() const { return terms_; }
    double max_rate() const;  // the largest A: the kernel's narrowest feature is 1/A

    // K(z) for z != 0 (the kernel jumps at 0; its value there is never used).
    double operator()(double z) const;

    // this - other, with equal terms cancelled: K2* - K1* is empty when they agree.
    kernel minus(const kernel& other) const;

    // rho K(rho z): the kernel of the stick-zone equation in its own variable (E6).
    kernel stretched(double rho) const;


private:
    std::vector<exponential_term> terms_;
};

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
