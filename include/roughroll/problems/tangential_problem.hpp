// SPDX-License-Identifier: GPL-3.0-or-later
// The tangential problem (3.21)-(3.22) with errata E4-E8. The stick zone is the
// leading part [-1, c0] of the contact, r = rho (t + 1) - 1 with rho = (1 + c0)/2 (E4),
// and p1 = f p + q0 there, p1 = f p on the slip zone (3.15). In the stick variable t:
//   (1/pi) int q(tau)/(tau - t) d tau + int q(tau) rho K1*(rho (tau - t)) d tau = xi + f G(r(t))  (E5, E6)
//   rho int q(tau) d tau = Q - f                                                           (3.22)
//   G(r) = (2/pi) lambda r + int_{-1}^{1} p(eta) [K2* - K1*](eta - r) d eta                (3.25), E8
// q = psi sqrt(1 - tau^2) (4.1). For a trial c0 a stick-zone system gives q and xi (the
// collocation of (4.4), tangential_solver.hpp; the Glauert system, one_parameter.hpp); Q(c0)
// then follows from (4.5), and c0 for a given Q is the root of Q(c0) - Q found by a secant
// iteration (from the coarse level's root, or Carter's c0), with gsl_root_fsolver_brent on
// [-1, 1] as the fallback (root_search.hpp).
//
// Q < 0 is the mirror case: p1, q0 and xi change sign, c0 does not. Q = 0 is full stick
// (c0 = 1, xi = 0, q0 = -f p) and |Q| = f the onset of gross sliding (c0 = -1,
// xi = -f G(-1)); neither needs a solve.
#pragma once

#include <optional>
#include <vector>

#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_solution.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

struct stick_zone_operator;  // stick_zone_operator.hpp

// The checks every tangential solver makes on a load Q before solving (and the one-parameter
// limit shares): |Q| for a finite Q with |Q| <= f, else an input_error (the cylinders slide).
double load_magnitude(double Q, double f);

// A resolution_error when 0 < |Q|/f < 1e-10: Q(c0) of (4.5) is f + rho int q, an O(f) sum
// that cancels to |Q|, and its rounding (1e-16 f) would make c0 and xi noise.
void check_load_resolvable(double magnitude, double f);

// The solution solved for |Q| as the solution for Q: the mirror case Q < 0 (xi, p1, q0
// change sign, c0 does not). Refuses a non-finite c0 or xi (numerical_error naming `what`).
void apply_load_sign(tangential_solution& s, double Q, const char* what);

// A solution of the |Q| problem (sign +1) with the stick zone [start, c0]: creep xi, load Q, the U
// coefficients of psi (none without a stick zone), the system's rcond (1 without a solve) and Dundurs' forcing (8(e)).
tangential_solution zone_solution(double f, double start, double c0, double xi, double Q,
                                  std::vector<double> psi_b = {}, double rcond = 1.0, double forcing = 0.0);

// q0(r) of (3.15) on the stick zone [start, c0] of s, q = psi(t) sqrt(1 - t^2) (4.1), 0 off it; at many points.
double stick_traction(const tangential_solution& s, double r);
std::vector<double> stick_traction(const tangential_solution& s, const std::vector<double>& r);

// One driver for every stick-zone system, since the root search in c0, the special loads (2(g)), the mirror
// (apply_load_sign), the traction (3.15), the slip velocity (3.6) and the checks (3.3)-(3.4) are the same for all.
// A system supplies its equation on a stick zone [start, c0] (`on_zone`), the two special loads, the slip velocity
// off the zone and the checks' rounding: the collocation of (4.4) (tangential_solver.hpp) and the Glauert system of
// the one-parameter limit (one_parameter.hpp).
class tangential_problem {
public:
    virtual ~tangential_problem() = default;

    virtual const normal_solution& normal() const = 0;
    double friction() const { return f_; }
    // Dundurs' forcing b of the |Q| problem at the load Q: sgn(Q) beta_D (Q = 0: beta_D), 8(s); 0 but for the
    // one-parameter limit of dissimilar rollers (the collocation's dissimilar rollers pass theirs to solve_on_zone).
    double forcing_at(double Q) const { return Q < 0.0 ? -beta_d_ : beta_d_; }

    // Throws input_error for |Q| > f or non-finite Q. `guess`: a c0 close to the root (the
    // coarse level's, when extrapolating), the start of a secant iteration (root_search.hpp);
    // without it the secant starts from `search_start` (Carter's c0 for the collocation), else Brent on [-1, 1].
    // `checked` = false skips the checks (3.3)-(3.4), as in at_stick_end.
    // `slope`: dQ/dc0 near `guess` (the level below's load_slope), for a first Newton step.
    tangential_solution solve(double Q, std::optional<double> guess = std::nullopt, bool checked = true,
                              std::optional<double> slope = std::nullopt);
    // The solution for a trial c0 in [-1, 1], Q = Q(c0) (the Q >= 0 branch): a creep curve swept
    // in c0 needs no root search.
    // `checked` = false skips the checks (3.3)-(3.4) (their fields are then zero): for the
    // coarse level of an extrapolation, whose distributions are not reported.
    // `near` = true: a point of a sweep in c0, whose system is solved by refinement on the
    // last factorisation when that converges (dense_system::solve_near), the same to rounding.
    tangential_solution at_stick_end(double c0, bool checked = true, bool near = false);
    // Q(c0) alone, the |Q| branch with Dundurs' forcing b (`forcing`, default forcing_at(Q >= 0)).
    double load(double c0, std::optional<double> forcing = std::nullopt);

    double traction(const tangential_solution& s, double r) const;  // p1(r), (3.15)
    double slip_velocity(const tangential_solution& s, double r);   // v(r), (3.6), 0 on the stick zone
    // v at many points (any order), in one sweep.
    std::vector<double> slip_velocity(const tangential_solution& s, const std::vector<double>& r);
    // p >= 0, (3.3) on the stick zone [start, c0], (3.4) on the slip zones (zone_checks.hpp).
    traction_checks check(const tangential_solution& s);
    double pressure_margin();  // min p on the check grid, once per solver

protected:
    // n coefficients; `closed_form`: smooth in both directions, Carter's c0 and xi at every load but Q = 0. `what`:
    // the problem in messages; `root_what`: its root search for c0. Throws input_error for f not positive and finite.
    tangential_problem(double f, int n, double beta_d, bool closed_form, const char* what, const char* root_what);

    // The stick equation on the zone [start, c0] (r = start + rho (t + 1), rho = (c0 - start)/2), slip on both
    // sides in the direction of Q, with Dundurs' forcing b; the |Q| branch, unchecked. `near`: as at_stick_end's.
    virtual tangential_solution on_zone(double start, double c0, double forcing, bool near) = 0;
    // Q = 0, solved without a system (2(g)): c0 = 1, xi = 0, q0 = -f p (psi's coefficients -f times the pressure's).
    virtual tangential_solution full_stick(double forcing);
    // |Q| = f (2(g)): the paper's zone shrunk onto r = -1, Carter's where smooth; with Dundurs' forcing the stick
    // point r*, where w = b p + f G is least (8(s), as 8(g); gross_sliding.hpp).
    virtual tangential_solution gross_sliding(double forcing);
    // |Q| = f at the least point r* of w = b p + f G on [-1, 1] (gross_sliding.hpp), also where b = 0: the general
    // search's form (7(d)), and gross_sliding's with Dundurs' forcing.
    tangential_solution least_sliding(double forcing);
    // v of the |Q| problem (3.6) at points of the slip zones, in descending order (the caller applies s.sign).
    virtual std::vector<double> slip_velocity_magnitude(const tangential_solution& s, const std::vector<double>& r) = 0;
    virtual double check_rounding(const tangential_solution& s) = 0;  // the margins' rounding floor (7(d))
    // Q(1) where it is known exactly (then the root search does not ask the system there, nor refuses a load below
    // it); empty: the system's, the discretisation's error, which solve refuses where it reaches |Q|.
    virtual std::optional<double> exact_full_stick_load() const { return std::nullopt; }
    // Where the root search in c0 starts without a guess; empty: Brent on [-1, 1].
    virtual std::optional<double> search_start(double) const { return std::nullopt; }
    // Smooth cylinders: Carter's solution with the stick zone [-1, c0], and at the load |Q| (carter.hpp), no solve.
    tangential_solution carter_solution(double Q, double c0, double xi) const;
    tangential_solution carter_at(double magnitude) const;
    // The one zone search's operator parts every system shares (zone_operators.cpp), for the |Q| problem with
    // Dundurs' forcing b: the zone's system, the load's excess, the empty zone's load, gross sliding, the checks.
    stick_zone_operator zone_operator_of(double forcing);
    virtual std::vector<double> G(const std::vector<double>& r) = 0;  // (3.25) or its limit, at points of [-1, 1]

    double f_;
    double beta_d_;
    bool carter_;  // smooth in both directions, closed form allowed
    int n_;

private:
    const char* what_;
    const char* root_what_;
    std::optional<tangential_solution> last_system_;  // of the last load(c0)
    std::optional<double> pressure_margin_;           // min p on the check grid of (-1, 1), c0-independent
};

}  // namespace roughroll
