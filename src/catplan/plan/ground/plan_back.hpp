#pragma once
// A plan of ground actions as DPO steps: replayed on the problem's initial C-set, each action's
// match (its objects and atoms as the state's parts at that step) is checked by
// rewrite::match_problem and applied by rewrite_in_place, and the step names its parameters'
// parts as validate_plan reads them.

#include "catplan/base/result.hpp"
#include "catplan/plan/ground/task.hpp"

#include <optional>

namespace catplan::plan::ground {

/// The steps of a ground plan, or why a step does not apply to the C-set (a bug in the
/// compiler: the caller validates the result and falls back); the state after the last step in
/// *last when it is not null.
Result<Plan> to_dpo_plan(const Task& task, const std::vector<ActionId>& plan,
                         std::optional<ACSet>* last = nullptr);

} // namespace catplan::plan::ground
