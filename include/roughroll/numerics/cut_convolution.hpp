// SPDX-License-Identifier: GPL-3.0-or-later
// The same convolution of a function with one-sided square roots at given cuts (docs/formulation.md 8(o),
// "Rough rollers": the layer terms K2[p_q^0] of (D1) and (K2 - K1)[p_q^0] of G, p_q^0 the pressure's kinks):
//   D(r) = int_{-1}^{1} g(eta) K(eta - r) d eta,   K = sum_i T_i exp(-A_i |z|) sgn z,
// for g analytic on each piece [a, b] between consecutive cuts once mapped by r = m + h cos u (m, h the piece's
// midpoint and half-length, u in [0, pi]): square roots (and 3/2 powers) at a piece's ends become entire in u,
// as in chebyshev_projection and pressure_kinks::integral. Per piece, D is kept as a theta_panels table in u (the
// variable of convolution_table with the piece for [-1, 1]); L and R of convolution_table run across all pieces,
// carried from piece to piece at the cuts, where D is continuous (the kernel is bounded). Inside a piece D is then
// analytic in u too: D(r) - D(a) = O((r - a)^(3/2)) on the side of a's square root.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/theta_panels.hpp"

namespace roughroll {

class cut_convolution {
public:
    // g(r[i]) into out[i], i < count, for r inside (-1, 1) (the Lobatto points of the pieces' panels).
    using values = std::function<void(const double* r, double* out, std::size_t count)>;
    // `cuts`: the points inside (-1, 1) where g has its one-sided roots (-1 and 1 are added; cuts within 1e-12 of
    // each other or of an edge are merged). `oscillation`: g's degree in u on a piece of half-length `narrowest`
    // (n + 1 for the kinks' n-term series on their zone, -sum b_j cos((j + 1) u)); on a piece of half-length h it is
    // taken as oscillation max(1, sqrt(h/narrowest)): next to a zone of half-length rho its terms z^(j+1) =
    // exp(-(j + 1) acosh t), t - 1 = (r - c)/rho, vary in u like exp(-2 (j + 1) sqrt(h/rho) cos(u/2)). Each piece's
    // panels are then convolution_table's for that degree and the piece's rate A h, refined until its bound is below
    // eps (convolution_table::panel_bound). That degree is an estimate (it ignores, e.g., sqrt(1 - r^2) of a zone next
    // to an edge), so it is checked a posteriori, not bounded: on every panel the interpolant of g dr/du (the
    // integrand of L and R before the kernel's factor, which panel_bound covers) has Chebyshev coefficients c_k,
    // k <= 24; the check sums over a piece's panels max(|c_22|, |c_23|, |c_24|) times the panel's half-length in u
    // (an estimate of the spectral integration's error on that piece, as Chebfun's tail test: it presumes the
    // coefficients fall geometrically beyond 24, which an analytic g gives) and asks it to be at most 1e-13 of
    // pi max |g dr/du| (the size the integrals are measured against, all pieces). A piece above it takes twice the
    // degree (and panel_bound's panels for it) until it is below; beyond degree 2^16 it is refused (numerical_error).
    // What is NOT bounded: a g whose coefficients stall above 24 and fall later (the check reads only the last three),
    // and g's own evaluation error. Tests: tests/test_rough_step0_s19.cpp (braked) and tests/test_rough_blend_s20.cpp
    // (driven, with the blend's kinks; a degree given too low; a jump off the cuts refused) against GSL's quadrature of
    // the definition, to 2.4e-14. It has no error_bound().
    cut_convolution(const kernel& k, const values& g, const std::vector<double>& cuts, int oscillation,
                    double narrowest);

    double operator()(double r) const;                                      // D(r), r clamped to [-1, 1]
    void operator()(const double* r, double* out, std::size_t count) const;  // D(r[i]) into out[i]
    const std::vector<double>& cuts() const { return cuts_; }
    int panels() const;  // all pieces' panels
    // The check's largest sum (class comment) over the pieces, relative to pi max |g dr/du|, after any raise.
    double tail() const { return worst_tail_; }

private:
    std::vector<double> cuts_;          // -1 = cuts_[0] < ... < cuts_.back() = 1
    std::vector<theta_panels> pieces_;
    double worst_tail_ = 0.0;  // piece i on [cuts_[i], cuts_[i + 1]], in x = (r - m)/h = cos u
    std::size_t piece_of(double r) const;
};

}  // namespace roughroll
