#include "catplan/cli/common.hpp"

#include "catplan/acset/printer.hpp"
#include "catplan/base/output_file.hpp"
#include "catplan/cli/commands.hpp"
#include "catplan/cli/options.hpp"
#include "catplan/cli/pddl_transfer.hpp"
#include "catplan/plan/actions.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <fmt/format.h>
#include <ostream>
#include <unistd.h>

namespace catplan::cli {

// Prints the diagnostics collected since the last call, each once (a command loads in phases, each
// reporting what it found); returns true when there were errors.
bool report(Session& s, std::ostream& err) {
    const auto& all = s.sink.diagnostics();
    // Only the new ones: a session that reads many plans goes on after one that had errors.
    bool errors = std::any_of(all.begin() + static_cast<std::ptrdiff_t>(s.reported), all.end(),
                              [](const Diagnostic& d) { return d.severity == Severity::Error; });
    err << s.sink.render_from(s.reported);
    s.reported = all.size();
    return errors;
}

int input_error(const Session& s) {
    return s.sink.only_unsupported() ? kUnsupported : kBadInput;
}

// Loads a file and its imports; nullopt (with every diagnostic printed) when it has errors.
std::optional<lang::Module> load(Session& s, const std::string& file, std::ostream& err) {
    auto m = lang::load_file(file, s.sources, s.sink);
    if (report(s, err)) {
        return std::nullopt;
    }
    return m;
}

std::optional<std::uint32_t> read_input(Session& s, const std::string& path, std::ostream& err) {
    auto file = s.sources.add_file(path);
    if (!file) {
        error(err, fmt::format("cannot read '{}': {}", path, file.error()));
        return std::nullopt;
    }
    return *file;
}

std::optional<plan::Plan> load_plan(Session& s, const std::string& path,
                                    const plan::Problem& problem, std::ostream& err) {
    auto file = read_input(s, path, err);
    if (!file) {
        return std::nullopt;
    }
    auto plan = plan::parse_plan(*file, s.sources, s.sink);
    if (plan) {
        plan::check_plan(*plan, *problem.domain, *problem.initial, s.sink);
    }
    if (report(s, err) || !plan) {
        return std::nullopt;
    }
    return plan::rule_plan(*problem.domain, *problem.initial, *plan);
}

void error(std::ostream& err, const std::string& message) {
    err << "catplan: error: " << message << "\n";
}

// The files are staged (each written in full beside its target) before anything is printed or put
// in place, so that a command that cannot write one of its outputs writes none.
int emit(const std::vector<OutputText>& outputs, std::ostream& out, std::ostream& err) {
    OutputSet files;
    std::string why;
    for (const auto& o : outputs) {
        if (!o.path.empty() && o.path != "-" && !files.stage(o.path, o.text, why)) {
            error(err, why);
            return kBadInput;
        }
    }
    out.flush(); // what stdout had comes before a target written in place, such as /dev/stdout
    if (!files.commit(why)) {
        error(err, why);
        return kBadInput;
    }
    for (const auto& o : outputs) {
        if (o.path.empty() || o.path == "-") {
            out << o.text;
        }
    }
    return kOk;
}

int emit(const std::string& text, const std::string& output, std::ostream& out, std::ostream& err) {
    return emit(std::vector<OutputText>{{text, output}}, out, err);
}

std::string declared_names(const lang::Module& m) {
    std::string names;
    for (const auto& d : m.declarations()) {
        names += (names.empty() ? "" : ", ") + d.name;
    }
    return names.empty() ? "none" : names;
}

std::string indent(const std::string& text, std::size_t n) {
    std::string out, pad(n, ' ');
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        end = end == std::string::npos ? text.size() : end + 1;
        out += pad + text.substr(start, end - start);
        start = end;
    }
    return out;
}

std::string rule_tables(const rewrite::Rule& rule, std::size_t n) {
    std::string out = indent(lang::summarize_rule(rule) + "\n", n);
    std::vector<std::pair<std::string, const acset::ACSet*>> states = {
        {"Pre", &rule.L}, {"Keep", &rule.K}, {"Eff", &rule.R}};
    for (const auto& c : rule.conditions) {
        states.emplace_back(c.name, &c.n_state);
    }
    for (const auto& [label, state] : states) {
        out += indent(fmt::format("{}:\n", label), n + 2) + indent(acset::to_tables(*state), n + 4);
    }
    return out;
}

std::string_view kind_name(lang::DeclKind kind) {
    switch (kind) {
    case lang::DeclKind::Schema:
        return "a schema";
    case lang::DeclKind::Instance:
        return "an instance";
    case lang::DeclKind::Rule:
        return "a rule";
    case lang::DeclKind::Domain:
        return "a domain";
    case lang::DeclKind::Problem:
        return "a problem";
    case lang::DeclKind::Map:
        return "a map";
    }
    return "a declaration";
}

// The declaration `name` of the wanted kind, or an error message on err.
const lang::Declaration* find_declaration(const lang::Module& m, const std::string& file,
                                          const std::string& name,
                                          std::optional<lang::DeclKind> kind, std::ostream& err) {
    const auto* d = m.find(name);
    if (d == nullptr) {
        error(err, fmt::format("'{}' declares nothing named '{}' (declared: {})", file, name,
                               declared_names(m)));
        return nullptr;
    }
    if (kind && d->kind != *kind) {
        error(err, fmt::format("'{}' is {}, not {}", name, kind_name(d->kind), kind_name(*kind)));
        return nullptr;
    }
    return d;
}

// The instance `name` as a goal on the map's target schema.
std::shared_ptr<const acset::ACSet> find_target_goal(const lang::Module& m, const std::string& file,
                                                     const std::string& name,
                                                     const schema::SchemaPtr& target,
                                                     std::ostream& err) {
    const auto* g = find_declaration(m, file, name, lang::DeclKind::Instance, err);
    if (g == nullptr) {
        return nullptr;
    }
    if (g->schema != target) {
        error(err, fmt::format("goal '{}' is on {}, not on the map's target {}", name,
                               g->schema->name(), target->name()));
        return nullptr;
    }
    return g->instance;
}

const rewrite::Rule* find_rule(const lang::Module& m, const std::string& name) {
    for (const auto& d : m.declarations()) {
        if (d.kind == lang::DeclKind::Rule && d.name == name) {
            return d.rule.get();
        }
        if (d.kind == lang::DeclKind::Domain) {
            if (const auto* r = d.domain->find_rule(name)) {
                return r;
            }
        }
    }
    return nullptr;
}

const lang::Declaration* load_declaration(Session& s, const std::string& file,
                                          const std::string& name,
                                          std::optional<lang::DeclKind> kind,
                                          std::optional<lang::Module>& m, std::ostream& err) {
    m = load(s, file, err);
    return m ? find_declaration(*m, file, name, kind, err) : nullptr;
}

// The problem `problem_name` of FILE, checked against `--domain` when one is given.
plan::ProblemPtr load_problem(Session& s, const std::string& file, const std::string& domain_name,
                              const std::string& problem_name, std::ostream& err) {
    auto m = load(s, file, err);
    if (!m) {
        return nullptr;
    }
    return find_problem(*m, file, domain_name, problem_name, err);
}

plan::ProblemPtr find_problem(const lang::Module& m, const std::string& file,
                              const std::string& domain_name, const std::string& problem_name,
                              std::ostream& err) {
    const auto* p = find_declaration(m, file, problem_name, lang::DeclKind::Problem, err);
    if (p == nullptr) {
        return nullptr;
    }
    if (!domain_name.empty()) {
        const auto* d = find_declaration(m, file, domain_name, lang::DeclKind::Domain, err);
        if (d == nullptr) {
            return nullptr;
        }
        if (d->domain != p->problem->domain) {
            error(err, fmt::format("problem '{}' is on domain '{}', not '{}'", problem_name,
                                   p->problem->domain->name, domain_name));
            return nullptr;
        }
    }
    return p->problem;
}

void add_transfer_input_options(CLI::App* cmd, TransferArgs& a, std::vector<std::string>* plans) {
    cmd->add_option("FILE", a.file,
                    "language file declaring (or importing) the map, the domain and the problem")
        ->required();
    cmd->add_option("--map", a.map, "the ontology map F : target -> source")->required();
    cmd->add_option("--domain", a.domain, "the source domain (default: the problem's)");
    cmd->add_option("--problem", a.problem,
                    "the source problem (or a PDDL problem file of a domain FILE imports)")
        ->required();
    const std::string plan_help =
        "the source plan: one step per line (an IPC plan with a PDDL problem)";
    if (plans == nullptr) {
        cmd->add_option("--plan", a.plan_file, plan_help)->required();
    } else {
        // One value per --plan, so that a plan cannot swallow the FILE after it.
        cmd->add_option("--plan", *plans,
                        plan_help + "; repeat it, or name a directory, to transfer many plans")
            ->required()
            ->allow_extra_args(false);
    }
    cmd->add_option("--goal", a.goal,
                    "an instance of the target schema: the goal intended in the target domain "
                    "(default: the migrated source goal)");
    cmd->add_flag("--rename-by-type", a.rename_by_type,
                  "name target parts after their type (bread1, tomato1, ...)");
}

void add_replan_options(CLI::App* cmd, TransferArgs& a, const std::string& replan_help) {
    cmd->add_flag("--replan", a.replan, replan_help);
    cmd->add_option("--search", a.search, "with --replan: bfs, astar or gbfs")
        ->check(CLI::IsMember({"bfs", "astar", "gbfs"}))
        ->capture_default_str();
    cmd->add_option("--heuristic", a.heuristic, "with --replan: blind, goalcount, hadd or hff")
        ->check(CLI::IsMember({"blind", "goalcount", "hadd", "hff"}))
        ->capture_default_str();
    cmd->add_option("--max-time", a.max_time,
                    "with --replan: stop the search after S seconds (default: 60, or none with "
                    "--max-nodes)")
        ->check(positive_number("seconds"));
    cmd->add_option("--max-nodes", a.max_nodes,
                    "with --replan: stop the search after expanding N states (the same result on "
                    "every machine, unlike a time limit)")
        ->check(positive_count());
    cmd->add_flag("--progress", a.progress,
                  "with --replan: report the search's progress on stderr every 2 s (the default "
                  "when stderr is a terminal)");
}

void add_trajectory_options(CLI::App* cmd, TransferArgs& a) {
    cmd->add_flag("--strict", a.strict,
                  "a target trajectory that diverges from the migrated source states is invalid "
                  "(exit 1)");
    cmd->add_flag("--follow-source", a.follow_source,
                  "take each target state to be the migrated source state and check that each "
                  "target step reaches it");
}

plan::SearchOptions replan_options(const TransferArgs& a, std::ostream& err) {
    plan::SearchOptions so;
    so.search = *plan::parse_search(a.search);
    so.heuristic = *plan::parse_heuristic(a.heuristic);
    so.max_nodes = a.max_nodes;
    so.max_seconds = a.max_time > 0 ? a.max_time : a.max_nodes > 0 ? 0 : 60;
    if (a.progress || ::isatty(STDERR_FILENO) != 0) {
        so.progress = [&err](const plan::SearchStats& st) {
            err << fmt::format("catplan: replanning: expanded {}, generated {}, frontier {}, "
                               "{:.1f} s\n",
                               st.expanded, st.generated, st.frontier, st.seconds);
        };
    }
    return so;
}

std::optional<TransferInputs> load_transfer_inputs(Session& s, const TransferArgs& a,
                                                   std::ostream& err) {
    auto in = load_transfer_setting(s, a, err);
    if (!in || !load_transfer_plan(s, *in, a.plan_file, err)) {
        return std::nullopt;
    }
    return in;
}

std::optional<TransferInputs> load_transfer_setting(Session& s, const TransferArgs& a,
                                                    std::ostream& err) {
    auto m = load(s, a.file, err);
    if (!m) {
        return std::nullopt;
    }
    TransferInputs in;
    if (const auto* d = find_declaration(*m, a.file, a.map, lang::DeclKind::Map, err)) {
        in.map = d->map;
    }
    if (is_pddl_problem(a.problem)) {
        return in.map ? load_pddl_transfer_inputs(s, *m, std::move(in), a, err) : std::nullopt;
    }
    // The problem of the loaded module: loading FILE again would make new schemas, which the
    // map would not be on.
    in.problem = find_problem(*m, a.file, a.domain, a.problem, err);
    if (in.map == nullptr || in.problem == nullptr) {
        return std::nullopt;
    }
    if (in.map->source() != in.problem->domain->schema) {
        error(err, fmt::format("map '{}' goes from {} to {}, but problem '{}' is on {}", a.map,
                               in.map->target()->name(), in.map->source()->name(), a.problem,
                               in.problem->domain->schema->name()));
        return std::nullopt;
    }
    if (!a.goal.empty()) {
        in.target_goal = find_target_goal(*m, a.file, a.goal, in.map->target(), err);
        if (in.target_goal == nullptr) {
            return std::nullopt;
        }
    }
    return in;
}

bool load_transfer_plan(Session& s, TransferInputs& in, const std::string& path,
                        std::ostream& err) {
    if (in.pddl) {
        return load_ipc_plan(s, in, path, err);
    }
    auto plan = load_plan(s, path, *in.problem, err);
    if (!plan) {
        return false;
    }
    in.plan = std::move(*plan);
    return true;
}

transfer::TransferOptions transfer_options(const TransferArgs& a, const TransferInputs& in) {
    // PDDL inputs: the target domain's own actions carry the steps out.
    transfer::TransferOptions options =
        in.pddl ? pddl_transfer::transfer_options(*in.pddl->setting, in.pddl->plan)
                : transfer::TransferOptions{};
    options.rename_by_type = a.rename_by_type;
    // The verdict is about the goal intended in the target domain, when one is given.
    options.goal = in.target_goal;
    options.goal_conditions = in.target_goal_conditions;
    // The command names the user's target problem by its file.
    options.goal_name = in.pddl && a.goal.empty() ? a.target_problem : a.goal;
    options.strict = a.strict;
    options.follow_source = a.follow_source;
    return options;
}

std::optional<int> CommandTable::run_parsed(std::ostream& out, std::ostream& err) const {
    for (const auto& [command, run] : entries_) {
        if (command->parsed()) {
            return run(out, err);
        }
    }
    return std::nullopt;
}

} // namespace catplan::cli
