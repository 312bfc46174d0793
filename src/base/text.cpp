// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/base/text.hpp"

#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace roughroll {

std::string shortest(double x) {
    char buffer[32];
    const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, result.ptr);
}

std::string significant(double x, int digits) {
    // The length first: %.40g may need more than any fixed buffer of the usual sizes.
    const int length = std::snprintf(nullptr, 0, "%.*g", digits, x);
    std::string text(static_cast<std::size_t>(length), '\0');
    std::snprintf(text.data(), text.size() + 1, "%.*g", digits, x);
    return text;
}

double rounded_up(double x, int digits) {
    const double unit = std::pow(10.0, std::floor(std::log10(x)) - (digits - 1));
    return std::ceil(x * (1.0 + 1e-12) / unit) * unit;
}

namespace {

// The length of the well-formed UTF-8 sequence at the start of `s` (RFC 3629: no overlong
// forms, no surrogates, nothing above U+10FFFF), or 0 when it is not one.
std::size_t utf8_sequence(std::string_view s) {
    const auto byte = [&s](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    const unsigned char b0 = byte(0);
    if (b0 < 0x80) return 1;
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
    if (b0 >= 0xC2 && b0 <= 0xDF) {
        length = 2;
    } else if (b0 >= 0xE0 && b0 <= 0xEF) {
        length = 3;
        if (b0 == 0xE0) low = 0xA0;   // overlong
        if (b0 == 0xED) high = 0x9F;  // surrogates
    } else if (b0 >= 0xF0 && b0 <= 0xF4) {
        length = 4;
        if (b0 == 0xF0) low = 0x90;   // overlong
        if (b0 == 0xF4) high = 0x8F;  // above U+10FFFF
    } else {
        return 0;
    }
    if (s.size() < length || byte(1) < low || byte(1) > high) return 0;
    for (std::size_t i = 2; i < length; ++i)
        if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
    return length;
}

void escape(unsigned char byte, std::string& out) {
    char text[5];
    std::snprintf(text, sizeof text, "\\x%02x", byte);
    out += text;
}

}  // namespace

std::string one_line(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    while (!text.empty()) {
        const auto byte = static_cast<unsigned char>(text.front());
        const std::size_t length = utf8_sequence(text);
        if (length == 0 || byte < 0x20 || byte == 0x7f) {
            escape(byte, out);
            text.remove_prefix(1);
        } else {
            out.append(text.substr(0, length));
            text.remove_prefix(length);
        }
    }
    return out;
}

std::string echo(std::string_view text, std::size_t max_chars) {
    if (text.size() <= max_chars) return one_line(text);
    // Cut at a character boundary, so that the cut does not make an invalid sequence.
    std::size_t cut = max_chars;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return one_line(text.substr(0, cut)) + "...";
}

std::string underflow_problem(std::string_view literal, double value) {
    if (!(std::fabs(value) < DBL_MIN)) return {};  // normal, infinite or NaN: another rule's
    // Below DBL_MIN: 0 is fine when it was written as 0 (0, -0.0, 0e5, 0_0.0): no nonzero
    // digit before the exponent.
    bool nonzero = false;
    for (const char c : literal) {
        if (c == 'e' || c == 'E') break;
        if (c >= '1' && c <= '9') nonzero = true;
    }
    if (!nonzero) return {};
    return echo(literal) + " is below " + shortest(DBL_MIN) + ", the smallest normal double: it would be read as " +
           (value == 0.0 ? std::string("0") : "the subnormal " + shortest(value) + ", with digits lost");
}

std::optional<double> parse_double(std::string_view literal, std::string& problem) {
    problem.clear();
    double x = 0.0;
    const char* end = literal.data() + literal.size();
    const std::from_chars_result r = std::from_chars(literal.data(), end, x);
    if (literal.empty() || r.ptr != end) return std::nullopt;
    if (r.ec == std::errc::result_out_of_range) {
        // from_chars leaves x alone: strtod tells an overflow (+-HUGE_VAL) from an underflow.
        const std::string text(literal);
        x = std::strtod(text.c_str(), nullptr);
        if (std::isinf(x)) {
            problem = echo(literal) + " is beyond " + shortest(DBL_MAX) + ", the largest double";
            return std::nullopt;
        }
    } else if (r.ec != std::errc()) {
        return std::nullopt;
    }
    problem = underflow_problem(literal, x);
    if (!problem.empty()) return std::nullopt;
    return x;
}

}  // namespace roughroll
