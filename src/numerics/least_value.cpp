// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/least_value.hpp"

#include <algorithm>
#include <cmath>

#include "roughroll/base/error.hpp"

namespace roughroll {

least_value least_on_contact(const std::function<std::vector<double>(const std::vector<double>&)>& sampled,
                             const std::function<double(double)>& value, int samples, bool trailing_edge,
                             const std::string& who) {
    std::vector<double> r(samples);
    for (int i = 0; i < samples; ++i) r[i] = 1.0 - 2.0 * i / (samples - 1);  // descending
    const std::vector<double> g = sampled(r);
    for (double v : g)
        if (!std::isfinite(v))
            throw numerical_error(who + ": G of (3.25) is not finite (roughness parameters too large?)");
    const auto least = static_cast<int>(std::min_element(g.begin(), g.end()) - g.begin());
    double lo = r[std::min(least + 1, samples - 1)], hi = r[std::max(least - 1, 0)];
    // Golden section on the sample's bracket (the function is smooth inside (-1, 1)).
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    double g1 = value(x1), g2 = value(x2);
    while (hi - lo > 1e-12) {
        if (g1 <= g2) {
            hi = x2, x2 = x1, g2 = g1;
            x1 = hi - golden * (hi - lo), g1 = value(x1);
        } else {
            lo = x1, x1 = x2, g1 = g2;
            x2 = lo + golden * (hi - lo), g2 = value(x2);
        }
    }
    least_value out{0.5 * (lo + hi), value(0.5 * (lo + hi))};
    for (double edge : {-1.0, 1.0}) {
        if (edge == 1.0 && !trailing_edge) break;
        const double at_edge = value(edge);
        if (at_edge <= out.value) out = {edge, at_edge};
    }
    return out;
}

}  // namespace roughroll
