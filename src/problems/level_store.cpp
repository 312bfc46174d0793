// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/level_store.hpp"

#include <utility>

#include "roughroll/problems/point_model.hpp"

namespace roughroll {

level_store::level_store() = default;
level_store::~level_store() = default;

point_model& level_store::model(const key& k, const std::function<std::unique_ptr<point_model>()>& make,
                                std::unique_ptr<point_model>& own) {
    for (const auto& [at, m] : shared_)
        if (at == k) return *m;
    own = make();
    ++made_[k.options.nodes()];
    if (!own->shareable()) return *own;
    own->share_levels_in(this);
    own->set_checkpoint([this] { checkpoint(); });
    return *shared_.emplace_back(k, std::move(own)).second;
}

}  // namespace roughroll
