// SPDX-License-Identifier: GPL-3.0-or-later
// The model of one level's points, chosen once from the options and the materials (make_point_model)
// and held by contact, which keeps Richardson's lambda and the estimate around it:
//   - the paper's stick zone [-1, c0] and zone_solver's general search (docs/formulation.md 4, 7) on
//     the collocation of (4.4), with Richardson's rule on a companion level n/2 for 'extrapolated';
//   - the same on the one-parameter limit's Glauert system ("The one-parameter limit", 7(g));
//   - dissimilar rollers at Johnson's level (8(g)-8(n)): three or five zones, or the edge layers
//     neglected for free rolling of smooth rollers (8(n));
//   - dissimilar rollers at full coupling (8(e)): the alternation from Johnson's point of the level.
// Each model keeps its levels (the same model at the estimate's other n, model_levels) as its own type,
// and caches its last point per Q, so that the levels of an estimate are solved once.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "roughroll/model/dissimilar.hpp"
#include "roughroll/model/kernel.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"
#include "roughroll/problems/full_coupling.hpp"
#include "roughroll/problems/level_store.hpp"
#include "roughroll/problems/normal_problem.hpp"
#include "roughroll/problems/point_estimate.hpp"
#include "roughroll/problems/tangential_solver.hpp"

namespace roughroll {

// What the model of one level is made of (make_point_model, model_levels): the scene, its friction, the options at
// the level's n, the materials, and the normal problems solved before (normal_problem.hpp; may be null).
struct model_input {
    roughness surfaces;
    double f;
    solver_options options;
    dissimilar materials;
    normal_cache* cache;
};

class point_model {
public:
    explicit point_model(const model_input& in)
        : surfaces_(in.surfaces), f_(in.f), options_(in.options), materials_(in.materials) {}
    point_model(const point_model&) = delete;  // its solvers refer to its normal solution
    point_model& operator=(const point_model&) = delete;
    virtual ~point_model() = default;

    int nodes() const { return options_.nodes(); }
    method how() const { return options_.how; }  // the method it was made with (what its normal reports)
    // This level's own normal solution (lambda not extrapolated); at full coupling, after a point,
    // that point's coupled pressure.
    virtual const normal_solution& normal() const = 0;
    // What full coupling's alternation measured at the last point; nullptr for any other model.
    virtual const coupling_summary* coupling() const { return nullptr; }
    // The two-parameter tangential solver; nullptr for the one-parameter limit.
    virtual tangential_solver* tangential() = 0;
    // Johnson's three- and five-zone workspace of this level (dissimilar rollers: Johnson's point, and full coupling's
    // start); null for any other model. For tests that count its searches (contact_internals::johnson_zones).
    virtual const dissimilar_zones* johnson_zones() const { return nullptr; }
    virtual estimate_structure structure() const = 0;
    virtual void set_checkpoint(std::function<void()> hook) { checkpoint_ = std::move(hook); }
    // This model at m nodes by the level method (model_levels): an estimate level, the companion n/2 of
    // 'extrapolated' or level 2n. resolution_error where m does not resolve the kernels.
    virtual point_model& level(int m) = 0;

    // The point reported at Q, its checks made. `below`: the n of the estimate's levels below this one,
    // coarsest first (their points start this level's search), asked for on the first call.
    virtual tangential_solution point(double Q, const std::function<std::vector<int>()>& below) = 0;
    // The point at Q of a curve continued in the load (contact::continued_point): `previous`, the curve's
    // previous row, is a start of the same zone search (issue 24, 3: a layout already solved, zone_start.hpp),
    // tried before the search's own; the answer is the point's, to Newton's resolution. Models with one
    // structure (the paper's, its one-parameter limit) have no start to give: their point.
    virtual tangential_solution continued(double Q, const tangential_solution& previous,
                                          const std::function<std::vector<int>()>& below) {
        static_cast<void>(previous);
        return point(Q, below);
    }
    // This level's solution at s.Q on the zone structure of s (another level's point of this model), its
    // checks made but not acted on: a level of s's estimate. resolution_error where the level has no such
    // solution, naming the estimate of method `how` at n (no_honest_estimate) as refused.
    virtual tangential_solution like(const tangential_solution& s, method how, int n) = 0;
    // The estimate's levels below this one at Q (coarsest first, each with its P_H/P2), solved as point(Q, below) solves
    // them before its own point and kept, so that point(Q, below) next reuses them and their cached points are the
    // levels its estimate reads (full coupling: the ladder's rule (a') for a rung no rung below predicts,
    // docs/formulation.md 8(q)). Throws what point(Q, below) would throw before its own solve. Empty where the model
    // solves no levels before its point (every model but full coupling's, and its no-slip route), or one of them failed.
    virtual std::vector<estimate_level> levels_before(double Q, const std::function<std::vector<int>()>& below) {
        static_cast<void>(Q);
        static_cast<void>(below);
        return {};
    }
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

    // Whether every solution of this model is the same whatever was asked of it before and from which start: no
    // level's point starts another's search, and its caches hold what a fresh solve gives, bit for bit (the
    // one-parameter limit). Such a model is shared by the rungs of a ladder (level_store); any other model's
    // levels start from the level below them, which differs between rungs (8(e) "The start from the coarser
    // level"; the paper's root from n/4's, Johnson's zones from the coarser level's), so sharing it would move
    // the next rung's numbers.
    virtual bool shareable() const { return false; }
    // Whether a ladder's rungs share this model as a level (level_store): shareable() models, and full coupling's
    // (issue 24, cost; docs/formulation.md 8(q) "One chain of levels"). A full-coupling level's point starts its
    // alternation from the level below (8(e) "The start from the coarser level"), so its numbers depend on the chain
    // that reached it; a ladder climbs its rungs in order (128, 256, ...), so rung 2n's levels n/2, n are rung n's
    // own, as solved there, and rung 2n's level 2n starts from rung n's point: the levels of one chain n/4 .. 2n, each
    // solved once. The numbers differ from an explicit n's (whose chain starts at n/4 from Johnson's point) by the
    // alternation's and Newton's stopping rules (measured within 1e-10 of the ends, inside every estimate). For one load
    // (a point: its own ladder and store) rung 2n is only ever reached through rung n, so the answer does not depend on
    // what else was asked. A curve's rows share one ladder (ladder_curve): its levels, as each rung's own levels did
    // before they were shared, keep the previous row's zones (Johnson's five zones continued, zone_start.hpp) and may
    // start a later row's search from them, so a row may differ from the point at its load by Newton's tolerance.
    // Rule (a) of 8(q) becomes exact: rung 2n's levels n/2, n are rung n's, not solved again.
    bool shared_by_rungs() const { return shareable() || structure() == estimate_structure::full_coupling; }
    // The ladder's store where this model's levels are asked for first (level_store.hpp: it outlives this model).
    void share_levels_in(level_store* store) { store_ = store; }

protected:
    // The ladder's models of this scene at the other n, computed by the level method (level_store::alike); none without a
    // store.
    std::vector<point_model*> stored_alike() const {
        if (!store_) return {};
        return store_->alike({surfaces_, f_, materials_,
                              solver_options{nodes(), level_of(options_.how), options_.zones, options_.tolerance}});
    }
    template <class M>
    friend class model_levels;
    void checkpoint() const {
        if (checkpoint_) checkpoint_();
    }
    roughness surfaces_;  // the scene, whose levels differ in n alone (model_levels)
    double f_;
    solver_options options_;
    dissimilar materials_;
    std::function<void()> checkpoint_;
    level_store* store_ = nullptr;  // the ladder's, where it has one
};

// 'extrapolated' on rough surfaces: Richardson's rule on the level n/2 (a smooth scene is exact at one level).
inline bool extrapolates(const roughness& surfaces, const solver_options& options) {
    return options.how == method::extrapolated && kernel::layered(surfaces);
}

// The levels of a model of final type M (point_model::level): its holder's scene at m nodes by the level
// method, each made once and kept. A model reaches its levels as M, so the type says which levels it may use.
// In a ladder a shareable level is its store's, referred to here (level_store.hpp), whose checkpoint is the hook of the
// asker at work (level_store::asked, a contact's); any other is the holder's own, with the holder's checkpoint. Under
// 'extrapolated' the level n/2 is made first, its normal problem from `cache` (normal_problem.hpp).
template <class M>
class model_levels {
public:
    model_levels(const point_model& holder, normal_cache* cache) : holder_(holder) {
        if (extrapolates(holder.surfaces_, holder.options_)) at(holder.nodes() / 2, cache);
    }
    M& at(int m, normal_cache* cache = nullptr) {
        for (M* level : levels_)
            if (level->nodes() == m) return *level;
        // The holder's tolerance too: a rung's level m is the rung m's model on a ladder (level_store's key holds the
        // tolerance, which dissimilar rollers' routes read), so that a ladder at a tolerance of its own shares them as at
        // the default (the near-sliding climb at 1e-3 made levels 128 and 256 twice: LevelLadder.RungsShareTheirLevels).
        const solver_options options{m, level_of(holder_.options_.how), holder_.options_.zones,
                                     holder_.options_.tolerance};
        const auto make = [&] {
            return std::make_unique<M>(model_input{holder_.surfaces_, holder_.f_, options, holder_.materials_, cache});
        };
        std::unique_ptr<point_model> own;
        M& level = dynamic_cast<M&>(
            holder_.store_
                ? holder_.store_->model({holder_.surfaces_, holder_.f_, holder_.materials_, options}, make, own)
                : *(own = make()));
        if (own) {
            level.set_checkpoint([&holder = holder_] { holder.checkpoint(); });
            own_.push_back(std::move(own));
        }
        levels_.push_back(&level);
        return level;
    }
    // The levels at each n of `ms`, as B (M or a base of it).
    template <class B = M>
    std::vector<B*> at(const std::vector<int>& ms) {
        std::vector<B*> levels;
        for (int m : ms) levels.push_back(&at(m));
        return levels;
    }

private:
    const point_model& holder_;
    std::vector<M*> levels_;                         // every level made or asked for, own or the store's
    std::vector<std::unique_ptr<point_model>> own_;  // the levels this model owns (none of the store's)
};

// The model of `materials` and `options` at n = options.nodes() (its normal problem from `cache` where
// solved before, normal_problem.hpp).
std::unique_ptr<point_model> make_point_model(const roughness& surfaces, double f, const solver_options& options,
                                              const dissimilar& materials, normal_cache* cache);

// The normal problem of a model at n = options.nodes() by the level method (normal_problem.hpp).
normal_solution level_normal(const model_input& in);

// The models of dissimilar rollers (dissimilar_model.cpp), for make_point_model.
std::unique_ptr<point_model> make_dissimilar_model(const model_input& in);

}  // namespace roughroll
