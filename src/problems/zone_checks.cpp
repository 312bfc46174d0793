// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/zone_checks.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gsl/gsl_math.h>

#include "roughroll/base/text.hpp"

namespace roughroll {

namespace {
constexpr int check_points = 200;  // interior grid points per zone

// The i-th interior Chebyshev point of (lo, hi), descending in i; the ends are excluded.
double grid_point(double lo, double hi, int i) {
    const double x = std::cos(M_PI * (i + 0.5) / check_points);
    return 0.5 * (lo + hi) + 0.5 * (hi - lo) * x;
}

std::vector<double> grid(double lo, double hi) {
    std::vector<double> r(check_points);
    for (int i = 0; i < check_points; ++i) r[i] = grid_point(lo, hi, i);
    return r;
}

// A NaN margin must read as a failed check: min() would drop it.
void lower(double& margin, double v) {
    if (!(v >= margin)) margin = v;
}
}  // namespace

double least_pressure(const normal_solution& normal) { return least_pressure(normal, -1.0, 1.0); }

double least_pressure(const normal_solution& normal, double from, double to) {
    double margin = std::numeric_limits<double>::infinity();
    for (int i = 0; i < check_points; ++i) lower(margin, normal.pressure(grid_point(from, to, i)));
    return margin;
}

traction_checks check_zones(const std::vector<zone>& zones, const zone_check_terms& terms) {
    traction_checks c{};
    c.pressure_margin = terms.pressure_margin;
    c.stick_margin = std::numeric_limits<double>::infinity();
    c.slip_margin = std::numeric_limits<double>::infinity();
    // (3.3) on each stick zone that is more than a point (gross sliding's is r* alone).
    for (const zone& z : zones)
        if (z.stick && z.to > z.from)
            for (const double gap : terms.stick_gap(grid(z.from, z.to))) lower(c.stick_margin, gap / terms.f);
    // (3.4): every slip zone's points in one call, descending (a kernel sweep's order), with their directions.
    std::vector<double> r;
    std::vector<int> direction;
    for (auto z = zones.rbegin(); z != zones.rend(); ++z)
        if (!z->stick)
            for (const double x : grid(z->from, z->to)) {
                r.push_back(x);
                direction.push_back(z->direction);
            }
    const std::vector<double> v = r.empty() ? std::vector<double>{} : terms.slip_velocity(r);
    for (std::size_t i = 0; i < v.size(); ++i) lower(c.slip_margin, direction[i] * v[i] / terms.f);
    const double floor = terms.within_rounding ? terms.rounding : 0.0;
    c.stick_rounding = c.slip_rounding = terms.rounding;
    c.pressure_holds = c.pressure_margin >= 0.0;
    c.stick_holds = c.stick_margin >= -floor;
    c.slip_holds = c.slip_margin > -floor;
    return c;
}

traction_checks check_zones(const std::vector<zone>& zones, zone_check_terms terms, const std::function<double(double)>& p,
                            const std::function<double(double)>& p1, const std::function<double(double)>& v) {
    const double f = terms.f;
    terms.stick_gap = [&](const std::vector<double>& r) {
        std::vector<double> gap(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) gap[i] = f * p(r[i]) - std::fabs(p1(r[i]));
        return gap;
    };
    terms.slip_velocity = [&](const std::vector<double>& r) {
        std::vector<double> out(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) out[i] = v(r[i]);
        return out;
    };
    return check_zones(zones, terms);
}

namespace {
std::string margin_text(const char* kind, double margin) {
    if (margin == std::numeric_limits<double>::infinity()) return std::string("no ") + kind + " zone";
    if (!std::isfinite(margin)) return std::string(kind) + " not finite";
    return std::string(kind) + " " + significant(margin, 3);
}
}  // namespace

std::string margins_text(const traction_checks& c) {
    return margin_text("stick", c.stick_margin) + ", " + margin_text("slip", c.slip_margin);
}

}  // namespace roughroll
