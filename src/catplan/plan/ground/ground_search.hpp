#pragma once
// The grounded search (search.hpp): compile, search the ground task with the configuration the
// options name, replay the plan as DPO steps and validate it.

#include "catplan/plan/search.hpp"

namespace catplan::plan::ground {

struct GroundOutcome {
    /// Whether the problem compiled into a ground task (else why_not says why).
    bool compiled = false;
    std::string why_not;
    /// The search's result (when compiled, or when a limit stopped the compiling).
    SearchResult result;
    /// A found plan failed its replay or validation (a bug); the reason.
    std::string rejected;
};

/// Runs the grounded search within the budget.
GroundOutcome ground_search(const ProblemPtr& problem, const SearchOptions& options,
                            Budget& budget);

} // namespace catplan::plan::ground
