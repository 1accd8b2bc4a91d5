#pragma once
// Plan repair (semantics.md "Plan transfer", item 6): where no target action corresponds to a
// step's generated action, the step is carried out by a short plan in the target's own actions
// from the target state Y_{i-1} to a state into which Δ_F(X_i), the migrated source state after
// the step, embeds monically. The migrated source state is the subgoal, so one source step may
// become several target steps (a 3-operator blocks-world `move` becomes `unstack` + `stack`), or
// none when Y_{i-1} already holds what Δ_F(X_i) says (the 4-operator `pick-up` seen through a map
// that forgets the gripper).
//
// The local plan is found with plan::find_plan (greedy best-first with h_FF by default, within
// node and time limits); an empty plan is tried first.

#include "catplan/acset/acset.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/plan/search.hpp"

#include <string>
#include <vector>

namespace catplan::transfer {

struct RepairOptions {
    /// The local search: greedy best-first with h_FF, at most 100,000 expansions or 30 s.
    plan::SearchOptions search = [] {
        plan::SearchOptions s;
        s.search = plan::SearchKind::GreedyBestFirst;
        s.heuristic = plan::HeuristicKind::HFF;
        s.max_nodes = 100000;
        s.max_seconds = 30;
        return s;
    }();
};

/// A repair: the target steps found, or why none were.
struct Repair {
    bool found = false;
    std::vector<plan::Step> steps; ///< arguments name parts of y by name
    plan::SearchStats stats;
    std::string why; ///< when not found: "the subgoal is unreachable", "time limit reached"
};

/// A plan in the target domain from y to a state into which subgoal embeds monically.
Repair repair_step(const plan::DomainPtr& target, const acset::ACSet& y,
                   const acset::ACSet& subgoal, const RepairOptions& options = {});

} // namespace catplan::transfer
