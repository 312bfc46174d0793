// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/load_ratio.hpp"

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/one_parameter.hpp"

namespace roughroll {

namespace {
// P_H/P2 of the normal problem of one level at n by `how`'s level method (the one-parameter limit's own).
double level_load_ratio(const roughness& surfaces, method how, int n, normal_cache* cache) {
    if (how == method::one_parameter) return one_parameter_normal(one_parameter_compliances(surfaces).normal, n).lambda;
    return solve_normal(kernel::normal(surfaces), n, level_of(how), cache).lambda;
}
}  // namespace

double load_ratio(const roughness& surfaces, const solver_options& options, normal_cache* cache) {
    // The calls of contact's constructor for P_H/P2, in the same order and with the same arguments.
    const int n = options.nodes();
    if (options.how != method::extrapolated) return level_load_ratio(surfaces, options.how, n, cache);
    const kernel k2 = kernel::normal(surfaces);
    if (k2.empty()) return solve_normal(k2, n, level_of(options.how), cache).lambda;
    check_extrapolation_range(k2, n, "the normal kernel");
    const double coarse = solve_normal(k2, n / 2, method::product, cache).lambda;
    return richardson(solve_normal(k2, n, method::product, cache).lambda, coarse);
}

double coarse_load_ratio(const roughness& surfaces, const solver_options& options, normal_cache* cache) {
    const int n = options.nodes() / 2;
    if (n < min_nodes)
        throw resolution_error("the cheap level n/2 = " + std::to_string(n) + " is below " + std::to_string(min_nodes));
    return level_load_ratio(surfaces, options.how, n, cache);
}

double coupled_load_ratio(const roughness& surfaces, double f, const solver_options& options,
                          const dissimilar& materials, double Q, normal_cache* cache,
                          const std::function<void()>& checkpoint) {
    if (materials.beta_d == 0.0 || materials.coupling != coupling_level::full)
        throw input_error("coupled_load_ratio: the rollers are not dissimilar at full coupling (use load_ratio)");
    contact c(surfaces, f, options, materials, cache);
    c.set_checkpoint(checkpoint);
    c.point(Q);
    return c.normal().lambda;
}

}  // namespace roughroll
