// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_newton.hpp"

#include <cmath>
#include <vector>

#include <gsl/gsl_math.h>

#include "roughroll/numerics/damped_newton.hpp"

namespace roughroll {

std::optional<tangential_solution> zone_ends_newton(
    const std::function<tangential_solution(double, double)>& solve_on_zone,
    const std::function<double(const tangential_solution&)>& entry, double gap, double start, double c0,
    int max_iterations, double tolerance) {
    if (!(gap > 0.0 && c0 > start)) return std::nullopt;
    std::optional<tangential_solution> last;  // the solve at the last x, which is the root's
    newton_problem problem;
    problem.residual = [&](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        const double rho = std::exp(x[1]);
        last = solve_on_zone(x[0] - rho, x[0] + rho);
        const double deficit = -rho * M_PI_2 * last->psi_b[0];
        if (!(deficit > 0.0)) return std::nullopt;  // this zone carries more than f: off the family
        return std::vector<double>{std::log(deficit / gap), entry(*last)};
    };
    problem.inside = [](const std::vector<double>& x) {
        const double rho = std::exp(x[1]);
        return x[0] - rho > -1.0 && x[0] + rho <= 1.0;
    };
    problem.difference_step = [&problem](const std::vector<double>& x, std::size_t j) {
        if (j == 1) return -1e-6;
        const double h = 1e-6 * std::exp(x[1]);
        return problem.inside({x[0] - h, x[1]}) ? -h : h;
    };
    problem.step_size = [](const std::vector<double>& x, const std::vector<double>& dx) {
        return std::fabs(dx[0]) + std::exp(x[1]) * std::fabs(dx[1]);
    };
    const auto root =
        damped_newton(problem, {0.5 * (start + c0), std::log(0.5 * (c0 - start))}, {max_iterations, tolerance, 1e-6});
    if (!root) return std::nullopt;
    tangential_solution s = *last;
    s.iterations = root->iterations;
    return s;
}

}  // namespace roughroll
