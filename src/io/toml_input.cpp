// SPDX-License-Identifier: GPL-3.0-or-later
#include "toml_input.hpp"

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll::toml_input {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw input_error(one_line(source + ": " + what));
}

// The dotted path of `key` inside the table at `parent` ("" is the root).
std::string join(const std::string& parent, std::string_view key) {
    std::string path = parent;
    if (!path.empty()) path += '.';
    path += key;
    return path;
}

// Cut: a path built from the input's keys (a table nested a thousand deep) must not make a long message.
std::string quoted(const std::string& path) { return "'" + echo(path, 200) + "'"; }

namespace {
// "a string", "an integer", ...: what was found where something else was expected.
const char* type_phrase(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return "an array";
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a floating-point number";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
        case toml::node_type::none: break;
    }
    return "nothing";
}
}  // namespace

[[noreturn]] void wrong_type(const toml::node& node, const char* expected, const std::string& source,
                             const std::string& path) {
    fail(source, quoted(path) + " must be " + expected + ", not " + type_phrase(node));
}

// A misspelt key would otherwise be ignored silently and the scene solved with a
// default in its place; so every key must be one of `allowed`. A toml::table
// iterates in key order, so the key reported does not depend on the file's layout.
void check_keys(const toml::table& table, key_list allowed, const std::string& source, const std::string& path) {
    for (const auto& [key, node] : table) {
        if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
        std::string names;
        for (const std::string_view name : allowed) names += (names.empty() ? "" : ", ") + std::string(name);
        const char* kind = node.is_table() ? "unknown table " : "unknown key ";
        fail(source, kind + quoted(join(path, echo(key.str()))) + " (allowed here: " + names + ")");
    }
}

// The sub-table at `key`, or nullptr when it is absent: every table of a scene is optional.
const toml::table* table_at(const toml::table& parent, std::string_view key, const std::string& source,
                            const std::string& path) {
    const toml::node* node = parent.get(key);
    if (node == nullptr) return nullptr;
    if (!node->is_table()) wrong_type(*node, "a table", source, path);
    return node->as_table();
}

// TOML writes 1 for a whole number, and a physicist writing T = 1 means 1.0.
double number_at(const toml::node& node, const std::string& source, const std::string& path) {
    if (const auto* integer = node.as_integer()) return static_cast<double>(integer->get());
    if (const auto* floating = node.as_floating_point()) return floating->get();
    wrong_type(node, "a number", source, path);
}

// A number that is finite and > 0 or >= 0: the one check T, A and f share.
double bounded_number(const toml::node& node, lower_bound bound, const std::string& source, const std::string& path) {
    const double x = number_at(node, source, path);
    const bool positive = bound == lower_bound::positive;
    const bool ok = std::isfinite(x) && (positive ? x > 0.0 : x >= 0.0);
    if (!ok) {
        fail(source,
             quoted(path) + " must be finite and " + (positive ? "> 0" : ">= 0") + " (got " + shortest(x) + ")");
    }
    return x;
}

const std::string& string_at(const toml::node& node, const std::string& source, const std::string& path) {
    if (!node.is_string()) wrong_type(node, "a string", source, path);
    return node.as_string()->get();
}

namespace {

// The text of the literal that starts at `where` (toml++ counts columns in code points).
std::string_view literal_at(std::string_view text, const toml::source_position& where) {
    for (toml::source_index line = 1; line < where.line; ++line) {
        const std::size_t end = text.find('\n');
        if (end == std::string_view::npos) return {};
        text.remove_prefix(end + 1);
    }
    std::size_t at = 0;
    for (toml::source_index column = 1; column < where.column && at < text.size(); ++at)
        if ((static_cast<unsigned char>(text[at]) & 0xC0) != 0x80) ++column;  // not a continuation byte
    while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
    text.remove_prefix(std::min(at, text.size()));
    std::size_t length = 0;
    const auto literal_char = [](char c) {
        return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '.' || c == '_' ||
               c == '+' || c == '-';
    };
    while (length < text.size() && literal_char(text[length])) ++length;
    return text.substr(0, length);
}

// The underflow rule of text.hpp for every floating-point value of the document: toml++
// reads 1e-400 as 0 and 1e-310 as a subnormal without a word, so the literal's own text,
// found at the node's source position, tells a written 0 from an underflow.
void check_underflow(const toml::node& node, std::string_view text, const std::string& source,
                     const std::string& path) {
    if (const toml::table* table = node.as_table()) {
        for (const auto& [key, child] : *table) check_underflow(child, text, source, join(path, echo(key.str())));
    } else if (const toml::array* array = node.as_array()) {
        for (std::size_t i = 0; i < array->size(); ++i)
            check_underflow(*array->get(i), text, source, path + "[" + std::to_string(i) + "]");
    } else if (const auto* floating = node.as_floating_point()) {
        const double x = floating->get();
        if (!(std::fabs(x) < DBL_MIN)) return;
        const toml::source_position where = node.source().begin;
        const std::string problem = underflow_problem(literal_at(text, where), x);
        if (!problem.empty())
            fail(source + ":" + std::to_string(where.line) + ":" + std::to_string(where.column),
                 quoted(path) + " = " + problem);
    }
}

}  // namespace

// A syntax error is located like a compiler's, so editors can jump to it.
toml::table parse_toml(std::string_view text, const std::string& source) {
    toml::table root;
    try {
        root = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        const toml::source_position where = e.source().begin;
        throw input_error(one_line(source + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                                   ": malformed TOML: " + std::string(e.description())));
    }
    check_underflow(root, text, source, "");
    return root;
}

namespace {
[[noreturn]] void cannot_read(const std::string& what, const std::string& path, const std::string& reason) {
    throw input_error(one_line("cannot read " + what + " '" + path + "': " + reason));
}
}  // namespace

std::string read_text(const std::string& path, const std::string& what) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error) cannot_read(what, path, error.message());
    // Checked before opening: a directory opens on Linux and then reads as empty.
    if (fs::is_directory(status)) cannot_read(what, path, "it is a directory");
    if (!fs::is_regular_file(status)) cannot_read(what, path, "it is not a regular file");
    // Input files are kilobytes; a huge "regular" file (/proc/kcore) would exhaust memory.
    constexpr std::uintmax_t max_bytes = 64u << 20;
    const std::uintmax_t bytes = fs::file_size(path, error);
    if (!error && bytes > max_bytes) cannot_read(what, path, "larger than 64 MiB");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) cannot_read(what, path, errno != 0 ? std::strerror(errno) : "cannot open it");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace roughroll::toml_input
