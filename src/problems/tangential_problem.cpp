// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/tangential_problem.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <gsl/gsl_math.h>

#include "roughroll/model/carter.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/numerics/root_search.hpp"
#include "roughroll/problems/gross_sliding.hpp"
#include "roughroll/problems/zone_checks.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

namespace {
constexpr double min_load_ratio = 1e-10;  // smallest |Q|/f > 0 solved (see solve)
}  // namespace

double load_magnitude(double Q, double f) {
    if (!std::isfinite(Q)) throw input_error("Q must be finite");
    const double magnitude = std::fabs(Q);
    if (magnitude > f) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "|Q| = " << magnitude << " exceeds the friction coefficient f = " << f
            << ": the cylinders slide (no rolling solution)";
        throw input_error(msg.str());
    }
    return magnitude;
}

void check_load_resolvable(double magnitude, double f) {
    if (magnitude >= min_load_ratio * f) return;
    std::ostringstream msg;
    msg << "|Q|/f = " << magnitude / f << " is below " << min_load_ratio
        << ", the relative precision of the load equation (4.5) in double precision: c0 and xi "
           "cannot be resolved at any n; give |Q|/f >= "
        << min_load_ratio << ", or Q = 0 (solved exactly)";
    throw beyond_method_error(msg.str());
}

void apply_load_sign(tangential_solution& s, double Q, const char* what) {
    if (!(std::isfinite(s.xi) && std::isfinite(s.c0())))
        throw numerical_error(std::string(what) + ": the creep is not finite (roughness parameters too large?)");
    s.Q = Q;  // the requested load; the solved one agrees to the root tolerance
    if (Q < 0.0) {
        s.sign = -1.0;
        s.xi = -s.xi;
        s.layout = mirrored(std::move(s.layout));
    }
}

tangential_solution zone_solution(double f, double start, double c0, double xi, double Q, std::vector<double> psi_b,
                                  double rcond, double forcing) {
    tangential_solution s{};
    s.f = f;
    s.xi = xi;
    s.Q = Q;  // (4.5)
    s.sign = 1.0;
    s.layout = one_stick_zone(start, c0);
    s.psi_b = std::move(psi_b);
    s.rcond = rcond;
    s.forcing = forcing;
    return s;
}

std::vector<double> stick_traction(const tangential_solution& s, const std::vector<double>& r) {
    // The U-series summed for all points at once (the batched Clenshaw of quadrature.hpp, bit for bit the scalar).
    const std::size_t count = r.size();
    std::vector<double> t(count), psi(count, 0.0), q(count, 0.0);
    const double rho = s.rho();
    for (std::size_t i = 0; i < count; ++i) t[i] = (r[i] - s.start()) / rho - 1.0;
    if (s.weight_a > 0.0) {  // the Jacobi weight of 8(v)
        for (std::size_t i = 0; i < count; ++i) q[i] = stick_traction(s, r[i]);
        return q;
    }
    if (!s.psi_b.empty()) u_series(s.psi_b, t.data(), psi.data(), count);
    for (std::size_t i = 0; i < count; ++i)
        if (!(r[i] <= s.start() || r[i] >= s.c0() || s.psi_b.empty()))
            q[i] = psi[i] * std::sqrt(std::max(0.0, 1.0 - t[i] * t[i]));
    return q;
}

double stick_traction(const tangential_solution& s, double r) {
    // One point: no series outside the zone, no vectors (the traction's sweeps and full coupling's right side call it at
    // every node of every step); the same bits as the batch (its Clenshaw is the scalar's, quadrature.hpp).
    if (r <= s.start() || r >= s.c0() || s.psi_b.empty()) return 0.0;
    const double t = (r - s.start()) / s.rho() - 1.0;
    if (s.weight_a > 0.0)  // q = (1 - t)^a (1 + t)^b sum_j c_j P_j^(a,b)(t), docs/formulation.md 8(v)
        return jacobi_weight(s.weight_a, s.weight_b, t) * jacobi_series(s.psi_b, s.weight_a, s.weight_b, t);
    return u_series(s.psi_b, t) * std::sqrt(std::max(0.0, 1.0 - t * t));
}

tangential_problem::tangential_problem(double f, int n, double beta_d, bool closed_form, const char* what,
                                       const char* root_what)
    : f_(f), beta_d_(beta_d), carter_(closed_form), n_(n), what_(what), root_what_(root_what) {
    if (!(std::isfinite(f) && f > 0.0)) throw input_error("friction coefficient f must be positive and finite");
}

tangential_solution tangential_problem::solve(double Q, std::optional<double> guess, bool checked,
                                              std::optional<double> slope) {
    const double forcing = forcing_at(Q);  // the |Q| problem's (8(s))
    const auto search = [&](double target) {
        if (carter_) return carter_at(target);
        check_load_resolvable(target, f_);
        // Q(-1) = f > |Q|, and Q(1) = 0 < |Q|: exactly (exact_full_stick_load), or up to the discretisation error,
        // which is checked.
        const auto full_stick_below = [this, target] {
            if (exact_full_stick_load()) return;
            // Q(1) is 0 up to the discretisation error and the rounding of (4.5), an O(f)
            // sum cancelling to Q whose terms grow with P_H/P2 (G of (3.25)): n eps f max(1, P_H/P2).
            const double at_full_stick = load(1.0);
            const double rounding = rounding_floor(n_, f_ * std::max(1.0, std::fabs(normal().lambda)));
            if (!(at_full_stick + rounding < target)) {
                std::ostringstream msg;
                msg << "|Q|/f = " << target / f_ << " is below the resolution of this discretisation: "
                    << "its full-stick load Q(c0 = 1) = " << at_full_stick << " plus its rounding " << rounding
                    << " is not below |Q|; " << (n_ < max_nodes ? "increase n" : "n is at its largest: a larger load");
                throw resolution_error(msg.str());
            }
        };
        const root c0 = stick_end_for_load([&](double c) { return load(c, forcing); }, target, guess, root_what_,
                                           full_stick_below, search_start(target), slope);
        const bool kept = last_system_ && last_system_->c0() == c0.x && last_system_->forcing == forcing;
        tangential_solution s = kept ? *last_system_ : on_zone(-1.0, c0.x, forcing, false);
        s.iterations = c0.iterations;
        s.load_slope = c0.slope;
        return s;
    };
    const double magnitude = load_magnitude(Q, f_);
    tangential_solution s = magnitude == 0.0  ? full_stick(forcing)
                            : magnitude == f_ ? gross_sliding(forcing)
                                              : search(magnitude);
    apply_load_sign(s, Q, what_);
    if (checked) s.checks = check(s);
    return s;
}

tangential_solution tangential_problem::at_stick_end(double c0, bool checked, bool near) {
    if (!(c0 >= -1.0 && c0 <= 1.0)) throw input_error("c0 must lie in [-1, 1]");
    const double forcing = forcing_at(1.0);  // the Q >= 0 branch
    tangential_solution s;
    if (c0 == 1.0) {
        s = full_stick(forcing);
    } else if (c0 == -1.0) {
        s = gross_sliding(forcing);
    } else if (carter_) {
        const carter_stick_end smooth = carter_at_stick_end(c0, f_);  // Smooth: Carter's closed form
        s = carter_solution(smooth.Q, c0, smooth.xi);
    } else {
        s = on_zone(-1.0, c0, forcing, near);
    }
    if (checked) s.checks = check(s);
    return s;
}

tangential_solution tangential_problem::full_stick(double) {
    // c0 = 1: q0 = -f p solves the stick equation with xi = 0, since L1[p] = -G (2(g)).
    std::vector<double> psi_b = normal().b;
    for (double& bj : psi_b) bj *= -f_;
    return zone_solution(f_, -1.0, 1.0, 0.0, 0.0, std::move(psi_b));
}

tangential_solution tangential_problem::gross_sliding(double forcing) {
    if (carter_) return carter_at(f_);
    if (forcing != 0.0) return least_sliding(forcing);
    return gross_sliding_at(f_, -1.0, -f_ * G(std::vector<double>{-1.0}).front());
}

tangential_solution tangential_problem::least_sliding(double forcing) {
    return roughroll::gross_sliding(normal(), f_, forcing, [this](const std::vector<double>& r) { return G(r); });
}

double tangential_problem::load(double c0, std::optional<double> forcing) {
    if (c0 <= -1.0) return f_;
    if (c0 >= 1.0 && exact_full_stick_load()) return *exact_full_stick_load();
    // Kept: the root search ends on a c0 it evaluated.
    last_system_ = on_zone(-1.0, c0, forcing.value_or(forcing_at(1.0)), false);
    return last_system_->Q;
}

tangential_solution tangential_problem::carter_solution(double Q, double c0, double xi) const {
    // Smooth cylinders: q0 = -(2 f/pi) rho sqrt(1 - t^2), psi constant, no kernel, no solve.
    tangential_solution s = zone_solution(f_, -1.0, c0, xi, Q);
    if (s.rho() > 0.0) s.psi_b = {-M_2_PI * f_ * s.rho()};  // no stick zone at |Q| = f
    return s;
}

tangential_solution tangential_problem::carter_at(double magnitude) const {
    const carter_point cp = carter(magnitude, f_);
    return carter_solution(magnitude, cp.c0, cp.xi);
}

double tangential_problem::traction(const tangential_solution& s, double r) const {
    return s.sign * (f_ * normal().pressure(r) + stick_traction(s, r));  // (3.15)
}

double tangential_problem::slip_velocity(const tangential_solution& s, double r) {
    return slip_velocity(s, std::vector<double>{r}).front();
}

std::vector<double> tangential_problem::slip_velocity(const tangential_solution& s, const std::vector<double>& r) {
    // The sweep wants points in descending order: sort a copy, keep the way back.
    std::vector<std::size_t> order(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&r](std::size_t a, std::size_t b) { return r[a] > r[b]; });
    std::vector<double> slip;
    std::vector<std::size_t> where;
    for (std::size_t i : order)
        if (r[i] > s.c0() || r[i] < s.start()) {
            slip.push_back(std::max(-1.0, std::min(r[i], 1.0)));
            where.push_back(i);
        }
    const std::vector<double> v = slip_velocity_magnitude(s, slip);
    std::vector<double> out(r.size(), 0.0);  // 0 on the stick zone (3.2)
    for (std::size_t k = 0; k < slip.size(); ++k) out[where[k]] = s.sign * v[k];
    return out;
}

double tangential_problem::pressure_margin() {
    if (!pressure_margin_) pressure_margin_ = least_pressure(normal());  // p does not depend on the zones
    return *pressure_margin_;
}

traction_checks tangential_problem::check(const tangential_solution& s) {
    zone_check_terms terms{f_, pressure_margin(), check_rounding(s), true, nullptr, nullptr};
    terms.stick_gap = [&](const std::vector<double>& r) {
        const std::vector<double> p = normal().pressure(r), q = stick_traction(s, r);
        std::vector<double> gap(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) {
            const double fp = f_ * p[i];
            gap[i] = fp - std::fabs(fp + q[i]);  // |p1| = |sign (f p + q0)|, (3.15)
        }
        return gap;
    };
    terms.slip_velocity = [&](const std::vector<double>& r) {
        std::vector<double> v = slip_velocity_magnitude(s, r);
        for (double& x : v) x *= s.sign;
        return v;
    };
    return check_zones(s.layout.zones, terms);
}

}  // namespace roughroll
