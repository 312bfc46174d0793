// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/variable_k_weight.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/gsl_handles.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"

namespace roughroll {

namespace {

void check_zones(const std::vector<double>& ends, std::size_t zones, const char* what) {
    if (ends.size() < 2 || ends.size() != zones + 1 || ends.front() != -1.0 || ends.back() != 1.0)
        throw numerical_error(std::string(what) + ": the zone ends must run from -1 to 1, one more than the zones");
    for (std::size_t j = 1; j < ends.size(); ++j)
        if (!(ends[j] > ends[j - 1]))
            throw numerical_error(std::string(what) + ": the zone ends must increase (zone " + std::to_string(j) +
                                  " is empty)");
}

// Gauss-Jacobi rules of the discretisations, by their size and exponents (exact keys: the exponents come from one table).
// Kept between calls, per thread (a Newton step rebuilds the rule with the same exponents at the edges and sizes that are
// multiples of 8: building them again was a sixth of a rebuild, 8(z) "The cost"); at most 512 rules, then started afresh.
class panel_rules {
public:
    const gauss_jacobi& rule(int points, double right, double left) {
        for (const std::unique_ptr<gauss_jacobi>& r : rules_)
            if (r->n == points && r->a == right && r->b == left) return *r;
        if (rules_.size() >= 512) rules_.clear();
        rules_.push_back(std::make_unique<gauss_jacobi>(points, right, left));
        return *rules_.back();
    }

private:
    std::vector<std::unique_ptr<gauss_jacobi>> rules_;
};

panel_rules& shared_rules() {
    thread_local panel_rules rules;
    return rules;
}

struct discrete_measure {
    std::vector<double> x, w;
};

// The points of a panel [u, v] for inner products of degree <= 2 count - 1 (8(z), "The cost"). A polynomial of degree d
// bounded on [-1, 1] is cos(d theta) in the Chebyshev angle: on a panel spanning the angle acos u - acos v it turns
// through d (acos u - acos v) and Gauss's N points integrate it when 2 N exceeds that by a margin: twice the
// full-interval count per angle (count points for degree 2 count - 1 on [-1, 1]; measured: 1.0 times leaves the
// points 0.05 off the exact collocation at n = 256, 1.25 times the nodes 1.7e-13 off the dense route's, 2 times within
// rounding, 8(z)) plus the 24 of the analytic rest (Bernstein ellipse rho >= 5.8: 5.8^-48). Rounded up to a multiple
// of 8 (fewer distinct rules to build), never above the dense route's count + 24.
int panel_points(double u, double v, int count, discretisation how) {
    if (how == discretisation::dense) return count + 24;
    const double angle = std::acos(std::clamp(u, -1.0, 1.0)) - std::acos(std::clamp(v, -1.0, 1.0));
    const int p = 24 + static_cast<int>(std::ceil(2.0 * count * angle / M_PI));
    return std::min(count + 24, 8 * ((p + 7) / 8));
}

// The discrete measure of one panel [u, v] of zone `zone`: Gauss-Jacobi with the powers of the zone ends it touches,
// the other powers and m at its points.
void panel_measure(const piecewise_power_weight& pw, int zone, double u, double v, int count, discretisation how,
                   panel_rules& rules, discrete_measure& out) {
    const int points = panel_points(u, v, count, how);
    const double length = v - u;
    int ju = -1, jv = -1;
    for (std::size_t j = 0; j < pw.ends.size(); ++j) {
        if (pw.ends[j] == u) ju = static_cast<int>(j);
        if (pw.ends[j] == v) jv = static_cast<int>(j);
    }
    const double beta = ju >= 0 ? pw.exponents[ju] : 0.0, alpha = jv >= 0 ? pw.exponents[jv] : 0.0;
    const gauss_jacobi& r = rules.rule(points, alpha, beta);
    const double half = 0.5 * length, mid = 0.5 * (u + v);
    const double scale = pw.factors[zone] * std::pow(half, 1.0 + alpha + beta);
    for (int k = 0; k < r.n; ++k) {
        const double x = mid + half * r.nodes[k];
        double f = scale * r.weights[k];
        for (std::size_t j = 0; j < pw.ends.size(); ++j)
            if (static_cast<int>(j) != ju && static_cast<int>(j) != jv && pw.exponents[j] != 0.0)
                f *= std::pow(std::fabs(x - pw.ends[j]), pw.exponents[j]);
        if (pw.smooth) f *= pw.smooth(x);
        out.x.push_back(x);
        out.w.push_back(f);
    }
}

void append(const discrete_measure& m, discrete_measure* out, std::size_t& size) {
    size += m.x.size();
    if (!out) return;
    out->x.insert(out->x.end(), m.x.begin(), m.x.end());
    out->w.insert(out->w.end(), m.w.begin(), m.w.end());
}

// A panel [u, v] of zone `zone` is resolved when every zone end other than u and v lies at least v - u away from it
// (8(z)); otherwise it is halved. The panel's own ends carry their powers in the Gauss-Jacobi rule. A null measure
// only counts (`size`).
void add_panel(const piecewise_power_weight& pw, int zone, double u, double v, int count, discretisation how,
               panel_rules& rules, discrete_measure* out, std::size_t& size, int depth) {
    const double length = v - u;
    bool resolved = true;
    for (double s : pw.ends) {
        if (s == u || s == v) continue;
        const double d = s < u ? u - s : s - v;
        if (d < length) resolved = false;
    }
    // A finitely smooth factor m is graded towards the zone ends it touches (8(z), "A varying k"), to 2^-16 of the zone:
    // the dense route towards every end; the economical one only towards the ends where it is not analytic (`rough`:
    // an end next to a zone where k varies), and there only as deep as m needs (below).
    const bool all = how == discretisation::dense || pw.rough.empty();
    bool rough_end = false;
    if (pw.smooth && length > std::ldexp(pw.ends[zone + 1] - pw.ends[zone], -16))
        rough_end = (u == pw.ends[zone] && (all || pw.rough[zone])) || (v == pw.ends[zone + 1] && (all || pw.rough[zone + 1]));
    if (!resolved || (rough_end && all)) {
        if (depth > 200) throw numerical_error("variable-k weight: a panel could not be resolved (zone ends too close)");
        const double m = 0.5 * (u + v);
        add_panel(pw, zone, u, m, count, how, rules, out, size, depth + 1);
        add_panel(pw, zone, m, v, count, how, rules, out, size, depth + 1);
        return;
    }
    if (!rough_end && !out) {
        size += static_cast<std::size_t>(panel_points(u, v, count, how));
        return;
    }
    discrete_measure whole;
    panel_measure(pw, zone, u, v, count, how, rules, whole);
    if (!rough_end) {
        append(whole, out, size);
        return;
    }
    // The grading's depth from m itself (8(z), "The cost"): m ~ 1 + c d^b (log d) at a rough end (b = 9/2 for 8(x)'s
    // blend, 1 for a k whose derivative jumps there), and a Gauss rule on the panel touching the end errs by about
    // c h^(b+1) N^-(2b+2), the same on the half touching it with h/2: the panel's rule against its two halves' estimates
    // the panel's error and bounds the halves' (their error is 2^-(b+1) of it). Both the mass and the moment of
    // T_{2 count - 1}, the fastest turning polynomial the recurrence integrates, within 1e-14 of the panel's mass: the
    // halves are kept; otherwise both halves are examined again, down to the dense route's 2^-16 of the zone.
    const double mid = 0.5 * (u + v);
    discrete_measure left, right;
    panel_measure(pw, zone, u, mid, count, how, rules, left);
    panel_measure(pw, zone, mid, v, count, how, rules, right);
    const int degree = 2 * count - 1;
    auto moments = [degree](const discrete_measure& m, double& mass, double& turning) {
        for (std::size_t k = 0; k < m.x.size(); ++k) {
            mass += m.w[k];
            turning += m.w[k] * std::cos(degree * std::acos(std::clamp(m.x[k], -1.0, 1.0)));
        }
    };
    double m0 = 0.0, t0 = 0.0, m1 = 0.0, t1 = 0.0;
    moments(whole, m0, t0);
    moments(left, m1, t1);
    moments(right, m1, t1);
    if (std::fabs(m1 - m0) <= 1e-14 * std::fabs(m1) && std::fabs(t1 - t0) <= 1e-14 * std::fabs(m1)) {
        append(left, out, size);
        append(right, out, size);
        return;
    }
    add_panel(pw, zone, u, mid, count, how, rules, out, size, depth + 1);
    add_panel(pw, zone, mid, v, count, how, rules, out, size, depth + 1);
}

void check_weight(const piecewise_power_weight& pw, int count) {
    check_zones(pw.ends, pw.factors.size(), "variable-k weight");
    if (pw.exponents.size() != pw.ends.size() || count < 1 || !(pw.rough.empty() || pw.rough.size() == pw.ends.size()))
        throw numerical_error("variable-k weight: one exponent (and flag) per zone end and at least one term are needed");
    for (double e : pw.exponents)
        if (!(e > -1.0)) throw numerical_error("variable-k weight: an exponent at a zone end is not above -1");
}

}  // namespace

double piecewise_power_weight::operator()(double x) const {
    if (x < -1.0 || x > 1.0) return 0.0;
    double f = factors[zone_of(x)];
    for (std::size_t j = 0; j < ends.size(); ++j)
        if (exponents[j] != 0.0) f *= std::pow(std::fabs(x - ends[j]), exponents[j]);
    return smooth ? f * smooth(x) : f;
}

int piecewise_power_weight::zone_of(double x) const {
    const int zones = static_cast<int>(factors.size());
    const int i = static_cast<int>(std::upper_bound(ends.begin(), ends.end(), x) - ends.begin()) - 1;
    return std::clamp(i, 0, zones - 1);
}

std::size_t discretisation_size(const piecewise_power_weight& pw, int count, discretisation how) {
    check_weight(pw, count);
    panel_rules& rules = shared_rules();
    std::size_t size = 0;
    for (std::size_t i = 0; i + 1 < pw.ends.size(); ++i)
        add_panel(pw, static_cast<int>(i), pw.ends[i], pw.ends[i + 1], count, how, rules, nullptr, size, 0);
    return size;
}

orthogonal_recurrence recurrence_of(const piecewise_power_weight& pw, int count, discretisation how) {
    gsl_guard();
    check_weight(pw, count);
    panel_rules& rules = shared_rules();
    discrete_measure m;
    std::size_t size = 0;
    for (std::size_t i = 0; i + 1 < pw.ends.size(); ++i)
        add_panel(pw, static_cast<int>(i), pw.ends[i], pw.ends[i + 1], count, how, rules, &m, size, 0);
    // Stieltjes in its orthonormal form (Lanczos on diag(x) from sqrt(w)): p_{-1} = 0, p_0 = 1/sqrt(beta_0),
    // alpha_j = <x p_j, p_j>, sqrt(beta_{j+1}) p_{j+1} = (x - alpha_j) p_j - sqrt(beta_j) p_{j-1}.
    const std::size_t N = m.x.size();
    orthogonal_recurrence r;
    r.alpha.resize(count);
    r.beta.resize(count);
    double beta0 = 0.0;
    for (double wi : m.w) beta0 += wi;
    r.beta[0] = beta0;
    std::vector<double> p(N, 1.0 / std::sqrt(beta0)), prev(N, 0.0), next(N);
    for (int j = 0; j < count; ++j) {
        double a = 0.0;
        for (std::size_t i = 0; i < N; ++i) a += m.w[i] * m.x[i] * p[i] * p[i];
        r.alpha[j] = a;
        if (j + 1 == count) break;
        const double sb = j == 0 ? 0.0 : std::sqrt(r.beta[j]);
        double b = 0.0;
        for (std::size_t i = 0; i < N; ++i) {
            next[i] = (m.x[i] - a) * p[i] - sb * prev[i];
            b += m.w[i] * next[i] * next[i];
        }
        if (!(b > 0.0) || !std::isfinite(b)) throw numerical_error("variable-k weight: the Stieltjes procedure broke down");
        r.beta[j + 1] = b;
        const double inv = 1.0 / std::sqrt(b);
        for (std::size_t i = 0; i < N; ++i) {
            prev[i] = p[i];
            p[i] = next[i] * inv;
        }
    }
    return r;
}

namespace {
// sqrt(a^2 + b^2): std::hypot (a quarter of the rule's cost, 8(z) "The cost") only where a square could overflow or
// underflow; the QL sweep's entries are those of a Jacobi matrix on [-1, 1], below 2 in size, except a shift's g.
inline double pythag(double a, double b) {
    const double m = std::max(std::fabs(a), std::fabs(b));
    return m < 1e150 && m > 1e-150 ? std::sqrt(a * a + b * b) : std::hypot(a, b);
}
}  // namespace

gauss_rule gauss_rule_of(const orthogonal_recurrence& r, int n) {
    gsl_guard();
    if (n < 1 || static_cast<int>(r.alpha.size()) < n)
        throw numerical_error("Gauss rule of " + std::to_string(n) + " nodes from a shorter recurrence");
    // Golub and Welsch: the nodes are the eigenvalues of the Jacobi matrix. The implicit QL iteration with Wilkinson
    // shifts on the tridiagonal matrix (Numerical Recipes' tqli, after EISPACK's imtql1), eigenvalues only: O(n^2),
    // where a dense eigensolver costs O(n^3); the weights come from the Christoffel function below.
    std::vector<double> d(r.alpha.begin(), r.alpha.begin() + n), e(n, 0.0);
    for (int j = 0; j + 1 < n; ++j) e[j] = std::sqrt(r.beta[j + 1]);
    for (int l = 0; l < n; ++l) {
        int iter = 0, m = l;
        do {
            for (m = l; m < n - 1; ++m) {
                const double dd = std::fabs(d[m]) + std::fabs(d[m + 1]);
                if (std::fabs(e[m]) <= GSL_DBL_EPSILON * dd) break;
            }
            if (m == l) break;
            if (++iter > 60)
                throw numerical_error("Gauss rule of a variable-k weight: the QL iteration did not converge at n = " +
                                      std::to_string(n));
            double g = (d[l + 1] - d[l]) / (2.0 * e[l]);
            double rr = pythag(g, 1.0);
            g = d[m] - d[l] + e[l] / (g + (g >= 0.0 ? std::fabs(rr) : -std::fabs(rr)));
            double s = 1.0, c = 1.0, p = 0.0;
            int i = m - 1;
            bool underflow = false;
            for (; i >= l; --i) {
                const double f = s * e[i], b = c * e[i];
                e[i + 1] = rr = pythag(f, g);
                if (rr == 0.0) {
                    d[i + 1] -= p;
                    e[m] = 0.0;
                    underflow = true;
                    break;
                }
                s = f / rr;
                c = g / rr;
                g = d[i + 1] - p;
                rr = (d[i] - g) * s + 2.0 * c * b;
                p = s * rr;
                d[i + 1] = g + p;
                g = c * rr - b;
            }
            if (underflow) continue;
            d[l] -= p;
            e[l] = g;
            e[m] = 0.0;
        } while (m != l);
    }
    std::vector<int> order(n);
    for (int k = 0; k < n; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](int i, int j) { return d[i] < d[j]; });
    gauss_rule g;
    g.nodes.resize(n);
    g.weights.resize(n);
    // The weights by the Christoffel function, W_k = 1/sum_{j<n} p_j(t_k)^2 (p_j orthonormal): relative accuracy for
    // the small weights next to the ends, where beta_0 v_{0k}^2 keeps only absolute accuracy (2.6e-10 relative at
    // n = 1000 against GSL's Gauss-Jacobi rule, 8(z)).
    for (int k = 0; k < n; ++k) {
        // One Newton step on sqrt(beta_n) p_n = (t - alpha_{n-1}) p_{n-1} - sqrt(beta_{n-1}) p_{n-2} (with its
        // derivative by the same recurrence) polishes the QL eigenvalue to the recurrence's own accuracy.
        double t = d[order[k]];
        {
            double pm = 0.0, p0 = 1.0 / std::sqrt(r.beta[0]), dm = 0.0, d0 = 0.0;
            for (int j = 0; j < n; ++j) {
                const double sb = j == 0 ? 0.0 : std::sqrt(r.beta[j]);
                const double scale = j + 1 < n ? 1.0 / std::sqrt(r.beta[j + 1]) : 1.0;
                const double p1 = ((t - r.alpha[j]) * p0 - sb * pm) * scale;
                const double d1 = (p0 + (t - r.alpha[j]) * d0 - sb * dm) * scale;
                pm = p0;
                p0 = p1;
                dm = d0;
                d0 = d1;
            }
            // Taken only while it stays within a quarter of the gaps to the neighbouring QL values: a step that
            // would carry the node towards the next root (a cluster at a zone end) is not a polish.
            const double step = p0 / d0, left = k > 0 ? d[order[k]] - d[order[k - 1]] : HUGE_VAL,
                         right = k + 1 < n ? d[order[k + 1]] - d[order[k]] : HUGE_VAL;
            if (d0 != 0.0 && std::isfinite(step) && std::fabs(step) < 0.25 * std::min(left, right)) t -= step;
        }
        g.nodes[k] = t;
        double prev = 0.0, p = 1.0 / std::sqrt(r.beta[0]), sum = p * p;
        for (int j = 0; j + 1 < n; ++j) {
            const double next = ((t - r.alpha[j]) * p - (j == 0 ? 0.0 : std::sqrt(r.beta[j]) * prev)) / std::sqrt(r.beta[j + 1]);
            prev = p;
            p = next;
            sum += p * p;
        }
        g.weights[k] = 1.0 / sum;
        if (!(std::isfinite(g.nodes[k]) && std::fabs(g.nodes[k]) < 1.0 && g.weights[k] > 0.0 &&
              (k == 0 || g.nodes[k] > g.nodes[k - 1])))
            throw numerical_error("Gauss rule of a variable-k weight: a node or weight is not valid (or nodes not "
                                  "strictly increasing) at n = " + std::to_string(n));
    }
    return g;
}

variable_k_weight::variable_k_weight(std::vector<double> ends, std::vector<double> k)
    : variable_k_weight(std::move(ends), std::move(k), {}) {}

namespace {
// int_lo^hi f by QAGS (the moments mu_0, mu_1 of a where k varies); a round-off stop is accepted where its own error
// estimate is at rounding: 1e-13 of the result or of int |f| (21-point Kronrod's resabs), at least 1e-15 (the floor
// before session 23) or 1e-15 of the zone's length. int |f| because the integral may cancel to nothing: atan(k) of 8(x)'s
// blend is odd about the stick zone's middle, so int atan(k) = 0 and QAGS stops at the rounding of int |atan(k)|
// (2.3e-15 on a zone 1.9 long at k_0 = 0.157: free rolling at f = 0.4 of NoSlipFull's pair, session 23). The weight's
// mass check (variable_k_collocation: 1e-12 of the closed form, which mu_0 and mu_1 enter) stands behind it.
double qags(const std::function<double(double)>& f, double lo, double hi, gsl_integration_workspace* ws) {
    if (!(hi > lo)) return 0.0;
    gsl_function F{[](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
                   const_cast<std::function<double(double)>*>(&f)};
    double r = 0.0, e = 0.0;
    const int status = gsl_integration_qags(&F, lo, hi, 1e-15, 1e-13, 1000, ws, &r, &e);
    if (status == GSL_EROUND) {
        double r21 = 0.0, e21 = 0.0, resabs = 0.0, resasc = 0.0;
        gsl_integration_qk21(&F, lo, hi, &r21, &e21, &resabs, &resasc);
        if (e <= std::max({1e-15, 1e-15 * (hi - lo), 1e-13 * std::fabs(r), 1e-13 * resabs})) return r;
    }
    gsl_check(status, "variable-k weight: the integral of a over a zone where k varies");
    return r;
}

// int_lo^hi f for f analytic inside (lo, hi) but finitely smooth at its ends, or nearly singular at a point `near`
// outside: 20-point Gauss-Legendre panels, each at least its length away from `near` and halved towards both ends down
// to 2^-grading of the zone (`scale`). A fixed rule, not adaptive: I_c's integrand (a_c(t) - a_c(x))/(t - x) carries rounding
// noise eps/|t - x| next to x, which an adaptive rule chases (QAGS stops with "bad behaviour" there).
double graded(const std::function<double(double)>& f, double lo, double hi, double near, double scale,
              const std::vector<double>& nodes, const std::vector<double>& weights, int grading) {
    double sum = 0.0;
    const double floor = std::ldexp(scale, -grading);
    std::function<void(double, double)> panel = [&](double u, double v) {
        const double h = v - u, mid = 0.5 * (u + v);
        const double d = near < u ? u - near : (near > v ? near - v : (std::isnan(near) ? h : 0.0));
        // Halved while it is longer than 1e-15 of the zone (and its halves are distinct numbers).
        if (h > 1e-15 * scale && mid > u && mid < v && ((d < h) || ((u == lo || v == hi) && h > floor))) {
            panel(u, mid);
            panel(mid, v);
            return;
        }
        for (std::size_t k = 0; k < nodes.size(); ++k) sum += 0.5 * h * weights[k] * f(0.5 * (u + v) + 0.5 * h * nodes[k]);
    };
    panel(lo, hi);
    return sum;
}

// I_c's part from a zone [l, r] where k, so a_c = A, is constant: int_l^r (A - a_c(x))/(t - x) dt in closed form (8(z)).
double constant_zone_part(double A, double ax, double x, double l, double r) {
    return A != ax && x != l && x != r ? (A - ax) * std::log(std::fabs((r - x) / (l - x))) : 0.0;
}
}  // namespace

variable_k_weight::variable_k_weight(std::vector<double> ends, std::vector<double> k,
                                     std::vector<std::function<double(double)>> varying)
    : k_(std::move(k)), varying_(std::move(varying)), workspace_(make_integration_workspace(1000)) {
    gsl_guard();
    {
        // GSL's tabulated 20-point Gauss-Legendre rule (its nodes and weights to double precision; the Golub-Welsch rule of
        // numerics/gauss_jacobi has its weights 2.6e-14 off, which a_c's Legendre coefficients amplify to 2e-13 in I_c).
        const std::unique_ptr<gsl_integration_glfixed_table, void (*)(gsl_integration_glfixed_table*)> table(
            gsl_integration_glfixed_table_alloc(20), gsl_integration_glfixed_table_free);
        if (!table) throw numerical_error("variable-k weight: no Gauss-Legendre table");
        legendre_.n = 20;
        legendre_.nodes.resize(20);
        legendre_.weights.resize(20);
        for (std::size_t k = 0; k < 20; ++k)
            gsl_check(gsl_integration_glfixed_point(-1.0, 1.0, k, &legendre_.nodes[k], &legendre_.weights[k], table.get()),
                      "variable-k weight: a Gauss-Legendre point");
        // c_j = (2j + 1)/2 sum_k W_k a_c(t_k) P_j(s_k): the Legendre coefficients of the degree-19 interpolant at the
        // nodes (exact: the rule integrates degree 39); transform_[k n + j] = (2j + 1)/2 W_k P_j(s_k) (Bonnet).
        transform_.assign(400, 0.0);
        for (int k = 0; k < 20; ++k) {
            double pm = 0.0, p = 1.0;
            for (int j = 0; j < 20; ++j) {
                transform_[k * 20 + j] = 0.5 * (2 * j + 1) * legendre_.weights[k] * p;
                const double next = ((2 * j + 1) * legendre_.nodes[k] * p - j * pm) / (j + 1);
                pm = p;
                p = next;
            }
        }
    }
    check_zones(ends, k_.size(), "variable-k weight");
    const std::size_t M = k_.size();
    if (varying_.empty()) varying_.resize(M);
    if (varying_.size() != M) throw numerical_error("variable-k weight: one k (constant or varying) per zone");
    bool any = false;
    for (std::size_t i = 0; i < M; ++i) {
        if (varying_[i]) {
            any = true;
            continue;
        }
        if (!std::isfinite(k_[i])) throw numerical_error("variable-k weight: k is not finite on zone " + std::to_string(i));
    }
    auto a_of = [&](std::size_t i, double x) {
        const double kx = varying_[i] ? varying_[i](x) : k_[i];
        if (!std::isfinite(kx)) throw numerical_error("variable-k weight: k is not finite on zone " + std::to_string(i));
        return 0.5 - std::atan(kx) / M_PI;  // k = cot(pi a), 0 < a < 1
    };
    a_.resize(M);
    std::vector<double> right(M);
    for (std::size_t i = 0; i < M; ++i) {
        a_[i] = a_of(i, ends[i]);
        right[i] = a_of(i, ends[i + 1]);
    }
    // 8(z): w = prod |x - x_j|^{e_j} (times m where k varies); e_0 = 1 - a(-1), e_j = a(x_j-) - a(x_j+), e_M = a(1).
    std::vector<double> e(M + 1), s(M);
    e[0] = 1.0 - a_[0];
    for (std::size_t j = 1; j < M; ++j) e[j] = right[j - 1] - a_[j];
    e[M] = right[M - 1];
    for (std::size_t i = 0; i < M; ++i) {
        s[i] = std::sin(M_PI * a_[i]);
        if (varying_[i]) {
            // a = 1/2 - atan(k)/pi with the constant half in closed form, QAGS on the small atan(k) part only: on a
            // thin zone near the edge QAGS of a t itself stopped at round-off above its acceptance (free rolling of the
            // pair at full coupling, f = 0.1, zone [0.9417, 0.9805]; tests/test_exact_weight_s23.cpp).
            const double lo = ends[i], hi = ends[i + 1];
            mu0_ += 0.5 * (hi - lo) -
                    M_1_PI * qags([&](double t) { return std::atan(varying_[i](t)); }, lo, hi, workspace_.get());
            mu1_ += 0.25 * (hi - lo) * (hi + lo) -
                    M_1_PI * qags([&](double t) { return std::atan(varying_[i](t)) * t; }, lo, hi, workspace_.get());
        } else {
            mu0_ += a_[i] * (ends[i + 1] - ends[i]);
            mu1_ += a_[i] * 0.5 * (ends[i + 1] - ends[i]) * (ends[i + 1] + ends[i]);
        }
    }
    std::vector<double> minus(M + 1);
    for (std::size_t j = 0; j <= M; ++j) minus[j] = -e[j];
    if (!any) {
        weight_ = {ends, e, s, {}, {}};
        dual_ = {std::move(ends), std::move(minus), std::move(s), {}, {}};
        return;
    }
    // a = a_pc + a_c: a_pc takes a's jumps, a_c continuous with a_c(-1) = 0.
    a_pc_.resize(M);
    a_pc_[0] = a_[0];
    for (std::size_t i = 1; i < M; ++i) a_pc_[i] = a_pc_[i - 1] + (a_[i] - right[i - 1]);
    a_c_offset_.resize(M);
    for (std::size_t i = 0; i < M; ++i) a_c_offset_[i] = 0.5 - a_pc_[i];
    a_c_right_ = a_c_on(M - 1, 1.0);
    const std::vector<double> ones(M, 1.0);
    // m is finitely smooth only at the ends of the zones where k varies (a_c and I_c are analytic elsewhere, 8(z)).
    std::vector<char> rough(M + 1, 0);
    for (std::size_t i = 0; i < M; ++i)
        if (varying_[i]) rough[i] = rough[i + 1] = 1;
    weight_ = {ends, e, ones, [this](double x) { const factors f = factors_at(x); return f.sine * f.m; }, rough};
    build_rules();
    dual_ = {std::move(ends), std::move(minus), ones, [this](double x) { const factors f = factors_at(x); return f.sine / f.m; },
             std::move(rough)};
}

double variable_k_weight::k_at(double x) const {
    const int i = weight_.zone_of(x);
    return varying_[i] ? varying_[i](x) : k_[i];
}

// I_c's panels are halved towards the zone's ends to 2^-4 only: where k varies by 8(x)'s blend, a_c - a_c(end) ~ d^{9/2}
// there (Theta_3' ~ (1 - t^2)^{5/2}), which 20-point Gauss-Legendre integrates to 20^-11 on a panel touching it.
constexpr int end_grading = 4;

double variable_k_weight::i_c_by_quadrature(double x) const {
    if (a_pc_.empty()) return 0.0;
    // I_c(x) = int (a_c(t) - a_c(x))/(t - x) dt zone by zone: closed form where k is constant (a_c constant there),
    // 20-point Gauss-Legendre where it varies, on the zone's fixed panels graded to its ends (rules_, a_c cached at their
    // nodes: 8(z), "The cost"). The integrand is analytic on a panel unless x lies on it or, outside k's zone, closer to
    // it than its length (the pole at t = x): such a panel is split at x (analytic at t = x inside the zone: no further
    // grading), or halved towards x, with a_c evaluated afresh; every other panel takes the cached sum.
    const std::vector<double>& ends = weight_.ends;
    const double ax = a_c(x);
    double I = 0.0;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        const double l = ends[i], r = ends[i + 1];
        if (!varying_[i]) {
            I += constant_zone_part(a_c_on(i, l), ax, x, l, r);
            continue;
        }
        const std::function<double(double)> f = [&](double t) { return t == x ? 0.0 : (a_c_on(i, t) - ax) / (t - x); };
        const bool inside = x > l && x < r;
        const panel_set& z = rules_[i].coarse;
        const int per = legendre_.n;
        for (std::size_t p = 0; p < z.u.size(); ++p) {
            const double u = z.u[p], v = z.v[p], h = v - u;
            const double d = x < u ? u - x : (x > v ? x - v : 0.0);
            if (x > u && x < v) {
                const double none = std::numeric_limits<double>::quiet_NaN();
                I += graded(f, u, x, none, h, legendre_.nodes, legendre_.weights, 0) +
                     graded(f, x, v, none, h, legendre_.nodes, legendre_.weights, 0);
            } else if (!inside && d < h) {
                I += graded(f, u, v, x, h, legendre_.nodes, legendre_.weights, 0);
            } else {
                for (int k = 0; k < per; ++k) {
                    const std::size_t q = p * per + k;
                    if (z.t[q] != x) I += z.w[q] * (z.a[q] - ax) / (z.t[q] - x);
                }
            }
        }
    }
    return I;
}

double variable_k_weight::i_c(double x) const { return a_pc_.empty() ? 0.0 : i_c_at(x, a_c(x)); }

double variable_k_weight::i_c_at(double x, double ax) const {
    // I_c(x) zone by zone (8(z), "The cost"): closed form where k is constant; where it varies the cached Gauss-Legendre
    // sum of (a_c(t) - a_c(x))/(t - x) on every panel at least its length from x (the integrand analytic in a Bernstein
    // ellipse rho >= 5.8 there: 5.8^-40), and on the panels nearer than that product integration on a_c's degree-19
    // interpolant p = sum_j c_j P_j(s), s = (2t - u - v)/(v - u), y = s(x):
    //   int_u^v (p(t) - a_c(x))/(t - x) dt = sum_j c_j R_j(y) + (p(y) - a_c(x)) log|(v - x)/(u - x)|,
    //   R_j(y) = int_{-1}^1 (P_j(s) - P_j(y))/(s - y) ds:  R_0 = 0, R_1 = 2, (j + 1) R_{j+1} = (2j + 1) y R_j - j R_{j-1}
    // (from Bonnet's recurrence of P_j; R_j is Christoffel's 2 W_{j-1}, DLMF 14.7.1 with Q_j = P_j Q_0 - W_{j-1}). Exact for
    // the interpolant, inside the panel and out (|y| <= 3: R_j + P_j log is -2 Q_j there, and the rounding of the two
    // parts, eps |c_j P_j(y)| <= eps |c_j| 5.8^j, stays at rounding while the c_j decay); no evaluation of a at x's panel.
    const std::vector<double>& ends = weight_.ends;
    double I = 0.0;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        const double l = ends[i], r = ends[i + 1];
        if (!varying_[i]) {
            I += constant_zone_part(a_c_on(i, l), ax, x, l, r);
            continue;
        }
        const zone_rule& z = rules_[i];
        for (std::size_t p = 0; p < z.coarse.u.size(); ++p) {
            const double u = z.coarse.u[p], v = z.coarse.v[p];
            const double d = x < u ? u - x : (x > v ? x - v : 0.0);
            if (d >= v - u || z.fine_begin[p] == z.fine_end[p]) {
                I += panel_part(z.coarse, p, x, ax);
                continue;
            }
            for (std::size_t q = z.fine_begin[p]; q < z.fine_end[p]; ++q) I += panel_part(z.fine, q, x, ax);
        }
    }
    return I;
}

double variable_k_weight::panel_part(const panel_set& z, std::size_t p, double x, double ax) const {
    const int per = legendre_.n;
    const double u = z.u[p], v = z.v[p], h = v - u;
    const double d = x < u ? u - x : (x > v ? x - v : 0.0);
    const std::size_t first = p * static_cast<std::size_t>(per);
    double I = 0.0;
    if (d >= h) {
        for (int k = 0; k < per; ++k) I += z.w[first + k] * (z.a[first + k] - ax) / (z.t[first + k] - x);
        return I;
    }
    const double y = (2.0 * x - u - v) / h;
    double pm = 0.0, pk = 1.0, rm = 0.0, rk = 0.0, value = 0.0;
    for (int j = 0; j < per; ++j) {
        value += z.c[first + j] * pk;
        I += z.c[first + j] * rk;
        const double pn = ((2 * j + 1) * y * pk - j * pm) / (j + 1);
        const double rn = j == 0 ? 2.0 : ((2 * j + 1) * y * rk - j * rm) / (j + 1);
        pm = pk;
        pk = pn;
        rm = rk;
        rk = rn;
    }
    if (x != u && x != v) I += (value - ax) * std::log(std::fabs((v - x) / (u - x)));
    return I;
}

void variable_k_weight::build_rules() {
    // Each zone where k varies: 20-point Gauss-Legendre panels halved towards both its ends to 2^-end_grading of it
    // (a_c - a_c(end) ~ d^{9/2} for 8(x)'s blend: 20^-11 on the panel that touches the end), a_c cached at their nodes
    // with its Legendre coefficients. Product integration needs a_c's interpolant, which converges only as N^-9 on a
    // panel touching such an end (measured: 2e-13 on the 2^-4 panel, 6e-12 in I_c near the end): the two end panels are
    // graded again, to 2^-16 of the zone, for the x near them.
    const std::vector<double>& ends = weight_.ends;
    rules_.assign(ends.size() - 1, {});
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        if (!varying_[i]) continue;
        const double l = ends[i], r = ends[i + 1];
        zone_rule& z = rules_[i];
        auto add = [&](panel_set& s, double u, double v) {
            const double mid = 0.5 * (u + v);
            s.u.push_back(u);
            s.v.push_back(v);
            const std::size_t first = s.a.size();
            for (int k = 0; k < legendre_.n; ++k) {
                const double t = mid + 0.5 * (v - u) * legendre_.nodes[k];
                s.t.push_back(t);
                s.w.push_back(0.5 * (v - u) * legendre_.weights[k]);
                s.a.push_back(a_c_on(i, t));
            }
            // a_c's Legendre coefficients (transform_); the mean c_0 is taken out first: the others then carry the rounding
            // of a_c's variation on the panel, not of a_c (their sum is p at the panel's ends).
            s.c.resize(s.a.size(), 0.0);
            double mean = 0.0;
            for (int k = 0; k < legendre_.n; ++k) mean += 0.5 * legendre_.weights[k] * s.a[first + k];
            for (int k = 0; k < legendre_.n; ++k) {
                const double d = s.a[first + k] - mean;
                for (int j = 0; j < legendre_.n; ++j) s.c[first + j] += transform_[k * legendre_.n + j] * d;
            }
            s.c[first] = mean;
        };
        // Halved while it touches an end of [lo, hi] and is longer than `floor`.
        std::function<void(panel_set&, double, double, double, double, double)> graded_panels =
            [&](panel_set& s, double u, double v, double lo, double hi, double floor) {
                const double mid = 0.5 * (u + v);
                if ((u == lo || v == hi) && v - u > floor && mid > u && mid < v) {
                    graded_panels(s, u, mid, lo, hi, floor);
                    graded_panels(s, mid, v, lo, hi, floor);
                    return;
                }
                add(s, u, v);
            };
        graded_panels(z.coarse, l, r, l, r, std::ldexp(r - l, -end_grading));
        for (std::size_t p = 0; p < z.coarse.u.size(); ++p) {
            const double u = z.coarse.u[p], v = z.coarse.v[p];
            z.fine_begin.push_back(z.fine.u.size());
            if (u == l || v == r) {
                graded_panels(z.fine, u, v, u == l ? l : u - 1.0, v == r ? r : v + 1.0, std::ldexp(r - l, -16));
            } else {
                // At least its length from either end, the interpolant still errs by 5.8^-19 of a_c's variation
                // (measured 3e-14 in I_c at a panel's end): quarters, four lengths away at least (16^-19).
                for (int q = 0; q < 4; ++q) add(z.fine, u + 0.25 * q * (v - u), q == 3 ? v : u + 0.25 * (q + 1) * (v - u));
            }
            z.fine_end.push_back(z.fine.u.size());
        }
    }
}

variable_k_weight::factors variable_k_weight::factors_at(double x) const {
    // The weight's and the dual's discretisations share most points (the panels inside [-1, 1] carry the same rule in
    // both): m is computed once per point (8(z), "The cost").
    const auto found = memo_.find(x);
    if (found != memo_.end()) return found->second;
    if (memo_.size() >= 200000) memo_.clear();
    const factors f{std::sin(M_PI * a_at(x)), m_of(x)};
    memo_.emplace(x, f);
    return f;
}

double variable_k_weight::m_of(double x) const {
    const double ax = a_c(x);
    return std::pow(1.0 - x, ax - a_c_right_) * std::pow(1.0 + x, -ax) * std::exp(i_c_at(x, ax));
}

double variable_k_weight::mass() const { return M_PI * (mu0_ + mu1_ - 0.5 * mu0_ * mu0_); }

double variable_k_weight::hilbert_of_weight(double x) const { return k_at(x) * weight_(x) - (x + 1.0 - mu0_); }

variable_k_collocation::variable_k_collocation(const variable_k_weight& weight, int n, discretisation how)
    : weight_(weight), n_(n), recurrence_(recurrence_of(weight.weight(), std::max(n, 1), how)) {
    if (n < 1) throw numerical_error("variable-k collocation needs at least one node");
    // The discretisation against the closed-form masses (8(z)): a panel left unresolved would show here first.
    const double mass = weight.mass();
    if (!(std::fabs(recurrence_.beta[0] - mass) <= 1e-12 * mass))
        throw numerical_error("variable-k weight: the discretised mass " + std::to_string(recurrence_.beta[0]) +
                              " misses the closed form " + std::to_string(mass));
    const orthogonal_recurrence dual = recurrence_of(weight.dual(), n + 1, how);
    if (!(std::fabs(dual.beta[0] - M_PI) <= 1e-12 * M_PI))
        throw numerical_error("variable-k weight: the dual weight's discretised mass misses pi");
    rule_ = gauss_rule_of(recurrence_, n);
    points_ = gauss_rule_of(dual, n + 1).nodes;
    root_beta_.resize(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) root_beta_[j] = std::sqrt(recurrence_.beta[j]);
    for (double x : points_) {
        double sum = 0.0;
        for (int j = 0; j < n; ++j) sum += rule_.weights[j] / (rule_.nodes[j] - x);
        defect_ = std::max(defect_, std::fabs(-(x + 1.0 - weight.mu0()) - M_1_PI * sum));
    }
    // D vanishes at the points in exact arithmetic (8(z)); the masses above can be right while a node or point is not
    // (a QL value on the wrong root, a point of an under-resolved dual rule), and then the matrix is not (H - k) on
    // w_k psi. Measured: 1e-14 .. 6e-11 relative to the scale of (H - k)[w_k] up to n = 1000 (8(z)).
    double scale = 1.0;
    for (double x : points_) scale = std::max(scale, std::fabs(x + 1.0 - weight.mu0()));
    if (!(defect_ <= 1e-9 * scale))
        throw numerical_error("variable-k collocation: the points miss the exact collocation by " +
                              std::to_string(defect_) + " at n = " + std::to_string(n) + " (8(z))");
}

void variable_k_collocation::assemble(gsl_matrix* m) const {
    gsl_matrix_set_zero(m);
    for (int i = 0; i <= n_; ++i) {
        const double x = points_[i];
        for (int j = 0; j < n_; ++j) gsl_matrix_set(m, i, j, M_1_PI * rule_.weights[j] / (rule_.nodes[j] - x));
        gsl_matrix_set(m, i, n_, -1.0);
    }
}

variable_k_collocation::solution variable_k_collocation::solve(const std::vector<double>& g) {
    if (static_cast<int>(g.size()) != n_ + 1)
        throw numerical_error("variable-k collocation: the right side needs one value per collocation point");
    const char* context = "variable-k collocation";
    if (!plain_) plain_ = std::make_unique<dense_system>(n_ + 1);
    const bool fresh = !plain_->holds_factors();
    if (fresh) assemble(plain_->matrix());
    for (int i = 0; i <= n_; ++i) gsl_vector_set(plain_->rhs(), i, g[i]);
    const gsl_vector* x = fresh ? plain_->solve(context) : plain_->solve_factorised(context);
    solution s;
    s.psi.assign(x->data, x->data + n_);
    s.xi = gsl_vector_get(x, n_);
    return s;
}

variable_k_collocation::solution variable_k_collocation::solve_loaded(const std::vector<double>& g,
                                                                      const std::vector<double>& h, double load) {
    if (static_cast<int>(g.size()) != n_ + 1 || static_cast<int>(h.size()) != n_ + 1)
        throw numerical_error("variable-k collocation: the right side needs one value per collocation point");
    const char* context = "variable-k collocation with its load";
    if (!loaded_) {
        loaded_ = std::make_unique<dense_system>(n_ + 2);
        loaded_->keep_matrix();  // for lambda's rounding bound (below)
    }
    const bool fresh = !loaded_->holds_factors() || h != loaded_h_;
    if (fresh) {
        gsl_matrix* m = loaded_->matrix();
        const matrix_ptr plain = make_matrix(n_ + 1, n_ + 1);
        assemble(plain.get());
        gsl_matrix_set_zero(m);
        for (int i = 0; i <= n_; ++i) {
            for (int j = 0; j <= n_; ++j) gsl_matrix_set(m, i, j, gsl_matrix_get(plain.get(), i, j));
            gsl_matrix_set(m, i, n_ + 1, -h[i]);
        }
        for (int j = 0; j < n_; ++j) gsl_matrix_set(m, n_ + 1, j, rule_.weights[j]);
        loaded_h_ = h;
    }
    for (int i = 0; i <= n_; ++i) gsl_vector_set(loaded_->rhs(), i, g[i]);
    gsl_vector_set(loaded_->rhs(), n_ + 1, load);
    const gsl_vector* x = fresh ? loaded_->solve(context) : loaded_->solve_factorised(context);
    solution s;
    s.psi.assign(x->data, x->data + n_);
    s.xi = gsl_vector_get(x, n_);
    s.lambda = gsl_vector_get(x, n_ + 1);
    // The entries (1/pi) W_j/(t_j - x_m) carry four roundings from the stored nodes, weights and points (1/pi's, the
    // difference, the quotient, the product), the load one; the rest are exact (8(w), "The solve's rounding, a
    // posteriori").
    s.lambda_rounding = loaded_->rounding_bound(static_cast<std::size_t>(n_) + 1, 2.0 * GSL_DBL_EPSILON);
    return s;
}

double variable_k_collocation::interpolate(const std::vector<double>& psi, double x) const {
    // c_j = sum_k W_k psi_k p_j(t_k) (exact: degree <= 2n - 2), psi(x) = sum_j c_j p_j(x), p_j orthonormal.
    const orthogonal_recurrence& r = recurrence_;
    auto values = [&](double t, std::vector<double>& p) {
        p.resize(n_);
        p[0] = 1.0 / std::sqrt(r.beta[0]);
        if (n_ > 1) p[1] = (t - r.alpha[0]) * p[0] / std::sqrt(r.beta[1]);
        for (int j = 1; j + 1 < n_; ++j)
            p[j + 1] = ((t - r.alpha[j]) * p[j] - std::sqrt(r.beta[j]) * p[j - 1]) / std::sqrt(r.beta[j + 1]);
    };
    std::vector<double> c(n_, 0.0), p;
    for (int k = 0; k < n_; ++k) {
        values(rule_.nodes[k], p);
        for (int j = 0; j < n_; ++j) c[j] += rule_.weights[k] * psi[k] * p[j];
    }
    values(x, p);
    double s = 0.0;
    for (int j = 0; j < n_; ++j) s += c[j] * p[j];
    return s;
}

double variable_k_collocation::rcond() const {
    return loaded_ && loaded_->holds_factors() ? loaded_->rcond() : plain_ ? plain_->rcond() : 0.0;
}

std::vector<double> variable_k_collocation::coefficients(const std::vector<double>& psi) const {
    const orthogonal_recurrence& r = recurrence_;
    const std::vector<double>& q = root_beta_;
    std::vector<double> c(n_, 0.0), p(n_);
    for (int k = 0; k < n_; ++k) {
        const double t = rule_.nodes[k];
        p[0] = 1.0 / q[0];
        if (n_ > 1) p[1] = (t - r.alpha[0]) * p[0] / q[1];
        for (int j = 1; j + 1 < n_; ++j) p[j + 1] = ((t - r.alpha[j]) * p[j] - q[j] * p[j - 1]) / q[j + 1];
        for (int j = 0; j < n_; ++j) c[j] += rule_.weights[k] * psi[k] * p[j];
    }
    return c;
}

double variable_k_collocation::series(const std::vector<double>& c, double x) const {
    const orthogonal_recurrence& r = recurrence_;
    const std::vector<double>& q = root_beta_;
    double prev = 0.0, cur = 1.0 / q[0];
    double s = c[0] * cur;
    for (int j = 0; j + 1 < n_; ++j) {
        const double next = ((x - r.alpha[j]) * cur - q[j] * prev) / q[j + 1];
        prev = cur;
        cur = next;
        s += c[j + 1] * cur;
    }
    return s;
}

double variable_k_collocation::hilbert(const std::vector<double>& psi, double x) const {
    double sum = 0.0, plain = 0.0;
    for (int j = 0; j < n_; ++j) {
        const double d = rule_.nodes[j] - x;
        if (d == 0.0) throw numerical_error("variable-k collocation: H asked at a node");
        sum += rule_.weights[j] * psi[j] / d;
        plain += rule_.weights[j] / d;
    }
    // (H - k)[w psi](x) = (1/pi) sum W_j psi_j/(t_j - x) + psi(x) D(x), D = (H - k)[w](x) - (1/pi) sum W_j/(t_j - x).
    const double px = interpolate(psi, x);
    const double D = -(x + 1.0 - weight_.mu0()) - M_1_PI * plain;
    return M_1_PI * sum + px * D + weight_.k_at(x) * weight_(x) * px;
}

double variable_k_collocation::load(const std::vector<double>& psi) const {
    double s = 0.0;
    for (int j = 0; j < n_; ++j) s += rule_.weights[j] * psi[j];
    return s;
}

}  // namespace roughroll
