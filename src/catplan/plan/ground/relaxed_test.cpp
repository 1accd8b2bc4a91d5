#include "catplan/plan/ground/relaxed.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace catplan::plan::ground {
namespace {

std::vector<std::pair<int, Prop>> drain(AdaptiveQueue& q) {
    std::vector<std::pair<int, Prop>> out;
    while (!q.empty()) {
        out.push_back(q.pop());
    }
    return out;
}

using Popped = std::vector<std::pair<int, Prop>>;

TEST(AdaptiveQueue, LeastCostFirstAndOfEqualCostsThePropositionPushedLast) {
    AdaptiveQueue q;
    q.push(2, 7);
    q.push(0, 1);
    q.push(2, 8);
    q.push(1, 4);
    q.push(0, 2);
    EXPECT_EQ(drain(q), (Popped{{0, 2}, {0, 1}, {1, 4}, {2, 8}, {2, 7}}));
}

TEST(AdaptiveQueue, WithLeastPropositionTiesEqualCostsPopByProposition) {
    AdaptiveQueue q(AdaptiveQueue::Ties::LeastProposition);
    q.push(2, 7);
    q.push(0, 5);
    q.push(2, 3);
    q.push(0, 1);
    q.push(2, 9);
    EXPECT_EQ(q.pop(), (std::pair<int, Prop>{0, 1}));
    q.push(0, 2); // pushed while its bucket is popped
    EXPECT_EQ(drain(q), (Popped{{0, 2}, {0, 5}, {2, 3}, {2, 7}, {2, 9}}));
}

// LM-cut lowers values after a cut: a cost below the last one popped comes out next.
TEST(AdaptiveQueue, ACostBelowTheLastPoppedComesOutNext) {
    AdaptiveQueue q;
    q.push(5, 1);
    q.push(9, 2);
    EXPECT_EQ(q.pop(), (std::pair<int, Prop>{5, 1}));
    q.push(3, 3);
    EXPECT_EQ(drain(q), (Popped{{3, 3}, {9, 2}}));
}

TEST(AdaptiveQueue, LargeCostsComeOutAfterSmallOnesInOrder) {
    AdaptiveQueue q;
    q.push(1 << 20, 1);
    q.push(7, 2);
    q.push((1 << 20) - 1, 3);
    q.push(1 << 15, 4);
    EXPECT_EQ(drain(q), (Popped{{7, 2}, {1 << 15, 4}, {(1 << 20) - 1, 3}, {1 << 20, 1}}));
}

TEST(AdaptiveQueue, ClearLeavesItEmptyAndUsable) {
    AdaptiveQueue q;
    q.push(4, 1);
    q.push(1 << 20, 2);
    q.clear();
    EXPECT_TRUE(q.empty());
    q.push(6, 3);
    EXPECT_EQ(drain(q), (Popped{{6, 3}}));
}

} // namespace
} // namespace catplan::plan::ground
