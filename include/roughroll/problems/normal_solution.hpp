// SPDX-License-Identifier: GPL-3.0-or-later
// The solution of the normal problem (3.19)-(3.20) as the solver (normal_problem.hpp) returns it and
// the reports read it: phi at the nodes of the rule (4.6), its U coefficients, lambda = P_H/P2 and
// the pressure p(r) of (4.1) with its peak. A value, apart from the solver: part of the public interface
// (roughroll.hpp); the kernel term's operator and the kinks it may share stay declared only.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "roughroll/numerics/method.hpp"
#include "roughroll/numerics/gauss_chebyshev.hpp"

namespace roughroll {

class kernel_operator;  // numerics/collocation.hpp
class pressure_kinks;   // problems/pressure_kinks.hpp

struct normal_solution {
    gauss_chebyshev rule;
    method how;
    std::vector<double> phi;  // phi(eta_k) of (4.1)
    std::vector<double> b;    // U coefficients of the interpolant of phi
    double lambda;            // P_H/P2
    double gamma;             // gamma_0n, tends to 0 as n grows (4.8)
    double rcond;             // reciprocal condition of the LU factor U
    // The kernel term's operator of (4.2) (product integration: its sweep workspace), shared
    // with the tangential solver when K1*'s rates do not exceed K2*'s: the Lagrange basis at
    // the sweep's quadrature points is then computed once per level. Empty for Hertz.
    std::shared_ptr<const kernel_operator> kernel_term;
    // Full coupling of dissimilar rollers (docs/formulation.md 8(e)): beta_D p1(r) of the (D1) this
    // pressure solves, and its offset e = pi gamma_0n/(2 lambda) (8(c)); G = -L1[p] then gains
    // (2/pi) lambda e + beta_D p1 (tangential_solver::G). Empty and 0 for the uncoupled problem.
    std::function<double(double)> tangential_term;
    double offset = 0.0;
    // Full coupling, docs/formulation.md 8(l) step 0: the explicit term p_q^0 carrying the pressure's
    // one-sided kinks at the zone ends (pressure_kinks.hpp), p = phi sqrt(1 - r^2) + p_q^0. Null otherwise.
    std::shared_ptr<const pressure_kinks> kinks;
    // Full coupling of smooth rollers: the Chebyshev coefficients c_0..c_n of the projection P_n[beta_D p1 - removed]
    // the solve put on (D1)'s right side (chebyshev_projection.hpp; `removed` the q that `kinks` carries, 8(l)).
    // With them -H[p] of this discrete p is known at any r (projected_minus_hilbert). Empty otherwise (K2* present:
    // the collocation holds (D1) at its points only).
    std::vector<double> projected = {};
    // On the exact weight of 8(z): the a posteriori bound on lambda's rounding by this solve (docs/formulation.md 8(w),
    // "The solve's rounding, a posteriori"); 0 elsewhere (no bound computed: the a priori eps |lambda| / rcond).
    double lambda_rounding = 0.0;

    double pressure(double r) const;  // p(r) = phi(r) sqrt(1 - r^2) (4.1), + p_q^0(r) with `kinks`
    // The same at each r[i], bit for bit, the U-series summed for all points at once (the batched Clenshaw of
    // quadrature.hpp): the zone solves and checks take p at a zone's points.
    std::vector<double> pressure(const std::vector<double>& r) const;
    // -H[p](r) of this discrete p, exactly (up to rounding) where `projected` is set: (2/pi) lambda (r + e)
    // + P_n[beta_D p1 - removed](r) + removed(r) (docs/formulation.md 8(u)). Beside G's formula, which takes beta_D p1
    // itself, kinks and all, the two differ by the projection's residual. Only where `projected` is not empty.
    double projected_minus_hilbert(double r) const;
};

// The peak of the pressure p(r) of (4.1) on (-1, 1): its value (in units of P2/a) and position r.
// Sampled at 2001 points and refined by golden section (least_value.hpp): the value to rounding, r
// only to `r_resolution` (a flat maximum: points within it of the peak have pressures within the
// rounding of p, 16 eps p, so no comparison of values tells them apart; about 1e-7 for Hertz's
// peak, 2/pi at r = 0). Both are this discretisation's: their error estimates come from the levels
// (error_estimate::peak, point_estimate.hpp), and the reports print r and p to them (io/output.cpp).
// `p_rounding`: on the weighted pressure of 8(w), whose levels agree to rounding (spectral), the dense solve's forward
// error eps |p| / rcond (rcond of the factor U, about 1/kappa): the levels' own rounding, which grows with kappa
// (measured on the pair at Q/f = -0.75: p's changes 64..512 within 1e-13, 512 -> 1000 5.6e-13 as rcond falls
// 3.5e-5 .. 3.5e-8; the bound is 2.3e-11 at 128, 4e-9 at 1000). 0 elsewhere, where the levels' changes carry it.
// `centre`: p(0), the pressure at the centre, read with the peak so that its estimate comes from the same levels
// (peak_error::centre; docs/formulation.md 2(j), "The SI values' estimates").
struct pressure_peak {
    double r, p;
    double r_resolution;
    double p_rounding = 0.0;
    double centre = 0.0;
};
pressure_peak peak_of(const normal_solution& s);

}  // namespace roughroll
