#include "roughroll/scene.hpp"
#include "roughroll/text.hpp"

#include <cmath>
#include <cstdint>

#include "roughroll/error.hpp"
#include "roughroll/quadrature.hpp"
#include "toml_input.hpp"

namespace roughroll {
namespace {

using namespace toml_input;

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

scene read_scene(const std::string& path) { return parse_scene(read_text(path, "scene file"), path); }

double load_of(const scene& s, std::optional<double> override) {
    // The command line wins, so one scene file can be solved for several loads.
    const std::optional<double> Q = override ? override : s.Q;
    if (!Q) throw input_error("no load Q given: set Q in the scene or pass --Q");
    const std::string problem = load_problem(*Q, s.friction);
    if (!problem.empty()) throw input_error("Q " + problem);
    return *Q;
}

}  // namespace roughroll
