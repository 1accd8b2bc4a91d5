#pragma once
// Actions of several rules (rewrite::ActionOf): plans name actions, the engines apply rules.
//
// A PDDL action becomes a handful of rules, one per identification of its parameters
// (pddl/import.hpp), and a file written by `pddl import` says so with `action = stack(x, x)`.
// The plans users read and write name the action (`stack(b, a)`); search, validation and transfer
// work on steps of rules. rule_plan goes from the first to the second, replaying the plan to pick
// per step the rule that applies (exactly one does for an imported action); action_plan goes back.
// A rule that says nothing carries out the action of its own name with its own parameters.

#include "catplan/base/result.hpp"
#include "catplan/plan/domain.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::plan {

/// The rules carrying out the action with this name, in the domain's order.
std::vector<const Rule*> action_rules(const Domain& d, std::string_view name);

/// Whether some rule of the domain carries out an action other than itself.
bool has_actions(const Domain& d);

/// The step of r that a step of its action is, when the arguments fit: as many as the action
/// has, one name for a parameter given twice, and the part a constant argument names.
std::optional<Step> rule_step(const Rule& r, const Step& action_step);

/// A step of r written as a step of the action it carries out.
Step action_step(const Rule& r, const Step& rule_step);

/// A step of a rule of d written as a step of its action (a step that names no rule of d, or
/// gives it the wrong number of arguments, stays as it is).
Step action_step(const Domain& d, const Step& rule_step);

/// A rule step in words as its action, naming the rule when it is another:
/// "connect(b, a) (rule connect~2)".
std::string describe_step(const Domain& d, const Step& rule_step);

/// A plan of rule steps written as actions (action_step of each).
Plan action_plan(const Domain& d, const Plan& plan);

/// Applies a step of an action to x, in place, as the first rule of the action whose arguments
/// fit and whose match exists: the rule step applied, or why none applied (the last reason).
Result<Step> apply_action_step(const Domain& d, ACSet& x, const Step& action_step);

/// The rule steps of a plan of actions: each step as the first rule of its action that applies
/// when the plan is replayed from `initial`. From the first step that no rule applies to on, a
/// step becomes the first rule its arguments fit, or stays as written (a step naming a rule by the
/// rule's own name, or one that check_plan rejects), so that replaying the result fails there.
Plan rule_plan(const Domain& d, const ACSet& initial, const Plan& plan);

} // namespace catplan::plan
