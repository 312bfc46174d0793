// SPDX-License-Identifier: GPL-3.0-or-later
// contact's state and its work (contact.hpp), behind the public class's pointer so that the installed
// header names no solver: the model of the points and its levels (point_model.hpp), Richardson's
// lambda, the estimate's levels and the sweep's route. Not installed; contact.cpp, estimate_levels.cpp
// and swept_point.cpp define its members, contact's own forward to them.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/model/kernel.hpp"
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/point_model.hpp"

namespace roughroll {

struct contact::impl {
    impl(const roughness& surfaces, double f, const solver_options& options, const dissimilar& materials,
         normal_cache* cache, std::shared_ptr<level_store> levels);

    const normal_solution& normal() const;  // contact::normal
    tangential_solution distribution(const tangential_solution& s) { return model_->distribution(s); }
    std::optional<error_estimate> estimate(const tangential_solution& s);  // contact::estimate
    swept_point at_stick_end(double c0);                                   // contact::at_stick_end

    // A sweep's consecutive c0 give nearby systems: each level's point at c0 (point_model::at_stick_end)
    // refines on its last factorisation while sweeping_near_ (dense_system::solve_near, docs/formulation.md
    // "Swept points refined on the previous factorisation"), the same solution to rounding.
    swept_point swept_at(double c0);  // at_stick_end's point, by the route sweeping_near_ picks
    // That point as reported, without its estimate: level n's at c0 (`own`), with Richardson's Q and xi where the
    // method extrapolates (from the companion's point at c0, `coarse`); no load checked.
    tangential_solution reported_at(double c0, tangential_solution& own, std::optional<tangential_solution>& coarse);
    // at_stick_end's refusal (resolution_error) of a load Q(c0) (with `error`: its interval
    // Q +- error) outside [0, f] at an inner c0.
    void refuse_load_outside(const tangential_solution& s, std::optional<double> error) const;
    int nodes() const { return options_.nodes(); }
    std::vector<int> below();        // the n of the estimate's levels below this one, coarsest first
    bool build_levels();             // the two other levels of the estimate; false when none fit
    double kernel_strength() const;  // the larger kernel's sum |T|, for the rounding floors
    kernel widest_kernel() const;    // one term at either kernel's largest rate: the resolution both need
    // The estimate from the three levels' solutions (s of this contact, level-n values `own`): the
    // table of s's structure, the rule of point_estimate.hpp, level 2n solved where it asks.
    error_estimate estimate_from(const tangential_solution& s, const tangential_solution& own,
                                 const std::array<tangential_solution, 3>& at_levels, bool swept);
    pressure_peak peak_of_level(const point_model& level);  // its pressure's peak, once per n where uncoupled
    // Refuses (resolution_error) where `level`, the estimate's level of m nodes, has other zones than s (the general
    // search's structure at another n): their ends are not compared.
    void require_same_zones(const tangential_solution& level, int m, const tangential_solution& s) const;

    roughness surfaces_;
    solver_options options_;
    double f_;
    dissimilar materials_;
    // A model as this contact holds it (level_store::asked): every call through it, whatever the call of the contact,
    // runs with this contact's hook (contact::set_checkpoint), also where the model is the store's and another rung's.
    using held = level_store::asked<point_model>;
    held hold(point_model& m) { return {m, store_.get(), hook_}; }
    held level(int m) { return hold(model_->level(m)); }  // the model's level at m (model_levels), so held

    std::shared_ptr<level_store> store_;         // a ladder's (level_store.hpp), or none
    std::function<void()> hook_;                 // contact::set_checkpoint's
    contact::estimate_term term_;                // contact::set_estimate_term's
    std::shared_ptr<point_model> owner_;         // keeps the points' model, chosen once (the store's keeps the store)
    held model_;                                 // that model, called through here alone
    held companion_;                             // method::extrapolated: the coarse level n/2 (product)
    std::unique_ptr<normal_solution> reported_;  // extrapolated lambda, or empty
    std::array<held, 3> levels_{};               // the estimate's levels, coarsest first; empty: this one
    bool levels_built_ = false;
    bool sweeping_near_ = true;  // false: at_stick_end's second, fresh-LU route for a refused point
    // The peaks of the levels' pressures by n where they do not depend on the load (every structure but full coupling):
    // a curve's rows find them once (peak_of samples 2001 points: 1-2 ms a level at n <= 128).
    std::map<int, pressure_peak> peaks_;
};

}  // namespace roughroll
