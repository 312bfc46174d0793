// SPDX-License-Identifier: GPL-3.0-or-later
// The roughroll command line: scene files in, creep points, curves and figures out.
// Exit status: 0 success, 2 invalid input or a case beyond reach (one line on stderr).
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <sstream>
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
#include "roughroll/problems/creep_curve.hpp"

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

// The options of a plain value show it as their default in --help (a function option has no
// variable for CLI11 to capture it from).
CLI::Option* add_number(CLI::App* cmd, const std::string& name, double& value, const std::string& help) {
    return cmd
        ->add_option_function<std::string>(
            name, [name, &value](const std::string& text) { value = number_option(name, text); }, help)
        ->type_name("NUMBER")
        ->default_str(shortest(value));
}

CLI::Option* add_number(CLI::App* cmd, const std::string& name, std::optional<double>& value, const std::string& help) {
    return cmd
        ->add_option_function<std::string>(
            name, [name, &value](const std::string& text) { value = number_option(name, text); }, help)
        ->type_name("NUMBER");
}

CLI::Option* add_integer(CLI::App* cmd, const std::string& name, std::optional<int>& value, const std::string& help) {
    return cmd
        ->add_option_function<std::string>(
            name, [name, &value](const std::string& text) { value = integer_option(name, text); }, help)
        ->type_name("INT");
}

CLI::Option* add_integer(CLI::App* cmd, const std::string& name, int& value, const std::string& help) {
    return cmd
        ->add_option_function<std::string>(
            name, [name, &value](const std::string& text) { value = integer_option(name, text); }, help)
        ->type_name("INT")
        ->default_str(std::to_string(value));
}

std::optional<load_given> load_options::given() const {
    if (Q) return load_given(load_kind::Q, *Q);
    if (Q_over_f) return load_given(load_kind::Q_over_f, *Q_over_f);
    if (P1) return load_given(load_kind::P1, *P1);
    return std::nullopt;
}

void add_load_options(CLI::App* cmd, load_options& o) {
    CLI::Option* Q = add_number(cmd, "--Q", o.Q, "tangential load Q = P1/P2 (overrides the scene's load)");
    CLI::Option* ratio =
        add_number(cmd, "--Q-over-f", o.Q_over_f, "tangential load as Q/f in [-1, 1] (overrides the scene's load)");
    CLI::Option* P1 =
        add_number(cmd, "--P1", o.P1, "tangential load P1 in N/m, physical scenes only (overrides the scene's load)");
    Q->excludes(ratio)->excludes(P1);
    ratio->excludes(Q)->excludes(P1);
    P1->excludes(Q)->excludes(ratio);
}

void add_progress_options(CLI::App* cmd, progress_options& o) {
    CLI::Option* shown = cmd->add_flag("--progress", o.shown,
                                       "one line per point, row or level on stderr even when stderr is not a terminal");
    cmd->add_flag("--quiet", o.quiet, "no progress lines (they are shown by default when stderr is a terminal)")
        ->excludes(shown);
}

void add_scene_options(CLI::App* cmd, scene_options& o) {
    cmd->add_option("SCENE", o.path, "scene file (TOML)")->required();
    add_scene_overrides(cmd, o);
}

void add_scene_overrides(CLI::App* cmd, scene_options& o) {
    add_integer(cmd, "--n", o.n, "Gauss-Chebyshev nodes (overrides solver.n)");
    cmd->add_option("--method", o.method_name,
                    "paper, product, extrapolated or one-parameter (overrides solver.method)");
    cmd->add_option("--zones", o.zones_name,
                    "auto, single or general: how the stick and slip zones are found "
                    "(overrides solver.zones)");
    add_number(cmd, "--tolerance", o.tolerance,
               "relative accuracy of the estimates that choose n (P_H/P2, c0, xi, the zone ends; docs/cli.md): n chosen "
               "from the method's default up to 1000 (overrides "
               "solver.tolerance and solver.n; default " +
                   shortest(default_tolerance) + " where no n is given)");
    add_number(cmd, "--friction", o.friction, "friction coefficient f (overrides the scene's friction)");
}

scene load_scene(const scene_options& o) {
    scene s = read_scene(o.path);
    override_solver(s, o.n, o.method_name, o.zones_name, o.tolerance);
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

int run_point(const scene_options& o, const load_options& load, bool json) {
    scene s = load_scene(o);
    const std::string name = std::filesystem::path(o.path).filename().string();
    progress(name + ": solving the point" + (s.physical ? " (its contact width first)" : ""));
    const auto start = std::chrono::steady_clock::now();
    const scene_point p = solve_point(std::move(s), load.given());
    std::ostringstream line;
    line << name << ": solved in " << std::setprecision(3)
         << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s";
    progress(line.str());
    if (json)
        std::cout << dump(to_json(p.report())) << "\n";
    else
        write_summary(std::cout, p.report());
    return 0;
}

// curve_of with one progress line before each row (its hook, called between rows: the rows are
// the same numbers with or without it; tests/cli_curve_plot.sh compares the CSVs).
scene_curve curve_with_progress(scene s, int points, bool sweep, const std::string& name) {
    if (!progress_shown()) return curve_of(std::move(s), std::nullopt, points, sweep);
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&start]() {
        return significant(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3);
    };
    // The row's load as curve_of chooses it: Q/f given, or the stick end c0 of a sweep
    // (swept_curve: rho = (1 + c0)/2 uniform from 1 to 0).
    const std::vector<double> Qs = curve_loads(points, s.friction, s.materials.beta_d);
    const double f = s.friction;
    std::size_t row = 0;
    const bool in_c0 = sweep && s.materials.beta_d == 0.0;  // dissimilar rollers: continued in the load
    progress(name + ": " + std::to_string(points) +
             (in_c0 ? " points swept in c0" : sweep ? " loads, each row from the previous one's zones" : " loads") +
             (s.physical ? " (contact width first)" : ""));
    const auto before_row = [&]() {
        std::string what;
        if (in_c0) {
            const double rho = 1.0 - static_cast<double>(row) / (points - 1);
            what = "c0 = " + significant(row + 1 == static_cast<std::size_t>(points) ? -1.0 : 2.0 * rho - 1.0, 4);
        } else if (row < Qs.size()) {
            what = "Q/f = " + ratio_text(Qs[row] / f, 4);
        }
        progress(name + ": row " + std::to_string(row + 1) + "/" + std::to_string(points) + ", " + what + " (" +
                 seconds() + " s so far)");
        ++row;
    };
    scene_curve c = curve_of(std::move(s), std::nullopt, points, sweep, before_row);
    progress(name + ": done in " + seconds() + " s");
    return c;
}

struct curve_options {
    scene_options scene;             // the overrides; scene.path unused
    std::vector<std::string> paths;  // one scene, or several overlaid in one plot
    int points = 51;
    bool sweep = false;
    std::string csv;
    bool plot = false;
};

// The CSV of each scene: --csv itself for one scene; for several, FILE's stem-SCENE.csv beside it.
std::vector<std::filesystem::path> curve_csv_paths(const curve_options& o) {
    namespace fs = std::filesystem;
    if (o.paths.size() == 1) return {fs::path(o.csv)};
    const fs::path csv(o.csv);
    const fs::path stem = csv.extension() == ".csv" ? fs::path(csv).replace_extension() : csv;
    std::vector<fs::path> out;
    for (const std::string& p : o.paths) {
        const fs::path one = stem.string() + "-" + fs::path(p).stem().string() + ".csv";
        if (std::find(out.begin(), out.end(), one) != out.end())
            throw input_error("two scenes are named '" + echo(fs::path(p).stem().string()) +
                              "': their CSVs would be the same file " + "'" + echo(one.string()) + "'");
        out.push_back(one);
    }
    return out;
}

int run_curve(const curve_options& o) {
    namespace fs = std::filesystem;
    if (o.plot && o.csv.empty())
        throw input_error("--plot needs --csv FILE: the plot is written beside the CSV (FILE's stem .gp, .svg, .png)");
    if (o.paths.size() > 1 && o.csv.empty())
        throw input_error("several scenes need --csv FILE: each scene's curve goes to FILE's stem-SCENE.csv");
    // Every scene read and every output checked and opened before any work; written whole or not at all.
    std::vector<scene> scenes;
    std::vector<std::string> inputs;
    for (const std::string& path : o.paths) {
        scene_options so = o.scene;
        so.path = path;
        scenes.push_back(load_scene(so));
        inputs.insert(inputs.end(), scenes.back().files.begin(), scenes.back().files.end());
        if (o.sweep) check_sweepable(scenes.back().materials);
    }
    std::vector<fs::path> csv_paths;
    std::vector<std::unique_ptr<output_file>> files;
    if (!o.csv.empty()) {
        csv_paths = curve_csv_paths(o);
        for (const fs::path& p : csv_paths) files.push_back(std::make_unique<output_file>(p, inputs));
    }
    // The plot beside the CSV: FILE.csv -> FILE.gp, FILE.svg, FILE.png.
    fs::path stem;
    std::unique_ptr<output_file> script;
    if (o.plot) {
        const fs::path csv(o.csv);
        stem = csv.extension() == ".csv" ? fs::path(csv).replace_extension() : csv;
        const fs::path gp = stem.string() + ".gp";
        if (std::find(csv_paths.begin(), csv_paths.end(), gp) != csv_paths.end())
            throw input_error("--csv '" + echo(o.csv) + "' is the plot's script: name the CSV FILE.csv");
        std::vector<std::string> taken = inputs;
        for (const fs::path& p : csv_paths) taken.push_back(p.string());
        script = std::make_unique<output_file>(gp, taken);
        for (const char* ext : {".svg", ".png"}) check_output(stem.string() + ext, taken);
    }

    std::vector<curve_plot_scene> plotted;
    std::vector<std::vector<curve_point>> all_rows;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        scene& s = scenes[k];
        const std::string& path = o.paths[k];
        const bool in_c0 = o.sweep && s.materials.beta_d == 0.0;  // dissimilar rollers: continued in the load
        const curve_header header{path,   s.label, s.friction, s.solver, in_c0, s.physical.has_value(),
                                  o.sweep && !in_c0};
        curve_plot_scene facts;
        facts.csv = csv_paths.empty() ? fs::path() : csv_paths[k];
        facts.title = s.label.empty() ? fs::path(path).filename().string() : s.label;
        facts.friction = s.friction;
        facts.physical = s.physical.has_value();
        facts.swept = in_c0;
        facts.two_sided = s.materials.beta_d != 0.0;
        const scene_curve c = curve_with_progress(std::move(s), o.points, o.sweep, fs::path(path).filename().string());
        std::optional<si_context> si;
        if (c.settled.physical) si = si_context{*c.settled.physical, c.widths};
        std::ostream& out = files.empty() ? std::cout : files[k]->stream();
        write_curve_header(out, header);
        write_curve_csv(out, c.rows, si, c.nodes);
        for (const curve_point& row : c.rows)
            if (row.is_refused()) ++facts.refused;
        plotted.push_back(facts);
        all_rows.push_back(c.rows);
    }
    for (auto& file : files) file->commit();
    if (o.plot) {
        write_curve_gnuplot(script->stream(), stem, plotted);
        script->commit();
        run_gnuplot(stem.string() + ".gp", stem, {".svg", ".png"});
    }
    // Each refused point on stderr, once the curves are written (curve_point, contact.hpp).
    int status = 0;
    for (const auto& rows : all_rows)
        for (const curve_point& row : rows)
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
    CLI::App app{
        "roughroll: rolling contact of long elastic cylinders with two-parameter surface roughness\n"
        "(Pauk & Wozniak). Exit status 2: invalid input or a case beyond the method's reach (nothing written);\n"
        "3: a curve written with refused points (rows with status 'refused', one stderr line each)."};
    app.require_subcommand(1);
    // Every option's default in --help (subcommands inherit this; function options set theirs).
    app.option_defaults()->always_capture_default();
    // "roughroll X.Y.Z" on stdout, exit 0, as GNU programs print it.
    app.set_version_flag("--version", std::string("roughroll ") + version(), "print roughroll's version and exit");

    scene_options point_scene;
    load_options point_load;
    bool json = false;
    CLI::App* point = app.add_subcommand("point", "one creep point: c0, xi and P_H/P2 for a given Q");
    add_scene_options(point, point_scene);
    add_load_options(point, point_load);
    point->add_flag("--json", json, "one JSON object on stdout");

    curve_options curve_o;
    CLI::App* curve =
        app.add_subcommand("curve",
                           "a creep curve, Q/f from 0 to 1 (-1 to 1 for beta_d != 0), as CSV; with --plot, its figure "
                           "(several scenes: their curves overlaid)");
    curve->add_option("SCENE", curve_o.paths, "scene file(s) (TOML); several need --csv")
        ->required()
        ->default_str("");  // no default to show (the captured one is "[]")
    add_scene_overrides(curve, curve_o.scene);
    add_integer(curve, "--points", curve_o.points, "number of loads (Q/f dense near 1)");
    curve->add_option("--csv", curve_o.csv, "output file (default: stdout); several scenes: FILE's stem-SCENE.csv");
    curve->add_flag("--sweep", curve_o.sweep,
                    "sweep the stick-zone end c0 instead of solving for given loads: one linear solve per point, "
                    "no root search, loads Q(c0)");
    curve->add_flag("--plot", curve_o.plot,
                    "xi/f against Q/f with Carter's curve (physical scenes also xi1 against P1) as gnuplot script, "
                    "SVG and PNG beside the CSV");

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

    progress_options progress_o;
    for (CLI::App* cmd : {point, curve, figure, traction, convergence}) add_progress_options(cmd, progress_o);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        return report("error", e.what(), 2);
    }

    // Progress on a terminal's stderr, or wherever with --progress; never with --quiet: a
    // script's or a test's stderr holds only the errors (one line per bad input).
    set_progress(!progress_o.quiet && (progress_o.shown || ::isatty(STDERR_FILENO) == 1));

    try {
        int status = 2;
        if (*point)
            status = run_point(point_scene, point_load, json);
        else if (*curve)
            status = run_curve(curve_o);
        else if (*figure)
            status = run_figure(fig);
        else if (*convergence)
            status = run_convergence(conv);
        else if (*traction)
            status = run_traction(trac);
        else if (*roughness_cmd)
            status = run_roughness(rough);
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
