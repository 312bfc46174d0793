// SPDX-License-Identifier: GPL-3.0-or-later
// problems/level_store: an asker's hold on a model (level_store::asked). A default-built hold is an empty slot (a
// contact's companion where nothing is extrapolated, its estimate's own level among the three): asking a model through
// it is a programming error, thrown as std::logic_error (the program's "internal error"), not a null dereference.
#include "roughroll/problems/level_store.hpp"

#include <functional>
#include <stdexcept>

#include <gtest/gtest.h>

namespace roughroll {
namespace {

// A stand-in model: asked<M> only forwards calls to M.
struct counted_model {
    int calls = 0;
    int solve() { return ++calls; }
};

TEST(LevelStoreHold, AnEmptyHoldThrowsInsteadOfFollowingANullModel) {
    const level_store::asked<counted_model> empty;
    EXPECT_FALSE(empty);
    EXPECT_THROW(empty->solve(), std::logic_error);
    EXPECT_THROW((void)*empty, std::logic_error);
}

// Without a store there is no hook to put at work (the hook travels through the store: LevelLadder.EveryCallOfARung
// CallsItsHookOnSharedLevels tests that): the hold forwards to its model, and holds compare by their model.
TEST(LevelStoreHold, AHoldWithoutAStoreForwardsToItsModel) {
    counted_model m;
    const std::function<void()> hook = [] {};
    const level_store::asked<counted_model> held(m, nullptr, hook);
    ASSERT_TRUE(held);
    EXPECT_EQ(held->solve(), 1);
    EXPECT_EQ((*held).calls, 1);
    EXPECT_FALSE(held == level_store::asked<counted_model>{});
    EXPECT_TRUE(held == level_store::asked<counted_model>(m, nullptr, hook));
}

}  // namespace
}  // namespace roughroll
