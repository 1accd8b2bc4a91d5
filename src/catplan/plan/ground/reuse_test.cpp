#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/ground/reuse.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>

namespace catplan::plan::ground {
namespace {

using namespace plan::testing;

SearchOptions greedy() {
    SearchOptions o;
    o.search = SearchKind::GreedyBestFirst;
    o.heuristic = HeuristicKind::HFF;
    o.max_nodes = 100'000;
    return o;
}

// A state `steps` random valid steps away from x (seeded), each step's parameters bound to named
// parts (in the paper's domain, putting the hand-empty marker block down makes a second marker,
// which the task leaves out).
ACSet walk(const Domain& d, ACSet x, int steps, std::mt19937_64& rng) {
    for (int i = 0; i < steps; ++i) {
        std::vector<std::pair<const Rule*, ACSetMorphism>> moves;
        for (const auto& rule : d.rules) {
            for (auto& m : rewrite::find_matches(*rule, x)) {
                bool named = std::all_of(
                    rule->parameters.begin(), rule->parameters.end(),
                    [&](const auto& p) { return !x.part_name(p.ob, m(p.ob, p.part)).empty(); });
                if (named) {
                    moves.emplace_back(rule.get(), std::move(m));
                }
            }
        }
        if (moves.empty()) {
            break;
        }
        std::uniform_int_distribution<std::size_t> pick(0, moves.size() - 1);
        auto& [rule, m] = moves[pick(rng)];
        EXPECT_TRUE(rewrite::rewrite_in_place(*rule, x, m));
    }
    return x;
}

// The reused task's answer for (x, g), checked: a plan that validates from x to g, as a fresh
// search finds one.
void expect_solves(ReusableTask& task, const Domain& d, const ACSet& x, const ACSet& g) {
    auto initial = std::make_shared<const ACSet>(x);
    auto goal = std::make_shared<const ACSet>(g);
    auto r = task.search(initial, goal, greedy());
    ASSERT_TRUE(r) << r.error();
    EXPECT_EQ(r->path, "grounded");
    EXPECT_EQ(r->stats.ground_seconds, 0.0); // nothing compiled again
    Problem p{"again", std::shared_ptr<const Domain>(&d, [](const Domain*) {}), initial, goal, {}};
    auto fresh = find_plan(p, greedy());
    ASSERT_EQ(r->status, fresh.status) << fresh.path_reason;
    if (r->status == SearchStatus::Solved) {
        auto v = validate_plan(p, *r->plan);
        EXPECT_TRUE(v.valid) << v.reason;
    }
}

TEST(ReusableTask, SearchesFromStatesReachedLaterToOtherGoalsWithoutCompilingAgain) {
    for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        auto names = block_names(7);
        auto d = blocks_domain(true);
        auto first = blocks_problem(d, names, random_towers(7, rng), random_towers(7, rng));
        auto task = ReusableTask::compile(first, greedy());
        ASSERT_TRUE(task) << task.error();
        std::size_t actions = task->task().actions.size();
        ACSet x = *first->initial;
        for (int round = 0; round < 4; ++round) {
            x = walk(*d, std::move(x), 5, rng);
            ACSet g = blocks_goal(d->schema, names, random_towers(7, rng));
            expect_solves(*task, *d, x, g);
            EXPECT_EQ(task->task().actions.size(), actions);
        }
    }
}

TEST(ReusableTask, FollowsSlotsThatRulesDeleteAndCreate) {
    // The paper's domain: taking a block deletes the hand-empty marker block, putting one down
    // makes a new one, so a later state's marker is another part than the first one's.
    auto first = paper_case_study();
    auto task = ReusableTask::compile(first, greedy());
    ASSERT_TRUE(task) << task.error();
    ACSet g(first->domain->schema);
    paper_block(g, "E", Value::string("purple"), {}, true);
    paper_block(g, "D", {}, true, {});
    std::mt19937_64 rng(7);
    ACSet x = *first->initial;
    for (int round = 0; round < 5; ++round) {
        expect_solves(*task, *first->domain, x, g);
        x = walk(*first->domain, std::move(x), 3, rng);
    }
}

TEST(ReusableTask, SaysWhyAStateOrAGoalCannotBeWrittenInTheTask) {
    std::mt19937_64 rng(11);
    auto names = block_names(4);
    auto d = blocks_domain(true);
    auto first = blocks_problem(d, names, {{0, 1}, {2}, {3}}, {{3, 2, 1, 0}});
    auto task = ReusableTask::compile(first, greedy());
    ASSERT_TRUE(task) << task.error();
    auto goal = first->goal;
    // A block the task does not have.
    ACSet more = blocks_state(d->schema, block_names(5), {{0, 1}, {2}, {3}, {4}});
    auto r = task->search(std::make_shared<const ACSet>(more), goal, greedy());
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("Block"), std::string::npos) << r.error();
    // A goal whose blocks have no names.
    ACSet unnamed(d->schema);
    add_block(unnamed, "", true);
    r = task->search(first->initial, std::make_shared<const ACSet>(unnamed), greedy());
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("no entity of the task by name"), std::string::npos) << r.error();
    // A goal fact no state reaches (a block on itself): unsolvable without a search.
    ACSet self = blocks_goal(d->schema, names, {});
    add_on(self, 0, 0, "");
    r = task->search(first->initial, std::make_shared<const ACSet>(self), greedy());
    ASSERT_TRUE(r) << r.error();
    EXPECT_EQ(r->status, SearchStatus::Unsolvable);
    EXPECT_EQ(r->stats.expanded, 0u);
    // And the task still answers for states it can write.
    expect_solves(*task, *d, walk(*d, *first->initial, 3, rng), *goal);
}

} // namespace
} // namespace catplan::plan::ground
