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

namespace {

// The rules of a step's action whose arguments fit: the first such step, and whether another fits.
struct Fits {
    std::optional<Step> first;
    bool several = false;
};

Fits fits_of(const Domain& d, const Step& s) {
    Fits out;
    for (const Rule* r : action_rules(d, s.action)) {
        if (auto step = rule_step(*r, s)) {
            if (out.first) {
                out.several = true;
                break;
            }
            out.first = std::move(step);
        }
    }
    return out;
}

// rule_plan's replay: x and whether it still replays, advanced by one step of the plan.
class Replay {
public:
    Replay(const Domain& d, const ACSet& initial) : d_(d), x_(initial) {}

    // The rule step s is: the first rule of its action that applies, else the first its
    // arguments fit, else s as written (see rule_plan).
    Step advance(const Step& s) {
        if (replaying_) {
            if (auto applied = apply_action_step(d_, x_, s)) {
                return std::move(*applied);
            }
        }
        Fits fits = fits_of(d_, s);
        const Rule* named = fits.first ? nullptr : d_.find_rule(s.action);
        if (named != nullptr && replaying_ && named->parameters.size() == s.args.size()) {
            auto m = resolve_step(*named, x_, s);
            if (m && rewrite::rewrite_in_place(*named, x_, *m)) {
                return s;
            }
        }
        replaying_ = false;
        if (fits.first) {
            return std::move(*fits.first);
        }
        return s;
    }

private:
    const Domain& d_;
    ACSet x_;
    bool replaying_ = true;
};

} // namespace

Plan rule_plan(const Domain& d, const ACSet& initial, const Plan& plan) {
    if (!has_actions(d)) {
        return plan;
    }
    // A step that at most one rule fits is that rule's step whatever the state: the plan is
    // replayed (lazily, from where it stopped) only for a step that several rules fit.
    Plan out;
    std::optional<Replay> replay;
    std::size_t replayed = 0;
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const Step& s = plan.steps[i];
        Fits fits = fits_of(d, s);
        if (!fits.several) {
            if (fits.first) {
                out.steps.push_back(std::move(*fits.first));
            } else {
                out.steps.push_back(s);
            }
            continue;
        }
        if (!replay) {
            replay.emplace(d, initial);
        }
        for (; replayed < i; ++replayed) {
            replay->advance(plan.steps[replayed]);
        }
        out.steps.push_back(replay->advance(s));
        replayed = i + 1;
    }
    return out;
}

} // namespace catplan::plan
