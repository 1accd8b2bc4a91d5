#pragma once
// The grounded search (search.hpp): compile, search the ground task with the configuration the
// options name, replay the plan as DPO steps and validate it.

#include "catplan/plan/ground/task.hpp"
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

/// The search of ground_search on a task compiled before (its problem, initial state and goal as
/// they are set in it, reuse.hpp), the plan replayed as DPO steps and validated, into out.
void search_task(const Task& task, const SearchOptions& options, Budget& budget,
                 GroundOutcome& out);

} // namespace catplan::plan::ground
