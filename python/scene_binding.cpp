// SPDX-License-Identifier: GPL-3.0-or-later
// Scenes, points, creep curves and tractions for Python: the same library calls as the
// command line's `point`, `curve` and `traction` (src/cli), so the same numbers.
//   point:    solve_point (io/scene_point.hpp): the width of a physical scene (formulation 2(j)),
//             the normal problem (3.19)-(3.20), c0 for the load by Brent on Q(c0) of (4.5),
//             the tangential problem (3.21)-(3.22), its error estimate; to_json (io/output.hpp).
//   curve:    creep_curve at given loads, or swept_curve in c0 (contact.hpp), with Carter's
//             curve and for a physical scene xi1 of to_si (physical_scene.hpp) with the estimates of
//             estimate_si (io/si_estimate.hpp), as the CSV's.
//   traction: p(r) of (4.1), p1(r) of (3.15) and the slip velocity v(r) of (3.6) on a grid.
// Every solve runs with the GIL released; nothing here touches a Python object meanwhile.
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/io/si_estimate.hpp"
#include "roughroll/io/traction_table.hpp"
#include "roughroll/problems/zone_layout.hpp"
#include "roughroll/problems/creep_curve.hpp"

namespace py = pybind11;

namespace roughroll::python {

namespace {

py::array_t<double> array_of(const std::vector<double>& v) {
    py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

py::array_t<bool> bool_array_of(const std::vector<char>& v) {
    py::array_t<bool> a(static_cast<py::ssize_t>(v.size()));
    bool* out = a.mutable_data();
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i] != 0;
    return a;
}

py::object term_dict(const roughness_term& t) {
    if (!t.present()) return py::none();
    py::dict d;
    d["T"] = t.T;
    d["A"] = t.A;
    return std::move(d);
}

py::dict roughness_dict(const roughness& r) {
    const auto cylinder = [](const cylinder_roughness& c) {
        py::dict d;
        d["tangential"] = term_dict(c.tangential);
        d["normal"] = term_dict(c.normal);
        return d;
    };
    py::dict d;
    d["cylinder1"] = cylinder(r.cylinder1);
    d["cylinder2"] = cylinder(r.cylinder2);
    return d;
}

py::object physical_dict(const scene& s) {
    if (!s.physical) return py::none();
    const physical_scene& p = *s.physical;
    const auto stiff = [](const surface_stiffness& c) {
        const auto one = [](const stiffness& st) -> py::object {
            if (!st.present()) return py::none();
            py::dict d;
            d["k"] = st.k;
            d["t"] = st.t;
            return std::move(d);
        };
        py::dict d;
        d["tangential"] = one(c.tangential);
        d["normal"] = one(c.normal);
        return d;
    };
    py::dict d;
    // One material (E, nu), or one per cylinder (docs/formulation.md 8(a)): the other form is None.
    d["E"] = p.materials ? py::object(py::none()) : py::object(py::float_(p.E));
    d["nu"] = p.materials ? py::object(py::none()) : py::object(py::float_(p.nu));
    if (p.materials) {
        for (int i = 0; i < 2; ++i) {
            py::dict m;
            m["shear_modulus"] = (*p.materials)[i].mu;
            m["poisson"] = (*p.materials)[i].nu;
            d[i == 0 ? "material1" : "material2"] = m;
        }
    }
    d["compliance"] = compliance(p);
    d["beta_d"] = dundurs_beta(p);
    d["R1"] = p.R1;
    d["R2"] = p.R2;
    d["P2"] = p.P2;
    d["P1"] = p.P1 ? py::object(py::float_(*p.P1)) : py::object(py::none());
    d["contact_width"] = p.width == width_rule::hertz ? "hertz" : "given-load";
    d["a_hertz_m"] = hertz_half_width(p, p.P2);
    d["cylinder1"] = stiff(p.cylinder1);
    d["cylinder2"] = stiff(p.cylinder2);
    return std::move(d);
}

scene overridden(scene s, const solver_keywords& k) {
    override_solver(s, k.n, k.method, k.zones, k.tolerance);
    override_friction(s, k.friction, "friction");
    return s;
}

// The columns of `roughroll curve`'s CSV (output.hpp, write_curve_csv), as arrays; an absent
// estimate is NaN (an empty CSV field), and so is every computed number of a refused row
// (curve_point, contact.hpp), whose zones are 0 (an int array has no NaN) and whose line, the
// program's stderr line, is in `refused`.
struct curve_columns {
    std::vector<double> Q, Q_over_f, c0, xi, xi_over_f, xi_carter, c0_carter;
    std::vector<char> checks_hold;
    std::vector<double> c0_error, xi_error, Q_error;
    std::vector<int> zones;                   // the number of stick and slip zones (formulation section 7)
    std::vector<double> stick_start;          // the start of the stick zone, -1 in the paper's structure
    std::vector<double> stick_start_error;    // its estimate (the CSV's stick_start_error_estimate)
    std::vector<std::string> zone_path;       // single, general or no-slip (the layout's route); "" when refused
    std::vector<double> P1, xi1, xi1_carter;  // physical scenes only
    std::vector<double> P1_error, xi1_error;  // their estimates (estimate_si, io/si_estimate.hpp; NaN: none)
    std::vector<int> n;                       // each row's n (the ladder's rung; 0 for a refused row)
    std::vector<std::string> status;          // "ok" or "refused"
    std::vector<std::string> refused;         // one line per refused row
    bool physical = false;
};

curve_columns solve_curve(scene s, const std::optional<std::vector<double>>& loads, int points, bool sweep) {
    // Ctrl-C between rows and between the levels of a row.
    const scene_curve c = curve_of(std::move(s), loads, points, sweep, check_signals, check_signals);
    curve_columns out;
    out.physical = c.settled.physical.has_value();
    const double nan = std::nan("");
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        const curve_point& row = c.rows[i];
        const std::optional<contact_width> width =
            out.physical ? std::optional<contact_width>(c.widths[i]) : std::nullopt;
        const tangential_solution& t = row.solution;
        out.Q.push_back(t.Q);
        out.Q_over_f.push_back(t.Q / t.f);
        out.c0.push_back(t.c0());
        out.xi.push_back(t.xi);
        out.xi_over_f.push_back(t.xi / t.f);
        out.xi_carter.push_back(row.smooth.xi);
        out.c0_carter.push_back(row.smooth.c0);
        out.checks_hold.push_back(t.checks.hold() ? 1 : 0);
        out.c0_error.push_back(row.estimate ? row.estimate->c0 : nan);
        out.xi_error.push_back(row.estimate ? row.estimate->xi : nan);
        out.Q_error.push_back(row.estimate ? row.estimate->Q : nan);
        out.zones.push_back(
            row.is_refused() ? 0 : static_cast<int>(t.layout.zones.size()));  // five for two stick zones, as the CSV
        out.stick_start.push_back(t.start());
        out.stick_start_error.push_back(row.estimate ? row.estimate->start : nan);
        out.zone_path.push_back(row.is_refused() ? "" : to_string(t.layout.route));
        out.status.push_back(row.is_refused() ? "refused" : "ok");
        out.n.push_back(c.nodes[i]);
        if (row.is_refused()) out.refused.push_back(row.refused);
        if (width) {
            // As write_curve_csv, by its rule (si_curve_row): NaN where the CSV's cell is empty.
            const si_curve_cells si = si_curve_row(*c.settled.physical, *width, row);
            out.P1.push_back(si.P1);
            out.xi1.push_back(si.xi1);
            out.xi1_carter.push_back(si.xi1_carter);
            out.P1_error.push_back(si.P1_error);
            out.xi1_error.push_back(si.xi1_error);
        }
    }
    return out;
}

// The columns of `roughroll traction`'s CSV (traction_table.hpp, the same rows), and the point.
struct traction_columns {
    std::string point;  // the point's JSON
    std::vector<double> r, p, p1, v, p_hertz, p1_carter;
    std::vector<char> stick;
    std::vector<double> x1_m, p2_Pa, p1_Pa;  // a physical scene's
    bool physical = false;
    double c0_level;  // the stick zone the distributions have (level n when extrapolating)
};

traction_columns solve_traction(scene s, const std::optional<load_given>& load, const std::vector<double>& grid) {
    for (const double r : grid)
        if (!(r >= -1.0 && r <= 1.0)) throw input_error("r must lie in [-1, 1] (got " + shortest(r) + ")");
    const double Q = load_of(s, load), f = s.friction;  // as the program's traction: the load asked for
    scene_point sp = solve_point(std::move(s), load, check_signals);
    const tangential_solution level = sp.solved.distribution(sp.solution);
    const point_report report = sp.report();
    traction_columns out;
    out.point = to_json(report).dump();
    out.c0_level = level.c0();
    out.physical = report.si.has_value();
    for (const traction_row& row : traction_table(sp.solved, level, grid, Q, f, report.si)) {
        out.r.push_back(row.r);
        out.p.push_back(row.p);
        out.p1.push_back(row.p1);
        out.v.push_back(row.v);
        out.stick.push_back(row.stick ? 1 : 0);
        out.p_hertz.push_back(row.p_hertz);
        out.p1_carter.push_back(row.p1_carter);
        if (out.physical) {
            out.x1_m.push_back(*row.x1_m);
            out.p2_Pa.push_back(*row.p2_Pa);
            out.p1_Pa.push_back(*row.p1_Pa);
        }
    }
    return out;
}

}  // namespace

std::optional<load_given> load_keywords(std::optional<double> Q, std::optional<double> Q_over_f,
                                        std::optional<double> P1) {
    if (int(Q.has_value()) + int(Q_over_f.has_value()) + int(P1.has_value()) > 1)
        throw input_error("give the load once, as Q, Q_over_f or P1, not several");
    if (Q) return load_given(load_kind::Q, *Q);
    if (Q_over_f) return load_given(load_kind::Q_over_f, *Q_over_f);
    if (P1) return load_given(load_kind::P1, *P1);
    return std::nullopt;
}

void check_signals() {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

std::string point_json(scene s, const std::optional<load_given>& load, const solver_keywords& k,
                       const std::function<void()>& checkpoint) {
    return to_json(solve_point(overridden(std::move(s), k), load, checkpoint).report()).dump();
}

void bind_scene(py::module_& m) {
    py::class_<scene>(m, "_Scene", "A checked scene (io/scene.hpp); use roughroll.Scene.")
        .def_static("read", &read_scene, py::arg("path"), "The scene file at path (read_scene).")
        .def_static(
            "parse",
            [](const std::string& text, const std::string& source, const std::string& base_dir) {
                return parse_scene(text, source, base_dir);
            },
            py::arg("text"), py::arg("source"), py::arg("base_dir"), "Scene TOML text (parse_scene).")
        .def_property_readonly("label", [](const scene& s) { return s.label; })
        .def_property_readonly("friction", [](const scene& s) { return s.friction; })
        .def_property_readonly("Q", [](const scene& s) { return s.Q; })
        .def_property_readonly(
            "Q_over_f",
            [](const scene& s) {
                return s.Q_over_f ? s.Q_over_f : s.Q ? std::optional<double>(*s.Q / s.friction) : std::nullopt;
            })
        .def_property_readonly("n", [](const scene& s) { return s.solver.nodes(); })
        .def_property_readonly("tolerance",  // the ladder's (level_ladder.hpp); None with an explicit n
                               [](const scene& s) {
                                   return s.solver.n != 0 ? std::optional<double>()
                                                          : s.solver.tolerance.value_or(default_tolerance);
                               })
        .def_property_readonly("method", [](const scene& s) { return to_string(s.solver.how); })
        .def_property_readonly("roughness", [](const scene& s) { return roughness_dict(s.surfaces); })
        .def_property_readonly("physical", &physical_dict)
        .def_property_readonly("beta_d", [](const scene& s) { return s.materials.beta_d; })
        .def_property_readonly("coupling", [](const scene& s) { return to_string(s.materials.coupling); })
        .def(
            "point_json",
            [](const scene& s, std::optional<double> Q, std::optional<double> Q_over_f, std::optional<double> P1,
               std::optional<int> n, std::optional<std::string> method, std::optional<std::string> zones,
               std::optional<double> friction, std::optional<double> tolerance) {
                const std::optional<load_given> load = load_keywords(Q, Q_over_f, P1);
                py::gil_scoped_release release;
                return point_json(s, load, {n, method, zones, friction, tolerance}, check_signals);
            },
            py::arg("Q"), py::arg("Q_over_f"), py::arg("P1"), py::arg("n"), py::arg("method"), py::arg("zones"),
            py::arg("friction"), py::arg("tolerance") = py::none())
        .def(
            "curve",
            [](const scene& s, std::optional<std::vector<double>> loads, std::optional<std::vector<double>> ratios,
               int points, bool sweep, std::optional<int> n, std::optional<std::string> method,
               std::optional<std::string> zones, std::optional<double> friction, std::optional<double> tolerance) {
                curve_columns c;
                {
                    py::gil_scoped_release release;
                    scene o = overridden(s, {n, method, zones, friction, tolerance});
                    if (ratios) {
                        // Each load Q/f as a point's (load_of): the same checks and the same Q = (Q/f) f.
                        loads.emplace();
                        for (const double q : *ratios) loads->push_back(load_of(o, load_given(load_kind::Q_over_f, q)));
                    }
                    c = solve_curve(std::move(o), loads, points, sweep);
                }
                py::dict d;
                d["Q"] = array_of(c.Q);
                d["Q_over_f"] = array_of(c.Q_over_f);
                d["c0"] = array_of(c.c0);
                d["xi"] = array_of(c.xi);
                d["xi_over_f"] = array_of(c.xi_over_f);
                d["xi_carter"] = array_of(c.xi_carter);
                d["c0_carter"] = array_of(c.c0_carter);
                d["checks_hold"] = bool_array_of(c.checks_hold);
                d["c0_error_estimate"] = array_of(c.c0_error);
                d["xi_error_estimate"] = array_of(c.xi_error);
                d["Q_error_estimate"] = array_of(c.Q_error);
                d["zones"] = py::array_t<int>(static_cast<py::ssize_t>(c.zones.size()), c.zones.data());
                d["stick_start"] = array_of(c.stick_start);
                d["stick_start_error_estimate"] = array_of(c.stick_start_error);
                d["zone_path"] = c.zone_path;  // a NumPy array of str in roughroll.Scene.curve
                d["n"] = py::array_t<int>(static_cast<py::ssize_t>(c.n.size()), c.n.data());
                d["status"] = c.status;     // a NumPy array of str in roughroll.Scene.curve
                d["_refused"] = c.refused;  // warned by roughroll.Scene.curve
                if (c.physical) {
                    d["P1_N_per_m"] = array_of(c.P1);
                    d["xi1"] = array_of(c.xi1);
                    d["xi1_carter"] = array_of(c.xi1_carter);
                    d["P1_N_per_m_error_estimate"] = array_of(c.P1_error);
                    d["xi1_error_estimate"] = array_of(c.xi1_error);
                }
                return d;
            },
            py::arg("loads"), py::arg("Q_over_f"), py::arg("points"), py::arg("sweep"), py::arg("n"), py::arg("method"),
            py::arg("zones"), py::arg("friction"), py::arg("tolerance") = py::none())
        .def(
            "traction",
            [](const scene& s, std::optional<double> Q, std::optional<double> Q_over_f, std::optional<double> P1,
               std::vector<double> r, std::optional<int> n, std::optional<std::string> method,
               std::optional<std::string> zones, std::optional<double> friction, std::optional<double> tolerance) {
                const std::optional<load_given> load = load_keywords(Q, Q_over_f, P1);
                traction_columns t;
                {
                    py::gil_scoped_release release;
                    t = solve_traction(overridden(s, {n, method, zones, friction, tolerance}), load, r);
                }
                py::dict d;
                d["point"] = t.point;
                d["r"] = array_of(t.r);
                d["p"] = array_of(t.p);
                d["p1"] = array_of(t.p1);
                d["slip_velocity"] = array_of(t.v);
                d["stick"] = bool_array_of(t.stick);
                d["p_hertz"] = array_of(t.p_hertz);
                d["p1_carter"] = array_of(t.p1_carter);
                if (t.physical) {
                    d["x1_m"] = array_of(t.x1_m);
                    d["p2_Pa"] = array_of(t.p2_Pa);
                    d["p1_Pa"] = array_of(t.p1_Pa);
                }
                d["c0_distribution"] = t.c0_level;
                return d;
            },
            py::arg("Q"), py::arg("Q_over_f"), py::arg("P1"), py::arg("r"), py::arg("n"), py::arg("method"),
            py::arg("zones"), py::arg("friction"), py::arg("tolerance") = py::none());
}

}  // namespace roughroll::python
