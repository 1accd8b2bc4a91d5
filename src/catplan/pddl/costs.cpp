#include "catplan/pddl/costs.hpp"

#include "catplan/pddl/ipc_plan.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <limits>

namespace catplan::pddl {

bool unit_cost(const Domain& d, const Problem& p) {
    return !p.metric || std::all_of(d.actions.begin(), d.actions.end(), [](const Action& a) {
        return a.cost.size() == 1 && !a.cost[0].fluent && a.cost[0].number == 1;
    });
}

Result<std::int64_t> step_cost(const Domain& d, const Problem& p, const IpcStep& s) {
    const Action* a = d.find_action(s.action);
    if (a == nullptr || a->params.size() != s.args.size()) {
        return fail(fmt::format("it is no step of domain {}", d.name));
    }
    if (!p.metric) {
        return std::int64_t{1};
    }
    std::int64_t total = 0;
    for (const auto& c : a->cost) {
        std::int64_t value = c.number;
        if (c.fluent) {
            Atom term = ground(*a, *c.fluent, s);
            auto v = p.value_of(term);
            if (!v) {
                return fail(
                    fmt::format("its cost {} has no value in the problem", term.to_string()));
            }
            value = *v;
        }
        if (value > std::numeric_limits<std::int64_t>::max() - total) {
            return fail(std::string("its cost is out of range"));
        }
        total += value;
    }
    return total;
}

PlanCost plan_cost(const Domain& d, const Problem& p, const IpcPlan& plan) {
    PlanCost out;
    out.unit = unit_cost(d, p);
    for (std::size_t i = 0; i < plan.size(); ++i) {
        auto c = step_cost(d, p, plan[i]);
        if (!c || *c > std::numeric_limits<std::int64_t>::max() - out.total) {
            out.undefined =
                fmt::format("step {} {}: {}", i + 1, plan[i].to_string(),
                            c ? std::string("the plan's cost is out of range") : c.error());
            break;
        }
        out.steps.push_back(*c);
        out.total += *c;
    }
    return out;
}

std::string describe_cost(const PlanCost& cost) {
    if (!cost.undefined.empty()) {
        return "undefined: " + cost.undefined;
    }
    return fmt::format("{} ({} cost)", cost.total, cost.unit ? "unit" : "general");
}

std::string cost_line(const PlanCost& cost) {
    if (!cost.undefined.empty()) {
        return fmt::format("; cost undefined: {}\n", cost.undefined);
    }
    return fmt::format("; cost = {} ({} cost)\n", cost.total, cost.unit ? "unit" : "general");
}

} // namespace catplan::pddl
