// `catplan report`: a plan transfer as one self-contained HTML page (report/report.hpp).

#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/cli/options.hpp"
#include "catplan/report/report.hpp"
#include "catplan/transfer/transfer.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <memory>
#include <ostream>

namespace catplan::cli {
namespace {

struct ReportArgs {
    TransferArgs in;
    std::string output;
    bool lr = false, no_timing = false;
};

int cmd_report(const ReportArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto in = load_transfer_inputs(s, a.in, err);
    if (!in) {
        return input_error(s);
    }
    auto options = transfer_options(a.in, *in);
    options.keep_states = true; // the page shows every state
    auto t = transfer::transfer_plan(*in->map, *in->problem, in->plan, options);
    report::ReportInput r;
    r.map = in->map.get();
    r.map_name = a.in.map;
    r.problem = in->problem.get();
    r.plan = &in->plan;
    r.transfer = &t;
    r.transfer_peak_kib = catplan::peak_rss_kib();
    r.no_timing = a.no_timing;
    r.dot.left_to_right = a.lr;
    std::optional<transfer::Replan> rp;
    if (a.in.replan) {
        rp = transfer::replan(t, replan_options(a.in, err));
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
    add_transfer_input_options(cmd, a->in);
    add_trajectory_options(cmd, a->in);
    add_replan_options(
        cmd, a->in, "also plan from scratch in the target domain and show the efficiency figures");
    cmd->add_flag("--lr", a->lr, "lay schemas and states out left to right");
    cmd->add_flag("--no-timing", a->no_timing, "leave out times and memory");
    cmd->add_option("-o,--output", a->output, "write the page to this file (default: stdout)");
    table.add(cmd, [a](std::ostream& o, std::ostream& e) { return cmd_report(*a, o, e); });
}

} // namespace catplan::cli
