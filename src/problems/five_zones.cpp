// SPDX-License-Identifier: GPL-3.0-or-later
// Five zones of dissimilar rollers (docs/formulation.md 8(g), 8(j) items 3-4): slip -1, stick,
// slip +1, stick, slip -1 (beta_D > 0), the structure of free rolling, of a driven roller 1
// below Q/f ~ 0.9 and of a braked one near free rolling (8(j) 4a). The blend of 8(g) with two
// stick zones, each with its own collocation system (tangential_solver::solve_on_zone) whose right
// side carries the other zone's L1[q] (block Gauss-Seidel): the zone search's operator on two zones, with
// its Newton in the four ends (zone_newton) from the starts of zone_start.hpp, tried by find_zones (zone_solver.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/zone_layout.hpp"
#include "roughroll/problems/zone_newton.hpp"

namespace roughroll {

namespace {
constexpr int max_sweeps = 200;  // block Gauss-Seidel sweeps of one system
// On the change of xi1 + xi2 between sweeps: 1e-15 f, and the rounding of the sum itself. Without
// the second term a 2-ulp limit cycle (xi1 + xi2 = -0.1365 at f = 0.05 alternating by 5.6e-17 >
// 1e-15 f) ran the sweeps out, and Newton, finding the residual undefined at a difference point,
// gave up: the failures "from f = 0.05's ends at f = 0.049" and from nearby loads (8(j) 4a).
constexpr double sweep_tolerance = 1e-15;
constexpr double sweep_rounding = 4.0 * std::numeric_limits<double>::epsilon();
// The scan's loads Q/f = k/8, 1/4 first: it gave starts at f = 0.05 and 0.1 (each try costs about a continuation).
// Then 1/16, 1/32, 1/64, after them so that every start that answered before answers first: where the five zones
// close in the load near free rolling, the driven three zones hold at every k/8 and give no start (the rough pair of
// data/aluminium-on-steel-rough.toml: five zones up to Q/f = 0.078 at f = 0.1 and beta_D/f = 1.5, not at 0.086;
// 1/16 is their start at f = 0.1 and 0.2, 8(j) 4a).
constexpr double scan_loads[] = {2.0 / 8, 4.0 / 8, 1.0 / 8, 3.0 / 8, 5.0 / 8, 6.0 / 8, 7.0 / 8, 1.0 / 16, 1.0 / 32, 1.0 / 64};
}  // namespace

tangential_solution dissimilar_zones::five_zone_system(double s1, double c1, double s2, double c2, double beta) {
    // Solved in the frame beta_D > 0 with the forcing beta (|beta_D| but on a continuation in
    // beta_D/f); for beta_D < 0 the exchange of rollers of 8(h) gives xi, Q, p1, v with the opposite
    // sign and the same ends.
    const std::vector<double> r1 = solver_.collocation_points(s1, c1), r2 = solver_.collocation_points(s2, c2);
    // solve_on_zone's right side is xi + b p + f G; the blend's is xi + b p - f G - 2 f W1 + 2 f W2, at full coupling
    // with G_H = (1 - phi) G + phi G_d in the second G (8(u)): each zone's exit reads the slip side beyond it, which
    // holds the pressure's kink, through G's formula. Zone 1 as the driven zone, phi = H1 (G_d at its exit, slip+
    // beyond; G at its entry); zone 2 phi = 0 (G: slip- beyond its exit), on the whole zone: its entry's side, the
    // slip+ zone, holds no kink near it, and phi = 1 - H2 there read the exit's kink one zone width away through p_d
    // (s2 moved by up to 2e-6, 8(u)).
    const auto base = [&](const std::vector<double>& r, bool first) {
        const std::vector<double> g = first ? blended_G(r, [&](double x) { return H(x, s1, c1); }) : solver_.G(r),
                                  w1 = W(r, s1, c1), w2 = W(r, s2, c2);
        std::vector<double> e(r.size());
        for (std::size_t m = 0; m < r.size(); ++m) e[m] = -2.0 * f_ * (g[m] + w1[m] - w2[m]);
        return e;
    };
    const std::vector<double> base1 = base(r1, true), base2 = base(r2, false);
    // The other zone's system's right side: its base plus -L1[q_k] at its points, -L1[q_k] = v_k - (xi_k + f G) with
    // v_k zone k's own slip velocity without its forcing b p (which v_k would add and this take away again: at full
    // coupling a series of n terms at every point).
    const auto coupled = [&](tangential_solution t, const std::vector<double>& r, const std::vector<double>& base) {
        t.forcing = 0.0;
        const std::vector<double> v = solver_.slip_velocity(t, r);
        const std::vector<double> g = solver_.G(r);
        std::vector<double> out(r.size());
        for (std::size_t m = 0; m < r.size(); ++m) out[m] = v[m] - (t.xi + f_ * g[m]) + base[m];
        return out;
    };
    tangential_solution zone1 = solver_.solve_on_zone(s1, c1, beta, &base1),
                        zone2 = solver_.solve_on_zone(s2, c2, beta, &base2);
    double previous = zone1.xi + zone2.xi;
    for (int sweeps = 1;; ++sweeps) {
        const std::vector<double> e1 = coupled(zone2, r1, base1);
        zone1 = solver_.solve_on_zone(s1, c1, beta, &e1);
        const std::vector<double> e2 = coupled(zone1, r2, base2);
        zone2 = solver_.solve_on_zone(s2, c2, beta, &e2);
        const double now = zone1.xi + zone2.xi;
        if (std::fabs(now - previous) <= sweep_tolerance * f_ + sweep_rounding * std::fabs(now)) break;
        if (sweeps == max_sweeps || !std::isfinite(now))
            throw numerical_error("five zones: the coupling of the two stick zones does not converge");
        previous = now;
    }
    const double sign = beta_d_ > 0.0 ? 1.0 : -1.0;
    // Q = f (-1 + 2 int p H1 - 2 int p H2) + rho1 int q1 + rho2 int q2; solve_on_zone's Q is f + rho int q.
    const double Q =
        sign * (f_ * (-1.0 + 2.0 * load_under_H(s1, c1) - 2.0 * load_under_H(s2, c2)) + (zone1.Q - f_) + (zone2.Q - f_));
    // The point: xi = xi1 (= xi2 at the root) with the frame's sign, the forcing |beta_D| of the frame (sign * forcing
    // = beta_D, as reported), the worse rcond, the layout and each zone's system.
    tangential_solution s =
        zone_solution(f_, s1, c1, sign * zone1.xi, Q, {}, std::min(zone1.rcond, zone2.rcond), zone1.forcing);
    s.sign = sign;
    s.layout = five_zones_layout(s1, c1, s2, c2, sign > 0.0 ? 1 : -1);
    s.zone_systems =
        std::make_shared<const std::vector<tangential_solution>>(std::vector{std::move(zone1), std::move(zone2)});
    return s;
}

stick_zone_operator dissimilar_zones::five_zone_newton_operator(double beta) {
    // The zone search's Newton in the blend's stick zones (zone_newton, k = 2): the load's gap, both entry conditions
    // psi_k(-1) = 0 and xi1 = xi2, absolute, in (m1, rho1, m2, rho2) with -1 < s1 < c1 < s2 < c2 <= 1; their checks,
    // and their seed from the driven three zones (find_zones' starts).
    stick_zone_operator op;
    op.f = f_;
    op.systems = [this, beta](const std::vector<stick_span>& z) -> std::optional<tangential_solution> {
        // Ends of another structure: a programming error (every caller passes a layout's, review R23 of session 27).
        if (z.size() != 2) throw std::invalid_argument("five zones: Newton's start needs four ends s1, c1, s2, c2");
        try {
            return five_zone_system(z[0].start, z[0].end, z[1].start, z[1].end, beta);
        } catch (const numerical_error&) {
            return std::nullopt;  // ends where the coupling or W fails: off the family, the step is halved
        }
    };
    op.newton_entry = zone_solver::entry_coefficient;
    op.check = [this](const tangential_solution& s) { return check(s); };
    op.seed = [this, beta](double load, bool& holds, rounding_limits& met) {
        return from_three_zones(load, beta, holds, met);
    };
    op.method.relative_load = false;
    op.method.newton_tolerance = zone_end_resolution;
    return op;
}

std::optional<tangential_solution> dissimilar_zones::five_zones(double Q, const std::vector<double>& ends,
                                                               std::optional<double> beta, rounding_limits* met,
                                                               newton_jacobian* kept, bool checked) {
    if (!(std::fabs(Q) < f_)) throw input_error("five zones: |Q| < f");
    const double forcing = beta.value_or(std::fabs(beta_d_));
    rounding_limits own;  // where the caller keeps none
    std::optional<tangential_solution> s = zone_newton(five_zone_newton_operator(forcing), Q, ends, met ? *met : own, kept);
    // Not made: NaN margins, nothing holding (a caller that reads them makes them: check).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (s) s->checks = checked ? check(*s) : traction_checks{nan, nan, nan, nan, nan, false, false, false};
    return s;
}

double dissimilar_zones::stick_zones_traction(const tangential_solution& s, double r) {
    // p1 = f p S + q1 + q2, S = -1 + 2 H1 - 2 H2 in the frame beta_D > 0 (8(j)), each q_k its zone's system's.
    const zone &z1 = s.layout.stick_zone(0), &z2 = s.layout.stick_zone(1);
    double p1 = f_ * pressure(r) * (s.sign * (-1.0 + 2.0 * H(r, z1.from, z1.to) - 2.0 * H(r, z2.from, z2.to)));
    for (std::size_t k = 0; k < 2; ++k)
        if (const tangential_solution& t = s.zone_system(k); r > t.start() && r < t.c0())
            p1 += s.sign * stick_traction(t, r);
    return p1;
}

double dissimilar_zones::stick_zones_slip_velocity(const tangential_solution& s, double r) {
    // v = xi + b p + f G - 2 f (G_H + W1 - W2) - L1[q1] - L1[q2], with -L1[q_k] = v_k - (xi_k + b p + f G). Next to each
    // stick zone G_H is that zone's (five_zone_system), the form its discrete q solves, with which v vanishes like
    // (r - c)^(1/2) beyond an exit and (s - r)^(3/2) before an entry: G on the leading slip- zone (zone 1's entry) and
    // the trailing one (zone 2's exit). The slip+ zone follows zone 1's exit (G_d) and precedes zone 2's entry (G):
    // G_H = G + X (G_d - G), X = 1 - 35 u^4 + 84 u^5 - 70 u^6 + 20 u^7, u = (r - c1)/(s2 - c1), 1 - X = O(u^4) at c1 and
    // X = O((1 - u)^4) at s2, below v's own orders there (8(u)). One form on the whole slip+ zone would leave
    // 2 f (G - G_d) at one of its ends: zone 1's on all of r < s2 failed the slip check at n = 256 (8(u)).
    const zone &z1 = s.layout.stick_zone(0), &z2 = s.layout.stick_zone(1);
    if ((r >= z1.from && r <= z1.to) || (r >= z2.from && r <= z2.to)) return 0.0;
    const double x = std::clamp(r, -1.0, 1.0);
    const double g = solver_.G(x), bp = s.forcing * pressure(x);  // in the frame beta_D > 0
    double v = s.sign * s.xi + bp - f_ * g - 2.0 * f_ * (W(x, z1.from, z1.to) - W(x, z2.from, z2.to));
    if (r > z1.to && r < z2.from) {  // G_H - G added apart, so that G_H = G (Johnson's level) leaves v bit for bit
        const double u = (r - z1.to) / (z2.from - z1.to);
        const double X = 1.0 - u * u * u * u * (35.0 + u * (-84.0 + u * (70.0 - 20.0 * u)));
        const double g_h = blended_G({x}, [X](double) { return X; }).front();
        v -= 2.0 * f_ * (g_h - g);
    }
    for (std::size_t k = 0; k < 2; ++k) {
        const tangential_solution& t = s.zone_system(k);
        v += solver_.slip_velocity(t, x) - (t.xi + bp + f_ * g);
    }
    return s.sign * v;
}

std::vector<five_zone_start> dissimilar_zones::search_starts(double Q) const {
    // In the frame beta_D > 0 (8(h)) the scan's loads lie above sign * Q; the starts' loads have Q's sign. Outside
    // beta_D/f in [1, 6] (f <= 0.02 or f >= 0.15 for aluminium on steel) free rolling at 2.875 (f = 0.05's) or 1.5.
    const double sign = beta_d_ > 0.0 ? 1.0 : -1.0, beta = std::fabs(beta_d_), ratio = beta / f_;
    const bool inside = ratio >= 1.0 && ratio <= 6.0;
    const double forcing = inside ? beta : (ratio > 6.0 ? 2.875 : 1.5) * f_, from = inside ? sign * Q : 0.0;
    std::vector<five_zone_start> starts;
    if (inside && from > 0.0) starts.push_back(five_zone_start::three_zones_at(Q, beta));
    for (const double k : scan_loads) {
        if (k * f_ <= from) continue;
        five_zone_start s = five_zone_start::three_zones_at(sign * (k * f_), forcing);
        if (!inside) s.path = {{zone_parameter::load, 0.0}, {zone_parameter::forcing, beta}};
        // Free rolling at the scan's forcing, and the braked side (reached through free rolling), are every start's.
        if (!inside) s.shared_after = 1;
        if (inside && from < 0.0) s.shared_after = 0;
        starts.push_back(std::move(s));
    }
    // Near complete slip, last: the scan's continuation in the load moves the stick zones by about 1/32 of the
    // contact per step of f/8 (their centres follow the central band's edge), thousands of their widths O(f/|beta_D|)
    // at f = 1e-9, and Newton from there wanders (at Q/f = 0.5, f = 1e-9: 40 iterations without a root at every
    // step down to f/1024, at every level of every rung). The limit f -> 0 places them (8(f), "The complete-slip
    // start"): centred on the band's edges +-r_c, each of the width derived there.
    if (ratio > 6.0)
        if (std::optional<std::vector<double>> ends = complete_slip_ends(Q))
            starts.push_back(five_zone_start::at_ends(*ends));
    return starts;
}

std::optional<std::vector<double>> dissimilar_zones::complete_slip_ends(double Q) const {
    complete_slip c{};
    try {
        c = complete_slip_creep(solver_.normal(), beta_d_, Q / f_);
    } catch (const input_error&) {
        return std::nullopt;  // a pressure not even and decreasing in |r|: the band is not derived, no start
    }
    if (!(c.r_c > 0.0 && c.r_c < 1.0)) return std::nullopt;  // no band, or the band is the contact: no stick zones
    // Each zone carries the traction from -f p to f p where v_0 = xi_0 + beta_D p changes sign: width
    // 4 f p/(pi |beta_D p'|) at r_c (8(f)), p' by central differences; kept inside its half of the contact.
    constexpr double h = 1e-6;
    const normal_solution& normal = solver_.normal();
    const double slope = (normal.pressure(c.r_c + h) - normal.pressure(c.r_c - h)) / (2.0 * h);
    const double rho = std::min({2.0 * f_ * normal.pressure(c.r_c) / (M_PI * std::fabs(beta_d_ * slope)),
                                 0.5 * c.r_c, 0.5 * (1.0 - c.r_c)});
    if (!(rho > 0.0)) return std::nullopt;
    return std::vector<double>{-c.r_c - rho, -c.r_c + rho, c.r_c - rho, c.r_c + rho};
}

std::optional<tangential_solution> dissimilar_zones::from_three_zones(double load, double forcing, bool& holds,
                                                                     rounding_limits& met) {
    // slip-, stick [s, c], slip+ leave v < 0 near the trailing edge (8(j) item 4): the second zone from there.
    holds = false;
    const double frame = (beta_d_ > 0.0 ? 1.0 : -1.0) * load;
    try {
        const std::optional<tangential_solution> found =
            zone_solver(zone_operator(true, forcing, frame)).find(frame, false, {}, met);
        if (!found) return std::nullopt;  // no three zones carry this load: no start from here
        const tangential_solution& three = *found;
        constexpr int samples = 400;
        for (int i = 1; i <= samples; ++i) {
            const double r = i == samples ? 1.0 : three.c0() + (1.0 - three.c0()) * i / samples;
            if (!(slip_velocity(three, r) < 0.0)) continue;
            const double turn = three.c0() + (1.0 - three.c0()) * (i - 0.5) / samples;
            return zone_newton(five_zone_newton_operator(forcing), load,
                               {three.start(), three.c0(), turn, turn + 0.5 * (1.0 - turn)}, met);
        }
        holds = true;  // v > 0 up to the edge: the three zones are the answer
    } catch (const error&) {
        // a load the three zones' search refuses (resolution_error), or W fails on them: no start from here
    }
    return std::nullopt;
}

std::optional<tangential_solution> dissimilar_zones::five_zones(double Q, std::vector<five_zone_start> starts,
                                                               rounding_limits* met) {
    if (!(std::fabs(Q) < f_)) throw input_error("five zones: |Q| < f");
    rounding_limits kept;  // where the caller keeps none
    rounding_limits& limits = met ? *met : kept;
    const std::vector<five_zone_start> own = search_starts(Q);
    starts.insert(starts.end(), own.begin(), own.end());
    // A root whose checks (3.3)-(3.4) fail is kept only until a later start reaches a root whose checks hold: the rough
    // pair at Q/f = 0.02 (data/aluminium-on-steel-rough.toml), where the driven three zones at Q, at n = 80 and 128,
    // led Newton to a slip+ zone closed to 2.6e-5 (stick margin -0.091) and every finer level followed it from the
    // coarser ends, while the scan's start (Q/f = 1/4 continued in Q) reaches the physical root, n = 64's (8(j) 4a,
    // "Which root"). Where no start reaches one whose checks hold, the first root stands, as before (first_holding).
    return find_zones([this](double beta) { return five_zone_newton_operator(beta); }, Q, std::fabs(beta_d_), starts,
                      limits);
}

}  // namespace roughroll
