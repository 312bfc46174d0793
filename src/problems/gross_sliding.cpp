// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/gross_sliding.hpp"

#include "roughroll/numerics/least_value.hpp"

namespace roughroll {

tangential_solution gross_sliding_at(double f, double point, double xi) {
    // The stick equation shrinks to the point r*, where v = xi + scale w = 0 (docs/formulation.md 7(d)).
    return zone_solution(f, point, point, xi, f);
}

tangential_solution gross_sliding(double f, double scale,
                                  const std::function<std::vector<double>(const std::vector<double>&)>& sampled,
                                  const std::function<double(double)>& value, int samples, bool trailing_edge,
                                  const std::string& who) {
    const least_value least = least_on_contact(sampled, value, samples, trailing_edge, who);
    return gross_sliding_at(f, least.r, -scale * least.value);
}

}  // namespace roughroll
