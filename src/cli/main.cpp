// The roughroll command line: scene files in, creep points, curves and figures out.
// Exit status: 0 success, 2 invalid input or a case beyond reach (one line on stderr).
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"

namespace roughroll::cli {

void add_scene_options(CLI::App* cmd, scene_options& o) {
    cmd->add_option("SCENE", o.path, "scene file (TOML)")->required();
    cmd->add_option("--n", o.n, "Gauss-Chebyshev nodes (overrides solver.n)");
    cmd->add_option("--method", o.method_name, "paper, product, extrapolated or one-parameter (overrides solver.method)");
}

scene load_scene(const scene_options& o) {
    scene s = read_scene(o.path);
    override_solver(s, o.n, o.method_name);
    return s;
}

namespace {

int run_point(const scene_options& o, std::optional<double> Q_option, bool json) {
    const scene_point p = solve_point(load_scene(o), Q_option);
    if (json)
        std::cout << to_json(p.report()).dump(2) << "\n";
    else
        write_summary(std::cout, p.report());
    return 0;
}

int run_curve(const scene_options& o, int points, bool sweep, const std::string& csv) {
    scene s = load_scene(o);
    const std::optional<contact_width> width = settle_width(s);
    contact c(s.surfaces, s.friction, s.solver);
    const auto curve = sweep ? swept_curve(c, points) : creep_curve(c, curve_loads(points, s.friction));
    std::optional<si_context> si;
    if (width) si = si_context{*s.physical, *width};
    if (csv.empty()) {
        write_curve_csv(std::cout, curve, si);
        return 0;
    }
    std::ofstream out(csv);
    if (!out) throw input_error("cannot write '" + csv + "'");
    write_curve_csv(out, curve, si);
    if (!out.flush()) throw input_error("cannot write '" + csv + "'");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"roughroll: rolling contact of long elastic cylinders with two-parameter surface roughness\n"
                 "(Pauk & Wozniak). Exit status 2: invalid input or a case beyond the method's reach."};
    app.require_subcommand(1);

    scene_options point_scene;
    std::optional<double> Q;
    bool json = false;
    CLI::App* point = app.add_subcommand("point", "one creep point: c0, xi and P_H/P2 for a given Q");
    add_scene_options(point, point_scene);
    point->add_option("--Q", Q, "tangential load P1/P2 (overrides the scene's Q)");
    point->add_flag("--json", json, "one JSON object on stdout");

    scene_options curve_scene;
    int points = 51;
    std::string csv;
    CLI::App* curve = app.add_subcommand("curve", "a creep curve, Q/f from 0 to 1, as CSV");
    add_scene_options(curve, curve_scene);
    curve->add_option("--points", points, "number of loads (Q/f dense near 1)");
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
        if (e.get_exit_code() == 0) return app.exit(e);  // --help
        std::cerr << "roughroll: error: " << e.what() << "\n";
        return 2;
    }

    try {
        if (*point) return run_point(point_scene, Q, json);
        if (*curve) return run_curve(curve_scene, points, sweep, csv);
        if (*figure) return run_figure(fig);
        if (*convergence) return run_convergence(conv);
        if (*traction) return run_traction(trac);
        if (*roughness_cmd) return run_roughness(rough);
    } catch (const roughroll::error& e) {
        std::cerr << "roughroll: error: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "roughroll: error: out of memory\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "roughroll: internal error: " << e.what() << "\n";
        return 70;
    }
    return 2;
}

}  // namespace roughroll::cli

int main(int argc, char** argv) { return roughroll::cli::main(argc, argv); }
