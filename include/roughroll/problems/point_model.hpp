// SPDX-License-Identifier: GPL-3.0-or-later
// The model of one level's points, chosen once from the options and the materials (make_point_model)
// and held by contact, which keeps the levels, Richardson's lambda and the estimate around it:
//   - the paper's stick zone [-1, c0] and zone_solver's general search (docs/formulation.md 4, 7) on
//     the collocation of (4.4), with Richardson's rule on a companion level n/2 for 'extrapolated';
//   - the same on the one-parameter limit's Glauert system ("The one-parameter limit", 7(g));
//   - dissimilar rollers at Johnson's level (8(g)-8(n)): three or five zones, or the edge layers
//     neglected for free rolling of smooth rollers (8(n));
//   - dissimilar rollers at full coupling (8(e)): the alternation from Johnson's point of the level.
// Each model caches its last point per Q, so that the levels of an estimate are solved once.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/model/dissimilar.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/problems/tangential_problem.hpp"

namespace roughroll {

class point_model {
public:
    point_model() = default;
    point_model(const point_model&) = delete;  // its solvers refer to its normal solution
    point_model& operator=(const point_model&) = delete;
    virtual ~point_model() = default;

    // This level's own normal solution (lambda not extrapolated); at full coupling, after a point,
    // that point's coupled pressure.
    virtual const normal_solution& normal() const = 0;
    // What full coupling's alternation measured at the last point; nullptr for any other model.
    virtual const coupling_summary* coupling() const { return nullptr; }
    // The two-parameter tangential solver; nullptr for the one-parameter limit.
    virtual tangential_solver* tangential() = 0;
    virtual estimate_structure structure() const = 0;
    virtual void set_checkpoint(std::function<void()> hook) { checkpoint_ = std::move(hook); }

    // The point reported at Q, its checks made. `below`: the same model at the estimate's levels below
    // this one, coarsest first (their points start this level's search), built on the first call.
    virtual tangential_solution point(double Q, const std::function<std::vector<point_model*>()>& below) = 0;
    // This level's solution at s.Q on the zone structure of s (another level's point of this model), its
    // checks made but not acted on: a level of s's estimate. resolution_error where the level has no such
    // solution, naming the estimate of method `how` at n (no_honest_estimate) as refused.
    virtual tangential_solution like(const tangential_solution& s, method how, int n) = 0;
    // The solution whose distributions belong with the reported s (contact::distribution).
    virtual tangential_solution distribution(const tangential_solution& s) { return s; }
    // The paper's zone ending at c0 (a curve swept in c0; check_sweepable refuses the other models first).
    virtual tangential_solution at_stick_end(double c0, bool checked, bool near);

    // p1(r) of (3.15) and v(r) of (3.6) of a solution d of this model as distribution() returns it.
    virtual double traction(const tangential_solution& d, double r) = 0;
    virtual double slip_velocity(const tangential_solution& d, double r) = 0;
    virtual std::vector<double> slip_velocity(const tangential_solution& d, const std::vector<double>& r) {
        std::vector<double> v(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) v[i] = slip_velocity(d, r[i]);
        return v;
    }

    // contact::beyond_every_n (free rolling of smooth dissimilar rollers at Johnson's level only).
    virtual std::optional<std::string> beyond_every_n(double, int, double) const { return std::nullopt; }

protected:
    void checkpoint() const {
        if (checkpoint_) checkpoint_();
    }
    std::function<void()> checkpoint_;
};

// The model of `materials` and `options` at n = options.nodes() (its normal problem from `cache` where
// solved before, normal_problem.hpp). `companion`: the level n/2 of 'extrapolated' (the paper's problem
// extrapolates its points on it; dissimilar rollers report level n), else nullptr.
std::unique_ptr<point_model> make_point_model(const roughness& surfaces, double f, const solver_options& options,
                                              const dissimilar& materials, normal_cache* cache,
                                              point_model* companion);

// The normal problem of a model at n = options.nodes() by the level method (normal_problem.hpp).
normal_solution level_normal(const roughness& surfaces, const solver_options& options, normal_cache* cache);

// The models of dissimilar rollers (dissimilar_model.cpp), for make_point_model.
std::unique_ptr<point_model> make_dissimilar_model(const roughness& surfaces, double f, const solver_options& options,
                                                   const dissimilar& materials, normal_cache* cache);

}  // namespace roughroll
