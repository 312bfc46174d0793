// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive quadrature of integrands with square-root or 3/2-power ends (docs/formulation.md 8(g), 8(p)): W of the
// blended stick zone and int p Theta of dissimilar rollers (dissimilar_zones), summed over pieces whose errors add.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "roughroll/base/gsl_handles.hpp"

namespace roughroll {

// A quadrature's value and GSL's estimate of its error.
struct quadrature_value {
    double value;
    double error;
};

// The sum of `count` pieces of one integral, piece(i, accepted) -> quadrature_value, whose errors add (W's
// breakpoints, end_quadrature::pieces' cuts; docs/formulation.md 8(p)): each piece first at the whole limit `accepted`
// (the values of before, bit for bit, where their errors' sum is within it), then, where the sum is not, each piece
// above its share accepted/count again at that share (end_quadrature::piece takes its other route or throws).
// A piece that meets GSL's own tolerances (1e-14 absolute or 1e-12 relative: GSL_SUCCESS) is kept at any error below
// them, so the sum's error is within `accepted` plus 1e-12 of the sum of |piece| (session 17 review I2): for W and
// int p Theta, of order 1 on at most 28 pieces, a few 1e-11 more.
template <class Piece>
quadrature_value within_accepted(std::size_t count, double accepted, const Piece& piece) {
    std::vector<quadrature_value> v(count);
    double error = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        v[i] = piece(i, accepted);
        error += v[i].error;
    }
    if (error > accepted) {
        const double share = accepted / static_cast<double>(count);
        for (std::size_t i = 0; i < count; ++i)
            if (v[i].error > share) v[i] = piece(i, share);
    }
    quadrature_value total{0.0, 0.0};
    for (const quadrature_value& x : v) {
        total.value += x.value;
        total.error += x.error;
    }
    return total;
}

// GSL's adaptive rules on one workspace (one per user: not shared between threads).
class end_quadrature {
public:
    end_quadrature();

    // int_a^b of an integrand with square-root or 3/2-power ends at a and b, with GSL's estimate of its error: GSL
    // meets its tolerances, or that estimate is below `accepted` (the piece's share of its integral's limit), or the
    // call throws numerical_error naming `what`.
    quadrature_value piece(const std::function<double(double)>& integrand, double a, double b, const char* what,
                           double accepted);
    // The same over [a, b], where one piece fails cut into pieces equal in the angle arccos(eta), as many as a U-series
    // of `terms` terms has periods there over 16: the whole first five-zone stick zone in one GSL call meets its
    // rounding (GSL_EROUND) at n = 512 (int p Theta) and 1000 (W) (docs/formulation.md 8(p)). The pieces' errors add:
    // their sum is held to `accepted`.
    quadrature_value pieces(const std::function<double(double)>& integrand, double a, double b, int terms,
                            const char* what, double accepted);

private:
    integration_workspace_ptr workspace_;
};

}  // namespace roughroll
