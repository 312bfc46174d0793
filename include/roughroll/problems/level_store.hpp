// SPDX-License-Identifier: GPL-3.0-or-later
// The levels solved by the rungs of one ladder (issue 24, 4; level_ladder.hpp): a point_model made once per key
// (everything a level's numbers depend on) is given again to the next rung that asks for the same key, where the
// model is shareable() (its numbers the same bit for bit, whoever asked first: the one-parameter limit). Counts the
// models made at each n, shared or not: a level solved twice in a climb shows as 2. Not installed; its members are
// defined in level_store.cpp.
//
// Who owns what (no model owns another model of the store, so no cycle of owners can form):
//   - the store owns every shared model, and nothing else;
//   - a shared model refers to its levels (shared models of the same store, model_levels) and to the store without
//     owning them: all of them end with the store;
//   - a model that is not shareable is owned by its holder (a contact, or the model whose level it is), its levels
//     with it; as a contact's model it refers to the store (to count its levels), which that contact keeps;
//   - the store is owned by its ladder and by every contact built with it (contact_internals::with_levels, whose
//     model is an aliasing pointer to the store where the store owns it): a released contact (level_ladder::release,
//     the program's answer) keeps its model and that model's levels after the ladder ends.
// A shared model's checkpoint is the store's: the hook of the asker whose call it serves. An asker (a contact) holds each
// model it asks for, its own model and its estimate's levels, as asked<>: every call through it runs with the asker's
// hook at work in the store, so a level made by one rung and asked for by another calls the asking rung's hook, and no
// call of the asker can reach a model without its hook.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "roughroll/model/dissimilar.hpp"
#include "roughroll/model/roughness.hpp"
#include "roughroll/numerics/method.hpp"

namespace roughroll {

class point_model;
struct tangential_solution;
struct error_estimate;

class level_store {
public:
    struct key {
        roughness surfaces;
        double f;
        dissimilar materials;
        solver_options options;
        // Equal in every field (n as nodes(), an empty tolerance as default_tolerance, 'extrapolated' on smooth rollers as
        // 'product': computed_by); fields() takes the key and each value in it apart by a structured binding, so that a
        // field added to any of them stops the build there.
        auto fields() const {
            const auto term = [](const roughness_term& t) {
                const auto& [T, A] = t;
                return std::make_tuple(T, A);
            };
            const auto cylinder = [&term](const cylinder_roughness& c) {
                const auto& [tangential, normal] = c;
                return std::tuple_cat(term(tangential), term(normal));
            };
            const auto& [scene_surfaces, friction, scene_materials, scene_options] = *this;
            const auto& [cylinder1, cylinder2] = scene_surfaces;
            const auto& [beta_d, coupling] = scene_materials;
            [[maybe_unused]] const auto& [n, how, zones, tolerance] = scene_options;
            return std::tuple_cat(cylinder(cylinder1), cylinder(cylinder2),
                                  std::make_tuple(friction, beta_d, coupling, scene_options.nodes(),
                                                  computed_by(scene_surfaces, how), zones,
                                                  tolerance.value_or(default_tolerance)));
        }
        bool operator==(const key& other) const { return fields() == other.fields(); }
    };
    // The method a model's numbers are computed by: 'extrapolated' on smooth rollers is its level method 'product' (one
    // level is exact: point_model.hpp's extrapolates), so that a rung's own model (the scene's default method) is the
    // level of the same n the next rung asks for (issue 24, cost; full coupling's one chain, point_model::shared_by_rungs).
    // The model made first keeps its own method for what it reports (JSON "method"), so an asker under 'extrapolated' (a
    // rung's contact) is given only a model made under 'extrapolated' (model(): never a level made first as 'product',
    // e.g. a level 2n asked by rung n's estimate before rung 2n: on smooth rollers none is asked, and on rough ones,
    // which confirm changes of opposite sign on it, the key keeps the two methods apart anyway; docs/formulation.md 8(q)
    // "Changes of opposite sign", session 23); a 'product' asker (a level) takes either.
    static method computed_by(const roughness& surfaces, method how);
    level_store();  // out of line, as the destructor: point_model is complete only in level_store.cpp
    level_store(const level_store&) = delete;
    level_store& operator=(const level_store&) = delete;
    ~level_store();

    // The model at k: the store's where it is shared_by_rungs() (made before by any rung, or now by make() and kept), else
    // make()'s, handed over in `own` to the caller, who owns it. Counted at k's n when made.
    point_model& model(const key& k, const std::function<std::unique_ptr<point_model>()>& make,
                       std::unique_ptr<point_model>& own);
    // The shared models of k's scene at every other n (each field of k but n equal), for a model that starts from another
    // level's solution: full coupling's rung 1000, whose levels 250, 500 double no rung (docs/formulation.md 8(q),
    // "The top rung's levels from the finest coupled rung"). Made nothing, counted nothing.
    std::vector<point_model*> alike(const key& k) const;
    // How many models at n were made: a level solved by two rungs on models of their own counts 2.
    int made(int n) const {
        const auto it = made_.find(n);
        return it == made_.end() ? 0 : it->second;
    }

    // The ladder's tolerance as its rungs' estimates may ask it (level_ladder's check_estimate of a point s with its
    // P_H/P2 `lambda`): true where the estimate fails it. A rung's estimate whose changes of opposite sign would be
    // confirmed on level 2n, and which fails it before that confirmation, cannot answer whatever level 2n adds, so it
    // does not solve level 2n (docs/formulation.md 8(q) "Changes of opposite sign"; error_estimate::lower_bound).
    // Set by level_ladder::climb for the climb alone (empty before and after it, and while it confirms such an
    // estimate), so that no estimate asked outside a climb is a lower bound. Holds values only (the ladder's tolerance
    // and kernels' strength), never the ladder.
    using tolerance_test = std::function<bool(const tangential_solution& s, double lambda, const error_estimate& e)>;
    void set_tolerance_test(tolerance_test fails) { fails_tolerance_ = std::move(fails); }
    const tolerance_test& fails_tolerance() const { return fails_tolerance_; }

private:
    // While one lives, `hook` (an asker's checkpoint) is the one every shared model's solve calls; then the one before.
    class at_work {
    public:
        at_work(level_store* store, const std::function<void()>& hook)
            : store_(store), before_(store ? std::exchange(store->hook_, &hook) : nullptr) {}
        at_work(const at_work&) = delete;
        at_work& operator=(const at_work&) = delete;
        ~at_work() {
            if (store_) store_->hook_ = before_;
        }

    private:
        level_store* store_;
        const std::function<void()>* before_;
    };

public:
    // A model as one asker holds it (a contact's model and levels): `->` calls it with the asker's hook at work in
    // `store` for that call alone (at_work, the hook before it restored after the call, also where it throws). Without
    // a store it is the model itself, whose checkpoint is its holder's (point_model::set_checkpoint). `*` gives the
    // model read-only: its const members solve nothing, so call no checkpoint.
    // Default-built it is empty: a slot that holds no model (contact's companion where nothing is extrapolated, its
    // estimate's own level among the three), told by `bool`. Every caller tests it first; `->` or `*` on an empty one
    // would follow a null model and hook, so both throw std::logic_error instead (a programming error: the program's
    // "internal error", exit 70), never undefined behaviour.
    template <class M>
    class asked {
    public:
        asked() = default;
        asked(M& model, level_store* store, const std::function<void()>& hook)
            : model_(&model), store_(store), hook_(&hook) {}

        class call {  // lives to the end of the full expression that called through ->
        public:
            call(const call&) = delete;
            call& operator=(const call&) = delete;
            M* operator->() const { return model_; }

        private:
            friend class asked;
            call(level_store* store, const std::function<void()>& hook, M* model)
                : working_(store, hook), model_(model) {}
            at_work working_;
            M* model_;
        };
        call operator->() const { return call(store_, *held().hook_, model_); }
        const M& operator*() const { return *held().model_; }
        explicit operator bool() const { return model_ != nullptr; }
        bool operator==(const asked& other) const { return model_ == other.model_; }

    private:
        const asked& held() const {
            if (!model_ || !hook_)
                throw std::logic_error(
                    "level_store::asked: a model asked for through an empty hold (no model was "
                    "given to this slot)");
            return *this;
        }
        M* model_ = nullptr;
        level_store* store_ = nullptr;
        const std::function<void()>* hook_ = nullptr;
    };

private:
    void checkpoint() const {
        if (hook_ && *hook_) (*hook_)();
    }
    std::vector<std::pair<key, std::unique_ptr<point_model>>> shared_;
    std::map<int, int> made_;
    tolerance_test fails_tolerance_;
    const std::function<void()>* hook_ = nullptr;  // the asker at work's (at_work, asked)
};

}  // namespace roughroll
