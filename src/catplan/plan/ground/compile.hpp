#pragma once
// Compiling a C-set problem into a ground task (task.hpp), once, before the search.
//
// 1. Objects: the entities (entities.hpp); per object that homs point into and whose parts are
//    not all entities, as many slots as it has other parts initially or a rule creates at once
//    (whichever is more); per object nothing points into, atoms.
// 2. The initial state is encoded: entities and slots take their parts' values (each unknown
//    becomes kUnknown: no two cells of the state may share one), atoms are interned.
// 3. Relaxed reachability: each rule's L is matched against everything reached so far (the
//    matcher ignores which values exclude each other), each match becomes a ground action, and its
//    effects are reached; until nothing new is reached. A rule's created parts take the lowest
//    free slots (a ground action per choice; none free: an exit action). Each action costs what
//    Problem::step_cost says (1 when unset); a step it gives no cost is no action of the task.
// 4. Each action then gets the conditions that need the whole universe: the dangling condition
//    (every object or atom that may point to a deleted slot and is not part of the match must
//    not), and its negative application conditions (every extension of the match along L -> N,
//    as facts).
// 5. The goal: every monic match of the goal, as a term of facts.
// 6. Mutex groups of atoms (mutexes.hpp), so that states pack into fewer bits.
//
// The fast path does not apply (the result says why) to SPO rules, positive application
// conditions, rules that merge parts, an object whose parts could be merged, a state with two
// equal atoms or with an unknown in two cells, or when a cap of CompileOptions is passed.

#include "catplan/base/result.hpp"
#include "catplan/plan/ground/task.hpp"
#include "catplan/plan/limits.hpp"

namespace catplan::plan::ground {

struct CompileOptions {
    std::size_t max_actions = 2'000'000;
    std::size_t max_atoms = 2'000'000;
    std::size_t max_values = 4096; // per variable
    std::size_t max_goal_terms = 4096;
    /// Find the mutex groups that pack a state into fewer words (mutexes.hpp); a task whose
    /// search expands a handful of states (a repair's focus) does better without the analysis.
    bool mutexes = true;
};

/// The ground task of a problem, or why the fast path does not apply; polls budget (and may
/// throw LimitReached, limits.hpp).
Result<Task> compile(const ProblemPtr& problem, Budget& budget, const CompileOptions& options = {});

} // namespace catplan::plan::ground
