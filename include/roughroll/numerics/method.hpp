// SPDX-License-Identifier: GPL-3.0-or-later
// The discretisations of the kernel terms of (4.2) and (4.4).
//   paper:   the node sum  sum_k w_k phi_k K(eta_k - s_m)  of (4.2), (4.4) as printed.
//   product: product integration, int phi_n(eta) sqrt(1-eta^2) K(eta - s_m) d eta with
//            phi_n the interpolant of the nodal values and the jump of K at eta = s_m
//            integrated exactly (kernel_sweep). Same unknowns, same collocation.
//   extrapolated: product integration at n/2 and n, combined by Richardson's rule for its
//            order 4: v = (16 v_n - v_{n/2})/15 for P_H/P2, c0 and xi (contact.hpp).
//   one_parameter: not a discretisation of the two-parameter kernels but their limit t -> 0
//            (T, A -> infinity, 2T/A^2 fixed): the Winkler-layer model of the paper's
//            reference [2], solved directly by Glauert-type collocation (one_parameter.hpp).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace roughroll {

enum class method { paper, product, extrapolated, one_parameter };

std::string to_string(method m);
std::ostream& operator<<(std::ostream& os, method m);  // to_string(m): readable test names

// The default method is extrapolated (docs/performance.md: 1e-10 within the time goals).
// Nodes used when a scene does not set n, for Fig. 2's parameters: relative error in
// P_H/P2, c0 and xi about 1e-5 with the paper's scheme at 200, 5e-9 with product
// integration at 96, 5e-11 extrapolated from 64 and 128 (docs/performance.md). The
// one-parameter limit converges at order 2 in n: at 128, for 2T/A^2 = 0.2, about 6e-5
// relative in P_H/P2 and xi and 1e-6 to 3e-6 in c0, in 4 ms per point at a given Q
// (validation/test_one_parameter.cpp, docs/performance.md).
int default_nodes(method m);
// The discretisation a method solves at each level: product integration for extrapolated
// (Richardson's rule combines two product levels), the method itself otherwise.
method level_of(method m);
method method_from_string(const std::string& name);
// Richardson's rule of method::extrapolated for an error ~ C n^-4, levels n and n/2:
// (16 v_n - v_{n/2})/15, as (4.6) for order 4.
inline double richardson(double fine, double coarse) {
    return (16.0 * fine - coarse) / 15.0;
}  // throws input_error naming the method

// How the tangential problem's zones are found (docs/formulation.md section 7):
//   automatic: the paper's single stick zone [-1, c0] (the fast path), and the general search
//              of zone_solver only where the single zone fails its checks (3.3)-(3.4);
//   single:    the paper's single zone only (its checks reported, never acted on);
//   general:   the general search for every point.
enum class zone_search { automatic, single, general };
std::string to_string(zone_search z);
zone_search zone_search_from_string(const std::string& name);  // "auto", "single", "general"

// The relative tolerance when neither the scene (solver.tolerance) nor the caller gives one:
// every point of Fig. 2 and of data/ meets it at the method's default n (measured: the largest
// ratio of an estimate to its allowance over Fig. 2's curves is far below 1, docs/performance.md),
// and the one-parameter case near gross sliding whose checks fail at n = 128 is answered at 256.
constexpr double default_tolerance = 1e-4;

// A tolerance a scene or an option may give: finite, in (0, 1) (a relative accuracy of 1 or more
// says nothing). Throws input_error naming `name` ("--tolerance", "solver.tolerance", "tolerance").
void check_tolerance(double tolerance, const std::string& name);

// The method and its number of nodes, as a scene's [solver] table gives them.
struct solver_options {
    int n = 0;  // 0: default_nodes(how)
    method how = method::extrapolated;
    zone_search zones = zone_search::automatic;
    // The relative tolerance of the ladder that chooses n where n = 0 (problems/level_ladder.hpp);
    // empty: default_tolerance. An explicit n ignores it.
    std::optional<double> tolerance = std::nullopt;

    int nodes() const { return n == 0 ? default_nodes(how) : n; }
};

}  // namespace roughroll
