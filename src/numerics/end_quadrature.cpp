// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/end_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

namespace {
// Tolerances, and the workspace's intervals; the error GSL's own estimate may keep when it cannot reach them is the
// caller's `accepted`, a limit on each whole integral (W's Cauchy part, each of K1*'s terms, int p Theta), not on each
// of the pieces it is summed from (within_accepted).
constexpr std::size_t quadrature_intervals = 400;
constexpr double quadrature_absolute = 1e-14;
constexpr double quadrature_relative = 1e-12;
}  // namespace

end_quadrature::end_quadrature() : workspace_(make_integration_workspace(quadrature_intervals)) {}

quadrature_value end_quadrature::piece(const std::function<double(double)>& integrand, double a, double b,
                                       const char* what, double accepted) {
    // int_a^b in eta = (a + b)/2 - (b - a)/2 cos phi, d eta = (b - a)/2 sin phi d phi: between
    // neighbouring breakpoints the integrands of W and of int p Theta have at most square-root
    // (p at r = 1) and 3/2-power (H at s and c0) ends, which this substitution makes analytic in
    // phi, so that GSL's adaptive Gauss-Kronrod rule meets the tolerance in a few bisections
    // instead of the hundreds that the ends cost in eta (measured: docs/performance.md).
    // eta is taken from the nearer end, a + 2 half sin^2(phi/2) or b - 2 half cos^2(phi/2), so that
    // its distance to that end (the Cauchy integrand's eta - r when r is the end) carries no
    // cancellation. Where GSL still fails (a Cauchy point r next to an end, within the 1e-9 for which
    // the caller's W does not cut there, or eta rounding onto the end), the piece is integrated as before, in eta
    // by qags, whose extrapolation serves end singularities; only that route's failure is an error.
    // GSL's "cannot reach the tolerance" is accepted where its own estimate of the error is below `accepted` (the
    // piece's share of its integral's limit, within_accepted).
    if (!(b > a)) return {0.0, 0.0};
    const double half = 0.5 * (b - a);
    const std::function<double(double)> in_phi = [&](double phi) {
        const double s = std::sin(0.5 * phi), c = std::cos(0.5 * phi);
        const double eta = phi < M_PI_2 ? a + 2.0 * half * s * s : b - 2.0 * half * c * c;
        return integrand(eta) * half * std::sin(phi);
    };
    const auto integrate = [&](const std::function<double(double)>& f, bool in_eta) {
        gsl_function fn;
        fn.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
        fn.params = const_cast<std::function<double(double)>*>(&f);
        quadrature_value v{0.0, 0.0};
        double& result = v.value;
        double& error = v.error;
        const int status =
            in_eta ? gsl_integration_qags(&fn, a, b, quadrature_absolute, quadrature_relative, quadrature_intervals,
                                          workspace_.get(), &result, &error)
                   : gsl_integration_qag(&fn, 0.0, M_PI, quadrature_absolute, quadrature_relative, quadrature_intervals,
                                         GSL_INTEG_GAUSS21, workspace_.get(), &result, &error);
        return std::make_pair(status == GSL_SUCCESS || error < accepted ? GSL_SUCCESS : status, v);
    };
    const auto [status, result] = integrate(in_phi, false);
    if (status == GSL_SUCCESS && std::isfinite(result.value)) return result;
    const auto [eta_status, eta_result] = integrate(integrand, true);
    gsl_check(eta_status, what);
    return eta_result;
}

quadrature_value end_quadrature::pieces(const std::function<double(double)>& integrand, double a, double b, int terms,
                                        const char* what, double accepted) {
    // Where the whole piece fails (both of piece's routes at their rounding: the whole first five-zone stick zone at
    // n = 512 for int p Theta, n = 1000 for W; GSL_EROUND), the same in pieces equal in the angle arccos(eta): a
    // U-series of n = `terms` terms runs through about n/2 periods over the angle pi, so a piece of angle 32 pi/n holds
    // about 16, which GSL's 21-point rule bisects to 1e-12 without meeting the sum's rounding (8(p), "Free rolling at
    // f = 0.2"). First as one piece, so that every integral that succeeded so keeps its value bit for bit. The pieces'
    // errors add, and their sum is held to the whole's `accepted` (within_accepted).
    const double from = std::acos(std::clamp(a, -1.0, 1.0)), to = std::acos(std::clamp(b, -1.0, 1.0));
    const int count = static_cast<int>(std::ceil((from - to) * terms / (32.0 * M_PI)));
    if (!(b > a) || count <= 1) return piece(integrand, a, b, what, accepted);
    try {
        return piece(integrand, a, b, what, accepted);
    } catch (const numerical_error&) {
    }
    const auto end = [&](int k) { return k == 0 ? a : k == count ? b : std::cos(from + (to - from) * k / count); };
    return within_accepted(static_cast<std::size_t>(count), accepted, [&](std::size_t k, double share) {
        const int i = static_cast<int>(k);
        return piece(integrand, end(i), end(i + 1), what, share);
    });
}

}  // namespace roughroll
