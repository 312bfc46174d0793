// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/layer/piecewise_averages.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll {

layer_integrals closed_form_layer_integrals(decay_kind kind, double u0) {
    layer_integrals v;
    switch (kind) {
        case decay_kind::linear: {
            // dhat = u, dhat_u = 1: int u^2, -int u, int 1 over [0, u0].
            const double u2 = u0 * u0;
            v.a = u2 * u0 / 3.0;
            v.a3 = -0.5 * u2;
            v.a33 = u0;
            break;
        }
        case decay_kind::quadratic: {
            // dhat = u^2, dhat_u = 2u: int u^4, -int 2u^3, int 4u^2.
            const double u2 = u0 * u0, u3 = u2 * u0;
            v.a = u3 * u2 / 5.0;
            v.a3 = -0.5 * u2 * u2;
            v.a33 = 4.0 * u3 / 3.0;
            break;
        }
        case decay_kind::cosine: {
            // dhat = sin(pi u/2), dhat_u = (pi/2) cos(pi u/2), x = pi u0:
            //   int sin^2(pi u/2) du = u0/2 - sin(x)/(2 pi) = (x - sin x)/(2 pi),
            //   int (pi/2)^2 cos^2(pi u/2) du = (pi^2/4)(u0/2 + sin(x)/(2 pi)) = (pi/8)(x + sin x),
            //   a3 = -sin^2(x/2)/2; sin x = 2 sin(x/2) cos(x/2): one sine and one cosine.
            const double x = M_PI * u0, s = std::sin(0.5 * x), c = std::cos(0.5 * x), sin_x = 2.0 * s * c;
            double x_minus_sin = x - sin_x;
            if (std::fabs(x) < 1.0) {
                // x - sin x = x^3/3! - x^5/5! + ...: to x^23, the next term below 1e-17 of the sum.
                x_minus_sin = 0.0;
                double term = x * x * x / 6.0;
                for (int n = 3; n <= 23; n += 2) {
                    x_minus_sin += term;
                    term *= -x * x / ((n + 1.0) * (n + 2.0));
                }
            }
            v.a = x_minus_sin / (2.0 * M_PI);
            v.a3 = -0.5 * s * s;
            v.a33 = M_PI / 8.0 * (x + sin_x);
            break;
        }
    }
    return v;
}

namespace {

// The 15-point Gauss-Kronrod rule on [-1, 1] and its embedded 7-point Gauss rule (QUADPACK,
// Piessens et al. 1983, qk15): nodes +-xgk[j] and 0 (= xgk[7]); the Gauss nodes are xgk[1],
// xgk[3], xgk[5] and 0, with the weights wg. K15 integrates polynomials of degree 22
// exactly, G7 of degree 13 (PiecewiseAverages.* of tests/test_roughness_parameters.cpp check
// the rule against the adaptive route to 1e-12: a weight wrong by 1e-10 fails them).
constexpr double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                           0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                           0.586087235467691130294144838258730, 0.405845151377397166906606412076961,
                           0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                          0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
constexpr double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                           0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                           0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                           0.204432940075298892414161999234649, 0.209482141084727828012999174891714};

// Compensated (Neumaier) summation: a sum of 1e6 pieces keeps the rounding of one addition.
class compensated_sum {
public:
    void add(double x) {
        const double t = sum_ + x;
        compensation_ += std::fabs(sum_) >= std::fabs(x) ? (sum_ - t) + x : (x - t) + sum_;
        sum_ = t;
    }
    double value() const { return sum_ + compensation_; }

private:
    double sum_ = 0.0, compensation_ = 0.0;
};

// The five integrands at one x1, in the order of `averages` below.
constexpr int n_averages = 5;
struct integrands {
    double f[n_averages];  // a/H, a h_1^2/H, a33 H, a h_1/H, a3 h_1
};

class piece_integrator {
public:
    explicit piece_integrator(const micro_geometry& g) : g_(g) {}

    // K15 and G7 of the five integrands over [lo, hi], h0(x1) given by `h0`.
    template <class Profile>
    void integrate(double lo, double hi, const Profile& h0) {
        const double centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
        double kronrod[n_averages] = {}, gauss[n_averages] = {}, absolute[n_averages] = {};
        const auto add = [&](const integrands& v, double wk, double wgauss) {
            for (int k = 0; k < n_averages; ++k) {
                kronrod[k] += wk * v.f[k];
                gauss[k] += wgauss * v.f[k];
                absolute[k] += wk * std::fabs(v.f[k]);
            }
        };
        add(at(centre, h0), wgk[7], wg[3]);
        for (int j = 0; j < 7; ++j) {
            const double dx = half * xgk[j], w_gauss = j % 2 == 1 ? wg[j / 2] : 0.0;
            add(at(centre - dx, h0), wgk[j], w_gauss);
            add(at(centre + dx, h0), wgk[j], w_gauss);
        }
        for (int k = 0; k < n_averages; ++k) {
            const double value = half * kronrod[k];
            total_[k].add(value);
            error_[k] += std::max(half * std::fabs(kronrod[k] - gauss[k]), 50.0 * DBL_EPSILON * half * absolute[k]);
        }
        evaluations_ += 15;
    }

    scaled_averages result(double l) const {
        scaled_averages r;
        const auto average = [&](int k) { return total_[k].value() / l; };
        r.value = {average(0), average(4), average(2), average(3), average(1)};
        r.error = {error_[0] / l, error_[4] / l, error_[2] / l, error_[3] / l, error_[1] / l};
        r.evaluations = evaluations_;
        return r;
    }

private:
    template <class Profile>
    integrands at(double x1, const Profile& h0) const {
        const double H = g_.material.H;
        // H - h0 is exact when h0 is within a factor 2 of H (Sterbenz).
        const layer_integrals v = closed_form_layer_integrals(g_.decay, (H - h0(x1)) / H);
        const double h1 = micro_shape_slope(g_.shape, x1, g_.material.l);
        return {{v.a, v.a * h1 * h1, v.a33, v.a * h1, v.a3 * h1}};
    }

    const micro_geometry& g_;
    compensated_sum total_[n_averages];
    double error_[n_averages] = {};
    int evaluations_ = 0;
};

}  // namespace

scaled_averages piecewise_averages(const micro_geometry& g) {
    const double l = g.material.l;
    const profile_function h0(g.bottom, l);
    const std::vector<double>& breaks = h0.breakpoints();
    const std::size_t pieces = breaks.size() - 1;
    // Equal parts per piece, so that the period has at least min_pieces.
    const std::size_t parts = (min_pieces + pieces - 1) / pieces;
    piece_integrator rule(g);
    const auto cut = [&rule, parts](double lo, double hi, const auto& profile) {
        for (std::size_t j = 0; j < parts; ++j)
            rule.integrate(lo + (hi - lo) * j / parts, j + 1 == parts ? hi : lo + (hi - lo) * (j + 1) / parts, profile);
    };
    for (std::size_t i = 0; i < pieces; ++i) {
        if (g.bottom.kind == profile_kind::measured) {
            // The spline's own cubic on the knot interval, by Horner in t = (x1 - x0)/w.
            const profile_function::cubic p = h0.piece(i);
            cut(breaks[i], breaks[i + 1], [&p](double x1) { return p((x1 - p.x0) / p.width); });
        } else {
            cut(breaks[i], breaks[i + 1], [&h0](double x1) { return h0(x1); });
        }
    }
    const scaled_averages r = rule.result(l);
    const double* values[] = {&r.value.a, &r.value.a3_h1, &r.value.a33, &r.value.a_h1, &r.value.a_h1_squared};
    for (const double* v : values) {
        if (!std::isfinite(*v))
            throw numerical_error("the piecewise rule's averages (2.9) are not finite (" + shortest(*v) + ")");
    }
    return r;
}

}  // namespace roughroll
