// `catplan transfer`: plan transfer along an ontology map (the paper's Algorithm 1), printed as
// text or JSON with its verdict.

#include "catplan/acset/printer.hpp"
#include "catplan/base/assert.hpp"
#include "catplan/base/keep.hpp"
#include "catplan/base/parallel.hpp"
#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/cli/json_output.hpp"
#include "catplan/cli/options.hpp"
#include "catplan/cli/pddl_transfer.hpp"
#include "catplan/json/json.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/describe.hpp"
#include "catplan/plan/actions.hpp"
#include "catplan/transfer/transfer.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string_view>

namespace catplan::cli {
namespace {

struct TransferCommandArgs {
    TransferArgs in;
    /// --plan: one plan, or many (files and directories) for a batch.
    std::vector<std::string> plans;
    std::string format = "text", output;
    bool trace = false, no_timing = false;
    /// --jobs: worker threads of a batch (0: one per core).
    std::size_t jobs = 0;
};

// Whether the claim of Appendix A holds, or the hypothesis it lacks: one line of the report.
std::string construction_line(const transfer::Verdict& v) {
    const auto& c = v.claim(transfer::Claim::Kind::ValidByConstruction);
    if (const auto* no = c.failing()) {
        return fmt::format("not valid by construction (paper Appendix A assumes {}, but {}): "
                           "every step is checked\n",
                           no->statement, no->why_not);
    }
    return "a delta migration preserves pushouts: the transferred plan is valid by "
           "construction (paper Appendix A); checked anyway\n";
}

// The first divergence as JSON (null when the target states are the migrated source states).
nlohmann::ordered_json divergence_json(const transfer::Verdict& v) {
    const auto* d = v.diverged();
    if (d == nullptr) {
        return nullptr;
    }
    return {{"index", d->step},
            {"step", d->where},
            {"only_in_target", d->only_in_target},
            {"only_in_migrated", d->only_in_migrated},
            {"more", d->more},
            {"difference", d->to_string()}};
}

std::string percent(const transfer::GoalSatisfaction& g) {
    return fmt::format("{:.0f}% ({} of {} goal statements{})", 100 * g.fraction(), g.satisfied,
                       g.total, g.exact ? "" : ", at least: the search was cut short");
}

// "1 step", "8 steps".
std::string step_count(std::size_t n) {
    return fmt::format("{} step{}", n, n == 1 ? "" : "s");
}

std::string map_brief(const migrate::SchemaMap& f) {
    auto lines = migrate::describe_map(f);
    // The attributes' defaults make the brief long; `catplan show` has them.
    lines.erase(
        std::remove_if(lines.begin(), lines.end(),
                       [](const auto& l) { return l.target.kind == schema::GeneratorKind::Attr; }),
        lines.end());
    return migrate::map_text(lines);
}

std::vector<std::string> plan_strings(const std::vector<plan::Step>& steps) {
    std::vector<std::string> out;
    for (const auto& s : steps) {
        out.push_back(s.to_string());
    }
    return out;
}

// Source step i as the user wrote it: an IPC step with PDDL inputs, else the action's step.
std::string source_step_text(const TransferInputs& in, std::size_t i) {
    return in.pddl ? in.pddl->plan[i].to_string()
                   : plan::action_step(*in.problem->domain, in.plan.steps[i]).to_string();
}

// The target steps as the actions they carry out: a generated step as the source action it is
// Δ_F of (`stack`, not the rule `stack~2`), the others as the target's own actions.
std::vector<plan::Step> target_steps(const TransferInputs& in, const transfer::TransferResult& t) {
    std::vector<plan::Step> out;
    for (const auto& st : t.steps) {
        const plan::Domain* d = st.kind == transfer::StepTransfer::Kind::Generated
                                    ? t.target_domain.domain.get()
                                    : in.pddl->setting->actions->domain.get();
        for (const auto& s : st.target_steps) {
            out.push_back(d != nullptr ? plan::action_step(*d, s) : s);
        }
    }
    return out;
}

// A match as morphism_json when the rule and the state it went into are known (the states are
// kept for JSON), else null.
nlohmann::ordered_json match_json(const hom::ACSetMorphism& m, const rewrite::Rule* rule,
                                  const std::vector<acset::ACSet>& states, std::size_t i) {
    if (rule == nullptr || i >= states.size() ||
        m.components.size() != rule->L.schema().num_obs()) {
        return nullptr;
    }
    return morphism_json(m, rule->L, states[i]);
}

// Each transferred step as an object: the source step with its match, how it was carried out,
// and the target steps it became (the first with its match, unless repaired).
nlohmann::ordered_json steps_json(const TransferInputs& in, const transfer::TransferResult& t) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < t.steps.size(); ++i) {
        const auto& st = t.steps[i];
        const auto* source_rule = in.problem->domain->find_rule(st.source.action);
        const rewrite::Rule* target_rule = nullptr;
        if (st.kind == transfer::StepTransfer::Kind::Generated) {
            target_rule = t.target_domain.domain->find_rule(st.target.action);
        } else if (st.kind == transfer::StepTransfer::Kind::Corresponds) {
            target_rule = in.pddl->setting->actions->domain->find_rule(st.target.action);
        }
        nlohmann::ordered_json targets = nlohmann::ordered_json::array();
        for (const auto& ts : st.target_steps) {
            targets.push_back(step_json(
                ts.action, ts.args,
                targets.empty() ? match_json(st.target_match, target_rule, t.target_states, i)
                                : nullptr));
        }
        out.push_back(
            {{"source", step_json(st.source.action, st.source.args,
                                  match_json(st.source_match, source_rule, t.source_states, i))},
             {"carried_out_by", transfer::to_string(st.kind)},
             {"target", targets},
             {"lost_parameters", st.lost_parameters}});
        if (st.kind == transfer::StepTransfer::Kind::Repaired) {
            out.back()["repair"] = {
                {"expanded", st.repair_stats.expanded},
                {"focus_parts", st.repair_focus},
                {"from_action", st.repair_from_action},
                {"reused_from", st.repair_reused_from
                                    ? nlohmann::ordered_json(*st.repair_reused_from + 1)
                                    : nlohmann::ordered_json(nullptr)},
                {"cost", st.repair_cost ? nlohmann::ordered_json(*st.repair_cost)
                                        : nlohmann::ordered_json(nullptr)},
                {"least_cost", st.repair_least_cost}};
        }
    }
    return out;
}

// What the command measured around the library calls.
struct Outcome {
    transfer::TransferResult t;
    long transfer_peak_kib = 0;
    std::optional<transfer::Replan> replan;
    /// What the source and target plans cost, where a `.cp` source problem sums costs.
    std::optional<transfer::PlanCosts> costs;
};

std::string cost_text(const Result<std::int64_t>& c) {
    return c ? std::to_string(*c) : "undefined: " + c.error();
}

// As a PDDL transfer's costs are written: {"total": 12}, or {"total": null, "undefined": why}.
nlohmann::ordered_json cost_json(const Result<std::int64_t>& c) {
    if (!c) {
        return {{"total", nullptr}, {"undefined", c.error()}};
    }
    return {{"total", *c}};
}

std::string text_report(const TransferCommandArgs& a, const TransferInputs& in, const Outcome& r,
                        const PddlChecks& checks) {
    const auto& t = r.t;
    const auto& v = t.verdict;
    const auto& goal = v.goal;
    const auto& rp = r.replan;
    const auto& f = *in.map;
    std::string o;
    o += fmt::format("transfer of {} ({}) along {} : {} -> {} ({} migration)\n", a.in.problem,
                     in.problem->domain->name, a.in.map, f.target()->name(), f.source()->name(),
                     transfer::to_string(t.migration));
    o += fmt::format("map:\n{}", map_brief(f));
    o += fmt::format("source plan ({}): {}\n", step_count(in.plan.steps.size()),
                     v.source_valid()
                         ? "valid"
                         : "invalid: " + v.find(transfer::Fault::Kind::SourcePlan)->to_string());
    for (std::size_t i = 0; i < in.plan.steps.size(); ++i) {
        o += fmt::format("  {}. {}\n", i + 1, source_step_text(in, i));
    }
    o += fmt::format("target plan ({}):\n", step_count(transfer::target_plan(t.steps).size()));
    if (in.pddl) {
        o += pddl_steps_text(in, t, checks);
    }
    for (std::size_t i = 0; i < t.steps.size() && !in.pddl; ++i) {
        const auto& st = t.steps[i];
        o += fmt::format("  {}. {}\n     match: {}\n", i + 1,
                         plan::action_step(*t.target_domain.domain, st.target).to_string(),
                         st.target_bindings.empty() ? "(nothing: the map sees no part of its "
                                                      "precondition)"
                                                    : st.target_bindings);
        if (!st.lost_parameters.empty()) {
            o += fmt::format("     note: the map does not see parameter(s) {} of {}\n",
                             fmt::join(st.lost_parameters, ", "), st.source.action);
        }
        if (a.trace) {
            o += fmt::format("     state after step {}:\n{}", i + 1,
                             acset::to_tables(t.target_states[i + 1]));
        }
    }
    if (const auto* failed = v.failed_step()) {
        o += fmt::format("  {}. {}: not transferred\n", *failed->step + 1,
                         source_step_text(in, *failed->step));
    }
    o += construction_line(v);
    for (const auto& d : v.divergences) {
        o += fmt::format("diverged: {}\n", d.to_string());
    }
    o += fmt::format("verdict: {}\n", v.summary());
    o += fmt::format("goal satisfaction: {}{}\n", percent(goal),
                     v.goal_name.empty() ? std::string() : fmt::format(" (goal {})", v.goal_name));
    for (const auto& u : goal.unsatisfied) {
        o += fmt::format("  unsatisfied: {}\n", u);
    }
    if (r.costs) {
        o += fmt::format("source plan cost: {}\ntarget plan cost: {}\n", cost_text(r.costs->source),
                         cost_text(r.costs->target));
    }
    if (!a.no_timing) {
        const auto& tm = t.timings;
        o += fmt::format("time: {:.3f} ms (migrate {:.3f}, replay and apply {:.3f}, validate "
                         "{:.3f})\n",
                         tm.total_ms, tm.migrate_ms, tm.apply_ms, tm.validate_ms);
    }
    if (rp) {
        o += fmt::format("replanning in {} ({}): {}", t.target_domain.domain->name, a.in.search,
                         plan::to_string(rp->search.status));
        if (rp->search.plan) {
            o += fmt::format(
                ", {}{}, edit distance to the transferred plan {}", step_count(rp->steps.size()),
                rp->cost ? fmt::format(" (cost {})", *rp->cost) : "", rp->edit_distance);
        }
        o += fmt::format("; expanded {}\n", rp->search.stats.expanded);
        bool mixed = false;
        for (std::size_t i = 0; i < rp->steps.size(); ++i) {
            o += fmt::format("  {}. {}\n", i + 1, rp->steps[i].to_string());
            for (const auto& arg : rp->steps[i].args) {
                mixed = mixed || arg.find('|') != std::string::npos;
            }
        }
        if (mixed) {
            o += "  note: an argument a|b binds one parameter to different parts in different "
                 "target types (e.g. one block's Object and another's Receptacle): the target "
                 "ontology does not tie them, so replanning may mix them\n";
        }
        if (!a.no_timing) {
            o += fmt::format("transfer {:.3f} ms vs replanning {:.3f} ms: {}; peak memory "
                             "{:.1f} MB after transfer, {:.1f} MB after replanning\n",
                             t.timings.total_ms, rp->ms,
                             transfer::speedup_text(*rp, t.timings.total_ms),
                             static_cast<double>(r.transfer_peak_kib) / 1024.0,
                             static_cast<double>(rp->peak_rss_kib) / 1024.0);
        }
    }
    return o;
}

nlohmann::ordered_json json_report(const TransferCommandArgs& a, const TransferInputs& in,
                                   const Outcome& r) {
    const auto& t = r.t;
    const auto& v = t.verdict;
    nlohmann::ordered_json j;
    j["map"] = a.in.map;
    j["source_schema"] = in.map->source()->name();
    j["target_schema"] = in.map->target()->name();
    j["valid"] = v.valid();
    j["failed_step"] = nullptr;
    if (const auto* failed = v.failed_step()) {
        j["failed_step"] = {{"index", *failed->step}, {"reason", v.reason()}};
    } else if (!v.valid()) {
        j["reason"] = v.reason();
    }
    j["goal_satisfaction"] = v.goal.fraction();
    j["goal_statements"] = v.goal.total;
    j["unsatisfied"] = v.goal.unsatisfied;
    j["migration"] = std::string(transfer::to_string(t.migration));
    const auto& claim = v.claim(transfer::Claim::Kind::ValidByConstruction);
    j["valid_by_construction"] = claim.holds();
    if (const auto* no = claim.failing()) {
        j["not_by_construction"] = {{"hypothesis", no->statement}, {"why_not", no->why_not}};
    }
    j["diverged_at"] = divergence_json(v);
    if (v.divergences.size() > 1) {
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const auto& d : v.divergences) {
            all.push_back(d.step);
        }
        j["diverged_steps"] = all;
    }
    j["source_plan"] = plan_strings(plan::action_plan(*in.problem->domain, in.plan).steps);
    j["source_valid"] = v.source_valid();
    j["target_plan"] = plan_strings(target_steps(in, t));
    j["steps"] = steps_json(in, t);
    nlohmann::ordered_json actions = nlohmann::ordered_json::array();
    for (const auto& rule : t.target_domain.domain->rules) {
        actions.push_back(rule->name);
    }
    j["generated_actions"] = actions;
    if (r.costs) {
        j["source_cost"] = cost_json(r.costs->source);
        j["target_cost"] = cost_json(r.costs->target);
    }
    if (!a.no_timing) {
        const auto& tm = t.timings;
        j["timings_ms"] = {{"migrate", tm.migrate_ms},
                           {"apply", tm.apply_ms},
                           {"validate", tm.validate_ms},
                           {"total", tm.total_ms}};
        j["peak_rss_kib"] = r.transfer_peak_kib;
    }
    if (r.replan) {
        const auto& rp = *r.replan;
        nlohmann::ordered_json k;
        k["status"] = std::string(plan::to_string(rp.search.status));
        k["plan"] = plan_strings(rp.steps);
        k["edit_distance"] = rp.edit_distance;
        if (rp.cost) {
            k["cost"] = *rp.cost;
        }
        k["expanded"] = rp.search.stats.expanded;
        if (!a.no_timing) {
            k["ms"] = rp.ms;
            k["ground_ms"] = rp.search.stats.ground_seconds * 1000;
            k["peak_rss_kib"] = rp.peak_rss_kib;
            k["speedup"] = rp.ms / std::max(t.timings.total_ms, 1e-6);
            k["speedup_is_lower_bound"] = transfer::hit_limit(rp);
        }
        j["replan"] = k;
    }
    return j;
}

Outcome run_transfer(const TransferCommandArgs& a, const TransferInputs& in, std::ostream& err) {
    auto options = transfer_options(a.in, in);
    // JSON gives each match with the state it went into.
    options.keep_states = a.trace || a.format != "text";
    // Only the text report of a plan in catplan's syntax prints the bindings.
    options.describe_bindings = a.format == "text" && !in.pddl;
    Outcome r;
    r.t = transfer::transfer_plan(*in.map, *in.problem, in.plan, options);
    r.transfer_peak_kib = catplan::peak_rss_kib();
    if (!in.pddl) {
        r.costs = transfer::plan_costs(r.t, *in.problem, in.plan);
    }
    if (a.in.replan) {
        r.replan = transfer::replan(r.t, replan_options(a.in, err));
    }
    return r;
}

// With PDDL inputs, the JSON report also has the target IPC plan and what the PDDL side checked.
void add_pddl_json(nlohmann::ordered_json& j, const std::string& plan_text,
                   const PddlChecks& checks) {
    j["target_ipc_plan"] = plan_text;
    j["pddl"] = checks.json;
}

// The exit code of one transferred plan: 0 valid (and, with PDDL inputs, checked), else 1.
int transfer_exit_code(const Outcome& r, int checked) {
    return r.t.verdict.valid() && checked == kOk ? kOk : kNo;
}

int cmd_transfer(const TransferCommandArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto in = load_transfer_setting(s, a.in, err);
    if (!in || !load_transfer_plan(s, *in, a.plans.front(), err)) {
        return input_error(s);
    }
    Outcome r = run_transfer(a, *in, err);
    int checked = kOk;
    std::vector<OutputText> outputs;
    PddlChecks checks;
    std::string plan_text;
    if (in->pddl) {
        checked = finish_pddl_transfer(*in, a.in, r.t, plan_text, checks, outputs);
    }
    std::string text;
    if (a.format == "json") {
        nlohmann::ordered_json j = json_report(a, *in, r);
        if (in->pddl) {
            add_pddl_json(j, plan_text, checks);
        }
        text = json::dump(j, 2) + "\n";
    } else {
        text = text_report(a, *in, r, checks) + checks.text;
    }
    if (in->pddl) {
        // With PDDL inputs, -o is the target IPC plan and the report goes to stdout.
        outputs.insert(outputs.begin(), OutputText{text, ""});
        if (!a.output.empty()) {
            outputs.push_back({plan_text, a.output});
        }
    } else {
        outputs.push_back({text, a.output});
    }
    int rc = emit(outputs, out, err);
    rc = rc != kOk ? rc : transfer_exit_code(r, checked);
    // When the process ends now, its exit frees the states, domains and plans (base/keep.hpp).
    keep_until_exit(r);
    keep_until_exit(in);
    return rc;
}

// Many plans at once: every plan transferred on the same map and problem, one report line (or JSON
// object) per plan in the order given, the worst exit code at the end.

// The plan files --plan names, in order: a file as given, a directory's files by name (hidden
// files left out); nullopt with every error printed.
std::optional<std::vector<std::string>> expand_plans(const std::vector<std::string>& given,
                                                     std::ostream& err) {
    namespace fs = std::filesystem;
    std::vector<std::string> plans;
    bool ok = true;
    for (const auto& g : given) {
        std::error_code ec;
        if (!fs::is_directory(g, ec)) {
            plans.push_back(g); // reading it says what is wrong with it
            continue;
        }
        std::vector<std::string> files;
        for (auto it = fs::directory_iterator(g, ec); !ec && it != fs::directory_iterator();
             it.increment(ec)) {
            std::error_code kind;
            std::string name = it->path().filename().string();
            if (it->is_regular_file(kind) && !name.empty() && name.front() != '.') {
                files.push_back(it->path().string());
            }
        }
        if (ec || files.empty()) {
            error(err, ec ? fmt::format("cannot read the directory '{}': {}", g, ec.message())
                          : fmt::format("the directory '{}' holds no plan file", g));
            ok = false;
        }
        std::sort(files.begin(), files.end());
        plans.insert(plans.end(), files.begin(), files.end());
    }
    return ok ? std::optional(std::move(plans)) : std::nullopt;
}

bool is_batch(const TransferCommandArgs& a) {
    std::error_code ec;
    return a.plans.size() > 1 || a.format == "jsonl" ||
           std::filesystem::is_directory(a.plans.front(), ec);
}

// What one plan of a batch gave.
struct PlanResult {
    int rc = kOk;
    std::string json;        // its report as one line of JSON (json and jsonl)
    std::string line;        // its report line (text)
    std::string target_plan; // with PDDL inputs: the target IPC plan
    std::string diagnostics; // what loading it printed
};

std::string summary_line(const std::string& path, const TransferInputs& in, const Outcome& r) {
    const auto& v = r.t.verdict;
    std::string o =
        fmt::format("{}: {}; {} -> {}; goal satisfaction {}\n", path, v.summary(),
                    step_count(in.plan.steps.size()),
                    step_count(transfer::target_plan(r.t.steps).size()), percent(v.goal));
    if (r.replan) {
        o += fmt::format("  replanning: {}{}\n", plan::to_string(r.replan->search.status),
                         r.replan->search.plan ? ", " + step_count(r.replan->steps.size()) : "");
    }
    return o;
}

PlanResult transfer_one(const TransferCommandArgs& a, Session& s, TransferInputs in,
                        const std::string& path) {
    PlanResult p;
    std::ostringstream diag;
    if (!load_transfer_plan(s, in, path, diag)) {
        p.rc = kBadInput;
        p.diagnostics = diag.str();
        p.json = json::dump(nlohmann::ordered_json{
            {"plan_file", path}, {"exit_code", p.rc}, {"errors", p.diagnostics}});
        p.line = fmt::format("{}: not read (exit 2): the errors are on stderr\n", path);
        return p;
    }
    Outcome r = run_transfer(a, in, diag);
    int checked = kOk;
    PddlChecks checks;
    if (in.pddl) {
        std::vector<OutputText> none; // a batch takes no --problem-output
        checked = finish_pddl_transfer(in, a.in, r.t, p.target_plan, checks, none);
    }
    p.rc = transfer_exit_code(r, checked);
    p.diagnostics = diag.str();
    if (a.format == "text") {
        p.line = summary_line(path, in, r);
        for (std::string_view rest = checks.text; !rest.empty();) {
            auto end = rest.find('\n');
            p.line += fmt::format("  {}\n", rest.substr(0, end));
            rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
        }
    } else {
        nlohmann::ordered_json j = json_report(a, in, r);
        j["plan_file"] = path;
        j["exit_code"] = p.rc;
        if (in.pddl) {
            add_pddl_json(j, p.target_plan, checks);
        }
        p.json = json::dump(j);
    }
    return p;
}

// One loaded copy of the shared inputs per worker thread (parallel.hpp says why).
struct Worker {
    Session s;
    std::optional<TransferInputs> in;
};

// With PDDL inputs, -o names a directory that receives each target plan under its source plan's
// file name; two plans of one name would overwrite each other.
std::optional<std::vector<OutputText>> plan_outputs(const TransferCommandArgs& a,
                                                    const std::vector<std::string>& plans,
                                                    const std::vector<PlanResult>& results,
                                                    std::ostream& err) {
    namespace fs = std::filesystem;
    std::vector<OutputText> outputs;
    std::map<std::string, std::string> taken;
    for (std::size_t i = 0; i < plans.size(); ++i) {
        std::string name = fs::path(plans[i]).filename().string();
        if (auto [it, fresh] = taken.emplace(name, plans[i]); !fresh) {
            error(err, fmt::format("plans '{}' and '{}' have one file name: their target plans "
                                   "would overwrite each other in '{}'",
                                   it->second, plans[i], a.output));
            return std::nullopt;
        }
        if (results[i].rc != kBadInput) {
            outputs.push_back({results[i].target_plan, (fs::path(a.output) / name).string()});
        }
    }
    std::error_code ec;
    fs::create_directories(a.output, ec);
    if (ec) {
        error(err, fmt::format("cannot make the directory '{}': {}", a.output, ec.message()));
        return std::nullopt;
    }
    return outputs;
}

std::string batch_report(const TransferCommandArgs& a, const std::vector<PlanResult>& results) {
    std::string o;
    if (a.format == "json") {
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const auto& p : results) {
            all.push_back(nlohmann::ordered_json::parse(p.json));
        }
        return json::dump(all, 2) + "\n";
    }
    std::array<std::size_t, 3> count{}; // by exit code 0, 1, 2
    for (const auto& p : results) {
        o += a.format == "jsonl" ? p.json + "\n" : p.line;
        ++count[static_cast<std::size_t>(std::min<int>(p.rc, kBadInput))];
    }
    if (a.format == "text") {
        o += fmt::format("{} plans: {} valid, {} invalid, {} not read\n", results.size(),
                         count[kOk], count[kNo], count[kBadInput]);
    }
    return o;
}

int cmd_transfer_batch(const TransferCommandArgs& a, std::ostream& out, std::ostream& err) {
    if (a.trace || !a.in.problem_output.empty()) {
        error(err, fmt::format("{} takes one --plan", a.trace ? "--trace" : "--problem-output"));
        return kBadInput;
    }
    auto plans = expand_plans(a.plans, err);
    if (!plans) {
        return kBadInput;
    }
    std::size_t jobs = std::min(a.jobs != 0 ? a.jobs : default_jobs(), plans->size());
    std::vector<std::unique_ptr<Worker>> workers;
    for (std::size_t w = 0; w < jobs; ++w) {
        workers.push_back(std::make_unique<Worker>());
    }
    // The shared inputs' errors are printed once; the other workers load the same files again.
    workers[0]->in = load_transfer_setting(workers[0]->s, a.in, err);
    if (!workers[0]->in) {
        return input_error(workers[0]->s);
    }
    std::vector<PlanResult> results(plans->size());
    parallel_for(plans->size(), jobs, [&](std::size_t k, std::size_t i) {
        Worker& w = *workers[k];
        if (!w.in) {
            std::ostringstream again;
            w.in = load_transfer_setting(w.s, a.in, again);
            CATPLAN_ASSERT(w.in.has_value(), "inputs that loaded once load again");
        }
        results[i] = transfer_one(a, w.s, *w.in, (*plans)[i]);
    });
    int worst = kOk;
    for (const auto& p : results) {
        err << p.diagnostics;
        worst = std::max(worst, p.rc);
    }
    std::vector<OutputText> outputs{{batch_report(a, results), ""}};
    if (workers[0]->in->pddl && !a.output.empty()) {
        auto files = plan_outputs(a, *plans, results, err);
        if (!files) {
            return kBadInput;
        }
        outputs.insert(outputs.end(), files->begin(), files->end());
    } else {
        outputs.front().path = a.output;
    }
    int rc = emit(outputs, out, err);
    return rc != kOk ? rc : worst;
}

} // namespace

void add_transfer_commands(CLI::App& app, CommandTable& table) {
    auto a = std::make_shared<TransferCommandArgs>();
    auto* cmd = app.add_subcommand(
        "transfer", "Transfer a plan along an ontology map and validate it in the target domain "
                    "(exit 1 when the transferred plan is invalid)");
    add_transfer_input_options(cmd, a->in, &a->plans);
    cmd->add_flag("--trace", a->trace, "print every target state as tables");
    add_trajectory_options(cmd, a->in);
    cmd->add_option("--format", a->format,
                    "text, json, or jsonl (JSON Lines: one object per plan, for many plans)")
        ->check(CLI::IsMember({"text", "json", "jsonl"}))
        ->capture_default_str();
    cmd->add_option("--jobs", a->jobs, "with many plans: worker threads (default: one per core)")
        ->check(CLI::PositiveNumber);
    add_replan_options(cmd, a->in,
                       "also plan from scratch in the target domain and compare (paper Metric 5)");
    cmd->add_option("-o,--output", a->output,
                    "write the report to this file (with a PDDL problem: the target IPC plan; "
                    "with many plans and a PDDL problem: a directory for the target plans, each "
                    "named as its source plan)");
    cmd->add_option("--problem-output", a->in.problem_output,
                    "with a PDDL problem: write the target problem (Δ_F of its initial state and "
                    "goal) as PDDL to this file");
    cmd->add_option("--target-problem", a->in.target_problem,
                    "with a PDDL problem: the target's own PDDL problem, whose initial state must "
                    "be Δ_F of the source's and whose goal is the intended goal");
    cmd->add_flag("--no-timing", a->no_timing, "leave out times and memory (reproducible output)");
    table.add(cmd, [a](std::ostream& o, std::ostream& e) {
        return is_batch(*a) ? cmd_transfer_batch(*a, o, e) : cmd_transfer(*a, o, e);
    });
}

} // namespace catplan::cli
