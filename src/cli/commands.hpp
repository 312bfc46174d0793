// SPDX-License-Identifier: GPL-3.0-or-later
// Subcommands of the CLI that live in their own files, and the scene options they share.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "roughroll/problems/contact_width.hpp"
#include "roughroll/model/physical_scene.hpp"
#include "roughroll/io/scene.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll::cli {

// SCENE [--n N] [--method NAME] [--zones HOW] [--friction F]: a scene file and the overrides
// every scene-based subcommand accepts (defined in main.cpp).
struct scene_options {
    std::string path;
    std::optional<double> friction;
    std::optional<int> n;
    std::optional<std::string> method_name;
    std::optional<std::string> zones_name;
    std::optional<double> tolerance;  // --tolerance: the ladder chooses n (problems/level_ladder.hpp)
};

void add_scene_options(CLI::App* cmd, scene_options& o);
// The overrides alone (--n, --method, --zones, --tolerance, --friction), for a command with its own SCENE.
void add_scene_overrides(CLI::App* cmd, scene_options& o);

// The load of one point, as --Q (P1/P2), --Q-over-f (Q/f) or --P1 (N/m, physical scenes): at most
// one of them (CLI11 refuses two), over the scene's load (load_of, io/scene.hpp).
struct load_options {
    std::optional<double> Q, Q_over_f, P1;
    std::optional<load_given> given() const;
};
void add_load_options(CLI::App* cmd, load_options& o);

// --progress and --quiet of the commands that work long (set_progress, output_files.hpp).
struct progress_options {
    bool shown = false;  // --progress: progress lines even when stderr is not a terminal
    bool quiet = false;  // --quiet: none
};
void add_progress_options(CLI::App* cmd, progress_options& o);

// Numeric options read by the one rule of text.hpp: an empty value, trailing text or a
// literal that underflows (1e-400) is a parse error naming the option; CLI11's own
// conversion ignores "" and reads 1e-400 as 0.
CLI::Option* add_number(CLI::App* cmd, const std::string& name, std::optional<double>& value, const std::string& help);
CLI::Option* add_number(CLI::App* cmd, const std::string& name, double& value, const std::string& help);
CLI::Option* add_integer(CLI::App* cmd, const std::string& name, std::optional<int>& value, const std::string& help);
CLI::Option* add_integer(CLI::App* cmd, const std::string& name, int& value, const std::string& help);

// JSON as printed (two-space indent), invalid UTF-8 replaced rather than thrown on.
std::string dump(const nlohmann::json& j);
scene load_scene(const scene_options& o);  // the file, with the command line's overrides

// settle_width and si_of, shared with the Python module: roughroll/io/scene_point.hpp.

// One scene's curve in `roughroll curve --plot` (figure.cpp).
struct curve_plot_scene {
    std::filesystem::path csv;  // its CSV, beside the script
    std::string title;          // the scene's label, or its file name
    double friction = 0.0;
    bool physical = false;   // the CSV has P1_N_per_m, xi1, xi1_carter
    bool swept = false;      // loads Q(c0): a refused row has no load to place it at
    bool two_sided = false;  // loads from -f to f (beta_d != 0)
    int refused = 0;         // refused rows
};

// The gnuplot script of `roughroll curve --plot`: xi/f against Q/f of every scene over Carter's
// smooth curve, refused rows as ticks on the Q/f axis (or a note where they have no load), and
// for physical scenes a second panel xi1 against P1 in N/mm with each scene's smooth rollers.
void write_curve_gnuplot(std::ostream& gp, const std::filesystem::path& stem,
                         const std::vector<curve_plot_scene>& scenes);

struct figure_options {
    std::string which;  // "2a" or "2b"
    std::string out = "figures";
    int points = 101;      // creep points per curve
    std::optional<int> n;  // unset: the method's default
    std::string method_name = "extrapolated";
    bool plot = true;
};

void add_figure_options(CLI::App* cmd, figure_options& o);
int run_figure(const figure_options& o);

// `roughroll traction SCENE`: p, p1, +-f p and v on a grid of r, as CSV, gnuplot, SVG, PNG.
struct traction_options {
    scene_options scene;
    load_options load;  // overrides the scene's load
    int points = 401;   // grid points on [-1, 1]
    std::string out = "figures";
    std::string name;  // file stem after "traction-" (default: the scene file's stem)
    bool plot = true;
};

void add_traction_options(CLI::App* cmd, traction_options& o);
int run_traction(const traction_options& o);

struct convergence_options {
    scene_options scene;
    load_options load;  // overrides the scene's load
    std::string out = "figures";
    double max_seconds = 2.0;  // a method's ladder stops after a point slower than this
    bool plot = true;
};

void add_convergence_options(CLI::App* cmd, convergence_options& o);
int run_convergence(const convergence_options& o);

// `roughroll roughness SPEC [--json]`: k, t, alpha of (2.11)-(2.15) from a micro-geometry.
struct roughness_options {
    std::string spec;
    bool json = false;
};

void add_roughness_options(CLI::App* cmd, roughness_options& o);
int run_roughness(const roughness_options& o);

}  // namespace roughroll::cli
