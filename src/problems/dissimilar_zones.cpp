#include "roughroll/problems/dissimilar_zones.hpp"

#include "roughroll/base/error.hpp"

namespace roughroll {

void check_dissimilar(const dissimilar& materials, const solver_options& options) {
    check_beta_d(materials.beta_d);
    if (materials.beta_d == 0.0) return;  // the paper's problem at both coupling levels (8(d))
    if (options.how == method::one_parameter)
        throw input_error("beta_d != 0 is not available for method 'one-parameter': its edge behaviour is not "
                          "derived (docs/formulation.md 8(g)); use 'product' or 'extrapolated'");
    if (materials.coupling == coupling_level::full)
        throw input_error("coupling 'full' for beta_d != 0 is not built yet (docs/formulation.md 8(j) item 7); use "
                          "coupling \"johnson\"");
    if (options.zones == zone_search::single)
        throw input_error("zones 'single' with beta_d != 0: the paper's stick zone from r = -1 is never the answer "
                          "for dissimilar rollers (docs/formulation.md 8(g)); use 'auto' or 'general'");
    throw input_error("beta_d != 0 (dissimilar rollers) is not solved yet");
}

}  // namespace roughroll
