#pragma once
// Plan validation (semantics.md "Planning"): replay a plan from the problem's initial state, one
// DPO step at a time, then check that the goal embeds monically in the last state.
//
// A step `pickup(B)` binds the rule's parameters (Rule::parameters, in order) to the parts of the
// current state with those names (`#3` names the third part of the parameter's object, for a part
// without a name); rewrite::find_matches completes the match, which must be unique. When there is
// no match, the explanation names the part of the precondition that cannot be found: L is grown
// from the bound parameters one statement at a time (a part with its hom values to the parts
// already there, then each of its attribute values), and the first statement whose addition leaves
// no monic morphism into the state is reported, e.g. `no match: IsClear clearblock
// (isClearDom(clearblock) == block)` or `no match: isClear(clearblock) == true`. When L embeds but
// every embedding breaks a gluing or application condition, rewrite::match_problem gives the
// reason.
//
//   auto v = validate_plan(*problem, plan);
//   if (!v.valid) std::cout << v.reason << "\n";   // "step 3 pickup(B): no match: ..."

#include "catplan/hom/hom_search.hpp"
#include "catplan/plan/domain.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace catplan::plan {

using hom::ACSetMorphism;

/// The match of one step in state x: the parameters bound by name, completed uniquely; fails with
/// the reason (wrong number of arguments, unknown part name, no match and which part of L is
/// missing, a gluing problem, or an ambiguity naming two matches).
Result<ACSetMorphism> resolve_step(const Rule& rule, const ACSet& x, const Step& step);

/// The first statement of `pattern` (grown from the bound parts along homs, as above) whose
/// addition leaves no monic morphism into x, described in words; nullopt when the whole pattern
/// embeds monically (respecting `initial`).
std::optional<std::string> explain_no_embedding(const ACSet& pattern, const ACSet& x,
                                                const std::vector<hom::PartBinding>& initial = {});

/// A monic morphism goal -> x (monic on objects only; the goal's unknowns bind to anything), or
/// the reason there is none, naming the first goal statement that cannot be satisfied.
Result<ACSetMorphism> embed_goal(const ACSet& goal, const ACSet& x);

/// A monic morphism goal -> x that meets the conditions (each n : goal -> N; Problem's
/// goal_conditions), or the reason there is none: a goal statement nothing satisfies, or the
/// condition every embedding breaks.
Result<ACSetMorphism> embed_goal(const ACSet& goal,
                                 const std::vector<rewrite::ApplicationCondition>& conditions,
                                 const ACSet& x);

/// How describe_match calls the parts it binds.
struct MatchWords {
    /// A word for part p of ob in a state; empty: the part's label (`E`, `#3`).
    std::function<std::string(const ACSet&, ObId, Part)> part;
    /// Parts of l that stand for one thing share a key (a migrated rule's parts of one source
    /// part, one per target object); empty: every part stands alone.
    std::function<std::optional<std::uint64_t>(ObId, Part)> group;
};

/// "block ↦ E, underblock ↦ D, o ↦ x1": each part (and variable) of l with its image in x, each
/// such binding once. The parts of a group are one binding when their images agree, each side
/// called by the first of its words that is not a bare label (`isEmpty(empty)`, not `#3`).
std::string describe_match(const ACSetMorphism& m, const ACSet& l, const ACSet& x,
                           const MatchWords& words = {});

struct ValidateOptions {
    /// Keep every state X_0 .. X_k in the result (for a trace).
    bool keep_states = false;
};

struct Validation {
    /// Every step applied and the goal reached.
    bool valid = false;
    /// Whether the goal embeds in the last state reached (false when a step failed).
    bool goal_reached = false;
    /// The index (0-based) of the step that failed, if one did.
    std::optional<std::size_t> failed_step;
    /// Why the plan is invalid: "step 3 pickup(B): no match: ..." or "goal not reached: ...".
    std::string reason;
    /// The failed step's arguments leave several matches (the plan may hold with one of them:
    /// its text cannot say which).
    bool ambiguous = false;
    /// The match of each step applied, in order.
    std::vector<ACSetMorphism> matches;
    /// With keep_states: X_0 (the initial state) and the state after each step applied.
    std::vector<ACSet> states;
    /// The cost of the steps applied (plan/costs.hpp), when the problem sums costs (step_cost
    /// set). A step without a cost is not applied: the plan is invalid there.
    std::optional<std::int64_t> cost;
    /// The last state reached (always set).
    std::optional<ACSet> final_state;
};

/// Replays plan from problem.initial with the problem's domain and checks the goal; the outcome
/// (valid or not, and why) is data.
Validation validate_plan(const Problem& problem, const Plan& plan,
                         const ValidateOptions& options = {});

} // namespace catplan::plan
