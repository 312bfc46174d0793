// SPDX-License-Identifier: GPL-3.0-or-later
// How numbers and messages are written as text, everywhere in roughroll, and the one rule
// by which a number written as text is read.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace roughroll {

// The shortest text that reads back as x (std::to_chars): "0.3", "-1", "nan", "inf".
// Exact, so every digit printed can be trusted, and readable.
std::string shortest(double x);

// x rounded to `digits` significant digits, as printf's %.<digits>g writes it ("0.000123", "1.23e+06", "nan",
// "-inf"): a bound's size or a plot's label, where the digits beyond those asked for would be noise.
std::string significant(double x, int digits);

// x > 0 rounded up to `digits` significant digits and at least a relative 1e-12 above x: the tolerance a refusal
// advises for an estimate x relative (an x already of two digits would otherwise be advised as itself, and the
// rounding of tol * scale against the estimate could refuse it again). Written with significant(., digits).
double rounded_up(double x, int digits);

// Messages are one line of valid UTF-8 (the CLI prints them as such, JSON needs UTF-8), but
// a quoted TOML key, a string value or a path may hold a newline, another control character
// or bytes that are not UTF-8 (a file name is any bytes): those are shown as \xNN instead.
std::string one_line(std::string_view text);

// Text taken from the input and shown back in a message (a key, a value, a CSV field):
// one_line, cut after `max_chars` bytes with "..." so that a 1 MB key does not become a
// 1 MB message.
constexpr std::size_t max_echo = 60;
std::string echo(std::string_view text, std::size_t max_chars = max_echo);

// The underflow rule, the same for scene and spec files, profile CSVs and the command line:
// a literal with a nonzero digit whose value is below the smallest normal double
// (DBL_MIN = 2.2250738585072014e-308) in magnitude has lost digits or all of itself (1e-400
// reads as 0, 1e-310 as a subnormal). It is refused. Returns why `literal` (read as `value`)
// breaks the rule, or "" when it does not: "1e-400 is below 2.2250738585072014e-308, the
// smallest normal double: it would be read as 0".
std::string underflow_problem(std::string_view literal, double value);

// A whole decimal literal as a double: from_chars (locale-independent, no leading '+' or
// blanks), so that "1.5x", "" or "0x1p3" are not numbers. Nothing when it is not a number
// (`problem` left empty) or when it is one that double precision cannot hold: beyond the
// largest double, or breaking the underflow rule above (`problem` says why).
std::optional<double> parse_double(std::string_view literal, std::string& problem);

}  // namespace roughroll
