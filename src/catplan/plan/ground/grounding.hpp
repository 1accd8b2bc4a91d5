#pragma once
// Steps 3 to 5 of the ground compiler (compile.hpp): ground actions by relaxed reachability, their
// conditions over the whole universe, and the goal. Internal to the ground compiler.

#include "catplan/plan/ground/compile.hpp"
#include "catplan/plan/ground/universe.hpp"

#include <optional>
#include <string>

namespace catplan::plan::ground {

/// Per attribute: whether some rule may change its value on a kept part.
std::vector<bool> changed_attributes(const Domain& domain);

/// Grounds every rule by relaxed reachability; why not, when a cap is passed.
std::optional<std::string> ground_actions(Universe& u, const CompileOptions& options);

/// Adds the dangling and negative conditions and drops the actions that can never apply.
void finish_actions(Universe& u);

/// The goal's terms; why not, when there are too many.
std::optional<std::string> ground_goal(Universe& u, const CompileOptions& options);

} // namespace catplan::plan::ground
