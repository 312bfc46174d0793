// SPDX-License-Identifier: GPL-3.0-or-later
// `roughroll convergence SCENE`: error against run time for every method (the
// work-precision study of docs/performance.md). The reference is the extrapolated method
// at n = 512, checked against an independent route: the paper's node-sum scheme at 300
// and 600 extrapolated for its order 2, (4 v_600 - v_300)/3.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#include "cli/commands.hpp"
#include "cli/output_files.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/io/output.hpp"

namespace roughroll::cli {

namespace {

struct values {
    double lambda, c0, xi;
};

struct measurement {
    method how;
    int n;
    double seconds;  // median wall time of a whole point: normal solve, Brent search, checks
    values v;
    double estimate_xi;
};

values solve_point(const scene& s, double Q, int n, method how, double* seconds = nullptr) {
    const auto start = std::chrono::steady_clock::now();
    contact c(s.surfaces, s.friction, solver_options{n, how}, s.materials);
    const tangential_solution p = c.point(Q);
    if (seconds) *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {c.normal().lambda, p.c0(), p.xi};
}

// The median of three runs (one run when a run takes longer than a second).
measurement measure(const scene& s, double Q, int n, method how) {
    std::vector<double> times;
    values v{};
    for (int run = 0; run < 3; ++run) {
        double t = 0.0;
        v = solve_point(s, Q, n, how, &t);
        times.push_back(t);
        if (t > 1.0) break;
    }
    std::sort(times.begin(), times.end());
    contact c(s.surfaces, s.friction, solver_options{n, how}, s.materials);
    const auto e = c.estimate(c.point(Q));
    return {how, n, times[times.size() / 2], v, e ? e->xi : NAN};
}

double relative(double value, double reference) {
    return reference == 0.0 ? std::fabs(value) : std::fabs(value - reference) / std::fabs(reference);
}

}  // namespace

void add_convergence_options(CLI::App* cmd, convergence_options& o) {
    cmd->add_option("SCENE", o.scene.path, "scene file (TOML)")->required();
    add_load_options(cmd, o.load);
    cmd->add_option("--out", o.out, "output folder for the CSV and the plot");
    add_number(cmd, "--max-seconds", o.max_seconds, "stop a method's ladder once a point takes longer")
        ->check(CLI::Range(0.001, 600.0));
    cmd->add_flag("!--no-plot", o.plot, "write the CSV and the gnuplot script only");
}

int run_convergence(const convergence_options& o) {
    scene s = load_scene(o.scene);
    const double Q = load_of(s, o.load.given());
    if (Q == 0.0) throw input_error("Q = 0 is solved exactly without a discretisation: nothing to converge");
    // The outputs, checked and opened before the minutes of work.
    const std::string name = "convergence-" + std::filesystem::path(o.scene.path).stem().string();
    plot_files files(output_stem(o.out, name), s.files);

    settle_width(s, nullptr, Q);  // a physical scene: the roughness at the width for its load
    if (s.surfaces.smooth())
        throw input_error("the scene is smooth (no roughness term" + std::string(s.physical ? " at its width" : "") +
                          "): every method gives Carter's closed form exactly at every n, nothing to converge");

    progress("convergence: the reference, extrapolated at n = 512");
    const values ref = solve_point(s, Q, 512, method::extrapolated);
    std::printf("reference (extrapolated, n = 512): P_H/P2 = %.15g, c0 = %.15g, xi = %.15g\n", ref.lambda, ref.c0,
                ref.xi);
    try {
        progress("convergence: the independent check, the paper's scheme at n = 300 and 600");
        const values a = solve_point(s, Q, 300, method::paper), b = solve_point(s, Q, 600, method::paper);
        auto r2 = [](double coarse, double fine) { return (4.0 * fine - coarse) / 3.0; };
        std::printf(
            "independent check (paper scheme, 300 and 600, extrapolated for order 2): relative differences "
            "P_H/P2 %.1e, c0 %.1e, xi %.1e\n",
            relative(r2(a.lambda, b.lambda), ref.lambda), std::fabs(r2(a.c0, b.c0) - ref.c0),
            relative(r2(a.xi, b.xi), ref.xi));
    } catch (const resolution_error& e) {
        std::printf("independent check skipped: %s\n", e.what());
    }

    const int ladder[] = {4, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1000};
    std::vector<measurement> rows;
    std::printf("%-13s %5s %11s %10s %10s %10s %12s\n", "method", "n", "seconds", "err P_H/P2", "err c0", "err xi",
                "estimate xi");
    for (method how : {method::paper, method::product, method::extrapolated}) {
        for (int n : ladder) {
            measurement m{};
            progress("convergence: " + to_string(how) + ", n = " + std::to_string(n));
            try {
                m = measure(s, Q, n, how);
            } catch (const resolution_error&) {
                continue;  // this n cannot resolve the kernels: the method starts higher
            }
            rows.push_back(m);
            std::printf("%-13s %5d %11.3e %10.2e %10.2e %10.2e %12.2e\n", to_string(how).c_str(), n, m.seconds,
                        relative(m.v.lambda, ref.lambda), std::fabs(m.v.c0 - ref.c0), relative(m.v.xi, ref.xi),
                        m.estimate_xi / std::fabs(ref.xi));
            if (m.seconds > o.max_seconds) break;
        }
    }

    std::ostream& out = files.csv_file.stream();
    out << "# roughroll " << version() << "\n"
        << "# roughroll convergence " << one_line(o.scene.path) << ", Q = " << shortest(Q)
        << "; errors against the extrapolated "
        << "method at n = 512 (relative for P_H/P2 and xi, absolute for c0)\n"
        << "method,n,seconds,err_lambda,err_c0,err_xi,err_max,estimate_xi\n";
    for (const auto& m : rows) {
        const double el = relative(m.v.lambda, ref.lambda), ec = std::fabs(m.v.c0 - ref.c0),
                     ex = relative(m.v.xi, ref.xi);
        out << to_string(m.how) << ',' << m.n << ',' << shortest(m.seconds) << ',' << shortest(el) << ','
            << shortest(ec) << ',' << shortest(ex) << ',' << shortest(std::max({el, ec, ex})) << ','
            << shortest(m.estimate_xi / std::fabs(ref.xi)) << '\n';
    }
    files.csv_file.commit();

    std::ostream& gp = files.script_file.stream();
    gp << gnuplot_output_stem(files.stem)
       << "set datafile separator ','\nset logscale xy\nset grid\nset key top right box opaque\n"
       // Powers of ten on both axes (the default printed 0.000010 ... 10.00000, the last one
       // cut at the right edge, which the right margin now leaves room for).
       << "set format x '10^{%L}'\nset format y '10^{%L}'\nset rmargin 5\n"
       << "set xlabel 'run time of one point (s): normal solve, Brent search for c_0, checks'\n"
       << "set ylabel 'largest error in P_H/P_2, c_0, {/Symbol x} (relative; c_0 absolute)'\n"
       << "set title 'Error against run time: " << gnuplot_path(name) << ", Q = " << shortest(Q) << "' noenhanced\n";
    const char* terminals[][2] = {{"svg size 900,640 enhanced font 'Helvetica,13'", ".svg"},
                                  {"pngcairo size 1200,850 enhanced font 'Helvetica,13'", ".png"}};
    for (const auto& t : terminals) {
        gp << "set terminal " << t[0] << "\nset output out.'" << t[1] << "'\nplot ";
        const char* sep = "";
        for (method how : {method::paper, method::product, method::extrapolated}) {
            gp << sep << "'" << gnuplot_path(files.csv.filename()) << "' using 3:(strcol(1) eq '" << to_string(how)
               << "' ? $7 : NaN) with linespoints lw 2 pt 7 title '" << to_string(how) << "'";
            sep = ", \\\n     ";
        }
        gp << "\n";
    }
    gp << "unset output\n";
    files.script_file.commit();
    if (o.plot) run_gnuplot(files.script, files.stem, {".svg", ".png"});
    std::printf("written: %s (.csv, .gp%s)\n", one_line(files.stem.string()).c_str(), o.plot ? ", .svg, .png" : "");
    return 0;
}

}  // namespace roughroll::cli
