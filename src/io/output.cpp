// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <gsl/gsl_math.h>

#include "roughroll/io/si_estimate.hpp"
#include "roughroll/model/carter.hpp"
#include "roughroll/problems/edge_layers.hpp"
#include "roughroll/problems/creep_curve.hpp"

// The build systems define it from the VERSION file (CMakeLists.txt, Makefile.am).
#ifndef ROUGHROLL_VERSION
#error "ROUGHROLL_VERSION (the VERSION file's X.Y.Z) must be defined when output.cpp is compiled"
#endif

namespace roughroll {

const char* version() { return ROUGHROLL_VERSION; }

std::string ratio_text(double q, int digits) {
    for (int d = std::max(digits, 1); d < 17; ++d) {
        std::ostringstream text;
        text << std::setprecision(d) << q;
        if (std::fabs(q) == 1.0 || !std::isfinite(q) || std::fabs(std::strtod(text.str().c_str(), nullptr)) != 1.0)
            return text.str();
    }
    return shortest(q);
}

namespace {
nlohmann::json term_json(const roughness_term& t) {
    if (!t.present()) return nullptr;
    return {{"T", t.T}, {"A", t.A}};
}

nlohmann::json cylinder_json(const cylinder_roughness& c) {
    return {{"tangential", term_json(c.tangential)}, {"normal", term_json(c.normal)}};
}

// The zones of docs/formulation.md section 7, from r = -1 to 1: the solution's layout.
nlohmann::json zones_json(const tangential_solution& s) {
    nlohmann::json zones = nlohmann::json::array();
    for (const zone& z : s.layout.zones)
        zones.push_back(
            {{"from", z.from}, {"to", z.to}, {"state", z.stick ? "stick" : "slip"}, {"direction", z.direction}});
    return zones;
}

// single, general, or no-slip (the edge layers neglected, docs/formulation.md 8(n)).
const char* zone_path(const tangential_solution& s) { return to_string(s.layout.route); }

// The closed form that gave the point's traction and creep, where no zone search did; the method and n
// are then the pressure's. Null for every other point. (Carter's closed form of smooth equal rollers is
// not told apart here: the solution does not carry the kernels.)
const char* closed_form(const tangential_solution& s, bool full) {
    if (s.layout.layers_neglected())
        return full ? "no slip at full coupling with the edge layers neglected (docs/formulation.md 8(t))"
                    : "no slip with the edge layers neglected (docs/formulation.md 8(n))";
    if (std::fabs(s.Q) == s.f) return "gross sliding (docs/formulation.md 2(g), 8(g))";
    if (s.Q == 0.0 && s.forcing == 0.0) return "full stick (c0 = 1, xi = 0)";
    return nullptr;
}

// The neglected edge layers of a free-rolling point at large friction (8(n); full coupling's, 8(t), where `full`):
// null for every other point.
nlohmann::json layers_json(const tangential_solution& s, bool full) {
    if (!s.layout.layers_neglected()) return nullptr;
    const neglected_layers l = neglected_layers_at(s.forcing, s.f, full);
    nlohmann::json layers = {{"neglected", true},      {"thickness_bound", l.thickness}, {"crossing", l.crossing},
                             {"xi_shift", l.xi_shift}, {"xi_bound", l.xi_bound},         {"leading", l.leading},
                             {"trailing", l.trailing}};
    if (full) layers["hertz_load_ratio_bound"] = l.lambda_bound;  // 8(t): the pressure moves with the layers
    return layers;
}

// The SI values' estimates under the keys of the values they bound (si_point's JSON); a_hertz_m and xi1_carter are
// closed forms.
nlohmann::json si_estimate_json(const si_estimate& e) {
    const auto optional = [](const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); };
    return {{"a_m", e.a},
            {"a_over_a_hertz", e.a_over_a_hertz},
            {"c_m", e.c},
            {"P_H_N_per_m", e.P_H},
            {"P2_N_per_m", e.P2},
            {"P1_N_per_m", e.P1},
            {"xi1", e.xi1},
            {"p_centre_Pa", optional(e.p_centre)},
            {"p_peak_Pa", optional(e.p_peak)},
            {"x_peak_m", optional(e.x_peak)},
            {"roughness_at_a_relative", e.surfaces_relative}};
}

// gamma_0n's estimate: at full coupling its levels' (error_estimate::coupling; none on the edge layers' closed form);
// elsewhere the model's gamma is 0 exactly ((4.8): the normal problem's solvability, docs/formulation.md section 3), so
// |gamma_0n| is its distance, not an estimate of it.
// NaN where it has none (a printed-only estimate, below).
double gamma_estimate(const point_report& r) {
    if (!r.coupling) return std::fabs(r.normal.gamma);
    return r.estimate && r.estimate->coupling ? r.estimate->coupling->gamma : std::numeric_limits<double>::quiet_NaN();
}

// A printed-only estimate (error_estimate::coupling's, peak_error::centre): NaN where it has none. In the text, "none"
// there, else the estimate times `scale` followed by `unit` (the peak's relative change in %).
nlohmann::json estimate_or_null(double x) { return std::isnan(x) ? nlohmann::json(nullptr) : nlohmann::json(x); }
std::string estimate_text(double x, double scale = 1.0, const std::string& unit = "") {
    return std::isnan(x) ? std::string("none") : shortest(scale * x) + unit;
}

std::string term_text(const roughness_term& t) {
    return t.present() ? "T " + shortest(t.T) + ", A " + shortest(t.A) : std::string("smooth");
}
}  // namespace

std::string zones_text(const tangential_solution& s) {
    std::string text;
    for (const zone& z : s.layout.zones) {
        if (!text.empty()) text += ", ";
        text += zone_kind(z) + std::string(" [") + shortest(z.from) + ", " +
                shortest(z.to) + "]";
    }
    return text;
}

namespace {
// Why a point carries no error estimate (contact::estimate); empty when it carries one.
std::string no_estimate_reason(const point_report& r) {
    if (r.estimate) return "";
    if (!r.solution.checks.hold())
        return "none: the checks (3.3)-(3.4) fail, so this answer is not the model's solution and no difference "
               "between levels bounds its error";
    return "unavailable (the estimate's levels do not fit: one below n is too coarse for the kernels, or one above "
           "n (2n, or 4n for the paper's method) beyond the largest n)";
}
}  // namespace

nlohmann::json to_json(const point_report& r) {
    const auto& s = r.solution;
    const carter_point smooth = carter(s.Q, s.f);
    const pressure_peak peak = peak_of(r.normal);
    nlohmann::json checks = {
        {"pressure_nonnegative", s.checks.pressure_holds},
        {"stick_traction_bound_3_3", s.checks.stick_holds},
        {"slip_velocity_positive_3_4", s.checks.slip_holds},
        {"pressure_margin", s.checks.pressure_margin},
        {"stick_margin", s.checks.stick_margin},
        {"slip_margin", s.checks.slip_margin},
        {"stick_margin_rounding", s.checks.stick_rounding},
        {"slip_margin_rounding", s.checks.slip_rounding},
    };
    nlohmann::json estimate = nullptr;
    if (r.estimate)
        estimate = {{"hertz_load_ratio", r.estimate->lambda},
                    {"c0", r.estimate->c0},
                    {"xi", r.estimate->xi},
                    {"against", r.estimate->against}};
    if (r.estimate && r.estimate->start != 0.0) estimate["stick_start"] = r.estimate->start;  // dissimilar rollers
    if (r.estimate && r.estimate->peak) {
        estimate["pressure_peak_r"] = r.estimate->peak->r;
        estimate["pressure_peak_p"] = r.estimate->peak->p;
    }
    if (r.estimate) estimate["gamma"] = estimate_or_null(gamma_estimate(r));
    if (r.estimate && r.estimate->zone_ends) {
        // Full coupling's zone ends each with its own estimate, by one Richardson level where clean (docs/formulation.md
        // 8(q)): beside level n's (c0, stick_start, zones). Only there: other points' keys unchanged.
        const zone_end_values& x = *r.estimate->zone_ends;
        const auto end = [](const std::optional<zone_end_value>& v) {
            return v ? nlohmann::json{{"value", v->value},
                                      {"error_estimate", v->error},
                                      {"extrapolated", v->extrapolated}}
                     : nlohmann::json(nullptr);
        };
        nlohmann::json ends = {{"c0", end(x.c0)}, {"stick_start", end(x.start)}};
        if (s.layout.stick_zones() == 2) {
            ends["second_zone_end"] = end(x.end2);
            ends["second_zone_start"] = end(x.start2);
        }
        estimate["zone_ends"] = ends;
    }
    nlohmann::json si = nullptr;
    if (r.si) {
        si = {{"a_m", r.si->a},
              {"a_hertz_m", r.si->a_hertz},
              {"a_over_a_hertz", r.si->a / r.si->a_hertz},
              {"c_m", r.si->c},
              {"P_H_N_per_m", r.si->P_H},
              {"P2_N_per_m", r.si->P2},
              {"P1_N_per_m", r.si->P1},
              {"xi1", r.si->xi1},
              {"xi1_carter", r.si->xi1_carter},
              {"p_centre_Pa", r.si->p_scale * peak.centre},
              {"p_peak_Pa", r.si->p_scale * peak.p},
              {"x_peak_m", r.si->a * peak.r},
              {"width_iterations", r.si->width_iterations},
              {"roughness_at_a",
               {{"cylinder1", cylinder_json(r.si->surfaces.cylinder1)},
                {"cylinder2", cylinder_json(r.si->surfaces.cylinder2)}}}};
        // Each SI value's estimate from the dimensionless ones by its scaling (docs/formulation.md 2(j), "The SI
        // values' estimates"); none where the point has none (error_estimate_absent says why).
        si["error_estimate"] = r.estimate ? si_estimate_json(estimate_si(*r.si, *r.estimate, s.Q, s.c0(), s.xi, peak))
                                          : nlohmann::json(nullptr);
    }
    nlohmann::json coupling = nullptr;  // docs/formulation.md 8(e): the level, and what full coupling measured
    if (s.forcing != 0.0) coupling = {{"level", r.coupling ? "full" : "johnson"}};
    if (r.coupling)
        coupling.update({{"offset_e", r.coupling->offset},
                         {"hertz_load_ratio_johnson", r.coupling->lambda_johnson},
                         {"peak_pressure_change", r.coupling->peak_pressure_change},
                         {"iterations", r.coupling->iterations},
                         {"start_level", r.coupling->start_level},
                         {"contraction", r.coupling->contraction},
                         {"newton_residuals", r.coupling->newton_residuals},
                         {"newton_jacobians", r.coupling->newton_jacobians}});
    // The measured values' estimates from the point's levels (docs/formulation.md 8(e), "The measured values'
    // estimates"); none on the edge layers' closed form or where the point has no estimate. contraction, iterations and
    // the Newton counts describe the alternation, not the model: no estimate.
    if (r.coupling) {
        const std::optional<coupling_values> e = r.estimate ? r.estimate->coupling : std::nullopt;
        coupling["error_estimate"] = e ? nlohmann::json{{"offset_e", estimate_or_null(e->offset)},
                                                         {"hertz_load_ratio_johnson", estimate_or_null(e->lambda_johnson)},
                                                         {"peak_pressure_change", estimate_or_null(e->peak_change)}}
                                       : nlohmann::json(nullptr);
    }
    nlohmann::json point = {
        {"label", r.label},
        {"coupling", coupling},
        {"si", si},
        {"error_estimate", estimate},
        {"error_estimate_absent", r.estimate ? nlohmann::json(nullptr) : nlohmann::json(no_estimate_reason(r))},
        {"Q", s.Q},
        {"f", s.f},
        {"c0", s.c0()},
        {"stick_start", s.start()},
        {"zones", zones_json(s)},
        {"zone_path", zone_path(s)},
        // Dundurs' beta_D of the solution (docs/formulation.md 8): its forcing is sigma beta_D, sigma = sign.
        {"beta_d", s.sign * s.forcing},
        {"xi", s.xi},
        {"hertz_load_ratio", r.normal.lambda},
        {"pressure_peak", {{"r", peak.r}, {"p", peak.p}, {"r_resolution", peak.r_resolution}}},
        {"gamma", r.normal.gamma},
        {"n", r.normal.rule.n},
        {"method", to_string(r.normal.how)},
        {"seconds", r.seconds},
        {"checks_hold", s.checks.hold()},
        {"checks", checks},
        {"c0_carter", smooth.c0},
        {"xi_carter", smooth.xi},
        {"brent_iterations", s.iterations},
        {"rcond_normal", r.normal.rcond},
        {"rcond_tangential", s.rcond},
        {"reference", paper_reference},
        {"version", version()},
    };
    if (s.layout.layers_neglected()) point["edge_layers"] = layers_json(s, r.coupling.has_value());  // only there: other points' keys unchanged
    return point;
}

void write_summary(std::ostream& out, const point_report& r) {
    const auto& s = r.solution;
    const carter_point smooth = carter(s.Q, s.f);
    const pressure_peak peak = peak_of(r.normal);
    if (!r.label.empty()) out << one_line(r.label) << "\n";  // no control character reaches the terminal
    out << "  Q = P1/P2           " << shortest(s.Q) << "   (Q/f = " << shortest(s.Q / s.f) << ", f = " << shortest(s.f)
        << ")\n"
        << "  P_H/P2              " << shortest(r.normal.lambda) << "\n"
        << "  peak pressure p     " << shortest(peak.p) << " P2/a at r = " << shortest(peak.r) << "\n"
        << "  gamma_0n            " << shortest(r.normal.gamma) << "\n"
        << "  c0 = c/a            " << shortest(s.c0()) << "   (Carter " << shortest(smooth.c0) << ")\n"
        << "  zones (r = x1/a)    " << zones_text(s) << "   (" << zone_path(s) << " zone search)\n"
        << "  xi (creep)          " << shortest(s.xi) << "   (Carter " << shortest(smooth.xi) << ")\n"
        << "  method, n           ";
    if (const char* form = closed_form(s, r.coupling.has_value()))
        out << "closed form: " << form << "; pressure " << to_string(r.normal.how) << ", n = " << r.normal.rule.n
            << "\n";
    else
        out << to_string(r.normal.how) << ", " << r.normal.rule.n << "\n";
    if (s.forcing != 0.0 && !r.coupling)
        out << "  beta_d (Dundurs)    " << shortest(s.sign * s.forcing) << "   (Johnson's level: pressure uncoupled)\n";
    if (s.forcing != 0.0 && r.coupling) {
        out << "  beta_d (Dundurs)    " << shortest(s.sign * s.forcing);
        if (s.layout.layers_neglected())  // docs/formulation.md 8(t): no alternation
            out << "   (full coupling: the no-slip limit in closed form)\n";
        else
            out << "   (full coupling: " << r.coupling->iterations << " normal solves after "
                << (r.coupling->start_level > 0 ? "level " + std::to_string(r.coupling->start_level) + "'s coupling"
                                                : std::string("Johnson's"))
                << ", contraction " << shortest(r.coupling->contraction) << ")\n";
        out << "  offset e = x_c/a    " << shortest(r.coupling->offset) << "   (P_H/P2 at Johnson's level "
            << shortest(r.coupling->lambda_johnson) << "; peak pressure at the same P2 changed by "
            << shortest(100.0 * r.coupling->peak_pressure_change) << " %)\n";
    }
    if (s.layout.layers_neglected() && r.coupling) {
        const neglected_layers l = coupled_no_slip_layers(s.forcing, s.f);
        out << "  edge layers         neglected: each thinner than " << shortest(l.thickness)
            << " (twice the crossing where |p1| of the no-slip limit exceeds f p); xi and P_H/P2 the limit's, within "
            << shortest(l.xi_bound) << " and " << shortest(l.lambda_bound)
            << " of the model's (a bound on two measured premises); the layers' slip not resolved: stick reported on "
               "[-1, 1] (docs/formulation.md 8(t))\n";
    } else if (s.layout.layers_neglected()) {
        const neglected_layers l = no_slip_layers(s.forcing, s.f);
        const double exponent = M_PI * s.f / std::fabs(s.forcing);  // t = 4/(1 + exp(pi f/|beta_d|))
        out << "  edge layers         neglected: each thinner than " << shortest(l.thickness) << " (about 4 exp(-"
            << shortest(exponent) << "), where |p1| of no slip exceeds f p); xi with their first-order shift "
            << shortest(l.xi_shift) << ", within " << shortest(l.xi_bound)
            << " of the model's; the leading layer's slip velocity from its inner problem; the trailing slip zone "
               "is the trailing layer (slip, stick, reversed slip, not resolved: its slip velocity not available, "
               "'-' in the traction table) (docs/formulation.md 8(n))\n";
    }
    // Five zones: c0's and the start's estimates are each the larger of the two stick zones' (zone_ends_table), so
    // they bound the second zone's ends printed among the zones too, and say so.
    const bool two = s.layout.stick_zones() == 2;
    if (r.estimate)
        out << "  error estimate      P_H/P2 " << shortest(r.estimate->lambda)
            << (two ? ", c0 and the second stick zone's end " : ", c0 ") << shortest(r.estimate->c0)
            << (r.estimate->start != 0.0
                    ? (two ? ", stick start and the second stick zone's start " : ", stick start ") +
                          shortest(r.estimate->start)
                    : std::string())
            << ", xi " << shortest(r.estimate->xi)
            << (r.estimate->peak
                    ? ", peak p " + shortest(r.estimate->peak->p) + ", peak r " + shortest(r.estimate->peak->r)
                    : std::string())
            << ", gamma_0n " << estimate_text(gamma_estimate(r))
            << (r.estimate->coupling
                    ? ", offset e " + estimate_text(r.estimate->coupling->offset) + ", P_H/P2 at Johnson's level " +
                          estimate_text(r.estimate->coupling->lambda_johnson) + ", peak pressure change " +
                          estimate_text(r.estimate->coupling->peak_change, 100.0, " %")
                    : std::string())
            << "   (difference from " << r.estimate->against << ")\n";
    else
        out << "  error estimate      " << no_estimate_reason(r) << "\n";
    out << "  checks (3.3) (3.4)  " << (s.checks.hold() ? "hold" : "VIOLATED") << "   (margins: p "
        << shortest(s.checks.pressure_margin) << ", stick " << shortest(s.checks.stick_margin) << ", slip "
        << shortest(s.checks.slip_margin) << ")\n"
        << "  seconds             " << shortest(r.seconds) << "\n";
    if (!r.si) return;
    const si_point& p = *r.si;
    out << "  SI units\n"
        << "  half-width a        " << shortest(p.a) << " m   (Hertz a_H " << shortest(p.a_hertz)
        << " m, a/a_H = " << shortest(p.a / p.a_hertz) << ", " << p.width_iterations << " width-search iterations)\n"
        << "  stick zone end c    " << shortest(p.c) << " m\n"
        << "  loads P2, P1        " << shortest(p.P2) << " N/m, " << shortest(p.P1) << " N/m\n"
        << "  P_H (Hertz, width a) " << shortest(p.P_H) << " N/m\n"
        << "  pressure at centre  " << shortest(p.p_scale * peak.centre) << " Pa\n"
        << "  peak pressure       " << shortest(p.p_scale * peak.p) << " Pa at x1 = " << shortest(p.a * peak.r)
        << " m\n"
        << "  creep xi1           " << shortest(p.xi1) << "   (Carter, smooth: " << shortest(p.xi1_carter) << ")\n";
    const auto cylinder = [&out](const char* name, const cylinder_roughness& c) {
        out << "  " << name << " at a     tangential " << term_text(c.tangential) << "; normal " << term_text(c.normal)
            << "\n";
    };
    cylinder("cylinder 1", p.surfaces.cylinder1);
    cylinder("cylinder 2", p.surfaces.cylinder2);
    // The SI values' estimates (docs/formulation.md 2(j), "The SI values' estimates"), as the dimensionless line above.
    if (!r.estimate) {
        out << "  error estimate      " << no_estimate_reason(r) << "\n";
        return;
    }
    const si_estimate e = estimate_si(p, *r.estimate, s.Q, s.c0(), s.xi, peak);
    out << "  error estimate      a " << shortest(e.a) << " m (a/a_H " << shortest(e.a_over_a_hertz) << "), c " << shortest(e.c) << " m, P2 " << shortest(e.P2)
        << " N/m, P1 " << shortest(e.P1) << " N/m, P_H " << shortest(e.P_H) << " N/m, xi1 " << shortest(e.xi1);
    if (e.p_peak && e.x_peak)
        out << ", peak pressure " << shortest(*e.p_peak) << " Pa, its x1 " << shortest(*e.x_peak) << " m";
    if (e.p_centre) out << ", pressure at centre " << shortest(*e.p_centre) << " Pa";
    out << ", T and A at a " << shortest(e.surfaces_relative)
        << " relative   (the dimensionless estimates scaled)\n";
}

void write_curve_header(std::ostream& out, const curve_header& h) {
    out << "# roughroll " << version() << "\n"
        << "# roughroll curve " << one_line(h.scene_path) << (h.label.empty() ? "" : ": ") << one_line(h.label) << "\n"
        << "# f = " << shortest(h.friction) << ", method = " << to_string(h.solver.how) << ", n = " << h.solver.nodes()
        << (h.solver.n != 0 ? std::string()
                            : " (the method's default; a row climbs to larger n, column n, until its estimates are "
                              "below the relative tolerance " +
                                  shortest(h.solver.tolerance.value_or(default_tolerance)) + ")")
        << ", zones = " << to_string(h.solver.zones) << "; "
        << (h.swept       ? "swept in c0: each row's load Q(c0) is found for its stick zone end c0"
            : h.continued ? "swept in the load: Q/f over the curve's range, each row's zone search started from the "
                            "previous row's zones"
                          : "loads given: Q/f over the curve's range, dense near gross sliding")
        << "\n"
        << "# Q = P1/P2, Q_over_f = Q/f; c0 = c/a, the stick zone's end (r = x1/a); xi: the creep, dimensionless "
           "(docs/formulation.md), xi_over_f = xi/f; xi_carter, c0_carter: Carter's smooth cylinders, same f, at the "
           "row's load (swept: at its c0)\n"
           "# checks_hold: 1 when p >= 0, (3.3) and (3.4) hold on the solver's grids; c0_error_estimate, "
           "xi_error_estimate, Q_error_estimate: the estimates of their errors (empty: none)\n"
           "# zones: the number of stick and slip zones; stick_start: r where the stick zone starts (-1: at the "
           "leading edge); stick_start_error_estimate: the estimate of its error (0: the paper's zone, starting at the "
           "edge exactly; five zones: the larger of the two stick zones' starts'; empty: none); zone_path: how the zones were found, single (the paper's zone), general (the search of "
           "section 7, every dissimilar structure) or no-slip (the edge layers neglected, docs/formulation.md 8(n)); n: the Gauss-Chebyshev nodes of the row; status: ok, or refused (only the given Q or c0 "
           "and Carter's columns filled)\n";
    if (h.physical)
        out << "# SI: P1_N_per_m = Q P2, the tangential load in N/m; xi1 = C P2 xi/a, the creep ratio (dimensionless); "
               "xi1_carter: Carter's creep ratio for the same loads on smooth cylinders (a closed form); "
               "P1_N_per_m_error_estimate, xi1_error_estimate (after status): their estimates, the row's scaled "
               "(docs/formulation.md 2(j); empty: none)\n";
}

void write_curve_csv(std::ostream& out, const std::vector<curve_point>& curve, const std::optional<si_context>& si,
                     const std::vector<int>& nodes) {
    out << "Q,Q_over_f,c0,xi,xi_over_f,xi_carter,c0_carter,checks_hold,c0_error_estimate,xi_error_estimate,"
           "Q_error_estimate,zones,stick_start,stick_start_error_estimate,zone_path"
        << (si ? ",P1_N_per_m,xi1,xi1_carter" : "") << ",n,status"
        << (si ? ",P1_N_per_m_error_estimate,xi1_error_estimate" : "") << "\n";
    if (!nodes.empty() && nodes.size() != curve.size())
        throw std::invalid_argument("write_curve_csv: " + std::to_string(nodes.size()) + " n for " +
                                    std::to_string(curve.size()) + " rows");
    const auto n_cell = [&nodes](std::size_t i) {
        return nodes.empty() || nodes[i] == 0 ? std::string() : std::to_string(nodes[i]);
    };
    if (si && si->widths.size() != curve.size())
        throw std::invalid_argument("write_curve_csv: " + std::to_string(si->widths.size()) + " widths for " +
                                    std::to_string(curve.size()) + " rows");
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const curve_point& row = curve[i];
        const auto& s = row.solution;
        // A physical row's SI cells (si_curve_row: the rule the Python module shares), empty where NaN.
        const si_curve_cells cells = si ? si_curve_row(si->scene, si->widths[i], row) : si_curve_cells{};
        const auto si_cell = [](double x) { return std::isnan(x) ? std::string() : shortest(x); };
        if (row.is_refused()) {
            // Only what was given: the load Q (creep_curve), or the stick end c0 (swept_curve),
            // with Carter's values at it; every computed field is empty (curve_point, contact.hpp).
            const bool at_Q = !std::isnan(s.Q);
            const auto cell = [](bool given, double x) { return given ? shortest(x) : std::string(); };
            out << cell(at_Q, s.Q) << ',' << cell(at_Q, s.Q / s.f) << ',' << cell(!at_Q, s.c0()) << ",,,"
                << shortest(row.smooth.xi) << ',' << shortest(row.smooth.c0) << ",,,,,,,,";
            if (si) out << ',' << si_cell(cells.P1) << ",," << shortest(cells.xi1_carter);
            out << ',' << n_cell(i) << ",refused";
            if (si) out << ',' << si_cell(cells.P1_error) << ',';
            out << '\n';
            continue;
        }
        out << shortest(s.Q) << ',' << shortest(s.Q / s.f) << ',' << shortest(s.c0()) << ',' << shortest(s.xi) << ','
            << shortest(s.xi / s.f) << ',' << shortest(row.smooth.xi) << ',' << shortest(row.smooth.c0) << ','
            << (s.checks.hold() ? 1 : 0) << ',';
        if (row.estimate)
            out << shortest(row.estimate->c0) << ',' << shortest(row.estimate->xi) << ',' << shortest(row.estimate->Q);
        else
            out << ",,";
        out << ',' << s.layout.zones.size() << ',' << shortest(s.start()) << ','
            << (row.estimate ? shortest(row.estimate->start) : std::string()) << ',' << zone_path(s);
        if (si) out << ',' << shortest(cells.P1) << ',' << shortest(cells.xi1) << ',' << shortest(cells.xi1_carter);
        out << ',' << n_cell(i) << ",ok";
        if (si) out << ',' << si_cell(cells.P1_error) << ',' << si_cell(cells.xi1_error);
        out << '\n';
    }
}

}  // namespace roughroll
