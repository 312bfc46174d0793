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

// Throws input_error naming n when it is outside [min_nodes, max_nodes].
void check_node_count(int n);

struct gauss_chebyshev {
    explicit gauss_chebyshev(int n);  // throws input_error outside [min_nodes, max_nodes]

    int n;
    std::vector<double> nodes;        // eta_k = cos(k pi/(n+1)), k = 1..n      (4.6)
    std::vector<double> weights;      // w_k = pi/(n+1) sin^2(k pi/(n+1))       (4.6)
    std::vector<double> collocation;  // s_m = cos((2m-1) pi/(2n+2)), m = 1..n+1 (4.7)
};

}  // namespace roughroll
