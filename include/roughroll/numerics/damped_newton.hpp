// SPDX-License-Identifier: GPL-3.0-or-later
// Damped Newton iteration in k unknowns with a forward-difference Jacobian: the search for the
// ends of the stick zones (docs/formulation.md 7(e), step 2, and 8(j) item 3). For x in R^k,
//   J_ij = (F_i(x + h_j e_j) - F_i(x)) / h_j,   J dx = -F(x)   (GSL's LU),
//   x <- x + lambda dx, lambda = 1, 1/2, 1/4, ... until x + lambda dx is inside the domain and F is
// defined there (lambda >= min_step). It stops after a full step (lambda = 1) whose size, measured by
// the caller, is at most `tolerance`, or at the limit of the accuracy F carries: where the caller gives
// the size of the steps F's rounding makes (`rounding`), after two successive full steps within it,
// the second no smaller than the first (a contracting Newton step is far smaller than the one before:
// what is left is F's rounding, below which a later step gets only by chance), and only where that
// rounding is at most `rounding_cap` tolerances: an ill-conditioned F (a rounding near the iterate's
// distance from the root) or a non-contracting cycle far from it is no root. The result says why it
// stopped (newton_stop): a root; at F's rounding beyond the cap (stopped there, as no later step can
// tell more: the caller refuses with what lowers that rounding, not as for a search that may succeed
// elsewhere); or no root: a singular or non-finite Jacobian, no admissible step, F undefined at x0 or
// at a difference point, or max_iterations spent, where the callers fall back to bracketing (Brent).
// Whatever F throws passes through.
#pragma once

#include <functional>
#include <optional>
#include <vector>

namespace roughroll {

struct newton_problem {
    // F(x); empty where x is off the family the residuals describe (e.g. a zone carrying more than f).
    std::function<std::optional<std::vector<double>>(const std::vector<double>&)> residual;
    // The difference step h_j at x (its sign chooses the side: -h is a backward difference).
    std::function<double(const std::vector<double>& x, std::size_t j)> difference_step;
    // Where a step may land (the zone inside [-1, 1]); always true when empty.
    std::function<bool(const std::vector<double>&)> inside;
    // The size of the step dx taken to x, compared with the tolerance (in r, the zone ends' unit).
    std::function<double(const std::vector<double>& x, const std::vector<double>& dx)> step_size;
    // The size (as step_size measures it) of the steps F's rounding makes at x, asked right after F(x); empty: F's
    // rounding is taken to lie below `tolerance`.
    std::function<double(const std::vector<double>& x)> rounding;
};

struct newton_options {
    int max_iterations = 40;
    double tolerance = 1e-11;
    double min_step = 1e-6;  // the smallest damping factor lambda
    // The largest rounding (in tolerances) at which the rounding stop is a stop (docs/formulation.md 8(q), "The
    // five zones' Newton at large n"): the zone ends' eps/rcond, 1.5e-10, 8.6e-10, 4.0e-9 at n = 250, 500, 1000
    // (max_nodes) on free rolling of the pair at Johnson's level, is at most 400 of their tolerances 1e-11; 1000
    // leaves 2.5 for other scenes. Beyond it the ends would be known to no more than 1e-8 of the half-width.
    double rounding_cap = 1000.0;
};

struct newton_root {
    std::vector<double> x;
    int iterations;
    // How well x is fixed (in step_size's unit): the tolerance where a step got below it, else the rounding the stop
    // accepted (docs/formulation.md 8(q), "The estimates' floor of the zone ends").
    double resolution;
};

// Why damped_newton stopped.
enum class newton_stop {
    root,            // a full step below the tolerance, or the rounding stop within rounding_cap tolerances
    rounding_limit,  // the rounding stop, F's rounding beyond rounding_cap tolerances: x is known to no better
    no_root,         // no convergence (singular Jacobian, no admissible step, F undefined, iterations spent)
};

struct newton_result {
    newton_stop stop;
    std::optional<newton_root> root;  // where stop == root
    double rounding = 0.0;            // at rounding_limit: F's rounding there (step_size's unit)
};

// A Jacobian kept from one solve to the next of a sequence whose roots and residuals move little (full coupling's
// alternation: the zone ends from step to step, docs/formulation.md 8(e), "The Jacobian kept between steps"). Where
// damped_newton is given one, it starts from `J` (when its size fits) and updates it by Broyden's rule after each
// accepted step, J += (dF - J dx) dx^T / (dx^T dx), instead of differencing at every iteration; a step of such a
// Jacobian is accepted only whole, inside, with F defined and contracting (|F| halved, or the step at most half the
// last one), or below the tolerance or F's rounding; else J is differenced afresh at x and the iteration goes on as
// without it (Broyden's update skipped for a step shorter than the difference steps: it would measure F's rounding).
// With J of relative error delta the root lies within delta/(1 - delta) of the last step. One stop more, with a kept
// Jacobian only: after a full step, a next step contracting by rho = its size/the last one's <= 1/2 whose bound
// size/(1 - rho) on the steps left is within the tolerance, or within F's rounding at x up to rounding_cap tolerances,
// makes x the root to that resolution without the residual at x + dx (docs/formulation.md 8(e), "The root before the
// last step").
// On return `J` is the last one (empty where no root was found). The counters add up what was spent.
struct newton_jacobian {
    std::vector<std::vector<double>> J;  // empty: none kept
    int residuals = 0;                   // evaluations of F (differences included)
    int differenced = 0;                 // Jacobians by differences
};

// `kept`: a Jacobian carried between solves (above); null: every iteration's Jacobian by differences.
newton_result damped_newton(const newton_problem& problem, std::vector<double> x0, const newton_options& options,
                            newton_jacobian* kept = nullptr);

}  // namespace roughroll
