// SPDX-License-Identifier: GPL-3.0-or-later
// The Gauss-Chebyshev rule of the second kind, (4.6)-(4.7), and the range of n: the nodes at which
// normal_solution holds phi (normal_solution.hpp), so part of the installed interface. The series
// and transforms that use it (quadrature.hpp) are the library's own.
#pragma once

#include <vector>

namespace roughroll {

// The documented range of n: at least 2 nodes, and no more than a dense
// (n+2)x(n+2) system that solves in about a second.
constexpr int min_nodes = 2;
constexpr int max_nodes = 1000;
// A transform's rule inside the library (kinks_blend's expansion of g W_1, docs/formulation.md 8(o) "W with the
// kinks") solves no system: its cost is O(m^2) in u_coefficients and m evaluations, so it may exceed max_nodes, the
// collocation's limit (at n = max_nodes g alone has up to max_nodes terms, and W_1's ellipse asks up to about 2046
// more before blended_cauchy declines the zone).
constexpr int max_transform_nodes = 4000;

// Throws input_error naming n when it is outside [min_nodes, max_nodes].
void check_node_count(int n);

struct gauss_chebyshev {
    explicit gauss_chebyshev(int n);  // throws input_error outside [min_nodes, max_nodes]
    // The rule for a transform (not a collocation): throws numerical_error outside [min_nodes, max_transform_nodes].
    static gauss_chebyshev transform(int n);

    int n;
    std::vector<double> nodes;        // eta_k = cos(k pi/(n+1)), k = 1..n      (4.6)
    std::vector<double> weights;      // w_k = pi/(n+1) sin^2(k pi/(n+1))       (4.6)
    std::vector<double> collocation;  // s_m = cos((2m-1) pi/(2n+2)), m = 1..n+1 (4.7)

private:
    struct unchecked {};
    gauss_chebyshev(int n, unchecked);
};

}  // namespace roughroll
