// SPDX-License-Identifier: GPL-3.0-or-later
// Dissimilar rollers in Johnson's approximation (docs/formulation.md section 8): the pressure of
// the uncoupled normal problem, and the tangential problem (D2) with Dundurs' forcing,
//   v(r) = xi - L1[p1](r) + beta_D p(r);  stick: v = 0, |p1| <= f p;  slip: p1 = sigma f p, sigma v > 0;
//   int p1 = Q                                                                          8(c), 8(e)
// No stick zone reaches a contact edge when beta_D != 0 (8(g)), so the paper's zone [-1, c0] is
// never the answer. The structures solved here:
//   - three zones, slip sigma [-1, s), stick [s, c0], slip sigma (c0, 1] with both slip zones in
//     the direction sigma = sgn Q. With p1 = sigma (f p + q) on the stick zone and the mirror of
//     8(h), (beta_D, Q, xi, p1) -> (-beta_D, -Q, -xi, -p1), this is the |Q| problem
//       L1[q] = xi' + b p + f G,  rho int q = |Q| - f,   b = sigma beta_D,  xi = sigma xi'   8(e)
//     on the moved zone r = s + rho (t + 1) (tangential_solver::solve_on_zone with forcing b), with
//     the entry condition psi(-1) = 0 of 7(b) at s > -1 and the exit C0 = 0 built into (4.1).
//     This is the structure of a braked roller 1 for beta_D > 0 (Q beta_D < 0; 8(g)'s table);
//   - three zones with the leading slip against Q: slip -sigma [-1, s), stick [s, c0], slip sigma
//     (c0, 1] (a driven roller 1 for beta_D > 0, 8(g)). In the |Q| frame p1 = -f p on the leading
//     zone, f p on the trailing one, and on the stick zone p1 = f p S + q with the blend
//       S = -1 + 2 Theta(t),  Theta(t) = 1/2 + (asin t + t sqrt(1 - t^2))/pi                  8(g)
//     (Theta rises like (1 + t)^(3/2) and ends like 1 - (1 - t)^(3/2): only half-integer powers at
//     the ends, so the collocation keeps its order). With H = 0, Theta, 1 on the three zones,
//     p S = -p + 2 p H, L1[p S] = G + 2 W, W = L1[p H], and
//       L1[q] = xi' + b p - f G - 2 f W  (stick),  v = xi' + b p - f G - 2 f W - L1[q]  (slip),
//     at full coupling of smooth rollers with G_H = (1 - H) G + H G_d in place of G, G_d = -L1[p_d] of the discrete
//     pressure: the kinks of p beyond each end from G's formula alone (8(u));
//       Q' = f (2 int p H - 1) + rho int q;
//     W by adaptive quadrature (GSL qagp, the Cauchy part with its singularity subtracted);
//   - gross sliding |Q| = f: slip everywhere, v = xi' + b p + f G >= 0 vanishing at its least
//     point r*: xi' = -min_r (b p + f G) (8(g));
//   - the complete-slip limit f -> 0 (8(f)), its own special case (complete_slip_creep).
//   - five zones (8(j)): by five_zones (five_zones.cpp), not through solve().
// The two three-zone structures are values of the one zone search's operator (zone_operator below,
// stick_zone_operator.hpp), found by zone_solver; solve tries them in turn (the coarser level's first).
// Not solve()'s (refused with resolution_error naming what is missing, never a number): free rolling Q = 0 and
// every load whose answer is not one of the three-zone structures above (five zones: five_zones), and coupling
// "full" (full_coupling.hpp).
#pragma once

#include <functional>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "roughroll/model/kernel.hpp"

#include "roughroll/model/dissimilar.hpp"
#include "roughroll/numerics/blended_cauchy.hpp"
#include "roughroll/numerics/damped_newton.hpp"
#include "roughroll/numerics/end_quadrature.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/numerics/u_series_table.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_solver.hpp"
#include "roughroll/problems/zone_checks.hpp"
#include "roughroll/problems/zone_layout.hpp"
#include "roughroll/problems/zone_solver.hpp"
#include "roughroll/problems/zone_start.hpp"

namespace roughroll {

// What a contact with these materials and options can solve: beta_D finite with |beta_D| < 3/4; for beta_D != 0,
// not method 'one-parameter' at coupling 'full' (the limit is derived at Johnson's level only, 8(s)), and not zones
// 'single' with the other methods (the paper's zone is never their answer, 8(g)). Each refusal is one input_error line.
void check_dissimilar(const dissimilar& materials, const solver_options& options);

// The complete-slip limit f -> 0 at fixed Q/f (docs/formulation.md 8(f)): v = xi + beta_D p, the
// central band |r| < r_c carries (1 + sgn(beta_D) Q/f)/2 of the load, and xi_0 = -beta_D p(r_c).
// Needs p even and decreasing in |r| (checked on 2001 points: else input_error). For Hertz and
// Q = 0, -pi xi_0/(4 beta_D) = cos(phi)/2 = 0.457386 (Bentall and Johnson's 0.457).
struct complete_slip {
    double r_c;  // edge of the central band
    double xi;   // xi_0, divided by nothing: the limit of xi itself (xi = O(beta_D), not O(f))
};
complete_slip complete_slip_creep(const normal_solution& normal, double beta_d, double Q_over_f);

// The thickness of the slip zone at the leading edge for |beta_D| small against f, 2 exp(-pi f kappa/|beta_D|)
// with kappa from Carter's traction at the load (docs/formulation.md 8(j) item 11). Below
// thinnest_edge_zone(n), a hundredth of the collocation's end spacing (pi^2/2)/n^2, no point is resolved
// at n (measured there), and contact::point refuses the load at once (check_edge_zones_resolvable: a
// resolution_error saying which |beta_d| is needed, and beta_d = 0 where that moves xi by less than the user's
// relative `tolerance`) instead of after minutes of search. Gross sliding |Q| = f is never refused.
double leading_zone_estimate(double beta_d, double f, double Q);
double thinnest_edge_zone(int n);
void check_edge_zones_resolvable(double beta_d, double f, double Q, int n, double tolerance);

// int_lo^hi p(r) dr for the pressure (4.1), in closed form from its U-series (r = cos theta:
// U_j(r) sqrt(1 - r^2) dr = -sin((j + 1) theta) sin(theta) d theta).
double load_between(const normal_solution& normal, double lo, double hi);

// Breakpoints of W's quadrature closer than this are not cut (r next to an end, the kinks' ends at the zone's); the
// zones thinner than a few of it are refused before any solve (unresolvable_zones.hpp).
constexpr double breakpoint_apart = 1e-9;

// How well Newton's method fixes the zone ends (as zone_solver's, docs/formulation.md 7(e)): the
// entry condition psi(-1) carries rounding of about 1e-13, which moves the ends by a few 1e-12;
// the estimates of the ends include it as a floor.
constexpr double zone_end_resolution = 1e-11;

// resolution_error naming the failed checks unless s's checks (3.3)-(3.4) hold: a three-zone
// answer that fails them is another structure's, never reported.
void require_checks(const tangential_solution& s);

// Five zones (docs/formulation.md 8(g), 8(j)): slip -1 [-1, s1), stick [s1, c1], slip +1 (c1, s2),
// stick [s2, c2], slip -1 (c2, 1], in the frame beta_D > 0 (the exchange of rollers of 8(h) gives
// beta_D < 0: Q, xi, p1, v and the slip directions change sign, the ends do not). p1 = f p S + q1 + q2 with S = -1 + 2 H1 - 2 H2, H_k rising as Theta over zone k, and
//   L1[q1 + q2] = xi + beta_D p - f G - 2 f W1 + 2 f W2  on both stick zones,  W_k = L1[p H_k],
// (at full coupling zone 1 with G_H = (1 - H1) G + H1 G_d in place of G, 8(u)),
//   Q = f (-1 + 2 int p H1 - 2 int p H2) + rho1 int q1 + rho2 int q2.
// Each zone's system carries its own constant xi_k (the regularising constant of 8(g)'s counting);
// the four ends solve Q(ends) = Q, psi1(-1) = 0, psi2(-1) = 0, xi1 = xi2.
// Their solution is a tangential_solution (five_zone_system): the layout slip -d [-1, s1), stick [s1, c1], slip d
// (c1, s2), stick [s2, c2], slip -d (c2, 1], d = sgn beta_D (five_zones_layout; start, c0 the first stick zone, start2,
// end2 the second), xi = xi1 (= xi2 at the root) and Q with the frame's sign `sign` (8(h)), `forcing` the frame's
// |beta_D| (another value only on a continuation in beta_D/f), the worse rcond, Newton's iterations and ends'
// resolution, the checks ((3.3) on both stick zones, (3.4) with S on the three slip zones), and each stick zone's
// system (zone_system(k): its psi and xi_k), from which traction, slip_velocity and check answer for all five zones.
using five_zone_start = zone_start<tangential_solution>;  // a start of their search (zone_start.hpp)

// The last four zones' values of T (W's Cauchy parts of the blended zone, 8(g), 8(o)): five zones alternate
// two zones and Newton's steps move both, so each is made once per zone. A pointer returned stays valid
// until the next call; null where `make` gives none (the caller's adaptive quadrature).
template <class T>
class zone_memo {
public:
    template <class Make>
    const T* operator()(double start, double c0, const Make& make) {
        for (const auto& [s, c, value] : entries_)
            if (s == start && c == c0) return value ? &*value : nullptr;
        if (entries_.size() == 4) entries_.erase(entries_.begin());
        entries_.push_back({start, c0, make()});
        const auto& value = std::get<2>(entries_.back());
        return value ? &*value : nullptr;
    }

private:
    std::vector<std::tuple<double, double, std::optional<T>>> entries_;
};

class dissimilar_zones {
public:
    // The tangential solver supplies G, the system (4.4) on any zone with the forcing, the
    // tractions, slip velocities and checks; it must outlive this workspace. beta_d != 0.
    // `k1`: K1* of the solver (for W of the blended stick zone).
    dissimilar_zones(tangential_solver& solver, const kernel& k1, double beta_d);

    // p1(r) and v(r) (0 on the stick zones) of a solution of this workspace, every structure (three zones of either
    // kind, five zones, the edge layers neglected), and its checks (3.3)-(3.4) on its layout.
    double traction(const tangential_solution& s, double r);
    double slip_velocity(const tangential_solution& s, double r);
    traction_checks check(const tangential_solution& s);

    // The point at load Q, |Q| <= f, with its checks (3.3)-(3.4) on every zone (made, not acted
    // on: a reported point goes through require_checks, a level of an estimate need not);
    // resolution_error for free rolling and where no three zones carry Q (numerical_error only for a
    // numerical fault of the searches: a GSL status, a singular system). `ends`: the ends (s, c) of a zone near the one sought
    // (the coarser level's layout), the start of Newton's method; empty: the starts of the stick zone are scanned.
    // `opposite`: try the leading slip against Q first (the coarser level's structure).
    // only_this_kind: the structure `opposite` names, not the other one after it (full coupling's weighted steps, 8(w)).
    tangential_solution solve(double Q, const std::vector<double>& ends = {}, bool opposite = false,
                              bool only_this_kind = false);
    // How many times solve was asked here (each a three-zone search, both structures where the first fails): a
    // count of work, for tests that pin where a search is not made (Johnson's point from coarser five zones).
    std::size_t three_zone_searches() const { return three_zone_searches_; }

    // Five zones at load Q, |Q| < f, by Newton in the four ends from `ends` = (s1, c1, s2, c2) (damped_newton),
    // with the forcing `beta` in place of |beta_D| where given (a step of the continuation in beta_D/f); empty
    // when Newton does not converge, and where it stops at the ends' rounding limit, noted in `met` where given
    // (zone_newton.hpp: the caller refuses with it where none of its routes answers). The checks are made, not
    // acted on. `kept`: Newton's Jacobian carried from the last call (full coupling's alternation, damped_newton.hpp).
    // `checked` false: the checks are not made (NaN margins, none holding), for a caller that makes them (check) where
    // it reads them.
    std::optional<tangential_solution> five_zones(double Q, const std::vector<double>& ends,
                                                 std::optional<double> beta = std::nullopt,
                                                 rounding_limits* met = nullptr, newton_jacobian* kept = nullptr,
                                                 bool checked = true);
    // Five zones at load Q, |Q| < f, from the starts `first` (the coarser level's ends, a curve's previous row),
    // then from the search's own (zone_start.hpp, 8(j) 4a): the first start to reach Q whose checks hold is the
    // answer (a root whose checks fail stands only where no later start gives one that holds); empty where
    // none does, where the continuation ends on the braked side (the three zones of a braked roller 1 answer), and
    // where the driven three zones at Q keep v > 0 up to the trailing edge (they answer). A start whose Newton (of
    // the three zones or the five) stops at the ends' rounding limit gives nothing, the next start is tried; the
    // limit is noted in `met` where given.
    std::optional<tangential_solution> five_zones(double Q, std::vector<five_zone_start> first,
                                                 rounding_limits* met = nullptr);
    std::optional<tangential_solution> five_zones(double Q) { return five_zones(Q, std::vector<five_zone_start>{}); }
    // The systems of both stick zones at given ends (block Gauss-Seidel on their coupling L1[q_other]).
    tangential_solution five_zone_system(double s1, double c1, double s2, double c2, double beta);

    // Free rolling (Q = 0) of smooth rollers with the edge layers neglected (edge_layers.hpp,
    // docs/formulation.md 8(n)): the no-slip solution, its checks (3.3)-(3.4) on [-1 + t, 1 - t], t the
    // layers' thickness bound. Only where the normal and tangential kernels are empty (the caller's test).
    tangential_solution layers_neglected_point();

private:
    std::vector<five_zone_start> search_starts(double Q) const;  // five_zones(Q)'s own starts
    // The five zones' ends of the complete-slip limit at Q (8(f)): empty where the pressure has no central band.
    std::optional<std::vector<double>> complete_slip_ends(double Q) const;
    // Newton from the driven three zones at `load` with `forcing`; `holds` where their v stays positive up to the
    // edge (they are the answer: no five zones).
    std::optional<tangential_solution> from_three_zones(double load, double forcing, bool& holds, rounding_limits& met);
    double load_under_H(double start, double c0);           // int p H over [-1, 1] for the zone [start, c0]
    // The three zones at |Q| = magnitude with the forcing b as the one zone search's operator: both slip
    // zones in the direction of Q (`opposite` false), or the leading one against it (8(g)).
    stick_zone_operator zone_operator(bool opposite, double b, double magnitude);
    // The five zones with the forcing `beta` as an operator of zone_newton only (its k = 2 systems): the members of the
    // one zone's search (solve, excess, scan...) are unset, so it is no operator for zone_solver.
    stick_zone_operator five_zone_newton_operator(double beta);
    tangential_solution blended(double start, double c0, double b);  // the system with S of 8(g)
    tangential_solution gross_sliding(double b);
    zone_check_terms blended_checks();  // what check_zones needs for the blended zones
    // The same for a solution of zones slipping both ways (three blended or five), with their rounding floor (8(f)).
    zone_check_terms opposite_checks(const tangential_solution& s);
    // p1(r) and v(r) of five zones (8(j)) from their point's layout and stick zones' systems (zone_system).
    double stick_zones_traction(const tangential_solution& s, double r);
    double stick_zones_slip_velocity(const tangential_solution& s, double r);
    // G_H = (1 - phi) G + phi G_d at each r[i] (docs/formulation.md 8(u)), phi = (1 + S)/2 of the blend S: G_d = -L1[p]
    // of the discrete p (normal_solution::projected_minus_hilbert) where the normal solution keeps its projection and
    // K1* is empty (smooth rollers at full coupling); G elsewhere, where the two agree (Johnson's level) or G_d is not
    // known in closed form (rough rollers).
    std::vector<double> blended_G(const std::vector<double>& r, const std::function<double(double)>& phi);
    double W(double r, double start, double c0);          // L1[p H] of the blended zone
    std::vector<double> W(const std::vector<double>& r, double start, double c0);  // the same at each r[i]
    // W at r from its closed-form Cauchy part (empty: declined): that part by quadrature where empty, + K1*'s terms.
    double completed_W(double r, const std::optional<double>& cauchy, double start, double c0);
    double cauchy_by_quadrature(double r, double start, double c0);  // W's Cauchy part by adaptive quadrature
    std::vector<double> breakpoints(double r, double start, double c0) const;  // W's pieces
    const blended_cauchy* blend_of(double start, double c0);  // W's Cauchy part on the zone, null: adaptive
    const kinks_blend* kinks_blend_of(double start, double c0);  // that of p_q^0 (8(o)), null: adaptive
    // The sum over the pieces between `points` (sorted) of end_quadrature's pieces (`cut`) or piece, their errors held
    // to quadrature_accepted (within_accepted); `last` (where given) in place of `integrand` on the last piece.
    double integrate_over(const std::vector<double>& points, const char* what, bool cut,
                          const std::function<double(double)>& integrand,
                          const std::function<double(double)>& last = {});
    double H(double r, double start, double c0) const;  // 0, Theta, 1
    const u_series_table* table() const;                // pressure_table_, built at the first call; null: the series
    double pressure(double r) const;  // p of (4.1), from pressure_b_ or its table, + p_q^0 (8(l) step 0)

    tangential_solver& solver_;
    kernel k1_;
    double beta_d_;
    double f_;
    std::vector<double> pressure_b_;  // the pressure's U coefficients without trailing zeros
    // The pressure tabulated (u_series_table.hpp) where its series has more than 50 terms, at its first use.
    mutable std::optional<u_series_table> pressure_table_;
    std::shared_ptr<const pressure_kinks> pressure_kinks_;  // the normal solution's (null but at full coupling)
    end_quadrature quadrature_;  // W's and int p Theta's
    zone_memo<blended_cauchy> blends_;    // blend_of's
    zone_memo<kinks_blend> kinks_blends_;  // kinks_blend_of's
    std::shared_ptr<const std::vector<tangential_solution>> tractions_of_;  // traction's memo of five zones' p1
    std::unordered_map<double, double> tractions_;
    std::size_t three_zone_searches_ = 0;  // solve's calls
};

}  // namespace roughroll
