// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/contact_width.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/root_search.hpp"
#include "roughroll/problems/load_ratio.hpp"

namespace roughroll {

namespace {
constexpr double width_step = 1.25;  // bracket expansion factor of the width search
constexpr int max_width_steps = 60;  // 1.25^60 = 6.5e5 a_H: far beyond any physical width
constexpr int max_width_iterations = 100;
constexpr double max_width_over_radius = 0.1;  // a/R above which (3.7)'s half-spaces are refused
constexpr double width_tolerance = width_search_tolerance;  // contact_width.hpp
constexpr int max_polish_steps = 8;            // secant steps from the cheap level's root

// "contact width search at a = ... m (a/a_H = ...)": where a failure of the normal problem
// happened, so that its advice (increase n, another method) can be judged.
std::string at_width(double x, double a_H) {
    return "contact width search at a = " + shortest(x * a_H) + " m (a/a_H = " + shortest(x) + "): ";
}

// (3.7) takes each cylinder as a half-space: the contact must be small against the radius.
// `lead` names the width a: the one found, Hertz's, or a bound below the one that carries P2.
[[noreturn]] void wide_against_radius(const physical_scene& s, double a, const std::string& lead) {
    std::ostringstream msg;
    msg << lead << " = " << shortest(a) << " m, " << shortest(a / s.radius())
        << " times the radius R = " << shortest(s.radius())
        << " m: the half-space theory of (3.7) needs a << R (refused above a/R = " << max_width_over_radius
        << "); check 'R1', 'R2', 'P2' and the roughness";
    throw input_error(msg.str());
}

contact_width small_against_radius(const physical_scene& s, const contact_width& w) {
    if (!(w.a <= max_width_over_radius * s.radius())) wide_against_radius(s, w.a, "the half-width a");
    return w;
}

// F(x) = lambda(x a_H) - x^2 with the trial width named in the solver's failures.
std::function<double(double)> width_function(const physical_scene& s, double a_H,
                                             const std::function<double(const roughness&)>& load_ratio) {
    return [&s, a_H, &load_ratio](double x) {
        try {
            return load_ratio(roughness_at(s, x * a_H)) - x * x;
        } catch (const rounding_limit_error& e) {  // its kind kept: the ladder climbs no higher
            throw rounding_limit_error(at_width(x, a_H) + e.what());
        } catch (const resolution_error& e) {
            throw resolution_error(at_width(x, a_H) + e.what());
        } catch (const numerical_error& e) {
            throw numerical_error(at_width(x, a_H) + e.what());
        }
    };
}

// The root x = a/a_H of F, F(1) = F1 != 0, by Brent to 1e-12 relative in x, bracketed as
// described in contact_width.hpp; x_max = (R/10)/a_H.
root bracketed_width(const physical_scene& s, const std::function<double(double)>& F, double F1, double a_H,
                     double x_max) {
    // F(1) = lambda - 1 > 0 for the compliant roughness of E2. The first trial is
    // x = sqrt(lambda(1)), where F <= 0 whenever lambda falls as a grows; then the bracket grows
    // by 1.25 away from x = 1. A trial too wide for the discretisation (A grows with a) is
    // halved back towards the last good point rather than refused.
    const bool up = F1 > 0.0;
    double near = 1.0;
    double far = std::sqrt(F1 + 1.0);
    if (far == 1.0) far = up ? width_step : 1.0 / width_step;
    for (int steps = 0;;) {
        if (steps > max_width_steps) {
            std::ostringstream msg;
            msg << "contact width search: no half-width between a_H and " << shortest(far * a_H)
                << " m carries the load P2 = " << shortest(s.P2) << " N/m";
            throw numerical_error(msg.str());
        }
        if (up && far > x_max) {
            // The root lies beyond a/R = 0.1 unless it lies below the bound itself.
            if (near >= x_max) wide_against_radius(s, near * a_H, "the half-width that carries P2 is above a");
            far = x_max;
        }
        double value = 0.0;
        try {
            value = F(far);
        } catch (const resolution_error&) {
            if (std::fabs(far - near) <= 1e-3 * near) throw;  // nothing resolvable beyond `near`
            far = 0.5 * (near + far);
            continue;
        }
        if ((value > 0.0) != up) break;  // a sign change between near and far
        if (up && far >= x_max) wide_against_radius(s, far * a_H, "the half-width that carries P2 is above a");
        near = far;
        far *= up ? width_step : 1.0 / width_step;
        ++steps;
    }
    const double lo = std::min(near, far), hi = std::max(near, far);
    return brent_root(F, lo, hi, 0.0, width_tolerance, max_width_iterations, "contact width search (Brent in a)");
}

// The root of F by a Newton step from x0 (F(x0) = F0, slope s0 there), then secant steps,
// until the next step is below the Brent search's tolerance: the root returned is the last
// iterate evaluated, within that tolerance of the secant's next one (whose own error is far
// smaller: superlinear convergence), so that the normal problems solved at it serve the
// contact built at the width found (normal_cache). The root's slope is the last secant's. Nothing when an
// iterate leaves (0, x_max], F or a slope is not finite or zero, or the steps do not converge
// within max_polish_steps: the caller then searches by bracket and Brent instead.
std::optional<root> secant_width(const std::function<double(double)>& F, double x0, double F0, double s0,
                                 double x_max) {
    double x_prev = x0;
    double F_prev = F0;
    double slope = s0;
    for (int step = 0; step < max_polish_steps; ++step) {
        if (F_prev == 0.0) return root{x_prev, step, slope};
        if (!(std::isfinite(slope) && slope != 0.0)) return std::nullopt;
        const double x = x_prev - F_prev / slope;
        if (!(x > 0.0 && x <= x_max)) return std::nullopt;
        if (std::fabs(x - x_prev) <= width_tolerance * x) return root{x_prev, step, slope};
        const double Fx = F(x);
        if (!std::isfinite(Fx)) return std::nullopt;
        slope = (Fx - F_prev) / (x - x_prev);
        x_prev = x;
        F_prev = Fx;
    }
    return std::nullopt;
}

contact_width search_width(const physical_scene& s, const std::function<double(const roughness&)>& load_ratio,
                           const std::function<double(const roughness&)>& cheap_load_ratio,
                           bool lambda_has_traction_term) {
    const double a_H = hertz_half_width(s, s.P2);
    // Widths beyond R/10 are refused whatever the kernels: checked before any solve, so that
    // a wide contact is told so rather than sent to a discretisation that cannot resolve it.
    const double x_max = max_width_over_radius * s.radius() / a_H;
    if (!(1.0 <= x_max)) wide_against_radius(s, a_H, "the Hertz half-width a_H");
    if (smooth(s) && !lambda_has_traction_term) return {a_H, a_H, 1.0, s.P2, 0};  // Hertz exactly, no kernel to solve

    // In x = a/a_H the model carries P2 where lambda(x) = x^2 (the coefficient of (3.19)
    // for a load normalised to P2; docs/formulation.md 2(j)). Failures name the trial width.
    const auto F = width_function(s, a_H, load_ratio);
    if (s.width == width_rule::hertz) {
        const double lambda_H = F(1.0) + 1.0;
        return {a_H, a_H, lambda_H, s.P2 / lambda_H, 0};
    }
    if (smooth(s)) {
        // Full coupling of smooth rollers: the dimensionless problem depends on a only through the
        // layers' T(a), A(a) (docs/formulation.md 8(e), "The width of a physical scene"), so without
        // layers lambda does not vary with a, F(x) = lambda - x^2, and the root is x = sqrt(lambda):
        // one coupled point (the secant polish from Johnson's root x = 1 took three).
        const double lambda = F(1.0) + 1.0;
        return {std::sqrt(lambda) * a_H, a_H, lambda, s.P2, 0};
    }
    if (cheap_load_ratio) {
        // The cheap level first: its root is within the discretisation error of the scene's,
        // so that a few solves at the scene's method polish it. Any failure of the cheap level
        // (beyond its resolution, no bracket, a root beyond R/10) or of the polish leaves the
        // answer to the search below, at the scene's method throughout: the cheap level never
        // decides what is found or refused.
        try {
            // On the cheap level from x = 1, where F = lambda - x^2 has the slope -2 for a
            // lambda that does not vary with a (the first step is then to sqrt(lambda(1)),
            // the bracket's first trial); on the scene's level from the cheap root, with the
            // cheap level's last secant slope.
            const auto G = width_function(s, a_H, cheap_load_ratio);
            // The root must lie on the side of a_H that F(a_H)'s sign points to, as the bracket's.
            const double G1 = G(1.0);
            const std::optional<root> c = secant_width(G, 1.0, G1, -2.0, x_max);
            if (c && (c->x > 1.0) == (G1 > 0.0))
                if (const std::optional<root> x = secant_width(F, c->x, F(c->x), c->slope, x_max))
                    return {x->x * a_H, a_H, x->x * x->x, s.P2, c->iterations + x->iterations};
        } catch (const error&) {
        }
    }
    const double F1 = F(1.0);
    if (F1 == 0.0) return {a_H, a_H, 1.0, s.P2, 0};
    const root x = bracketed_width(s, F, F1, a_H, x_max);
    return {x.x * a_H, a_H, x.x * x.x, s.P2, x.iterations};
}
}  // namespace

contact_width find_width(const physical_scene& s, const std::function<double(const roughness&)>& load_ratio,
                         const std::function<double(const roughness&)>& cheap_load_ratio,
                         bool lambda_has_traction_term) {
    return small_against_radius(s, search_width(s, load_ratio, cheap_load_ratio, lambda_has_traction_term));
}

}  // namespace roughroll
