// SPDX-License-Identifier: GPL-3.0-or-later
// The micro-geometry table of a TOML document (a spec file's root, or a physical scene's
// [cylinderN.micro_geometry]), read by the keys of roughroll/io/micro_geometry_input.hpp.
// Internal to the library (not installed): toml++ stays out of the public headers.
#pragma once

#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "roughroll/layer/micro_geometry.hpp"

namespace roughroll {

// The micro-geometry in `table`; `source` names the file in messages, `path` is the dotted key
// of the table ("" for a file's root), `base_dir` resolves a relative profile_csv.
micro_geometry read_micro_geometry(const toml::table& table, const std::string& source, const std::string& path,
                                   const std::filesystem::path& base_dir);

}  // namespace roughroll
