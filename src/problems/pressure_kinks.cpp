// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/pressure_kinks.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <string>
#include <unordered_map>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/variable_k_weight.hpp"

namespace roughroll {

// blend()'s kept tables and rules are of the pressure before a change (each of its changes calls this first).
void pressure_kinks::drop_blend_tables() {
    piece_tables_.reset();
    blend_rules_.reset();
}

// integral()'s rule, made by the first of the calls that set the pressure's parts; later calls keep it.
void pressure_kinks::keep_legendre_rule(int points) {
    if (!legendre_nodes_.empty()) return;
    const gauss_legendre legendre(points);
    legendre_nodes_ = legendre.nodes;
    legendre_weights_ = legendre.weights;
}

namespace {
// The graded rule of kinks_blend::near_part: Gauss-Legendre points per graded piece (8(x) "W's routes").
constexpr int graded_points = 32;

// Cuts in increasing order, each once.
void sort_cuts(std::vector<double>& cuts) {
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
}

// Node j of `rule` on [a, e] in the cos map eta = a + (e - a)(1 - cos u)/2, u = (pi/2)(x_j + 1), and its weight d eta:
// the weighted W's rule (8(x)). eta is taken from the nearer end, so that its distance to that end (where p has a
// one-sided root, or r sits) carries no cancellation.
struct mapped_node {
    double eta, weight;
};
mapped_node cos_map_node(const gauss_legendre& rule, std::size_t j, double a, double e) {
    const double half = 0.5 * (e - a);
    const double u = M_PI_2 * (rule.nodes[j] + 1.0), sh = std::sin(0.5 * u), ch = std::cos(0.5 * u);
    return {u < M_PI_2 ? a + 2.0 * half * sh * sh : e - 2.0 * half * ch * ch, rule.weights[j] * M_PI_2 * half * std::sin(u)};
}

}  // namespace

void pressure_kinks::add_zone(const gauss_chebyshev& rule, double beta_d, double sign, double start, double c0,
                              const std::vector<double>& psi_b, const std::function<double(double)>& blend) {
    drop_blend_tables();
    if (!(start > -1.0 && start < c0 && c0 < 1.0))
        throw numerical_error(
            "full coupling: a stick zone of the pressure's kinks is not inside the contact "
            "(docs/formulation.md 8(l))");
    zone z{start, 0.5 * (c0 - start), beta_d * sign, {}, nullptr};
    keep_legendre_rule(2 * rule.n + 32);
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

void pressure_kinks::set_weight(double k_e) {
    drop_blend_tables();
    if (!zones_.empty() || !wzones_.empty())
        throw numerical_error("full coupling: the weighted pressure (docs/formulation.md 8(w)) takes no U-series kinks");
    weighted_ = true;
    k_e_ = k_e;
    a_n_ = 0.5 + std::atan(k_e) * M_1_PI;  // cot(pi a_N) = -k_E: (H + k_E) is the identity's H - cot(pi a_N) (8(v))
}

void pressure_kinks::add_weighted_zone(int n, double beta_d, double sign, double start, double c0, double a_z,
                                       const std::function<double(double)>& psi, const pressure_kinks* rules_of,
                                       jacobi_rule_set* rules) {
    drop_blend_tables();
    if (!weighted_) throw numerical_error("full coupling: a weighted kink zone before the pressure's weight (8(w))");
    if (!(start > -1.0 && start < c0 && c0 < 1.0))
        throw numerical_error(
            "full coupling: a stick zone of the pressure's kinks is not inside the contact (docs/formulation.md 8(w))");
    const weighted_zone* same = nullptr;  // an earlier step's zone of the same rules (the alternation's source)
    if (rules_of)
        for (const weighted_zone& w : rules_of->wzones_)
            if (w.rule->n == n && w.a == a_z) same = &w;
    weighted_zone z{start,
                    0.5 * (c0 - start),
                    beta_d * sign,
                    a_z,
                    rules  ? rules->rule(n, a_z, 1.0 - a_z)
                    : same ? same->rule
                           : std::make_shared<const gauss_jacobi>(n, a_z, 1.0 - a_z),
                    rules  ? rules->rule(4 * n, a_z, 1.0 - a_z)
                    : same ? same->far
                           : std::make_shared<const gauss_jacobi>(4 * n, a_z, 1.0 - a_z),
                    {},
                    {},
                    {},
                    nullptr,
                    nullptr};
    keep_legendre_rule(2 * n + 32);
    // G(t) = psi(t)/w_N(r(t)), analytic on the zone (inside the contact): its degree n - 1 interpolant on the zone's
    // Gauss-Jacobi nodes; the q carried is sign w_Z w_N G_n (removed()), so that (D1) holds for the p represented.
    const gauss_jacobi& rule = *z.rule;
    z.at_nodes.resize(static_cast<std::size_t>(n));
    const double sin_n = std::sin(M_PI * a_n_);
    double zeroth = 0.0, first = 0.0;
    for (int i = 0; i < n; ++i) {
        const double r = start + z.rho * (rule.nodes[i] + 1.0);
        z.at_nodes[i] = psi(rule.nodes[i]) / jacobi_weight(a_n_, 1.0 - a_n_, r);
        // int (q/w_N) (1, P_1^(-a_N, a_N - 1)(r)) dr = rho sum W_k G_k (1, P_1(r_k)): exact for G_n (degree n - 1, n).
        double p1[2];
        jacobi_values(-a_n_, a_n_ - 1.0, r, 2, p1);
        zeroth += rule.weights[i] * z.at_nodes[i];
        first += rule.weights[i] * z.at_nodes[i] * p1[1];
    }
    z.c = jacobi_coefficients(rule, z.at_nodes);
    z.own = same ? same->own : std::make_shared<const jacobi_recurrence>(a_z, 1.0 - a_z, n);
    z.shifted = same ? same->shifted : std::make_shared<const jacobi_recurrence>(-a_z, a_z - 1.0, n + 1);
    z.at_far.resize(z.far->nodes.size());
    for (std::size_t i = 0; i < z.at_far.size(); ++i) z.at_far[i] = jacobi_series(z.c, a_z, 1.0 - a_z, z.far->nodes[i]);
    load_ += 2.0 * sin_n * z.amplitude * z.rho * first;
    constant_ += sin_n * M_1_PI * z.amplitude * z.rho * zeroth;
    wzones_.push_back(std::move(z));
}

// set_variable's state (pressure_kinks.hpp; 8(z), "Wired").
struct pressure_kinks::variable_state {
    int n = 0;
    std::array<double, 4> ends{};
    std::unique_ptr<variable_k_weight> weight;   // w_k of (H - k_z), k_z = -k
    std::unique_ptr<variable_k_collocation> colloc;
    std::array<std::vector<double>, 2> b;        // U coefficients of g_Z, h w_d = sqrt(1 - t^2) g_Z(t) on zone Z
    std::vector<double> psi, c;                  // solve_variable's, and psi's orthonormal coefficients
    // p(r) (operator()) at the points asked since solve_variable: the tangential side asks p again at the same r (its
    // collocation points, checks and quadratures at every Newton step), and each costs w_k's I_c and psi's n-term series
    // (8(z) "Wired": p's evaluations were two thirds of the wired free rolling point, session 24). The same value as
    // afresh (a function of r).
    mutable std::unordered_map<double, double, double_bits_hash> pressure;
    // Zone Z's t of r (|t| < 1 on the zone).
    double t_of(int z, double r) const {
        const double s = ends[2 * z], c = ends[2 * z + 1];
        return (2.0 * r - s - c) / (c - s);
    }
    // sqrt(1 - t^2) g_n(t) on the stick zones (h w_d as carried), 0 elsewhere; and H[h w_d](r).
    double carried(double r) const {
        for (int z = 0; z < 2; ++z) {
            const double t = t_of(z, r);
            if (std::fabs(t) < 1.0) return std::sqrt((1.0 - t) * (1.0 + t)) * u_series(b[z], t);
        }
        return 0.0;
    }
    double cauchy(double r) const { return cauchy_u_series(b[0], t_of(0, r)) + cauchy_u_series(b[1], t_of(1, r)); }
};

void pressure_kinks::set_variable(int n, double beta_d, double sign, double f, const std::array<double, 4>& e,
                                  const std::array<std::function<double(double)>, 2>& psi) {
    drop_blend_tables();
    if (!weighted_ || !wzones_.empty() || variable_)
        throw numerical_error("full coupling: the variable-k pressure (8(z)) needs set_weight alone before it");
    if (!(-1.0 < e[0] && e[0] < e[1] && e[1] < e[2] && e[2] < e[3] && e[3] < 1.0))
        throw numerical_error("full coupling: the variable-k pressure (8(z)) needs five zones of positive length");
    auto st = std::make_shared<variable_state>();
    st->n = n;
    st->ends = e;
    // k_z = -k = k0 (2 B - 1), k0 = -sign beta_D f: -k0 = -k_E at the edges (8(z)'s convention (H - k_z)).
    const double k0 = -sign * beta_d * f;
    const auto t_of = [](double x, double l, double r) { return std::clamp((2.0 * x - l - r) / (r - l), -1.0, 1.0); };
    const double s1 = e[0], c1 = e[1], s2 = e[2], c2 = e[3];
    std::vector<std::function<double(double)>> varying{
        {}, [=](double x) { return k0 * (2.0 * blend_theta3(t_of(x, s1, c1)) - 1.0); }, {},
        [=](double x) { return k0 * (1.0 - 2.0 * blend_theta3(t_of(x, s2, c2))); }, {}};
    try {
        st->weight = std::make_unique<variable_k_weight>(std::vector<double>{-1.0, s1, c1, s2, c2, 1.0},
                                                         std::vector<double>{-k0, 0.0, k0, 0.0, -k0}, varying);
        st->colloc = std::make_unique<variable_k_collocation>(*st->weight, n);
    } catch (const numerical_error& e) {
        // The weight's own checks (its masses, the collocation points' defect, QAGS of mu_0, mu_1, the panels' grading)
        // failed at these ends: no fallback (header).
        throw resolution_error("full coupling: the five zones' exact pressure weight (docs/formulation.md 8(z)) cannot "
                               "be built at n = " + std::to_string(n) + " for the stick zones [" + shortest(s1) + ", " +
                               shortest(c1) + "] and [" + shortest(s2) + ", " + shortest(c2) + "] (" + e.what() +
                               "); another n (--n, or a tolerance for the ladder) may answer, and coupling = "
                               "\"johnson\" answers the load");
    }
    // h = -beta_D sign sqrt(1 - t^2) psi_Z: g_Z = -beta_D sign psi_Z w_d at the zone's n Gauss-Chebyshev nodes.
    const gauss_chebyshev rule = gauss_chebyshev::transform(n);
    const double mu0 = st->weight->mu0(), amplitude = -beta_d * sign;
    load_ = 0.0;
    constant_ = 0.0;
    for (int z = 0; z < 2; ++z) {
        const double s = e[2 * z], c = e[2 * z + 1], rho = 0.5 * (c - s), m = 0.5 * (s + c);
        std::vector<double> g(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            const double t = rule.nodes[i];
            g[i] = amplitude * psi[z](t) * st->weight->dual()(m + rho * t);
        }
        st->b[z] = u_coefficients(rule, g);
        const std::vector<double>& b = st->b[z];
        // C = -(1/pi) int h w_d = -(rho/2) b_0; int p_q = -int h w_d (r + 1 - mu_0), r = m + rho t, t = U_1/2 (8(z)).
        constant_ += -0.5 * rho * b[0];
        load_ += -rho * M_PI_2 * ((m + 1.0 - mu0) * b[0] + 0.5 * rho * (b.size() > 1 ? b[1] : 0.0));
    }
    keep_legendre_rule(2 * n + 32);
    variable_ = std::move(st);
}

pressure_kinks::variable_result pressure_kinks::solve_variable() {
    drop_blend_tables();
    if (!variable_) throw numerical_error("full coupling: solve_variable without set_variable");
    variable_state& st = *variable_;
    const std::vector<double> zero(static_cast<std::size_t>(st.n) + 1, 0.0);
    // (H - k_z)[w_k psi] - xi - lambda' r = 0, int w_k psi = 1 - int p_q; with (H - k_z)[p_q] = h + C:
    // (H + k) p = xi + lambda' r + h + C, i.e. gamma = -(xi + C), lambda = -(pi/2) lambda'.
    const variable_k_collocation::solution s = st.colloc->solve_loaded(zero, st.colloc->points(), 1.0 - load_);
    st.psi = s.psi;
    st.c = st.colloc->coefficients(s.psi);
    st.pressure.clear();
    return {s.psi, -M_PI_2 * s.lambda, -(s.xi + constant_), st.colloc->rcond(), M_PI_2 * s.lambda_rounding};
}

double pressure_kinks::k_at(double r) const { return variable_ ? -variable_->weight->k_at(r) : k_e_; }

void pressure_kinks::set_series(std::vector<double> phi_c) {
    drop_blend_tables();
    series_ = std::move(phi_c);
    series_rec_ = std::make_shared<const jacobi_recurrence>(a_n_, 1.0 - a_n_, static_cast<int>(series_.size()));
}

double pressure_kinks::series_part(double r) const {
    if (variable_) return std::fabs(r) < 1.0 ? (*variable_->weight)(r) * variable_->colloc->series(variable_->c, r) : 0.0;
    if (!(std::fabs(r) < 1.0) || series_.empty()) return 0.0;
    return jacobi_weight(a_n_, 1.0 - a_n_, r) * series_rec_->series(series_, r);
}

double pressure_kinks::cauchy_outside(const weighted_zone& z, double x) const {
    return jacobi_cauchy_outside(z.c, *z.rule, z.at_nodes, *z.far, z.at_far, x, z.own.get());  // 8(v), "Off the zone"
}

double pressure_kinks::kink_part(double r) const {
    if (!(std::fabs(r) < 1.0)) return 0.0;
    if (variable_) {  // p_q = -w_k (k_z sqrt(1 - t^2) g_n + H[h w_d]) (1/((1 + k_z^2) w_d) = w_k, 8(z))
        const double kz = variable_->weight->k_at(r);
        return -(*variable_->weight)(r) * (kz * variable_->carried(r) + variable_->cauchy(r));
    }
    const double w_n = jacobi_weight(a_n_, 1.0 - a_n_, r), scale = 1.0 / (1.0 + k_e_ * k_e_);
    double sum = 0.0;
    for (const weighted_zone& z : wzones_) {
        const double t = (r - z.start) / z.rho - 1.0, b = 1.0 - z.a;
        if (std::fabs(t) < 1.0) {
            // On the zone, by the identity of 8(v): H[w_Z G_n] = cot(pi a_Z) w_Z G_n - (2/sin(pi a_Z)) sum G_j P_{j+1}^(-a_Z,-b_Z),
            // so k q - w_N H[q/w_N] = (k_E - cot(pi a_Z)) q + sign w_N (2/sin(pi a_Z)) sum G_j P_{j+1}^(-a_Z,-b_Z).
            const double tail = z.shifted->series_shifted(z.c, t);
            const double g = z.own->series(z.c, t);
            const double k_z = 1.0 / std::tan(M_PI * z.a);
            const double bracket = (k_e_ - k_z) * jacobi_weight(z.a, b, t) * w_n * g + w_n * 2.0 / std::sin(M_PI * z.a) * tail;
            sum -= scale * z.amplitude * bracket;
        } else {
            // Off the zone q = 0: p_q = (beta_D/(1 + k_E^2)) w_N H[q/w_N].
            sum += scale * z.amplitude * w_n * cauchy_outside(z, t);
        }
    }
    return sum;
}

double pressure_kinks::factor(double r) const {
    if (weighted_) return (*this)(r) / std::sqrt((1.0 - r) * (1.0 + r));
    double h = 0.0;  // H[q/sqrt(1 - r^2)]: the zone variable's Cauchy integral (d eta/(eta - r) = d tau/(tau - t))
    for (const zone& z : zones_) h += z.amplitude * (*z.cauchy)((r - z.start) / z.rho - 1.0);
    return h;
}

double pressure_kinks::operator()(double r) const {
    if (!(std::fabs(r) < 1.0)) return 0.0;
    if (variable_) {  // one evaluation of w_k for both parts
        const variable_state& v = *variable_;
        const auto found = v.pressure.find(r);
        if (found != v.pressure.end()) return found->second;
        const double kz = v.weight->k_at(r);
        const double p = (*v.weight)(r) * (v.colloc->series(v.c, r) - (kz * v.carried(r) + v.cauchy(r)));
        if (v.pressure.size() >= 200000) v.pressure.clear();
        v.pressure.emplace(r, p);
        return p;
    }
    if (weighted_) return series_part(r) + kink_part(r);
    return std::sqrt(1.0 - r * r) * factor(r);
}

double pressure_kinks::integral(double lo, double hi) const {
    // On each piece p_q^0 is sqrt(1 - r^2) times a polynomial of the zone variable (inside a zone) or
    // an algebraic function with square roots at the zone's ends (outside): smooth in u after the map.
    std::vector<double> cuts{std::clamp(lo, -1.0, 1.0), std::clamp(hi, -1.0, 1.0)};
    std::vector<double> inner = ends();
    for (const double e : inner)
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
    if (variable_) {  // -h_n = -(1 + k_z^2) w_k sqrt(1 - t^2) g_n: what p_q carries exactly
        const double c = variable_->carried(r);
        if (c == 0.0) return 0.0;
        const double kz = variable_->weight->k_at(r);
        return -(1.0 + kz * kz) * (*variable_->weight)(r) * c;
    }
    double sum = 0.0;
    for (const weighted_zone& z : wzones_) {
        const double t = (r - z.start) / z.rho - 1.0;
        if (!(std::fabs(t) < 1.0)) continue;
        sum += z.amplitude * jacobi_weight(z.a, 1.0 - z.a, t) * jacobi_weight(a_n_, 1.0 - a_n_, r) * z.own->series(z.c, t);
    }
    for (const zone& z : zones_) {
        const double t = (r - z.start) / z.rho - 1.0;
        if (!(std::fabs(t) < 1.0)) continue;
        sum += z.amplitude * std::sqrt((1.0 - r * r) * (1.0 - t * t)) * u_series(z.b, t);
    }
    return normal_layer_ ? sum - (*normal_layer_)(r) : sum;  // 8(o): the right side gains K2[p_q^0]
}

void pressure_kinks::add_layers(const kernel& k2, const kernel& k1) {
    drop_blend_tables();
    if (zones_.empty()) return;
    // p_q^0 on the pieces between the zone ends (and the edges) is sqrt(1 - r^2) times a polynomial of the zone variable
    // (inside a zone) or an algebraic function with square roots at the zone's ends (outside): analytic in the cut
    // map's u (cut_convolution); its degree there is that of the zone's U-series plus one, next to the shortest zone.
    double narrowest = HUGE_VAL;
    std::size_t terms = 0;
    for (const zone& z : zones_) {
        narrowest = std::min(narrowest, z.rho);
        terms = std::max(terms, z.b.size());
    }
    const cut_convolution::values g = [this](const double* r, double* out, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) out[i] = (*this)(r[i]);
    };
    const int oscillation = static_cast<int>(terms) + 1;
    if (!k2.empty()) normal_layer_ = std::make_shared<const cut_convolution>(k2, g, ends(), oscillation, narrowest);
    const kernel difference = k2.minus(k1);
    if (!difference.empty())
        difference_layer_ = std::make_shared<const cut_convolution>(difference, g, ends(), oscillation, narrowest);
}

double pressure_kinks::layer_difference(double r) const { return difference_layer_ ? (*difference_layer_)(r) : 0.0; }
double pressure_kinks::layer_normal(double r) const { return normal_layer_ ? (*normal_layer_)(r) : 0.0; }

double pressure_kinks::load() const { return load_; }
double pressure_kinks::constant() const { return constant_; }

std::vector<double> pressure_kinks::ends() const {
    std::vector<double> e;
    if (variable_) e.assign(variable_->ends.begin(), variable_->ends.end());
    for (const zone& z : zones_) {
        e.push_back(z.start);
        e.push_back(z.start + 2.0 * z.rho);
    }
    for (const weighted_zone& z : wzones_) {
        e.push_back(z.start);
        e.push_back(z.start + 2.0 * z.rho);
    }
    return e;
}

namespace {
// W's fixed cuts graded towards a short piece (8(z), "W next to a thin zone"): between two neighbouring kinks' ends (or
// one and the edge 1) a piece more than short_piece_ratio times longer than its neighbour is cut at l, 3 l, 7 l, ...
// from the end they share (l the neighbour's length) up to its middle. Every point within the short piece is then at
// least the piece lengths it meets away from their far ends, so the rule of the tables answers it; ungraded, the long
// piece's band (4 (88/M^2)^2 of its length, blend) covers the whole short piece and every point there took near_part's
// graded rule, p afresh at about 10 x 32 points each (the driven pair's second stick zone, 3.3e-4 long beside a reversed
// slip 1.5 long: ten times the point's CPU). The cuts depend on the kinks' ends only: their pieces are kept (piece_table).
constexpr double short_piece_ratio = 16.0;
std::vector<double> cuts_towards_short_pieces(std::vector<double> fixed) {
    fixed.push_back(1.0);
    sort_cuts(fixed);
    std::vector<double> cuts;
    for (std::size_t i = 0; i + 1 < fixed.size(); ++i) {
        const double a = fixed[i], e = fixed[i + 1], mid = 0.5 * (a + e), length = e - a;
        if (i > 0 && length > short_piece_ratio * (a - fixed[i - 1]))
            for (double x = a, h = a - fixed[i - 1]; x + h < mid; h *= 2.0) cuts.push_back(x += h);
        if (i + 2 < fixed.size() && length > short_piece_ratio * (fixed[i + 2] - e))
            for (double x = e, h = fixed[i + 2] - e; x - h > mid; h *= 2.0) cuts.push_back(x -= h);
    }
    return cuts;
}
}  // namespace

std::optional<kinks_blend> pressure_kinks::blend(double s, double c) const {
    auto unit = blended_cauchy::make({1.0}, s, c);
    if (!unit) return std::nullopt;
    kinks_blend k(std::move(*unit));
    if (weighted_) {
        // 8(x): the whole weighted p on the pieces [s, ..., 1] cut at c and at the kinks' ends. The rule's points per
        // piece: a collocation point at a node spacing pi/(2n) (in the angle) from an end where p has a one-sided root
        // puts a pole of the subtracted integrand at twice that from the piece (in the angle); Gauss-Legendre then
        // converges like exp(-4 M/sqrt(n)) (Bernstein ellipse 1 + 2/sqrt(n)): M = 10 sqrt(n) + 48 gives e^-40 there.
        if (!piece_tables_) piece_tables_ = std::make_shared<std::vector<piece_nodes>>();
        k.whole_ = std::make_shared<const pressure_kinks>(*this);
        int n = 0;
        for (const weighted_zone& z : wzones_) n = std::max(n, z.rule->n);
        if (variable_) n = variable_->n;
        const int m = static_cast<int>(std::ceil(10.0 * std::sqrt(static_cast<double>(std::max(n, 1))))) + 48;
        // A piece inside a weighted zone carries its q, a series of up to n terms (about n/2 periods in the piece's
        // angle), which M points alias: M + n there (8(x) "W's routes": at n = 1000, f = 0.2 M alone erred by 5.3e-12
        // against QUADPACK, and its two interlaced rules differed by 1.3e-11, so W jumped where a point neared a node).
        if (!blend_rules_)
            blend_rules_ = std::make_shared<blend_rules>(blend_rules{
                std::make_shared<const gauss_legendre>(m), std::make_shared<const gauss_legendre>(m + n),
                std::make_shared<const gauss_legendre>(graded_points), std::make_shared<const gauss_legendre>(m + 1),
                std::make_shared<const gauss_legendre>(m + n + 1)});
        k.rule_ = blend_rules_->rule;
        k.zone_rule_ = blend_rules_->zone_rule;
        k.graded_rule_ = blend_rules_->graded_rule;
        k.second_rule_ = blend_rules_->second_rule;
        k.second_zone_rule_ = blend_rules_->second_zone_rule;
        const auto in_zone = [this](double a, double e) {
            for (const weighted_zone& z : wzones_)
                if (a >= z.start && e <= z.start + 2.0 * z.rho) return true;
            // The wired five zones (8(z)): p_q carries the n-term U-series of h w_d on each stick zone (without M + n
            // there the zone's load erred by -4.8e-10, +5.2e-10 at n = 512, 1000: session 23's review V5).
            if (variable_)
                for (int z = 0; z < 2; ++z)
                    if (a >= variable_->ends[2 * z] && e <= variable_->ends[2 * z + 1]) return true;
            return false;
        };
        std::vector<double> cuts{s, c, 1.0}, inner = ends();
        const std::vector<double> graded = cuts_towards_short_pieces(inner);
        inner.insert(inner.end(), graded.begin(), graded.end());
        for (const double e : inner)
            if (e > s && e < 1.0) cuts.push_back(e);
        sort_cuts(cuts);
        // A piece between two of the kinks' ends (or one and the edge 1) is the same for every blend of this pressure:
        // its nodes and p there are kept (piece_table) for the next blend, which multiplies them by its own H (bit for
        // bit the product tabulate forms). Newton's steps move s and c, and each asks a blend of both stick zones: the
        // pieces beyond the zones (the second stick zone's with M + n points) were tabulated afresh every time (the
        // tabulation was a third of the wired free rolling point, session 24).
        std::vector<double> kink_ends = ends();
        kink_ends.insert(kink_ends.end(), graded.begin(), graded.end());
        const auto fixed = [&kink_ends](double x) {
            return x == 1.0 || std::find(kink_ends.begin(), kink_ends.end(), x) != kink_ends.end();
        };
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            kinks_blend::weighted_piece piece{cuts[i], cuts[i + 1], 0, 0, in_zone(cuts[i], cuts[i + 1]), false};
            piece.kept = fixed(piece.a) && fixed(piece.e);
            const gauss_legendre& rule = piece.zone ? *k.zone_rule_ : *k.rule_;
            piece.begin = k.tables_[0].eta.size();
            if (piece.kept)
                k.tabulate(piece_table(rule, piece.a, piece.e, 0), k.tables_[0]);
            else
                k.tabulate(rule, piece.a, piece.e, k.tables_[0]);
            piece.end = k.tables_[0].eta.size();
            k.pieces_.push_back(piece);
        }
        // A point r at a distance d from a cut of a piece of length L sees the subtracted integrand's mirrored pole at
        // u = -2 sqrt(d/L) in the piece's angle, and the rule's error is about exp(-2 M sqrt(8 sqrt(d/L)/pi)): within
        // 1e-13 for d/L > (88/M^2)^2; the band is 4 times that. Nearer (a trial end next to the source's kink, the
        // checks' points at an end), near_part: the same rule on the pieces trimmed by 4 bands away from the cut, the
        // graded rule between (8(x) "W's routes"). Until session 22 such a point was declined, and the adaptive route
        // (dissimilar_zones::cauchy_by_quadrature) differed from this rule by 2.5e-11 at n = 1000: Newton cycled.
        const double near = 4.0 * std::pow(88.0 / (static_cast<double>(m) * m), 2);
        const std::size_t count = k.pieces_.size(), none = static_cast<std::size_t>(-1);
        // Cut i's band (pieces i - 1 and i on either side); groups of cuts nearer than 16 bands, merged until every
        // piece between two groups is 16 of both groups' bands long, so a point is near at most one group and the
        // trimmed pieces keep at least half their length.
        std::vector<double> band(cuts.size(), 0.0);
        for (std::size_t i = 0; i < count; ++i) {
            band[i] = std::max(band[i], near * (cuts[i + 1] - cuts[i]));
            band[i + 1] = std::max(band[i + 1], near * (cuts[i + 1] - cuts[i]));
        }
        std::vector<std::pair<std::size_t, std::size_t>> spans;  // [first cut, last cut] of each group
        for (std::size_t i = 0; i < cuts.size(); ++i) spans.push_back({i, i});
        const auto span_band = [&band](const std::pair<std::size_t, std::size_t>& g) {
            return *std::max_element(band.begin() + static_cast<std::ptrdiff_t>(g.first),
                                     band.begin() + static_cast<std::ptrdiff_t>(g.second) + 1);
        };
        for (bool merged = true; merged;) {
            merged = false;
            for (std::size_t g = 0; g + 1 < spans.size(); ++g) {
                const double gap = cuts[spans[g + 1].first] - cuts[spans[g].second];
                if (gap < 16.0 * std::max(span_band(spans[g]), span_band(spans[g + 1]))) {
                    spans[g].second = spans[g + 1].second;
                    spans.erase(spans.begin() + static_cast<std::ptrdiff_t>(g) + 1);
                    merged = true;
                    break;
                }
            }
        }
        for (const auto& g : spans) {
            kinks_blend::near_group group;
            group.cuts.assign(cuts.begin() + static_cast<std::ptrdiff_t>(g.first),
                              cuts.begin() + static_cast<std::ptrdiff_t>(g.second) + 1);
            group.band = span_band(g);
            group.left = g.first == 0 ? none : g.first - 1;  // piece [cuts[first - 1], cuts[first]]
            group.right = g.second + 1 == cuts.size() ? none : g.second;
            group.lo = group.left == none ? cuts[g.first] : cuts[g.first] - 4.0 * group.band;
            group.hi = group.right == none ? cuts[g.second] : cuts[g.second] + 4.0 * group.band;
            k.groups_.push_back(std::move(group));
        }
        k.trimmed_ = std::make_shared<std::vector<kinks_blend::trimmed_pair>>(k.groups_.size());
        return k;
    }
    for (const zone& z : zones_) {
        // g W_1 on the zone (docs/formulation.md 8(o), "W with the kinks"): g, a polynomial of degree terms - 1
        // (`terms` its coefficients above eps of their sum; those below change g by at most n eps of it), times W_1,
        // analytic inside the Bernstein ellipse through the images of r = +-1 (blended_cauchy.hpp), whose U
        // coefficients fall below e^-37 (1e-16) of W_1's size beyond degree 37/log(ellipse): m = terms + extra nodes
        // interpolate the product without aliasing any term above that, so H[g_Z W_1] is exact to about 1e-16 times
        // sum |b| max|W_1| plus the sums' rounding (m eps). No term of g is dropped: the rule is a transform's, not
        // the collocation's, so m may exceed max_nodes (at n = 1000 g has up to 1000 terms, none of them a rounding
        // plateau in general: 2e-6 of sum |b| beyond 789 at f = 0.2). m stays below max_transform_nodes where
        // blended_cauchy takes [s, c] (its rule asks log(ellipse) > 18.5/1023, so extra <= 2046, with n <= 1000);
        // a kink zone nearer an edge than that is declined (the adaptive route).
        const double lo = (1.0 + z.start) / z.rho + 1.0, hi = (1.0 - z.start) / z.rho - 1.0;
        const auto ellipse = [](double tau) { return tau + std::sqrt((tau - 1.0) * (tau + 1.0)); };
        const double extra = std::ceil(37.0 / std::log(std::min(ellipse(lo), ellipse(hi))));
        double size = 0.0;
        for (const double b : z.b) size += std::fabs(b);
        std::size_t terms = z.b.size();
        while (terms > 1 && std::fabs(z.b[terms - 1]) <= DBL_EPSILON * size) --terms;
        if (!(extra > 0.0 && extra + static_cast<double>(terms) <= max_transform_nodes)) return std::nullopt;
        const gauss_chebyshev rule = gauss_chebyshev::transform(std::max(min_nodes, static_cast<int>(terms + extra)));
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

void kinks_blend::tabulate(const gauss_legendre& rule, double a, double e, weighted_table& table) const {
    tabulate(whole_->nodes_on(rule, a, e, -1), table);
}

void kinks_blend::tabulate(const pressure_kinks::piece_nodes& kept, weighted_table& table) const {
    for (std::size_t j = 0; j < kept.eta.size(); ++j) {
        table.eta.push_back(kept.eta[j]);
        table.weight.push_back(kept.weight[j]);
        table.g.push_back(kept.p[j] * blend_at(kept.eta[j]));
    }
}

pressure_kinks::piece_nodes pressure_kinks::nodes_on(const gauss_legendre& rule, double a, double e, int table) const {
    piece_nodes nodes{a, e, table, {}, {}, {}};
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
        const mapped_node x = cos_map_node(rule, j, a, e);
        nodes.eta.push_back(x.eta);
        nodes.weight.push_back(x.weight);
        nodes.p.push_back((*this)(x.eta));
    }
    return nodes;
}

const pressure_kinks::piece_nodes& pressure_kinks::piece_table(const gauss_legendre& rule, double a, double e,
                                                               int table) const {
    for (const piece_nodes& kept : *piece_tables_)
        if (kept.a == a && kept.e == e && kept.table == table) return kept;
    piece_tables_->push_back(nodes_on(rule, a, e, table));
    return piece_tables_->back();
}

const kinks_blend::weighted_table& kinks_blend::second_table() const {
    if (second_built_) return tables_[1];
    for (const weighted_piece& piece : pieces_) {
        const gauss_legendre& rule = piece.zone ? *second_zone_rule_ : *second_rule_;
        if (piece.kept)
            tabulate(whole_->piece_table(rule, piece.a, piece.e, 1), tables_[1]);
        else
            tabulate(rule, piece.a, piece.e, tables_[1]);
    }
    second_built_ = true;
    return tables_[1];
}

double kinks_blend::blend_at(double eta) const {
    const double s = unit_.start(), c = unit_.end(), rho = 0.5 * (c - s);
    if (eta <= s) return 0.0;
    if (eta >= c) return 1.0;
    const double t = std::clamp((eta - s) / rho - 1.0, -1.0, 1.0);
    return 0.5 + M_1_PI * (std::asin(t) + t * std::sqrt((1.0 - t) * (1.0 + t)));
}

namespace {
// sum w (g(eta) - gr)/(eta - r) over `rule` on [a, e] in the cos map of the tables (pressure_kinks::blend).
template <class G>
double cos_map_sum(const gauss_legendre& rule, double a, double e, double r, double gr, const G& g) {
    double sum = 0.0;
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
        const mapped_node x = cos_map_node(rule, j, a, e);
        if (x.eta == r) continue;  // a node rounded onto the end r: its weight is below r's rounding
        sum += x.weight * (g(x.eta) - gr) / (x.eta - r);
    }
    return sum;
}
}  // namespace

double kinks_blend::near_part(double r, double gr, const near_group& group, trimmed_pair& trimmed) const {
    const auto g = [this](double eta) { return (*whole_)(eta) * blend_at(eta); };
    const std::size_t none = static_cast<std::size_t>(-1);
    if (!trimmed.built) {  // the rule on the trimmed pieces (their nodes do not depend on r)
        const auto rule = [this](const weighted_piece& p) -> const gauss_legendre& { return p.zone ? *zone_rule_ : *rule_; };
        if (group.left != none) tabulate(rule(pieces_[group.left]), pieces_[group.left].a, group.lo, trimmed.left);
        if (group.right != none) tabulate(rule(pieces_[group.right]), group.hi, pieces_[group.right].e, trimmed.right);
        trimmed.built = true;
    }
    // The rule's table on every piece outside the group's (r lies in (lo, hi): no node of these is near it), and on
    // the trimmed ones.
    const std::size_t first = group.left != none ? group.left : 0;
    const std::size_t last = group.right != none ? group.right : pieces_.size() - 1;
    double sum = 0.0;
    const weighted_table& table = tables_[0];
    const auto add = [&](const weighted_table& t, std::size_t from, std::size_t to) {
        for (std::size_t i = from; i < to; ++i) sum += t.weight[i] * (t.g[i] - gr) / (t.eta[i] - r);
    };
    for (std::size_t p = 0; p < pieces_.size(); ++p)
        if (p < first || p > last) add(table, pieces_[p].begin, pieces_[p].end);
    add(trimmed.left, 0, trimmed.left.eta.size());
    add(trimmed.right, 0, trimmed.right.eta.size());
    // [lo, hi] cut at the group's cuts and r, each part graded geometrically (ratio 2) towards each end from the
    // distance d to the nearest point beyond that end (r or a cut): a piece of length h then has its nearest singular
    // point (a kink's root, or the subtracted integrand's pole mirrored about a cut) at least h from it, where the cos
    // map's graded_points-point rule is exact to rounding (8(x) "W's routes").
    std::vector<double> points = group.cuts;
    points.push_back(r);
    points.push_back(group.lo);
    points.push_back(group.hi);
    sort_cuts(points);
    std::vector<double> ends;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const double u = points[i], v = points[i + 1];
        if (u < group.lo || v > group.hi) continue;  // r below s (W at a point before the zone): not integrated
        const double du = i > 0 ? u - points[i - 1] : INFINITY, dv = i + 2 < points.size() ? points[i + 2] - v : INFINITY;
        const double mid = 0.5 * (u + v);
        ends.assign(1, u);
        for (double x = u, h = du; x + h < mid; h *= 2.0) ends.push_back(x += h);
        std::size_t from_right = ends.size();
        for (double x = v, h = dv; x - h > mid; h *= 2.0) ends.push_back(x -= h);
        std::reverse(ends.begin() + static_cast<std::ptrdiff_t>(from_right), ends.end());
        ends.push_back(v);
        for (std::size_t j = 0; j + 1 < ends.size(); ++j) sum += cos_map_sum(*graded_rule_, ends[j], ends[j + 1], r, gr, g);
    }
    return sum;
}

std::optional<double> kinks_blend::zone_load() const {
    if (!whole_) return std::nullopt;
    // The pieces up to c (a cut) carry the zone; M + n points where q's n-term series lies (8(x) "W's routes": GSL's
    // route on [s, c] erred by 8e-12 at n = 1000, its own estimate 4e-13; this rule 3e-16).
    double sum = 0.0;
    const weighted_table& table = tables_[0];
    for (const weighted_piece& p : pieces_)
        if (p.e <= unit_.end())
            for (std::size_t i = p.begin; i < p.end; ++i) sum += table.weight[i] * table.g[i];
    return sum;
}

std::size_t kinks_blend::near_group_of(double r) const {
    std::size_t i = 0;
    while (i < groups_.size() && !(r > groups_[i].cuts.front() - groups_[i].band && r < groups_[i].cuts.back() + groups_[i].band))
        ++i;
    return i;
}

bool kinks_blend::near(double r) const { return near_group_of(r) < groups_.size(); }

std::optional<double> kinks_blend::weighted_part(double r, double blend) const {
    // Within 1e-9 of the trailing edge (1 - r)^a_N's difference quotient is a spike no fixed rule resolves: the
    // adaptive route (dissimilar_zones::cauchy_by_quadrature).
    const double s = unit_.start();
    const bool inside = r > s && r < 1.0;
    if (inside && !(1.0 - r > 1e-9)) return std::nullopt;
    const double gr = inside ? (*whole_)(r) * blend : 0.0;
    double sum = 0.0;
    const std::size_t group = near_group_of(r);
    const bool near = group < groups_.size();
    if (near) sum = near_part(r, gr, groups_[group], (*trimmed_)[group]);
    // A node within a thousandth of its weight (its local spacing) of r would lose eps |g|/|eta - r| of the difference
    // quotient to cancellation: then the other rule, whose nodes interlace (M and M + 1 points per piece), none as near.
    for (int l = 0; l < 2; ++l) {
        if (near) break;
        const weighted_table& table = l == 0 ? tables_[0] : second_table();
        sum = 0.0;
        bool near_node = false;
        for (std::size_t i = 0; i < table.eta.size() && !near_node; ++i) {
            const double d = table.eta[i] - r;
            near_node = std::fabs(d) < 1e-3 * table.weight[i];
            sum += table.weight[i] * (table.g[i] - gr) / d;
        }
        if (!near_node) break;
    }
    if (gr != 0.0) sum += gr * std::log((1.0 - r) / (r - s));
    return M_1_PI * sum;
}

std::optional<double> kinks_blend::operator()(double r, double blend) const {
    if (whole_) return weighted_part(r, blend);
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
    if (whole_) {
        for (std::size_t i = 0; i < count; ++i) out[i] = weighted_part(r[i], blend[i]);
        return;
    }
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

double blend_theta3(double t) {
    // P's U coefficients (header; 8(r)).
    static const std::vector<double> p{0.0, 45.0 / (60.0 * M_PI), 0.0, -9.0 / (60.0 * M_PI), 0.0, 1.0 / (60.0 * M_PI)};
    return 0.5 + M_1_PI * std::asin(t) + std::sqrt((1.0 - t) * (1.0 + t)) * u_series(p, t);
}

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
