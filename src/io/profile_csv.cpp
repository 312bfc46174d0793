// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/profile_csv.hpp"

#include <charconv>
#include <cmath>
#include <optional>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "toml_input.hpp"

namespace roughroll {
namespace {

std::string_view trim(std::string_view s) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

// The rules of every measured profile's samples (profile_csv.hpp), whichever way they are given:
// sample `at` (a CSV line, or an array index) is named as "<source>:<at>: ".
class sample_list {
public:
    sample_list(const std::string& source, double l) : source_(source), l_(l) {}

    [[noreturn]] void fail(int at, const std::string& what) const {
        throw input_error(one_line(source_ + ":" + std::to_string(at) + ": " + what));
    }

    void add(double x, double h, int at) {
        if (!std::isfinite(x)) fail(at, "x1 = " + shortest(x) + " is not finite");
        if (!std::isfinite(h)) fail(at, "h0 = " + shortest(h) + " is not finite");
        if (closed_) fail(at, "a sample after the closing point x1 = l = " + shortest(l_));
        if (samples_.x1.empty()) {
            if (x != 0.0) fail(at, "the first sample must be at x1 = 0 (got x1 = " + shortest(x) + ")");
        } else if (!(x > samples_.x1.back())) {
            fail(at, "x1 = " + shortest(x) +
                         " does not increase (the previous sample is at x1 = " + shortest(samples_.x1.back()) + ")");
        }
        if (x == l_) {
            // The periodic closing point: allowed only as a repeat of the first sample.
            if (h != samples_.h0.front()) {
                fail(at, "the closing point x1 = l = " + shortest(l_) + " has h0 = " + shortest(h) + ", not the h0 = " +
                             shortest(samples_.h0.front()) + " of x1 = 0 (the profile is periodic)");
            }
            closed_ = true;
            return;
        }
        if (x > l_) fail(at, "x1 = " + shortest(x) + " is beyond the period l = " + shortest(l_));
        samples_.x1.push_back(x);
        samples_.h0.push_back(h);
        samples_.lines.push_back(at);
    }

    profile_samples finish() {
        const int n = static_cast<int>(samples_.x1.size());
        if (n < min_profile_samples) {
            throw input_error(one_line(source_ + ": a measured profile needs at least " +
                                       std::to_string(min_profile_samples) + " samples over one period (got " +
                                       std::to_string(n) + ")"));
        }
        samples_.source = source_;
        return std::move(samples_);
    }

private:
    const std::string& source_;
    const double l_;
    profile_samples samples_;
    bool closed_ = false;
};

class line_parser {
public:
    line_parser(const std::string& source, double l) : samples_(source, l) {}

    void take(std::string_view raw, int line) {
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        const std::string_view text = trim(raw);
        if (text.empty() || text.front() == '#') return;
        const std::size_t comma = text.find(',');
        const bool first = !seen_data_;
        seen_data_ = true;
        if (comma == std::string_view::npos || text.find(',', comma + 1) != std::string_view::npos) {
            samples_.fail(line, "expected two comma-separated fields 'x1, h0', got '" + echo(text) + "'");
        }
        const std::string_view f1 = trim(text.substr(0, comma)), f2 = trim(text.substr(comma + 1));
        // A whole field as a double (text.hpp: "1.5x" or "" is not 1.5 or 0, and 1e-400 is
        // refused by the underflow rule, as in a scene file).
        std::string x_problem, h_problem;
        const std::optional<double> x = parse_double(f1, x_problem), h = parse_double(f2, h_problem);
        if (first && f1 == "x1" && f2 == "h0") return;  // the optional header
        if (!x || !h) {
            const std::string_view bad = !x ? f1 : f2;
            const std::string& problem = !x ? x_problem : h_problem;
            const std::string name = !x ? "x1" : "h0";
            if (!problem.empty()) samples_.fail(line, name + " = " + problem);
            samples_.fail(line, name + " '" + echo(bad) + "' is not a number" +
                                    (first ? " (the only header allowed is 'x1,h0')" : ""));
        }
        samples_.add(*x, *h, line);
    }

    profile_samples finish() { return samples_.finish(); }

private:
    sample_list samples_;
    bool seen_data_ = false;
};

}  // namespace

profile_samples parse_profile_csv(std::string_view text, const std::string& source, double l) {
    if (!(std::isfinite(l) && l > 0.0)) {
        throw input_error(one_line(source + ": the period l must be finite and > 0 (got " + shortest(l) + ")"));
    }
    // A UTF-8 byte-order mark, as spreadsheet programs write, is not part of the first field.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    line_parser parser(source, l);
    int line = 0;
    while (!text.empty()) {
        ++line;
        const std::size_t end = text.find('\n');
        parser.take(text.substr(0, end), line);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    }
    return parser.finish();
}

profile_samples profile_from_arrays(const std::vector<double>& x1, const std::vector<double>& h0,
                                    const std::string& source, double l) {
    if (!(std::isfinite(l) && l > 0.0)) {
        throw input_error(one_line(source + ": the period l must be finite and > 0 (got " + shortest(l) + ")"));
    }
    if (x1.size() != h0.size()) {
        throw input_error(one_line(source + ": x1 has " + std::to_string(x1.size()) + " samples but h0 has " +
                                   std::to_string(h0.size()) + ": give one h0 per x1"));
    }
    sample_list samples(source, l);
    for (std::size_t i = 0; i < x1.size(); ++i) samples.add(x1[i], h0[i], static_cast<int>(i));
    return samples.finish();
}

profile_samples read_profile_csv(const std::string& path, double l) {
    return parse_profile_csv(toml_input::read_text(path, "profile file"), path, l);
}

}  // namespace roughroll
