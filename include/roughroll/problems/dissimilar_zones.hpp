// Dissimilar rollers in Johnson's approximation (docs/formulation.md section 8): the pressure of
// the uncoupled normal problem, and the tangential problem (D2) with Dundurs' forcing,
//   v(r) = xi - L1[p1](r) + beta_D p(r);  stick: v = 0, |p1| <= f p;  slip: p1 = sigma f p, sigma v > 0;
//   int p1 = Q                                                                          8(c), 8(e)
// No stick zone reaches a contact edge when beta_D != 0 (8(g)), so the paper's zone [-1, c0] is
// never the answer. The structures solved here:
//   - three zones, slip sigma [-1, s), stick [s, c0], slip sigma (c0, 1] with both slip zones in
//     the direction sigma = sgn Q. With p1 = sigma (f p + q) on the stick zone and the mirror of
//     8(h), (beta_D, Q, xi, p1) -> (-beta_D, -Q, -xi, -p1), this is the |Q| problem
//       L1[q] = xi' + b p + f G,  rho int q = |Q| - f,   b = sigma beta_D,  xi = sigma xi'   8(e)
//     on the moved zone r = s + rho (t + 1) (tangential_solver::solve_on_zone with forcing b), with
//     the entry condition psi(-1) = 0 of 7(b) at s > -1 and the exit C0 = 0 built into (4.1).
//     This is the structure of a braked roller 1 for beta_D > 0 (Q beta_D < 0; 8(g)'s table);
//   - gross sliding |Q| = f: slip everywhere, v = xi' + b p + f G >= 0 vanishing at its least
//     point r*: xi' = -min_r (b p + f G) (8(g));
//   - the complete-slip limit f -> 0 (8(f)), its own special case (complete_slip_creep).
// Not built (refused with numerical_error naming what is missing, never a number): free rolling
// Q = 0 and every load whose answer is not the three zones above (five zones, or leading and
// trailing slip in opposite directions with the blended stick traction of 8(g)), and coupling "full".
#pragma once

#include <optional>

#include "roughroll/model/dissimilar.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_problem.hpp"
#include "roughroll/problems/zone_solver.hpp"

namespace roughroll {

// What a contact with these materials and options can solve: beta_D finite with |beta_D| < 3/4;
// for beta_D != 0, not method 'one-parameter' (its edge behaviour, 8(g), is not derived), not
// zones 'single' (the paper's zone is never the answer, 8(g)), and not coupling 'full' (not
// built). Each refusal is one input_error line.
void check_dissimilar(const dissimilar& materials, const solver_options& options);

// The complete-slip limit f -> 0 at fixed Q/f (docs/formulation.md 8(f)): v = xi + beta_D p, the
// central band |r| < r_c carries (1 + sgn(beta_D) Q/f)/2 of the load, and xi_0 = -beta_D p(r_c).
// Needs p even and decreasing in |r| (checked on 2001 points: else input_error). For Hertz and
// Q = 0, -pi xi_0/(4 beta_D) = cos(phi)/2 = 0.457386 (Bentall and Johnson's 0.457).
struct complete_slip {
    double r_c;   // edge of the central band
    double xi;    // xi_0, divided by nothing: the limit of xi itself (xi = O(beta_D), not O(f))
};
complete_slip complete_slip_creep(const normal_solution& normal, double beta_d, double Q_over_f);

// int_lo^hi p(r) dr for the pressure (4.1), in closed form from its U-series (r = cos theta:
// U_j(r) sqrt(1 - r^2) dr = -sin((j + 1) theta) sin(theta) d theta).
double load_between(const normal_solution& normal, double lo, double hi);

// How well Newton's method fixes the zone ends (as zone_solver's, docs/formulation.md 7(e)): the
// entry condition psi(-1) carries rounding of about 1e-13, which moves the ends by a few 1e-12;
// the estimates of the ends include it as a floor.
constexpr double zone_end_resolution = 1e-11;

// numerical_error naming the structure not built unless s's checks (3.3)-(3.4) hold: a three-zone
// answer that fails them is another structure's, never reported.
void require_checks(const tangential_solution& s);

class dissimilar_zones {
public:
    // The tangential solver supplies G, the system (4.4) on any zone with the forcing, the
    // tractions, slip velocities and checks; it must outlive this workspace. beta_d != 0.
    dissimilar_zones(tangential_solver& solver, double beta_d);

    // The point at load Q, |Q| <= f, with its checks (3.3)-(3.4) on every zone (made, not acted
    // on: a reported point goes through require_checks, a level of an estimate need not);
    // numerical_error for free rolling and where no three zones carry Q. `guess`: a zone near the one sought (the coarser
    // level's), the start of Newton's method; without it the starts of the stick zone are scanned.
    tangential_solution solve(double Q, std::optional<zone_guess> guess = std::nullopt);

private:
    tangential_solution three_zones(double magnitude, double b, std::optional<zone_guess> guess);
    tangential_solution gross_sliding(double b);
    std::optional<tangential_solution> newton(double magnitude, double b, double start, double c0);
    std::optional<double> stick_end(double start, double magnitude, double b);  // Q(start, c0) = |Q|

    tangential_solver& solver_;
    double beta_d_;
    double f_;
};

}  // namespace roughroll
