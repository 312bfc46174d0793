// SPDX-License-Identifier: GPL-3.0-or-later
// The Cauchy integral of a weighted U-series times the blend of a stick zone (docs/formulation.md 8(g),
// "W of the blend as a mean of steps"):
//   W(r) = (1/pi) PV int_{-1}^{1} p(eta) H(eta) d eta / (eta - r),   p = sqrt(1 - eta^2) sum_j b_j U_j(eta),
// H = 0 on [-1, s), Theta(t) on [s, c] (r = s + rho (t + 1)), 1 on (c, 1]. H is the mean of unit steps at
// e(t) weighted by Theta'(t) = (2/pi) sqrt(1 - t^2), and a step's Cauchy integral is closed form in
// theta = acos e, so
//   W(r) = (1/pi) [ sum_j c_j(r) sigma_j + p(r) (log 2 + 2 Lambda(r) - ell(r)) ]
// with sigma_j the zone's moments of sin(j theta)/j, c_j(r) from the series by one Clenshaw recurrence,
// ell(r) = int Theta' log|e - r| in closed form and Lambda(r) = int Theta' log sin((theta_e + alpha)/2),
// alpha = acos r, the only part taken per r by quadrature. sigma_j and Lambda are integrals of functions
// analytic in t up to the images of e = +-1 (a Bernstein ellipse): Gauss-Chebyshev rules of the second kind
// with 16, 32, ... nodes (nested), accepted when two successive rules differ by at most `tolerance`
// (the next rule's error is then of the order of that difference squared), the last two (1023 nodes) by at most
// `tolerance` plus their sum's rounding (128 eps of the value); no rule up to 1023 nodes that meets it, and the
// caller takes its adaptive quadrature (an empty optional).
#pragma once

#include <optional>
#include <vector>

namespace roughroll {

class blended_cauchy {
public:
    // Absolute tolerance on sigma_j and on Lambda (both of order 1; the adaptive rule it replaces asked 1e-14
    // absolute, 1e-12 relative).
    static constexpr double tolerance = 2e-15;
    static constexpr int most_nodes = 1023;

    // The zone [s, c], -1 <= s < c <= 1, of the series b (b_0..b_{n-1}). Empty when no rule up to most_nodes
    // meets the tolerance for the moments (a zone within about 1e-5 of a contact edge) or the zone is not
    // inside [-1, 1].
    static std::optional<blended_cauchy> make(const std::vector<double>& b, double s, double c);

    // W(r) for -1 <= r <= 1; empty where Lambda(r) does not converge by most_nodes.
    std::optional<double> operator()(double r) const;
    // The same at each of `count` points r[i] into out[i], bit for bit as operator()(r[i]) (its Clenshaw sums
    // for blocks of points together: W at a zone's collocation points, dissimilar_zones::W).
    void operator()(const double* r, std::optional<double>* out, std::size_t count) const;

    double start() const { return s_; }
    double end() const { return c_; }

private:
    blended_cauchy() = default;
    // W(r) from the sums sum_j c_j(r) sigma_j (`smooth`) and sum_j b_j U_j(r) (`series`): p(r)'s logarithms.
    std::optional<double> finish(double r, double smooth, double series) const;
    struct node {
        double half_sin, half_cos;  // sin, cos of theta_e/2 at the node
        double weight;              // the node's weight in the rule that adds it (halved at each later level)
    };
    std::vector<double> b_;      // the series
    std::vector<double> f_;      // (1 - r^2) sum b_j U_j = sum f_k T_k
    std::vector<double> sigma_;  // int Theta' sin(j theta_e)/j dt (j = 0: theta_e)
    std::vector<std::vector<node>> levels_;  // the nodes each nested rule adds: 15, 16, 32, ...
    double s_ = 0.0, c_ = 0.0;
};

}  // namespace roughroll
