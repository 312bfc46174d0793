// SPDX-License-Identifier: GPL-3.0-or-later
// `roughroll traction SCENE`: the tractions of one creep point over the contact, for a
// reader of the paper to see (3.2)-(3.5) at work. On a grid of r = x1/a over [-1, 1]:
// the normal pressure p(r) = a p2/P2, the tangential traction p1(r) = a p1/P2 of (3.15),
// the Coulomb limits +-f p, the zone (stick or slip; the zones' ends in the header) and the slip
// velocity v(r) of (3.6), zero on a stick zone and with the sign of p1 on a slip zone.
// Carter's smooth solution for the same Q and f is written beside them for comparison
// (each solution on its own contact width: both integrate to 1 and to Q).
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include "cli/commands.hpp"
#include "cli/output_files.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/zone_layout.hpp"
#include "roughroll/io/output.hpp"
#include "roughroll/io/scene_point.hpp"
#include "roughroll/io/si_estimate.hpp"
#include "roughroll/io/traction_table.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll::cli {

namespace {

// " using 1:COLUMN ... title "TITLE"" of one curve (notitle when TITLE is empty). The
// cairo terminals snap exactly horizontal segments wider than a pixel to the pixel grid,
// which notches a curve at its flat top; a monotone cubic (no overshoot) through the
// points, drawn on sub-pixel samples (set samples), avoids that and changes nothing else.
// The script's scales xs, ps (the contact's; 1 and 1 for a dimensionless scene) carry r and p to
// mm and MPa; xh, ph those of the smooth cylinders' own width (Hertz's and Carter's columns).
std::string curve(int column, const std::string& style, const std::string& title, bool right_axis = false,
                  bool smooth_width = false) {
    const std::string x = smooth_width ? "xh" : "xs", y = column == 7 ? "1" : smooth_width ? "ph" : "ps";
    return " using ($1*" + x + "):($" + std::to_string(column) + "*" + y + ")" + (right_axis ? " axes x1y2" : "") +
           " smooth mcsplines with lines " + style +
           (title.empty() ? std::string(" notitle") : " title \"" + title + "\"");
}

struct plot_facts {
    std::string title;  // first title line (gnuplot enhanced text, escaped)
    double Q, f, c0, xi, lambda;
    std::vector<zone> zones;  // from r = -1 to 1: one, three or five (formulation 7, 8(j))
    double p_max;
    double v_low, v_high;        // least and greatest slip velocity, 0 included: v may take both signs (8(g))
    bool v_unresolved;           // some v not resolved ('-' in the CSV: the trailing edge layer, 8(n))
    bool checks_hold;            // (3.3), (3.4) and p >= 0 on the solver's own grids
    std::optional<si_point> si;  // a physical scene: drawn in mm and MPa
};

void write_traction_gnuplot(std::ostream& gp, const std::filesystem::path& csv, const std::filesystem::path& stem,
                            const plot_facts& k) {
    const double f = k.f;
    const bool negative = k.Q < 0.0;  // the mirror case: p1 follows -f p on the slip zone
    // y range of the tractions: the pressure on top with room for the key, -f p below.
    // The key (in the ticks' font) fills the top third of the panel: the pressure stays below it.
    const double y_top = 1.75 * k.p_max;
    const double y_bottom = -1.25 * f * k.p_max;
    // Where f is small, p1 (at most f p) would be a flat line on p's scale: p1, +-f p and
    // Carter's p1 go on a right axis f times the left one, so that f p there is drawn where p
    // is on the left (p1 = f p on a slip zone still reads as p1 on its limit).
    const bool right_axis = f < 0.25;
    // A physical scene in mm and MPa (issue 25): x1 = r a, p2 = p P2/a; Hertz's and Carter's
    // smooth tractions on their own half-width a_H. Every position below is r times xs.
    const double xs = k.si ? k.si->a * 1e3 : 1.0, ps = k.si ? k.si->p_scale * 1e-6 : 1.0;
    const double xh = k.si ? k.si->a_hertz * 1e3 : 1.0, ph = k.si ? k.si->P2 / k.si->a_hertz * 1e-6 : 1.0;
    const double x_end = std::max(xs, xh);
    const std::string p_unit = k.si ? "   (MPa)" : "   (dimensionless)";
    const std::string p_name = k.si ? "p_2" : "a p_2/P_2", p1_name = k.si ? "p_1" : "a p_1/P_2";
    const bool has_stick = std::any_of(k.zones.begin(), k.zones.end(), [](const zone& z) { return z.stick; });
    const bool has_slip = std::any_of(k.zones.begin(), k.zones.end(), [](const zone& z) { return !z.stick; });
    const int load_sign = k.Q > 0.0 ? 1 : k.Q < 0.0 ? -1 : 0;
    const std::string data = "'" + gnuplot_path(csv.filename()) + "'";  // beside the script
    const std::string subtitle =
        "Q = " + shortest(k.Q) + "  (Q/f = " + ratio_text(k.Q / f, 3) + "),   f = " + shortest(f) +
        ",   c_0 = c/a = " + significant(k.c0, 3) + ",   {/Symbol x} = " + significant(k.xi, 3) +
        ",   P_H/P_2 = " + significant(k.lambda, 4) + (k.checks_hold ? "" : "   (checks (3.3), (3.4) VIOLATED)");
    gp << "# Tractions over the contact, written by roughroll traction. Columns of the CSV:\n"
       << "# 1 r, 2 p, 3 p1, 4 f p, 5 -f p, 6 zone, 7 slip velocity v, 8 p (Hertz), 9 p1 (Carter)\n"
       << gnuplot_output_stem(stem) << "set datafile separator ','\n"
       << (k.v_unresolved ? "set datafile missing '-'  # v not resolved on the trailing edge layer\n" : "")
       << "c0 = " << shortest(k.c0) << "\n"
       << "# Scales: r -> x (xs: the contact's, xh: the smooth cylinders'), p -> pressure (ps, ph)\n"
       << "xs = " << shortest(xs) << "\nps = " << shortest(ps) << "\nxh = " << shortest(xh) << "\nph = " << shortest(ph)
       << "\n"
       << "set xrange [" << shortest(-x_end) << ":" << shortest(x_end) << "]\n"
       << "set samples 2000\n"  // sub-pixel steps for the monotone cubics of curve()
       << "set grid back lc rgb '#d8d8d8'\n"
       << "set border lw 1.2\n"
       << "set lmargin at screen 0.13\nset rmargin at screen " << (right_axis ? "0.88" : "0.975") << "\n";
    const char* terminals[][2] = {{"svg size 1000,760 enhanced font 'Helvetica,14' background '#ffffff'", ".svg"},
                                  {"pngcairo size 1300,990 enhanced font 'Helvetica,15'", ".png"}};
    for (const auto& t : terminals) {
        gp << "\nset terminal " << t[0] << "\n"
           << "set output out.'" << t[1] << "'\n"
           << "set multiplot title \"" << k.title << "\\n"
           << subtitle << "\"\n";

        // Upper panel: the tractions, the zones named above the frame.
        // (0.83: room above the frame for two rows of narrow zones' names under the title)
        gp << "set tmargin at screen 0.83\nset bmargin at screen 0.355\n"
           << "unset xlabel\nset format x ''\nset format y '%g'\n"
           << "set ylabel \"" << p_name << ",   " << p1_name << p_unit << "\" offset -1.5,0\n"
           << "set yrange [" << shortest(y_bottom * ps) << ":" << shortest(y_top * ps) << "]\n"
           << "set xzeroaxis lt 1 lw 1 lc rgb '#808080'\n"
           // The key in two columns of three across the top, over the room left above the
           // pressure: in the ticks' font (not smaller), it stays clear of the curves.
           << "set key top center maxrows 3 box opaque samplen 2.5 spacing 1.1 width 1\n";
        // Every zone shaded (stick) and named above the frame: a wide one over itself, a narrow
        // one (under an eighth of the contact) on a row of its own above, from its side of the
        // contact, and one thinner than a line (under 2 % of it) marked by a line of its colour.
        int id = 10, left_row = 1, right_row = 1;
        for (std::size_t i = 0; i < k.zones.size(); ++i, ++id) {
            const zone& z = k.zones[i];
            const double width = z.to - z.from, mid = 0.5 * (z.from + z.to);
            const std::string colour = z.stick ? "#1f4e79" : "#8c2d04";
            std::string name = z.stick                    ? "stick zone"
                               : load_sign == 0           ? (z.direction > 0 ? "slip, p_1 > 0" : "slip, p_1 < 0")
                               : z.direction == load_sign ? "slip zone"
                                                          : "reversed slip";
            if (z.stick)
                gp << "set object " << id << " rect from " << shortest(z.from * xs) << ", graph 0 to "
                   << shortest(z.to * xs) << ", graph 1 behind fc rgb '#e3edf7' fs solid 1.0 noborder\n";
            if (width < 0.04) {
                name += " (" + significant(width, 2) + " a wide)";
                gp << "set arrow " << id << " from " << shortest(mid * xs) << ", graph 0 to " << shortest(mid * xs)
                   << ", graph 1 nohead lw 2.5 lc rgb '" << colour << "' front\n";
            }
            std::string where = " center";
            int row = 0;
            if (width < 0.25) {
                row = mid > 0.0 ? right_row++ : left_row++;
                where = mid > 0.0 ? " right" : " left";
            }
            gp << "set label " << id << " \"" << name << "\" at " << shortest(std::clamp(mid, -1.0, 1.0) * xs)
               << ", graph 1 offset 0," << shortest(0.8 + 1.25 * row) << where << " font ',14' tc rgb '" << colour
               << "'\n";
            if (i > 0)  // the boundary with the zone before, dashed
                gp << "set arrow " << 100 + id << " from " << shortest(z.from * xs) << ", graph 0 to "
                   << shortest(z.from * xs) << ", graph 1 nohead lw 1.5 dt 2 lc rgb '#404040' back\n";
        }
        if (right_axis)
            gp << "set yrange [" << shortest(y_bottom / f * ps) << ":" << shortest(y_top * ps) << "]\n"
               << "set y2range [" << shortest(y_bottom * ps) << ":" << shortest(y_top * f * ps) << "]\n"
               << "set ytics nomirror\nset y2tics format '%g' tc rgb '#1f77b4'\n"
               << "set ylabel \"" << p_name << p_unit << "\" offset -1.5,0\n"
               << "set y2label \"" << p1_name << " and {/Symbol \\261} f p" << (k.si ? " (MPa)" : "")
               << "   (right axis: f = " << shortest(f) << ")\" tc rgb '#1f77b4'\n";
        // Drawn in this order: the limits over p1 show p1 = f p on the slip zone (3.5).
        // Columns 4 and 5 are f p and -f p; with Q < 0 the limit p1 follows is -f p.
        const std::string limit = negative ? "-f p" : "f p";
        const std::string other = negative ? "f p" : "-f p";
        const std::string right;  // the right axis' label names its curves: short key entries fit two columns
        gp << "plot " << data << curve(2, "lw 3 lc rgb '#000000'", "normal pressure p") << ", \\\n     ''"
           << curve(3, "lw 3.5 lc rgb '#1f77b4'", "tangential traction p_1" + right, right_axis) << ", \\\n     ''"
           << curve(negative ? 5 : 4, "lw 1.5 lc rgb '#d62728'", "limit " + limit + right, right_axis)
           << ", \\\n     ''" << curve(negative ? 4 : 5, "lw 1.5 dt 2 lc rgb '#d62728'", other, right_axis)
           << ", \\\n     ''" << curve(8, "lw 1.5 dt 3 lc rgb '#505050'", "Hertz p (smooth)", false, true)
           << ", \\\n     ''" << curve(9, "lw 1.5 dt 4 lc rgb '#5fa2dd'", "Carter p_1 (smooth)", right_axis, true)
           << "\n";

        // Lower panel: the slip velocity, zero on the stick zone (3.2), with the sign of Q
        // on the slip zone (3.4); c0 named beside the dashed line, on the stick side.
        gp << "unset label\nunset key\nunset y2tics\nunset y2label\nset ytics mirror\n"
           << "set tmargin at screen 0.325\nset bmargin at screen 0.085\n"
           << "set format x '%g'\nset xlabel \"" << (k.si ? "x_1   (mm)" : "r = x_1/a") << "\"\n"
           << "set ylabel \"slip velocity v\\n(scaled as {/Symbol x})\" offset -1.5,0\n";
        // Room above (below) a velocity of either sign, a thin margin on a side that is only 0.
        if (const double span = k.v_high - k.v_low; span > 0.0)
            gp << "set yrange [" << shortest(k.v_low - (k.v_low < 0.0 ? 0.15 : 0.08) * span) << ":"
               << shortest(k.v_high + (k.v_high > 0.0 ? 0.15 : 0.08) * span) << "]\n";
        else
            gp << "set yrange [-1:1]\n";
        if (has_stick && has_slip) {
            const bool left = k.c0 > -0.55;
            gp << "set label 3 \""
               << (k.si ? "c = " + significant(k.c0 * xs, 3) + " mm" : "c_0 = " + significant(k.c0, 3))
               << "\" at c0*xs, graph " << (negative ? 0.25 : 0.6)
               << (left ? " right offset -0.8,0" : " left offset 0.8,0") << " font ',14'\n";
        }
        gp << "plot " << data << curve(7, "lw 3 lc rgb '#2ca02c'", "") << "\n"
           << "unset label\nunset object\nunset arrow\nunset multiplot\nset output\n";
    }
}

}  // namespace

void add_traction_options(CLI::App* cmd, traction_options& o) {
    add_scene_options(cmd, o.scene);
    add_load_options(cmd, o.load);
    add_integer(cmd, "--points", o.points, "grid points on [-1, 1]");
    cmd->add_option("--out", o.out, "output folder, created if missing");
    cmd->add_option("--name", o.name, "file stem after 'traction-' (default: the scene file's stem)");
    cmd->add_flag("!--no-plot", o.plot, "write the CSV and the gnuplot script only");
}

int run_traction(const traction_options& o) {
    if (o.points < 3 || o.points > 100000) throw input_error("--points must lie in [3, 100000]");
    const bool named = !o.name.empty();
    const std::string name = named ? o.name : std::filesystem::path(o.scene.path).stem().string();
    const bool control = std::any_of(name.begin(), name.end(),
                                     [](char ch) { return static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f; });
    if (name.empty() || control || name.find('/') != std::string::npos || name == "." || name == "..") {
        // The default name is the scene file's: then the scene's name is the problem, not --name.
        if (named) throw input_error("--name '" + echo(name) + "' is not a file name");
        throw input_error("the scene file's name '" + echo(name) + "' cannot name the output files" +
                          (control ? " (it holds a control character)" : "") + ": give --name NAME");
    }

    scene s = load_scene(o.scene);
    // The outputs, checked and opened before any work: a bad --out costs no solve.
    plot_files files(output_stem(o.out, "traction-" + name), s.files);

    const double Q = load_of(s, o.load.given());
    progress("traction " + name + ": solving the point at Q = " + shortest(Q) +
             (s.physical ? " (its contact width first)" : ""));
    const auto start = std::chrono::steady_clock::now();
    // The point as `point` solves it (without n the ladder chooses n: problems/level_ladder.hpp; refused as there), with
    // its estimate and width, as Python's Scene.traction: the header's numbers carry the point's estimates.
    scene_point sp = solve_point(s, Q);
    contact& c = sp.solved;
    const tangential_solution& solution = sp.solution;
    const tangential_solution level = c.distribution(solution);  // the distributions' own c0 and xi
    {
        std::ostringstream line;
        line << "traction " << name << ": solved in " << std::setprecision(3)
             << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s; tractions on "
             << o.points << " points";
        progress(line.str());
    }
    const normal_solution& normal = c.normal();
    const double f = s.friction;

    std::vector<double> grid(static_cast<std::size_t>(o.points));
    for (int i = 0; i < o.points; ++i)
        grid[i] = static_cast<double>(2 * i - (o.points - 1)) / (o.points - 1);  // -1 and 1 exactly
    const point_report report = sp.report();
    const std::optional<si_point>& si = report.si;
    const std::vector<traction_row> rows = traction_table(c, level, grid, Q, f, si);
    double p_max = 0.0;
    double v_low = 0.0, v_high = 0.0;
    for (const traction_row& row : rows) {
        p_max = std::max(p_max, row.p);
        if (std::isnan(row.v)) continue;  // not resolved (the trailing edge layer, formulation 8(n)): no value
        v_low = std::min(v_low, row.v);
        v_high = std::max(v_high, row.v);
    }
    const bool unresolved = std::any_of(rows.begin(), rows.end(), [](const traction_row& row) { return std::isnan(row.v); });

    std::ostream& out = files.csv_file.stream();
    out << "# roughroll " << version() << "\n"
        << "# roughroll traction " << one_line(o.scene.path) << (s.label.empty() ? "" : ": ") << one_line(s.label)
        << "\n"
        << "# Q = " << shortest(Q) << ", f = " << shortest(f) << ", c0 = " << shortest(solution.c0())
        << ", xi = " << shortest(solution.xi) << ", P_H/P2 = " << shortest(normal.lambda)
        << ", method = " << to_string(normal.how) << ", n = " << normal.rule.n
        << ", checks = " << (solution.checks.hold() ? "hold" : "VIOLATED") << "\n"
        // The rows are level n's distributions; with Richardson's c0 (method extrapolated) the header's c0 is not their
        // zone end (they differ within c0's estimate): the line says so where they differ (docs/cli.md, `traction`).
        << "# zones (r = x1/a" << (level.c0() == solution.c0() ? std::string()
                                   : "; the rows' own, at n = " + std::to_string(normal.rule.n) +
                                         ", where the header's c0 is extrapolated")
        << "): " << zones_text(level) << "\n"
        << "# r = x1/a; p = a p2/P2; p1 = a p1/P2 (3.15); zone: stick or slip, the zones above;"
           " slip_velocity: v of (3.6), scaled as xi; p_hertz, p1_carter: smooth cylinders, same Q and f\n";
    if (unresolved)
        out << "# slip_velocity '-': not resolved, on the trailing edge layer (slip, a stick zone and reversed slip"
               " within the slip zone reported there; its velocity changes sign; docs/formulation.md 8(n))\n";
    if (si)
        out << "# SI: a = " << shortest(si->a) << " m (Hertz " << shortest(si->a_hertz)
            << " m), P2 = " << shortest(si->P2) << " N/m, xi1 = " << shortest(si->xi1)
            << "; x1_m = r a, p2_Pa = p P2/a, p1_Pa = p1 P2/a\n";
    // The point's estimates (the rows' distributions have none of their own: docs/cli.md), the SI ones scaled
    // (docs/formulation.md 2(j), "The SI values' estimates").
    if (sp.estimate) {
        out << "# error estimate: c0 " << shortest(sp.estimate->c0) << ", xi " << shortest(sp.estimate->xi)
            << ", P_H/P2 " << shortest(sp.estimate->lambda);
        if (si) {
            const si_estimate e = estimate_si(*si, *sp.estimate, solution.Q, solution.c0(), solution.xi);
            out << "; SI: a " << shortest(e.a) << " m, P2 " << shortest(e.P2) << " N/m, xi1 " << shortest(e.xi1);
        }
        out << "\n";
    } else {
        out << "# error estimate: none (as `roughroll point` says why)\n";
    }
    out << "r,p,p1,f_p,minus_f_p,zone,slip_velocity,p_hertz,p1_carter" << (si ? ",x1_m,p2_Pa,p1_Pa" : "") << "\n";
    for (const auto& row : rows) {
        out << shortest(row.r) << ',' << shortest(row.p) << ',' << shortest(row.p1) << ',' << shortest(f * row.p) << ','
            << shortest(-f * row.p) << ',' << (row.stick ? "stick" : "slip") << ','
            << (std::isnan(row.v) ? std::string("-") : shortest(row.v)) << ','
            << shortest(row.p_hertz) << ',' << shortest(row.p1_carter);
        if (si) out << ',' << shortest(*row.x1_m) << ',' << shortest(*row.p2_Pa) << ',' << shortest(*row.p1_Pa);
        out << '\n';
    }
    files.csv_file.commit();

    plot_facts facts{};
    facts.title = "Tractions over the contact: " +
                  gnuplot_text(s.label.empty() ? std::filesystem::path(o.scene.path).filename().string() : s.label);
    facts.Q = Q;
    facts.f = f;
    facts.c0 = level.c0();             // the stick zone the plotted tractions have
    facts.zones = level.layout.zones;  // the zones the plotted tractions have
    facts.xi = solution.xi;
    facts.lambda = normal.lambda;
    facts.p_max = p_max;
    facts.v_low = v_low;
    facts.v_high = v_high;
    facts.v_unresolved = unresolved;
    facts.checks_hold = solution.checks.hold();
    facts.si = si;
    write_traction_gnuplot(files.script_file.stream(), files.csv, files.stem, facts);
    files.script_file.commit();
    if (!o.plot) return 0;
    run_gnuplot(files.script, files.stem, {".svg", ".png"});
    return 0;
}

}  // namespace roughroll::cli
