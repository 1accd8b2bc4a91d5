// `catplan pddl import|export`, and `plan` / `validate` on PDDL files (commands.cpp dispatches to
// pddl_plan and pddl_validate when a positional file ends in .pddl).

#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/cli/json_output.hpp"
#include "catplan/cli/pddl_export.hpp"
#include "catplan/cli/plan_commands.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/export.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <ostream>
#include <tuple>

namespace catplan::cli {

namespace {

/// Reads and imports a domain and (when `problem_file` is not empty) a problem; nullopt with
/// every diagnostic printed.
std::optional<pddl::Import> load_pddl(Session& s, const std::string& domain_file,
                                      const std::string& problem_file, std::ostream& err) {
    auto df = read_input(s, domain_file, err);
    if (!df) {
        return std::nullopt;
    }
    auto domain = pddl::parse_domain(*df, s.sources, s.sink);
    if (report(s, err) || !domain) {
        return std::nullopt;
    }
    std::optional<pddl::Problem> problem;
    if (!problem_file.empty()) {
        auto pf = read_input(s, problem_file, err);
        if (!pf) {
            return std::nullopt;
        }
        problem = pddl::parse_problem(*pf, *domain, s.sources, s.sink);
        if (report(s, err) || !problem) {
            return std::nullopt;
        }
    }
    auto im = pddl::import_pddl(*domain, problem ? &*problem : nullptr, s.sink);
    if (report(s, err) || !im) {
        return std::nullopt;
    }
    return im;
}

/// "cost 3" or "cost (road-length ?from ?to)" after `prefix`, for an action of a domain whose
/// actions have costs; "" otherwise.
std::string cost_words(const pddl::Import& im, const std::string& action, std::string_view prefix) {
    const pddl::Action* a = im.pddl_domain.find_action(action);
    if (a == nullptr || !im.pddl_domain.has_costs()) {
        return "";
    }
    std::vector<std::string> terms;
    for (const auto& c : a->cost) {
        terms.push_back(c.to_string());
    }
    return fmt::format("{}cost {}", prefix,
                       terms.empty() ? "0" : fmt::format("{}", fmt::join(terms, " + ")));
}

/// The negative literals of the problem's goal, as PDDL writes them ("(not (at t1 hq))").
std::vector<std::string> negative_goals(const pddl::Import& im) {
    std::vector<std::string> out;
    for (const auto& l : im.pddl_problem->goal) {
        if (!l.positive) {
            out.push_back(l.to_string());
        }
    }
    return out;
}

/// The imported domain as `@domain <name>_domain(<name>)`: named apart from its schema, which
/// keeps the PDDL name that maps refer to.
std::string domain_text(const pddl::Import& im) {
    plan::Domain d = *im.domain;
    d.name += "_domain";
    auto text = lang::print_domain(d);
    // An imported rule is always writable: no attribute variables, expressions or SPO, and
    // every created fact has all its arguments.
    CATPLAN_ASSERT(text.has_value(), "an imported PDDL domain cannot be written");
    return *text;
}

/// The objects of the PDDL types, most specific first: a PDDL object is a part of its type and
/// of each ancestor, all named alike, and its name goes to the part of its own type.
std::vector<ObId> types_deepest_first(const pddl::Import& im) {
    // A subtype has every ancestor of its supertype and that supertype: strictly more.
    std::vector<std::tuple<std::size_t, ObId>> types;
    for (const auto& [type, ob] : im.type_ob) {
        std::size_t ancestors = 0;
        for (const auto& [other, _] : im.type_ob) {
            ancestors += other != type && im.pddl_domain.is_subtype(type, other) ? 1 : 0;
        }
        types.emplace_back(ancestors, ob);
    }
    std::sort(types.begin(), types.end(), [](const auto& a, const auto& b) {
        return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) > std::get<0>(b)
                                                : std::get<1>(a) < std::get<1>(b);
    });
    std::vector<ObId> out;
    for (const auto& [ancestors, ob] : types) {
        out.push_back(ob);
    }
    return out;
}

/// The imported domain and problem in catplan's language: schema, states, rules and problem.
std::string import_text(const pddl::Import& im, const std::string& domain_file) {
    std::string out = fmt::format("# Imported by catplan from {}.\n", domain_file);
    out += "# Each PDDL action is one rule per identification of its parameters and per open fact\n"
           "# (src/catplan/pddl/import.hpp)";
    for (const auto& a : im.actions) {
        if (a.variants.size() > 1) {
            out += fmt::format(": `{}` is the second rule of the action `{}`,\n# as its "
                               "`action = ...` says, and plans name the action",
                               a.variants[1].rule->name, a.action);
            break;
        }
    }
    out += ".\n# The predicates are facts: a fact that is added where it holds is not added "
           "again.\n\n";
    out += lang::print_schema(*im.domain->schema) + "\n";
    out += domain_text(im);
    if (im.problem != nullptr) {
        auto order = types_deepest_first(im);
        out += "\n" + lang::print_instance(*im.problem->initial, "Initial", order) + "\n";
        out += lang::print_instance(*im.problem->goal, "Goal", order) + "\n";
        auto problem =
            lang::print_problem(*im.problem, im.domain->name + "_domain", "Initial", "Goal", order);
        // An imported goal condition is a fact added to the goal: always writable.
        CATPLAN_ASSERT(problem.has_value(), "an imported PDDL problem cannot be written");
        auto negative = negative_goals(im);
        if (!negative.empty()) {
            out += fmt::format("# The negative goals {} are the NAC blocks.\n",
                               fmt::join(negative, ", "));
        }
        out += *problem;
    }
    return out;
}

/// `pddl import --format json`: the schema, the initial state and goal, the rules of each action.
nlohmann::ordered_json import_json(const pddl::Import& im) {
    nlohmann::ordered_json j;
    j["schema"] = schema_value(*im.domain->schema);
    j["initial"] = im.problem ? acset_value(*im.problem->initial) : nlohmann::ordered_json(nullptr);
    j["goal"] = im.problem ? acset_value(*im.problem->goal) : nlohmann::ordered_json(nullptr);
    if (im.problem != nullptr) {
        j["negative_goals"] = negative_goals(im);
    }
    j["actions"] = nlohmann::ordered_json::array();
    for (const auto& a : im.actions) {
        nlohmann::ordered_json rules = nlohmann::ordered_json::array();
        for (const auto& v : a.variants) {
            rules.push_back({{"name", v.rule->name}, {"summary", lang::summarize_rule(*v.rule)}});
        }
        j["actions"].push_back({{"action", a.action}, {"rules", std::move(rules)}});
        if (im.pddl_domain.has_costs()) {
            j["actions"].back()["cost"] = cost_words(im, a.action, "").substr(5);
        }
    }
    return j;
}

int cmd_pddl_import(const std::vector<std::string>& files, const std::string& output, bool json,
                    std::ostream& out, std::ostream& err) {
    Session s;
    auto im = load_pddl(s, files[0], files.size() > 1 ? files[1] : "", err);
    if (!im) {
        return input_error(s);
    }
    return emit(json ? json_text(import_json(*im)) : import_text(*im, files[0]), output, out, err);
}

struct ExportArgs {
    std::string file, domain, problem, map, output, problem_output, plan, from_ipc;
};

/// The domain (and problem) carried along the map declared in the module; nullopt with an error
/// printed when the map does not fit or a rule cannot be migrated.
std::optional<std::pair<plan::DomainPtr, plan::ProblemPtr>>
migrate_for_export(const lang::Module& m, const ExportArgs& a, const plan::DomainPtr& domain,
                   const plan::ProblemPtr& problem, std::ostream& err) {
    const auto* decl = find_declaration(m, a.file, a.map, lang::DeclKind::Map, err);
    if (decl == nullptr) {
        return std::nullopt;
    }
    auto migrated = migrate_along(*decl->map, domain, problem);
    if (!migrated) {
        error(err, migrated.error());
        return std::nullopt;
    }
    return *migrated;
}

/// `pddl export --plan P`: P (a plan of the problem exported) in the export's terms, as an IPC
/// plan; `--from-ipc F`: the export's IPC plan F as a catplan plan, validated on the problem
/// exported (exit 1 when it is invalid there).
int translate_plan(Session& s, const ExportArgs& a, const pddl::Exported& ex, std::ostream& out,
                   std::ostream& err) {
    auto f = read_input(s, a.plan.empty() ? a.from_ipc : a.plan, err);
    if (!f) {
        return kBadInput;
    }
    if (!a.plan.empty()) {
        auto plan = plan::parse_plan(*f, s.sources, s.sink);
        if (report(s, err) || !plan) {
            return kBadInput;
        }
        auto ipc = pddl::to_exported_plan(ex, *plan);
        if (!ipc) {
            error(err, ipc.error());
            return kNo;
        }
        return emit(pddl::write_ipc_plan(*ipc), a.output, out, err);
    }
    auto ipc = pddl::parse_ipc_plan(*f, s.sources, s.sink);
    if (report(s, err) || !ipc) {
        return kBadInput;
    }
    auto plan = pddl::from_exported_plan(ex, *ipc);
    if (!plan) {
        error(err, plan.error());
        return kBadInput;
    }
    // Checked with the matches the export expresses (replay_exported), and by catplan's
    // validation, which may find a step of a migrated rule ambiguous.
    auto r = pddl::replay_exported(ex, *plan);
    auto v = plan::validate_plan(*ex.source, *plan);
    std::string text = plan->to_string();
    text += r ? "# valid on " + ex.source->name + " with the export's matches: goal reached\n"
              : "# invalid on " + ex.source->name + ": " + r.error() + "\n";
    text += v.valid ? "# catplan validate: valid\n" : "# catplan validate: " + v.reason + "\n";
    int rc = emit(text, a.output, out, err);
    return rc != kOk ? rc : (r ? kOk : kNo);
}

int cmd_pddl_export(const ExportArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    plan::DomainPtr domain;
    plan::ProblemPtr problem;
    auto m = load(s, a.file, err);
    if (!m) {
        return input_error(s);
    }
    if (!a.problem.empty()) {
        // From the module loaded above, so that its schemas are the ones a map refers to.
        const auto* d = find_declaration(*m, a.file, a.problem, lang::DeclKind::Problem, err);
        if (d == nullptr) {
            return input_error(s);
        }
        problem = d->problem;
        domain = problem->domain;
        if (!a.domain.empty() && a.domain != domain->name) {
            error(err, fmt::format("problem '{}' is on domain {}, not {}", a.problem, domain->name,
                                   a.domain));
            return input_error(s);
        }
    } else {
        if (a.domain.empty()) {
            error(err, "pddl export needs --domain or --problem");
            return input_error(s);
        }
        const auto* d = find_declaration(*m, a.file, a.domain, lang::DeclKind::Domain, err);
        if (d == nullptr) {
            return input_error(s);
        }
        domain = d->domain;
    }
    if (problem != nullptr && !problem->goal_conditions.empty()) {
        // PDDL can say a negative goal; this export does not write one (nor migrate it).
        for (const auto& c : problem->goal_conditions) {
            s.sink.unsupported(c.range, fmt::format("the negative goal {} of problem {}: catplan's "
                                                    "PDDL export does not write goal conditions",
                                                    c.name, problem->name));
        }
        report(s, err);
        return kUnsupported;
    }
    if (!a.map.empty()) {
        auto migrated = migrate_for_export(*m, a, domain, problem, err);
        if (!migrated) {
            return input_error(s);
        }
        std::tie(domain, problem) = *migrated;
    }
    if ((!a.plan.empty() || !a.from_ipc.empty()) && problem == nullptr) {
        error(err, "--plan and --from-ipc need --problem");
        return kBadInput;
    }
    auto ex = pddl::export_pddl(*domain, problem.get());
    if (!ex) {
        error(err, ex.error());
        return kUnsupported;
    }
    for (const auto& note : ex->notes) {
        err << "catplan: note: " << note << "\n";
    }
    if (!a.plan.empty() || !a.from_ipc.empty()) {
        return translate_plan(s, a, *ex, out, err);
    }
    if (!a.problem_output.empty()) {
        // Both files or neither (emit stages them together).
        return emit({{ex->domain, a.output}, {ex->problem, a.problem_output}}, out, err);
    }
    return emit(ex->problem.empty() ? ex->domain : ex->domain + "\n" + ex->problem, a.output, out,
                err);
}

/// " (file:line:col)" for a located step, "" otherwise.
std::string where(const Session& s, SourceRange r) {
    if (!r.valid()) {
        return "";
    }
    auto lc = s.sources.line_col(r.file, r.begin);
    return fmt::format(" ({}:{}:{})", s.sources.name(r.file), lc.line, lc.col);
}

/// `validate --format json` on PDDL: each step applied with its IPC action and arguments, the
/// rule variant that applied and its match (replayed as DPO steps to find the matches).
nlohmann::ordered_json ipc_validation_json(const Session& s, const pddl::Import& im,
                                           const pddl::IpcPlan& plan,
                                           const pddl::IpcValidation& v) {
    plan::ValidateOptions options;
    options.keep_states = true;
    auto replay = plan::validate_plan(*im.problem, v.plan, options);
    nlohmann::ordered_json rule_steps = validated_steps_json(*im.problem, v.plan.steps, replay);
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < rule_steps.size(); ++i) {
        auto step = step_json(plan[i].action, plan[i].args, rule_steps[i]["match"]);
        step["rule"] = v.plan.steps[i].to_string();
        step["cost"] = v.cost.steps[i];
        steps.push_back(std::move(step));
    }
    std::string at = v.failed_step ? where(s, plan[*v.failed_step].range) : "";
    if (at.size() > 3) {
        at = at.substr(2, at.size() - 3); // " (f:l:c)" -> "f:l:c"
    }
    auto j =
        validation_json(v.valid, v.goal_reached, v.failed_step, v.reason, at, std::move(steps));
    j["cost"] = v.valid ? nlohmann::ordered_json(v.cost.total) : nlohmann::ordered_json(nullptr);
    j["unit_cost"] = v.cost.unit;
    return j;
}

/// The plan's cost as the plan file's last line says it (when `written` to a file), and whether
/// the search's "optimal" holds for it: only A* sums costs (docs/planner.md).
std::string cost_summary(const pddl::PlanCost& cost, bool written, const plan::SearchResult& r) {
    // The plan's own last line says its cost, unless the plan went to a file.
    std::string out = written ? "; plan cost: " + pddl::describe_cost(cost) + "\n" : "";
    if (!cost.unit && r.optimal && !r.costs) {
        out += "; the search counted every step as 1: the plan is shortest, its cost may not be "
               "the least\n";
    }
    return out;
}

} // namespace

Result<std::pair<plan::DomainPtr, plan::ProblemPtr>>
migrate_along(const migrate::SchemaMap& f, const plan::DomainPtr& domain,
              const plan::ProblemPtr& problem) {
    if (domain->schema != f.source()) {
        return fail(fmt::format("domain '{}' is on schema {}, but the map migrates {}",
                                domain->name, domain->schema->name(), f.source()->name()));
    }
    auto d = std::make_shared<plan::Domain>();
    d->name = domain->name + "_" + f.target()->name();
    d->schema = f.target();
    for (const auto& rule : domain->rules) {
        auto migrated = migrate::migrate(f, *rule);
        if (!migrated) {
            return fail(fmt::format("{} cannot be migrated: {}", rule->name, migrated.error()));
        }
        d->rules.push_back(std::make_shared<rewrite::Rule>(std::move(*migrated)));
    }
    plan::ProblemPtr p;
    if (problem != nullptr) {
        auto q = std::make_shared<plan::Problem>(*problem);
        q->domain = d;
        q->initial = std::make_shared<acset::ACSet>(migrate::migrate(f, *problem->initial));
        q->goal = std::make_shared<acset::ACSet>(migrate::migrate(f, *problem->goal));
        p = q;
    }
    return std::pair{plan::DomainPtr(d), p};
}

bool is_pddl_input(const std::vector<std::string>& files) {
    return std::any_of(files.begin(), files.end(), [](const std::string& f) {
        return f.size() >= 5 && f.compare(f.size() - 5, 5, ".pddl") == 0;
    });
}

int pddl_validate(const std::vector<std::string>& files, bool json, std::ostream& out,
                  std::ostream& err) {
    if (files.size() != 3) {
        error(err, "validate on PDDL takes DOMAIN.pddl PROBLEM.pddl PLAN");
        return kBadInput;
    }
    Session s;
    auto im = load_pddl(s, files[0], files[1], err);
    if (!im) {
        return input_error(s);
    }
    auto f = read_input(s, files[2], err);
    if (!f) {
        return input_error(s);
    }
    auto plan = pddl::parse_ipc_plan(*f, s.sources, s.sink);
    if (plan) {
        pddl::check_ipc_plan(*im, *plan, s.sink);
    }
    if (report(s, err) || !plan) {
        return input_error(s);
    }
    auto v = pddl::validate_ipc_plan(*im, *plan);
    if (json) {
        out << json_text(ipc_validation_json(s, *im, *plan, v));
        return v.valid ? kOk : kNo;
    }
    for (std::size_t i = 0; i < v.plan.steps.size(); ++i) {
        out << fmt::format("{}. {}   [rule {}]{}\n", i + 1, (*plan)[i].to_string(),
                           v.plan.steps[i].to_string(),
                           v.cost.unit ? "" : fmt::format("   cost {}", v.cost.steps[i]));
    }
    if (v.valid) {
        out << "valid: goal reached\nplan cost: " << pddl::describe_cost(v.cost) << "\n";
        return kOk;
    }
    std::string at = v.failed_step ? where(s, (*plan)[*v.failed_step].range) : "";
    out << fmt::format("invalid: {}{}\n", v.reason, at);
    return kNo;
}

int pddl_plan(const std::vector<std::string>& files, const plan::SearchOptions& options,
              const std::string& search, const std::string& output, bool timing, bool json,
              std::ostream& out, std::ostream& err) {
    if (files.size() != 2) {
        error(err, "plan on PDDL takes DOMAIN.pddl PROBLEM.pddl");
        return kBadInput;
    }
    Session s;
    auto im = load_pddl(s, files[0], files[1], err);
    if (!im) {
        return input_error(s);
    }
    auto r = plan::find_plan(*im->problem, options);
    int rc = plan_exit_code(r.status);
    std::optional<pddl::IpcPlan> ipc;
    pddl::PlanCost cost;
    std::string text;
    if (r.plan) {
        auto converted = pddl::to_ipc_plan(*im, *r.plan);
        CATPLAN_ASSERT(converted.has_value(), "the planner uses the imported rules");
        ipc = std::move(*converted);
        cost = pddl::plan_cost(im->pddl_domain, *im->pddl_problem, *ipc);
        if (!cost.undefined.empty()) {
            // The grounded search leaves such steps out; the C-set search does not read costs.
            error(err, fmt::format("the plan found is not valid: {} (the C-set search does not "
                                   "read costs, so it cannot avoid a step without one)",
                                   cost.undefined));
            return kUnsupported;
        }
        text = pddl::write_ipc_plan(*ipc, cost);
        if (!output.empty() && output != "-") {
            if (int wrc = emit(text, output, out, err); wrc != kOk) {
                return wrc;
            }
            text.clear();
        }
    }
    if (json) {
        nlohmann::ordered_json steps = nlohmann::ordered_json::array();
        for (const auto& st : ipc ? *ipc : pddl::IpcPlan{}) {
            steps.push_back({{"action", st.action}, {"args", st.args}});
        }
        auto j = plan_json(r, search, std::move(steps), timing);
        j["cost"] = ipc ? nlohmann::ordered_json(cost.total) : nlohmann::ordered_json(nullptr);
        j["unit_cost"] = pddl::unit_cost(im->pddl_domain, *im->pddl_problem);
        if (!j["unit_cost"].get<bool>() && !r.costs && r.plan) {
            j["optimal"] = false; // the search counted steps, not costs
        }
        out << j.dump(2) << "\n";
        return rc;
    }
    out << text << plan_summary(r, search, ipc ? ipc->size() : 0, timing, "; ");
    if (ipc) {
        out << cost_summary(cost, text.empty(), r);
    }
    return rc;
}

void add_pddl_commands(CLI::App& app, CommandTable& table) {
    auto* pddl_cmd = app.add_subcommand("pddl", "PDDL interop (plan and validate also read PDDL)");
    pddl_cmd->require_subcommand(1);

    static std::vector<std::string> import_files;
    static std::string import_output;
    static std::string import_format = "text";
    auto* imp = pddl_cmd->add_subcommand(
        "import", "Read a PDDL domain (and problem) and print it in catplan's language");
    imp->add_option("FILES", import_files, "DOMAIN.pddl [PROBLEM.pddl]")
        ->required()
        ->expected(1, 2);
    imp->add_option("-o,--output", import_output, "write to this file instead of stdout");
    imp->add_option("--format", import_format, "text (catplan's language) or json")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
    table.add(imp, [](std::ostream& o, std::ostream& e) {
        return cmd_pddl_import(import_files, import_output, import_format == "json", o, e);
    });

    static ExportArgs ea;
    auto* exp = pddl_cmd->add_subcommand(
        "export", "Write a domain (and problem) of a language file as PDDL, where expressible");
    exp->add_option("FILE", ea.file, "language file (.cp)")->required();
    exp->add_option("--domain", ea.domain, "the domain (default: the problem's domain)");
    exp->add_option("--problem", ea.problem, "the problem, exported after the domain");
    exp->add_option("--map", ea.map,
                    "an ontology map declared in FILE: export the domain (and problem) migrated "
                    "along it");
    exp->add_option("-o,--output", ea.output, "write the domain (and problem) to this file");
    exp->add_option("--problem-output", ea.problem_output, "write the problem to this file");
    exp->add_option("--plan", ea.plan,
                    "a plan of the problem: print it in the export's terms (an IPC plan) instead")
        ->excludes(exp->get_option("--problem-output"));
    exp->add_option("--from-ipc", ea.from_ipc,
                    "an IPC plan of the export: print it as a plan of the problem, validated on "
                    "it (exit 1 when invalid), instead")
        ->excludes(exp->get_option("--problem-output"))
        ->excludes(exp->get_option("--plan"));
    table.add(exp, [](std::ostream& o, std::ostream& e) { return cmd_pddl_export(ea, o, e); });
}

} // namespace catplan::cli
