#pragma once
// The planner: forward state-space search over C-set states.
//
// The successors of a state are, for each rule of the domain in order and each valid match of it
// (rewrite::find_matches, in its deterministic order), the state rewritten at that match (a copy,
// rewrite::rewrite_in_place). States are kept once per isomorphism class (StateRegistry), so the
// search never expands two isomorphic states.
//
//   BreadthFirst     shortest plans (the goal is tested when a state is generated).
//   AStar            f = g + h, ties broken by smaller h then first generated; the goal is tested
//   on
//                    expansion; a cheaper path to a known state reopens it. Optimal with an
//                    admissible heuristic (blind; goalcount in domains where a step adds one goal
//                    fact).
//   GreedyBestFirst  by h only, ties by first generated; the goal is tested when generated.
//
// The plan's steps name the parameters' images in the state where each step applies (`#k` for a
// part without a name). Because states are merged up to isomorphism, the plan is rebuilt at the end
// by replaying the found path from the initial state, carrying each match through an isomorphism
// between the stored state and the replayed one, so the names are those validate_plan sees. A
// step's arguments determine its match when the rule's parameters cover the parts that vary; when
// they do not, validate_plan reports the step as ambiguous.
//
// Limits (0 = none): expanded nodes, seconds, and approximate bytes of stored states; the result
// says which stopped the search. Everything is deterministic except the time and the progress
// reports.

#include "catplan/plan/domain.hpp"
#include "catplan/plan/heuristic.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

namespace catplan::plan {

enum class SearchKind { BreadthFirst, AStar, GreedyBestFirst };

/// "bfs", "astar" or "gbfs"; nullopt for another name.
std::optional<SearchKind> parse_search(std::string_view name);
/// The name parse_search reads.
std::string_view to_string(SearchKind kind);

struct SearchStats {
    std::uint64_t expanded = 0;
    std::uint64_t generated = 0;  // successors produced (including duplicates)
    std::uint64_t duplicates = 0; // successors isomorphic to a state already stored
    std::uint64_t states = 0;     // distinct states stored
    std::uint64_t frontier = 0;   // open nodes now
    std::size_t bytes = 0;        // approximate bytes of stored states
    int f = 0;                    // the f (A*), h (GBFS) or depth (BFS) of the last node expanded
    double seconds = 0;
};

struct SearchOptions {
    SearchKind search = SearchKind::BreadthFirst;
    HeuristicKind heuristic = HeuristicKind::Blind;
    std::uint64_t max_nodes = 0; // expansions
    double max_seconds = 0;
    std::size_t max_bytes = 0;
    /// Called about every progress_interval seconds during a long search.
    std::function<void(const SearchStats&)> progress;
    double progress_interval = 2.0;
};

enum class SearchStatus {
    Solved,
    Unsolvable, // every reachable state was expanded
    NodeLimit,
    TimeLimit,
    MemoryLimit,
};

/// "solved", "unsolvable", "node limit", "time limit", "memory limit".
std::string_view to_string(SearchStatus status);

struct SearchResult {
    SearchStatus status = SearchStatus::Unsolvable;
    std::optional<Plan> plan; // when solved
    SearchStats stats;
};

/// Searches for a plan from problem.initial to a state the goal embeds in (monic on objects).
SearchResult find_plan(const Problem& problem, const SearchOptions& options = {});

} // namespace catplan::plan
