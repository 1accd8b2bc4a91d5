#pragma once
// A plan transfer with PDDL inputs, shared by `catplan transfer` and the Python bindings: a map
// whose source (and, often, target) is a PDDL domain the module imports, a PDDL problem of the
// source domain, an IPC plan (as Fast Downward writes it). The target plan is carried out in the
// target domain's own actions where the target is a PDDL domain (transfer/correspond.hpp,
// repair.hpp) and checked by catplan's PDDL validator on Δ_F(I), Δ_F(G); the user's own target
// problem, when given, is compared with Δ_F(I). What is found is data: the callers word it.

#include "catplan/base/diagnostic.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/transfer/transfer.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace catplan::pddl_transfer {

/// What every plan of a transfer with PDDL inputs shares.
struct Setting {
    std::shared_ptr<const migrate::SchemaMap> map;
    /// The source domain's import with the problem (its rules may be the problem's own).
    std::shared_ptr<const pddl::Import> source;
    /// The target domain's import, when the map's target is a PDDL domain (else null).
    std::shared_ptr<const pddl::Import> target;
    /// Δ_F of the source domain: the generated actions.
    std::shared_ptr<const transfer::MigratedDomain> generated;
    /// The target's own actions, matched to the generated ones (with the target).
    std::shared_ptr<const transfer::TargetActions> actions;
    /// The user's own target problem, and its goal (the goal the verdict judges).
    std::optional<pddl::Problem> target_problem;
    std::shared_ptr<const acset::ACSet> target_goal;
    std::vector<rewrite::ApplicationCondition> target_goal_conditions;
    /// The map's functions section: (target function, source function) pairs.
    std::vector<lang::FunctionCorrespondence> functions;
    /// Without a target problem, the source values the functions section carries to the target's
    /// functions (carried_values in the .cpp), and those Δ_F(I) could not take: an argument that
    /// is no object of Δ_F(I) of the target function's type (`(road-length a t1)`).
    std::vector<pddl::FunctionValue> carried_values;
    std::vector<std::string> uncarried_values;
    /// The target problem's function values where they are known (the user's target problem's,
    /// or the carried ones), as the target's rules' costs read them: repairs take no step
    /// without a cost.
    std::optional<std::vector<plan::FunctionValue>> target_values;
};

/// The PDDL import of a domain the module declares on this schema, or nullptr.
std::shared_ptr<const pddl::Import> pddl_domain_on(const lang::Module& m,
                                                   const schema::SchemaPtr& schema);

/// The setting of a transfer along the module's map `map` of the PDDL problem in `problem_file`
/// (of the map's source domain), with the user's target problem in `target_problem_file` when
/// given; nullopt with every error in sink.
std::optional<Setting> load_setting(const lang::Module& m, const lang::Declaration& map,
                                    std::uint32_t problem_file,
                                    std::optional<std::uint32_t> target_problem_file,
                                    const SourceManager& sources, DiagnosticSink& sink);

/// The IPC plan in `file`, checked against the source problem (a step no state could take is bad
/// input); nullopt with every error in sink.
std::optional<pddl::IpcPlan> read_plan(const Setting& s, std::uint32_t file,
                                       const SourceManager& sources, DiagnosticSink& sink);

/// The source plan's steps as steps of the source rules (replayed: pddl::rule_plan).
plan::Plan source_plan(const Setting& s, const pddl::IpcPlan& plan);

/// The transfer options the setting fixes for the IPC source plan `plan`: the goal judged by,
/// the target's own actions, and the source plan's faults in the words of catplan's PDDL
/// validator (`catplan validate` on the source's PDDL files).
transfer::TransferOptions transfer_options(const Setting& s, const pddl::IpcPlan& plan);

/// A target step as a step of the target's PDDL action, or nullopt when the target is not PDDL.
std::optional<pddl::IpcStep> ipc_step(const Setting& s, const plan::Step& step);

/// A target step in IPC form, `(stack b a)` (the rule step when the target is not PDDL).
std::string ipc_text(const Setting& s, const plan::Step& step);

/// Δ_F(I) against the user's target problem: the objects and facts only in each.
struct Comparison {
    std::string name; ///< the user's problem
    std::vector<std::string> only_in_migrated, only_in_target_problem;

    bool same() const { return only_in_migrated.empty() && only_in_target_problem.empty(); }
};

/// What the PDDL side found after a transfer.
struct Checks {
    /// The source plan's cost, when the source domain's actions have costs.
    std::optional<pddl::PlanCost> source_cost;
    /// The target plan: IPC text with its cost line where the target is a PDDL domain (else the
    /// rule steps, one a line).
    std::string plan_text;
    /// Where the target is a PDDL domain and the transfer reached a target state:
    std::optional<pddl::IpcPlan> target_plan;
    /// Δ_F(I), Δ_F(G) as a PDDL problem of the target domain. Its function values are the
    /// user's target problem's, else the source problem's carried along the map's functions
    /// section (Setting::carried_values, those left out in Setting::uncarried_values).
    std::optional<pddl::Problem> migrated;
    /// The target plan's cost, when the target domain's actions have costs.
    std::optional<pddl::PlanCost> target_cost;
    std::optional<Comparison> comparison;
    /// Conditions of Δ_F(G) a PDDL goal cannot say, left out of the PDDL check.
    std::size_t unwritten_goal_conditions = 0;
    /// catplan's PDDL validator on the target plan, Δ_F(I) and Δ_F(G).
    std::optional<pddl::IpcValidation> validation;

    /// False when Δ_F(I) is not the user's problem, or the transfer's verdict is valid and the
    /// PDDL validator rejects the plan.
    bool ok(const transfer::TransferResult& t) const;
};

/// The PDDL side of a transfer of `plan` (the IPC source plan) whose outcome is t.
Checks check(const Setting& s, const pddl::IpcPlan& plan, const transfer::TransferResult& t);

} // namespace catplan::pddl_transfer
