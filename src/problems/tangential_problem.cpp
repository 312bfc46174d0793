// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/tangential_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include <gsl/gsl_math.h>

#include "roughroll/model/carter.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/error_bound.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/numerics/root_search.hpp"
#include "roughroll/problems/gross_sliding.hpp"
#include "roughroll/problems/zone_checks.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

namespace {
constexpr double min_load_ratio = 1e-10;  // smallest |Q|/f > 0 solved (see solve)

// The resolution check before any workspace is sized by the kernel's rate.
const kernel& resolved(const kernel& k, const normal_solution& normal) {
    check_resolution(k, normal.rule, normal.how, "K1* (tangential kernel)");
    return k;
}
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
                                  double rcond) {
    tangential_solution s{};
    s.f = f;
    s.xi = xi;
    s.Q = Q;  // (4.5)
    s.sign = 1.0;
    s.layout = one_stick_zone(start, c0);
    s.psi_b = std::move(psi_b);
    s.rcond = rcond;
    return s;
}

tangential_solution full_stick_solution(double f, const std::vector<double>& pressure_b) {
    // c0 = 1: q0 = -f p solves the stick equation with xi = 0, since L1[p] = -G.
    std::vector<double> psi_b = pressure_b;
    for (double& bj : psi_b) bj *= -f;
    return zone_solution(f, -1.0, 1.0, 0.0, 0.0, std::move(psi_b));
}

double stick_traction(const tangential_solution& s, double r) {
    const double rho = s.rho();
    if (r <= s.start() || r >= s.c0() || s.psi_b.empty()) return 0.0;
    const double t = (r - s.start()) / rho - 1.0;
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

tangential_solution tangential_problem::full_stick(double) { return full_stick_solution(f_, normal().b); }

tangential_solution tangential_problem::gross_sliding(double forcing) {
    if (carter_) return carter_at(f_);
    if (forcing != 0.0)
        return roughroll::gross_sliding(normal(), f_, forcing, [this](const std::vector<double>& r) { return G(r); });
    return gross_sliding_at(f_, -1.0, -f_ * G(std::vector<double>{-1.0}).front());
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
        // p(r) of (4.1) and q0(r) of (3.15) on the stick grid, their U-series summed for the
        // whole grid at once (the batched Clenshaw of quadrature.hpp, bit for bit the scalar
        // normal_solution::pressure and q0: the same r, the same t = (r - start)/rho - 1).
        const std::size_t count = r.size();
        std::vector<double> t(count), psi(count, 0.0), gap(count);
        const double rho = s.rho();
        for (std::size_t i = 0; i < count; ++i) t[i] = (r[i] - s.start()) / rho - 1.0;
        const std::vector<double> p = normal().pressure(r);
        if (!s.psi_b.empty()) u_series(s.psi_b, t.data(), psi.data(), count);
        for (std::size_t i = 0; i < count; ++i) {
            const double fp = f_ * p[i];
            const bool inside = !(r[i] <= s.start() || r[i] >= s.c0() || s.psi_b.empty());
            const double q = inside ? psi[i] * std::sqrt(std::max(0.0, 1.0 - t[i] * t[i])) : 0.0;
            gap[i] = fp - std::fabs(fp + q);  // |p1| = |sign (f p + q0)|, (3.15)
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

tangential_solver::tangential_solver(const normal_solution& normal, const kernel& k1, const kernel& k2, double f,
                                     bool closed_form)
    : tangential_problem(f, normal.rule.n, 0.0, closed_form && k1.empty() && k2.empty(), "tangential problem",
                         "root search for c0"),
      normal_(normal),
      k1_(resolved(k1, normal)),
      dk_(k2.minus(k1)),
      cauchy_(make_matrix(static_cast<std::size_t>(n_) + 1, static_cast<std::size_t>(n_) + 1)),
      system_(static_cast<std::size_t>(n_) + 1),
      k1_operator_(normal.kernel_term && k1.max_rate() <= normal.kernel_term->max_rate()
                       ? normal.kernel_term
                       : std::make_shared<const kernel_operator>(normal.rule, normal.how, k1.max_rate())) {
    gsl_matrix_set_zero(cauchy_.get());
    add_cauchy_term(cauchy_.get(), normal_.rule);
    // Column n: -xi moves to the left of (4.4).
    for (int m = 0; m <= n_; ++m) gsl_matrix_set(cauchy_.get(), m, n_, -1.0);
}

std::vector<double> tangential_solver::G(const std::vector<double>& r) {
    // (3.25): the kernel difference integrated on the interpolant of phi, split at its jump
    // (E8), so that G, and with it Q(c0), is continuous in c0. G does not depend on c0: its
    // kernel part is tabulated once per solver (convolution_table.hpp; its representation
    // error is bounded below eps times its size, docs/formulation.md "G once per contact").
    std::vector<double> g(r.size());
    for (std::size_t m = 0; m < r.size(); ++m) g[m] = M_2_PI * normal_.lambda * r[m];
    // Full coupling (docs/formulation.md 8(e) item 2): G = -L1[p] of the pressure solving (D1),
    // (2/pi) lambda (r + e) + beta_D p1 + int p (K2* - K1*), with p1 itself, kinks and all, not the
    // polynomial -L1 of the discrete p (which is the projection of that and smooths the kinks at the
    // zone ends, where the ends are decided: measured in 8(e), the ends then converge no better).
    if (normal_.tangential_term)
        for (std::size_t m = 0; m < r.size(); ++m)
            g[m] += M_2_PI * normal_.lambda * normal_.offset + normal_.tangential_term(r[m]);
    if (dk_.empty()) return g;
    if (!g_table_) g_table_.emplace(dk_, normal_.b);
    std::vector<double> table(r.size());
    (*g_table_)(r.data(), table.data(), r.size());
    for (std::size_t m = 0; m < r.size(); ++m) g[m] += table[m];
    return g;
}

double tangential_solver::G(double r) { return G(std::vector<double>{r}).front(); }

tangential_solution tangential_solver::solve_on_zone(double start, double c0, double forcing,
                                                     const std::vector<double>* extra, bool near) {
    // The stick zone [start, c0]: r = start + rho (t + 1), rho = (c0 - start)/2 (E4 with the
    // zone's own start; docs/formulation.md 7(b)). The paper's zone has start = -1.
    const double rho = 0.5 * (c0 - start);
    const auto& rule = normal_.rule;
    // Without K1 (smooth tangential compliance) the matrix is the Cauchy part alone, the same for
    // every zone: its factors are kept from the first solve, and each later solve (Newton's steps,
    // the alternation of full coupling, 8(e)) changes only the right side (dense_system::solve_factorised).
    const bool same_matrix = k1_.empty() && !near && system_.holds_factors();
    if (!same_matrix) {
        gsl_matrix* a = system_.matrix();
        gsl_check(gsl_matrix_memcpy(a, cauchy_.get()), "tangential problem: copy of the Cauchy term");
        k1_operator_->add_to(a, k1_.stretched(rho));  // E6
    }
    gsl_vector* rhs = system_.rhs();
    std::vector<double> r(n_ + 1);
    for (int m = 0; m <= n_; ++m) r[m] = rho * (rule.collocation[m] + 1.0) + start;  // E4
    const std::vector<double> g = G(r);
    for (int m = 0; m <= n_; ++m) gsl_vector_set(rhs, m, f_ * g[m]);  // E5
    if (forcing != 0.0) {  // Dundurs' term of (D2), docs/formulation.md 8(e): xi + sigma beta_D p + f G
        const std::vector<double> p = normal_.pressure(r);  // at full coupling every zone solve of Newton's steps
        for (int m = 0; m <= n_; ++m) gsl_vector_set(rhs, m, gsl_vector_get(rhs, m) + forcing * p[m]);
    }
    if (extra)
        for (int m = 0; m <= n_; ++m) gsl_vector_set(rhs, m, gsl_vector_get(rhs, m) + (*extra)[m]);
    std::ostringstream context;
    context.precision(17);
    context << "tangential problem (4.4) at c0 = " << c0;
    if (start != -1.0) context << ", stick zone from " << start;
    // near: refined on the last factorisation when it converges (linear_system.hpp), the same
    // solution to rounding.
    const gsl_vector* x = same_matrix ? system_.solve_factorised(context.str())
                          : near      ? system_.solve_near(context.str())
                                      : system_.solve(context.str());

    std::vector<double> psi(n_);
    double load = 0.0;
    for (int k = 0; k < n_; ++k) {
        psi[k] = gsl_vector_get(x, k);
        load += rule.weights[k] * psi[k];
    }
    tangential_solution s =
        zone_solution(f_, start, c0, gsl_vector_get(x, n_), f_ + rho * load, u_coefficients(rule, psi), system_.rcond());
    s.forcing = forcing;
    return s;
}

std::optional<double> tangential_solver::search_start(double magnitude) const { return carter(magnitude, f_).c0; }

namespace {
// L1[q0] at a point of a slip zone, in the stick variable |t| > 1: the Cauchy transform of
// the U-series, plus the kernel terms. For t > 1, tau - t < 0 on the whole stick zone and each
// term T' exp(-A' (t - tau)) factors as exp(-A' (t - 1)) times its integral at t = 1; for
// t < -1 (the leading slip zone of docs/formulation.md 7) likewise exp(-A' (-1 - t)) times
// its integral at t = -1. So the kernel part costs two integrals per term, whatever the
// number of points, each in closed form (integrate_at_end, kernel_moments.hpp).
class stick_operator_outside {
public:
    stick_operator_outside(const kernel& stretched_k1, const std::vector<double>& psi_b) : psi_b_(psi_b) {
        for (const auto& term : stretched_k1.terms()) {
            const kernel one({term});
            at_ends_.push_back({term.A, integrate_at_end(one, psi_b, 1.0), integrate_at_end(one, psi_b, -1.0)});
        }
    }

    // L1[q0] at the points t[i] into out[i]: the Cauchy transforms summed for all points at once
    // (cauchy_u_series, bit for bit the scalar one), then the kernel terms in the same order.
    void operator()(const double* t, double* out, std::size_t count) const {
        cauchy_u_series(psi_b_, t, out, count);
        for (std::size_t i = 0; i < count; ++i)
            for (const auto& e : at_ends_)
                out[i] += t[i] > 0.0 ? e.at_one * std::exp(-e.rate * (t[i] - 1.0))
                                     : e.at_minus_one * std::exp(-e.rate * (-1.0 - t[i]));
    }

private:
    struct end_values {
        double rate, at_one, at_minus_one;  // A', the kernel integral at t = 1 and at t = -1
    };
    const std::vector<double>& psi_b_;
    std::vector<end_values> at_ends_;
};
}  // namespace

std::vector<double> tangential_solver::slip_velocity_magnitude(const tangential_solution& s,
                                                               const std::vector<double>& r) {
    // v = xi + f G(r) - L1[q0](r) for the |Q| problem, (3.6) with (3.15), at sorted points
    // of the slip zones, where L1 is the stick-zone operator evaluated outside its interval.
    std::vector<double> v = G(r);
    const double rho = s.rho();
    std::vector<double> l(r.size(), 0.0);
    if (!(s.psi_b.empty() || rho == 0.0)) {
        std::vector<double> t(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) t[i] = (r[i] - s.start()) / rho - 1.0;
        stick_operator_outside(k1_.stretched(rho), s.psi_b)(t.data(), l.data(), t.size());
    }
    for (std::size_t i = 0; i < r.size(); ++i) {
        v[i] = s.sign * s.xi + f_ * v[i] - l[i];
        if (s.forcing != 0.0) v[i] += s.forcing * normal_.pressure(r[i]);  // (D2), docs/formulation.md 8(e)
    }
    return v;
}

double tangential_solver::rounding(double xi) const {
    // (3.3) to rounding (docs/formulation.md 7(d)): q solves (4.4), whose right-hand side
    // xi + f G is made of terms of size |xi| + f K (K = max(1, P_H/P2, sum |T|), the terms of G of
    // (3.25)) that q cancels to its own size (stick_system_floor). Near gross sliding q is that
    // small itself and the margin is rounding (measured -3.0e-11 at Q/f = 1 - 1e-12, n = 256,
    // T = 100, A = 1: floor 6.5e-11), where a wrong structure fails by far more (-0.09 for the
    // paper's zone there, -1.1e-3 in the one-parameter limit of section 6). (3.4) likewise: the slip
    // velocity (3.6) is what is left of the same terms off the stick zone (measured -2e-12 .. -5e-11
    // on the general search's right zones), so it carries the same floor.
    return stick_system_floor(
               n_, std::fabs(xi) + f_ * std::max({1.0, std::fabs(normal_.lambda), k1_.strength(), dk_.strength()})) /
           f_;
}

}  // namespace roughroll
