#include "roughroll/contact.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>

#include "roughroll/collocation.hpp"
#include "roughroll/error.hpp"

namespace roughroll {

contact::contact(const roughness& surfaces, double f, const solver_options& options)
    : surfaces_(surfaces), options_(options), f_(f) {
    if (!(std::isfinite(f) && f > 0.0)) throw input_error("friction coefficient f must be positive and finite");
    const auto start = std::chrono::steady_clock::now();
    normal_ = std::make_unique<normal_solution>(solve_normal(kernel::normal(surfaces), options.nodes(), options.how));
    normal_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    tangential_ = std::make_unique<tangential_solver>(*normal_, kernel::tangential(surfaces),
                                                      kernel::normal(surfaces), f);
}

std::optional<error_estimate> contact::estimate(const tangential_solution& s) {
    if (!companion_) {
        // The same problem at n/2 when n/2 is in the asymptotic range of the method; else
        // at 2n, where the difference is (1 - 2^-p) of the error at n: it is doubled to stay
        // an upper estimate for every order p >= 1.
        const int n = options_.nodes();
        const double rate = std::max(kernel::normal(surfaces_).max_rate(), kernel::tangential(surfaces_).max_rate());
        const kernel widest(std::vector<exponential_term>{{1.0, rate}});
        for (int other : {n / 2, 2 * n}) {
            if (other < min_nodes || other > max_nodes) continue;
            if (other < n && !in_asymptotic_range(widest, other, options_.how)) continue;
            try {
                companion_ = std::make_unique<contact>(surfaces_, f_, solver_options{other, options_.how});
                break;
            } catch (const resolution_error&) {
            }
        }
        if (!companion_) return std::nullopt;
    }
    const tangential_solution c = companion_->point(s.Q);
    const double scale = companion_->options_.nodes() > options_.nodes() ? 2.0 : 1.0;
    return error_estimate{scale * std::fabs(normal_->lambda - companion_->normal().lambda),
                          scale * std::fabs(s.c0 - c.c0), scale * std::fabs(s.xi - c.xi)};
}

std::vector<double> curve_loads(int points, double f) {
    if (points < 2 || points > 100000) throw input_error("a curve needs between 2 and 100000 points");
    std::vector<double> loads(points);
    for (int i = 0; i < points; ++i) {
        const double v = 1.0 - static_cast<double>(i) / (points - 1);  // 1 - u
        loads[i] = f * (1.0 - v * v);
    }
    loads.back() = f;  // exactly, so the last point is the onset of gross sliding
    return loads;
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
