#pragma once
// Plan repair (semantics.md "Plan transfer", item 6): where no target action corresponds to a
// step's generated action, the step is carried out by a short plan in the target's own actions
// from the target state Y_{i-1} to a state into which Δ_F(X_i), the migrated source state after
// the step, embeds monically. The migrated source state is the subgoal, so one source step may
// become several target steps (a 3-operator blocks-world `move` becomes `unstack` + `stack`), or
// none when Y_{i-1} already holds what Δ_F(X_i) says (the 4-operator `pick-up` seen through a map
// that forgets the gripper).
//
// No step is needed when Y_{i-1} already holds the subgoal by names (focus.hpp: each part that
// homs point into is its namesake, each fact is found by its arguments). Otherwise the plans that
// repaired earlier steps of the same source action are tried first, on this step's arguments
// (ActionRepair below), each replayed and checked as below. An action's first step that none
// serves searches, once, from the generated action's left side to its right side (GeneratedStep:
// its parts named and valued as the step binds them in Y_{i-1}, no other part), breadth-first;
// a plan found there is replayed and checked as below, and is remembered for the action's later
// steps. Then a repair costs what the step
// touches, not the size of the state: the local plan is searched first on a focus of Y_{i-1} (the
// parts near what the subgoal changes: radius 0, the seeds alone, then 1, 2 and 4), its goal
// reached by names, unless a focus of the same shape was searched before in this transfer: its
// plan, renamed, is used then (repair_memo.hpp); a plan found there is replayed on the whole
// Y_{i-1} as DPO steps and the whole subgoal is checked to hold by names in the result
// before it is used, and the result is the transfer's next target state (one that fails, for a
// negative condition or a dangling part the focus does not see, is set aside and the next focus
// tried). Only when no focus gives a plan, and the subgoal does not embed in Y_{i-1} by another
// monic morphism either, is the whole state searched: the target's ground task is compiled once per
// transfer and searched from each state with its subgoal (plan/ground/reuse.hpp), else the repair's
// own problem. Each search is the planner's (greedy best-first with h_FF by default, within node
// and time limits; A* with LM-cut, summing the target's costs, where they are known).

#include "catplan/acset/acset.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/plan/ground/reuse.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/transfer/focus.hpp"
#include "catplan/transfer/named_state.hpp"
#include "catplan/transfer/repair_memo.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
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
    /// The radii of the focuses searched before the whole state, in order (empty: the whole
    /// state only).
    std::vector<std::size_t> radii = {0, 1, 2, 4};
    /// At most this many expansions on a focus (a focus that needs more is not local, and the
    /// next one, or the whole state, is searched), within the search's own limit.
    std::uint64_t focus_max_nodes = 10000;
    /// At most this many expansions when the generated action's own sides are searched (a plan
    /// of a few steps on a few parts: a breadth-first search that needs more is not short).
    std::uint64_t generated_max_nodes = 16;
    /// Where the target's costs are known (its function values), search each repair with A* and
    /// LM-cut, summing them, for a least-cost repair on the focus or state searched, rather than
    /// with the search above, which counts steps (and which searches the whole state again where A*
    /// stops at a limit there). Plans are then remembered by shapes that hold the function values
    /// their steps can read (repair_memo.hpp); the shape of the change alone is not used.
    bool least_cost = true;
};

/// A repair: the target steps found, or why none were.
struct Repair {
    bool found = false;
    std::vector<plan::Step> steps; ///< arguments name parts of y by name
    /// The state the steps reach from y, its created parts named by the repair's naming function
    /// (empty when no step was needed): the transfer takes it as its next target state rather
    /// than applying the steps again.
    std::optional<NamedState> reached;
    /// The statistics of the searches, summed (the focuses tried and the whole state).
    plan::SearchStats stats;
    /// When found on a focus: how many parts of y it kept (focus.hpp); 0 on the whole state, or
    /// where an earlier step's plan for the same source action was used without a focus.
    std::size_t focus_parts = 0;
    /// Found by a search from the generated action's left side to its right side (GeneratedStep),
    /// no other part of y involved.
    bool from_action = false;
    /// The subgoal embeds in the state the steps reach sending each part that homs point into to
    /// its namesake (else by another monic morphism).
    bool by_names = false;
    /// The plan is that of the repair of this earlier source step, renamed: its focus had the
    /// same shape (repair_memo.hpp), or it repaired the same source action with its arguments
    /// in the same roles, so no search was needed.
    std::optional<std::size_t> reused_from;
    /// What the steps cost, where the target's costs are known.
    std::optional<std::int64_t> cost;
    /// The search summed the costs with an admissible heuristic (RepairOptions::least_cost): no
    /// plan of the focus (focus_parts), or of the whole state, reaches the subgoal for less.
    bool least_cost = false;
    std::string why; ///< when not found: "the subgoal is unreachable", "time limit reached"
};

/// The generated action Δ_F(a) of a source step that no target action carries out, its left
/// side's parts bound to parts of Y_{i-1} (those the source step's match names there).
struct GeneratedStep {
    const rewrite::Rule* rule = nullptr;
    std::vector<hom::PartBinding> bindings; ///< parts of rule->L to parts of y
};

/// The name of a part of an object that a repair's step creates, given the state it is created
/// in (which must not have that name yet).
using CreatedName = std::function<std::string(NamedState&, ObId)>;

/// Repairs steps of one transfer into one target domain.
class Repairer {
public:
    /// With the target problem's function values, where they are known, a repair takes no step
    /// without a cost, as a planner that reads the target problem would not.
    Repairer(plan::DomainPtr target, RepairOptions options,
             const std::optional<std::vector<plan::FunctionValue>>& values = std::nullopt);

    /// A plan in the target domain from y to a state into which subgoal embeds monically, for
    /// source step `step` (a later repair of the same shape names it as the one it reuses), and
    /// the state it reaches, whose created parts `name` names. With the source step itself, a
    /// plan that repaired a step of the same source action is tried first (see below).
    Repair repair(const NamedState& y, const acset::ACSet& subgoal, std::size_t step,
                  const CreatedName& name, const plan::Step* source = nullptr,
                  const GeneratedStep* generated = nullptr);

    /// Whether a repair of a step of this source action would search its generated action's
    /// sides (GeneratedStep): not where repairs sum costs, and once per action.
    bool searches_generated(const std::string& source_action) const {
        return !by_cost_ && !generated_searched_.contains(source_action);
    }

    /// Hands back a state the caller is done with (the y a repair's reached state replaced), whose
    /// memory the next replay reuses.
    void recycle(NamedState&& old);

private:
    // One repair asked for: from y to a state that holds subgoal, for source step `step`.
    struct Request {
        const NamedState& y;
        const acset::ACSet& subgoal;
        std::size_t step;
        const CreatedName& name;
        const plan::Step* source;       ///< the source step, when the caller gives it
        const GeneratedStep* generated; ///< its generated action, when the caller gives it
    };

    // A plan that repaired a step of one source action, each argument of its steps written as
    // the position of that argument among the source step's. A later step of the same action
    // tries it, on its own arguments, before any focus is built: a transfer repeats few kinds
    // of step, and the replay on the whole state checks it as any remembered plan.
    struct ActionRepair {
        std::vector<std::string> actions;
        std::vector<std::vector<std::uint32_t>> args;
        std::size_t origin = 0; ///< the repair that searched it
    };

    static constexpr std::size_t kActionRepairs = 4; ///< remembered per source action, at most

    bool use_action_repair(const Request& q, Repair& out);
    void remember_action_repair(const Request& q, const Repair& r);

    bool generated_repair(const Request& q, Repair& out);
    bool focus_repair(const Request& q, const Focus& focus, Repair& out);
    bool use_memo(const Request& q, const RepairMemo& memo, const RepairShape& shape, Repair& out,
                  bool& searched_before);
    // The scratch state, assigned a copy of y: a replay's work space, kept from one repair to
    // the next (a copy assigned into a state's containers reuses their memory).
    NamedState& scratch_copy(const NamedState& y);
    void whole_repair(const Request& q, Repair& out);
    plan::SearchResult search_whole(const plan::ProblemPtr& whole,
                                    const plan::SearchOptions& options);
    plan::SearchResult search_by_names(const plan::ProblemPtr& p,
                                       const plan::SearchOptions& options) const;
    // A repair problem on the target domain from initial to goal, with the target's costs.
    plan::ProblemPtr problem(acset::ACSet initial, acset::ACSet goal) const;
    // Whether every step has a cost (always, without the target's costs): a plan remembered from
    // another focus, or found by a search that reads no costs, may take one without.
    bool costed(const std::vector<plan::Step>& steps) const;
    // The steps' cost; nullopt without the target's costs or where a step has none.
    std::optional<std::int64_t> cost(const std::vector<plan::Step>& steps) const;
    // Whether r's plan is one of least cost: searched summing the target's costs, and optimal.
    bool least(const plan::SearchResult& r) const;
    // The repair found: its steps (their cost, and whether it is the least), and the state their
    // replay reached.
    void take(Repair& out, std::vector<plan::Step> steps, NamedState&& reached, bool by_names,
              bool least_cost) const;

    plan::DomainPtr target_;
    /// The target's domain with its step costs, where its values are known (else none).
    plan::Problem costs_;
    RepairOptions options_;
    bool by_cost_; ///< costs_.step_cost and options_.least_cost: A*, values in the shapes
    std::optional<ValueIndex> values_; ///< with by_cost_, costs_.values by the names they take
    /// With by_cost_, the greedy search the options gave: the whole state is searched with it
    /// where A* stops at a limit.
    std::optional<plan::SearchOptions> greedy_;
    /// The target's ground task, compiled at the first repair on the whole state.
    std::optional<plan::ground::ReusableTask> task_;
    std::string why_no_task_; ///< why it could not be compiled (then each repair compiles its own)
    RepairMemo memo_;         ///< the plans of the focuses searched, by shape
    RepairMemo changes_;      ///< the same plans, by the shape of what they change
    /// Without by_cost_: per source action, the plans that repaired its steps (ActionRepair).
    std::unordered_map<std::string, std::vector<ActionRepair>> by_action_;
    /// The source actions whose generated action's sides were searched (generated_repair).
    std::unordered_set<std::string> generated_searched_;
    std::optional<NamedState> scratch_; ///< see scratch_copy
};

} // namespace catplan::transfer
