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
    // eps (convolution_table::panel_bound). The degree next to a zone is an estimate, not a bound: the representation
    // is checked (tests/test_rough_step0_s19.cpp against QAGS of the definition, to 2.4e-14), not bounded as
    // convolution_table's is; it has no error_bound().
    cut_convolution(const kernel& k, const values& g, const std::vector<double>& cuts, int oscillation,
                    double narrowest);

    double operator()(double r) const;                                      // D(r), r clamped to [-1, 1]
    void operator()(const double* r, double* out, std::size_t count) const;  // D(r[i]) into out[i]
    const std::vector<double>& cuts() const { return cuts_; }
    int panels() const;  // all pieces' panels

private:
    std::vector<double> cuts_;          // -1 = cuts_[0] < ... < cuts_.back() = 1
    std::vector<theta_panels> pieces_;  // piece i on [cuts_[i], cuts_[i + 1]], in x = (r - m)/h = cos u
    std::size_t piece_of(double r) const;
};

}  // namespace roughroll
