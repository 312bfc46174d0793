#include "roughroll/output.hpp"

#include <iomanip>
#include <limits>

#include "roughroll/carter.hpp"

namespace roughroll {

nlohmann::json to_json(const point_report& r) {
    const auto& s = r.solution;
    const carter_point smooth = carter(s.Q, s.f);
    nlohmann::json checks = {
        {"pressure_nonnegative", s.checks.pressure_holds},
        {"stick_traction_bound_3_3", s.checks.stick_holds},
        {"slip_velocity_positive_3_4", s.checks.slip_holds},
        {"pressure_margin", s.checks.pressure_margin},
        {"stick_margin", s.checks.stick_margin},
        {"slip_margin", s.checks.slip_margin},
    };
    return {
        {"label", r.label},
        {"Q", s.Q},
        {"f", s.f},
        {"c0", s.c0},
        {"xi", s.xi},
        {"hertz_load_ratio", r.normal.lambda},
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
    };
}

void write_summary(std::ostream& out, const point_report& r) {
    const auto& s = r.solution;
    const carter_point smooth = carter(s.Q, s.f);
    const auto old = out.precision(std::numeric_limits<double>::max_digits10);
    if (!r.label.empty()) out << r.label << "\n";
    out << "  Q = P1/P2           " << s.Q << "   (f = " << s.f << ")\n"
        << "  P_H/P2              " << r.normal.lambda << "\n"
        << "  gamma_0n            " << r.normal.gamma << "\n"
        << "  c0 = c/a            " << s.c0 << "   (Carter " << smooth.c0 << ")\n"
        << "  xi (creep)          " << s.xi << "   (Carter " << smooth.xi << ")\n"
        << "  method, n           " << to_string(r.normal.how) << ", " << r.normal.rule.n << "\n"
        << "  checks (3.3) (3.4)  " << (s.checks.hold() ? "hold" : "VIOLATED") << "   (margins: p "
        << s.checks.pressure_margin << ", stick " << s.checks.stick_margin << ", slip " << s.checks.slip_margin
        << ")\n"
        << "  seconds             " << r.seconds << "\n";
    out.precision(old);
}

void write_curve_csv(std::ostream& out, const std::vector<curve_point>& curve) {
    const auto old = out.precision(std::numeric_limits<double>::max_digits10);
    out << "Q,Q_over_f,c0,xi,xi_over_f,xi_carter,c0_carter,checks_hold\n";
    for (const auto& row : curve) {
        const auto& s = row.solution;
        out << s.Q << ',' << s.Q / s.f << ',' << s.c0 << ',' << s.xi << ',' << s.xi / s.f << ',' << row.smooth.xi
            << ',' << row.smooth.c0 << ',' << (s.checks.hold() ? 1 : 0) << '\n';
    }
    out.precision(old);
}

}  // namespace roughroll
