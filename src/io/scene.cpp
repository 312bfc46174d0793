// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/scene.hpp"
#include "roughroll/base/text.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <cmath>
#include <cstdint>

#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/layer/roughness_parameters.hpp"
#include "micro_geometry_table.hpp"
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
        return "must satisfy |Q| <= f, but |Q| = " + shortest(std::fabs(Q)) + " exceeds f = " + shortest(f) +
               ": the cylinders slide";
    }
    return {};
}

// Why a load given as Q/f = q cannot be solved for, or "" when it can; the text follows the name
// of Q/f. Q = q f with |q| <= 1 rounds to |Q| <= f (rounding is monotone), so |q| <= 1 is the
// whole condition.
std::string ratio_problem(double q) {
    if (!std::isfinite(q)) return "must be finite (got " + shortest(q) + ")";
    if (!(std::fabs(q) <= 1.0))
        return "must lie in [-1, 1], but |Q/f| = " + shortest(std::fabs(q)) + " exceeds 1: the cylinders slide";
    return {};
}

// Why a load P1 (N/m) of physical scene p cannot be solved for with friction f, or "" when it can;
// the text follows the name of P1.
std::string tangential_load_problem(double P1, double f, const physical_scene& p) {
    if (p.width == width_rule::hertz)
        return "needs contact_width = \"given-load\": at the Hertz width the model carries P2/lambda, not P2; give "
               "Q = P1/P2 instead";
    if (!std::isfinite(P1)) return "must be finite (got " + shortest(P1) + ")";
    if (!(std::fabs(P1) <= f * p.P2))
        return "must satisfy |P1| <= f P2, but |P1| = " + shortest(std::fabs(P1)) +
               " N/m exceeds f P2 = " + shortest(f * p.P2) + " N/m: the cylinders slide";
    return {};
}

// Q = P1/P2 of a load P1 checked by tangential_load_problem: |P1| <= f P2, but the quotient may
// still round above f by an ulp.
double load_ratio_of(double P1, double f, const physical_scene& p) { return std::clamp(P1 / p.P2, -f, f); }

// Why a friction coefficient cannot be solved with, or "" when it can; the text follows its name.
std::string friction_problem(double f) {
    if (f >= min_friction && f <= max_friction) return {};
    return shortest(f) + " is outside [" + shortest(min_friction) + ", " + shortest(max_friction) +
           "], the range the solver is validated on (validation/test_stiff.cpp); xi/f depends on Q/f alone, so "
           "solve with f and Q scaled into it";
}

// The range is checked on the 64-bit TOML integer, before it is narrowed to int.
int nodes_at(const toml::node& node, const std::string& source, const std::string& path) {
    if (!node.is_integer()) wrong_type(node, "an integer", source, path);
    const std::int64_t n = node.as_integer()->get();
    if (n < min_nodes || n > max_nodes) {
        fail(source, quoted(path) + " = " + std::to_string(n) + " is outside [" + std::to_string(min_nodes) + ", " +
                         std::to_string(max_nodes) + "]");
    }
    return static_cast<int>(n);
}

method method_at(const toml::node& node, const std::string& source, const std::string& path) {
    const std::string& name = string_at(node, source, path);
    try {
        return method_from_string(echo(name));  // a long name is unknown anyway: shown cut
    } catch (const input_error& e) {
        // method_from_string knows the names but not where the name was written.
        fail(source, quoted(path) + ": " + e.what());
    }
}

// Dimensionless T, A of (3.26), or for a physical scene also the stiffness k, t of (2.10).
struct term_input {
    roughness_term dimensionless;
    std::optional<stiffness> dimensional;
};

// One direction of one cylinder; an absent table is a smooth surface (T = 0).
term_input read_term(const toml::table& cylinder, std::string_view key, bool physical, const std::string& source,
                     const std::string& cylinder_path) {
    const std::string path = join(cylinder_path, key);
    const toml::table* table = table_at(cylinder, key, source, path);
    if (table == nullptr) return {};
    const bool by_stiffness = table->contains("k") || table->contains("t");
    if (by_stiffness && !physical) {
        fail(source, "table " + quoted(path) +
                         ": k and t (Pa/m, Pa m) need a physical scene (E, nu, R1, R2, P2); give T and A otherwise");
    }
    if (physical)
        check_keys(*table, by_stiffness ? key_list{"k", "t"} : key_list{"T", "A", "k", "t"}, source, path);
    else
        check_keys(*table, {"T", "A"}, source, path);
    // T alone or A alone is a half-written term; a default for the other would hide that.
    const auto names = by_stiffness ? std::array<const char*, 2>{"k", "t"} : std::array<const char*, 2>{"T", "A"};
    for (const char* name : names) {
        if (!table->contains(name)) {
            fail(source, "table " + quoted(path) + " needs both " + names[0] + " and " + names[1] + " (missing '" +
                             name + "')");
        }
    }
    term_input term;
    if (by_stiffness) {
        stiffness st;
        st.k = bounded_number(*table->get("k"), lower_bound::non_negative, source, join(path, "k"));
        const double t = number_at(*table->get("t"), source, join(path, "t"));
        if (!(std::isfinite(t) && t > 0.0)) {
            fail(source, quoted(join(path, "t")) + " must be finite and > 0 (got " + shortest(t) +
                             "); the one-parameter model of [2], t -> 0, is method 'one-parameter', whose "
                             "results do not depend on t");
        }
        st.t = t;
        term.dimensional = st;
        return term;
    }
    term.dimensionless.T = bounded_number(*table->get("T"), lower_bound::non_negative, source, join(path, "T"));
    term.dimensionless.A = bounded_number(*table->get("A"), lower_bound::non_negative, source, join(path, "A"));
    return term;
}

struct cylinder_input {
    term_input tangential, normal;
    std::string profile_file;      // the profile CSV its micro-geometry read, if any
    std::optional<material> bulk;  // shear_modulus and poisson of a physical scene's cylinder
};

// A Poisson's ratio: (3.27), (3.26) and C of docs/formulation.md 8(a) divide by 1 - nu, and an
// isotropic solid has -1 < nu <= 1/2.
double poisson_at(const toml::node& node, const std::string& source, const std::string& path) {
    const double nu = number_at(node, source, path);
    if (!(nu > -1.0 && nu <= 0.5)) fail(source, quoted(path) + " must be in (-1, 0.5] (got " + shortest(nu) + ")");
    return nu;
}

// The bulk material of one cylinder of a physical scene (8(a)): both keys or neither.
std::optional<material> read_material(const toml::table& table, const std::string& path, const std::string& source) {
    const bool has_mu = table.contains("shear_modulus"), has_nu = table.contains("poisson");
    if (!has_mu && !has_nu) return std::nullopt;
    if (!(has_mu && has_nu))
        fail(source, "table " + quoted(path) + " needs both shear_modulus and poisson (missing '" +
                         (has_mu ? "poisson" : "shear_modulus") + "')");
    material m;
    m.mu = bounded_number(*table.get("shear_modulus"), lower_bound::positive, source, join(path, "shear_modulus"));
    m.nu = poisson_at(*table.get("poisson"), source, join(path, "poisson"));
    return m;
}

// A cylinder's terms, or for a physical scene its micro-geometry: the layer of Sec. 2, whose
// k, t of (2.11)-(2.14) replace both terms (roughness_parameters.hpp).
cylinder_input read_cylinder(const toml::table& root, std::string_view key, bool physical,
                             const std::filesystem::path& base_dir, const std::string& source) {
    const std::string path(key);
    const toml::table* table = table_at(root, key, source, path);
    if (table == nullptr) return {};
    if (!physical) {
        if (table->contains("micro_geometry"))
            fail(source, "table " + quoted(join(path, "micro_geometry")) +
                             " needs a physical scene (E, nu, R1, R2, P2): k and t are in SI units");
        for (const char* key : {"shear_modulus", "poisson"})
            if (table->contains(key))
                fail(source, quoted(join(path, key)) +
                                 " needs a physical scene (R1, R2, P2); a dimensionless scene gives beta_d instead");
        check_keys(*table, {"tangential", "normal"}, source, path);
    } else {
        check_keys(*table, {"tangential", "normal", "micro_geometry", "shear_modulus", "poisson"}, source, path);
    }
    const std::optional<material> bulk = physical ? read_material(*table, path, source) : std::nullopt;
    const std::string layer_path = join(path, "micro_geometry");
    if (const toml::table* layer = table_at(*table, "micro_geometry", source, layer_path)) {
        if (table->contains("tangential") || table->contains("normal"))
            fail(source, "table " + quoted(layer_path) + " gives both directions of " + quoted(path) +
                             ": leave out its 'tangential' and 'normal' tables");
        const micro_geometry g = read_micro_geometry(*layer, source, layer_path, base_dir);
        const roughness_parameters r = compute_roughness_parameters(g);
        cylinder_input c;
        c.tangential.dimensional = stiffness{r.k_tangential, r.t_tangential};
        c.normal.dimensional = stiffness{r.k_normal, r.t_normal};
        if (g.bottom.kind == profile_kind::measured) c.profile_file = g.bottom.measured.source;
        c.bulk = bulk;
        return c;
    }
    return {read_term(*table, "tangential", physical, source, path),
            read_term(*table, "normal", physical, source, path),
            {},
            bulk};
}

// A radius of a physical scene: > 0, and infinite for a plane.
double radius_at(const toml::node& node, const std::string& source, const std::string& path) {
    const double R = number_at(node, source, path);
    if (!(R > 0.0)) fail(source, quoted(path) + " must be > 0 (got " + shortest(R) + "; inf is a plane)");
    return R;
}

bool is_physical(const toml::table& root) {
    for (const std::string_view key : {"E", "nu", "R1", "R2", "P2", "P1", "contact_width"})
        if (root.contains(key)) return true;
    return false;
}

// The materials, radii and loads of a physical scene (physical_scene.hpp); the surfaces
// are filled in by the caller. `c1`, `c2`: the cylinders' own materials, if given (8(a)).
physical_scene read_physical(const toml::table& root, double friction, const std::string& source,
                             const std::optional<material>& c1, const std::optional<material>& c2) {
    physical_scene p;
    if (c1 || c2) {
        // A material per cylinder: both, and not also the one material E, nu.
        if (!(c1 && c2))
            fail(source, std::string("a material per cylinder needs shear_modulus and poisson in both [cylinder1] and "
                                     "[cylinder2]: missing in ") +
                             (c1 ? "'cylinder2'" : "'cylinder1'"));
        for (const char* key : {"E", "nu"})
            if (root.contains(key))
                fail(source, std::string("give one material (E, nu) or one per cylinder (shear_modulus, poisson), not "
                                         "both: remove '") +
                                 key + "'");
        for (const char* key : {"R1", "R2", "P2"})
            if (!root.contains(key))
                fail(source, std::string("a physical scene needs R1, R2 and P2: missing '") + key + "'");
        p.materials = std::array<material, 2>{*c1, *c2};
    } else {
        for (const char* key : {"E", "nu", "R1", "R2", "P2"}) {
            if (!root.contains(key))
                fail(source, std::string("a physical scene needs E, nu, R1, R2 and P2: missing '") + key + "'");
        }
        p.E = bounded_number(*root.get("E"), lower_bound::positive, source, "E");
        // (3.27) and (3.26) divide by 1 - nu and mu = E/(2(1 + nu)): -1 < nu <= 1/2 for an isotropic solid.
        p.nu = poisson_at(*root.get("nu"), source, "nu");
    }
    p.R1 = radius_at(*root.get("R1"), source, "R1");
    p.R2 = radius_at(*root.get("R2"), source, "R2");
    if (std::isinf(p.R1) && std::isinf(p.R2)) fail(source, "'R1' and 'R2' are both infinite: two planes do not roll");
    p.P2 = bounded_number(*root.get("P2"), lower_bound::positive, source, "P2");
    if (const toml::node* width = root.get("contact_width")) {
        const std::string& rule = string_at(*width, source, "contact_width");
        if (rule == "given-load")
            p.width = width_rule::given_load;
        else if (rule == "hertz")
            p.width = width_rule::hertz;
        else
            fail(source, "'contact_width' must be \"given-load\" or \"hertz\" (got \"" + echo(rule) + "\")");
    }
    if (const toml::node* load = root.get("P1")) {
        const double P1 = number_at(*load, source, "P1");
        const std::string problem = tangential_load_problem(P1, friction, p);
        if (!problem.empty()) fail(source, "'P1' " + problem);
        p.P1 = P1;
    }
    return p;
}

surface_stiffness stiffness_at_hertz(const physical_scene& p, const cylinder_input& c, const std::string& name) {
    // T, A in a physical scene are the paper's, at a = a_H(P2).
    const double a_H = hertz_half_width(p, p.P2);
    const auto one = [&](const term_input& t, const char* direction) {
        return t.dimensional ? *t.dimensional : stiffness_of(p, t.dimensionless, a_H, name + "." + direction);
    };
    return {one(c.tangential, "tangential"), one(c.normal, "normal")};
}

cylinder_roughness dimensionless(const cylinder_input& c) {
    return {c.tangential.dimensionless, c.normal.dimensionless};
}

solver_options read_solver(const toml::table& root, const std::string& source) {
    solver_options options;
    const toml::table* table = table_at(root, "solver", source, "solver");
    if (table == nullptr) return options;
    check_keys(*table, {"n", "method", "zones", "tolerance"}, source, "solver");
    if (const toml::node* n = table->get("n")) options.n = nodes_at(*n, source, "solver.n");
    if (const toml::node* how = table->get("method")) options.how = method_at(*how, source, "solver.method");
    if (const toml::node* zones = table->get("zones")) {
        try {
            options.zones = zone_search_from_string(string_at(*zones, source, "solver.zones"));
        } catch (const input_error& e) {
            fail(source, quoted("solver.zones") + ": " + e.what());
        }
    }
    if (const toml::node* tolerance = table->get("tolerance")) {
        if (table->contains("n"))
            fail(source, quoted("solver.n") + " and " + quoted("solver.tolerance") +
                             ": give one (n fixes the nodes; the tolerance lets the ladder choose n)");
        const double tol = number_at(*tolerance, source, "solver.tolerance");
        try {
            check_tolerance(tol, quoted("solver.tolerance"));
        } catch (const input_error& e) {
            fail(source, e.what());
        }
        options.tolerance = tol;
    }
    return options;
}

}  // namespace

scene parse_scene(std::string_view text, const std::string& source, const std::filesystem::path& base_dir) {
    const toml::table root = parse_toml(text, source);
    check_keys(root,
               {"label", "friction", "Q", "Q_over_f", "cylinder1", "cylinder2", "solver", "E", "nu", "R1", "R2", "P2",
                "P1", "contact_width", "beta_d", "coupling"},
               source, "");

    scene s;
    if (const toml::node* label = root.get("label")) s.label = string_at(*label, source, "label");

    const toml::node* friction = root.get("friction");
    if (friction == nullptr) fail(source, "missing key 'friction'");
    s.friction = bounded_number(*friction, lower_bound::positive, source, "friction");
    const std::string range = friction_problem(s.friction);
    if (!range.empty()) fail(source, "'friction' = " + range);

    // The load once: as Q, as Q/f or (a physical scene) as P1.
    std::vector<std::string> loads;
    for (const char* key : {"Q", "Q_over_f", "P1"})
        if (root.contains(key)) loads.push_back(quoted(key));
    if (loads.size() > 1)
        fail(source,
             "give " + loads[0] + " or " + loads[1] + ", not both: the load is given once, as Q, Q_over_f or P1");
    if (const toml::node* load = root.get("Q")) {
        const double Q = number_at(*load, source, "Q");
        const std::string problem = load_problem(Q, s.friction);
        if (!problem.empty()) fail(source, "'Q' " + problem);
        s.Q = Q;
    }
    if (const toml::node* load = root.get("Q_over_f")) {
        const double q = number_at(*load, source, "Q_over_f");
        const std::string problem = ratio_problem(q);
        if (!problem.empty()) fail(source, "'Q_over_f' " + problem);
        s.Q_over_f = q;
        s.Q = q * s.friction;
    }

    const bool physical = is_physical(root);
    const cylinder_input c1 = read_cylinder(root, "cylinder1", physical, base_dir, source);
    const cylinder_input c2 = read_cylinder(root, "cylinder2", physical, base_dir, source);
    for (const cylinder_input* c : {&c1, &c2})
        if (!c->profile_file.empty()) s.files.push_back(c->profile_file);
    if (physical) {
        if (root.contains("beta_d"))
            fail(source,
                 "'beta_d' is not a key of a physical scene: it follows from the materials (shear_modulus and "
                 "poisson per cylinder; docs/formulation.md 8(a))");
        physical_scene p = read_physical(root, s.friction, source, c1.bulk, c2.bulk);
        try {
            // Each derived value is checked where it is made (physical_scene.cpp): a_H and its
            // scales, k and t from T and A, T and A at a_H; the message names the keys.
            p.cylinder1 = stiffness_at_hertz(p, c1, "cylinder1");
            p.cylinder2 = stiffness_at_hertz(p, c2, "cylinder2");
            s.surfaces = roughness_at(p, hertz_half_width(p, p.P2));  // until the width is known
        } catch (const input_error& e) {
            fail(source, e.what());
        }
        if (p.P1) s.Q = load_ratio_of(*p.P1, s.friction, p);
        try {
            s.materials.beta_d = dundurs_beta(p);
        } catch (const input_error& e) {
            fail(source, e.what());
        }
        s.physical = p;
    } else {
        s.surfaces = {dimensionless(c1), dimensionless(c2)};
        if (const toml::node* beta = root.get("beta_d")) {
            const double b = number_at(*beta, source, "beta_d");
            try {
                check_beta_d(b);
            } catch (const input_error& e) {
                fail(source, e.what());
            }
            s.materials.beta_d = b;
        }
    }
    if (const toml::node* coupling = root.get("coupling")) {
        const std::string& name = string_at(*coupling, source, "coupling");
        try {
            s.materials.coupling = coupling_from_string(name);
        } catch (const input_error& e) {
            fail(source, quoted("coupling") + ": " + e.what());
        }
    }
    s.solver = read_solver(root, source);
    return s;
}

scene read_scene(const std::string& path) {
    // A profile_csv named in the scene is relative to the scene's folder.
    scene s = parse_scene(read_text(path, "scene file"), path, std::filesystem::path(path).parent_path());
    s.files.insert(s.files.begin(), path);
    return s;
}

double load_of(const scene& s, const std::optional<load_given>& override) {
    // The command line wins, so one scene file can be solved for several loads.
    const double f = s.friction;
    if (!override) {
        if (!s.Q) throw input_error("no load Q given: set Q (or Q_over_f) in the scene or pass --Q (or --Q-over-f)");
        const std::string problem = load_problem(*s.Q, f);
        if (!problem.empty()) throw input_error("Q " + problem);
        return *s.Q;
    }
    const double x = override->value;
    switch (override->kind) {
        case load_kind::Q: break;
        case load_kind::Q_over_f: {
            const std::string problem = ratio_problem(x);
            if (!problem.empty()) throw input_error("Q_over_f " + problem);
            return x * f;
        }
        case load_kind::P1: {
            if (!s.physical)
                throw input_error(
                    "P1 (N/m) needs a physical scene (E, nu, R1, R2, P2): give the load as Q or Q_over_f");
            const std::string problem = tangential_load_problem(x, f, *s.physical);
            if (!problem.empty()) throw input_error("P1 " + problem);
            return load_ratio_of(x, f, *s.physical);
        }
    }
    const std::string problem = load_problem(x, f);
    if (!problem.empty()) throw input_error("Q " + problem);
    return x;
}

void override_friction(scene& s, std::optional<double> friction, const std::string& name) {
    if (!friction) return;
    const std::string range = friction_problem(*friction);
    if (!range.empty()) throw input_error(name + " " + range);
    s.friction = *friction;
    if (s.Q_over_f) s.Q = *s.Q_over_f * s.friction;  // the scene's ratio kept (scene.hpp)
}

}  // namespace roughroll
