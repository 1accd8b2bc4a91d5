// `catplan report`: a plan transfer as one self-contained HTML page (report/report.hpp).

#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/report/report.hpp"
#include "catplan/transfer/transfer.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <memory>
#include <ostream>

namespace catplan::cli {
namespace {

struct ReportArgs {
    std::string file, map, domain, problem, plan_file, goal, output;
    bool replan = false, rename_by_type = false, lr = false, no_timing = false;
    std::string search = "bfs", heuristic = "hff";
    double max_time = 60;
};

// Everything a report reads from FILE and the plan file.
struct ReportInputs {
    std::shared_ptr<const migrate::SchemaMap> map;
    plan::ProblemPtr problem;
    plan::Plan plan;
    std::shared_ptr<const acset::ACSet> target_goal; // --goal
};

// The problem of the loaded module (loading FILE again would make new schemas, which the map
// would not be on), checked against --domain when one is given.
plan::ProblemPtr module_problem(const lang::Module& m, const ReportArgs& a, std::ostream& err) {
    const auto* p = find_declaration(m, a.file, a.problem, lang::DeclKind::Problem, err);
    if (p == nullptr) {
        return nullptr;
    }
    if (!a.domain.empty()) {
        const auto* d = find_declaration(m, a.file, a.domain, lang::DeclKind::Domain, err);
        if (d == nullptr) {
            return nullptr;
        }
        if (d->domain != p->problem->domain) {
            error(err, fmt::format("problem '{}' is on domain '{}', not '{}'", a.problem,
                                   p->problem->domain->name, a.domain));
            return nullptr;
        }
    }
    return p->problem;
}

std::optional<ReportInputs> load_inputs(Session& s, const ReportArgs& a, std::ostream& err) {
    auto m = load(s, a.file, err);
    if (!m) {
        return std::nullopt;
    }
    ReportInputs in;
    if (const auto* d = find_declaration(*m, a.file, a.map, lang::DeclKind::Map, err)) {
        in.map = d->map;
    }
    in.problem = module_problem(*m, a, err);
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
    auto f = s.sources.add_file(a.plan_file);
    if (!f) {
        error(err, fmt::format("cannot read '{}'", a.plan_file));
        return std::nullopt;
    }
    auto plan = plan::parse_plan(*f, s.sources, s.sink);
    if (report(s, err) || !plan) {
        return std::nullopt;
    }
    in.plan = std::move(*plan);
    return in;
}

int cmd_report(const ReportArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto in = load_inputs(s, a, err);
    if (!in) {
        return kBadInput;
    }
    transfer::TransferOptions options;
    options.keep_states = true; // the page shows every state
    options.rename_by_type = a.rename_by_type;
    // The verdict is about the goal intended in the target domain, as `transfer --goal`.
    options.goal = in->target_goal;
    options.goal_name = a.goal;
    auto t = transfer::transfer_plan(*in->map, *in->problem, in->plan, options);
    report::ReportInput r;
    r.map = in->map.get();
    r.map_name = a.map;
    r.problem = in->problem.get();
    r.plan = &in->plan;
    r.transfer = &t;
    r.transfer_peak_kib = transfer::peak_rss_kib();
    r.no_timing = a.no_timing;
    r.dot.left_to_right = a.lr;
    std::optional<transfer::Replan> rp;
    if (a.replan) {
        plan::SearchOptions so;
        so.search = *plan::parse_search(a.search);
        so.heuristic = *plan::parse_heuristic(a.heuristic);
        so.max_seconds = a.max_time;
        rp = transfer::replan(t, so);
        r.replan = &*rp;
    }
    int rc = emit(report::html_report(r), a.output, out, err);
    if (rc != kOk) {
        return rc;
    }
    const auto& v = t.verdict;
    if (!a.output.empty()) {
        out << fmt::format("{}: {}\n", a.output, v.valid() ? "valid" : "invalid: " + v.reason());
    }
    return v.valid() ? kOk : kNo;
}

} // namespace

void add_report_commands(CLI::App& app, CommandTable& table) {
    auto a = std::make_shared<ReportArgs>();
    auto* cmd = app.add_subcommand(
        "report", "Write an HTML report of a plan transfer: one self-contained page with the "
                  "ontologies, the map, both plans step by step with their states, the verdict "
                  "and goal satisfaction (exit 1 when the transferred plan is invalid)");
    cmd->add_option("FILE", a->file,
                    "language file declaring (or importing) the map, the domain and the problem")
        ->required();
    cmd->add_option("--map", a->map, "the ontology map F : target -> source")->required();
    cmd->add_option("--domain", a->domain, "the source domain (default: the problem's)");
    cmd->add_option("--problem", a->problem, "the source problem")->required();
    cmd->add_option("--plan", a->plan_file, "the source plan: one step per line")->required();
    cmd->add_option("--goal", a->goal,
                    "an instance of the target schema: the goal intended in the target domain "
                    "(default: the migrated source goal)");
    cmd->add_flag("--rename-by-type", a->rename_by_type,
                  "name target parts after their type (bread1, tomato1, ...)");
    cmd->add_flag("--replan", a->replan,
                  "also plan from scratch in the target domain and show the efficiency figures");
    cmd->add_option("--search", a->search, "with --replan: bfs, astar or gbfs")
        ->check(CLI::IsMember({"bfs", "astar", "gbfs"}))
        ->capture_default_str();
    cmd->add_option("--heuristic", a->heuristic, "with --replan: blind, goalcount, hadd or hff")
        ->check(CLI::IsMember({"blind", "goalcount", "hadd", "hff"}))
        ->capture_default_str();
    cmd->add_option("--max-time", a->max_time, "with --replan: stop the search after S seconds")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_flag("--lr", a->lr, "lay schemas and states out left to right");
    cmd->add_flag("--no-timing", a->no_timing, "leave out times and memory");
    cmd->add_option("-o,--output", a->output, "write the page to this file (default: stdout)");
    table.add(cmd, [a](std::ostream& o, std::ostream& e) { return cmd_report(*a, o, e); });
}

} // namespace catplan::cli
