// SPDX-License-Identifier: GPL-3.0-or-later
// The roughness parameters (2.11)-(2.15) of a micro-geometry as JSON: what `roughroll
// roughness SPEC --json` prints and the Python module's roughroll.roughness returns.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "roughroll/layer/micro_geometry.hpp"
#include "roughroll/layer/roughness_parameters.hpp"

namespace roughroll {

// `spec` names the spec (its file, or what the caller passed); k_*, t_*, alpha_* in SI units,
// the averages (2.9), every error estimate, the number of x1 points, and the units.
nlohmann::json to_json(const std::string& spec, const micro_geometry& g, const roughness_parameters& p);

}  // namespace roughroll
