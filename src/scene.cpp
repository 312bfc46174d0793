#include "roughroll/scene.hpp"
#include "roughroll/text.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include <toml++/toml.h>

#include "roughroll/error.hpp"
#include "roughroll/quadrature.hpp"

namespace roughroll {
namespace {

using key_list = std::initializer_list<std::string_view>;

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

std::string quoted(const std::string& path) { return "'" + path + "'"; }

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

[[noreturn]] void wrong_type(const toml::node& node, const char* expected, const std::string& source,
                             const std::string& path) {
    fail(source, quoted(path) + " must be " + expected + ", not " + type_phrase(node));
}

// A misspelt key would otherwise be ignored silently and the scene solved with a
// default in its place; so every key must be one of `allowed`. A toml::table
// iterates in key order, so the key reported does not depend on the file's layout.
void check_keys(const toml::table& table, key_list allowed, const std::string& source,
                const std::string& path) {
    for (const auto& [key, node] : table) {
        if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
        std::string names;
        for (const std::string_view name : allowed) names += (names.empty() ? "" : ", ") + std::string(name);
        const char* kind = node.is_table() ? "unknown table " : "unknown key ";
        fail(source, kind + quoted(join(path, key.str())) + " (allowed here: " + names + ")");
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

enum class lower_bound { positive, non_negative };

// A number that is finite and > 0 or >= 0: the one check T, A and f share.
double bounded_number(const toml::node& node, lower_bound bound, const std::string& source,
                      const std::string& path) {
    const double x = number_at(node, source, path);
    const bool positive = bound == lower_bound::positive;
    const bool ok = std::isfinite(x) && (positive ? x > 0.0 : x >= 0.0);
    if (!ok) {
        fail(source, quoted(path) + " must be finite and " + (positive ? "> 0" : ">= 0") + " (got " +
                         shortest(x) + ")");
    }
    return x;
}

const std::string& string_at(const toml::node& node, const std::string& source, const std::string& path) {
    if (!node.is_string()) wrong_type(node, "a string", source, path);
    return node.as_string()->get();
}

// Why a load Q cannot be solved for with friction f, or "" when it can. The text
// follows the name of Q. |Q| > f exceeds the limiting friction: the cylinders
// slide and the rolling-contact model does not apply. Written as !(|Q| <= f) so
// that a NaN f (a scene built by hand) is refused too.
std::string load_problem(double Q, double f) {
    if (!std::isfinite(Q)) return "must be finite (got " + shortest(Q) + ")";
    if (!(std::fabs(Q) <= f)) {
        return "must satisfy |Q| <= f, but |Q| = " + shortest(std::fabs(Q)) + " exceeds f = " +
               shortest(f) + ": the cylinders slide";
    }
    return {};
}

// The range is checked on the 64-bit TOML integer, before it is narrowed to int.
int nodes_at(const toml::node& node, const std::string& source, const std::string& path) {
    if (!node.is_integer()) wrong_type(node, "an integer", source, path);
    const std::int64_t n = node.as_integer()->get();
    if (n < min_nodes || n > max_nodes) {
        fail(source, quoted(path) + " = " + std::to_string(n) + " is outside [" + std::to_string(min_nodes) +
                         ", " + std::to_string(max_nodes) + "]");
    }
    return static_cast<int>(n);
}

method method_at(const toml::node& node, const std::string& source, const std::string& path) {
    const std::string& name = string_at(node, source, path);
    try {
        return method_from_string(name);
    } catch (const input_error& e) {
        // method_from_string knows the names but not where the name was written.
        fail(source, quoted(path) + ": " + e.what());
    }
}

// One direction of one cylinder; an absent table is a smooth surface (T = 0).
roughness_term read_term(const toml::table& cylinder, std::string_view key, const std::string& source,
                         const std::string& cylinder_path) {
    const std::string path = join(cylinder_path, key);
    const toml::table* table = table_at(cylinder, key, source, path);
    if (table == nullptr) return {};
    check_keys(*table, {"T", "A"}, source, path);
    // T alone or A alone is a half-written term; a default for the other would hide that.
    for (const char* name : {"T", "A"}) {
        if (!table->contains(name)) {
            fail(source, "table " + quoted(path) + " needs both T and A (missing '" + name + "')");
        }
    }
    roughness_term term;
    term.T = bounded_number(*table->get("T"), lower_bound::non_negative, source, join(path, "T"));
    term.A = bounded_number(*table->get("A"), lower_bound::non_negative, source, join(path, "A"));
    return term;
}

cylinder_roughness read_cylinder(const toml::table& root, std::string_view key, const std::string& source) {
    const std::string path(key);
    const toml::table* table = table_at(root, key, source, path);
    if (table == nullptr) return {};
    check_keys(*table, {"tangential", "normal"}, source, path);
    cylinder_roughness cylinder;
    cylinder.tangential = read_term(*table, "tangential", source, path);
    cylinder.normal = read_term(*table, "normal", source, path);
    return cylinder;
}

solver_options read_solver(const toml::table& root, const std::string& source) {
    solver_options options;
    const toml::table* table = table_at(root, "solver", source, "solver");
    if (table == nullptr) return options;
    check_keys(*table, {"n", "method"}, source, "solver");
    if (const toml::node* n = table->get("n")) options.n = nodes_at(*n, source, "solver.n");
    if (const toml::node* how = table->get("method")) options.how = method_at(*how, source, "solver.method");
    return options;
}

// A syntax error is located like a compiler's, so editors can jump to it.
toml::table parse_toml(std::string_view text, const std::string& source) {
    try {
        return toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        const toml::source_position where = e.source().begin;
        throw input_error(one_line(source + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                                   ": malformed TOML: " + std::string(e.description())));
    }
}

[[noreturn]] void cannot_read(const std::string& path, const std::string& reason) {
    throw input_error(one_line("cannot read scene file '" + path + "': " + reason));
}

std::string read_text(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error) cannot_read(path, error.message());
    // Checked before opening: a directory opens on Linux and then reads as empty.
    if (fs::is_directory(status)) cannot_read(path, "it is a directory");
    if (!fs::is_regular_file(status)) cannot_read(path, "it is not a regular file");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) cannot_read(path, errno != 0 ? std::strerror(errno) : "cannot open it");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

scene parse_scene(std::string_view text, const std::string& source) {
    const toml::table root = parse_toml(text, source);
    check_keys(root, {"label", "friction", "Q", "cylinder1", "cylinder2", "solver"}, source, "");

    scene s;
    if (const toml::node* label = root.get("label")) s.label = string_at(*label, source, "label");

    const toml::node* friction = root.get("friction");
    if (friction == nullptr) fail(source, "missing key 'friction'");
    s.friction = bounded_number(*friction, lower_bound::positive, source, "friction");

    if (const toml::node* load = root.get("Q")) {
        const double Q = number_at(*load, source, "Q");
        const std::string problem = load_problem(Q, s.friction);
        if (!problem.empty()) fail(source, "'Q' " + problem);
        s.Q = Q;
    }

    s.surfaces.cylinder1 = read_cylinder(root, "cylinder1", source);
    s.surfaces.cylinder2 = read_cylinder(root, "cylinder2", source);
    s.solver = read_solver(root, source);
    return s;
}

scene read_scene(const std::string& path) { return parse_scene(read_text(path), path); }

double load_of(const scene& s, std::optional<double> override) {
    // The command line wins, so one scene file can be solved for several loads.
    const std::optional<double> Q = override ? override : s.Q;
    if (!Q) throw input_error("no load Q given: set Q in the scene or pass --Q");
    const std::string problem = load_problem(*Q, s.friction);
    if (!problem.empty()) throw input_error("Q " + problem);
    return *Q;
}

}  // namespace roughroll
