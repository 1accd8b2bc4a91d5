#include "catplan/plan/actions.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::plan {

std::vector<const Rule*> action_rules(const Domain& d, std::string_view name) {
    std::vector<const Rule*> out;
    for (const auto& r : d.rules) {
        if (r->action_name() == name) {
            out.push_back(r.get());
        }
    }
    return out;
}

bool has_actions(const Domain& d) {
    return std::any_of(d.rules.begin(), d.rules.end(),
                       [](const RulePtr& r) { return r->action.has_value(); });
}

std::optional<Step> rule_step(const Rule& r, const Step& action_step) {
    if (!r.action) {
        return action_step.args.size() == r.parameters.size() ? std::optional(action_step)
                                                              : std::nullopt;
    }
    const auto& arguments = r.action->arguments;
    if (action_step.args.size() != arguments.size()) {
        return std::nullopt;
    }
    Step out{r.name, std::vector<std::string>(r.parameters.size()), action_step.range};
    bool located = action_step.arg_ranges.size() == arguments.size();
    if (located) {
        out.arg_ranges.resize(r.parameters.size());
    }
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& arg = action_step.args[i];
        if (arguments[i].parameter < 0) {
            if (arg != arguments[i].constant) {
                return std::nullopt;
            }
            continue;
        }
        auto p = static_cast<std::size_t>(arguments[i].parameter);
        if (!out.args[p].empty() && out.args[p] != arg) {
            return std::nullopt;
        }
        if (out.args[p].empty() && located) {
            out.arg_ranges[p] = action_step.arg_ranges[i];
        }
        out.args[p] = arg;
    }
    return out;
}

Step action_step(const Rule& r, const Step& rule_step) {
    if (!r.action) {
        return rule_step;
    }
    Step out{r.action->name, {}, rule_step.range};
    bool located = rule_step.arg_ranges.size() == rule_step.args.size();
    for (const auto& a : r.action->arguments) {
        auto p = static_cast<std::size_t>(a.parameter);
        out.args.push_back(a.parameter < 0 ? a.constant : rule_step.args.at(p));
        if (located) {
            out.arg_ranges.push_back(a.parameter < 0 ? rule_step.range : rule_step.arg_ranges[p]);
        }
    }
    return out;
}

Step action_step(const Domain& d, const Step& rule_step) {
    const Rule* r = d.find_rule(rule_step.action);
    return r != nullptr && r->parameters.size() == rule_step.args.size()
               ? action_step(*r, rule_step)
               : rule_step;
}

std::string describe_step(const Domain& d, const Step& rule_step) {
    Step a = action_step(d, rule_step);
    if (a.action == rule_step.action && a.args == rule_step.args) {
        return rule_step.to_string();
    }
    return fmt::format("{} (rule {})", a.to_string(), rule_step.action);
}

Plan action_plan(const Domain& d, const Plan& plan) {
    Plan out;
    for (const auto& s : plan.steps) {
        out.steps.push_back(action_step(d, s));
    }
    return out;
}

Result<Step> apply_action_step(const Domain& d, ACSet& x, const Step& action_step) {
    std::string why =
        fmt::format("no rule of the action {} fits the arguments", action_step.action);
    for (const Rule* r : action_rules(d, action_step.action)) {
        auto step = rule_step(*r, action_step);
        if (!step) {
            continue;
        }
        auto m = resolve_step(*r, x, *step);
        if (!m) {
            why = m.error();
            continue;
        }
        auto applied = rewrite::rewrite_in_place(*r, x, *m);
        CATPLAN_ASSERT(applied.has_value(), "a resolved match applies");
        return *step;
    }
    return fail(std::move(why));
}

Plan rule_plan(const Domain& d, const ACSet& initial, const Plan& plan) {
    if (!has_actions(d)) {
        return plan;
    }
    Plan out;
    ACSet x = initial;
    bool replaying = true;
    for (const auto& s : plan.steps) {
        if (replaying) {
            if (auto applied = apply_action_step(d, x, s)) {
                out.steps.push_back(std::move(*applied));
                continue;
            }
        }
        // Not replayed: the first rule the arguments fit, or a rule by its own name.
        std::optional<Step> fits;
        for (const Rule* r : action_rules(d, s.action)) {
            fits = rule_step(*r, s);
            if (fits) {
                break;
            }
        }
        const Rule* named = fits ? nullptr : d.find_rule(s.action);
        if (named != nullptr && replaying && named->parameters.size() == s.args.size()) {
            auto m = resolve_step(*named, x, s);
            if (m && rewrite::rewrite_in_place(*named, x, *m)) {
                out.steps.push_back(s);
                continue;
            }
        }
        replaying = false;
        out.steps.push_back(fits ? *fits : s);
    }
    return out;
}

} // namespace catplan::plan
