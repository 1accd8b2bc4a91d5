// `catplan transfer` with PDDL inputs (pddl_transfer.hpp).

#include "catplan/cli/pddl_transfer.hpp"

#include "catplan/cli/commands.hpp"
#include "catplan/hom/isomorphism.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/steps.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <set>

namespace catplan::cli {
namespace {

/// The PDDL import of a domain the module declares on this schema, or nullptr.
std::shared_ptr<const pddl::Import> pddl_domain_on(const lang::Module& m,
                                                   const schema::SchemaPtr& schema) {
    for (const auto& d : m.declarations()) {
        if (d.kind == lang::DeclKind::Domain && d.pddl && d.domain->schema == schema) {
            return d.pddl;
        }
    }
    return nullptr;
}

/// Reads and parses a PDDL problem of a domain; nullopt with the errors printed.
std::optional<pddl::Problem> read_problem(Session& s, const std::string& file,
                                          const pddl::Domain& d, std::ostream& err) {
    auto f = s.sources.add_file(file);
    if (!f) {
        error(err, fmt::format("cannot read '{}'", file));
        return std::nullopt;
    }
    auto p = pddl::parse_problem(*f, d, s.sources, s.sink);
    if (report(s, err) || !p) {
        return std::nullopt;
    }
    return p;
}

/// The target's own actions matched to the generated ones, with the target's rules for Δ_F(I).
bool add_target(Session& s, const lang::Module& m, const TransferInputs& in, const TransferArgs& a,
                PddlTransfer& pt, std::ostream& err) {
    auto target = pddl_domain_on(m, in.map->target());
    if (target == nullptr) {
        return true; // the generated actions are the target's
    }
    acset::ACSet y0 = migrate::migrate(*in.map, *in.problem->initial);
    auto own = pddl::for_initial_facts(*target, target->facts(y0), s.sink);
    if (report(s, err) || !own) {
        return false;
    }
    pt.target = std::make_shared<const pddl::Import>(std::move(*own));
    std::vector<std::pair<std::string, std::string>> named;
    for (const auto& c : m.find(a.map)->actions) {
        named.emplace_back(c.source, c.target);
    }
    auto generated = transfer::migrate_domain(*in.map, *in.problem->domain);
    auto source = pt.source;
    auto own_import = pt.target;
    pt.actions = std::make_shared<const transfer::TargetActions>(transfer::correspond_domain(
        *generated.domain, pt.target->domain, named,
        [own_import](std::string_view r) { return own_import->action_of(r); },
        [source](std::string_view r) { return source->action_of(r); }));
    return true;
}

/// A target step in IPC form (a rule step when the target is not a PDDL domain).
std::string ipc_text(const PddlTransfer& pt, const plan::Step& step) {
    if (pt.target == nullptr) {
        return step.to_string();
    }
    auto ipc = pddl::to_ipc_plan(*pt.target, plan::Plan{{step}});
    return ipc ? (*ipc)[0].to_string() : step.to_string();
}

/// The facts and objects only in a, in words.
std::vector<std::string> only_in(const pddl::Problem& a, const pddl::Problem& b) {
    std::set<std::string> theirs;
    for (const auto& f : b.init) {
        theirs.insert(f.to_string());
    }
    for (const auto& o : b.objects) {
        theirs.insert(o.name + " - " + o.type);
    }
    std::vector<std::string> out;
    for (const auto& o : a.objects) {
        if (theirs.count(o.name + " - " + o.type) == 0) {
            out.push_back(o.name + " - " + o.type);
        }
    }
    for (const auto& f : a.init) {
        if (theirs.count(f.to_string()) == 0) {
            out.push_back(f.to_string());
        }
    }
    return out;
}

/// Whether Δ_F(I) is the user's target initial state, and the differences, in words and in JSON.
bool compare_initial(const PddlTransfer& pt, const pddl::Problem& migrated, PddlChecks& out) {
    const auto& user = *pt.target_problem;
    auto theirs = only_in(user, migrated), ours = only_in(migrated, user);
    bool same = theirs.empty() && ours.empty();
    out.json["target_problem"] = {{"name", user.name},
                                  {"initial_is_migrated", same},
                                  {"only_in_migrated", ours},
                                  {"only_in_target_problem", theirs}};
    if (same) {
        out.text += fmt::format("target problem {}: its initial state is Δ_F(I)\n", user.name);
        return true;
    }
    out.text += fmt::format("target problem {}: its initial state is not Δ_F(I)\n", user.name);
    if (!ours.empty()) {
        out.text += fmt::format("  only in Δ_F(I): {}\n", fmt::join(ours, ", "));
    }
    if (!theirs.empty()) {
        out.text += fmt::format("  only in {}: {}\n", user.name, fmt::join(theirs, ", "));
    }
    return false;
}

/// A plan's cost for --format json: the total and whether every action costs 1, or why it is
/// undefined.
nlohmann::ordered_json cost_json(const pddl::PlanCost& cost) {
    if (!cost.undefined.empty()) {
        return {{"total", nullptr}, {"undefined", cost.undefined}};
    }
    return {{"total", cost.total}, {"unit_cost", cost.unit}};
}

/// "source plan cost: 12 (general cost)" when the source domain's actions have costs.
void source_cost(const PddlTransfer& pt, PddlChecks& out) {
    if (!pt.source->pddl_domain.has_costs()) {
        return;
    }
    auto cost = pddl::plan_cost(pt.source->pddl_domain, *pt.source->pddl_problem, pt.plan);
    out.text += "source plan cost: " + pddl::describe_cost(cost) + "\n";
    out.json["source_cost"] = cost_json(cost);
}

} // namespace

bool is_pddl_problem(const std::string& problem) {
    return problem.size() > 5 && problem.compare(problem.size() - 5, 5, ".pddl") == 0;
}

std::optional<TransferInputs> load_pddl_transfer_inputs(Session& s, const lang::Module& m,
                                                        TransferInputs in, const TransferArgs& a,
                                                        std::ostream& err) {
    auto source = pddl_domain_on(m, in.map->source());
    if (source == nullptr) {
        error(err, fmt::format("map '{}' migrates from {}, which is no PDDL domain of '{}' "
                               "(@import its .pddl file)",
                               a.map, in.map->source()->name(), a.file));
        return std::nullopt;
    }
    auto problem = read_problem(s, a.problem, source->pddl_domain, err);
    if (!problem) {
        return std::nullopt;
    }
    auto with_problem = pddl::import_problem(*source, *problem, s.sink);
    if (report(s, err) || !with_problem) {
        return std::nullopt;
    }
    PddlTransfer pt;
    pt.source = std::make_shared<const pddl::Import>(std::move(*with_problem));
    in.problem = pt.source->problem;
    if (!add_target(s, m, in, a, pt, err)) {
        return std::nullopt;
    }
    if (!a.target_problem.empty()) {
        if (pt.target == nullptr) {
            error(err, fmt::format("--target-problem needs a map into a PDDL domain; {} is not one",
                                   in.map->target()->name()));
            return std::nullopt;
        }
        pt.target_problem = read_problem(s, a.target_problem, pt.target->pddl_domain, err);
        if (!pt.target_problem) {
            return std::nullopt;
        }
        auto user = pddl::import_problem(*pt.target, *pt.target_problem, s.sink);
        if (report(s, err) || !user) {
            return std::nullopt;
        }
        if (in.target_goal == nullptr) {
            in.target_goal = user->problem->goal;
            in.target_goal_conditions = user->problem->goal_conditions;
        }
    }
    in.pddl = std::make_shared<const PddlTransfer>(std::move(pt));
    return in;
}

bool load_ipc_plan(Session& s, TransferInputs& in, const std::string& path, std::ostream& err) {
    auto f = read_input(s, path, err);
    if (!f) {
        return false;
    }
    auto plan = pddl::parse_ipc_plan(*f, s.sources, s.sink);
    if (plan) {
        // As `validate` does: a step no state could take is bad input, not an invalid plan.
        pddl::check_ipc_plan(*in.pddl->source, *plan, s.sink);
    }
    if (report(s, err) || !plan) {
        return false;
    }
    // The PDDL side is shared by every plan of a batch: this plan gets a copy of its own.
    auto pt = std::make_shared<PddlTransfer>(*in.pddl);
    pt->plan = std::move(*plan);
    in.plan = pddl::rule_plan(*pt->source, pt->plan);
    in.pddl = std::move(pt);
    return true;
}

std::string pddl_steps_text(const TransferInputs& in, const transfer::TransferResult& t) {
    const auto& pt = *in.pddl;
    std::string o;
    std::size_t n = 0;
    for (std::size_t i = 0; i < t.steps.size(); ++i) {
        const auto& st = t.steps[i];
        std::string from = fmt::format("step {} {}", i + 1, pt.plan[i].to_string());
        std::string how;
        switch (st.kind) {
        case transfer::StepTransfer::Kind::Generated:
            how = "its migrated action";
            break;
        case transfer::StepTransfer::Kind::Corresponds:
            how = fmt::format("{} is Δ_F({}) (the same action)",
                              pt.actions->name_of(st.target.action),
                              pt.source->action_of(st.source.action));
            break;
        case transfer::StepTransfer::Kind::Repaired:
            how = fmt::format(
                "repaired: {} step{} ({})", st.target_steps.size(),
                st.target_steps.size() == 1 ? "" : "s",
                st.repair_reused_from
                    ? fmt::format("step {}'s repair, renamed", *st.repair_reused_from + 1)
                    : fmt::format("{} states expanded", st.repair_stats.expanded));
            break;
        }
        if (st.target_steps.empty()) {
            o += fmt::format("  -  {}: {}, none needed (the target state holds what it made)\n",
                             from, how);
            continue;
        }
        for (std::size_t k = 0; k < st.target_steps.size(); ++k) {
            std::string line = fmt::format("  {}. {}", ++n, ipc_text(pt, st.target_steps[k]));
            if (k == 0) {
                line = fmt::format("{:<32} <- {}: {}", line, from, how);
            }
            o += line + "\n";
        }
    }
    return o;
}

int finish_pddl_transfer(const TransferInputs& in, const TransferArgs& a,
                         const transfer::TransferResult& t, std::string& plan_text,
                         PddlChecks& checks, std::vector<OutputText>& outputs) {
    const auto& pt = *in.pddl;
    plan::Plan target{transfer::target_plan(t.steps)};
    int rc = kOk;
    source_cost(pt, checks);
    if (pt.target == nullptr || !t.target_initial || !t.target_goal) {
        plan_text = target.to_string();
        return rc;
    }
    auto ipc = pddl::to_ipc_plan(*pt.target, target);
    CATPLAN_ASSERT(ipc.has_value(), "the target plan uses the target's rules");
    auto migrated = pddl::problem_of(*pt.target, pt.source->pddl_problem->name, *t.target_initial,
                                     *t.target_goal, t.target_goal_conditions);
    if (pt.target_problem) {
        // The target's function values (an action's cost) are the user's problem's.
        migrated.values = pt.target_problem->values;
        rc = compare_initial(pt, migrated, checks) ? rc : kNo;
    }
    auto cost = pddl::plan_cost(pt.target->pddl_domain, migrated, *ipc);
    plan_text = pddl::write_ipc_plan(*ipc, cost);
    if (pt.target->pddl_domain.has_costs()) {
        checks.text += "target plan cost: " + pddl::describe_cost(cost) +
                       (cost.undefined.empty() || pt.target_problem
                            ? "\n"
                            : " (--target-problem gives the target's values)\n");
        checks.json["target_cost"] = cost_json(cost);
    }
    std::size_t unwritten = migrated.unwritten_goal_conditions;
    if (unwritten > 0) {
        checks.text += fmt::format("note: {} condition{} of Δ_F(G) forbid{} several facts "
                                   "together, which a PDDL goal cannot say: the PDDL check below "
                                   "leaves {} out (the verdict above checks {})\n",
                                   unwritten, unwritten == 1 ? "" : "s", unwritten == 1 ? "s" : "",
                                   unwritten == 1 ? "it" : "them", unwritten == 1 ? "it" : "them");
    }
    auto v = pddl::simulate_ipc_plan(pt.target->pddl_domain, migrated, *ipc);
    checks.text += fmt::format("target plan checked by catplan's PDDL validator on {} and "
                               "Δ_F(I), Δ_F(G): {}\n",
                               pt.target->pddl_domain.name,
                               v.valid ? std::string("valid") : "invalid: " + v.reason);
    checks.json["pddl_check"] = {
        {"domain", pt.target->pddl_domain.name},
        {"valid", v.valid},
        {"reason", v.valid ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v.reason)},
        {"goal_conditions_left_out", unwritten}};
    if (t.verdict.valid() && !v.valid) {
        rc = kNo;
    }
    if (!a.problem_output.empty()) {
        outputs.push_back({pddl::write_problem(migrated), a.problem_output});
    }
    return rc;
}

} // namespace catplan::cli
