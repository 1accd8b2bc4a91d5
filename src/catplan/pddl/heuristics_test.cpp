// The ground heuristics on PDDL domains whose shapes test them: FF's relaxed plan on a grid of
// cells to visit (where the supporter found first may come through a cell visited already), the
// ground task's moves into visited cells (PDDL's set semantics), and RHW's disjunctive landmarks
// over atoms of one predicate (gripper's two hands).

#include "catplan/pddl/detail/test_load.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace catplan::pddl {
namespace {

using namespace testing;

const char* const kVisitall = R"((define (domain visitall)
  (:requirements :strips :typing)
  (:types place)
  (:predicates (connected ?x - place ?y - place) (at-robot ?x - place) (visited ?x - place))
  (:action move
    :parameters (?from - place ?to - place)
    :precondition (and (at-robot ?from) (connected ?from ?to))
    :effect (and (at-robot ?to) (not (at-robot ?from)) (visited ?to)))))";

std::string cell(int x, int y) {
    return fmt::format("cell-{}-{}", x, y);
}

// An n-by-n grid (n-by-height if given), its cells connected to their four neighbours; the robot at
// `at`, the cells `visited` visited (`at` among them), and every cell to be visited.
std::string visitall_problem(int n, std::pair<int, int> at,
                             const std::set<std::pair<int, int>>& visited, int height = 0) {
    height = height == 0 ? n : height;
    std::string objects, init = fmt::format("(at-robot {})", cell(at.first, at.second));
    std::string goal;
    for (int x = 0; x < n; ++x) {
        for (int y = 0; y < height; ++y) {
            objects += cell(x, y) + " ";
            goal += fmt::format("(visited {}) ", cell(x, y));
            if (visited.contains({x, y})) {
                init += fmt::format(" (visited {})", cell(x, y));
            }
            for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                if (x + dx >= 0 && x + dx < n && y + dy >= 0 && y + dy < height) {
                    init += fmt::format(" (connected {} {})", cell(x, y), cell(x + dx, y + dy));
                }
            }
        }
    }
    return fmt::format("(define (problem grid) (:domain visitall) (:objects {}- place) (:init {}) "
                       "(:goal (and {})))",
                       objects, init, goal);
}

plan::SearchResult solve(const Loaded& l, plan::SearchKind search, plan::HeuristicKind h) {
    plan::SearchOptions o;
    o.search = search;
    o.heuristic = h;
    o.max_nodes = 100'000;
    auto r = plan::find_plan(*l.import->problem, o);
    EXPECT_EQ(r.path, "grounded") << r.path_reason;
    EXPECT_EQ(r.status, plan::SearchStatus::Solved) << r.config;
    if (r.plan) {
        auto v = plan::validate_plan(*l.import->problem, *r.plan);
        EXPECT_TRUE(v.valid) << v.reason;
    }
    return r;
}

// The first search's value of heuristic h on the initial state.
std::optional<int> initial(const plan::SearchResult& r, plan::HeuristicKind h) {
    for (const auto& v : r.stats.initial_h) {
        if (v.heuristic == h) {
            return v.value;
        }
    }
    ADD_FAILURE() << "no initial value of " << plan::to_string(h);
    return std::nullopt;
}

// On a 4x4 grid with the robot at (1,1) and (0,0), (1,0), (1,1) visited, the 13 cells left are
// all reached through cells left: a relaxed plan of 13 moves. Cell (2,0) is entered from (1,0)
// or from (2,1) at the same cost; the first would add a move into (1,0), visited already.
TEST(HffOnAGrid, ACellIsEnteredFromOneTheRelaxedPlanEntersAnyway) {
    auto l = load_text(kVisitall, visitall_problem(4, {1, 1}, {{0, 0}, {1, 0}, {1, 1}}));
    ASSERT_TRUE(l->import) << l->errors();
    auto r = solve(*l, plan::SearchKind::GreedyBestFirst, plan::HeuristicKind::HFF);
    EXPECT_EQ(initial(r, plan::HeuristicKind::HFF), 13);
}

// From a corner of a 6x6 grid, greedy search on hff walks a path through all 36 cells and
// expands no state off it (it expanded 446,935 when ties went to the supporter found first).
TEST(HffOnAGrid, GreedySearchVisitsEveryCellWithoutBacktracking) {
    auto l = load_text(kVisitall, visitall_problem(6, {0, 0}, {{0, 0}}));
    ASSERT_TRUE(l->import) << l->errors();
    for (auto search : {plan::SearchKind::GreedyBestFirst, plan::SearchKind::LazyGreedy}) {
        auto r = solve(*l, search, plan::HeuristicKind::HFF);
        ASSERT_TRUE(r.plan) << r.config;
        EXPECT_EQ(r.plan->steps.size(), 35U) << r.config;
        EXPECT_EQ(r.stats.expanded, 35U) << r.config;
        EXPECT_EQ(initial(r, plan::HeuristicKind::HFF), 35);
    }
}

// A move into a cell visited already adds `visited` again: PDDL's set semantics make that no
// change, so the ground task keeps the move (it was an exit, "a second, equal part", and a robot
// in the middle of a corridor could not reach both ends).
TEST(VisitedCells, TheRobotWalksBackThroughACellItVisited) {
    auto l = load_text(kVisitall, visitall_problem(3, {1, 0}, {{1, 0}}, 1));
    ASSERT_TRUE(l->import) << l->errors();
    auto r = solve(*l, plan::SearchKind::GreedyBestFirst, plan::HeuristicKind::HFF);
    ASSERT_TRUE(r.plan);
    EXPECT_EQ(r.plan->steps.size(), 3U); // to one end, back through the middle, to the other
}

// From a cell next to the corner of a 7x7 grid, no path visits each cell once (a chessboard
// colouring: 25 cells of the corner's colour, 24 of the start's), so a plan has at least 49
// moves. Greedy search on hff walks through visited cells where it must (3.0 M expansions and
// no plan while such moves were exits).
TEST(VisitedCells, GreedySearchRevisitsWhereNoPathVisitsEachCellOnce) {
    auto l = load_text(kVisitall, visitall_problem(7, {0, 1}, {{0, 1}}));
    ASSERT_TRUE(l->import) << l->errors();
    auto r = solve(*l, plan::SearchKind::GreedyBestFirst, plan::HeuristicKind::HFF);
    ASSERT_TRUE(r.plan);
    EXPECT_GE(r.plan->steps.size(), 49U);
    EXPECT_LT(r.stats.expanded, 100U);
}

// With n balls in room a to carry to room b: the n goals, at-robby roomb, and per ball "carried
// by the left or by the right gripper", atoms of one predicate on two variables (Fast Downward's
// count too). LAMA then finds the shortest plan, two balls per trip.
TEST(LandmarksOfGripper, EachBallIsCarriedByOneHandOrTheOther) {
    auto l = load("gripper-domain.pddl", "gripper-p16.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    const std::size_t n = 16;
    auto count = solve(*l, plan::SearchKind::LazyGreedy, plan::HeuristicKind::LmCount);
    EXPECT_EQ(initial(count, plan::HeuristicKind::LmCount), static_cast<int>(2 * n + 1));
    auto lama = solve(*l, plan::SearchKind::Lama, plan::HeuristicKind::Default);
    ASSERT_TRUE(lama.plan);
    EXPECT_EQ(lama.plan->steps.size(), 3 * n - 1); // n / 2 trips of 2 picks, a move, 2 drops
}

} // namespace
} // namespace catplan::pddl
