#pragma once
// Planning domains, problems and plans (semantics.md "Planning").
//
// A domain is a schema and named rules; a problem is an initial state and a goal state on that
// schema; a plan is a list of steps `unstack(E, D)`, whose arguments bind the rule's parameters to
// parts of the current state by name. The rest of the match is completed by search and must be
// unique. A plan is valid when every step's match exists and satisfies the gluing conditions, and
// the goal embeds monically (monic on objects only; the goal's unknowns may bind to any value) by a
// morphism that meets the problem's goal conditions.

#include "catplan/acset/acset.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"
#include "catplan/rewrite/rule.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace catplan::plan {

using acset::ACSet;
using rewrite::Rule;
using rewrite::RulePtr;

struct Domain {
    std::string name;
    schema::SchemaPtr schema;
    std::vector<RulePtr> rules;
    SourceRange range;

    /// The rule with this name, or nullptr.
    const Rule* find_rule(std::string_view rule_name) const;
};

using DomainPtr = std::shared_ptr<const Domain>;

/// A value a problem gives a function that rules' costs read: `road_length(a, d) = 20`, the
/// arguments part names of the initial state (PDDL's `(= (road-length a d) 20)`).
struct FunctionValue {
    std::string function;
    std::vector<std::string> args;
    std::int64_t value = 0;
    SourceRange range;
};

struct Problem {
    std::string name;
    DomainPtr domain;
    std::shared_ptr<const ACSet> initial;
    std::shared_ptr<const ACSet> goal;
    SourceRange range;
    /// Conditions on the goal's embedding m : goal -> X (each n : goal -> N): the goal holds
    /// where some m meets them all, a negative one not extending along n (PDDL's negative goals,
    /// `(not (on a b))`). Empty for most problems.
    std::vector<rewrite::ApplicationCondition> goal_conditions = {};
    /// What a step of `rule` with these arguments (part names, one per parameter) costs, or
    /// nullopt when it has no cost and cannot be taken (a PDDL cost whose function value the
    /// problem does not give). Unset: every step costs 1 (the searches count steps).
    std::function<std::optional<std::int64_t>(const Rule& rule,
                                              const std::vector<std::string>& args)>
        step_cost = {};
    /// The values of the functions the rules' costs read (costs.hpp), in the order given.
    std::vector<FunctionValue> values = {};
    /// Whether plans are measured by their number of steps although the rules say costs
    /// (`metric = steps`; a PDDL problem without `(:metric minimize (total-cost))`).
    bool counts_steps = false;
};

using ProblemPtr = std::shared_ptr<const Problem>;

/// One step of a plan: an action and the names of the parts bound to its parameters.
struct Step {
    std::string action;
    std::vector<std::string> args;
    SourceRange range; // where the step was written (invalid for a step made by the planner)
    std::vector<SourceRange> arg_ranges = {}; // where each argument was written (or empty)

    /// "unstack(E, D)".
    std::string to_string() const;
};

struct Plan {
    std::vector<Step> steps;

    /// One step per line, in the format parse_plan reads.
    std::string to_string() const;
};

/// Parses a plan: steps `name(arg, ...)` (or `name` with no arguments) separated by line ends
/// (LF, CRLF, CR) or `;`, `#` comments; an argument is a part name or `#k` (k >= 1: the k-th part
/// of the parameter's object). The text must be UTF-8 (a byte-order mark is skipped). Every syntax
/// error is reported to sink; nullopt when there was one.
std::optional<Plan> parse_plan(std::uint32_t file, const SourceManager& sources,
                               DiagnosticSink& sink);

/// Reports, located, what makes a parsed plan wrong whatever the states it meets: an unknown
/// action, a wrong number of arguments, an argument naming a part that neither `initial` has nor
/// any rule of the domain creates (of the parameter's object), or `#k` beyond the parts of an
/// object no rule creates. Returns whether there was none. A plan that passes may still not apply:
/// that is validation's answer, not bad input.
bool check_plan(const Plan& plan, const Domain& domain, const ACSet& initial, DiagnosticSink& sink);

} // namespace catplan::plan
