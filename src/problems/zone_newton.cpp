// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_newton.hpp"

#include <cmath>
#include <vector>

#include "roughroll/numerics/damped_newton.hpp"

namespace roughroll {

namespace {
// The zones of x = (m_1, l_1, ..., m_k, l_k).
std::vector<stick_span> spans_of(const std::vector<double>& x, bool log_length) {
    std::vector<stick_span> z(x.size() / 2);
    for (std::size_t i = 0; i < z.size(); ++i) {
        const double rho = log_length ? std::exp(x[2 * i + 1]) : x[2 * i + 1];
        z[i] = {x[2 * i] - rho, x[2 * i] + rho, rho};
    }
    return z;
}

// -1 < s_1, each zone longer than a point, ordered without overlap, c_k <= 1.
bool inside(const std::vector<double>& x, bool log_length) {
    const std::vector<stick_span> z = spans_of(x, log_length);
    if (!(z.front().start > -1.0 && z.back().end <= 1.0)) return false;
    for (std::size_t i = 0; i < z.size(); ++i)
        if (!(z[i].rho > 0.0) || (i > 0 && !(z[i - 1].end < z[i].start))) return false;
    return true;
}
}  // namespace

std::optional<newton_root> zone_newton(
    const std::function<std::optional<std::vector<double>>(const std::vector<stick_span>&)>& residual,
    const std::vector<stick_span>& from, bool log_length, int max_iterations, double tolerance,
    const std::function<double()>& rounding) {
    newton_problem problem;
    problem.residual = [&](const std::vector<double>& x) { return residual(spans_of(x, log_length)); };
    problem.inside = [log_length](const std::vector<double>& x) { return inside(x, log_length); };
    problem.difference_step = [log_length](const std::vector<double>& x, std::size_t j) {
        if (!log_length) return -1e-7 * x[j | 1];
        if (j % 2 == 1) return -1e-6;
        const double h = 1e-6 * std::exp(x[j + 1]);
        std::vector<double> y = x;
        y[j] -= h;
        return inside(y, true) ? -h : h;
    };
    problem.step_size = [log_length](const std::vector<double>& x, const std::vector<double>& dx) {
        double size = 0.0;
        for (std::size_t j = 0; j < x.size(); ++j)
            size += (log_length && j % 2 == 1 ? std::exp(x[j]) : 1.0) * std::fabs(dx[j]);
        return size;
    };
    if (rounding) problem.rounding = [&rounding](const std::vector<double>&) { return rounding(); };
    std::vector<double> x0;
    for (const stick_span& z : from) {
        const double half = 0.5 * (z.end - z.start);
        x0.push_back(0.5 * (z.start + z.end));
        x0.push_back(log_length ? std::log(half) : half);
    }
    return damped_newton(problem, x0, {max_iterations, tolerance, 1e-6});
}

}  // namespace roughroll
