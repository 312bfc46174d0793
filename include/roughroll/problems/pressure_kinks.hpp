// SPDX-License-Identifier: GPL-3.0-or-later
// The pressure's one-sided kinks at the zone ends at full coupling, carried explicitly (docs/formulation.md
// 8(l), "Proposal", step 0). (D1) has -beta_D q on its right side, q the stick zones' part of p1 (p1 = sign
// (f p S + q), S = 1 off the blends), and the bounded solution of H[p] = -beta_D q has B (r - c)_+^(1/2) at
// every zone end, which the pressure's single U-series (4.1) cannot carry: the zone ends then converge at
// order 1 in n (8(l), "What limits the zone ends to order 1"). With
//   p = sqrt(1 - r^2) phi + p_q^0,   p_q^0 = beta_D sqrt(1 - r^2) H[q / sqrt(1 - r^2)],
//   H[g](r) = (1/pi) PV int g(eta) d eta / (eta - r),   H[p_q^0] = -beta_D q + C,   C = (beta_D/pi) int q/sqrt(1 - r^2),
// the normal solve for phi takes beta_D (p1 - q) on its right side (smooth but for k = sigma beta_D f times
// the kinks), its load row int sqrt(1 - r^2) phi = 1 - int p_q^0, int p_q^0 = beta_D int q r/sqrt(1 - r^2)
// (from (1/pi) PV int sqrt(1 - r^2)/(r - tau) dr = -tau), and e = pi (gamma_0n - C)/(2 lambda).
// Per stick zone [s, c], r = s + rho (t + 1): q/sqrt(1 - r^2) = sqrt(1 - t^2) g(t), g = psi(t)/sqrt(1 - r(t)^2)
// smooth (the zone lies inside the contact, 8(g)), expanded in U_j on the zone's Gauss-Chebyshev nodes
// (u_coefficients); its Cauchy integral is cauchy_u_series (-sum b_j T_{j+1} on the zone, -sum b_j z^(j+1) off
// it), which holds (r - c)_+^(1/2) exactly. The q carried is the one of that expansion,
// sqrt(1 - r^2) sqrt(1 - t^2) g_n(t), so that (D1) holds for the p represented (removed() below).
// Rough rollers (docs/formulation.md 8(o), "Rough rollers"; add_layers): with the layer terms L_i = H + K_i the
// normal solve's right side gains K2[p_q^0] (it goes in through removed(), which the solve takes from beta_D p1)
// and the tangential G = -L1[p] gains (K2 - K1)[p_q^0] (layer_difference), each tabulated once per kinks
// (cut_convolution, the zone ends as cuts).
#pragma once

#include <algorithm>
#include <functional>
#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/numerics/blended_cauchy.hpp"
#include "roughroll/numerics/cauchy_u_table.hpp"
#include "roughroll/numerics/cut_convolution.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

class kinks_blend;

class pressure_kinks {
public:
    // Adds the stick zone [start, c0] whose q(r) = sign sqrt(1 - t^2) psi(t), psi = sum psi_b U_j + blend(t), its
    // g expanded on `rule`'s nodes. `blend` (empty: 0) is a further part of psi carried with q, analytic on the
    // closed zone: the blended zone's 2 f p (Theta - Theta_3)/sqrt(1 - t^2) (blend_kinks). Needs -1 < start < c0 < 1.
    void add_zone(const gauss_chebyshev& rule, double beta_d, double sign, double start, double c0,
                  const std::vector<double>& psi_b, const std::function<double(double)>& blend = {});
    // The weighted pressure of docs/formulation.md 8(w) (plan C; braked three zones of smooth rollers, a + b = 1):
    //   p = w_N phi + p_q,  w_N = (1 - r)^a_N (1 + r)^(1 - a_N),  a_N = 1/2 + atan(k_E)/pi,  k_E = sigma beta_D f,
    //   p_q = -(beta_D/(1 + k_E^2)) sum_Z (k_E q_Z - w_N H[q_Z/w_N]),   (H + k_E)[p_q] = -beta_D q + C,
    //   C = (beta_D sin(pi a_N)/pi) int q/w_N,   int p_q = 2 beta_D sin(pi a_N) int (q/w_N) P_1^(-a_N, a_N - 1).
    // The object then carries the whole pressure (the normal solution's U-series is zero): set_weight first, then
    // add_weighted_zone per stick zone (q = sign w_Z(t) psi(t), w_Z = (1 - t)^a_Z (1 + t)^(1 - a_Z)), then, after the
    // normal solve, set_series with phi's Jacobi coefficients on w_N. Not combined with add_zone.
    void set_weight(double k_e);
    // `rules_of`: kinks of an earlier step whose zone recurrences (n, a_z) are taken instead of built again (the same
    // ones). `rules`: the solve's Gauss-Jacobi rules, whose rules of n and 4 n nodes of the weight w_Z the tangential
    // solver's Jacobi zone (8(v)) takes too; null: built here (or taken from `rules_of`).
    void add_weighted_zone(int n, double beta_d, double sign, double start, double c0, double a_z,
                           const std::function<double(double)>& psi, const pressure_kinks* rules_of = nullptr,
                           jacobi_rule_set* rules = nullptr);
    void set_series(std::vector<double> phi_c);
    // The five zones' pressure at full coupling on the exact weight of 8(z) ("Wired", session 23; it replaced 8(x)'s w_N
    // with the plateau and the remainder). After set_weight(k_E), k_E = -sign beta_D f: the operator is
    // (H + k(r)), k = sign beta_D f S_3(r), S_3 = 2 B - 1 with B the plateau of the stick zones `ends` (s1, c1, s2, c2;
    // blend_plateau), k = k_E at both edges; p = w_k psi + p_q on the weight of (H - k_z), k_z = -k (numerics/
    // variable_k_weight), p_q = -(k_z h/(1 + k_z^2) + w_k H[h w_d]) for h = -beta_D sign q, q = sqrt(1 - t^2) psi_Z(t) on
    // each stick zone (8(z), "The stick zones' part p_q for a varying k": 1/(1 + k^2) inside H), h w_d expanded in U_j on
    // the zone's n Gauss-Chebyshev nodes. Nothing is left on (D1)'s right side: solve_variable gives the whole p.
    // A weight or rule that cannot be built at these ends and n (numerics/variable_k_weight's checks) is a
    // resolution_error naming what may answer (another n, coupling = "johnson"): no fallback to another discretisation,
    // which would put the levels of one estimate on two (8(x), "The fallback").
    void set_variable(int n, double beta_d, double sign, double f, const std::array<double, 4>& ends,
                      const std::array<std::function<double(double)>, 2>& psi);
    bool variable() const { return static_cast<bool>(variable_); }
    // The k of (H + k) at r: k_E, or sign beta_D f S_3(r) after set_variable.
    double k_at(double r) const;
    struct variable_result {
        std::vector<double> psi;  // at the nodes of w_k's rule
        double lambda, gamma, rcond;  // P_H/P2, gamma = (2/pi) lambda e of (H + k) p + gamma + (2/pi) lambda r = -beta_D sign q
        double lambda_rounding;       // the bound on lambda's rounding (variable_k_collocation::solution)
    };
    variable_result solve_variable();  // after set_variable; stores psi
    bool weighted() const { return weighted_; }
    double weight_a() const { return a_n_; }
    double weight_k() const { return k_e_; }
    double series_part(double r) const;  // w_N(r) sum phi_j P_j^(a_N, 1 - a_N)(r), 0 outside (-1, 1)
    double kink_part(double r) const;    // p_q(r) of the weighted zones
    bool empty() const { return zones_.empty() && !weighted_; }

    double operator()(double r) const;  // p_q^0(r), 0 outside (-1, 1)
    // p_q^0(r)/sqrt(1 - r^2), a bounded function with one-sided square roots at the zone ends: the factor
    // that W's edge path multiplies by sqrt((1 - r)(1 + r)) without losing 1 - r's digits near r = 1.
    double factor(double r) const;
    // int_lo^hi p_q^0 for -1 <= lo <= hi <= 1 (docs/formulation.md 8(o)): Gauss-Legendre on the pieces
    // between lo, hi and the zone ends, each mapped by r = (a + b)/2 - (b - a)/2 cos u so that the square
    // roots at its ends (the one-sided terms, sqrt(1 - r^2) at the edges) become smooth in u.
    double integral(double lo, double hi) const;
    // What the normal solve takes from beta_D p1 on its right side: beta_D q(r) as carried by p_q^0 (its expansion),
    // less the layer term K2[p_q^0](r) with add_layers (8(o): (D1) for phi has -beta_D (p1 - q) - K2[p_q^0] there).
    double removed(double r) const;
    // Rough rollers (8(o)): tabulates K2[p_q^0] and (K2 - K1)[p_q^0] for the zones added so far (call it after them;
    // full_coupling carries rough rollers' kinks on three zones only).
    void add_layers(const kernel& k2, const kernel& k1);
    bool layered() const { return normal_layer_ || difference_layer_; }
    double layer_difference(double r) const;  // (K2 - K1)[p_q^0](r), G's part (0 without add_layers)
    double layer_normal(double r) const;      // K2[p_q^0](r) (0 without add_layers)
    double load() const;                // int p_q^0 = beta_D int q r/sqrt(1 - r^2)
    double constant() const;            // C of H[p_q^0] = -beta_D q + C
    std::vector<double> ends() const;   // the zone ends (the kinks)
    // The Cauchy part of W for p_q^0 and the blend of the stick zone [s, c] (kinks_blend below). Empty where
    // blended_cauchy declines [s, c] or a kink zone lies too near a contact edge for the expansion below.
    std::optional<kinks_blend> blend(double s, double c) const;

private:
    struct zone {
        double start, rho, amplitude;  // amplitude = beta_D sign
        std::vector<double> b;         // U coefficients of g(t) = psi(t)/sqrt(1 - r(t)^2)
        // H[g] = cauchy_u_series(b, t) tabulated (cauchy_u_table.hpp): p_q^0 is read by every quadrature of W and
        // int p H, and a value from the table costs an acos or acosh and 25 terms instead of n (within eps sum |b|).
        std::shared_ptr<const cauchy_u_table> cauchy;
    };
    std::vector<zone> zones_;
    struct weighted_zone {
        double start, rho, amplitude, a;  // amplitude = beta_D sign; q's weight exponent a_Z at t = 1
        std::shared_ptr<const gauss_jacobi> rule, far;
        std::vector<double> c, at_nodes, at_far;  // G = psi/w_N: Jacobi coefficients, values at both rules' nodes
        std::shared_ptr<const jacobi_recurrence> own, shifted;  // P^(a_Z, b_Z) and P^(-a_Z, -b_Z)
    };
    std::shared_ptr<const jacobi_recurrence> series_rec_;  // P^(a_N, 1 - a_N)
    double cauchy_outside(const weighted_zone& z, double x) const;
    bool weighted_ = false;
    double k_e_ = 0.0, a_n_ = 0.5;
    std::vector<double> series_;
    std::vector<weighted_zone> wzones_;
    std::vector<double> legendre_nodes_, legendre_weights_;  // integral's rule, 2n + 32 points (as chebyshev_projection)
    void keep_legendre_rule(int points);
    double load_ = 0.0, constant_ = 0.0;
    std::shared_ptr<const cut_convolution> normal_layer_, difference_layer_;  // add_layers' tables
    struct variable_state;                       // set_variable's (pressure_kinks.cpp); shared by copies
    std::shared_ptr<variable_state> variable_;
    // blend()'s tables of the pieces between the kinks' ends (pressure_kinks.cpp): per piece and table (0: M or M + n
    // points, 1: one more), the nodes in the cos map, their weights and p there. Shared by copies; every change of the
    // pressure drops them (not thread safe, as the tables of kinks_blend).
    friend class kinks_blend;
    struct piece_nodes {
        double a, e;
        int table;
        std::vector<double> eta, weight, p;
    };
    mutable std::shared_ptr<std::vector<piece_nodes>> piece_tables_;
    struct blend_rules {  // kinks_blend's rules (its rule_ .. second_zone_rule_), the same for every blend of this pressure
        std::shared_ptr<const gauss_legendre> rule, zone_rule, graded_rule, second_rule, second_zone_rule;
    };
    mutable std::shared_ptr<blend_rules> blend_rules_;
    const piece_nodes& piece_table(const gauss_legendre& rule, double a, double e, int table) const;
    // `rule`'s nodes on [a, e] in the cos map, their weights and p there (a piece kept or a blend's own).
    piece_nodes nodes_on(const gauss_legendre& rule, double a, double e, int table) const;
    void drop_blend_tables();
};

// W's Cauchy part of p_q^0 times the blend H of a stick zone [s, c] (docs/formulation.md 8(o), "W with the kinks"):
//   W_q(r) = H[p_q^0 H](r),   p_q^0 = sum_Z a_Z f_0 H[g_Z],   f_0 = sqrt(1 - r^2),  g_Z = sqrt(1 - t^2) g(t) on Z,
// by Tricomi's identity H[u H[v]] + H[v H[u]] = H[u] H[v] - u v (the finite Hilbert transform of 2(b)) with
// u = f_0 H and v = g_Z: with W_1 = H[f_0 H] (blended_cauchy of the one-term series {1}),
//   W_q(r) = sum_Z a_Z (W_1(r) H[g_Z](r) - f_0(r) H(r) g_Z(r) - H[g_Z W_1](r)),
// where H[g_Z] is cauchy_u_series of g's coefficients and H[g_Z W_1] that of g W_1 expanded in U_j on Z's
// Gauss-Chebyshev nodes: per r two sums of O(n) terms and W_1(r), instead of an adaptive quadrature of p_q^0.
// W_1 is analytic on [s, c] up to its ends (the blend's 3/2 powers give no own-side singular term), so the
// expansion converges geometrically on Z = [s, c]; where Z and [s, c] differ by delta (the alternation's last
// change of the ends), W_1 has (delta)^(3/2) one-sided terms on Z and the expansion an error of that order.
class kinks_blend {
public:
    // W_q(r) for -1 <= r <= 1, `blend` the value H(r) of the stick zone's blend; empty where W_1(r) does not converge.
    std::optional<double> operator()(double r, double blend) const;
    // The same at `count` points r[i] with blends blend[i] into out[i], bit for bit (the n-term sums of the points
    // side by side: W at a zone's collocation points, dissimilar_zones::W).
    void operator()(const double* r, const double* blend, std::optional<double>* out, std::size_t count) const;
    // int_s^c p H (the stick zone's part of int p H) by the weighted tables' rule (docs/formulation.md 8(x) "W's
    // routes"); empty unless the pressure is weighted.
    std::optional<double> zone_load() const;
    // Whether W at r takes the graded rule about a group of cuts (near_part) rather than the tables' rule: r within a
    // group's band (weighted pressures; false otherwise).
    bool near(double r) const;

private:
    friend class pressure_kinks;
    explicit kinks_blend(blended_cauchy unit) : unit_(std::move(unit)) {}
    // The weighted pressure (8(w), 8(x): the object carries the whole p, the normal U-series is zero): W's Cauchy part
    // H[p H](r) by a fixed rule on the pieces between s, the kinks' ends and 1, each in the cos map (p's one-sided
    // square roots at the zone ends and (1 - r)^a_N at the edge smooth or nearly so in the angle), p H tabulated at
    // its nodes once per blend, g(r) subtracted on every piece (the principal value), + g(r) log((1 - r)/(r - s)).
    // Next to a cut (within its band) the same rule on the pieces trimmed away from it and a graded rule on the rest
    // (near_part, docs/formulation.md 8(x) "W's routes"). Empty only within 1e-9 of r = 1.
    std::optional<double> weighted_part(double r, double blend) const;
    std::shared_ptr<const pressure_kinks> whole_;  // the weighted pressure (a copy), null otherwise
    struct weighted_table {
        std::vector<double> eta, weight, g;  // the pieces' nodes, weights (d eta), p H there
    };
    // M and M + 1 points per piece (interlaced nodes). The second is read only where a point r lies within a thousandth
    // of a node's weight of a node of the first (weighted_part): built then (second_table), not with every blend (half of
    // the tabulation, which was a third of the wired free rolling point, session 24).
    mutable weighted_table tables_[2];
    mutable bool second_built_ = false;
    const weighted_table& second_table() const;
    // The pieces [a, e] between the cuts, their entries [begin, end) in the first table, whether inside a weighted zone
    // (then M + n points: q's n-term series), and whether between two of the kinks' ends (pressure_kinks::piece_table).
    struct weighted_piece {
        double a, e;
        std::size_t begin, end;
        bool zone, kept;
    };
    std::vector<weighted_piece> pieces_;
    // Cuts nearer one another than 16 bands, as one group: a point within `band` of them (lo_band < r < hi_band)
    // takes the pieces `left` .. `right` (the one ending at the group's first cut .. the one starting at its last; npos
    // at s or 1) as the rule on [a of left, lo] and [hi, e of right] plus the graded rule on [lo, hi], lo and hi four
    // bands beyond the group's outer cuts.
    struct near_group {
        std::vector<double> cuts;
        double band, lo, hi;
        std::size_t left, right;
    };
    std::vector<near_group> groups_;
    struct trimmed_pair {
        bool built = false;
        weighted_table left, right;  // the rule on [a of left, lo] and on [hi, e of right]
    };
    std::shared_ptr<std::vector<trimmed_pair>> trimmed_;  // per group, built at its first near point (shared by copies)
    // M, M + n and graded_points points, and M + 1, M + n + 1 for the second table: the pressure's (blend_rules), made at its
    // first blend (building them for every blend was a twentieth of the wired free rolling point, session 24).
    std::shared_ptr<const gauss_legendre> rule_, zone_rule_, graded_rule_, second_rule_, second_zone_rule_;
    double near_part(double r, double gr, const near_group& group, trimmed_pair& trimmed) const;
    std::size_t near_group_of(double r) const;  // the first group whose band holds r, groups_.size() if none
    double blend_at(double eta) const;  // H of the zone [s, c] (8(g))
    // Appends `rule`'s nodes on [a, e] in the cos map, their weights and p H there to `table`.
    void tabulate(const gauss_legendre& rule, double a, double e, weighted_table& table) const;
    // The same from a piece the pressure kept (pressure_kinks::piece_table), times this blend's H.
    void tabulate(const pressure_kinks::piece_nodes& kept, weighted_table& table) const;
    struct part {
        double start, rho, amplitude;
        std::vector<double> g, gw;                   // U coefficients of g and of g W_1 on the kink zone
        std::shared_ptr<const cauchy_u_table> cauchy;  // H[g], the zone's table
    };
    blended_cauchy unit_;  // W_1
    std::vector<part> parts_;
};

// (Theta(t) - Theta_3(t))/sqrt(1 - t^2) = -(2/(15 pi)) t (1 - t^2) (9 - 4 t^2) on -1 <= t <= 1 (docs/formulation.md
// 8(r)): Theta the blend of 8(g) (Theta' = (2/pi) sqrt(1 - t^2), (1 +- t)^(3/2) at the ends), Theta_3 the blend with
// Theta_3' = (16/(5 pi)) (1 - t^2)^(5/2) ((1 +- t)^(7/2) at the ends). Both blends' arcsin t have the coefficient
// 1/pi, so their difference is sqrt(1 - t^2) times this polynomial: a part of q that pressure_kinks carries exactly.
double blend_kinks(double t);

// Theta_3(t) = 1/2 + arcsin(t)/pi + sqrt(1 - t^2) P(t), P = (45 U_1 - 9 U_3 + U_5)/(60 pi) = (33 t - 26 t^3 + 8 t^5)/(15 pi),
// |t| <= 1 (docs/formulation.md 8(r)): the blend whose derivative (16/(5 pi)) (1 - t^2)^(5/2) leaves (1 +- t)^(7/2) at the
// zone ends, Theta's arcsin with Theta's t sqrt(1 - t^2)/pi less blend_kinks; the variable exponent of 8(z) rises and
// falls with it across the five zones' stick zones (set_variable).
double blend_theta3(double t);

// Adds to `points` (breakpoints of a quadrature over [points' least, points' greatest]) the zone ends of
// `kinks` that lie strictly inside that range and more than `apart` from every point: an adaptive rule
// that maps each piece's ends to smooth ones (end_quadrature::piece) then meets p's one-sided
// square roots at piece ends (docs/formulation.md 8(o)).
void add_kink_points(std::vector<double>& points, const pressure_kinks& kinks, double apart);

}  // namespace roughroll
