// SPDX-License-Identifier: GPL-3.0-or-later
// A made-up rounding for the tests of the zone ends' Newton at its rounding stop (numerics/damped_newton.hpp):
// included as "rounding_jitter.hpp" from tests/, "../tests/rounding_jitter.hpp" from validation/.
#ifndef ROUGHROLL_TESTS_ROUNDING_JITTER_HPP
#define ROUGHROLL_TESTS_ROUNDING_JITTER_HPP

#include <cstdint>
#include <cstring>

// A rounding of size `a` that is a fixed function of x's bits (as an entry condition's at large n: the same x gives
// the same F, the nearest other x another one): a hash of the bits, uniform in [-a, a].
inline double jitter(double x, double a) {
    std::uint64_t u = 0;
    std::memcpy(&u, &x, sizeof u);
    u *= 0x9E3779B97F4A7C15ULL;
    u ^= u >> 29;
    u *= 0xBF58476D1CE4E5B9ULL;
    return a * (static_cast<double>(u >> 11) * 0x1p-52 - 1.0);
}

#endif
