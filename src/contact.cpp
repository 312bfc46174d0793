#include "roughroll/contact.hpp"

#include <chrono>
#include <cmath>

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
    const int n = options_.nodes();
    if (n < 2 * min_nodes) return std::nullopt;
    if (!coarse_) coarse_ = std::make_unique<contact>(surfaces_, f_, solver_options{n / 2, options_.how});
    const tangential_solution c = coarse_->point(s.Q);
    return error_estimate{std::fabs(normal_->lambda - coarse_->normal().lambda), std::fabs(s.c0 - c.c0),
                          std::fabs(s.xi - c.xi)};
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
