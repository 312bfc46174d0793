#include "roughroll/problems/contact.hpp"

#include <algorithm>
#include <cmath>

#include "roughroll/numerics/collocation.hpp"
#include "roughroll/base/error.hpp"

namespace roughroll {

namespace {
// Richardson's rule for an error ~ C n^-4: levels n and n/2.
double richardson(double fine, double coarse) { return (16.0 * fine - coarse) / 15.0; }

kernel widest_kernel(const roughness& r) {
    const double rate = std::max(kernel::normal(r).max_rate(), kernel::tangential(r).max_rate());
    return kernel(std::vector<exponential_term>{{1.0, rate}});
}
}  // namespace

contact::contact(const roughness& surfaces, double f, const solver_options& options)
    : surfaces_(surfaces), options_(options), f_(f) {
    if (!(std::isfinite(f) && f > 0.0)) throw input_error("friction coefficient f must be positive and finite");
    const int n = options.nodes();
    if (options.how == method::one_parameter) {
        if (options.zones == zone_search::general)
            throw input_error("zone search 'general' is not available for method 'one-parameter' (use 'auto' or "
                              "'single'; docs/formulation.md section 7)");
        limit_ = std::make_unique<one_parameter_solver>(surfaces, f, n);
        return;
    }
    const bool extrapolate = options.how == method::extrapolated && !(kernel::normal(surfaces).empty() &&
                                                                       kernel::tangential(surfaces).empty());
    if (extrapolate) {
        // Richardson's rule holds only where the error already falls like n^-4.
        if (n / 2 < min_nodes || !in_asymptotic_range(widest_kernel(surfaces), n / 2, method::product))
            throw resolution_error("method 'extrapolated' with n = " + std::to_string(n) +
                                   ": the coarse level n/2 is not in the asymptotic range of product integration "
                                   "for these kernels; increase n or use method 'product'");
        companion_ = std::make_unique<contact>(surfaces, f, solver_options{n / 2, method::product, options.zones});
    }
    const method level = options.how == method::extrapolated ? method::product : options.how;
    normal_ = std::make_unique<normal_solution>(solve_normal(kernel::normal(surfaces), n, level));
    normal_->how = options.how;  // a smooth scene under 'extrapolated' is exact at one level
    if (extrapolate) {
        reported_ = std::make_unique<normal_solution>(*normal_);
        reported_->lambda = richardson(normal_->lambda, companion_->normal().lambda);
    }
    tangential_ = std::make_unique<tangential_solver>(*normal_, kernel::tangential(surfaces),
                                                      kernel::normal(surfaces), f);
    zones_ = std::make_unique<zone_solver>(*tangential_);
}

const normal_solution& contact::normal() const {
    if (limit_) return limit_->normal();
    return reported_ ? *reported_ : *normal_;
}

tangential_solver& contact::tangential() {
    if (!tangential_)
        throw input_error("method 'one-parameter' has no two-parameter tangential solver: use contact::traction and "
                          "contact::slip_velocity");
    return *tangential_;
}

tangential_solution contact::level_point(double Q, const tangential_solution* coarse, bool general) {
    if (general || options_.zones == zone_search::general)
        return zones_->solve(Q, true, coarse ? std::optional<zone_guess>({coarse->start, coarse->c0}) : std::nullopt);
    // The coarse root brackets this one.
    tangential_solution s = tangential_->solve(Q, coarse ? std::optional<double>(coarse->c0) : std::nullopt);
    if (options_.zones == zone_search::single || s.checks.hold()) return s;
    // A structure the general search does not cover (no root, or its answer fails the checks
    // too): the single zone, its checks failed.
    try {
        tangential_solution g =
            zones_->solve(Q, true, coarse ? std::optional<zone_guess>({coarse->start, coarse->c0}) : std::nullopt);
        return g.checks.hold() ? g : s;
    } catch (const numerical_error&) {
        return s;
    }
}

tangential_solution contact::point(double Q) {
    if (limit_) return limit_->solve(Q);
    if (!reported_) return level_point(Q, nullptr, false);
    tangential_solution coarse = companion_->point(Q);
    tangential_solution s = level_point(Q, &coarse, coarse.general);
    // Both levels on the same path.
    if (s.general && !coarse.general) coarse = companion_->level_point(Q, nullptr, true);
    last_fine_ = s;
    if (s.general) {
        // The general path is not extrapolated: its zone ends do not yet converge at a clean
        // n^-4 at the default n (docs/formulation.md 7(e)). Level n, estimated against n/2.
        last_coarse_ = coarse;
        // Refused where the fast path's extrapolation is: a creep at the edge of the double range.
        if (!std::isfinite(richardson(s.xi, coarse.xi)))
            throw numerical_error("extrapolation: the creep is not finite (roughness parameters too large?)");
        return s;
    }
    s.c0 = richardson(s.c0, coarse.c0);
    s.xi = richardson(s.xi, coarse.xi);
    if (!(std::isfinite(s.c0) && std::isfinite(s.xi)))
        throw numerical_error("extrapolation: the creep is not finite (roughness parameters too large?)");
    return s;
}

tangential_solution contact::distribution(const tangential_solution& s) {
    if (!reported_) return s;
    if (!last_fine_ || last_fine_->Q != s.Q) last_fine_ = level_point(s.Q, nullptr, s.general);
    return *last_fine_;
}

std::optional<error_estimate> contact::estimate(const tangential_solution& s) {
    if (reported_ && s.general) {
        // A point of the general path is level n itself: the difference from n/2.
        if (!last_coarse_ || last_coarse_->Q != s.Q) point(s.Q);
        if (!last_coarse_ || last_coarse_->Q != s.Q) last_coarse_ = companion_->level_point(s.Q, nullptr, true);
        return error_estimate{std::fabs(reported_->lambda - normal_->lambda), std::fabs(s.c0 - last_coarse_->c0),
                              std::fabs(s.xi - last_coarse_->xi), 0.0, "n/2"};
    }
    if (reported_) {
        // Extrapolated: the difference from level n, which is 15/16 of level n's error and
        // above the extrapolated error wherever Richardson's rule holds.
        const tangential_solution level = distribution(s);
        return error_estimate{std::fabs(reported_->lambda - normal_->lambda), std::fabs(s.c0 - level.c0),
                              std::fabs(s.xi - level.xi), 0.0, "level n"};
    }
    if (!ensure_companion()) return std::nullopt;
    return companion_difference(s, companion_->point(s.Q), false);
}

error_estimate contact::companion_difference(const tangential_solution& s, const tangential_solution& c,
                                             bool swept) const {
    // At 2n the difference is (1 - 2^-p) of the error at n: doubled, it stays an upper
    // estimate for every order p >= 1. Swept in c0, c0 is the input and Q is estimated.
    const bool finer = companion_->options_.nodes() > options_.nodes();
    const double scale = finer ? 2.0 : 1.0;
    return error_estimate{scale * std::fabs(normal().lambda - companion_->normal().lambda),
                          swept ? 0.0 : scale * std::fabs(s.c0 - c.c0), scale * std::fabs(s.xi - c.xi),
                          swept ? scale * std::fabs(s.Q - c.Q) : 0.0, finer ? "2n (doubled)" : "n/2"};
}

tangential_solution contact::level_at_stick_end(double c0, bool checked) {
    return limit_ ? limit_->at_stick_end(c0, checked) : tangential_->at_stick_end(c0, checked);
}

contact::swept_point contact::at_stick_end(double c0) {
    tangential_solution s = level_at_stick_end(c0, true);
    if (reported_) {
        // Richardson's rule on Q(c0) and xi(c0) at the same c0.
        const tangential_solution coarse = companion_->level_at_stick_end(c0, false);
        const double Q = richardson(s.Q, coarse.Q), xi = richardson(s.xi, coarse.xi);
        if (!(std::isfinite(Q) && std::isfinite(xi)))
            throw numerical_error("extrapolation: Q(c0) or the creep is not finite (roughness parameters too large?)");
        const error_estimate e{std::fabs(reported_->lambda - normal_->lambda), 0.0, std::fabs(xi - s.xi),
                               std::fabs(Q - s.Q), "level n"};
        s.Q = Q;
        s.xi = xi;
        return {s, e};
    }
    if (!ensure_companion()) return {s, std::nullopt};
    return {s, companion_difference(s, companion_->level_at_stick_end(c0, false), true)};
}

double contact::traction(const tangential_solution& d, double r) {
    return limit_ ? limit_->traction(d, r) : tangential_->traction(d, r);
}

double contact::slip_velocity(const tangential_solution& d, double r) {
    return limit_ ? limit_->slip_velocity(d, r) : tangential_->slip_velocity(d, r);
}

std::vector<double> contact::slip_velocity(const tangential_solution& d, const std::vector<double>& r) {
    if (!limit_) return tangential_->slip_velocity(d, r);
    std::vector<double> v(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) v[i] = limit_->slip_velocity(d, r[i]);
    return v;
}

bool contact::ensure_companion() {
    if (!companion_) {
        // The same problem at n/2 when n/2 is in the asymptotic range of the method; else at 2n.
        const int n = options_.nodes();
        for (int other : {n / 2, 2 * n}) {
            if (other < min_nodes || other > max_nodes) continue;
            // The one-parameter limit has no kernel to resolve: its error falls as n^-2 from small n on.
            if (other < n && options_.how != method::one_parameter &&
                !in_asymptotic_range(widest_kernel(surfaces_), other, options_.how))
                continue;
            try {
                companion_ = std::make_unique<contact>(surfaces_, f_, solver_options{other, options_.how, options_.zones});
                break;
            } catch (const resolution_error&) {
            }
        }
    }
    return companion_ != nullptr;
}

double load_ratio(const roughness& surfaces, const solver_options& options) {
    // The calls of contact's constructor for P_H/P2, in the same order and with the same arguments.
    const int n = options.nodes();
    if (options.how == method::one_parameter)
        return one_parameter_normal(one_parameter_compliances(surfaces).normal, n).lambda;
    const kernel k2 = kernel::normal(surfaces);
    if (options.how != method::extrapolated || k2.empty()) {
        const method level = options.how == method::extrapolated ? method::product : options.how;
        return solve_normal(k2, n, level).lambda;
    }
    if (n / 2 < min_nodes || !in_asymptotic_range(k2, n / 2, method::product))
        throw resolution_error("method 'extrapolated' with n = " + std::to_string(n) +
                               ": the coarse level n/2 is not in the asymptotic range of product integration "
                               "for the normal kernel; increase n or use method 'product'");
    const double coarse = solve_normal(k2, n / 2, method::product).lambda;
    return richardson(solve_normal(k2, n, method::product).lambda, coarse);
}

namespace {
void check_curve_points(int points) {
    if (points < 2 || points > 100000) throw input_error("a curve needs between 2 and 100000 points");
}
}  // namespace

std::vector<double> curve_loads(int points, double f) {
    check_curve_points(points);
    std::vector<double> loads(points);
    for (int i = 0; i < points; ++i) {
        const double v = 1.0 - static_cast<double>(i) / (points - 1);  // 1 - u
        loads[i] = f * (1.0 - v * v);
    }
    loads.back() = f;  // exactly, so the last point is the onset of gross sliding
    return loads;
}

std::vector<curve_point> swept_curve(contact& c, int points) {
    check_curve_points(points);
    std::vector<curve_point> rows;
    rows.reserve(points);
    for (int i = 0; i < points; ++i) {
        // rho = (1 + c0)/2 uniform from 1 to 0: Carter's Q/f = 1 - rho^2, the loads of curve_loads.
        const double rho = 1.0 - static_cast<double>(i) / (points - 1);
        const double c0 = i + 1 == points ? -1.0 : 2.0 * rho - 1.0;
        contact::swept_point p = c.at_stick_end(c0);
        const carter_point smooth = carter(p.solution.Q, c.friction());
        rows.push_back({std::move(p.solution), smooth, p.estimate});
    }
    return rows;
}

std::vector<curve_point> creep_curve(contact& c, const std::vector<double>& loads) {
    std::vector<curve_point> rows;
    rows.reserve(loads.size());
    for (double Q : loads) {
        tangential_solution s = c.point(Q);
        const auto e = c.estimate(s);
        rows.push_back({std::move(s), carter(Q, c.friction()), e});
    }
    return rows;
}

}  // namespace roughroll
