#pragma once
// The planner: forward state-space search from a problem's initial state to a state the goal
// embeds in (monic on objects).
//
// Two searches. The grounded search (ground/) compiles the problem once into finite-domain
// variables and ground actions when its entity parts are fixed (ground/compile.hpp), then
// searches packed states compared exactly; every plan it finds is replayed as DPO steps and
// checked by validate_plan before it is returned. Where it does not apply, or cannot prove that no
// plan exists, the C-set search runs, and SearchResult::path says which ran and why.
//
// The C-set search (cset_search.hpp): the successors of a state are, for each rule of the domain
// in order and each valid match of it (rewrite::find_matches, in its deterministic order), the
// state rewritten at that match. States are kept once per isomorphism class (StateRegistry).
//
//   BreadthFirst     shortest plans (the goal is tested when a state is generated).
//   AStar            f = g + h, ties broken by smaller h then first generated; the goal is tested
//                    on expansion; a cheaper path to a known state reopens it. Optimal with an
//                    admissible heuristic (blind; goalcount in domains where a step adds one goal
//                    fact).
//   GreedyBestFirst  by h only, ties by first generated; the goal is tested when generated.
//   LazyGreedy       (grounded) lazy greedy best-first with deferred evaluation and the
//                    heuristic's preferred operators in a second, boosted open list.
//   Lama             (grounded) the same with hff and lmcount in turn (Richter & Westphal).
// A configuration the C-set search lacks runs as its nearest (lazy and lama as gbfs with hff,
// lmcut as hmax, lmcount as hff), and the result says so.
//
// Limits (limits.hpp): expansions, seconds and resident megabytes of the process; every phase
// counts (from SearchOptions::start, which a caller sets to when it began reading its input), and
// the result says which limit stopped the search. Everything is deterministic except the time,
// the memory and the progress reports.

#include "catplan/plan/domain.hpp"
#include "catplan/plan/heuristic.hpp"
#include "catplan/plan/limits.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::plan {

enum class SearchKind {
    BreadthFirst,
    AStar,
    GreedyBestFirst, // eager
    LazyGreedy,      // lazy, with the heuristic's preferred operators (grounded search only)
    Lama,            // lazy greedy, hff and lmcount in turn, preferred operators (grounded only)
};

/// "bfs", "astar", "gbfs", "lazy" or "lama"; nullopt for another name.
std::optional<SearchKind> parse_search(std::string_view name);
/// The name parse_search reads.
std::string_view to_string(SearchKind kind);

/// A heuristic's value on the initial state; nullopt where it finds that state a dead end.
struct InitialValue {
    HeuristicKind heuristic = HeuristicKind::Default;
    std::optional<int> value;

    bool operator==(const InitialValue&) const = default;
};

struct SearchStats {
    std::uint64_t expanded = 0;
    std::uint64_t evaluated = 0;  // heuristic evaluations
    std::uint64_t generated = 0;  // successors produced (including duplicates)
    std::uint64_t duplicates = 0; // successors equal (C-set: isomorphic) to a state stored before
    std::uint64_t states = 0;     // distinct states stored
    std::uint64_t frontier = 0;   // open nodes now
    /// The first search's heuristics on the initial state, in the order its configuration names
    /// them (Fast Downward's "initial heuristic value"); empty for breadth-first search.
    std::vector<InitialValue> initial_h;
    int f = 0;                    // the f (A*), h (GBFS) or depth (BFS) of the last node expanded
    double seconds = 0;           // since the start: every phase
    double setup_seconds = 0;     // from the start to the first expansion (input, heuristics)
    double ground_seconds = 0;    // of which compiling the ground task (grounded search)
    std::uint64_t variables = 0;  // of the ground task (grounded search)
    std::uint64_t actions = 0;    // ground actions (grounded search)
    std::uint64_t plans = 0;      // plans found (more than one with anytime)
    std::size_t memory = 0;       // resident bytes of the process now
    std::size_t peak_memory = 0;  // the largest resident bytes seen
    double cpu_seconds = 0;       // CPU time of the process at the end (all its threads)
    double setup_cpu_seconds = 0; // CPU time of the process when the set-up ended
    std::size_t setup_memory = 0; // resident bytes when the set-up ended

    /// Seconds of search proper (seconds - setup_seconds).
    double search_seconds() const { return seconds > setup_seconds ? seconds - setup_seconds : 0; }

    /// CPU seconds of search proper (cpu_seconds - setup_cpu_seconds).
    double search_cpu_seconds() const {
        return cpu_seconds > setup_cpu_seconds ? cpu_seconds - setup_cpu_seconds : 0;
    }

    /// Records the end of the set-up: its wall time, CPU time and resident memory.
    void end_setup(Budget& budget) {
        setup_seconds = budget.elapsed();
        setup_cpu_seconds = Budget::cpu_seconds();
        (void)budget.check();
        setup_memory = budget.resident();
    }
};

struct SearchOptions {
    SearchKind search = SearchKind::BreadthFirst;
    HeuristicKind heuristic = HeuristicKind::Default;
    /// Compile the problem into a ground task when it allows it (search.hpp's grounded search).
    bool ground = true;
    /// After the first plan, keep looking for shorter ones (weighted A* with weights 5, 3, 2, 1,
    /// bounded by the best plan) until the time limit or until the last weight is done.
    bool anytime = false;
    /// Check a grounded search's plan from its text (validate_plan) before returning it. A
    /// caller that replays the steps by their text and checks where they lead may leave it off.
    bool validate = true;
    std::uint64_t max_nodes = 0; // expansions
    double max_seconds = 0;
    /// Resident bytes of the whole process; 0: the default, 75% of the machine's memory
    /// (default_memory_limit_bytes); SIZE_MAX for none.
    std::size_t max_bytes = 0;
    /// When the work began (reading the input, say); unset: when find_plan is called.
    std::optional<Clock::time_point> start;
    /// Called about every progress_interval seconds during a long search.
    std::function<void(const SearchStats&)> progress;
    double progress_interval = 2.0;

    /// The limits, the default memory limit filled in.
    Limits limits() const;
};

struct SearchResult {
    SearchStatus status = SearchStatus::Unsolvable;
    std::optional<Plan> plan; // when solved
    SearchStats stats;
    /// Which search ran: "grounded" or "C-set"; why the C-set search ran, when it did.
    std::string path, path_reason;
    /// The configuration that ran, in words ("lazy greedy best-first, hff and lmcount, preferred
    /// operators").
    std::string config;
    /// Whether the plan is optimal (A* with an admissible heuristic over every transition): of
    /// least cost where `costs`, else shortest.
    bool optimal = false;
    /// Whether the search summed the steps' costs (Problem::step_cost), on a ground task whose
    /// actions do not all cost 1: A*, and the anytime searches after the first plan. Every other
    /// search counts each step as 1.
    bool costs = false;
    /// Ground actions left out because the problem gives their step no cost, and why costs were
    /// not counted where they could not be (ground/task.hpp: Task::uncosted, costs_ignored).
    std::uint64_t uncosted = 0;
    std::string costs_ignored;
    /// Transitions the grounded search could not follow (exits, ground/task.hpp) and one example;
    /// with any, "unsolvable" is not claimed from the grounded search.
    std::uint64_t exits = 0;
    std::string exit_example;
    /// What a plan found does not say by itself (empty: nothing), e.g. that a step's arguments
    /// leave several matches.
    std::string caveat;
};

/// The statistics as text, each line starting with `prefix` (a comment mark): the counts (the
/// same for the same run), then, with timing, the times, rates and memory (which vary).
std::string describe(const SearchStats& stats, bool timing, std::string_view prefix);

/// Searches for a plan from problem.initial to a state the goal embeds in (monic on objects).
SearchResult find_plan(const Problem& problem, const SearchOptions& options = {});

} // namespace catplan::plan
