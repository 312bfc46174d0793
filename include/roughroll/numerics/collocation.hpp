// SPDX-License-Identifier: GPL-3.0-or-later
// The discrete operators shared by the normal (4.2) and tangential (4.4) systems:
// row m is the collocation point s_m, column k the nodal unknown at eta_k.
//   Cauchy term:  (1/pi) w_k / (eta_k - s_m)           (exact for the interpolant)
//   kernel term:  paper   w_k K(eta_k - s_m)            (4.2), (4.4)
//                 product int l_k(eta) sqrt(1-eta^2) K(eta - s_m) d eta, l_k the
//                 Lagrange basis of the nodes, by kernel_sweep.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <gsl/gsl_matrix.h>

#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/gauss_jacobi.hpp"
#include "roughroll/numerics/kernel_sweep.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/numerics/quadrature.hpp"

namespace roughroll {

// Adds the Cauchy term into a(m, k), m <= n, k < n.
void add_cauchy_term(gsl_matrix* a, const gauss_chebyshev& rule);
// The same on the Gauss-Jacobi collocation of a weight with a + b = 1 (docs/formulation.md 8(v)):
// (1/pi) W_k/(t_k - x_m), which is (H - cot(pi a)) on w psi at x_m, exactly for deg psi <= n - 1.
void add_cauchy_term(gsl_matrix* a, const jacobi_collocation& rule);

// The kernel term for one rule and method. For product integration it keeps the sweep
// workspace, so the stretched kernels of successive trial c0 (rates up to max_rate) reuse
// its quadrature points and basis values.
class sweep_cache;

class kernel_operator {
public:
    // `cache` (optional): product-integration workspaces shared with other operators at the same n.
    kernel_operator(const gauss_chebyshev& rule, method how, double max_rate, sweep_cache* cache = nullptr);

    // Adds the kernel term of `k` into a(m, k), m <= n, k < n. Nothing when k is empty.
    void add_to(gsl_matrix* a, const kernel& k) const;
    // The fastest decay it integrates: at least the max_rate it was built for (the reach of its
    // sweep's layout; unbounded for the paper's node sum).
    double max_rate() const { return max_rate_; }

private:
    gauss_chebyshev rule_;  // a copy: an operator may outlive the solver that built it
    method how_;
    double max_rate_;
    std::shared_ptr<const kernel_sweep> sweep_;  // product integration only
};

// The product-integration workspaces (the Lagrange basis at the sweep's quadrature points: the
// set-up of a normal solve) shared by the solves of one scene at the same n: the trial widths of
// a width search, whose kernels differ in rate but mostly not in the workspace they need
// (kernel_sweep::same_layout_rate), and the contact at the width found. An operator given a
// cache gets the same values, bit for bit, as one that builds its own. One cache per search (not
// shared between threads); the operators keep their workspaces after it is gone.
class sweep_cache {
public:
    std::shared_ptr<const kernel_sweep> get(const gauss_chebyshev& rule, double max_rate);

private:
    struct entry {
        int n;
        double reach;  // the rate the workspace was built for (same_layout_rate)
        std::shared_ptr<const kernel_sweep> sweep;
    };
    std::vector<entry> entries_;
};

// One-off: kernel_operator(rule, how, k.max_rate()).add_to(a, k).
void add_kernel_term(gsl_matrix* a, const kernel& k, const gauss_chebyshev& rule, method how);

// Whether n is fine enough for k that the error falls at the method's order (2 paper,
// 4 product) from n on: the condition for n/2 to serve as the error estimate's companion.
bool in_asymptotic_range(const kernel& k, int n, method how);

// Richardson's rule of method::extrapolated holds where the error already falls like n^-4: throws
// resolution_error unless its coarse level n/2 is at least min_nodes and in the asymptotic range of
// product integration for `k`. `which` names the kernels ("the normal kernel"); the message says
// what can help (a larger n only where one puts n/2 in range).
void check_extrapolation_range(const kernel& k, int n, const char* which);

// Throws resolution_error when `k` varies faster than `how` resolves with this n.
// `what` names the kernel in the message ("K2* (normal)").
void check_resolution(const kernel& k, const gauss_chebyshev& rule, method how, const char* what);

}  // namespace roughroll
