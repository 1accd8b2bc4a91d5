#pragma once
// Mutex groups of a ground task: sets of atoms of which at most one is present in every reachable
// state (blocksworld: what a block is on, or holding it; what is on a block, or it is clear, or
// held; the hand empty or holding a block). The state packer stores a group in one field of
// ceil(log2(n + 1)) bits instead of n bits (packed.hpp), as Fast Downward's translator makes one
// finite-domain variable of each.
//
// Candidates are found as the translator finds its invariants (Helmert 2009), on the ground
// actions: a candidate is a set of parts, each an object nothing points into (a PDDL predicate)
// with the hom positions that name the group (its parameters; at most one argument is left
// free). An action *produces* an atom it sets present without needing it present, and *consumes*
// one it needs present and deletes. A candidate holds when, in each of its groups, every action
// produces at most one atom and, when it produces one, consumes one; an action that produces
// without consuming refines the candidate by a part of an atom it consumes. A group is proven by
// induction: at most one atom initially, and no action adds one without removing the one there.
// Exits are never applied and conditions only restrict actions, so neither is needed. The
// analysis is bounded (1,000 candidates, 10^8 atoms looked at): a large task may get fewer
// groups, never a wrong one.
//
// The groups found may overlap (blocksworld's Holding(A) is in three); the packer takes disjoint
// ones (disjoint_groups), the landmarks' reasonable orderings all of them.

#include "catplan/plan/ground/task.hpp"
#include "catplan/plan/limits.hpp"

namespace catplan::plan::ground {

/// Groups of at least two atom variables, at most one of each present in every reachable state
/// (sorted, each group once).
std::vector<std::vector<VarId>> find_mutex_groups(const Task& task, Budget& budget);

/// Disjoint groups of at least two variables taken from `groups` greedily, the one with most
/// variables not yet covered first (a part of a group is a group).
std::vector<std::vector<VarId>> disjoint_groups(std::vector<std::vector<VarId>> groups);

} // namespace catplan::plan::ground
