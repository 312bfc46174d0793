// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/model/physical_scene.hpp"

#include <cfloat>
#include <cmath>
#include <sstream>

#include "roughroll/model/carter.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll {

namespace {
constexpr double pi = 3.14159265358979323846;

// Every quantity derived from a physical scene is checked where it is made: a value that
// over- or underflowed double precision would otherwise reach the solver as inf, 0 or NaN
// (a Hertz width of 0 gave xi1 = -nan with exit 0). `keys` are the scene's keys it comes from.
bool normal_positive(double x) { return std::isfinite(x) && x >= DBL_MIN; }

[[noreturn]] void out_of_range(const std::string& what, double value, const std::string& inputs,
                               const std::string& keys) {
    throw input_error(what + " = " + shortest(value) + " (" + inputs + ") is beyond double precision: check " + keys);
}

std::string materials(const physical_scene& s) {
    if (!s.materials) return "E = " + shortest(s.E) + " Pa, nu = " + shortest(s.nu);
    const auto one = [](const material& m) { return "mu = " + shortest(m.mu) + " Pa, nu = " + shortest(m.nu); };
    return "cylinder1 " + one((*s.materials)[0]) + ", cylinder2 " + one((*s.materials)[1]);
}

// The scene keys of the material(s), for the messages.
std::string material_keys(const physical_scene& s) {
    return s.materials ? "'cylinder1.shear_modulus' and 'cylinder2.shear_modulus'" : "'E'";
}

// mu of (3.26): E/(2 (1 + nu)), infinite for a huge E with nu near -1.
double shear_modulus_of(const physical_scene& s) {
    const double mu = s.shear_modulus();
    if (!normal_positive(mu)) out_of_range("the shear modulus mu = E/(2 (1 + nu))", mu, materials(s), "'E' and 'nu'");
    return mu;
}

roughness_term term_at(const physical_scene& s, const stiffness& st, double a, const std::string& name) {
    if (!st.present()) return {};
    // (3.26) with C of docs/formulation.md 8(a) for 2 (1 - nu)/mu: T = a/(4 C t).
    const double C = compliance(s);
    const roughness_term term{a / (4.0 * C * st.t), a * std::sqrt(st.k / (2.0 * st.t))};
    const std::string inputs = "at a = " + shortest(a) + " m, k = " + shortest(st.k) + " Pa/m, t = " + shortest(st.t) +
                               " Pa m, " + materials(s);
    // An underflow to 0 or a subnormal is the smooth limit (a stiff layer): harmless. An
    // overflow is not.
    const std::string formula = s.materials ? "T = a/(4 C t)" : "T = a mu/(8 (1 - nu) t)";
    if (!std::isfinite(term.T))
        out_of_range("'" + name + "': " + formula + " of (3.26)", term.T, inputs,
                     "'" + name + ".t' and " + material_keys(s));
    if (!std::isfinite(term.A))
        out_of_range("'" + name + "': A = a sqrt(k/(2 t)) of (3.26)", term.A, inputs,
                     "'" + name + ".k' and '" + name + ".t'");
    return term;
}

cylinder_roughness cylinder_at(const physical_scene& s, const surface_stiffness& c, double a, const std::string& name) {
    return {term_at(s, c.tangential, a, name + ".tangential"), term_at(s, c.normal, a, name + ".normal")};
}
}  // namespace

double physical_scene::radius() const {
    // 1/R = 1/R1 + 1/R2, so an infinite radius (a plane) drops out.
    return 1.0 / (1.0 / R1 + 1.0 / R2);
}

double compliance(const physical_scene& s) {
    if (!s.materials) return 2.0 * (1.0 - s.nu) / shear_modulus_of(s);  // checked mu, then C finite
    // docs/formulation.md 8(a): C = (1 - nu1)/mu1 + (1 - nu2)/mu2 = 2/E* in Johnson's notation.
    const material& m1 = (*s.materials)[0];
    const material& m2 = (*s.materials)[1];
    const double C = (1.0 - m1.nu) / m1.mu + (1.0 - m2.nu) / m2.mu;
    if (!normal_positive(C))
        out_of_range("the compliance C = (1 - nu1)/mu1 + (1 - nu2)/mu2", C, materials(s), material_keys(s));
    return C;
}

double dundurs_beta(const physical_scene& s) {
    if (!s.materials) return 0.0;
    // docs/formulation.md 8(a): beta_D = ((1 - 2 nu1)/mu1 - (1 - 2 nu2)/mu2)/(2 C), |beta_D| < 3/4.
    const material& m1 = (*s.materials)[0];
    const material& m2 = (*s.materials)[1];
    return ((1.0 - 2.0 * m1.nu) / m1.mu - (1.0 - 2.0 * m2.nu) / m2.mu) / (2.0 * compliance(s));
}

double hertz_half_width(const physical_scene& s, double P) {
    const double C = compliance(s);
    const double R = s.radius();
    const std::string inputs = materials(s) + ", R = " + shortest(R) + " m, P = " + shortest(P) + " N/m";
    const std::string keys = material_keys(s) + ", 'R1', 'R2' and 'P2'";
    const std::string keys_list = s.materials ? keys : "'E', 'R1', 'R2' and 'P2'";
    if (!normal_positive(R)) out_of_range("the radius R = R1 R2/(R1 + R2)", R, inputs, "'R1' and 'R2'");
    // (3.27) with C of 8(a) for 2 (1 - nu)/mu: a_H^2 = 2 C R P/pi; where an intermediate product
    // over- or underflows, as a product of square roots, which does so only where a_H itself does.
    double a_H = std::sqrt(2.0 * C * R * P / pi);
    if (!normal_positive(a_H)) a_H = std::sqrt(2.0 / pi) * std::sqrt(R) * (std::sqrt(P) * std::sqrt(C));
    if (!normal_positive(a_H)) out_of_range("the Hertz half-width a_H of (3.27)", a_H, inputs, keys_list);
    // The scales back to SI units (to_si): the pressure P/a and the creep C P/a.
    if (!normal_positive(P / a_H)) out_of_range("the pressure scale P/a_H", P / a_H, inputs, keys_list);
    if (!normal_positive(P / a_H * C)) out_of_range("the creep scale C P/a_H", P / a_H * C, inputs, keys_list);
    return a_H;
}

stiffness stiffness_of(const physical_scene& s, const roughness_term& term, double a, const std::string& name) {
    if (!term.present()) return {};
    // (3.26) solved for t and alpha, then k = 2 t alpha^2 from alpha = sqrt(k/(2t)).
    const double t = a / (4.0 * compliance(s) * term.T);  // T = a/(4 C t), C of 8(a)
    const double alpha = term.A / a;
    const stiffness st{2.0 * t * alpha * alpha, t};
    const std::string inputs = "from T = " + shortest(term.T) + ", A = " + shortest(term.A) +
                               " at a_H = " + shortest(a) + " m, " + materials(s);
    const std::string who = name.empty() ? std::string() : "'" + name + "': ";
    const std::string formula = s.materials ? "t = a/(4 C T)" : "t = a mu/(8 (1 - nu) T)";
    if (!normal_positive(st.t)) out_of_range(who + formula + " of (3.26)", st.t, inputs, "'" + name + ".T'");
    if (!std::isfinite(st.k)) out_of_range(who + "k = 2 t (A/a)^2 of (3.26)", st.k, inputs, "'" + name + ".A'");
    return st;
}

roughness roughness_at(const physical_scene& s, double a) {
    return {cylinder_at(s, s.cylinder1, a, "cylinder1"), cylinder_at(s, s.cylinder2, a, "cylinder2")};
}

bool smooth(const physical_scene& s) {
    return !s.cylinder1.tangential.present() && !s.cylinder1.normal.present() && !s.cylinder2.tangential.present() &&
           !s.cylinder2.normal.present();
}

si_point to_si(const physical_scene& s, const contact_width& w, double Q, double f, double c0, double xi) {
    const double C = compliance(s);
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
    p.xi1 = C * load * xi / w.a;  // xi = a xi1/(C P2), docs/formulation.md 8(a)
    p.creep_scale = C * load / w.a;
    p.xi1_carter = C * load * smooth_point.xi / a_load;
    p.p_scale = load / w.a;
    p.width_iterations = w.iterations;
    p.surfaces = roughness_at(s, w.a);
    p.width = s.width;
    // hertz_half_width checked the scales at a_H; a >= a_H/6.5e5 and a <= R/10 keep them finite
    // in practice, and this check keeps that promise for every value reported.
    const std::string inputs = materials(s) + ", a = " + shortest(w.a) + " m, P2 = " + shortest(load) + " N/m";
    for (const auto& [name, value] : {std::pair<const char*, double>{"the pressure scale P2/a", p.p_scale},
                                      {"the creep xi1", p.xi1},
                                      {"Carter's creep xi1", p.xi1_carter},
                                      {"the Hertz load P_H", p.P_H}})
        if (!std::isfinite(value))
            out_of_range(name, value, inputs,
                         (s.materials ? material_keys(s) : std::string("'E'")) + ", 'R1', 'R2' and 'P2'");
    return p;
}

}  // namespace roughroll
