#include "catplan/cli/commands.hpp"

#include "catplan/acset/printer.hpp"
#include "catplan/base/assert.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/out_of_memory.hpp"
#include "catplan/base/output_file.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/cli/json_output.hpp"
#include "catplan/cli/options.hpp"
#include "catplan/cli/plan_commands.hpp"
#include "catplan/dot/dot.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/json/json.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/describe.hpp"
#include "catplan/plan/actions.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/schema/printer.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

namespace catplan::cli {

namespace {

// ---- json -----------------------------------------------------------------------------------

int cmd_json_export(const std::string& file, const std::string& name, bool pretty, bool names,
                    const std::string& output, std::ostream& out, std::ostream& err) {
    Session s;
    std::optional<lang::Module> m;
    const auto* d = load_declaration(s, file, name, std::nullopt, m, err);
    if (d == nullptr) {
        return kBadInput;
    }
    if (d->kind != lang::DeclKind::Schema && d->kind != lang::DeclKind::Instance) {
        error(err, fmt::format("'{}' is not a schema or an instance: Catlab's JSON has no format "
                               "for it",
                               name));
        return kBadInput;
    }
    std::string text = d->kind == lang::DeclKind::Schema
                           ? json::write_schema(*d->schema, pretty)
                           : json::write_acset(*d->instance, pretty, names);
    return emit(text + "\n", output, out, err);
}

// ---- dot ------------------------------------------------------------------------------------

int cmd_dot(const std::string& file, const std::string& name, bool left_to_right,
            const std::string& output, std::ostream& out, std::ostream& err) {
    Session s;
    auto m = load(s, file, err);
    if (!m) {
        return kBadInput;
    }
    dot::DotOptions options;
    options.left_to_right = left_to_right;
    if (const auto* rule = find_rule(*m, name)) {
        return emit(dot::rule_to_dot(*rule, options), output, out, err);
    }
    const auto* d = find_declaration(*m, file, name, std::nullopt, err);
    if (d == nullptr) {
        return kBadInput;
    }
    if (d->kind == lang::DeclKind::Schema) {
        return emit(dot::schema_to_dot(*d->schema, options), output, out, err);
    }
    if (d->kind == lang::DeclKind::Instance) {
        return emit(dot::state_to_dot(*d->instance, d->name, options), output, out, err);
    }
    if (d->kind == lang::DeclKind::Map) {
        return emit(dot::map_to_dot(*d->map, d->name, options), output, out, err);
    }
    error(err, fmt::format("'{}' has no picture: name a schema, an instance or a rule", name));
    return kBadInput;
}

std::string file_stem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

int cmd_json_import(const std::vector<std::string>& args, std::string name,
                    const std::string& output, std::ostream& out, std::ostream& err) {
    Session s;
    const std::string& json_file = args.back();
    if (name.empty()) {
        name = json_file == "-" ? "stdin" : file_stem(json_file);
    }
    if (args.size() == 1) {
        auto f = read_input(s, json_file, err);
        if (!f) {
            return kBadInput;
        }
        auto sch = json::read_schema(name, *f, s.sources, s.sink);
        if (report(s, err) || sch == nullptr) {
            return kBadInput;
        }
        return emit(lang::print_schema(*sch), output, out, err);
    }
    if (args.size() != 3) {
        error(err, "json import takes SCHEMA_FILE SCHEMA JSON_FILE, or JSON_FILE for a schema");
        return kBadInput;
    }
    auto m = load(s, args[0], err);
    if (!m) {
        return kBadInput;
    }
    const auto* d = find_declaration(*m, args[0], args[1], lang::DeclKind::Schema, err);
    if (d == nullptr) {
        return kBadInput;
    }
    auto f = read_input(s, json_file, err);
    if (!f) {
        return kBadInput;
    }
    auto x = json::read_acset(d->schema, *f, s.sources, s.sink);
    if (report(s, err) || !x) {
        return kBadInput;
    }
    return emit(lang::print_instance(*x, name), output, out, err);
}

// ---- validate and plan ----------------------------------------------------------------------

struct ValidateArgs {
    std::vector<std::string> files; // FILE, or DOMAIN.pddl PROBLEM.pddl PLAN
    std::string domain, problem, plan_file, format = "text";
    bool trace = false;
};

int cmd_validate(const ValidateArgs& a, std::ostream& out, std::ostream& err) {
    if (is_pddl_input(a.files)) {
        return pddl_validate(a.files, a.format == "json", out, err);
    }
    if (a.files.size() != 1 || a.problem.empty() || a.plan_file.empty()) {
        error(err, "validate takes FILE --problem P --plan PLAN, or DOMAIN.pddl PROBLEM.pddl PLAN");
        return kBadInput;
    }
    Session s;
    auto problem = load_problem(s, a.files[0], a.domain, a.problem, err);
    if (problem == nullptr) {
        return input_error(s);
    }
    auto plan = load_plan(s, a.plan_file, *problem, err);
    if (!plan) {
        return kBadInput;
    }
    plan::ValidateOptions options;
    options.keep_states = true; // the matches are printed against the state they apply to
    auto v = plan::validate_plan(*problem, *plan, options);
    std::string where;
    if (v.failed_step && plan->steps[*v.failed_step].range.valid()) {
        auto r = plan->steps[*v.failed_step].range;
        auto lc = s.sources.line_col(r.file, r.begin);
        where = fmt::format("{}:{}:{}", s.sources.name(r.file), lc.line, lc.col);
    }
    if (a.format == "json") {
        auto j = validation_json(v.valid, v.goal_reached, v.failed_step, v.reason, where,
                                 validated_steps_json(*problem, plan->steps, v));
        if (v.cost && v.valid) {
            j["cost"] = *v.cost;
        }
        out << json_text(j);
        return v.valid ? kOk : kNo;
    }
    if (a.trace) {
        out << "initial state:\n" << acset::to_tables(v.states[0]);
    }
    for (std::size_t i = 0; i < v.matches.size(); ++i) {
        const auto& step = plan->steps[i];
        const auto* rule = problem->domain->find_rule(step.action);
        out << fmt::format("{}. {}\n", i + 1, plan::action_step(*rule, step).to_string());
        out << fmt::format("   match: {}\n",
                           plan::describe_match(v.matches[i], rule->L, v.states[i]));
        if (a.trace) {
            out << fmt::format("state after step {}:\n", i + 1)
                << acset::to_tables(v.states[i + 1]);
        }
    }
    if (v.valid) {
        out << "valid: goal reached\n";
        out << (v.cost ? fmt::format("plan cost: {}\n", *v.cost) : "");
        return kOk;
    }
    out << fmt::format("invalid: {}{}\n", v.reason, where.empty() ? "" : " (" + where + ")");
    return kNo;
}

struct PlanArgs {
    std::vector<std::string> files; // FILE, or DOMAIN.pddl PROBLEM.pddl
    std::string domain, problem, output, format = "text";
    std::string search = "lama", heuristic = "default";
    std::uint64_t max_nodes = 0;
    double max_time = 0;
    double max_memory_mb = 0; // the planner's default (75% of the machine's memory)
    bool no_timing = false, anytime = false, no_ground = false;
};

/// The search options of `a`; progress reports go to `err` and into `last`, which is what an
/// out-of-memory error can tell of the search.
plan::SearchOptions plan_options(const PlanArgs& a, std::ostream& err,
                                 const std::shared_ptr<plan::SearchStats>& last) {
    plan::SearchOptions options;
    options.start = plan::Clock::now(); // reading the input counts against --max-time too
    options.search = *plan::parse_search(a.search);
    options.heuristic = *plan::parse_heuristic(a.heuristic);
    options.ground = !a.no_ground;
    options.anytime = a.anytime;
    options.max_nodes = a.max_nodes;
    options.max_seconds = a.max_time;
    options.max_bytes = static_cast<std::size_t>(a.max_memory_mb * 1e6);
    options.progress = [&err, last, timing = !a.no_timing](const plan::SearchStats& st) {
        *last = st;
        if (timing) {
            double search = st.search_seconds();
            err << fmt::format("catplan: searching: expanded {} ({:.0f}/s), evaluated {}, "
                               "generated {}, frontier {}, h {}, {:.1f} MB, {:.1f} s\n",
                               st.expanded,
                               search > 0 ? static_cast<double>(st.expanded) / search : 0.0,
                               st.evaluated, st.generated, st.frontier, st.f,
                               static_cast<double>(st.memory) / 1e6, st.seconds);
        }
    };
    return options;
}

} // namespace

std::string plan_summary(const plan::SearchResult& r, const std::string& search, std::size_t steps,
                         bool timing, std::string_view comment) {
    std::string label = fmt::format("{}: {}{}", search, r.config, r.optimal ? "; optimal" : "");
    std::string text;
    switch (r.status) {
    case plan::SearchStatus::Solved:
        text =
            fmt::format("{}plan of {} step{} ({})\n", comment, steps, steps == 1 ? "" : "s", label);
        break;
    case plan::SearchStatus::Unsolvable:
        text = fmt::format("{}no plan: the goal is unreachable (every reachable state was "
                           "expanded; {})\n",
                           comment, label);
        break;
    default:
        text = fmt::format("{}no plan found: {} reached ({})\n", comment, plan::to_string(r.status),
                           label);
    }
    if (r.path == "grounded") {
        text += fmt::format("{}grounded search: {} variables, {} actions", comment,
                            r.stats.variables, r.stats.actions);
        text += timing ? fmt::format(", compiled in {:.3f} s\n", r.stats.ground_seconds) : "\n";
    } else {
        text += fmt::format("{}C-set search: {}\n", comment, r.path_reason);
    }
    if (r.exits > 0) {
        text += fmt::format("{}{} transition{} left the ground task and {} not followed, e.g. "
                            "{}\n",
                            comment, r.exits, r.exits == 1 ? "" : "s",
                            r.exits == 1 ? "was" : "were", r.exit_example);
    }
    if (r.stats.plans > 1) {
        text += fmt::format("{}anytime: {} plans found, the {} kept\n", comment, r.stats.plans,
                            r.costs ? "cheapest" : "shortest");
    }
    if (r.uncosted > 0) {
        text += fmt::format("{}{} ground action{} left out: the problem gives {} step no cost\n",
                            comment, r.uncosted, r.uncosted == 1 ? " was" : "s were",
                            r.uncosted == 1 ? "its" : "their");
    }
    if (!r.costs_ignored.empty()) {
        text += fmt::format("{}note: every step counted as 1: {}\n", comment, r.costs_ignored);
    }
    if (!r.caveat.empty()) {
        text += fmt::format("{}note: {}\n", comment, r.caveat);
    }
    return text + plan::describe(r.stats, timing, comment);
}

nlohmann::ordered_json plan_json(const plan::SearchResult& r, const std::string& search,
                                 nlohmann::ordered_json steps, bool timing) {
    nlohmann::ordered_json j;
    j["status"] = std::string(plan::to_string(r.status));
    if (r.status == plan::SearchStatus::Solved) {
        j["plan"] = std::move(steps);
        j["optimal"] = r.optimal;
    }
    j["search"] = {{"name", search},        {"config", r.config},
                   {"path", r.path},        {"reason", r.path_reason},
                   {"exits", r.exits},      {"exit_example", r.exit_example},
                   {"sums_costs", r.costs}, {"uncosted_actions", r.uncosted}};
    if (!r.costs_ignored.empty()) {
        j["search"]["costs_ignored"] = r.costs_ignored;
    }
    if (!r.caveat.empty()) {
        j["search"]["caveat"] = r.caveat;
    }
    const auto& st = r.stats;
    nlohmann::ordered_json stats = {{"expanded", st.expanded},   {"evaluated", st.evaluated},
                                    {"generated", st.generated}, {"duplicates", st.duplicates},
                                    {"states", st.states},       {"variables", st.variables},
                                    {"actions", st.actions},     {"plans", st.plans}};
    nlohmann::ordered_json initial = nlohmann::ordered_json::object();
    for (const auto& [kind, value] : st.initial_h) {
        initial[std::string(plan::to_string(kind))] =
            value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
    }
    stats["initial_h"] = std::move(initial);
    if (timing) {
        double search_s = st.search_seconds();
        stats["seconds"] = st.seconds;
        stats["setup_seconds"] = st.setup_seconds;
        stats["ground_seconds"] = st.ground_seconds;
        stats["search_seconds"] = search_s;
        stats["expanded_per_second"] =
            search_s > 0 ? static_cast<double>(st.expanded) / search_s : 0.0;
        stats["evaluated_per_second"] =
            search_s > 0 ? static_cast<double>(st.evaluated) / search_s : 0.0;
        stats["memory_bytes"] = st.memory;
        stats["peak_memory_bytes"] = st.peak_memory;
        stats["setup_memory_bytes"] = st.setup_memory;
        stats["cpu_seconds"] = st.cpu_seconds;
        stats["search_cpu_seconds"] = st.search_cpu_seconds();
    }
    j["statistics"] = std::move(stats);
    return j;
}

int plan_exit_code(plan::SearchStatus status) {
    switch (status) {
    case plan::SearchStatus::Solved:
        return kOk;
    case plan::SearchStatus::Unsolvable:
        return kNo;
    default:
        return kLimit;
    }
}

namespace {

/// Whether every rule costs 1: a search that counts steps then finds the least cost.
bool unit_costs(const plan::Domain& d) {
    return std::all_of(d.rules.begin(), d.rules.end(), [](const auto& r) {
        return !r->cost || (r->cost->constant == 1 && r->cost->terms.empty());
    });
}

int cmd_plan(const PlanArgs& a, std::ostream& out, std::ostream& err) {
    auto last = std::make_shared<plan::SearchStats>();
    auto options = plan_options(a, err, last);
    OutOfMemoryNote note([last] {
        if (last->seconds == 0) {
            return std::string("the search ran out of memory before its first progress report");
        }
        std::string stats = plan::describe(*last, true, "");
        stats.pop_back(); // one line: the statistics' lines joined
        std::replace(stats.begin(), stats.end(), '\n', ';');
        return "the search had, at its last progress report, " + stats;
    });
    bool json = a.format == "json";
    if (is_pddl_input(a.files)) {
        return pddl_plan(a.files, options, a.search, a.output, !a.no_timing, json, out, err);
    }
    if (a.files.size() != 1 || a.problem.empty()) {
        error(err, "plan takes FILE --problem P, or DOMAIN.pddl PROBLEM.pddl");
        return kBadInput;
    }
    Session s;
    auto problem = load_problem(s, a.files[0], a.domain, a.problem, err);
    if (problem == nullptr) {
        return input_error(s);
    }
    auto r = plan::find_plan(*problem, options);
    std::optional<std::int64_t> cost;
    if (r.plan) {
        if (problem->step_cost) {
            auto c = plan::plan_cost(*problem, r.plan->steps);
            if (!c) {
                // The grounded search leaves such steps out; the C-set search does not read costs.
                error(err, fmt::format("the plan found is not valid: {} (the C-set search does "
                                       "not read costs, so it cannot avoid a step without one)",
                                       c.error()));
                return kUnsupported;
            }
            cost = *c;
        }
        r.plan = plan::action_plan(*problem->domain, *r.plan); // as the user writes them
    }
    int rc = plan_exit_code(r.status);
    std::string text = r.plan ? r.plan->to_string() : "";
    if (r.plan && !a.output.empty() && a.output != "-") {
        if (int wrc = emit(text, a.output, out, err); wrc != kOk) {
            return wrc;
        }
        text.clear();
    }
    if (json) {
        nlohmann::ordered_json steps = nlohmann::ordered_json::array();
        for (const auto& st : r.plan ? r.plan->steps : std::vector<plan::Step>{}) {
            steps.push_back({{"action", st.action}, {"args", st.args}});
        }
        auto j = plan_json(r, a.search, std::move(steps), !a.no_timing);
        if (cost) {
            j["cost"] = *cost;
            j["optimal"] = r.optimal && (r.costs || unit_costs(*problem->domain));
        }
        out << j.dump(2) << "\n";
        return rc;
    }
    out << text << (cost ? fmt::format("# cost = {}\n", *cost) : "")
        << plan_summary(r, a.search, r.plan ? r.plan->steps.size() : 0, !a.no_timing, "# ");
    if (cost && r.optimal && !r.costs && !unit_costs(*problem->domain)) {
        out << "# the search counted every step as 1: the plan is shortest, its cost may not be "
               "the least\n";
    }
    return rc;
}

// Catlab's ACSet JSON: json export, json import.
void add_json_commands(CLI::App& app, CommandTable& table) {
    struct Args {
        std::string export_file, export_name, export_output;
        bool export_pretty = false, export_names = false;
        std::vector<std::string> import_args;
        std::string import_name, import_output;
    };

    auto args = std::make_shared<Args>();
    auto* json_cmd = app.add_subcommand("json", "Catlab ACSet JSON interop");
    json_cmd->require_subcommand(1);
    auto* json_export = json_cmd->add_subcommand("export", "Write a schema or instance as JSON");
    json_export->add_option("FILE", args->export_file)->required();
    json_export->add_option("NAME", args->export_name)->required();
    json_export->add_flag("--pretty", args->export_pretty, "indent the JSON");
    json_export->add_flag("--names", args->export_names,
                          "keep part names as \"_name\" keys (read back by catplan; ACSets.jl "
                          "rejects them)");
    json_export->add_option("-o,--output", args->export_output,
                            "write to this file instead of stdout");
    auto* json_import = json_cmd->add_subcommand(
        "import", "Read Catlab JSON and print it in the language: SCHEMA_FILE SCHEMA JSON_FILE for "
                  "an instance, or JSON_FILE alone for a schema");
    json_import->add_option("ARGS", args->import_args, "SCHEMA_FILE SCHEMA JSON_FILE | JSON_FILE")
        ->required()
        ->expected(1, 3);
    json_import->add_option("--name", args->import_name, "name of the declaration printed");
    json_import->add_option("-o,--output", args->import_output,
                            "write to this file instead of stdout");

    using O = std::ostream;
    table.add(json_export, [args](O& o, O& e) {
        return cmd_json_export(args->export_file, args->export_name, args->export_pretty,
                               args->export_names, args->export_output, o, e);
    });
    table.add(json_import, [args](O& o, O& e) {
        return cmd_json_import(args->import_args, args->import_name, args->import_output, o, e);
    });
}

// dot: Graphviz pictures of schemas, states, rules and maps.
void add_dot_command(CLI::App& app, CommandTable& table) {
    struct Args {
        std::string dot_file, dot_name, dot_output;
        bool dot_lr = false;
    };

    auto args = std::make_shared<Args>();
    auto* dot_cmd = app.add_subcommand(
        "dot",
        "Write Graphviz DOT for a schema, an instance, a rule or an ontology map (render with "
        "`dot -Tsvg`)");
    dot_cmd->add_option("FILE", args->dot_file)->required();
    dot_cmd
        ->add_option("NAME", args->dot_name,
                     "a schema, an instance, a rule (also one of a domain) or a map")
        ->required();
    dot_cmd->add_flag("--lr", args->dot_lr, "lay schemas and states out left to right");
    dot_cmd->add_option("-o,--output", args->dot_output, "write to this file instead of stdout");

    using O = std::ostream;
    table.add(dot_cmd, [args](O& o, O& e) {
        return cmd_dot(args->dot_file, args->dot_name, args->dot_lr, args->dot_output, o, e);
    });
}

// The positional files and --domain / --problem that `validate` and `plan` share.
void add_problem_inputs(CLI::App* cmd, std::vector<std::string>& files, std::string& domain,
                        std::string& problem, const std::string& files_help) {
    cmd->add_option("FILE", files, files_help)->required()->expected(-1);
    cmd->add_option("--domain", domain, "the domain (default: the problem's domain)");
    cmd->add_option("--problem", problem, "the problem declared in FILE (required for a .cp file)");
}

// Plans: validate, plan.
void add_plan_commands(CLI::App& app, CommandTable& table) {
    struct Args {
        ValidateArgs validate_args;
        PlanArgs plan_args;
    };

    auto args = std::make_shared<Args>();
    auto* validate = app.add_subcommand(
        "validate", "Replay a plan on a problem and check its goal (exit 1 when invalid)");
    add_problem_inputs(validate, args->validate_args.files, args->validate_args.domain,
                       args->validate_args.problem,
                       "language file (.cp), or DOMAIN.pddl PROBLEM.pddl PLAN (an IPC plan)");
    validate->add_option("--plan", args->validate_args.plan_file,
                         "plan file: one step per line (required for a .cp file)");
    validate->add_flag("--trace", args->validate_args.trace, "print every state as tables");
    validate
        ->add_option("--format", args->validate_args.format,
                     "text or json (steps with their matches, the verdict)")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();

    auto* plan_cmd = app.add_subcommand(
        "plan", "Search for a plan (exit 1 when provably none, 4 when a limit stops the search)");
    add_problem_inputs(plan_cmd, args->plan_args.files, args->plan_args.domain,
                       args->plan_args.problem, "language file (.cp), or DOMAIN.pddl PROBLEM.pddl");
    plan_cmd
        ->add_option("--search", args->plan_args.search,
                     "lama (lazy greedy, hff and lmcount, preferred operators of hff), lazy (lazy "
                     "greedy with --heuristic), gbfs (eager greedy), astar (optimal with an "
                     "admissible heuristic) or bfs (shortest plans, small problems)")
        ->check(CLI::IsMember({"lama", "lazy", "gbfs", "astar", "bfs"}))
        ->capture_default_str();
    plan_cmd
        ->add_option("--heuristic", args->plan_args.heuristic,
                     "hff, hadd, hmax, lmcut (admissible), lmcount, goalcount or blind; default: "
                     "hff for gbfs and lazy, lmcut for astar")
        ->check(CLI::IsMember(
            {"default", "blind", "goalcount", "hadd", "hmax", "hff", "lmcut", "lmcount"}))
        ->capture_default_str();
    plan_cmd->add_flag("--anytime", args->plan_args.anytime,
                       "after the first plan, search for shorter ones until --max-time");
    plan_cmd->add_flag("--no-ground", args->plan_args.no_ground,
                       "search C-sets even where the problem compiles into a ground task");
    plan_cmd->add_option("--max-nodes", args->plan_args.max_nodes, "stop after expanding N states")
        ->check(positive_count());
    plan_cmd
        ->add_option("--max-time", args->plan_args.max_time,
                     "stop after S seconds of wall time, every phase included (default: none)")
        ->check(positive_number("seconds"));
    plan_cmd
        ->add_option("--max-memory", args->plan_args.max_memory_mb,
                     "stop when the process's resident memory reaches MB megabytes (default: 75% "
                     "of this machine's memory)")
        ->check(positive_number("megabytes"));
    plan_cmd->add_option("-o,--output", args->plan_args.output, "write the plan to this file");
    plan_cmd->add_option("--format", args->plan_args.format, "text or json (plan and statistics)")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
    plan_cmd->add_flag(
        "--no-timing", args->plan_args.no_timing,
        "no progress reports, no time or memory in the statistics (reproducible output)");

    using O = std::ostream;
    table.add(validate, [args](O& o, O& e) { return cmd_validate(args->validate_args, o, e); });
    table.add(plan_cmd, [args](O& o, O& e) { return cmd_plan(args->plan_args, o, e); });
}

} // namespace

const std::vector<CommandGroup>& command_groups() {
    static const std::vector<CommandGroup> groups = {
        {{"check", "show", "homs"}, add_inspect_commands},
        {{"json"}, add_json_commands},
        {{"dot"}, add_dot_command},
        {{"validate", "plan"}, add_plan_commands},
        {{"migrate", "migrate-domain"}, add_migrate_commands},
        {{"transfer"}, add_transfer_commands},
        {{"pddl"}, add_pddl_commands},
        {{"report"}, add_report_commands},
        {{"db", "library"}, add_db_commands},
    };
    return groups;
}

int run(int argc, char** argv, std::ostream& out, std::ostream& err) {
    CLI::App app{"catplan: categorical task planning and plan transfer between planning domains.\n"
                 "Exit codes: 0 ok, 1 no (e.g. no homomorphism), 2 bad input, 3 unsupported, "
                 "4 limit reached, 70 internal error (docs/exit-codes.md).",
                 "catplan"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "catplan 0.1.0");

    // Building every command's options is most of what catplan does before its work (a
    // millisecond), so only the group of the command named is built; every group when none is
    // (help, version, a misspelt command, which then gets a suggestion).
    CommandTable table;
    std::string_view named = argc > 1 ? argv[1] : "";
    const auto& groups = command_groups();
    auto group = std::find_if(groups.begin(), groups.end(), [&](const CommandGroup& g) {
        return std::find(g.names.begin(), g.names.end(), named) != g.names.end();
    });
    if (group != groups.end()) {
        group->add(app, table);
    } else {
        for (const auto& g : groups) {
            g.add(app, table);
        }
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e, out, err);
    } catch (const CLI::ParseError& e) {
        std::vector<std::string> args(argv + std::min(argc, 1), argv + argc);
        usage_error(err, command_for(app, args), subcommand_error(app, args).value_or(e.what()));
        return kBadInput;
    }

    if (auto rc = table.run_parsed(out, err)) {
        return *rc;
    }
    return kBadInput;
}

} // namespace catplan::cli
