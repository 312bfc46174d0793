// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/cauchy_u_table.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

namespace {
constexpr int size = theta_panels::degree + 1;

// The least panel count from `start` on (growing by an eighth) whose bound is at most eps.
template <class Bound>
int panels_for(int start, const Bound& bound) {
    int panels = std::max(1, start);
    while (!(bound(panels) <= DBL_EPSILON)) panels += std::max(1, panels / 8);
    return panels;
}
}  // namespace

double cauchy_u_table::inner_bound(int n, double length) {
    return theta_panels::ellipse_bound(0.5 * length, [n](double y, double) { return std::exp(n * y); });
}

double cauchy_u_table::outer_bound(int n, double length) {
    const double h = 0.5 * length;
    return theta_panels::ellipse_bound(h, [n, h](double, double x) { return std::exp(n * std::max(0.0, x - h)); });
}

cauchy_u_table::cauchy_u_table(const std::vector<double>& b) : b_(b) {
    double l1 = 0.0;
    for (const double bj : b) l1 += std::fabs(bj);
    if (b.empty() || !std::isfinite(l1)) throw numerical_error("cauchy_u_table: the series is empty or not finite");
    b_.resize(significant_terms(b_));
    const int n = static_cast<int>(b_.size());
    tail_.assign(b_.size() + 1, 0.0);
    for (int j = n; j-- > 0;) tail_[j] = tail_[j + 1] + std::fabs(b_[j]);

    // Inside: -sum b_j cos((j+1) phi) at the nodes, the cosines by rotation (rounding j eps, as the series').
    const int inner = panels_for(static_cast<int>(std::ceil(M_PI * n / 8.0)),
                                 [n](int p) { return inner_bound(n, M_PI / p); });
    inside_ = theta_panels(inner);
    std::vector<double> values(static_cast<std::size_t>(inner) * size);
    for (int p = 0; p < inner; ++p)
        for (int i = 0; i < size; ++i) {
            const double phi = inside_.node(p, i), c1 = std::cos(phi), s1 = std::sin(phi);
            double c = c1, s = s1, sum = 0.0;
            for (int j = 0; j < n; ++j) {
                sum += b_[j] * c;
                const double next = c * c1 - s * s1;
                s = s * c1 + c * s1;
                c = next;
            }
            values[static_cast<std::size_t>(p) * size + i] = -sum;
        }
    inside_.set_values(values);

    // Outside: -sum b_j z^(j+1), z = +-e^(-w), on panels of [0, w_top].
    outer_panels_ = panels_for(static_cast<int>(std::ceil(w_top * n / 8.0)),
                               [n](int p) { return outer_bound(n, w_top / p); });
    outer_length_ = w_top / outer_panels_;
    const std::vector<double> to_c = theta_panels::values_to_coefficients();
    for (int side = 0; side < 2; ++side) {
        std::vector<double>& c = outer_[side];
        c.assign(static_cast<std::size_t>(outer_panels_) * size, 0.0);
        for (int p = 0; p < outer_panels_; ++p) {
            double v[size];
            for (int i = 0; i < size; ++i) {
                const double w = i == theta_panels::degree ? (p + 1) * outer_length_
                                                           : (p + 0.5 * (theta_panels::lobatto(i) + 1.0)) * outer_length_;
                const double z = side == 0 ? std::exp(-w) : -std::exp(-w);
                double zp = z, sum = 0.0;
                for (int j = 0; j < n; ++j) {
                    sum += b_[j] * zp;
                    zp *= z;
                }
                v[i] = -sum;
            }
            for (int k = 0; k < size; ++k) {
                double sum = 0.0;
                for (int i = 0; i < size; ++i) sum += to_c[k * size + i] * v[i];
                c[static_cast<std::size_t>(p) * size + k] = sum;
            }
        }
    }
    // The tables' bounds, and beyond() stopping where its rest is below eps B / 4.
    bound_ = std::max({inner_bound(n, M_PI / inner), outer_bound(n, outer_length_), 0.25 * DBL_EPSILON}) * l1;
}

double cauchy_u_table::outer(double w, int side) const {
    const int p = std::min(outer_panels_ - 1, static_cast<int>(w / outer_length_));
    const double* c = &outer_[side][static_cast<std::size_t>(p) * size];
    return theta_panels::panel_sum(c, 2.0 * (w - p * outer_length_) / outer_length_ - 1.0);
}

double cauchy_u_table::beyond(double x) const {
    // |z| < e^(-w_top): the terms fall geometrically; stopped where the rest |z|^(j+1) sum_{k>=j} |b_k| is below
    // eps B / 4. z = x - sgn(x) sqrt(x^2 - 1) as its reciprocal, which does not cancel at large |x|.
    const double z = 1.0 / (x + std::copysign(std::sqrt(x * x - 1.0), x));
    const double floor = 0.25 * DBL_EPSILON * tail_[0];
    double zp = z, sum = 0.0;
    for (std::size_t j = 0; j < b_.size(); ++j) {
        if (std::fabs(zp) * tail_[j] <= floor) break;
        sum += b_[j] * zp;
        zp *= z;
    }
    return -sum;
}

double cauchy_u_table::operator()(double x) const {
    if (std::fabs(x) < 1.0) return inside_(x);
    const double w = std::acosh(std::fabs(x));
    if (!(w <= w_top)) return beyond(x);
    return outer(w, x > 0.0 ? 0 : 1);
}

}  // namespace roughroll
