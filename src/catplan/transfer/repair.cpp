#include "catplan/transfer/repair.hpp"

#include "catplan/plan/validate.hpp"

#include <fmt/format.h>

namespace catplan::transfer {

Repair repair_step(const plan::DomainPtr& target, const acset::ACSet& y,
                   const acset::ACSet& subgoal, const RepairOptions& options) {
    Repair out;
    if (plan::embed_goal(subgoal, y)) {
        out.found = true;
        return out;
    }
    plan::Problem p;
    p.name = "repair";
    p.domain = target;
    p.initial = std::make_shared<const acset::ACSet>(y);
    p.goal = std::make_shared<const acset::ACSet>(subgoal);
    auto r = plan::find_plan(p, options.search);
    out.stats = r.stats;
    if (r.status == plan::SearchStatus::Solved) {
        out.found = true;
        out.steps = std::move(r.plan->steps);
        return out;
    }
    out.why = r.status == plan::SearchStatus::Unsolvable
                  ? std::string("no target plan reaches the migrated source state")
                  : fmt::format("the local search stopped at its {} ({} states expanded)",
                                plan::to_string(r.status), r.stats.expanded);
    return out;
}

} // namespace catplan::transfer
