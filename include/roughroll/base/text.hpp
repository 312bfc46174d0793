// How numbers and messages are written as text, everywhere in roughroll.
#pragma once

#include <string>
#include <string_view>

namespace roughroll {

// The shortest text that reads back as x (std::to_chars): "0.3", "-1", "nan", "inf".
// Exact, so every digit printed can be trusted, and readable.
std::string shortest(double x);

// Messages are one line (the CLI prints them as such), but a quoted TOML key, a string
// value or a path may hold a newline or another control character: those are shown as
// \xNN instead of breaking the line.
std::string one_line(std::string_view text);

}  // namespace roughroll
