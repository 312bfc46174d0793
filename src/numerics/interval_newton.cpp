// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/interval_newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace roughroll {

namespace {
// The difference step of the Jacobian in (m, rho) is 1e-7 rho, but at least 16 times the ends' rounding eps/rcond
// (ends_newton's `rounding`, where given) and 2^16 eps: the residuals carry that rounding, and a step near it measures
// noise. The floor passes 1e-7 rho where rho < 16 (eps/rcond)/1e-7: with eps/rcond 1.5e-10, 8.6e-10, 4.0e-9 at n = 250,
// 500, 1000 (8(q)), rho below 0.024, 0.14, 0.64, so at large n it sets the step of most zones (their points move by
// the stopping rule's rounding, 8(p)). It was made for the five zones near complete slip, whose stick zones are
// O(f/beta_D) long (1.8e-5 at f = 1e-6 for aluminium on steel, docs/formulation.md 8(f)); there the
// step 1e-7 rho, 9e-13 in r, lay below the rounding 4e-12 (n = 65) to 2.3e-11 (n = 129), and full coupling's
// alternation, whose pressure is a series, wandered without converging at every n (8(p), "Complete slip at full
// coupling").
constexpr double rounding_steps = 16.0;
constexpr double smallest_difference_step = 65536.0 * std::numeric_limits<double>::epsilon();

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

newton_result interval_newton(
    const std::function<std::optional<std::vector<double>>(const std::vector<stick_span>&)>& residual,
    const std::vector<stick_span>& from, bool log_length, int max_iterations, double tolerance,
    const std::function<double()>& rounding, newton_jacobian* kept) {
    newton_problem problem;
    problem.residual = [&](const std::vector<double>& x) { return residual(spans_of(x, log_length)); };
    problem.inside = [log_length](const std::vector<double>& x) { return inside(x, log_length); };
    problem.difference_step = [log_length, &rounding](const std::vector<double>& x, std::size_t j) {
        if (!log_length)
            return -std::max({1e-7 * x[j | 1], smallest_difference_step, rounding ? rounding_steps * rounding() : 0.0});
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
    return damped_newton(problem, x0, {max_iterations, tolerance, 1e-6}, kept);
}

}  // namespace roughroll
