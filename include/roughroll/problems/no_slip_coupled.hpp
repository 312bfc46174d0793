// SPDX-License-Identifier: GPL-3.0-or-later
// The no-slip limit of free rolling at full coupling (Bufler; docs/formulation.md 8(p) for smooth rollers, 8(t) for
// this routine and rough layers). Stick on the whole contact, the pressure coupled to the traction through beta_D:
// (D1) and the stick equation of (D2),
//   L2[p] + beta_D p1 = -(2/pi) lambda (r + e),   L1[p1] - beta_D p = xi,   int p = 1,   p, p1 bounded at r = -1, 1,
// with L_i = H + K_i (2(b)), are one complex equation for F = p - i p1:
//   H[F] + i beta_D F + K2[Re F] + i K1[Im F] = -(2/pi) lambda (r + e) - i xi.
// With tanh(pi eps) = -beta_D and w = (1 + r)^(1/2 + i eps) (1 - r)^(1/2 - i eps), every polynomial P has (8(t))
//   H[w P] + i beta_D w P = -R_P(r)/cosh(pi eps),   int w P = -pi (y_1 - y_{-1})/(2 cosh(pi eps)),
// R_P the polynomial part of X(z) P(z), X = (z + 1)^(1/2 + i eps) (z - 1)^(1/2 - i eps). In the Joukowski variable
// z = (1/u + u)/2, X = (1/u - u) G(u)/2, G = ((1 + u)/(1 - u))^(2 i eps) = sum gamma_m u^m with
//   gamma_0 = 1, gamma_1 = 4 i eps, (m + 1) gamma_{m+1} = 4 i eps gamma_m + (m - 1) gamma_{m-1},
// and for P = T_j the Laurent coefficients of X T_j are
//   y_k = (gamma_{k+j+1} + gamma_{k-j+1} - gamma_{k+j-1} - gamma_{k-j-1})/4   (gamma_m = 0 for m < 0),
//   R_{T_j} = y_0 + 2 sum_{k=1}^{j+1} y_{-k} T_k.
// So F = w phi, phi = sum_{j<=n} c_j T_j (complex c_j), maps exactly to polynomials: collocated at the n + 2 zeros of
// T_{n+2} (real and imaginary parts) with the unknowns lambda e and xi at lambda = 1, then scaled to int p = 1. The
// layers' K_i[Re/Im (w T_j)] are taken by tanh-sinh quadrature on each side of the kernel's jump (the contact edges'
// (1 -+ r)^(1/2 -+ i eps) integrable at the ends). Smooth rollers: phi = c_0 exactly (n = 0 suffices),
//   lambda = 1/(1 + 4 eps^2),  e = 0,  xi = 4 eps/(pi (1 + 4 eps^2)),  p1/p = -tan(eps log((1 + r)/(1 - r))).
// With layers phi has (1 -+ r)^(1 + ...) terms at the edges (the kernels' jump integrates p once): lambda and xi
// converge at about order 4 in n (8(t), measured), the traction pointwise more slowly.
// The limit neglects the edge layers where |p1| > f p, and within t_inf = 2/(1 + exp(pi/(2 |eps|))) of each edge
// (smooth rollers) the pressure of this solution changes sign (8(p), "The edges"): an approximation, not a point of
// the model; 8(t) says by how much.
#pragma once

#include <complex>
#include <vector>

#include "roughroll/model/kernel.hpp"
#include "roughroll/problems/normal_solution.hpp"

namespace roughroll {

// tanh(pi eps) = -beta_D (8(p)): eps = log((1 - beta_D)/(1 + beta_D))/(2 pi).
double bufler_epsilon(double beta_d);

struct no_slip_coupled_solution {
    double beta_d = 0.0;
    double epsilon = 0.0;
    double load_ratio = 0.0;       // lambda = P_H/P2 at the width a (2(b)); a physical scene's width solves lambda(a) = (a/a_H)^2
    double offset = 0.0;           // e = x_c/a (8(c)); 0 by the symmetry p even, p1 odd, computed, not imposed
    double xi = 0.0;               // the creep of 8(a)
    double tangential_load = 0.0;  // int p1: complete stick with bounded p exists only at this load, 0 (8(p), 8(t))
    std::vector<std::complex<double>> phi;  // F = p - i p1 = w(r) sum_j phi_j T_j(r), int p = 1

    std::complex<double> F(double r) const;  // 0 outside (-1, 1)
    double pressure(double r) const { return F(r).real(); }
    double traction(double r) const { return -F(r).imag(); }
    // The crossing t_c at friction f > 0 (8(t), "Where the limit is an approximation", item 1): the distance from either
    // edge (the same at both, p even and p1 odd) where |p1| = f p, nearest the centre: inside it the model slips. Smooth
    // rollers: 2/(1 + exp(arctan(f)/|eps|)) of 8(p); rough: near 2 exp(-(arctan f + |arg phi(-1)|)/|eps|) for thin layers.
    // Found on the solution itself, the distance carried without r's rounding; 0 where it is below 1e-300.
    double crossing(double f) const;

private:
    std::complex<double> F_near_leading_edge(double x) const;  // F at r = -1 + x, x > 0 exactly
};

// The complete-stick solution at full coupling with layer kernels K1* (tangential) and K2* (normal) of 2(b); both empty:
// smooth rollers (exact for every n >= 0). beta_D as check_beta_d accepts, beta_D != 0; 0 <= n <= 1000.
no_slip_coupled_solution no_slip_coupled(double beta_d, const kernel& tangential, const kernel& normal, int n);

// The limit's pressure as a normal solution of n nodes (the point's report, 8(t) "What the wiring needs"): phi at the
// nodes p(eta_k)/sqrt(1 - eta_k^2) of the limit itself (exact there), its U interpolant between them, lambda, e and the
// tangential term beta_D p1 the limit's.
normal_solution no_slip_normal(const no_slip_coupled_solution& limit, int n, method how);

}  // namespace roughroll
