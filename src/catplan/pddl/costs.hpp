#pragma once
// What plans cost under PDDL's action costs (:action-costs).
//
// A problem with `(:metric minimize (total-cost))` counts each step at what its action adds to
// total-cost: the sum of its `(increase (total-cost) T)` terms, T a number or the value the
// problem's :init gives a function (`(= (road-length a b) 5)`), with the step's arguments in place
// of the action's parameters; an action that says nothing costs 0. A function term without a
// value leaves the step's cost undefined, and the step cannot be taken (VAL's reading). Without
// the metric every step costs 1, as Fast Downward and VAL count. The plan's cost is the sum,
// written at the end of an IPC plan as Fast Downward writes it: `; cost = 12 (general cost)`, or
// `(unit cost)` when every action costs 1.

#include "catplan/base/result.hpp"
#include "catplan/pddl/pddl.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace catplan::pddl {

struct IpcStep; // ipc_plan.hpp
using IpcPlan = std::vector<IpcStep>;

struct PlanCost {
    std::int64_t total = 0;
    std::vector<std::int64_t> steps; // per step, up to the first undefined one
    /// Every action costs 1 (no metric, or each says 1): Fast Downward's "unit cost".
    bool unit = true;
    /// Not empty when a step's cost has no value: "step 3 (drive t a b): its cost
    /// (road-length a b) has no value in the problem".
    std::string undefined;
};

/// Whether every action of the problem costs 1: no metric, or each action's cost is 1.
bool unit_cost(const Domain& d, const Problem& p);

/// The cost of a step, or why it has none (a function's value the problem does not give, or an
/// action the domain does not have or with another number of arguments).
Result<std::int64_t> step_cost(const Domain& d, const Problem& p, const IpcStep& s);

/// The cost of each step and of the plan, up to the first step without one.
PlanCost plan_cost(const Domain& d, const Problem& p, const IpcPlan& plan);

/// "12 (general cost)", "7 (unit cost)", or "undefined: step 3 ...".
std::string describe_cost(const PlanCost& cost);

/// The last line of an IPC plan: "; cost = 12 (general cost)", "; cost = 7 (unit cost)", or
/// "; cost undefined: step 3 ...".
std::string cost_line(const PlanCost& cost);

} // namespace catplan::pddl
