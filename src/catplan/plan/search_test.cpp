#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/state_registry.hpp"
#include "catplan/plan/validate.hpp"

#include <gtest/gtest.h>

namespace catplan::plan {
namespace {

using namespace testing;

const std::vector<std::string> kABC{"A", "B", "C"};

// The Sussman anomaly: C on A, B on the table; the goal is A on B on C (6 steps at least).
ProblemPtr sussman(bool labelled = true) {
    return blocks_problem(blocks_domain(labelled), kABC, {{0, 2}, {1}}, {{2, 1, 0}});
}

void expect_valid(const Problem& p, const SearchResult& r) {
    ASSERT_EQ(r.status, SearchStatus::Solved);
    ASSERT_TRUE(r.plan);
    auto v = validate_plan(p, *r.plan);
    EXPECT_TRUE(v.valid) << v.reason << "\n" << r.plan->to_string();
}

TEST(Search, BreadthFirstFindsAShortestPlan) {
    auto p = sussman();
    auto r = find_plan(*p);
    expect_valid(*p, r);
    EXPECT_EQ(r.plan->steps.size(), 6u);
    EXPECT_EQ(r.plan->to_string(), "unstack(C, A)\nputdown(C)\npickup(B)\nstack(B, C)\n"
                                   "pickup(A)\nstack(A, B)\n");
    EXPECT_GT(r.stats.expanded, 0u);
    EXPECT_GE(r.stats.generated, r.stats.duplicates);
}

TEST(Search, AStarIsOptimalWithBlindAndGoalCount) {
    auto p = sussman();
    for (auto h : {HeuristicKind::Blind, HeuristicKind::GoalCount}) {
        SearchOptions opt;
        opt.search = SearchKind::AStar;
        opt.heuristic = h;
        auto r = find_plan(*p, opt);
        expect_valid(*p, r);
        EXPECT_EQ(r.plan->steps.size(), 6u) << to_string(h);
    }
}

TEST(Search, EveryConfigurationFindsAValidPlan) {
    auto p =
        blocks_problem(blocks_domain(true), {"A", "B", "C", "D"}, {{0, 1, 2, 3}}, {{3, 2, 1, 0}});
    for (auto s : {SearchKind::AStar, SearchKind::GreedyBestFirst}) {
        for (auto h : {HeuristicKind::Blind, HeuristicKind::GoalCount, HeuristicKind::HAdd,
                       HeuristicKind::HFF}) {
            SearchOptions opt;
            opt.search = s;
            opt.heuristic = h;
            auto r = find_plan(*p, opt);
            SCOPED_TRACE(std::string(to_string(s)) + " " + std::string(to_string(h)));
            expect_valid(*p, r);
            EXPECT_GE(r.plan->steps.size(), 6u);
        }
    }
}

TEST(Search, DuplicatesAreDetectedUpToIsomorphism) {
    // The goal needs a fourth block, so the search expands every reachable state: 13 ways to
    // stack three labelled blocks with the hand empty, and 3 x 3 holding one; without labels,
    // only the shapes count: 3 + 2 for the C-set search, which merges isomorphic states, and 22
    // for the grounded search, which compares states exactly.
    for (bool ground : {false, true}) {
        for (bool labelled : {true, false}) {
            auto d = blocks_domain(labelled);
            auto p = std::make_shared<Problem>();
            p->domain = d;
            p->initial = std::make_shared<ACSet>(blocks_state(d->schema, kABC, {{0}, {1}, {2}}));
            p->goal = std::make_shared<ACSet>(blocks_goal(d->schema, {"A", "B", "C", "D"}, {}));
            SearchOptions opt;
            opt.ground = ground;
            auto r = find_plan(*p, opt);
            EXPECT_EQ(r.path, ground ? "grounded" : "C-set");
            EXPECT_EQ(r.status, SearchStatus::Unsolvable);
            EXPECT_FALSE(r.plan);
            std::uint64_t expected = labelled || ground ? 22 : 5;
            EXPECT_EQ(r.stats.expanded, expected);
            EXPECT_EQ(r.stats.states, expected);
            EXPECT_EQ(r.stats.generated - r.stats.duplicates + 1, expected);
        }
    }
}

TEST(Search, UnlabelledBlocksStillGiveValidPlans) {
    // Without labels, a goal "some block on some block on some block" is what matters, and the
    // plan's names come from the replay, not from the merged states.
    auto p = sussman(false);
    auto r = find_plan(*p);
    expect_valid(*p, r);
    EXPECT_EQ(r.plan->steps.size(), 2u); // C is already on A: pickup(B), stack(B, C)
}

TEST(Search, InitialStateSatisfyingTheGoalGivesAnEmptyPlan) {
    auto p = blocks_problem(blocks_domain(true), kABC, {{0, 2}, {1}}, {{0, 2}});
    auto r = find_plan(*p);
    ASSERT_EQ(r.status, SearchStatus::Solved);
    EXPECT_TRUE(r.plan->steps.empty());
}

TEST(Search, LimitsStopTheSearch) {
    auto p = sussman();
    SearchOptions nodes;
    nodes.max_nodes = 2;
    auto r = find_plan(*p, nodes);
    EXPECT_EQ(r.status, SearchStatus::NodeLimit);
    EXPECT_EQ(r.stats.expanded, 2u);
    EXPECT_FALSE(r.plan);
    SearchOptions memory;
    memory.max_bytes = 1;
    EXPECT_EQ(find_plan(*p, memory).status, SearchStatus::MemoryLimit);
    SearchOptions time;
    time.max_seconds = 1e-9;
    EXPECT_EQ(find_plan(*p, time).status, SearchStatus::TimeLimit);
}

TEST(Search, ProgressIsReported) {
    auto p = sussman();
    SearchOptions opt;
    opt.progress_interval = 0;
    int calls = 0;
    opt.progress = [&](const SearchStats& s) {
        ++calls;
        EXPECT_GT(s.expanded, 0u);
    };
    (void)find_plan(*p, opt);
    EXPECT_GT(calls, 0);
}

TEST(Search, StatisticsNameEachHeuristicsValueOnTheInitialState) {
    SearchStats st;
    st.expanded = 3;
    st.evaluated = 4;
    EXPECT_EQ(describe(st, false, "; "),
              "; expanded 3, evaluated 4, generated 0, duplicates 0, states 0\n");
    st.initial_h = {{HeuristicKind::HFF, 6}, {HeuristicKind::LmCount, std::nullopt}};
    EXPECT_EQ(describe(st, false, "# "), "# expanded 3, evaluated 4, generated 0, duplicates 0, "
                                         "states 0; initial state: hff 6, lmcount dead end\n");
}

TEST(Heuristic, ValuesOnTheSussmanAnomaly) {
    auto p = sussman();
    ACSet goal_state = blocks_state(p->domain->schema, kABC, {{2, 1, 0}});
    auto gc = make_heuristic(HeuristicKind::GoalCount, *p);
    EXPECT_EQ(gc->evaluate(*p->initial), 2);
    EXPECT_EQ(gc->evaluate(goal_state), 0);
    for (auto k : {HeuristicKind::HAdd, HeuristicKind::HFF}) {
        auto h = make_heuristic(k, *p);
        int v = h->evaluate(*p->initial);
        EXPECT_GE(v, 2) << to_string(k);
        EXPECT_LT(v, kDeadEnd) << to_string(k);
        EXPECT_EQ(h->evaluate(goal_state), 0) << to_string(k);
    }
    // h_FF's relaxed plan: unstack(C, A), pickup(B), stack(B, C), pickup(A)... at most 6.
    EXPECT_LE(make_heuristic(HeuristicKind::HFF, *p)->evaluate(*p->initial), 6);
    EXPECT_EQ(parse_heuristic("hff"), HeuristicKind::HFF);
    EXPECT_FALSE(parse_heuristic("foo"));
    EXPECT_EQ(parse_search("gbfs"), SearchKind::GreedyBestFirst);
}

TEST(StateRegistry, KeepsOneStatePerIsomorphismClass) {
    auto d = blocks_domain(false);
    StateRegistry reg;
    auto a = reg.insert(blocks_state(d->schema, kABC, {{0, 1}, {2}}));
    auto b = reg.insert(blocks_state(d->schema, kABC, {{2, 0}, {1}})); // same shape
    auto c = reg.insert(blocks_state(d->schema, kABC, {{0, 1, 2}}));
    EXPECT_TRUE(a.is_new);
    EXPECT_FALSE(b.is_new);
    EXPECT_EQ(b.id, a.id);
    EXPECT_TRUE(c.is_new);
    EXPECT_EQ(reg.size(), 2u);
    EXPECT_GT(reg.bytes(), 0u);
}

} // namespace
} // namespace catplan::plan
