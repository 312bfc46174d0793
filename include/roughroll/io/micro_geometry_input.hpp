// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a micro-geometry from TOML, strictly: every key known, every value of the right type
// and range, every problem one line naming the file and the key, as the scene reader does.
// The keys, the same at a spec file's root and in a table of a scene:
//   lambda0 = 1.15e11      # Pa, Lame constant of the layer, finite and >= 0
//   mu0 = 7.7e10           # Pa, shear modulus of the layer, finite and > 0
//   H = 1e-5               # m, mean thickness of the layer, finite and > 0
//   l = 1e-4               # m, period of the roughness, finite and > 0
//   profile = "sine"       # "flat" | "sine" | "sawtooth" | "measured" (required)
//   delta = 4e-6           # m, peak of h0: required for sine and sawtooth, 0 <= delta < H;
//                          #   an error for flat and measured
//   profile_csv = "p.csv"  # measured only (required there): one period of x1,h0 (profile_csv.hpp);
//                          #   a relative path is relative to base_dir (the spec's folder)
//   micro_shape = "sine"   # optional, the only shape so far (default "sine")
//   decay = "linear"       # "linear" | "quadratic" | "cosine" (required: it changes k by tens
//                          #   of per cent, so a default would hide a modelling choice)
//   factor_2_12 = "derived"  # optional, the factor of the corrector term of k^(2) in (2.12):
//                          #   "derived" (lambda0/(lambda0+2mu0))^2, the default, or "printed"
//                          #   ((lambda0+mu0)/(lambda0+2mu0))^2 as the paper prints it
//                          #   (docs/formulation.md, erratum E11)
// The paper's conditions (0 <= h0 < H on samples and spline) are checked too (check_conditions).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "roughroll/layer/micro_geometry.hpp"

namespace roughroll {

// A roughness spec: TOML text whose root holds the keys above.
micro_geometry parse_roughness_spec(std::string_view text, const std::string& source,
                                    const std::filesystem::path& base_dir);

// The spec file at `file` (a relative profile_csv is relative to the file's folder).
micro_geometry read_roughness_spec(const std::string& file);

}  // namespace roughroll
