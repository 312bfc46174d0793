// SPDX-License-Identifier: GPL-3.0-or-later
// Strict reading of TOML input files (scenes, roughness specs): every key known, every value
// of the right type and range, every problem one line naming the file and the dotted key.
// Internal to the library (not installed): the readers of scene.cpp and micro_geometry_input.cpp.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace roughroll::toml_input {

using key_list = std::initializer_list<std::string_view>;

// Throws input_error "<source>: <what>" on one line.
[[noreturn]] void fail(const std::string& source, const std::string& what);

// The dotted path of `key` inside the table at `parent` ("" is the root), and it quoted.
std::string join(const std::string& parent, std::string_view key);
std::string quoted(const std::string& path);

[[noreturn]] void wrong_type(const toml::node& node, const char* expected, const std::string& source,
                             const std::string& path);

// Every key of `table` must be one of `allowed`: a misspelt key would otherwise be ignored
// silently and a default used in its place.
void check_keys(const toml::table& table, key_list allowed, const std::string& source, const std::string& path);

// The sub-table at `key`, or nullptr when it is absent.
const toml::table* table_at(const toml::table& parent, std::string_view key, const std::string& source,
                            const std::string& path);

// A number: TOML's integers are accepted (a physicist writing T = 1 means 1.0).
double number_at(const toml::node& node, const std::string& source, const std::string& path);

enum class lower_bound { positive, non_negative };

// A number that is finite and > 0 (positive) or >= 0 (non_negative).
double bounded_number(const toml::node& node, lower_bound bound, const std::string& source, const std::string& path);

const std::string& string_at(const toml::node& node, const std::string& source, const std::string& path);

// Parses TOML text; a syntax error is "<source>:<line>:<column>: malformed TOML: ...".
toml::table parse_toml(std::string_view text, const std::string& source);

// The whole content of a regular file; anything else is an input_error
// "cannot read <what> '<path>': <reason>".
std::string read_text(const std::string& path, const std::string& what);

}  // namespace roughroll::toml_input
