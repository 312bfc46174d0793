// The least value of a function smooth inside [-1, 1]: where the stick zone shrinks to a point
// at gross sliding, v = xi + f G >= 0 with equality at the point where G is least
// (docs/formulation.md 7(d)). Sampled at `samples` points (its values taken together, as a
// kernel sweep gives them at sorted points), refined by golden section to 1e-12 in r, and the
// edge r = -1 compared.
#pragma once

#include <functional>
#include <vector>

namespace roughroll {

struct least_value {
    double r, value;
};

// `sampled`: values at points r_0 >= r_1 >= ... (descending); `value`: one value. Throws
// numerical_error when a sample is not finite.
least_value least_on_contact(const std::function<std::vector<double>(const std::vector<double>&)>& sampled,
                             const std::function<double(double)>& value, int samples = 2001);

}  // namespace roughroll
