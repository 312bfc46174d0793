// SPDX-License-Identifier: GPL-3.0-or-later
// `roughroll figure 2a|2b`: the paper's Fig. 2, creep force-creep curves xi/f against Q/f
// for the roughness parameters of its caption, with Carter's smooth curve for comparison.
// G of (3.25) does not involve f, so the stick problem divided by f depends on Q/f alone:
// xi/f against Q/f does not depend on the friction coefficient used here (for any kernels;
// with K1* = K2*, the caption's settings, G is moreover the linear (2/pi) lambda r).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include "cli/commands.hpp"
#include "cli/output_files.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/numerics/quadrature.hpp"
#include "roughroll/problems/creep_curve.hpp"

namespace roughroll::cli {

namespace {

constexpr double figure_friction = 0.3;  // any f > 0 gives the same xi/f against Q/f

struct figure_curve {
    std::string legend;  // gnuplot enhanced text
    roughness surfaces;
};

// Fig. 2 caption: the second cylinder is smooth; T_1^(1) = T_1^(2), A_1^(1) = A_1^(2).
roughness first_cylinder_rough(double T, double A) {
    roughness r;
    r.cylinder1.tangential = {T, A};
    r.cylinder1.normal = {T, A};
    return r;
}

std::vector<figure_curve> curves_of(const std::string& which) {
    std::vector<figure_curve> curves;
    const double values[] = {0.0, 0.5, 1.0};
    for (int i = 0; i < 3; ++i) {
        std::ostringstream legend;
        legend << "curve " << i + 1 << ": ";
        if (which == "2a") {
            legend << "T_1^{(1)} = T_1^{(2)} = " << values[i] << ",  A_1^{(1)} = A_1^{(2)} = 0.5";
            curves.push_back({legend.str(), first_cylinder_rough(values[i], 0.5)});
        } else {
            legend << "A_1^{(1)} = A_1^{(2)} = " << values[i] << ",  T_1^{(1)} = T_1^{(2)} = 0.5";
            curves.push_back({legend.str(), first_cylinder_rough(0.5, values[i])});
        }
    }
    return curves;
}

// The tables of docs/reproduction.md: P_H/P2 and xi/f at four loads per curve, with their
// error estimates (contact::estimate: three levels, docs/performance.md). One point per value
// at n: the root search starts from the coarse level's root, no Brent search at 2n.
void write_table(output_file& file, const std::string& which, const std::vector<figure_curve>& curves,
                 const solver_options& options) {
    const double ratios[] = {0.1, 0.5, 0.9, 0.99};
    std::ostream& md = file.stream();
    md << "Fig. " << which << ", method " << to_string(options.how) << ", n = " << options.nodes()
       << ": value, and in brackets its error estimate.\n\n"
       << "| curve | P_H/P2 |";
    for (double r : ratios) md << " xi/f at Q/f = " << r << " |";
    md << "\n|---|---|";
    for (std::size_t i = 0; i < std::size(ratios); ++i) md << "---|";
    md << "\n";
    auto cell = [&md](double value, std::optional<double> estimate) {
        char buf[64];
        if (estimate)
            std::snprintf(buf, sizeof buf, " %.10f (%.1e) |", value, *estimate);
        else
            std::snprintf(buf, sizeof buf, " %.10f (no estimate) |", value);
        md << buf;
    };
    for (const auto& c : curves) {
        contact problem(c.surfaces, figure_friction, options);
        std::optional<double> lambda_estimate;
        md << "| " << c.legend << " |";
        std::vector<std::pair<double, std::optional<double>>> xi;
        for (double r : ratios) {
            progress("Fig. " + which + " table: curve " + std::to_string(&c - curves.data() + 1) + "/" +
                     std::to_string(curves.size()) + ", Q/f = " + shortest(r) + " with its error estimate");
            const tangential_solution s = problem.point(r * figure_friction);
            const auto e = problem.estimate(s);
            if (e) lambda_estimate = e->lambda;
            xi.emplace_back(s.xi / figure_friction, e ? std::optional<double>(e->xi / figure_friction) : std::nullopt);
        }
        cell(problem.normal().lambda, lambda_estimate);
        for (const auto& [v, e] : xi) cell(v, e);
        md << "\n";
    }
    file.commit();
}

void write_gnuplot(output_file& script, const std::filesystem::path& csv, const std::filesystem::path& stem,
                   const std::string& which, const std::vector<figure_curve>& curves) {
    std::ostream& gp = script.stream();
    gp << gnuplot_output_stem(stem) << "# Fig. " << which << " of Pauk & Wozniak, written by roughroll figure " << which
       << "\n"
       << "set datafile separator ','\n"
       << "set key top left box opaque spacing 1.15\n"  // the ticks' font: readable
       << "set grid\n"
       << "set xlabel 'Q/f = P_1/(f P_2)  (dimensionless)'\n"
       << "set ylabel '{/Symbol x}/f  (dimensionless creep / f)'\n"
       << "set xrange [0:1]\nset yrange [0:*]\n"
       << "set title 'Fig. " << which << ": creep force-creep curves, second cylinder smooth'\n";
    const char* terminals[][2] = {{"svg size 900,640 enhanced font 'Helvetica,13'", ".svg"},
                                  {"pngcairo size 1200,850 enhanced font 'Helvetica,13'", ".png"}};
    const std::string data = "'" + gnuplot_path(csv.filename()) + "'";  // beside the script
    for (const auto& t : terminals) {
        gp << "set terminal " << t[0] << "\n"
           << "set output out.'" << t[1] << "'\n";
        // Carter first, wide and light: curve 1 (T = 0) lies on it and stays visible on top.
        gp << "plot " << data << " using " << 2 + 2 * curves.size() << ":" << 3 + 2 * curves.size()
           << " with lines lw 7 lc rgb '#c4c4c4' title 'Carter (smooth cylinders)'";
        const char* dash[] = {"", " dt 2", " dt 4"};
        for (std::size_t i = 0; i < curves.size(); ++i)
            gp << ", \\\n     '' using " << 2 + 2 * i << ":" << 3 + 2 * i << " with lines lw 2.5" << dash[i % 3]
               << " title '" << curves[i].legend << "'";
        gp << "\n";
    }
    gp << "unset output\n";
    script.commit();
}

}  // namespace

void add_figure_options(CLI::App* cmd, figure_options& o) {
    cmd->add_option("WHICH", o.which, "2a or 2b")->required()->check(CLI::IsMember({"2a", "2b"}));
    cmd->add_option("--out", o.out, "output folder (created if missing)");
    add_integer(cmd, "--points", o.points, "creep points per curve");
    add_integer(cmd, "--n", o.n, "Gauss-Chebyshev nodes (default: the method's, see README)");
    cmd->add_option("--method", o.method_name, "paper, product, extrapolated or one-parameter");
    cmd->add_flag("!--no-plot", o.plot, "write the CSV and the gnuplot script only");
}

int run_figure(const figure_options& o) {
    solver_options options;
    options.how = method_from_string(o.method_name);
    if (o.n) {
        check_node_count(*o.n);
        options.n = *o.n;
    }
    if (2 * options.nodes() > max_nodes)  // before any work (tests/cli_bad_input.sh: figure-n-too-large)
        throw input_error("the figure's table needs 2n <= " + std::to_string(max_nodes) +
                          " for its convergence estimates; use n <= " + std::to_string(max_nodes / 2));
    const auto curves = curves_of(o.which);
    // The outputs, checked and opened before any work.
    plot_files files(output_stem(o.out, "fig" + o.which), {});
    output_file table_file(files.stem.string() + "-table.md", {});

    // Each curve swept in c0 (one linear solve per point, no root search): all curves and
    // Carter's share the c0 grid, each has its own loads Q(c0).
    std::vector<std::vector<curve_point>> results;
    for (const auto& c : curves) {
        progress("Fig. " + o.which + ": curve " + std::to_string(results.size() + 1) + "/" +
                 std::to_string(curves.size()) + ", " + std::to_string(o.points) + " points swept in c0");
        contact problem(c.surfaces, figure_friction, options);
        results.push_back(swept_curve(problem, o.points));
        // A figure is a reproduction, whole or not at all: a refused point aborts it (exit 2),
        // as before curves learned to go on past one (curve_point, contact.hpp).
        for (const curve_point& row : results.back())
            if (row.is_refused()) throw resolution_error("Fig. " + o.which + ": " + row.refused);
    }

    std::ostream& out = files.csv_file.stream();
    out << "# roughroll " << version() << "\n";
    out << "# Fig. " << o.which << ", method " << to_string(options.how) << ", n = " << options.nodes()
        << "; curves swept in c0, each with its own Q(c0); *_error_estimate: the estimates of Q_over_f_i and "
           "xi_over_f_i (empty: none); Carter's columns a closed form\n";
    out << "c0";
    for (std::size_t i = 0; i < curves.size(); ++i) out << ",Q_over_f_" << i + 1 << ",xi_over_f_" << i + 1;
    // Each curve's estimates after the columns the gnuplot script reads by number: Q(c0)'s and xi's divided by f
    // (contact::at_stick_end, three levels; c0 is given). Carter's columns are his closed form.
    out << ",Q_over_f_carter,xi_carter_over_f,checks_hold";
    for (std::size_t i = 0; i < curves.size(); ++i)
        out << ",Q_over_f_" << i + 1 << "_error_estimate,xi_over_f_" << i + 1 << "_error_estimate";
    out << "\n";
    for (std::size_t p = 0; p < results[0].size(); ++p) {
        const double c0 = results[0][p].solution.c0(), rho = 0.5 * (1.0 + c0);
        out << shortest(c0);
        bool hold = true;
        for (const auto& curve : results) {
            const auto& sol = curve[p].solution;
            out << ',' << shortest(sol.Q / figure_friction) << ',' << shortest(sol.xi / figure_friction);
            hold = hold && sol.checks.hold();
        }
        // Carter at the same c0: Q/f = 1 - rho^2, xi/f = (2/pi)(1 - rho).
        out << ',' << shortest(1.0 - rho * rho) << ',' << shortest(M_2_PI * (1.0 - rho)) << ',' << (hold ? 1 : 0);
        for (const auto& curve : results) {
            const std::optional<error_estimate>& e = curve[p].estimate;
            out << ',' << (e ? shortest(e->Q / figure_friction) : std::string()) << ','
                << (e ? shortest(e->xi / figure_friction) : std::string());
        }
        out << '\n';
    }
    files.csv_file.commit();

    write_table(table_file, o.which, curves, options);
    write_gnuplot(files.script_file, files.csv, files.stem, o.which, curves);
    if (!o.plot) return 0;
    run_gnuplot(files.script, files.stem, {".svg", ".png"});
    return 0;
}

// --- roughroll curve --plot ---------------------------------------------------------------

namespace {

const char* const palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

// The plot commands of one scene in one panel: its curve (solved rows only), and its refused
// rows as ticks on the x axis (the y2 axis spans [0, 1]: ticks 6 % of the panel high), or, on
// a curve swept in c0 (a refused row has no load there), a note in the key.
void scene_curves(std::ostream& gp, const curve_plot_scene& s, const std::string& colour, const std::string& x,
                  const std::string& y, bool named, const char*& sep) {
    const std::string data = "'" + gnuplot_path(s.csv.filename()) + "'";
    gp << sep << data << " using " << x << ":(strcol('status') eq 'ok' ? " << y
       << " : NaN) with linespoints lw 2.5 pt 7 ps 0.55 lc rgb '" << colour << "' title \"" << gnuplot_text(s.title)
       << "\"";
    sep = ", \\\n     ";
    if (s.refused == 0) return;
    // Short: the key must fit under a panel (the reasons are the program's stderr lines).
    const std::string note = (named ? gnuplot_text(s.title) + ": " : std::string()) + std::to_string(s.refused) +
                             " refused row" + (s.refused == 1 ? "" : "s");
    if (s.swept)
        gp << sep << "NaN with lines lw 0 lc rgb '#ffffff' title \"" << note
           << " (swept in c_0: no load to place at)\"";
    else
        gp << sep << data << " using " << x << ":(strcol('status') eq 'refused' ? 0 : NaN):(0):(0.06) axes x1y2 "
           << "with vectors nohead lw 3 lc rgb '" << colour << "' title \"" << note << " (ticks at their load)\"";
}

}  // namespace

void write_curve_gnuplot(std::ostream& gp, const std::filesystem::path& stem,
                         const std::vector<curve_plot_scene>& scenes) {
    bool physical = false, two_sided = false;
    for (const auto& s : scenes) {
        physical = physical || s.physical;
        two_sided = two_sided || s.two_sided;
    }
    // The keys' lines (a refused row adds a line to its scene): both panels get the bottom
    // margin of the longer key, so that their frames line up.
    int rows1 = 1, rows2 = 0, physical_scenes = 0;
    for (const auto& s : scenes) {
        rows1 += 1 + (s.refused > 0);
        if (s.physical) {
            rows2 += 1 + (s.refused > 0);
            ++physical_scenes;
        }
    }
    rows2 += physical_scenes > 0;  // the smooth rollers' entry
    const double bottom = 0.11 + 0.034 * std::max(rows1, rows2);
    const std::string title = scenes.size() == 1 ? "Creep curve: " + gnuplot_text(scenes[0].title) : "Creep curves";
    gp << "# Creep curves, written by roughroll curve --plot. Data: the CSVs beside this script\n"
       << "# (solved rows: status ok; refused rows: ticks on the load axis).\n"
       << gnuplot_output_stem(stem) << "set datafile separator ','\n"
       << "set datafile columnheaders  # the CSV's header row names the columns (its # lines are skipped)\n"
       << "# Carter's smooth rollers (Johnson, Contact Mechanics 8.4): xi/f = (2/pi)(1 - sqrt(1 - Q/f)), odd in Q.\n"
       << "carter(q) = sgn(q) * 2/pi * (1 - sqrt(1 - abs(q)))\n"
       << "set samples 600\n"
       << "set grid back lc rgb '#d8d8d8'\n"
       << "set border lw 1.2\n"
       << "set y2range [0:1]\nunset y2tics\n"
       // The key's font as the ticks' (the terminal's): readable at the size the figure is seen.
       // below the panel: long scene labels hide no curve; one entry a line, text after its sample.
       // (width -6: the SVG terminal overestimates the width of escaped text and warns that a
       // title does not fit where the PNG shows it fitting with room to spare).
       << "set key below box Left reverse spacing 1.15 samplen 2.5 maxcols 1 width -6\n";
    const char* terminals[][2] = {
        // The SVG as the PNG (the two-panel keys need the width: gnuplot warns when a title does not fit).
        {physical ? "svg size 1800,820 enhanced font 'Helvetica,15' background '#ffffff'"
                  : "svg size 1100,830 enhanced font 'Helvetica,15' background '#ffffff'",
         ".svg"},
        {physical ? "pngcairo size 1800,820 enhanced font 'Helvetica,15'"
                  : "pngcairo size 1100,830 enhanced font 'Helvetica,15'",
         ".png"}};
    for (const auto& t : terminals) {
        gp << "\nset terminal " << t[0] << "\nset output out.'" << t[1] << "'\n";
        gp << "set multiplot layout 1," << (physical ? 2 : 1) << " title \"" << title << "\"\n";
        gp << "set tmargin at screen 0.88\nset bmargin at screen " << shortest(bottom) << "\n";
        // Panel 1: dimensionless, Carter's curve under the scenes' (wide and light, so that a
        // curve lying on it stays visible).
        gp << "set xlabel 'Q/f = P_1/(f P_2)'\nset ylabel '{/Symbol x}/f   (creep / friction coefficient)'\n"
           << "set format y '%g'\n"
           << "set xrange [" << (two_sided ? "-1" : "0") << ":1]\nset yrange [" << (two_sided ? "*" : "0") << ":*]\n"
           << (physical ? "set title 'dimensionless'\n" : "unset title\n")
           << "plot carter(x) with lines lw 7 lc rgb '#c4c4c4' title 'Carter: smooth rollers'";
        const char* sep = ", \\\n     ";
        for (std::size_t k = 0; k < scenes.size(); ++k)
            scene_curves(gp, scenes[k], palette[k % std::size(palette)], "(column('Q_over_f'))", "column('xi_over_f')",
                         scenes.size() > 1, sep);
        gp << "\n";
        if (physical) {
            // Panel 2: the physical scenes in N/mm and creep, each over its own smooth rollers
            // (Carter's xi1 at the same P1: the width, radii and moduli of the scene).
            gp << "set xlabel 'P_1  (N/mm)'\nset ylabel 'creep {/Symbol x}_1'\nset format y '%h'\n"
               << "set xrange [*:*]\nset yrange [*:*]\nset title 'physical scenes, SI units'\nplot ";
            const char* sep2 = "";
            for (std::size_t k = 0; k < scenes.size(); ++k) {
                if (!scenes[k].physical) continue;
                const std::string colour = palette[k % std::size(palette)];
                gp << sep2 << "'" << gnuplot_path(scenes[k].csv.filename())
                   << "' using (column('P1_N_per_m')/1000):(column('xi1_carter')) with lines lw 2 dt 2 lc rgb '"
                   << colour
                   << "' "
                   // One key entry for the dashed lines: the colour says whose (a long name would not fit).
                   << (sep2[0] == '\0' ? (physical_scenes > 1 ? "title \"dashed: each scene's rollers smooth (Carter)\""
                                                              : "title \"the same rollers smooth (Carter)\"")
                                       : "notitle");
                sep2 = ", \\\n     ";
                scene_curves(gp, scenes[k], colour, "(column('P1_N_per_m')/1000)", "column('xi1')", scenes.size() > 1,
                             sep2);
            }
            gp << "\n";
        }
        gp << "unset multiplot\nset output\n";
    }
}

}  // namespace roughroll::cli
