// SPDX-License-Identifier: GPL-3.0-or-later
// `roughroll roughness SPEC [--json]`: the roughness parameters k, t, alpha of (2.11)-(2.15)
// of a micro-geometry spec (micro_geometry_input.hpp), with the averages (2.9) they use and the
// quadrature's error estimates. SI units: k in Pa/m, t in Pa m, alpha in 1/m.
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "roughroll/io/micro_geometry_input.hpp"
#include "roughroll/io/roughness_output.hpp"
#include "roughroll/layer/roughness_parameters.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll::cli {
namespace {

std::string error_text(double e) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1e", e);
    return buffer;
}

void write_text(std::ostream& out, const std::string& spec, const micro_geometry& g, const roughness_parameters& p) {
    const layer& m = g.material;
    out << "roughness parameters (2.11)-(2.15) of " << one_line(spec) << "\n";
    out << "  layer: lambda0 = " << significant(m.lambda0, 12) << " Pa, mu0 = " << significant(m.mu0, 12)
        << " Pa, H = " << significant(m.H, 12) << " m, l = " << significant(m.l, 12) << " m\n";
    out << "  profile " << to_string(g.bottom.kind);
    if (g.bottom.kind == profile_kind::sine || g.bottom.kind == profile_kind::sawtooth)
        out << " (delta = " << significant(g.bottom.delta, 12) << " m)";
    if (g.bottom.kind == profile_kind::measured)
        out << " (" << g.bottom.measured.x1.size() << " samples from " << one_line(g.bottom.measured.source) << ")";
    out << ", micro-shape " << to_string(g.shape) << ", decay " << to_string(g.decay) << ", factor of (2.12) "
        << to_string(g.factor_2_12) << "\n\n";
    const auto row = [&out](const char* name, const char* unit, double t, double te, double n, double ne) {
        char line[160];
        std::snprintf(line, sizeof line, "  %-6s %-5s  %20s +- %-8s  %20s +- %-8s\n", name, unit,
                      significant(t, 12).c_str(), error_text(te).c_str(), significant(n, 12).c_str(),
                      error_text(ne).c_str());
        out << line;
    };
    char header[160];
    std::snprintf(header, sizeof header, "  %-6s %-5s  %31s  %31s\n", "", "", "tangential (1)", "normal (2)");
    out << header;
    row("k", "Pa/m", p.k_tangential, p.k_tangential_error, p.k_normal, p.k_normal_error);
    row("t", "Pa m", p.t_tangential, p.t_tangential_error, p.t_normal, p.t_normal_error);
    row("alpha", "1/m", p.alpha_tangential, p.alpha_tangential_error, p.alpha_normal, p.alpha_normal_error);
    out << "\n  averages (2.9), with the quadrature's error estimates:\n";
    const auto average = [&out](const char* name, const char* unit, double v, double e) {
        char line[160];
        std::snprintf(line, sizeof line, "    %-10s = %20s +- %-8s %s\n", name, significant(v, 12).c_str(),
                      error_text(e).c_str(), unit);
        out << line;
    };
    average("<a>", "m", p.averages.a, p.averages_error.a);
    average("<a3 h_1>", "", p.averages.a3_h1, p.averages_error.a3_h1);
    average("<a33>", "1/m", p.averages.a33, p.averages_error.a33);
    average("<a h_1>", "m", p.averages.a_h1, p.averages_error.a_h1);
    average("<a h_1^2>", "m", p.averages.a_h1_squared, p.averages_error.a_h1_squared);
    out << "  (" << p.evaluations << " points x1 of the outer quadratures)\n";
}

}  // namespace

void add_roughness_options(CLI::App* cmd, roughness_options& o) {
    cmd->add_option("SPEC", o.spec, "micro-geometry spec (TOML; docs/roughness-parameters.md)")->required();
    cmd->add_flag("--json", o.json, "one JSON object on stdout");
}

int run_roughness(const roughness_options& o) {
    const micro_geometry g = read_roughness_spec(o.spec);
    const roughness_parameters p = compute_roughness_parameters(g);
    if (o.json)
        std::cout << dump(to_json(o.spec, g, p)) << "\n";
    else
        write_text(std::cout, o.spec, g, p);
    return 0;
}

}  // namespace roughroll::cli
