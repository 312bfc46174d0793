#include "roughroll/model/physical_scene.hpp"

#include <cmath>
#include <sstream>

#include "roughroll/model/carter.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll {

namespace {
constexpr double pi = 3.14159265358979323846;

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
