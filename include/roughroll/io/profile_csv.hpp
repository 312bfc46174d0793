// SPDX-License-Identifier: GPL-3.0-or-later
// A measured profile h0(x1) of (2.1) from CSV text: one period of `x1, h0` samples in metres.
// The rules (docs/roughness-parameters.md, "Measured profiles"):
//   - lines end in \n (a \r before it is dropped); blank lines and lines whose first
//     non-blank character is '#' are skipped;
//   - the first other line may be the header `x1,h0` (spaces around the names allowed);
//   - every other line is two numbers separated by one comma, spaces around them allowed,
//     each a whole C/C++ floating-point literal (std::from_chars: no '+', no hex prefix) and
//     finite;
//   - x1 starts at exactly 0, increases strictly and stays below the period l; one last row
//     at x1 = l exactly is the periodic closing point and must repeat the h0 of x1 = 0 (it is
//     then dropped: the spline closes the period itself); no row may follow it;
//   - at least 4 samples (without the closing point).
// Every bad line is one input_error "<source>:<line>: <what>"; a file-wide problem is
// "<source>: <what>". The range 0 <= h0 < H is the paper's condition, checked with H by
// micro_geometry.hpp's condition_violations (naming the line too).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "roughroll/layer/micro_geometry.hpp"

namespace roughroll {

// The fewest samples a measured profile may have (the closing point not counted).
constexpr int min_profile_samples = 4;

// Parses CSV text for a profile of period l (finite, > 0); `source` names it in messages.
profile_samples parse_profile_csv(std::string_view text, const std::string& source, double l);

// The same profile from arrays of x1 and h0 (a scene's profile_x1 and profile_h0, Python's NumPy
// arrays), by the same rules from x1 = 0 on; sample i (from 0) is named "<source>:<i>: <what>",
// as a CSV names its line. Arrays of different lengths are an input_error too.
profile_samples profile_from_arrays(const std::vector<double>& x1, const std::vector<double>& h0,
                                    const std::string& source, double l);

// Reads and parses the file at `path` (a missing or unreadable file is an input_error
// "cannot read profile file '<path>': <reason>").
profile_samples read_profile_csv(const std::string& path, double l);

}  // namespace roughroll
