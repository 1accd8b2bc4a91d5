// A plan transfer with PDDL inputs (pddl_transfer.hpp).

#include "catplan/pddl_transfer/pddl_transfer.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/pddl/steps.hpp"

#include <fmt/format.h>
#include <map>
#include <set>

namespace catplan::pddl_transfer {
namespace {

/// The user's target problem and its goal; false with the errors in sink.
bool add_target_problem(std::uint32_t file, const SourceManager& sources, Setting& s,
                        DiagnosticSink& sink) {
    if (s.target == nullptr) {
        sink.error(fmt::format("a target problem needs a map into a PDDL domain; {} is not one",
                               s.map->target()->name()));
        return false;
    }
    s.target_problem = pddl::parse_problem(file, s.target->pddl_domain, sources, sink);
    if (!s.target_problem || sink.has_errors()) {
        return false;
    }
    auto user = pddl::import_problem(*s.target, *s.target_problem, sink);
    if (!user || sink.has_errors()) {
        return false;
    }
    s.target_goal = user->problem->goal;
    s.target_goal_conditions = user->problem->goal_conditions;
    s.target_values = user->problem->values;
    return true;
}

/// The objects and facts of a not in b, in words.
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

/// The type of each object and constant of p (a problem of d).
std::map<std::string, std::string> object_types(const pddl::Domain& d, const pddl::Problem& p) {
    std::map<std::string, std::string> out;
    for (const auto& c : d.constants) {
        out.emplace(c.name, c.type);
    }
    for (const auto& o : p.objects) {
        out.emplace(o.name, o.type);
    }
    return out;
}

/// The source problem's values of the functions the map's functions section names, as values of
/// the target's functions in `migrated` (g(a, b) = f(a, b) where the map says g => f): Δ_F keeps
/// the objects' names. A value some argument of which is no object of `migrated` of g's type is
/// left out and named in `left_out`.
std::vector<pddl::FunctionValue> carried_values(const Setting& s, const pddl::Problem& migrated,
                                                std::vector<std::string>& left_out) {
    const pddl::Domain& target = s.target->pddl_domain;
    auto types = object_types(target, migrated);
    std::vector<pddl::FunctionValue> out;
    if (s.functions.empty()) {
        return out;
    }
    for (const auto& c : s.functions) {
        const pddl::Function* g = target.find_function(c.target);
        CATPLAN_ASSERT(g != nullptr, "the map's functions section names the target's functions");
        for (const auto& v : s.source->pddl_problem->values) {
            if (v.term.predicate != c.source) {
                continue;
            }
            bool fits = v.term.args.size() == g->params.size();
            for (std::size_t i = 0; fits && i < v.term.args.size(); ++i) {
                auto it = types.find(v.term.args[i].name);
                fits = it != types.end() && target.is_subtype(it->second, g->params[i].type);
            }
            if (!fits) {
                left_out.push_back(v.term.to_string());
                continue;
            }
            pddl::FunctionValue carried = v;
            carried.term.predicate = g->name;
            out.push_back(std::move(carried));
        }
    }
    return out;
}

/// The target's own actions matched to the generated ones, with the target's rules for Δ_F(I),
/// and without a user's target problem the values the functions section carries; false with the
/// errors in sink.
bool add_target(const lang::Module& m, const lang::Declaration& map, bool has_target_problem,
                Setting& s, DiagnosticSink& sink) {
    auto target = pddl_domain_on(m, s.map->target());
    if (target == nullptr) {
        return true; // the generated actions are the target's
    }
    acset::ACSet y0 = migrate::migrate(*s.map, *s.source->problem->initial);
    auto own = pddl::for_initial_facts(*target, target->facts(y0), sink);
    if (!own || sink.has_errors()) {
        return false;
    }
    s.target = std::make_shared<const pddl::Import>(std::move(*own));
    if (!has_target_problem && !s.functions.empty()) {
        // Δ_F(I)'s objects, typed, take the values the functions section carries.
        auto objects = pddl::problem_of(*s.target, "", y0, acset::ACSet(s.map->target()), {});
        s.carried_values = carried_values(s, objects, s.uncarried_values);
        s.target_values = pddl::function_values(s.carried_values);
    }
    std::vector<std::pair<std::string, std::string>> named;
    for (const auto& c : map.actions) {
        named.emplace_back(c.source, c.target);
    }
    auto source = s.source;
    auto own_import = s.target;
    s.actions = std::make_shared<const transfer::TargetActions>(transfer::correspond_domain(
        *s.generated->domain, s.target->domain, named,
        [own_import](std::string_view r) { return own_import->action_of(r); },
        [source](std::string_view r) { return source->action_of(r); }));
    return true;
}

} // namespace

std::shared_ptr<const pddl::Import> pddl_domain_on(const lang::Module& m,
                                                   const schema::SchemaPtr& schema) {
    for (const auto& d : m.declarations()) {
        if (d.kind == lang::DeclKind::Domain && d.pddl && d.domain->schema == schema) {
            return d.pddl;
        }
    }
    return nullptr;
}

std::optional<Setting> load_setting(const lang::Module& m, const lang::Declaration& map,
                                    std::uint32_t problem_file,
                                    std::optional<std::uint32_t> target_problem_file,
                                    const SourceManager& sources, DiagnosticSink& sink) {
    CATPLAN_ASSERT(map.kind == lang::DeclKind::Map, "a map's declaration");
    Setting s;
    s.map = map.map;
    auto source = pddl_domain_on(m, s.map->source());
    if (source == nullptr) {
        sink.error(fmt::format("map '{}' migrates from {}, which is no PDDL domain of the module "
                               "(@import its .pddl file)",
                               map.name, s.map->source()->name()));
        return std::nullopt;
    }
    auto problem = pddl::parse_problem(problem_file, source->pddl_domain, sources, sink);
    if (!problem || sink.has_errors()) {
        return std::nullopt;
    }
    auto with_problem = pddl::import_problem(*source, *problem, sink);
    if (!with_problem || sink.has_errors()) {
        return std::nullopt;
    }
    s.source = std::make_shared<const pddl::Import>(std::move(*with_problem));
    s.functions = map.functions;
    s.generated = std::make_shared<const transfer::MigratedDomain>(
        transfer::migrate_domain(*s.map, *s.source->problem->domain));
    if (!add_target(m, map, target_problem_file.has_value(), s, sink)) {
        return std::nullopt;
    }
    if (target_problem_file && !add_target_problem(*target_problem_file, sources, s, sink)) {
        return std::nullopt;
    }
    return s;
}

std::optional<pddl::IpcPlan> read_plan(const Setting& s, std::uint32_t file,
                                       const SourceManager& sources, DiagnosticSink& sink) {
    auto plan = pddl::parse_ipc_plan(file, sources, sink);
    if (plan) {
        // As `validate` does: a step no state could take is bad input, not an invalid plan.
        pddl::check_ipc_plan(*s.source, *plan, sink);
    }
    if (!plan || sink.has_errors()) {
        return std::nullopt;
    }
    return plan;
}

plan::Plan source_plan(const Setting& s, const pddl::IpcPlan& plan) {
    return pddl::rule_plan(*s.source, plan);
}

transfer::TransferOptions transfer_options(const Setting& s, const pddl::IpcPlan& plan) {
    transfer::TransferOptions o;
    o.source_fault = [source = s.source, plan]() -> std::optional<transfer::Fault> {
        auto v = pddl::simulate_ipc_plan(source->pddl_domain, *source->pddl_problem, plan);
        if (v.valid) {
            return std::nullopt;
        }
        // The validator words a step's reason as "step 3 (unstack e d): why".
        auto k = v.failed_step;
        return transfer::Fault::from_reason(
            transfer::Fault::Kind::SourcePlan, k,
            k ? fmt::format("step {} {}", *k + 1, plan[*k].to_string()) : "", v.reason);
    };
    o.goal = s.target_goal;
    o.goal_conditions = s.target_goal_conditions;
    if (s.target_problem) {
        o.goal_name = s.target_problem->name;
    }
    o.target_actions = s.actions;
    o.migrated_domain = s.generated;
    o.target_values = s.target_values;
    return o;
}

std::optional<pddl::IpcStep> ipc_step(const Setting& s, const plan::Step& step) {
    if (s.target == nullptr) {
        return std::nullopt;
    }
    auto ipc = pddl::to_ipc_plan(*s.target, plan::Plan{{step}});
    return ipc ? std::optional((*ipc)[0]) : std::nullopt;
}

std::string ipc_text(const Setting& s, const plan::Step& step) {
    auto ipc = ipc_step(s, step);
    return ipc ? ipc->to_string() : step.to_string();
}

bool Checks::ok(const transfer::TransferResult& t) const {
    if (comparison && !comparison->same()) {
        return false;
    }
    return !(t.verdict.valid() && validation && !validation->valid);
}

Checks check(const Setting& s, const pddl::IpcPlan& plan, const transfer::TransferResult& t) {
    Checks c;
    if (s.source->pddl_domain.has_costs()) {
        c.source_cost = pddl::plan_cost(s.source->pddl_domain, *s.source->pddl_problem, plan);
    }
    plan::Plan target{transfer::target_plan(t.steps)};
    if (s.target == nullptr || !t.target_initial || !t.target_goal) {
        c.plan_text = target.to_string();
        return c;
    }
    auto ipc = pddl::to_ipc_plan(*s.target, target);
    CATPLAN_ASSERT(ipc.has_value(), "the target plan uses the target's rules");
    c.migrated = pddl::problem_of(*s.target, s.source->pddl_problem->name, *t.target_initial,
                                  *t.target_goal, t.target_goal_conditions);
    if (!s.target_problem) {
        c.migrated->values = s.carried_values;
    } else {
        // The target's function values (an action's cost) are the user's problem's.
        c.migrated->values = s.target_problem->values;
        c.comparison = Comparison{s.target_problem->name, only_in(*c.migrated, *s.target_problem),
                                  only_in(*s.target_problem, *c.migrated)};
    }
    auto cost = pddl::plan_cost(s.target->pddl_domain, *c.migrated, *ipc);
    c.plan_text = pddl::write_ipc_plan(*ipc, cost);
    if (s.target->pddl_domain.has_costs()) {
        c.target_cost = cost;
    }
    c.unwritten_goal_conditions = c.migrated->unwritten_goal_conditions;
    c.validation = pddl::simulate_ipc_plan(s.target->pddl_domain, *c.migrated, *ipc);
    c.target_plan = std::move(*ipc);
    return c;
}

} // namespace catplan::pddl_transfer
