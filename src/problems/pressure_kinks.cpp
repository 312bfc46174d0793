// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/pressure_kinks.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

namespace {
// g's terms that kinks_blend's rule cannot carry (only where n + 37/log(ellipse) exceeds max_nodes), relative to all:
// W_q's error is at most |beta_D| times their sum. At n = 1000 they are g's rounding plateau (the collocation's
// psi's own noise): measured 4e-10 to 1.2e-8 of all, 8e-12 to 2.2e-10 absolute, over its last 33 terms.
constexpr double blend_tail = 1e-7;
}  // namespace

void pressure_kinks::add_zone(const gauss_chebyshev& rule, double beta_d, double sign, double start, double c0,
                              const std::vector<double>& psi_b, const std::function<double(double)>& blend) {
    if (!(start > -1.0 && start < c0 && c0 < 1.0))
        throw numerical_error(
            "full coupling: a stick zone of the pressure's kinks is not inside the contact "
            "(docs/formulation.md 8(l))");
    zone z{start, 0.5 * (c0 - start), beta_d * sign, {}, nullptr};
    if (legendre_nodes_.empty()) {
        const gauss_legendre legendre(2 * rule.n + 32);
        legendre_nodes_ = legendre.nodes;
        legendre_weights_ = legendre.weights;
    }
    std::vector<double> g(static_cast<std::size_t>(rule.n));
    // int q r/sqrt(1 - r^2) dr and int q/sqrt(1 - r^2) dr over the zone: rho int sqrt(1 - t^2) g(t) (r, 1) dt,
    // by the rule's Gauss weights for sqrt(1 - t^2) (4.6), exact for the expansion g_n of degree n - 1 times r.
    double first = 0.0, zeroth = 0.0;
    for (int i = 0; i < rule.n; ++i) {
        const double r = start + z.rho * (rule.nodes[i] + 1.0);
        const double psi = u_series(psi_b, rule.nodes[i]) + (blend ? blend(rule.nodes[i]) : 0.0);
        g[i] = psi / std::sqrt(1.0 - r * r);
        first += rule.weights[i] * g[i] * r;
        zeroth += rule.weights[i] * g[i];
    }
    z.b = u_coefficients(rule, g);
    z.cauchy = std::make_shared<const cauchy_u_table>(z.b);
    load_ += z.amplitude * z.rho * first;
    constant_ += z.amplitude * z.rho * zeroth * M_1_PI;
    zones_.push_back(std::move(z));
}

double pressure_kinks::factor(double r) const {
    double h = 0.0;  // H[q/sqrt(1 - r^2)]: the zone variable's Cauchy integral (d eta/(eta - r) = d tau/(tau - t))
    for (const zone& z : zones_) h += z.amplitude * (*z.cauchy)((r - z.start) / z.rho - 1.0);
    return h;
}

double pressure_kinks::operator()(double r) const {
    if (!(std::fabs(r) < 1.0)) return 0.0;
    return std::sqrt(1.0 - r * r) * factor(r);
}

double pressure_kinks::integral(double lo, double hi) const {
    // On each piece p_q^0 is sqrt(1 - r^2) times a polynomial of the zone variable (inside a zone) or
    // an algebraic function with square roots at the zone's ends (outside): smooth in u after the map.
    std::vector<double> cuts{std::clamp(lo, -1.0, 1.0), std::clamp(hi, -1.0, 1.0)};
    for (const double e : ends())
        if (e > cuts[0] && e < cuts[1]) cuts.push_back(e);
    std::sort(cuts.begin(), cuts.end());
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double mid = 0.5 * (cuts[k] + cuts[k + 1]), half = 0.5 * (cuts[k + 1] - cuts[k]);
        if (!(half > 0.0)) continue;
        for (std::size_t i = 0; i < legendre_nodes_.size(); ++i) {
            const double u = M_PI_2 * (legendre_nodes_[i] + 1.0);  // dr = half sin u du, du = (pi/2) dx
            sum += legendre_weights_[i] * M_PI_2 * half * std::sin(u) * (*this)(mid - half * std::cos(u));
        }
    }
    return sum;
}

double pressure_kinks::removed(double r) const {
    double sum = 0.0;
    for (const zone& z : zones_) {
        const double t = (r - z.start) / z.rho - 1.0;
        if (!(std::fabs(t) < 1.0)) continue;
        sum += z.amplitude * std::sqrt((1.0 - r * r) * (1.0 - t * t)) * u_series(z.b, t);
    }
    return sum;
}

double pressure_kinks::load() const { return load_; }
double pressure_kinks::constant() const { return constant_; }

std::vector<double> pressure_kinks::ends() const {
    std::vector<double> e;
    for (const zone& z : zones_) {
        e.push_back(z.start);
        e.push_back(z.start + 2.0 * z.rho);
    }
    return e;
}

std::optional<kinks_blend> pressure_kinks::blend(double s, double c) const {
    auto unit = blended_cauchy::make({1.0}, s, c);
    if (!unit) return std::nullopt;
    kinks_blend k(std::move(*unit));
    for (const zone& z : zones_) {
        // g W_1 on the zone: g times W_1, analytic inside the Bernstein ellipse through the images of r = +-1
        // (blended_cauchy.hpp), so m >= terms + 37/log(ellipse) nodes, `terms` g's above its rounding (a smooth
        // psi's fall geometrically to it), bring W_1's part to 1e-16. At most max_nodes: g's terms beyond
        // m - 37/log(ellipse) (at large n its rounding plateau, about 1e-14 each) then bound the error relative to g.
        const double lo = (1.0 + z.start) / z.rho + 1.0, hi = (1.0 - z.start) / z.rho - 1.0;
        const auto ellipse = [](double tau) { return tau + std::sqrt((tau - 1.0) * (tau + 1.0)); };
        const double extra = std::ceil(37.0 / std::log(std::min(ellipse(lo), ellipse(hi))));
        if (!(extra > 0.0 && extra < 0.5 * max_nodes)) return std::nullopt;
        double size = 0.0;
        for (const double b : z.b) size += std::fabs(b);
        std::size_t terms = z.b.size();
        while (terms > 1 && std::fabs(z.b[terms - 1]) <= DBL_EPSILON * size) --terms;
        const int m = std::min(max_nodes, static_cast<int>(terms) + static_cast<int>(extra));
        double tail = 0.0;
        for (std::size_t j = static_cast<std::size_t>(m - static_cast<int>(extra)); j < terms; ++j) tail += std::fabs(z.b[j]);
        if (tail > blend_tail * size) return std::nullopt;
        const gauss_chebyshev rule(std::max(min_nodes, m));
        std::vector<double> values(static_cast<std::size_t>(rule.n));
        u_series(z.b, rule.nodes.data(), values.data(), values.size());  // g at the nodes, side by side (bit for bit)
        for (int i = 0; i < rule.n; ++i) {
            const auto w1 = k.unit_(z.start + z.rho * (rule.nodes[i] + 1.0));
            if (!w1) return std::nullopt;
            values[i] *= *w1;
        }
        k.parts_.push_back({z.start, z.rho, z.amplitude, z.b, u_coefficients(rule, values), z.cauchy});
    }
    return k;
}

std::optional<double> kinks_blend::operator()(double r, double blend) const {
    const auto w1 = unit_(r);
    if (!w1) return std::nullopt;
    const double root = std::sqrt((1.0 - r) * (1.0 + r));
    double sum = 0.0;
    for (const part& z : parts_) {
        const double t = (r - z.start) / z.rho - 1.0;
        const double inside =
            std::fabs(t) < 1.0 && blend != 0.0 ? root * blend * std::sqrt((1.0 - t) * (1.0 + t)) * u_series(z.g, t) : 0.0;
        sum += z.amplitude * (*w1 * (*z.cauchy)(t) - inside - cauchy_u_series(z.gw, t));
    }
    return sum;
}

void kinks_blend::operator()(const double* r, const double* blend, std::optional<double>* out, std::size_t count) const {
    // operator() at each point, bit for bit: W_1, then per part the n-term sums u_series(g) (only where the point is
    // inside the part's zone with a blend) and cauchy_u_series(g W_1) for all points at once (their batched forms).
    std::vector<std::optional<double>> w1(count);
    unit_(r, w1.data(), count);
    std::vector<double> sum(count, 0.0), t(count), inside(count), series(count), gathered, summed;
    std::vector<std::size_t> which;
    for (const part& z : parts_) {
        which.clear();
        gathered.clear();
        for (std::size_t i = 0; i < count; ++i) {
            t[i] = (r[i] - z.start) / z.rho - 1.0;
            inside[i] = 0.0;
            if (std::fabs(t[i]) < 1.0 && blend[i] != 0.0) {
                which.push_back(i);
                gathered.push_back(t[i]);
            }
        }
        summed.resize(gathered.size());
        u_series(z.g, gathered.data(), summed.data(), gathered.size());
        for (std::size_t k = 0; k < which.size(); ++k) {
            const std::size_t i = which[k];
            const double root = std::sqrt((1.0 - r[i]) * (1.0 + r[i]));
            inside[i] = root * blend[i] * std::sqrt((1.0 - t[i]) * (1.0 + t[i])) * summed[k];
        }
        cauchy_u_series(z.gw, t.data(), series.data(), count);
        for (std::size_t i = 0; i < count; ++i)
            if (w1[i]) sum[i] += z.amplitude * (*w1[i] * (*z.cauchy)(t[i]) - inside[i] - series[i]);
    }
    for (std::size_t i = 0; i < count; ++i) out[i] = w1[i] ? std::optional<double>(sum[i]) : std::nullopt;
}

double blend_kinks(double t) { return -2.0 / (15.0 * M_PI) * t * (1.0 - t * t) * (9.0 - 4.0 * t * t); }

void add_kink_points(std::vector<double>& points, const pressure_kinks& kinks, double apart) {
    if (points.empty()) return;
    const auto [lo, hi] = std::minmax_element(points.begin(), points.end());
    const double a = *lo, b = *hi;
    for (const double e : kinks.ends()) {
        if (!(e > a + apart && e < b - apart)) continue;
        if (std::all_of(points.begin(), points.end(), [&](double x) { return std::fabs(x - e) > apart; }))
            points.push_back(e);
    }
}

}  // namespace roughroll
