// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/numerics/u_series_table.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <gsl/gsl_math.h>

#include "roughroll/base/error.hpp"

namespace roughroll {

double u_series_table::panel_bound(int n, double length) {
    // M = e^{n y} on the ellipse (class comment).
    return theta_panels::ellipse_bound(0.5 * length, [n](double y, double) { return std::exp(n * y); });
}

u_series_table::u_series_table(const std::vector<double>& b) {
    const int n = static_cast<int>(b.size());
    double l1 = 0.0;
    for (double bj : b) l1 += std::fabs(bj);
    if (n == 0 || !std::isfinite(l1)) throw numerical_error("u_series_table: the series is empty or not finite");
    // From panels of about 8/n in theta (n y of order one), finer until the bound is below eps.
    int panels = std::max(1, static_cast<int>(std::ceil(M_PI * n / 8.0)));
    double relative = panel_bound(n, M_PI / panels);
    while (!(relative <= DBL_EPSILON)) {
        panels += std::max(1, panels / 8);
        relative = panel_bound(n, M_PI / panels);
    }
    table_ = theta_panels(panels);
    bound_ = relative * l1;
    // P at the panels' nodes as the sine series itself, term by term: the U-series at cos theta would
    // carry the rounding of cos theta, which next to the ends moves theta by eps/sin theta, and P
    // with it by up to sum (j+1) |b_j| times that (measured: 5e-11 for n = 128 equal terms).
    const int size = theta_panels::degree + 1;
    const std::size_t count = static_cast<std::size_t>(panels) * size;
    std::vector<double> values(count, 0.0);
    for (int j = 0; j < panels; ++j)
        for (int i = 0; i < size; ++i) {
            const double theta = table_.node(j, i);
            double sum = 0.0;
            for (int k = n; k-- > 0;) sum += b[k] * std::sin((k + 1) * theta);
            values[j * size + i] = sum;
        }
    table_.set_values(values);
}

}  // namespace roughroll
