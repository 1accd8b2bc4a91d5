#pragma once
// The state space of a ground task as the search engines see it: states stored once (exactly),
// the actions applicable in a state, successors, the goal test, per-state search nodes, the
// limits and the statistics.

#include "catplan/plan/ground/heuristics.hpp"
#include "catplan/plan/ground/successors.hpp"
#include "catplan/plan/search.hpp"

#include <deque>
#include <optional>

namespace catplan::plan::ground {

/// How a search reached a state.
struct Node {
    StateId parent = kNone;
    ActionId action = kNone;
    int g = 0;
    bool closed = false;
    bool dead = false;
};

class Space {
public:
    /// The space of task; with `costs` a step costs what its action does (Action::cost), else 1.
    Space(const Task& task, Budget& budget, const SearchOptions& options, SearchStats& stats,
          bool costs = false);

    const Task& task;

    /// What taking a costs in this search.
    int cost(ActionId a) const { return costs_ ? task.actions[a].cost : 1; }

    StateId initial();

    /// The actions applicable in s (exits included: successor() refuses them).
    void applicable(StateId s, std::vector<ActionId>& out) const {
        generator_.applicable(registry_.state(s), out);
    }

    /// The state a leads to from s (stored), or nullopt when a leaves the task (counted).
    std::optional<StateRegistry::Insertion> successor(StateId s, ActionId a);

    bool is_goal(StateId s) const { return ground::is_goal(task, packer_, registry_.state(s)); }

    /// The state's value per variable (valid until the next call).
    const std::vector<std::uint32_t>& values(StateId s);

    Node& node(StateId s) {
        while (nodes_.size() <= s) {
            nodes_.emplace_back();
        }
        return nodes_[s];
    }

    /// The actions from the initial state to s.
    std::vector<ActionId> path_to(StateId s);

    /// The node or time or memory limit reached, if any; reports progress now and then.
    std::optional<SearchStatus> limit_reached();

    SearchStats& stats;
    /// The heuristics' values on the initial state, in the order the engine took them (kDeadEnd
    /// for a dead end; a lazy search stops at the first that finds one); empty without any.
    std::vector<int> initial_values;
    /// Transitions refused because their result is outside the task, and one example.
    std::uint64_t exits = 0;
    std::string exit_example;

    std::size_t num_states() const { return registry_.size(); }

private:
    Budget& budget_;
    const SearchOptions& options_;
    bool costs_;
    StatePacker packer_;
    StateRegistry registry_;
    SuccessorGenerator generator_;
    std::vector<Word> scratch_;
    std::vector<std::uint32_t> values_;
    std::deque<Node> nodes_;
    Clock::time_point last_report_;
};

/// What an engine found: a plan (ground actions), or why it stopped.
struct EngineResult {
    SearchStatus status = SearchStatus::Unsolvable;
    std::vector<ActionId> plan;
};

/// Breadth-first search (shortest plans; the goal tested on generation).
EngineResult breadth_first(Space& space);

/// Eager best-first search: A* (f = g + h, g summing Space::cost, ties by h then first in, goal
/// tested on expansion, reopening) when astar, else greedy by h (goal tested on generation), as
/// Fast Downward's eager_greedy.
EngineResult eager_best_first(Space& space, Evaluator& h, bool astar);

/// Lazy best-first search with deferred evaluation (successors enter the open lists with their
/// parent's values and are evaluated when taken): greedy when weight is 0, else weighted A* with
/// f = g + weight * h; one open list per evaluator, and when `preferred` (evaluators of hs whose
/// preferred operators count) is not empty one more each holding only preferred successors, taken
/// in turn, the preferred ones boosted by 1000 whenever an evaluator's best value improves (Fast
/// Downward's lazy_greedy / lazy_wastar). g sums Space::cost; successors with g >= bound are
/// pruned (0: no bound).
EngineResult lazy_best_first(Space& space, const std::vector<Evaluator*>& hs,
                             const std::vector<Evaluator*>& preferred, int weight, int bound);

} // namespace catplan::plan::ground
