// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/level_store.hpp"

#include <utility>

#include "roughroll/model/kernel.hpp"
#include "roughroll/problems/point_model.hpp"

namespace roughroll {

level_store::level_store() = default;
level_store::~level_store() = default;

method level_store::computed_by(const roughness& surfaces, method how) {
    return how == method::extrapolated && !kernel::layered(surfaces) ? level_of(how) : how;
}

point_model& level_store::model(const key& k, const std::function<std::unique_ptr<point_model>()>& make,
                                std::unique_ptr<point_model>& own) {
    // An 'extrapolated' asker reports its model's method: never given a 'product' model of the same numbers (computed_by).
    for (const auto& [at, m] : shared_)
        if (at == k && (k.options.how != method::extrapolated || m->how() == method::extrapolated)) return *m;
    own = make();
    ++made_[k.options.nodes()];
    if (!own->shared_by_rungs()) return *own;
    own->share_levels_in(this);
    own->set_checkpoint([this] { checkpoint(); });
    return *shared_.emplace_back(k, std::move(own)).second;
}

std::vector<point_model*> level_store::alike(const key& k) const {
    std::vector<point_model*> found;
    for (const auto& [at, m] : shared_) {
        key other = k;
        other.options.n = at.options.nodes();
        if (at.options.nodes() != k.options.nodes() && other == at) found.push_back(m.get());
    }
    return found;
}

}  // namespace roughroll
