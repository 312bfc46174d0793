#include "roughroll/physical_scene.hpp"

#include <cmath>
#include <sstream>

#include "roughroll/carter.hpp"
#include "roughroll/error.hpp"
#include "roughroll/root_search.hpp"
#include "roughroll/text.hpp"

namespace roughroll {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double width_step = 1.25;  // bracket expansion factor of the width search
constexpr int max_width_steps = 60;  // 1.25^60 = 6.5e5 a_H: far beyond any physical width
constexpr int max_width_iterations = 100;

roughness_term term_at(const physical_scene& s, const stiffness& st, double a) {
    if (!st.present()) return {};
    // (3.26)
    const double mu = s.shear_modulus();
    return {a * mu / (8.0 * (1.0 - s.nu) * st.t), a * std::sqrt(st.k / (2.0 * st.t))};
}

cylinder_roughness cylinder_at(const physical_scene& s, const surface_stiffness& c, double a) {
    return {term_at(s, c.tangential, a), term_at(s, c.normal, a)};
}
}  // namespace

double physical_scene::radius() const {
    // 1/R = 1/R1 + 1/R2, so an infinite radius (a plane) drops out.
    return 1.0 / (1.0 / R1 + 1.0 / R2);
}

double hertz_half_width(const physical_scene& s, double P) {
    return std::sqrt(4.0 * (1.0 - s.nu) * s.radius() * P / (pi * s.shear_modulus()));  // (3.27)
}

stiffness stiffness_of(const physical_scene& s, const roughness_term& term, double a) {
    if (!term.present()) return {};
    // (3.26) solved for t and alpha, then k = 2 t alpha^2 from alpha = sqrt(k/(2t)).
    const double t = a * s.shear_modulus() / (8.0 * (1.0 - s.nu) * term.T);
    const double alpha = term.A / a;
    return {2.0 * t * alpha * alpha, t};
}

roughness roughness_at(const physical_scene& s, double a) {
    return {cylinder_at(s, s.cylinder1, a), cylinder_at(s, s.cylinder2, a)};
}

bool smooth(const physical_scene& s) {
    return !s.cylinder1.tangential.present() && !s.cylinder1.normal.present() && !s.cylinder2.tangential.present() &&
           !s.cylinder2.normal.present();
}

contact_width find_width(const physical_scene& s, const std::function<double(const roughness&)>& load_ratio) {
    const double a_H = hertz_half_width(s, s.P2);
    if (smooth(s)) return {a_H, a_H, 1.0, s.P2, 0};  // Hertz exactly, no kernel to solve
    const double lambda_H = load_ratio(roughness_at(s, a_H));
    if (s.width == width_rule::hertz) return {a_H, a_H, lambda_H, s.P2 / lambda_H, 0};

    // In x = a/a_H the model carries P2 where lambda(x) = x^2 (the coefficient of (3.19)
    // for a load normalised to P2). F(1) = lambda - 1 > 0 for the compliant roughness of E2;
    // the bracket grows away from x = 1 in the direction of the root.
    const auto F = [&](double x) { return load_ratio(roughness_at(s, x * a_H)) - x * x; };
    const double F1 = lambda_H - 1.0;
    const double step = F1 > 0.0 ? width_step : 1.0 / width_step;
    double near = 1.0, far = step;
    int steps = 1;
    while (!((F(far) > 0.0) != (F1 > 0.0))) {
        near = far;
        far *= step;
        if (++steps > max_width_steps) {
            std::ostringstream msg;
            msg << "contact width search: no half-width between a_H and " << shortest(far * a_H)
                << " m carries the load P2 = " << shortest(s.P2) << " N/m";
            throw numerical_error(msg.str());
        }
    }
    const double lo = std::min(near, far), hi = std::max(near, far);
    const root x = brent_root(F, lo, hi, 0.0, 1e-12, max_width_iterations, "contact width search (Brent in a)");
    const double a = x.x * a_H;
    return {a, a_H, x.x * x.x, s.P2, x.iterations};
}

si_point to_si(const physical_scene& s, const contact_width& w, double Q, double f, double c0, double xi) {
    const double mu = s.shear_modulus();
    const double load = w.load;
    // Smooth cylinders under the same loads: Carter's creep on Hertz's width for `load`.
    const carter_point smooth_point = carter(Q, f);
    const double a_load = hertz_half_width(s, load);
    si_point p;
    p.a = w.a;
    p.a_hertz = w.a_hertz;
    p.c = c0 * w.a;
    p.P_H = w.lambda * load;
    p.P2 = load;
    p.P1 = Q * load;
    p.xi1 = 2.0 * (1.0 - s.nu) * load * xi / (w.a * mu);  // xi = a mu xi1 / (2 (1 - nu) P2)
    p.xi1_carter = 2.0 * (1.0 - s.nu) * load * smooth_point.xi / (a_load * mu);
    p.p_scale = load / w.a;
    p.width_iterations = w.iterations;
    p.surfaces = roughness_at(s, w.a);
    return p;
}

}  // namespace roughroll
