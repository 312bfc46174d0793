// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/error_bound.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace roughroll {

namespace {
constexpr double min_ratio = 1.5;              // below: the levels do not visibly converge
constexpr double asymptotic_share = 0.7;       // rho >= 0.7 * 2^p: observed order >= p - 1/2
constexpr double min_sign_change_ratio = 4.0;  // |rho| when the differences change sign
}  // namespace

error_bound confirm_error(const three_levels& v, int order, bool extrapolated, double floor) {
    error_bound b = bound_error(v, order, reported_value{1, extrapolated}, floor);
    if (b.resolved) return b;
    const double d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    // Richardson's value from the middle level moves from it by |d1|/(2^p - 1).
    const double shift = extrapolated ? std::fabs(d1) / (std::ldexp(1.0, order) - 1.0) : 0.0;
    if (d1 * d2 < 0.0 && std::fabs(d2) <= std::fabs(d1)) {
        // Alternating without growing: the middle level sits in a band of the two steps' width
        // around the limit (a swept Q(c0) of data/steel-rollers-ground.toml at c0 = -0.65:
        // -8.0e-11, +8.0e-11, where n/4 -> n/2 moved by 1e-8). Twice the wider step.
        b.value = shift + 2.0 * std::max(std::fabs(d1), std::fabs(d2)) + floor;
        b.resolved = true;
    } else if (d1 * d2 > 0.0 && std::fabs(d1) > std::fabs(d2)) {
        // Still shrinking, too slowly to show an order: the geometric tail with that ratio (the
        // ground rollers' c0 at Q/f = 0.9856: -6.2e-10, -5.1e-10 after an estimate of 9.5e-8 from
        // n/4, n/2, n; the error against n = 1000 is 4.7e-10).
        const double r = std::fabs(d1 / d2);
        b.value = shift + std::fabs(d2) * (1.0 + 2.0 / (r - 1.0)) + floor;
        b.resolved = std::isfinite(b.value);
    }
    b.asymptotic = false;
    return b;
}

error_bound change_bound(const three_levels& v, double floor) {
    const double d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    const double value = 2.0 * std::max(std::fabs(d1), std::fabs(d2)) + floor;
    const bool finite = std::isfinite(value);
    return {finite ? value : 0.0, d1 / d2, false, finite};
}

double rounding_floor(int n, double scale) { return std::max(n, 1) * DBL_EPSILON * std::fabs(scale); }

double stick_system_floor(int n, double scale) {
    constexpr double growth = 8.0;  // twice the measured 3.7 (error_bound.hpp)
    return growth * rounding_floor(n, scale);
}

double entry_ends_floor(int n, double scale, double rho, double b0) {
    if (!(rho > 0.0) || !(b0 != 0.0)) return 0.0;
    // sum_{j < n} (j + 1) eps scale: the weights |U_j(-1)| of psi(-1) on each coefficient's rounding.
    const double m = std::max(n, 1);
    const double entry = 0.5 * m * (m + 1.0) * DBL_EPSILON * std::fabs(scale);
    return rho * entry / std::fabs(b0);
}

error_bound bound_error(const three_levels& v, int order, reported_value which, double floor) {
    const double full = std::ldexp(1.0, order);  // 2^p
    const double d1 = v.middle - v.coarsest, d2 = v.finest - v.middle;
    const double a1 = std::fabs(d1), a2 = std::fabs(d2);
    error_bound b{};
    b.ratio = d2 != 0.0 ? d1 / d2 : std::numeric_limits<double>::infinity();
    if (!(std::isfinite(d1) && std::isfinite(d2))) return b;  // not resolved
    // The difference that Richardson's rule (and the classic estimate) uses for the value.
    const double d_top = which.index == 1 ? a1 : a2;
    // Converging: |rho| >= 1.5; an error that changes sign between levels must contract
    // at least as an order-2 method's does (|rho| >= 4, or 0.7 * 2^p when that is less), else
    // the levels oscillate and give no estimate.
    const double r = std::fabs(b.ratio);
    const double needed = b.ratio < 0.0 ? std::min(asymptotic_share * full, min_sign_change_ratio) : min_ratio;
    if (a1 <= floor && a2 <= floor) {
        // Both differences are rounding: nothing converges any more. Where they still show a visible ratio (the
        // rule's `needed` below), never below the rule's estimate of them, with this floor: a floor raised so far that
        // changes the rule read as a ratio now fall within it must not lower the estimate (session 30 review: floor
        // 1 -> 8 with changes 6, 4 would give 12 where the rule gave 17; now 24). Changes without that ratio stay the
        // rounding rule's (their geometric tail 2/(r - 1) would grow without bound as r -> 1: 4.04, 4 at floor 8, 12).
        b.value = floor + (which.extrapolated ? d_top / (full - 1.0) : (which.index == 2 ? a2 : a1 + a2));
        if (std::max(a1, a2) > 0.0 && r >= needed) {
            const error_bound by_ratio = bound_error(v, order, which, 0.0);  // not this branch: a change above 0
            if (by_ratio.resolved) b.value = std::max(b.value, by_ratio.value + floor);
        }
        b.asymptotic = b.resolved = true;
        return b;
    }
    if (!(r >= needed) && a2 > floor) return b;
    const double r_eff = std::min(r, full);  // geometric tail, ratio capped at 2^p
    b.asymptotic = b.ratio >= asymptotic_share * full;
    // Below the assumed order the ratio may still fall at finer levels (pre-asymptotic): twice
    // the geometric tail, and at least twice the last difference (product integration at
    // n = 96 on a normal layer T = 1e6, A = 30: error 1.8 |d2| at Q/f = 0.5, rho = 3).
    const double e2 = a2 * (b.asymptotic ? 1.0 : std::max(2.0, 2.0 / (r_eff - 1.0)));
    b.resolved = true;
    // Bounds on the errors of the three levels.
    const double e1 = a2 + e2;
    const double e0 = a1 + e1;
    const double level_error[] = {e0, e1, e2};
    if (which.extrapolated) {
        // Richardson's value from levels index-1 and index: |value - v_index| = d_top/(2^p - 1),
        // and |v_index - limit| is about as much in the asymptotic range, so the value is within
        // twice that of the limit (the triangle inequality: where the error changes sign beyond
        // level n, Richardson's step moves away from the limit; extrapolated n = 32 near full
        // stick was 1.2 times its single shift away, validation/estimate_grid.py). In the
        // asymptotic range also the change of Richardson's value from the level pair below,
        // |2^p d2 - d1|/(2^p - 1) = |d2| |2^p - rho|/(2^p - 1) (the ratio's distance from 2^p):
        // a coarsest level that is itself pre-asymptotic shows there.
        const double shift = d_top / (full - 1.0);
        const double change = which.index == 2 ? std::fabs(full * d2 - d1) / (full - 1.0) : 0.0;
        b.value = b.asymptotic ? std::max(2.0 * shift, change) : shift + level_error[which.index];
    } else {
        b.value = level_error[which.index];
    }
    // Level n the coarsest of n, 2n, 4n (small n, or a coarser level outside the asymptotic range): its error is
    // |e_n| <= |x_2n - x_n| + |e_2n|, and e1 bounds e_2n only as far as the fall from 2n to 4n goes on, which a change
    // that falls much faster than the order there need not (docs/formulation.md 8(e), "Level n the coarsest": at
    // --n 3 the errors of Johnson's level fell so fast that the estimate was 1.0001 times the error). The rule assumes
    // that levels converging visibly (the ratio 1.5 and more above) halve the error per doubling at least,
    // |e_2n| <= |e_n|/2 -- an assumption the ratio does not prove (errors 1, 0.8, 0.79 pass it: estimate 0.4) -- and
    // then |e_n| <= 2 |x_2n - x_n|: twice the larger change, as full coupling's rule (change_bound), never less.
    if (which.index == 0 && !which.extrapolated) b.value = std::max(b.value, 2.0 * std::max(a1, a2));
    b.value += floor;
    return b;
}

}  // namespace roughroll
