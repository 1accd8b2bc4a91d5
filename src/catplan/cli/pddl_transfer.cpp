// `catplan transfer` with PDDL inputs (pddl_transfer.hpp).

#include "catplan/cli/pddl_transfer.hpp"

#include "catplan/cli/commands.hpp"
#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/steps.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <iterator>
#include <string_view>

namespace catplan::cli {
namespace {

/// A file's id in the session's sources; nullopt with the error printed.
std::optional<std::uint32_t> read_file(Session& s, const std::string& file, std::ostream& err) {
    auto f = s.sources.add_file(file);
    if (!f) {
        error(err, fmt::format("cannot read '{}'", file));
        return std::nullopt;
    }
    return *f;
}

/// Whether Δ_F(I) is the user's target initial state, and the differences, in words and in JSON.
void word_comparison(const pddl_transfer::Comparison& c, PddlChecks& out) {
    out.json["target_problem"] = {{"name", c.name},
                                  {"initial_is_migrated", c.same()},
                                  {"only_in_migrated", c.only_in_migrated},
                                  {"only_in_target_problem", c.only_in_target_problem}};
    if (c.same()) {
        out.text += fmt::format("target problem {}: its initial state is Δ_F(I)\n", c.name);
        return;
    }
    out.text += fmt::format("target problem {}: its initial state is not Δ_F(I)\n", c.name);
    if (!c.only_in_migrated.empty()) {
        out.text += fmt::format("  only in Δ_F(I): {}\n", fmt::join(c.only_in_migrated, ", "));
    }
    if (!c.only_in_target_problem.empty()) {
        out.text +=
            fmt::format("  only in {}: {}\n", c.name, fmt::join(c.only_in_target_problem, ", "));
    }
}

/// A plan's cost for --format json: the total and whether every action costs 1, or why it is
/// undefined.
nlohmann::ordered_json cost_json(const pddl::PlanCost& cost) {
    if (!cost.undefined.empty()) {
        return {{"total", nullptr}, {"undefined", cost.undefined}};
    }
    return {{"total", cost.total}, {"unit_cost", cost.unit}};
}

/// The PDDL validator's verdict and what it left out, in words and in JSON.
void word_validation(const pddl_transfer::Setting& st, const pddl_transfer::Checks& c,
                     PddlChecks& out) {
    std::size_t unwritten = c.unwritten_goal_conditions;
    if (unwritten > 0) {
        out.text += fmt::format("note: {} condition{} of Δ_F(G) forbid{} several facts "
                                "together, which a PDDL goal cannot say: the PDDL check below "
                                "leaves {} out (the verdict above checks {})\n",
                                unwritten, unwritten == 1 ? "" : "s", unwritten == 1 ? "s" : "",
                                unwritten == 1 ? "it" : "them", unwritten == 1 ? "it" : "them");
    }
    const auto& v = *c.validation;
    out.text += fmt::format("target plan checked by catplan's PDDL validator on {} and "
                            "Δ_F(I), Δ_F(G): {}\n",
                            st.target->pddl_domain.name,
                            v.valid ? std::string("valid") : "invalid: " + v.reason);
    out.json["pddl_check"] = {
        {"domain", st.target->pddl_domain.name},
        {"valid", v.valid},
        {"reason", v.valid ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v.reason)},
        {"goal_conditions_left_out", unwritten}};
}

} // namespace

bool is_pddl_problem(const std::string& problem) {
    return problem.size() > 5 && problem.compare(problem.size() - 5, 5, ".pddl") == 0;
}

std::optional<TransferInputs> load_pddl_transfer_inputs(Session& s, const lang::Module& m,
                                                        TransferInputs in, const TransferArgs& a,
                                                        std::ostream& err) {
    auto problem = read_file(s, a.problem, err);
    std::optional<std::uint32_t> target_problem;
    if (!problem ||
        (!a.target_problem.empty() && !(target_problem = read_file(s, a.target_problem, err)))) {
        return std::nullopt;
    }
    auto setting =
        pddl_transfer::load_setting(m, *m.find(a.map), *problem, target_problem, s.sources, s.sink);
    if (report(s, err) || !setting) {
        return std::nullopt;
    }
    in.problem = setting->source->problem;
    if (in.target_goal == nullptr) {
        in.target_goal = setting->target_goal;
        in.target_goal_conditions = setting->target_goal_conditions;
    }
    auto pt = std::make_shared<PddlTransfer>();
    pt->setting = std::make_shared<const pddl_transfer::Setting>(std::move(*setting));
    in.pddl = std::move(pt);
    return in;
}

bool load_ipc_plan(Session& s, TransferInputs& in, const std::string& path, std::ostream& err) {
    auto f = read_input(s, path, err);
    if (!f) {
        return false;
    }
    auto plan = pddl_transfer::read_plan(*in.pddl->setting, *f, s.sources, s.sink);
    if (report(s, err) || !plan) {
        return false;
    }
    // The setting is shared by every plan of a batch: each plan has its own PddlTransfer.
    auto pt = std::make_shared<PddlTransfer>(*in.pddl);
    pt->plan = std::move(*plan);
    in.plan = pddl_transfer::source_plan(*pt->setting, pt->plan);
    in.pddl = std::move(pt);
    return true;
}

namespace {

// A repair's cost where the target's costs are known, and whether it is the least of any plan of
// the focus (or whole state) searched: "; cost 3, the least on a focus of 5 parts".
std::string repair_cost_text(const transfer::StepTransfer& step) {
    if (!step.repair_cost) {
        return "";
    }
    if (!step.repair_least_cost) {
        return fmt::format("; cost {}", *step.repair_cost);
    }
    return fmt::format("; cost {}, the least {}", *step.repair_cost,
                       step.repair_focus > 0
                           ? fmt::format("on a focus of {} parts", step.repair_focus)
                           : std::string("from the state before it"));
}

// Pads the line that starts at `start` of o with spaces to `width` columns, as fmt's {:<width}
// does: an ASCII line by its bytes, any other as fmt measures it (by code points).
void pad_line(std::string& o, std::size_t start, std::size_t width) {
    std::string_view line(o.data() + start, o.size() - start);
    bool ascii = std::all_of(line.begin(), line.end(),
                             [](char c) { return static_cast<unsigned char>(c) < 0x80; });
    if (!ascii) {
        std::string padded = fmt::format("{:<{}}", line, width);
        o.resize(start);
        o += padded;
    } else if (line.size() < width) {
        o.append(width - line.size(), ' ');
    }
}

} // namespace

std::string pddl_steps_text(const TransferInputs& in, const transfer::TransferResult& t,
                            const PddlChecks& checks) {
    const auto& pt = *in.pddl;
    const auto& st = *pt.setting;
    std::size_t total = 0;
    for (const auto& step : t.steps) {
        total += step.target_steps.size();
    }
    const auto* ipc = checks.target_plan ? &*checks.target_plan : nullptr;
    if (ipc != nullptr && ipc->size() != total) {
        ipc = nullptr;
    }
    std::string o;
    auto out = std::back_inserter(o);
    std::size_t n = 0;
    for (std::size_t i = 0; i < t.steps.size(); ++i) {
        const auto& step = t.steps[i];
        std::string from = fmt::format("step {} {}", i + 1, pt.plan[i].to_string());
        std::string how;
        switch (step.kind) {
        case transfer::StepTransfer::Kind::Generated:
            how = "its migrated action";
            break;
        case transfer::StepTransfer::Kind::Corresponds:
            how = fmt::format("{} is Δ_F({}) (the same action)",
                              st.actions->name_of(step.target.action),
                              st.source->action_of(step.source.action));
            break;
        case transfer::StepTransfer::Kind::Repaired:
            how = fmt::format(
                "repaired: {} step{} ({}{})", step.target_steps.size(),
                step.target_steps.size() == 1 ? "" : "s",
                step.repair_reused_from
                    ? fmt::format("step {}'s repair, renamed", *step.repair_reused_from + 1)
                    : fmt::format(
                          "{}{} state{} expanded",
                          step.repair_from_action ? "from its migrated action's sides, " : "",
                          step.repair_stats.expanded, step.repair_stats.expanded == 1 ? "" : "s"),
                repair_cost_text(step));
            break;
        }
        if (step.target_steps.empty()) {
            fmt::format_to(out, "  -  {}: {}, none needed (the target state holds what it made)\n",
                           from, how);
            continue;
        }
        for (std::size_t k = 0; k < step.target_steps.size(); ++k) {
            std::string text = ipc != nullptr ? (*ipc)[n].to_string()
                                              : pddl_transfer::ipc_text(st, step.target_steps[k]);
            std::size_t start = o.size();
            o += "  ";
            o += std::to_string(++n);
            o += ". ";
            o += text;
            if (k == 0) {
                pad_line(o, start, 32);
                o += " <- ";
                o += from;
                o += ": ";
                o += how;
            }
            o += '\n';
        }
    }
    return o;
}

int finish_pddl_transfer(const TransferInputs& in, const TransferArgs& a,
                         const transfer::TransferResult& t, std::string& plan_text,
                         PddlChecks& checks, std::vector<OutputText>& outputs) {
    const auto& st = *in.pddl->setting;
    auto c = pddl_transfer::check(st, in.pddl->plan, t);
    plan_text = c.plan_text;
    checks.target_plan = std::move(c.target_plan);
    if (c.source_cost) {
        checks.text += "source plan cost: " + pddl::describe_cost(*c.source_cost) + "\n";
        checks.json["source_cost"] = cost_json(*c.source_cost);
    }
    if (!c.validation) {
        return kOk;
    }
    if (c.comparison) {
        word_comparison(*c.comparison, checks);
    }
    if (!st.target_problem && !st.uncarried_values.empty()) {
        checks.text +=
            fmt::format("note: {} value(s) of the source problem the map's functions "
                        "section names are not carried: {} (an argument is no "
                        "object of Δ_F(I) of the target function's type)\n",
                        st.uncarried_values.size(), fmt::join(st.uncarried_values, ", "));
        checks.json["uncarried_values"] = st.uncarried_values;
    }
    if (c.target_cost) {
        checks.text += "target plan cost: " + pddl::describe_cost(*c.target_cost) +
                       (c.target_cost->undefined.empty() || st.target_problem
                            ? ""
                            : " (--target-problem, or the map's functions section, gives the "
                              "target's values)");
        checks.json["target_cost"] = cost_json(*c.target_cost);
        // A transfer that stopped has a target plan only of the steps before it.
        if (const auto* stop = t.verdict.failed_step(); stop != nullptr && stop->step) {
            checks.text += fmt::format(", of the steps carried out before step {}, where the "
                                       "transfer stopped",
                                       *stop->step + 1);
            checks.json["target_cost"]["stopped_at_step"] = *stop->step + 1;
        }
        checks.text += "\n";
    }
    word_validation(st, c, checks);
    if (!a.problem_output.empty()) {
        outputs.push_back({pddl::write_problem(*c.migrated), a.problem_output});
    }
    return c.ok(t) ? kOk : kNo;
}

} // namespace catplan::cli
