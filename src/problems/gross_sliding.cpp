// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/gross_sliding.hpp"

#include "roughroll/numerics/least_value.hpp"

namespace roughroll {

tangential_solution gross_sliding_at(double f, double point, double xi) {
    // The stick equation shrinks to the point r*, where v = xi + scale w = 0 (docs/formulation.md 7(d)). A point
    // inside the contact has slip on both sides of it: the general search's structure (7(d)), not the paper's zone
    // shrunk onto r = -1 (2(g)), and the outputs' zone_path says so as it does for every load below f.
    tangential_solution s = zone_solution(f, point, point, xi, f);
    if (point > -1.0) s.layout.route = zone_route::general;
    return s;
}

tangential_solution gross_sliding(const normal_solution& normal, double f, double forcing,
                                  const std::function<std::vector<double>(const std::vector<double>&)>& G,
                                  bool trailing_edge, const std::string& who) {
    // w = G without forcing (7(d)), b p + f G with it (8(g), 8(s)).
    const auto w = [&](const std::vector<double>& r) {
        std::vector<double> out = G(r);
        if (forcing != 0.0)
            for (std::size_t i = 0; i < r.size(); ++i) out[i] = forcing * normal.pressure(r[i]) + f * out[i];
        return out;
    };
    const least_value least = least_on_contact(
        w, [&](double r) { return w(std::vector<double>{r}).front(); }, 2001, trailing_edge, who);
    tangential_solution s = gross_sliding_at(f, least.r, -(forcing == 0.0 ? f : 1.0) * least.value);
    s.forcing = forcing;
    return s;
}

}  // namespace roughroll
