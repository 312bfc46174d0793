// SPDX-License-Identifier: GPL-3.0-or-later
// The least value of a function smooth inside [-1, 1]: where the stick zone shrinks to a point
// at gross sliding, v = xi + f G >= 0 with equality at the point where G is least
// (docs/formulation.md 7(d)). Sampled at `samples` points (its values taken together, as a
// kernel sweep gives them at sorted points), refined by golden section to 1e-12 in r, and the
// edge r = -1 compared (and r = 1 with `trailing_edge`: the dissimilar gross sliding of
// docs/formulation.md 8(g), xi' = -min (b p + f G), which may be least at either edge).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace roughroll {

struct least_value {
    double r, value;
};

// `sampled`: values at points r_0 >= r_1 >= ... (descending); `value`: one value. Throws
// numerical_error, its message opened by `who`, when a sample is not finite.
least_value least_on_contact(const std::function<std::vector<double>(const std::vector<double>&)>& sampled,
                             const std::function<double(double)>& value, int samples = 2001, bool trailing_edge = false,
                             const std::string& who = "zone solver");

}  // namespace roughroll
