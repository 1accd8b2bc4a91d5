#pragma once
// What a step costs, from its rule's cost and the problem's function values.
//
// A rule that says `cost = 2 + road_length(from, to)` costs 2 plus the value the problem gives
// road_length at the step's arguments (`road_length(a, d) = 20`); a function value the problem
// does not give leaves the step without a cost, and a search that sums costs never takes it
// (PDDL's reading, as VAL's). A rule that says nothing costs 1. A problem whose rules say no
// cost, or that counts steps (`metric = steps`), has every step cost 1 and no step_cost.

#include "catplan/base/result.hpp"
#include "catplan/plan/domain.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace catplan::plan {

/// The values of a problem's functions, looked up by function and arguments.
class FunctionTable {
public:
    explicit FunctionTable(const std::vector<FunctionValue>& values);

    /// The value of f at these arguments, or nullopt when the problem gives none.
    std::optional<std::int64_t> value(const std::string& f,
                                      const std::vector<std::string>& args) const;

private:
    std::map<std::pair<std::string, std::vector<std::string>>, std::int64_t> values_;
};

/// What a step of rule with these arguments (part names, one per parameter) costs, or nullopt
/// when a function value it reads is not given. A sum beyond int64 is held at its maximum.
std::optional<std::int64_t> rule_cost(const Rule& rule, const std::vector<std::string>& args,
                                      const FunctionTable& table);

/// What a step of rule with these arguments costs under p: 1 when p sums no costs (no
/// step_cost); fails when it has no cost ("its cost road_length(a, e) has no value in the
/// problem").
Result<std::int64_t> step_cost(const Problem& p, const Rule& rule,
                               const std::vector<std::string>& args);

/// a + b for costs: a sum beyond int64 is held at its maximum.
std::int64_t add_cost(std::int64_t a, std::int64_t b);

/// What the steps (each naming a rule of p's domain) cost under p, which sums costs
/// (p.step_cost); fails at the first step without a cost ("step 3 drive(t1, a, e): its cost
/// length(a, e) has no value in the problem").
Result<std::int64_t> plan_cost(const Problem& p, const std::vector<Step>& steps);

/// Whether some rule of the domain says what its steps cost.
bool has_costs(const Domain& domain);

/// Sets p.step_cost from the rules' costs and p.values, unless p counts steps or no rule of its
/// domain says a cost (then every step costs 1).
void set_step_cost(Problem& p);

} // namespace catplan::plan
