#pragma once
// Between IPC steps and the steps of an imported domain's rules, and PDDL problems written back.
//
// A ground action `(stack a b)` is carried out by the variant of `stack` (import.hpp) whose
// parameters its arguments fit and whose match exists in the state; rule_plan replays an IPC
// plan to find them. A state of the imported schema reads back as a PDDL problem (its objects
// with their most specific types and its facts), which write_problem writes as a PDDL file.

#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/domain.hpp"

#include <optional>
#include <string>

namespace catplan::pddl {

/// The rule-level plan of an IPC plan (plan::rule_plan from the import's initial state).
plan::Plan rule_plan(const Import& im, const IpcPlan& plan);

/// A PDDL problem of the import's domain whose initial state is `initial` and whose goal is the
/// facts of `goal` (both states of the imported schema, objects named by their part names), with
/// `(not f)` for each negative goal condition that adds one fact f (the others are counted in
/// Problem::unwritten_goal_conditions), and the cost metric when the domain's actions have costs.
Problem problem_of(const Import& im, std::string name, const acset::ACSet& initial,
                   const acset::ACSet& goal,
                   const std::vector<rewrite::ApplicationCondition>& conditions = {});

/// A problem as a PDDL problem file.
std::string write_problem(const Problem& p);

} // namespace catplan::pddl
