// The roughroll command line: scene files in, creep points, curves and figures out.
// Exit status: 0 success, 2 invalid input or a case beyond reach (one line on stderr).
#include <charconv>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/output_files.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"

namespace roughroll::cli {

namespace {
// A whole decimal integer (no sign but '-', no blanks, nothing after it) in int's range.
int integer_option(const std::string& name, const std::string& text) {
    int n = 0;
    const char* end = text.data() + text.size();
    const std::from_chars_result r = std::from_chars(text.data(), end, n);
    if (text.empty() || r.ec != std::errc() || r.ptr != end)
        throw CLI::ValidationError(name, "'" + echo(text) + "' is not an integer in int's range");
    return n;
}

double number_option(const std::string& name, const std::string& text) {
    std::string problem;
    // A sign '+' is allowed on the command line (--Q +0.1), as CLI11 allowed it.
    const std::string_view literal = text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+'
                                         ? std::string_view(text).substr(1)
                                         : std::string_view(text);
    const std::optional<double> x = parse_double(literal, problem);
    if (!x) throw CLI::ValidationError(name, problem.empty() ? "'" + echo(text) + "' is not a number" : problem);
    return *x;
}
}  // namespace

CLI::Option* add_number(CLI::App* cmd, const std::string& name, double& value, const std::string& help) {
    return cmd->add_option_function<std::string>(
        name, [name, &value](const std::string& text) { value = number_option(name, text); }, help);
}

CLI::Option* add_number(CLI::App* cmd, const std::string& name, std::optional<double>& value, const std::string& help) {
    return cmd->add_option_function<std::string>(
        name, [name, &value](const std::string& text) { value = number_option(name, text); }, help);
}

CLI::Option* add_integer(CLI::App* cmd, const std::string& name, std::optional<int>& value, const std::string& help) {
    return cmd->add_option_function<std::string>(
        name, [name, &value](const std::string& text) { value = integer_option(name, text); }, help);
}

CLI::Option* add_integer(CLI::App* cmd, const std::string& name, int& value, const std::string& help) {
    return cmd->add_option_function<std::string>(
        name, [name, &value](const std::string& text) { value = integer_option(name, text); }, help);
}

void add_scene_options(CLI::App* cmd, scene_options& o) {
    cmd->add_option("SCENE", o.path, "scene file (TOML)")->required();
    add_integer(cmd, "--n", o.n, "Gauss-Chebyshev nodes (overrides solver.n)");
    cmd->add_option("--method", o.method_name, "paper, product, extrapolated or one-parameter (overrides solver.method)");
    cmd->add_option("--zones", o.zones_name, "auto, single or general: how the stick and slip zones are found "
                                             "(overrides solver.zones)");
    add_number(cmd, "--friction", o.friction, "friction coefficient f (overrides the scene's friction)");
}

scene load_scene(const scene_options& o) {
    scene s = read_scene(o.path);
    override_solver(s, o.n, o.method_name, o.zones_name);
    override_friction(s, o.friction);
    return s;
}

namespace {

// One line on stderr: valid UTF-8, no control character (a path or an option may hold any
// bytes, which must not reach the terminal raw), and not longer than a screenful.
int report(const char* kind, const std::string& message, int status) {
    std::cerr << "roughroll: " << kind << ": " << echo(message, 2000) << "\n";
    return status;
}

// The exit status of a curve written whole but with refused points (status = refused rows, one
// stderr line each): partial output, distinct from bad input and unreachable cases (2), which
// write nothing (README.md, docs/robustness.md).
constexpr int partial_output = 3;

int run_point(const scene_options& o, std::optional<double> Q_option, bool json) {
    const scene_point p = solve_point(load_scene(o), Q_option);
    if (json)
        std::cout << dump(to_json(p.report())) << "\n";
    else
        write_summary(std::cout, p.report());
    return 0;
}

int run_curve(const scene_options& o, int points, bool sweep, const std::string& csv) {
    scene s = load_scene(o);
    // The output, checked and opened before any work; written whole or not at all.
    std::optional<output_file> file;
    if (!csv.empty()) file.emplace(csv, s.files);
    const curve_header header{o.path, s.label, s.friction, s.solver, sweep, s.physical.has_value()};
    const scene_curve c = curve_of(std::move(s), std::nullopt, points, sweep);
    const std::vector<curve_point>& curve = c.rows;
    std::optional<si_context> si;
    if (c.settled.physical) si = si_context{*c.settled.physical, c.widths};
    std::ostream& out = file ? file->stream() : std::cout;
    write_curve_header(out, header);
    write_curve_csv(out, curve, si);
    if (file) file->commit();
    // Each refused point on stderr, once the curve is written (curve_point, contact.hpp).
    int status = 0;
    for (const curve_point& row : curve)
        if (row.is_refused()) status = report("refused", row.refused, partial_output);
    return status;
}

}  // namespace


std::string dump(const nlohmann::json& j) {
    // Every text in roughroll's JSON is valid UTF-8 already (one_line at its source); replace
    // is the last guard, so that a stray byte can never turn into exit 70 (type_error 316).
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

int main(int argc, char** argv) {
    CLI::App app{"roughroll: rolling contact of long elastic cylinders with two-parameter surface roughness\n"
                 "(Pauk & Wozniak). Exit status 2: invalid input or a case beyond the method's reach (nothing written);\n"
                 "3: a curve written with refused points (rows with status 'refused', one stderr line each)."};
    app.require_subcommand(1);
    // "roughroll X.Y.Z" on stdout, exit 0, as GNU programs print it.
    app.set_version_flag("--version", std::string("roughroll ") + version(), "print roughroll's version and exit");

    scene_options point_scene;
    std::optional<double> Q;
    bool json = false;
    CLI::App* point = app.add_subcommand("point", "one creep point: c0, xi and P_H/P2 for a given Q");
    add_scene_options(point, point_scene);
    add_number(point, "--Q", Q, "tangential load P1/P2 (overrides the scene's Q)");
    point->add_flag("--json", json, "one JSON object on stdout");

    scene_options curve_scene;
    int points = 51;
    std::string csv;
    CLI::App* curve = app.add_subcommand("curve", "a creep curve, Q/f from 0 to 1 (-1 to 1 for beta_d != 0), as CSV");
    add_scene_options(curve, curve_scene);
    add_integer(curve, "--points", points, "number of loads (Q/f dense near 1)");
    curve->add_option("--csv", csv, "output file (default: stdout)");
    bool sweep = false;
    curve->add_flag("--sweep", sweep,
                    "sweep the stick-zone end c0 instead of solving for given loads: one linear solve per point, "
                    "no root search, loads Q(c0)");

    figure_options fig;
    CLI::App* figure = app.add_subcommand("figure", "reproduce the paper's Fig. 2a or 2b (CSV, SVG, PNG)");
    add_figure_options(figure, fig);

    traction_options trac;
    CLI::App* traction = app.add_subcommand(
        "traction", "tractions p, p1 and the limits +-f p over the contact for one load (CSV, SVG, PNG)");
    add_traction_options(traction, trac);

    convergence_options conv;
    CLI::App* convergence =
        app.add_subcommand("convergence", "error against run time of every method for one point (CSV, SVG, PNG)");
    add_convergence_options(convergence, conv);

    roughness_options rough;
    CLI::App* roughness_cmd =
        app.add_subcommand("roughness", "roughness parameters k, t, alpha (2.11)-(2.15) from a micro-geometry spec");
    add_roughness_options(roughness_cmd, rough);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        return report("error", e.what(), 2);
    }

    try {
        int status = 2;
        if (*point) status = run_point(point_scene, Q, json);
        else if (*curve) status = run_curve(curve_scene, points, sweep, csv);
        else if (*figure) status = run_figure(fig);
        else if (*convergence) status = run_convergence(conv);
        else if (*traction) status = run_traction(trac);
        else if (*roughness_cmd) status = run_roughness(rough);
        finish_stdout();  // a full disk or a closed pipe is an error, not exit 0 with half a table
        return status;
    } catch (const roughroll::error& e) {
        return report("error", e.what(), 2);
    } catch (const std::bad_alloc&) {
        return report("error", "out of memory", 2);
    } catch (const std::exception& e) {
        return report("internal error", e.what(), 70);
    }
}

}  // namespace roughroll::cli

int main(int argc, char** argv) { return roughroll::cli::main(argc, argv); }
