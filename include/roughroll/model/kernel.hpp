// SPDX-License-Identifier: GPL-3.0-or-later
// The roughness kernels (3.23)-(3.24), with errata E1 and E2:
//   K_i*(z) = [T_1^(i) exp(-A_1^(i) |z|) + T_2^(i) exp(-A_2^(i) |z|)] sgn z,
// i = 1 tangential, i = 2 normal. The overall sign is + (E2: roughness adds
// compliance), each exponent carries its own A (E1), a term with T = 0 is left out.
//
// A kernel is a list of exponential terms, so differences (K2* - K1* in G,
// (3.25)) and the stretched kernel of the tangential problem (E6) are kernels too.
#pragma once

#include <vector>

#include "roughroll/model/roughness.hpp"

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
    // Whether the surfaces carry a roughness layer (2(b)): K1* or K2* not empty.
    static bool layered(const roughness& r) { return !tangential(r).empty() || !normal(r).empty(); }

    bool empty() const { return terms_.empty(); }
    const std::vector<exponential_term>& terms() const { return terms_; }
    double max_rate() const;  // the largest A: the kernel's narrowest feature is 1/A
    // sum |T|: the size of the kernel's terms, which multiply integrals of O(1) tractions and
    // cancel in the equations (the scale of their rounding floors, numerics/error_bound.hpp).
    double strength() const;

    // K(z) for z != 0 (the kernel jumps at 0; its value there is never used).
    double operator()(double z) const;

    // this - other, with equal terms cancelled: K2* - K1* is empty when they agree.
    kernel minus(const kernel& other) const;

    // rho K(rho z): the kernel of the stick-zone equation in its own variable (E6).
    kernel stretched(double rho) const;

private:
    std::vector<exponential_term> terms_;
};

}  // namespace roughroll
