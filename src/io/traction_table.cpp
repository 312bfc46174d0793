// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/traction_table.hpp"

#include <algorithm>
#include <cmath>

#include "roughroll/model/carter.hpp"

namespace roughroll {

namespace {
constexpr double two_over_pi = 0.636619772367581343076;
}  // namespace

smooth_traction carter_tractions(double r, double Q, double f) {
    const carter_point cp = carter(Q, f);
    const double rho = 0.5 * (1.0 + cp.c0);
    const double p = two_over_pi * std::sqrt(std::max(0.0, 1.0 - r * r));
    const double d = r + 1.0 - rho;
    const double q0 = r < cp.c0 ? -two_over_pi * f * std::sqrt(std::max(0.0, rho * rho - d * d)) : 0.0;
    return {p, (Q < 0.0 ? -1.0 : 1.0) * (f * p + q0)};
}

std::vector<traction_row> traction_table(contact& c, const tangential_solution& level, const std::vector<double>& grid,
                                         double Q, double f, const std::optional<si_point>& si) {
    std::vector<traction_row> rows;
    rows.reserve(grid.size());
    for (const contact::distribution_row& d : c.distributions(level, grid)) {
        const smooth_traction smooth = carter_tractions(d.r, Q, f);
        traction_row row{d.r, d.p, d.p1, d.v, d.stick, smooth.p, smooth.p1, std::nullopt, std::nullopt, std::nullopt};
        if (si) {
            row.x1_m = d.r * si->a;
            row.p2_Pa = d.p * si->p_scale;
            row.p1_Pa = d.p1 * si->p_scale;
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace roughroll
