// SPDX-License-Identifier: GPL-3.0-or-later
// W of the blended stick zone as a mean of steps (docs/formulation.md 8(g), "W of the blend as a mean of steps").
#include "roughroll/numerics/blended_cauchy.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

namespace {
constexpr int first_intervals = 16;  // the first rule: 15 nodes, t_k = cos(k pi/16)
constexpr int levels = 7;            // 16, 32, ..., 1024 intervals: at most 1023 nodes

// The rounding of a rule's sum of 1023 terms of about `value` (4 sqrt(1024) eps |value|): a change between the last two
// rules within it is that rule's rounding, not its error; below the last rule the tolerance alone decides (at n = 1000
// the moments sigma_0 ~ 2.6 changed by 3e-15 there, above the tolerance 2e-15: the zone had been declined).
double last_rule_rounding(double value) { return 128.0 * DBL_EPSILON * std::fabs(value); }

// The nodes the rule of level l (M = 16 2^l intervals) adds: all k at level 0, the odd k after; its sum is
// the previous level's halved plus theirs.
std::vector<double> level_ks(int level) {
    const int M = first_intervals << level;
    std::vector<double> ks;
    for (int k = 1; k < M; k += level == 0 ? 1 : 2) ks.push_back(k);
    return ks;
}
}  // namespace

std::optional<blended_cauchy> blended_cauchy::make(const std::vector<double>& b, double s, double c) {
    if (!(s >= -1.0 && c <= 1.0 && s < c)) return std::nullopt;
    const double rho = 0.5 * (c - s);
    // The nearest image of e = +-1 in t fixes the Bernstein ellipse of every integrand; below exp(18.5/1023)
    // no rule here reaches the tolerance (a zone within about 1.6e-4 rho of an edge): the adaptive route.
    const auto ellipse = [](double tau) { return tau + std::sqrt((tau - 1.0) * (tau + 1.0)); };
    const double bernstein = std::min(ellipse((1.0 - c) / rho + 1.0), ellipse((1.0 + s) / rho + 1.0));
    if (!(std::log(bernstein) * most_nodes > 18.5)) return std::nullopt;

    blended_cauchy w;
    w.b_ = b;
    w.s_ = s, w.c_ = c;
    // (1 - r^2) U_j = (T_j - T_{j+2})/2: f_k = (b_k - b_{k-2})/2, k = 0..n+1.
    const std::size_t n = b.size();
    w.f_.assign(n + 2, 0.0);
    for (std::size_t k = 0; k < n + 2; ++k)
        w.f_[k] = 0.5 * ((k < n ? b[k] : 0.0) - (k >= 2 && k - 2 < n ? b[k - 2] : 0.0));
    const std::size_t moments = n + 1;  // sigma_0..sigma_{n}
    std::vector<double> sum(moments, 0.0), previous(moments, 0.0), row(moments, 0.0);
    for (int l = 0; l < levels; ++l) {
        const int M = first_intervals << l;
        std::vector<node> added;
        for (const double k : level_ks(l)) {
            // e = s + 2 rho cos^2(k pi/2M) = c - 2 rho sin^2(k pi/2M); theta_e/2 from 1 -+ e without cancellation.
            const double half = 0.5 * M_PI * k / M, sh = std::sin(half), ch = std::cos(half);
            const double hs = std::sqrt(0.5 * ((1.0 - c) + 2.0 * rho * sh * sh));
            const double hc = std::sqrt(0.5 * ((1.0 + s) + 2.0 * rho * ch * ch));
            const double weight = 2.0 / M * std::pow(std::sin(M_PI * k / M), 2);
            added.push_back({hs, hc, weight});
            // sin(j theta)/j by the recurrence of sin((j + 1) theta) = 2 cos(theta) sin(j theta) - sin((j - 1) theta).
            const double theta = 2.0 * std::atan2(hs, hc), cos_t = (hc - hs) * (hc + hs), sin_t = 2.0 * hs * hc;
            row[0] = theta;
            double before = 0.0, now = sin_t;
            for (std::size_t j = 1; j < moments; ++j) {
                row[j] = now / static_cast<double>(j);
                const double next = 2.0 * cos_t * now - before;
                before = now, now = next;
            }
            for (std::size_t j = 0; j < moments; ++j) sum[j] += weight * row[j];
        }
        w.levels_.push_back(std::move(added));
        if (l > 0) {
            double change = 0.0;
            for (std::size_t j = 0; j < moments; ++j)
                change = std::max(
                    change, std::fabs(sum[j] - previous[j]) - (l + 1 == levels ? last_rule_rounding(sum[j]) : 0.0));
            if (change <= tolerance) {
                w.sigma_ = sum;
                return w;
            }
        }
        previous = sum;
        for (double& v : sum) v *= 0.5;  // the next level's halved weights of these nodes
    }
    return std::nullopt;
}

std::optional<double> blended_cauchy::operator()(double r) const {
    if (!(r >= -1.0 && r <= 1.0)) return std::nullopt;
    // c_j(r): (F(u) - F(r))/(u - r) = sum_j c_j T_j(u), c_0 = d_0, c_j = 2 d_j, d_j = f_{j+1} + 2 r d_{j+1} - d_{j+2}.
    double smooth = 0.0, d1 = 0.0, d2 = 0.0;
    for (std::size_t j = sigma_.size(); j-- > 0;) {
        const double d = f_[j + 1] + 2.0 * r * d1 - d2;
        smooth += (j == 0 ? 1.0 : 2.0) * d * sigma_[j];
        d2 = d1, d1 = d;
    }
    return finish(r, smooth, u_series(b_, r));
}

void blended_cauchy::operator()(const double* r, std::optional<double>* out, std::size_t count) const {
    // The two Clenshaw recurrences of operator() are chains of dependent operations, n terms each: blocks of
    // points advance together, each point's operations in the order of the scalar version (bit for bit).
    constexpr std::size_t block = 8;
    std::vector<double> series(count);
    u_series(b_, r, series.data(), count);
    for (std::size_t first = 0; first < count; first += block) {
        const std::size_t width = std::min(block, count - first);
        double two_r[block] = {}, smooth[block] = {}, d1[block] = {}, d2[block] = {};
        for (std::size_t i = 0; i < width; ++i) two_r[i] = 2.0 * r[first + i];
        for (std::size_t j = sigma_.size(); j-- > 0;) {
            const double fj = f_[j + 1], weight = (j == 0 ? 1.0 : 2.0), sj = sigma_[j];
            for (std::size_t i = 0; i < block; ++i) {
                const double d = fj + two_r[i] * d1[i] - d2[i];
                smooth[i] += weight * d * sj;
                d2[i] = d1[i], d1[i] = d;
            }
        }
        for (std::size_t i = 0; i < width; ++i) {
            const double x = r[first + i];
            out[first + i] = x >= -1.0 && x <= 1.0 ? finish(x, smooth[i], series[first + i]) : std::nullopt;
        }
    }
}

std::optional<double> blended_cauchy::finish(double r, double smooth, double series) const {
    const double p = std::sqrt((1.0 - r) * (1.0 + r)) * series;
    if (p == 0.0) return M_1_PI * smooth;
    // ell(r) = int Theta' log|e - r| dt = log rho + (2/pi) int sqrt(1 - t^2) log|t - tau| dt, tau = (r - s)/rho - 1.
    const double rho = 0.5 * (c_ - s_), tau = std::fabs((r - s_) / rho - 1.0);
    const double root = tau > 1.0 ? std::sqrt((tau - 1.0) * (tau + 1.0)) : 0.0;
    const double ell = std::log(rho) - 0.5 - M_LN2 + (tau <= 1.0 ? tau * tau : tau / (tau + root) + std::acosh(tau));
    // Lambda(r) = int Theta' log sin((theta_e + alpha)/2) dt by the nested rules.
    const double sa = std::sqrt(0.5 * (1.0 - r)), ca = std::sqrt(0.5 * (1.0 + r));
    double lambda = 0.0, before = 0.0;
    const auto level_sum = [&](const std::vector<node>& nodes) {
        double add = 0.0;
        for (const node& x : nodes) add += x.weight * std::log(x.half_sin * ca + x.half_cos * sa);
        return add;
    };
    for (int l = 0; l < levels; ++l) {
        std::vector<node> computed;
        if (l >= static_cast<int>(levels_.size())) {
            // Beyond the moments' rule: this level's nodes now (rare: r near the zone where sigma converged early).
            const int M = first_intervals << l;
            const double rho2 = 2.0 * rho;
            for (const double k : level_ks(l)) {
                const double half = 0.5 * M_PI * k / M, sh = std::sin(half), ch = std::cos(half);
                computed.push_back({std::sqrt(0.5 * ((1.0 - c_) + rho2 * sh * sh)),
                                    std::sqrt(0.5 * ((1.0 + s_) + rho2 * ch * ch)),
                                    2.0 / M * std::pow(std::sin(M_PI * k / M), 2)});
            }
        }
        lambda = 0.5 * lambda + level_sum(l < static_cast<int>(levels_.size()) ? levels_[l] : computed);
        if (l > 0 && std::fabs(lambda - before) - (l + 1 == levels ? last_rule_rounding(lambda) : 0.0) <= tolerance)
            return M_1_PI * (smooth + p * (M_LN2 + 2.0 * lambda - ell));
        before = lambda;
    }
    return std::nullopt;
}

}  // namespace roughroll
