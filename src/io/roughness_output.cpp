// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/roughness_output.hpp"

#include "roughroll/base/text.hpp"
#include "roughroll/io/output.hpp"

namespace roughroll {

namespace {
nlohmann::json averages_json(const layer_averages& m) {
    return {{"a", m.a}, {"a3_h1", m.a3_h1}, {"a33", m.a33}, {"a_h1", m.a_h1}, {"a_h1_squared", m.a_h1_squared}};
}
}  // namespace

nlohmann::json to_json(const std::string& spec, const micro_geometry& g, const roughness_parameters& p) {
    nlohmann::json j;
    j["spec"] = one_line(spec);  // a file name is any bytes; JSON needs UTF-8
    j["profile"] = to_string(g.bottom.kind);
    j["micro_shape"] = to_string(g.shape);
    j["decay"] = to_string(g.decay);
    j["factor_2_12"] = to_string(g.factor_2_12);
    j["k_tangential"] = p.k_tangential;
    j["k_normal"] = p.k_normal;
    j["t_tangential"] = p.t_tangential;
    j["t_normal"] = p.t_normal;
    j["alpha_tangential"] = p.alpha_tangential;
    j["alpha_normal"] = p.alpha_normal;
    j["averages"] = averages_json(p.averages);
    j["error_estimate"] = {{"k_tangential", p.k_tangential_error},         {"k_normal", p.k_normal_error},
                           {"t_tangential", p.t_tangential_error},         {"t_normal", p.t_normal_error},
                           {"alpha_tangential", p.alpha_tangential_error}, {"alpha_normal", p.alpha_normal_error},
                           {"averages", averages_json(p.averages_error)}};
    j["evaluations"] = p.evaluations;
    j["units"] = {{"k", "Pa/m"},  {"t", "Pa m"},  {"alpha", "1/m"}, {"a", "m"},
                  {"a3_h1", "1"}, {"a33", "1/m"}, {"a_h1", "m"},    {"a_h1_squared", "m"}};
    j["reference"] = paper_reference;
    j["version"] = version();
    return j;
}

}  // namespace roughroll
