// SPDX-License-Identifier: GPL-3.0-or-later
// Full coupling of dissimilar rollers (docs/formulation.md 8(c), 8(e)): the normal problem (D1)
// and the tangential problem (D2) solved together by alternation at a fixed width,
//   (D1)  L2[p](r) + beta_D p1(r) = -(2/pi) lambda (r + e),     int p = 1,
//   (D2)  v(r) = xi - L1[p1](r) + beta_D p(r);  stick: v = 0, |p1| <= f p;  slip: p1 = sigma f p,
//         sigma v > 0;  int p1 = Q,
//   lambda = 1 - int p J - beta_D int p1 r/sqrt(1 - r^2)                                    8(c)
// from Johnson's point (k = 0: p^(0) the uncoupled pressure, e = 0):
//   1. tangential solve k: (D2) with beta_D p^(k), and in place of G
//        G^(k) = -L1[p^(k)] = (2/pi) lambda^(k) (r + e^(k)) + int p^(k) (K2* - K1*) + beta_D p1^(k-1);
//   2. normal solve k + 1: (D1) with beta_D p1^(k) known on the right side at the collocation points
//      (normal_solver::solve with the coupled term: the same matrix, gamma_0n = (2/pi) lambda e); for
//      three zones of one direction on smooth rollers the pressure's kinks at the zone ends are carried
//      by p_q^0 from q of p1^(k) and the right side is beta_D (p1^(k) - q) (docs/formulation.md 8(l)
//      step 0, 8(o), pressure_kinks.hpp);
//   3. iterate, then test: stop when lambda, e, xi and the zone ends change by less than the
//      tolerances below; numerical_error (one line) after max_iterations or when the changes grow.
// Each tangential solve is Newton from the previous iterate's ends on the same structure (three
// zones of either kind, gross sliding, or five zones: dissimilar_zones), with its checks (3.3)-(3.4),
// acted on for a reported point at every step without p_q^0 and at the converged step with it (8(o)).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/model/kernel.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/numerics/damped_newton.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/coupling_summary.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/tangential_solution.hpp"
#include "roughroll/problems/tangential_solver.hpp"
#include "roughroll/problems/zone_layout.hpp"

namespace roughroll {

// The alternation's stopping rule (iterate-then-test). lambda, e and xi: absolute changes below
// 1e-12 (their size is O(1) or less; the rounding of a normal solve is a few 1e-15/rcond); the zone
// ends: below 10 times Newton's resolution zone_end_resolution (each tangential solve fixes them
// only to that, so smaller changes are that solve's jitter, not the alternation's). At the last of the
// max_iterations steps, and there only, ends whose changes run within the two iterates' own Newton resolutions summed
// stop at that floor, which their resolution then carries (docs/formulation.md 8(e), "The ends' rounding floor").
constexpr double coupling_value_tolerance = 1e-12;
constexpr double coupling_end_tolerance = 10.0 * zone_end_resolution;
constexpr int coupling_max_iterations = 40;

// The rounding floor of the values' change over one step (docs/formulation.md 8(e), "Growth within the rounding
// floor"): lambda and e are read off the normal solve, xi off the tangential one, each a dense LU solve whose forward
// error is within eps |x| / rcond (rcond of its factor, about 1/kappa; normal_solution.hpp's p_rounding), x of size
// at most `scale` = max(|lambda|, |e|, |xi| + f max(1, |lambda|)) (xi's system cancels terms of size f G, as
// rounding_floors' xi). A change is the difference of two such solves: 2 eps scale / rcond, the worse rcond of the
// two systems. Within it a change is rounding, whose size need not fall from step to step, so the test for growing
// changes reads only changes above it (beta_d = 0.7, f = 0.3, Q/f = 0.5 at n = 256: rcond 1.15e-6, floor 3.5e-10,
// changes 2.0e-12, 1.1e-12, 9.7e-13, 1.7e-11, 1.8e-11 while the ends still contract by 0.58). 0 where no rcond is known.
double coupling_value_floor(double lambda, double offset, double xi, double f, double normal_rcond,
                            double tangential_rcond);

// Where a coupled point's failed checks (3.3)-(3.4) are the structure's, not the discrete zones' at one n
// (docs/formulation.md 8(e)): why (`pressure`: the coupled pressure below zero; else the zones), and what answers the
// load instead. One text for a rung's refusal (full_coupling.cpp) and the ladder's settled one (settled_failure).
std::string coupled_failure_cause(bool pressure);
std::string coupled_failure_advice(bool pressure);

// The distance of the alternation's last iterate from its fixed point in lambda, e and xi (docs/formulation.md 8(w),
// "The alternation's share"): (kappa d + rho)/(1 - kappa), d the last change, rho = max(step_rounding, band) one step's
// rounding (step_rounding the normal solve's a posteriori bound; `band` the changes' rounding, which the tangential
// solve shares), kappa the largest ratio of the level's own successive changes that both exceed `band` (below it a
// ratio is noise); 1/2 (the stop's trusted limit) where no ratio is readable. Infinity where kappa >= 1 or no step was
// taken: no bound.
double coupling_fixed_point_distance(const coupling_summary& summary, double band, double step_rounding);
// The same for one group's changes `d` from index `own_from` (the first of the level's own map): the zone ends at the
// step limit's rounding floor (docs/formulation.md 8(e), "The ends' rounding floor"), `band` their floor.
double coupling_fixed_point_distance(const std::vector<double>& d, std::size_t own_from, double band,
                                     double step_rounding);

// A reported point whose coupled zones fail the checks (3.3)-(3.4) (full_coupling::solve): the refusal, with the
// margins and the structure they are of, which the ladder of levels compares over three rungs (docs/formulation.md
// 8(q), "A failure the levels settle").
class failed_checks_error : public resolution_error {
public:
    failed_checks_error(const std::string& what, const tangential_solution& t)
        : resolution_error(what), checks_(t.checks), layout_(t.layout) {}
    const traction_checks& checks() const { return checks_; }
    const zone_layout& layout() const { return layout_; }

private:
    traction_checks checks_;
    zone_layout layout_;
};

// A reported point whose alternation stops without converging (40 steps, or changes that grow) after a step whose
// checks (3.3)-(3.4) failed on the way (full_coupling::solve): the cause is the alternation, not those checks of an
// iterate that is no solution (docs/formulation.md 8(q), "An alternation that converges at no level").
// `levels_too`: the estimate's levels of the same point did not converge either (coupled_model::point), which the
// ladder of levels reads over two rungs.
class alternation_error : public resolution_error {
public:
    explicit alternation_error(const std::string& what, bool levels_too = false)
        : resolution_error(what), levels_too_(levels_too) {}
    bool levels_too() const { return levels_too_; }

private:
    bool levels_too_;
};

// What answers a load whose alternation converges at no level: one text for a rung's refusal (full_coupling.cpp) and
// the ladder's (level_ladder.cpp).
std::string alternation_failure_advice();

// The alternation's stop for one group of its numbers (lambda, e, xi; or the zone ends), docs/formulation.md 8(e),
// "The stop from the contraction": `changes` the group's largest change per step, from the first step; `own_from` the
// index of the first change that is the level's own map's (1 from a coarser level's start, whose first change is the
// levels' difference; else 0). Settled where the last change is within `tolerance` (the plain rule), or where
// kappa, the largest ratio changes[j]/changes[j - 1] of its own changes, is at most 1/2 and kappa/(1 - kappa)
// changes[k], the a posteriori bound of a contraction with that constant on the distance to the fixed point, is
// within a quarter of it. Ratios above 1/2 leave the plain rule (a map that contracts slowly, or not yet).
bool coupling_settled(const std::vector<double>& changes, std::size_t own_from, double tolerance);

// Which stop the alternation takes: the contraction's (above, the program's), or the plain rule alone (each last
// change within its tolerance: the reference that tests compare it with).
enum class coupling_stop { contraction, plain };

// Free rolling of smooth rollers at full coupling: the distance t_c from either edge where |p1| of the fully coupled
// no-slip solution reaches f p, 2/(1 + exp(arctan(f)/|epsilon|)) with tanh(pi epsilon) = -beta_D (docs/formulation.md
// 8(p), "The edges"); the edge layers of the five zones scale with it.
double coupled_layers_crossing(double beta_d, double f);

class full_coupling {
public:
    // The level's kernels, n and method, friction and beta_D != 0.
    full_coupling(const kernel& k1, const kernel& k2, int n, method how, double f, double beta_d);
    full_coupling(const full_coupling&) = delete;
    full_coupling& operator=(const full_coupling&) = delete;
    ~full_coupling();

    // Called before each step of the alternation (contact::set_checkpoint): what it throws ends it.
    void set_checkpoint(std::function<void()> hook) { checkpoint_ = std::move(hook); }
    void set_stop(coupling_stop rule) { stop_ = rule; }

    // The fully coupled point at Johnson's load `johnson_point.Q`, from Johnson's level: its pressure
    // `johnson`, its zones workspace (on `johnson`) and its point (k = 0 of the alternation).
    // `checked`: each step's checks (3.3)-(3.4) must hold (a point reported), else resolution_error;
    // without, five zones' are not made (a level of an estimate reads none; s.checks not made: NaN margins: docs/formulation.md
    // 8(q), "The checks where they are read"), three zones' made, not acted on.
    // `coarser`: a coarser level's alternation converged at the same load (or, for a top rung's coarsest level, the
    // finest coupled rung's below it: 8(q), "The top rung's levels from the finest coupled rung"); its last iterate
    // (beta_D p1, its zone ends and kinks, evaluated at this level's points) replaces Johnson's point as the start,
    // which the alternation then leaves for this level's own fixed point (docs/formulation.md 8(e), "The start
    // from the coarser level"); it must outlive this call only.
    const tangential_solution& solve(const normal_solution& johnson, dissimilar_zones& johnson_zones,
                                     const tangential_solution& johnson_point, bool checked,
                                     const full_coupling* coarser = nullptr);

    // The last solve's pressure p (with lambda, e and its beta_D p1 term), solver and zones, through
    // which traction, slip velocity and checks of the point are evaluated; valid until the next solve.
    const normal_solution& normal() const;
    tangential_solver& tangential();
    dissimilar_zones& zones();
    const coupling_summary& summary() const { return summary_; }
    // Whether the last solve stopped because its alternation did not converge (40 steps, or changes that grow; not a
    // step that failed), docs/formulation.md 8(e).
    bool did_not_converge() const { return did_not_converge_; }

private:
    struct iterate;
    kernel k1_, k2_;
    double f_, beta_d_;
    normal_solver normal_solver_;
    sweep_cache sweeps_;  // the product-integration workspaces of every normal solve (collocation.hpp)
    std::unique_ptr<iterate> current_, previous_;
    // The five zones' Newton Jacobian, kept from step to step of the alternation (the ends move little between
    // them: docs/formulation.md 8(e), "The Jacobian kept between steps"), and from the coarser level's last step.
    newton_jacobian jacobian_;
    coupling_summary summary_;
    std::function<void()> checkpoint_;
    coupling_stop stop_ = coupling_stop::contraction;
    bool did_not_converge_ = false;
};

}  // namespace roughroll
