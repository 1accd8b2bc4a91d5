#pragma once
// Heuristics for the planner: estimates of the number of steps from a state to the goal.
//
// The abstraction (computed once per problem from the rules' L and R and the goal):
//   - Entities are decided per part (entities.hpp): the parts of entity objects, which keep
//     their ids, and the initial parts of other objects that no rule can delete, followed by
//     name. A rule's slots are its kept L parts of objects with entities.
//   - A *fact* is any other part (a predicate object's: On, IsClear, Empty; the marker block)
//     seen as its tuple of hom values into entities and concrete attribute values; or a hom value
//     between two entities; or a concrete attribute value of an entity. Hom values into non-entity
//     parts and unknown values are dropped (wildcards).
//   - A precondition or goal fact with wildcards is satisfied by any fact that agrees on its other
//     positions (each fact is projected onto every wildcard pattern in use).
//   - Each rule is grounded by giving its L entity parts distinct entities (facts that no rule adds
//     are checked against the initial state during grounding); a ground action needs the facts of L
//     and adds the facts of R, at cost 1. Deletions are ignored (delete relaxation).
//   - Goal entities are identified with the initial state's entities by monic morphisms of the
//     goal's entity parts (names bound); when several exist (two purple blocks), each gives a goal
//     and h is the least over them (up to 24; beyond, unnamed goal entities are wildcards).
//
// Heuristics:
//   blind      0 everywhere (A* becomes uniform-cost search).
//   goalcount  the number of goal facts absent from the state.
//   hadd       h_add: the sum over goal facts of their relaxed costs (Bonet & Geffner).
//   hmax       h_max: the largest relaxed cost of a goal fact.
//   hff        h_FF: the size of the relaxed plan extracted from h_add's best supporters
//   (Hoffmann).
// (lmcut and lmcount exist on ground tasks only, ground/heuristics.hpp; make_heuristic gives hmax
// and hff for them.)
// None is admissible in general (goalcount is when each step adds at most one goal fact); a state
// whose goal facts are unreachable in the relaxation gets kDeadEnd, which the search does not
// prune (the abstraction can be wrong where wildcards hide information) but expands last.

#include "catplan/plan/domain.hpp"
#include "catplan/plan/limits.hpp"

#include <memory>
#include <optional>
#include <string_view>

namespace catplan::plan {

enum class HeuristicKind {
    Default, // the search's own: hff for greedy searches, lmcut for A*, blind for BFS
    Blind,
    GoalCount,
    HAdd,
    HMax,
    HFF,
    LmCut,   // grounded search only (the C-set search uses hmax)
    LmCount, // grounded search only (the C-set search uses hff)
};

/// "default", "blind", "goalcount", "hadd", "hmax", "hff", "lmcut" or "lmcount"; nullopt for
/// another name.
std::optional<HeuristicKind> parse_heuristic(std::string_view name);
/// The name parse_heuristic reads.
std::string_view to_string(HeuristicKind kind);

/// The value of a state from which the relaxation cannot reach the goal.
inline constexpr int kDeadEnd = 1'000'000;

class Heuristic {
public:
    virtual ~Heuristic() = default;
    /// The estimate for state x (0 .. kDeadEnd).
    virtual int evaluate(const ACSet& x) = 0;
};

/// A heuristic of this kind for the problem (its domain's rules, initial state and goal; Default
/// is hff); its
/// set-up polls budget when given (and may throw LimitReached, limits.hpp).
std::unique_ptr<Heuristic> make_heuristic(HeuristicKind kind, const Problem& problem,
                                          Budget* budget = nullptr);

} // namespace catplan::plan
