#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/heuristic.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"

#include <gtest/gtest.h>

namespace catplan::plan {
namespace {

using namespace testing;

constexpr HeuristicKind kInformative[] = {HeuristicKind::GoalCount, HeuristicKind::HAdd,
                                          HeuristicKind::HFF};

// The paper's plan for the case study (examples/colorblocksworld/paper.plan).
Plan paper_plan() {
    Plan p;
    for (auto [a, args] :
         std::vector<std::pair<std::string, std::vector<std::string>>>{{"unstack", {"E", "D"}},
                                                                       {"putdown", {"E"}},
                                                                       {"pickup", {"B"}},
                                                                       {"stack", {"B", "D"}},
                                                                       {"pickup", {"A"}},
                                                                       {"stack", {"A", "B"}},
                                                                       {"pickup", {"E"}},
                                                                       {"stack", {"E", "A"}}}) {
        p.steps.push_back({a, args, {}});
    }
    return p;
}

// The states the paper's plan passes through (the initial state first).
std::vector<ACSet> paper_states(const Problem& p) {
    ValidateOptions opt;
    opt.keep_states = true;
    auto v = validate_plan(p, paper_plan(), opt);
    EXPECT_TRUE(v.valid) << v.reason;
    return v.states;
}

SearchResult solve(const Problem& p, SearchKind s, HeuristicKind h) {
    SearchOptions opt;
    opt.search = s;
    opt.heuristic = h;
    opt.max_nodes = 200'000;
    auto r = find_plan(p, opt);
    EXPECT_EQ(r.status, SearchStatus::Solved) << to_string(s) << " " << to_string(h);
    if (r.plan) {
        auto v = validate_plan(p, *r.plan);
        EXPECT_TRUE(v.valid) << v.reason << "\n" << r.plan->to_string();
    }
    return r;
}

TEST(Heuristic, InformativeOnThePapersCaseStudy) {
    // The marker block is deleted and recreated, so Block is not an entity object; its named
    // blocks A..F still are entities (no rule can delete a block that no Empty points at).
    auto p = paper_case_study();
    auto states = paper_states(*p);
    ASSERT_EQ(states.size(), 9u);
    for (auto k : kInformative) {
        auto h = make_heuristic(k, *p);
        int h0 = h->evaluate(states.front());
        EXPECT_GT(h0, 0) << to_string(k);
        EXPECT_LT(h0, kDeadEnd) << to_string(k);
        EXPECT_EQ(h->evaluate(states.back()), 0) << to_string(k);
        for (const auto& x : states) {
            EXPECT_LT(h->evaluate(x), kDeadEnd) << to_string(k);
        }
    }
    // Three On facts are missing (E on A, A on B, B on D); each needs a stack, and the relaxed
    // plan needs at least those three.
    EXPECT_EQ(make_heuristic(HeuristicKind::GoalCount, *p)->evaluate(states.front()), 3);
    EXPECT_GE(make_heuristic(HeuristicKind::HFF, *p)->evaluate(states.front()), 3);
    // Once B is on D (step 4), one goal fact less is missing.
    auto gc = make_heuristic(HeuristicKind::GoalCount, *p);
    EXPECT_EQ(gc->evaluate(states[4]), 2);
}

TEST(Heuristic, ZeroAtTheGoalOnTheStripsBlocksworld) {
    auto d = blocks_domain(true);
    auto names = block_names(5);
    auto p = blocks_problem(d, names, {{0, 1}, {2, 3, 4}}, {{4, 3, 2, 1, 0}});
    ACSet goal_state = blocks_state(d->schema, names, {{4, 3, 2, 1, 0}});
    for (auto k : kInformative) {
        auto h = make_heuristic(k, *p);
        EXPECT_GT(h->evaluate(*p->initial), 0) << to_string(k);
        EXPECT_EQ(h->evaluate(goal_state), 0) << to_string(k);
    }
}

TEST(Heuristic, AStarWithHffSolvesThePapersCaseStudyWithFewerExpansions) {
    // Breadth-first search needs 7821 expansions here (tests/cli/plan_case_study_bfs.expected,
    // not rerun: it takes seconds under the sanitizers). GBFS with h_FF is not asserted: it
    // wanders on a plateau of states that putdown applied to the marker block keeps growing.
    auto p = paper_case_study();
    auto r = solve(*p, SearchKind::AStar, HeuristicKind::HFF);
    ASSERT_TRUE(r.plan);
    EXPECT_LE(r.plan->steps.size(), 10u);
    EXPECT_LT(r.stats.expanded, 7821u / 10);
}

TEST(Heuristic, GuidedSearchBeatsBreadthFirstOnSeededBlocksworlds) {
    auto d = blocks_domain(true);
    for (std::uint64_t seed : {1u, 3u, 4u}) { // seed 2 gives a problem solved initially
        std::mt19937_64 rng(seed);
        auto init = random_towers(5, rng);
        auto goal = random_towers(5, rng);
        auto p = blocks_problem(d, block_names(5), init, goal);
        SCOPED_TRACE("seed " + std::to_string(seed));
        auto bfs = solve(*p, SearchKind::BreadthFirst, HeuristicKind::Blind);
        ASSERT_GT(bfs.stats.expanded, 0u);
        for (auto s : {SearchKind::AStar, SearchKind::GreedyBestFirst}) {
            auto r = solve(*p, s, HeuristicKind::HFF);
            EXPECT_LT(r.stats.expanded, bfs.stats.expanded) << to_string(s);
        }
    }
}

} // namespace
} // namespace catplan::plan
