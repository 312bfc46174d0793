// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/chebyshev_projection.hpp"

#include <algorithm>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

std::vector<double> chebyshev_projection(const std::function<double(double)>& g, const std::vector<double>& kinks,
                                         int N) {
    std::vector<double> cuts{0.0, M_PI};
    for (const double r : kinks)
        if (r > -1.0 && r < 1.0) cuts.push_back(std::acos(r));
    std::sort(cuts.begin(), cuts.end());
    const gauss_legendre rule(2 * N + 32);
    std::vector<double> c(static_cast<std::size_t>(N) + 1, 0.0);
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
        const double mid = 0.5 * (cuts[p] + cuts[p + 1]), half = 0.5 * (cuts[p + 1] - cuts[p]);
        if (half <= 0.0) continue;
        for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            // u = pi (x + 1)/2 on the rule's [-1, 1]; dt = half sin u du
            const double u = 0.5 * M_PI * (rule.nodes[i] + 1.0);
            const double t = mid - half * std::cos(u);
            const double w = rule.weights[i] * 0.5 * M_PI * half * std::sin(u) * g(std::cos(t));
            // cos(j t) by the recurrence cos((j+1)t) = 2 cos t cos(jt) - cos((j-1)t)
            const double ct = std::cos(t);
            double c_prev = 1.0, c_cur = ct;
            c[0] += w;
            if (N >= 1) c[1] += w * ct;
            for (int j = 2; j <= N; ++j) {
                const double c_next = 2.0 * ct * c_cur - c_prev;
                c_prev = c_cur;
                c_cur = c_next;
                c[j] += w * c_cur;
            }
        }
    }
    c[0] /= M_PI;
    for (int j = 1; j <= N; ++j) c[j] *= M_2_PI;
    return c;
}

double chebyshev_sum(const std::vector<double>& c, double r) {
    double y1 = 0.0, y2 = 0.0;
    for (std::size_t j = c.size(); j-- > 1;) {
        const double y = 2.0 * r * y1 - y2 + c[j];
        y2 = y1;
        y1 = y;
    }
    return c.empty() ? 0.0 : c[0] + r * y1 - y2;
}

}  // namespace roughroll
