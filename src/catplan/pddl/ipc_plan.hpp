#pragma once
// IPC plan files, and validating them against an imported PDDL problem.
//
// An IPC plan is one ground action per line, `(unstack e d)`, with `;` comments; the last line of
// a plan written by catplan is `; cost = N (unit cost)`, as IPC planners (Fast Downward) write it.
// Timed plans (`0.000: (unstack e d) [1]`) are read too, the time and duration ignored. Anything
// else on a line is an error: text before the step that is not a time stamp, a second step, text
// after the step or its duration. Names are lowered, as PDDL's are.
//
// check_ipc_plan reports what is wrong with a plan whatever the state: an unknown action, a wrong
// number of arguments, an unknown object or one of the wrong type. Those are bad input (exit 2 on
// the command line); validation judges the rest, a plan whose step does not apply or whose goal
// is not reached.
//
// Validation replays the plan with PDDL's own meaning, independent of the rule encoding: a state
// is the set of ground atoms that hold; a step applies when each literal of its action's
// precondition, ground with its arguments, holds (an equality when both sides name one object),
// and then its deletes are removed and its adds added. A step that does not apply is reported
// with the first precondition that fails, as written in the domain, ground:
// `step 3 (unstack e d): precondition (on e d) does not hold`. validate_ipc_plan also replays each
// step on the imported rules: the step's arguments pick the variants of its action consistent
// with them (import.hpp), and the one whose match exists applies (that none does where PDDL's
// precondition holds is an internal error, reported as the step's failure).

#include "catplan/base/diagnostic.hpp"
#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/plan/domain.hpp"

#include <optional>
#include <string>
#include <vector>

namespace catplan::pddl {

/// One ground action of an IPC plan.
struct IpcStep {
    std::string action;
    std::vector<std::string> args;
    SourceRange range;
    SourceRange action_range = {};
    std::vector<SourceRange> arg_ranges = {}; // parallel to args (empty for a step not read)

    /// "(unstack e d)".
    std::string to_string() const;
};

using IpcPlan = std::vector<IpcStep>;

/// Reads an IPC plan file; every syntax error goes to sink; nullopt when there was one.
std::optional<IpcPlan> parse_ipc_plan(std::uint32_t file, const SourceManager& sources,
                                      DiagnosticSink& sink);

/// Reports every step that names an unknown action or object, or gives an action the wrong number
/// or types of arguments (located at the step's text); returns whether there was none.
bool check_ipc_plan(const Import& import, const IpcPlan& plan, DiagnosticSink& sink);

/// The plan one step per line, ending with `; cost = N (unit cost)` (N steps).
std::string write_ipc_plan(const IpcPlan& plan);

/// The plan one step per line, ending with its cost line (costs.hpp: `; cost = 12 (general
/// cost)`).
std::string write_ipc_plan(const IpcPlan& plan, const PlanCost& cost);

/// The action's atom (or function term) with the step's arguments in place of its parameters.
Atom ground(const Action& a, const Atom& atom, const IpcStep& s);

/// The PDDL steps of a plan found on the imported domain (rule variants back to their actions);
/// fails when a step's rule is not one of the import's.
Result<IpcPlan> to_ipc_plan(const Import& import, const plan::Plan& plan);

struct IpcValidation {
    bool valid = false;
    bool goal_reached = false;
    std::optional<std::size_t> failed_step; // 0-based
    /// "step 3 (unstack e d): precondition (on e d) does not hold" or "goal not reached: ...".
    std::string reason;
    /// The rule-level plan (the variant applied at each step that applied).
    plan::Plan plan;
    /// What the steps that applied cost (costs.hpp).
    PlanCost cost;
    /// The last state reached on the imported rules (validate_ipc_plan only).
    std::optional<acset::ACSet> final_state;
    /// The ground atoms that hold in the last state reached, as PDDL reads it, sorted: "(on a b)".
    std::vector<std::string> final_facts;
};

/// Replays an IPC plan on the import's problem and checks its goal, with PDDL's meaning and on
/// the imported rules (the rule-level plan and the final state).
IpcValidation validate_ipc_plan(const Import& import, const IpcPlan& plan);

/// Replays an IPC plan on a PDDL problem with PDDL's meaning alone and checks its goal: the
/// verdict and the cost (no rule-level plan, no final state).
IpcValidation simulate_ipc_plan(const Domain& domain, const Problem& problem, const IpcPlan& plan);

} // namespace catplan::pddl
