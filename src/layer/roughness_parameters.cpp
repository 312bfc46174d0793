// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/layer/roughness_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include <gsl/gsl_integration.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/gsl_handles.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/layer/piecewise_averages.hpp"

namespace roughroll {
namespace {

// The adaptive rule for every integral: Gauss-Kronrod 21 (qag key 2). The integrands are
// smooth on each piece (the pieces split a measured profile at its knots), so a high-order
// rule reaches the tolerance in few subdivisions.
constexpr int rule = GSL_INTEG_GAUSS21;
constexpr std::size_t workspace_intervals = 1000;

struct quadrature_result {
    double value = 0.0;
    double error = 0.0;
};

// qag of a C++ callable over [lo, hi]. GSL is C: an exception thrown by the integrand must
// not unwind through it, so it is caught, the integrand returns NaN, and it is rethrown here
// once qag has returned.
template <class F>
quadrature_result qag(const F& f, double lo, double hi, double epsabs, double epsrel, gsl_integration_workspace* w,
                      const std::string& what) {
    struct context {
        const F* f;
        std::exception_ptr failure;
    } c{&f, nullptr};
    gsl_function g;
    g.function = [](double x, void* p) -> double {
        auto* ctx = static_cast<context*>(p);
        if (ctx->failure) return std::nan("");
        try {
            return (*ctx->f)(x);
        } catch (...) {
            ctx->failure = std::current_exception();
            return std::nan("");
        }
    };
    g.params = &c;
    quadrature_result r;
    const int status =
        gsl_integration_qag(&g, lo, hi, epsabs, epsrel, workspace_intervals, rule, w, &r.value, &r.error);
    if (c.failure) std::rethrow_exception(c.failure);
    gsl_check(status, what);
    if (!std::isfinite(r.value)) throw numerical_error(what + ": not finite (" + shortest(r.value) + ")");
    return r;
}

// The layer integrals of (2.6)-(2.8) at one x1, dimensionless: in the depth below the top
// u = (H - x2)/H, with dhat(u) = d(H (1 - u)) and dhat_u = d dhat/du = -H d' (micro_geometry.hpp),
//   a   = H   int_0^u0 dhat^2 du          a3 = -int_0^u0 dhat dhat_u du
//   a33 = 1/H int_0^u0 dhat_u^2 du,       u0 = (H - h0(x1))/H,
// and `at` returns the integrals alone (a/H, a3, a33 H): H is factored out analytically, so
// neither d'^2 = O(1/H^2) nor d^2 H can leave the range of double for any H, and the
// integrands are exact as u -> 0, where 1 - x2/H would cancel (h0 -> H).
class layer_integrator {
public:
    explicit layer_integrator(const micro_geometry& g)
        : g_(g), h0_(g.bottom, g.material.l), work_(make_integration_workspace(workspace_intervals)) {
        // The absolute floors: inner_tolerance of each integral over the whole layer (u0 = 1,
        // the flat profile's), the scale of the averages the inner integrals feed.
        const layer_integrals whole = integrate(1.0, true, true, true, {0.0, 0.0, 0.0}, " over the whole layer");
        floor_ = {inner_tolerance * whole.a, inner_tolerance * std::fabs(whole.a3), inner_tolerance * whole.a33};
    }

    double h0(double x1) const { return h0_(x1); }
    const profile_function& profile() const { return h0_; }

    // Only the integrals asked for are computed (a alone for <a>, ...). Dimensionless.
    layer_integrals at(double x1, bool a, bool a3, bool a33) const {
        const double H = g_.material.H;
        // H - h0 is exact when h0 is within a factor 2 of H (Sterbenz).
        const double u0 = (H - h0_(x1)) / H;
        return integrate(u0, a, a3, a33, floor_, " at x1 = " + shortest(x1));
    }

private:
    struct floors {
        double a, a3, a33;
    };

    layer_integrals integrate(double u0, bool a, bool a3, bool a33, const floors& floor,
                              const std::string& where) const {
        const decay_kind k = g_.decay;
        layer_integrals r;
        // Every integrand is of one sign (dhat >= 0, dhat_u > 0): the relative tolerance, with
        // the absolute floor for an integral that is small against the whole layer's.
        if (a) {
            const auto q = qag(
                [k](double u) {
                    const double d = decay_value_from_top(k, u);
                    return d * d;
                },
                0.0, u0, floor.a, inner_tolerance, work_.get(), "the integral a of (2.6)" + where);
            r.a = q.value;
            r.a_error = q.error;
        }
        if (a3) {
            const auto q = qag([k](double u) { return -decay_value_from_top(k, u) * decay_slope_from_top(k, u); }, 0.0,
                               u0, floor.a3, inner_tolerance, work_.get(), "the integral a3 of (2.7)" + where);
            r.a3 = q.value;
            r.a3_error = q.error;
        }
        if (a33) {
            const auto q = qag(
                [k](double u) {
                    const double s = decay_slope_from_top(k, u);
                    return s * s;
                },
                0.0, u0, floor.a33, inner_tolerance, work_.get(), "the integral a33 of (2.8)" + where);
            r.a33 = q.value;
            r.a33_error = q.error;
        }
        return r;
    }

    const micro_geometry& g_;
    profile_function h0_;
    integration_workspace_ptr work_;  // the inner integrals' (the outer one has its own)
    floors floor_{0.0, 0.0, 0.0};
};

// One average (2.9): (1/l) int_0^l weight(x1) * inner(x1) dx1, split at the breakpoints.
// `inner` returns {value, error} of the layer integral; the error estimate of the average is
// the outer quadrature's over l plus the largest inner error times |weight|.
template <class Integrand>
quadrature_result average(const Integrand& integrand, const std::vector<double>& breaks, double l, double epsabs,
                          gsl_integration_workspace* w, int& evaluations, const std::string& what) {
    double inner_error = 0.0;
    const auto f = [&](double x1) {
        ++evaluations;
        const quadrature_result v = integrand(x1);
        inner_error = std::max(inner_error, v.error);
        return v.value;
    };
    quadrature_result total;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double width = breaks[i + 1] - breaks[i];
        const quadrature_result piece =
            qag(f, breaks[i], breaks[i + 1], epsabs * width, outer_tolerance, w, "the average " + what + " of (2.9)");
        total.value += piece.value;
        total.error += piece.error;
    }
    return {total.value / l, total.error / l + inner_error};
}

}  // namespace

layer_integrals integrals_at(const micro_geometry& g, double x1) {
    check_conditions(g);
    const double H = g.material.H;
    layer_integrals v = layer_integrator(g).at(x1, true, true, true);
    v.a *= H;
    v.a_error *= H;
    v.a33 /= H;
    v.a33_error /= H;
    return v;
}

roughness_parameters parameters_from_averages(const layer_averages& m, double lambda0, double mu0,
                                              normal_factor factor) {
    if (!(m.a_h1_squared > 0.0) || !std::isfinite(m.a_h1_squared)) {
        throw numerical_error("<a h_1^2> = " + shortest(m.a_h1_squared) +
                              " is not positive: (2.11)-(2.14) divide by it");
    }
    const double stiff = lambda0 + 2.0 * mu0;
    const double ratio = normal_factor_ratio(factor, lambda0, mu0);  // (2.12), E11
    // The correctors as x (x/q): <a h_1>^2 alone would leave double for H beyond about 1e+-154.
    const double corrector_k = m.a3_h1 * (m.a3_h1 / m.a_h1_squared);  // the corrector's share, (2.11)
    const double corrector_t = m.a_h1 * (m.a_h1 / m.a_h1_squared);    // (2.13)
    roughness_parameters p;
    p.averages = m;
    p.k_tangential = mu0 * (m.a33 - corrector_k);
    p.k_normal = stiff * (m.a33 - ratio * ratio * corrector_k);
    p.t_tangential = 0.5 * stiff * (m.a - corrector_t);
    p.t_normal = 0.5 * mu0 * (m.a - corrector_t);
    // Cauchy-Schwarz makes k, t >= 0; zero or a rounding below it would make alpha 0 or NaN.
    const std::pair<const char*, double> values[] = {{"k_tangential (2.11)", p.k_tangential},
                                                     {"k_normal (2.12)", p.k_normal},
                                                     {"t_tangential (2.13)", p.t_tangential},
                                                     {"t_normal (2.14)", p.t_normal}};
    for (const auto& [name, v] : values) {
        if (!(std::isfinite(v) && v > 0.0))
            throw numerical_error(std::string(name) + " = " + shortest(v) + " is not finite and > 0");
    }
    // sqrt(k)/sqrt(2t): k/(2t) = O(1/H^2) would leave double for H beyond about 1e+-154.
    p.alpha_tangential = std::sqrt(p.k_tangential) / std::sqrt(2.0 * p.t_tangential);
    p.alpha_normal = std::sqrt(p.k_normal) / std::sqrt(2.0 * p.t_normal);
    return p;
}

namespace {

// The five averages by nested qag (averages_rule::adaptive).
scaled_averages adaptive_averages(const micro_geometry& g) {
    const layer_integrator layer(g);
    const integration_workspace_ptr work = make_integration_workspace(workspace_intervals);
    const double l = g.material.l;
    const std::vector<double>& breaks = layer.profile().breakpoints();
    const micro_shape_kind shape = g.shape;
    const auto h1 = [shape, l](double x1) { return micro_shape_slope(shape, x1, l); };
    int evaluations = 0;

    const auto a_times = [&](int power) {
        return [&, power](double x1) {
            const layer_integrals v = layer.at(x1, true, false, false);
            const double w = std::pow(h1(x1), power);
            return quadrature_result{w * v.a, std::fabs(w) * v.a_error};
        };
    };
    // The one-signed averages first: they bound the signed ones (Cauchy-Schwarz), which gives
    // those an absolute tolerance (a relative one cannot be met by an average that is 0).
    const quadrature_result a = average(a_times(0), breaks, l, 0.0, work.get(), evaluations, "<a>");
    const quadrature_result a_h1_squared = average(a_times(2), breaks, l, 0.0, work.get(), evaluations, "<a h_1^2>");
    const quadrature_result a33 = average(
        [&](double x1) {
            const layer_integrals v = layer.at(x1, false, false, true);
            return quadrature_result{v.a33, v.a33_error};
        },
        breaks, l, 0.0, work.get(), evaluations, "<a33>");
    const quadrature_result a_h1 =
        average(a_times(1), breaks, l, outer_tolerance * std::sqrt(a.value) * std::sqrt(a_h1_squared.value), work.get(),
                evaluations, "<a h_1>");
    const quadrature_result a3_h1 = average(
        [&](double x1) {
            const layer_integrals v = layer.at(x1, false, true, false);
            const double w = h1(x1);
            return quadrature_result{w * v.a3, std::fabs(w) * v.a3_error};
        },
        breaks, l, outer_tolerance * std::sqrt(a33.value) * std::sqrt(a_h1_squared.value), work.get(), evaluations,
        "<a3 h_1>");
    scaled_averages r;
    r.value = {a.value, a3_h1.value, a33.value, a_h1.value, a_h1_squared.value};
    r.error = {a.error, a3_h1.error, a33.error, a_h1.error, a_h1_squared.error};
    r.evaluations = evaluations;
    return r;
}

}  // namespace

roughness_parameters compute_roughness_parameters(const micro_geometry& g, averages_rule rule) {
    check_conditions(g);
    const bool piecewise = rule == averages_rule::piecewise ||
                           (rule == averages_rule::automatic && g.bottom.kind == profile_kind::measured);
    const scaled_averages s = piecewise ? piecewise_averages(g) : adaptive_averages(g);
    const layer_averages& v = s.value;
    const layer_averages& e = s.error;

    // The averages above are of the dimensionless integrals (a/H, a3, a33 H): back to SI.
    const double H = g.material.H;
    const layer_averages m{H * v.a, v.a3_h1, v.a33 / H, H * v.a_h1, H * v.a_h1_squared};
    roughness_parameters p = parameters_from_averages(m, g.material.lambda0, g.material.mu0, g.factor_2_12);
    p.averages_error = {H * e.a, e.a3_h1, e.a33 / H, H * e.a_h1, H * e.a_h1_squared};
    p.evaluations = s.evaluations;

    // First-order propagation of the averages' errors through (2.11)-(2.15), in the
    // dimensionless averages (each product kept within the range of double).
    const double q = v.a_h1_squared, rk = v.a3_h1 / q, rt = v.a_h1 / q;
    const double dk = (2.0 * std::fabs(rk) * e.a3_h1 + rk * rk * e.a_h1_squared) / H;       // 1/m
    const double dt = H * (e.a + 2.0 * std::fabs(rt) * e.a_h1 + rt * rt * e.a_h1_squared);  // m
    const double stiff = g.material.lambda0 + 2.0 * g.material.mu0;
    const double ratio = normal_factor_ratio(g.factor_2_12, g.material.lambda0, g.material.mu0);  // (2.12), E11
    const double a33_error = e.a33 / H;
    p.k_tangential_error = g.material.mu0 * (a33_error + dk);
    p.k_normal_error = stiff * (a33_error + ratio * ratio * dk);
    p.t_tangential_error = 0.5 * stiff * dt;
    p.t_normal_error = 0.5 * g.material.mu0 * dt;
    // alpha = sqrt(k/2t): d(alpha)/alpha = (dk/k + dt/t)/2.
    p.alpha_tangential_error =
        0.5 * p.alpha_tangential * (p.k_tangential_error / p.k_tangential + p.t_tangential_error / p.t_tangential);
    p.alpha_normal_error = 0.5 * p.alpha_normal * (p.k_normal_error / p.k_normal + p.t_normal_error / p.t_normal);
    return p;
}

}  // namespace roughroll
