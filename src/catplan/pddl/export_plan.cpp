// Plans between catplan and an export: a catplan plan in the export's objects and actions, and an
// IPC plan of the export back as a catplan plan (export.hpp).

#include "catplan/base/ascii.hpp"
#include "catplan/pddl/detail/export_writer.hpp"
#include "catplan/pddl/export.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::pddl {

namespace {

using detail::NameSet;
using detail::Things;

/// The reading and marker shapes of the export's domain and problem.
Result<std::unique_ptr<detail::Writer>> writer_for(const Exported& ex) {
    if (ex.source == nullptr || ex.domain_ptr == nullptr) {
        return fail("the export has no problem");
    }
    NameSet preds;
    auto rd = detail::read_schema(*ex.domain_ptr, ex.source.get(), preds);
    if (!rd) {
        return fail(rd.error());
    }
    auto w = std::make_unique<detail::Writer>(*ex.domain_ptr, ex.source.get(), std::move(*rd),
                                              std::move(preds));
    if (auto ok = w->find_marker_shapes(); !ok) {
        return fail(ok.error());
    }
    return w;
}

/// The export's name of the thing that part p of ob belongs to in x.
Result<std::string> object_name(const detail::Writer& w, const acset::ACSet& x, ObId ob, Part p,
                                const std::string& step) {
    NameSet names;
    auto things = detail::find_things(w.rd, x, w.marker_shapes, names, "a state of the plan");
    if (!things) {
        return fail(things.error());
    }
    const auto& t = things->things[things->at(ob, p)];
    if (t.marker) {
        return fail(fmt::format("{} binds the {} marker, which the export does not express", step,
                                t.shape));
    }
    return ascii_lowercase(t.name);
}

const Exported::Action* find_action(const Exported& ex, std::string_view name) {
    for (const auto& a : ex.actions) {
        if (ascii_lowercase(a.name) == ascii_lowercase(name)) {
            return &a;
        }
    }
    return nullptr;
}

/// The plan with each step's arguments per parameter: a step of a migrated rule may name each
/// parameter name once (as a transfer prints it: `unstack(E, D)` for the rule's parameters block,
/// block, underblock, underblock, one per target object).
plan::Plan per_parameter(const plan::Domain& d, plan::Plan plan) {
    for (auto& step : plan.steps) {
        const auto* rule = d.find_rule(step.action);
        if (rule == nullptr || step.args.size() == rule->parameters.size()) {
            continue;
        }
        std::vector<std::string> names;
        for (const auto& p : rule->parameters) {
            if (std::find(names.begin(), names.end(), p.name) == names.end()) {
                names.push_back(p.name);
            }
        }
        if (names.size() != step.args.size()) {
            continue; // validation says what is wrong
        }
        std::vector<std::string> args;
        for (const auto& p : rule->parameters) {
            args.push_back(step.args[static_cast<std::size_t>(
                std::find(names.begin(), names.end(), p.name) - names.begin())]);
        }
        step.args = std::move(args);
        step.arg_ranges.clear();
    }
    return plan;
}

} // namespace

namespace {

/// Whether m sends L's kept things to objects and its deleted things to markers: the matches the
/// export expresses.
bool expressed(const detail::Writer& w, const rewrite::Rule& rule, const Things& xt,
               const hom::ACSetMorphism& m) {
    NameSet scratch;
    auto L = detail::find_things(w.rd, rule.L, {}, scratch, rule.name);
    if (!L) {
        return false;
    }
    for (const auto& t : L->things) {
        bool deleted =
            std::find(rule.l.components[t.first.index()].begin(),
                      rule.l.components[t.first.index()].end(),
                      t.part[t.first.index()]) == rule.l.components[t.first.index()].end();
        const auto& image = xt.things[xt.at(t.first, m(t.first, t.part[t.first.index()]))];
        if (image.marker != deleted) {
            return false;
        }
    }
    return true;
}

} // namespace

Result<ExportedReplay> replay_exported(const Exported& ex, const plan::Plan& given) {
    auto w = writer_for(ex);
    if (!w) {
        return fail(w.error());
    }
    plan::Plan plan = per_parameter(*ex.domain_ptr, given);
    ExportedReplay out;
    acset::ACSet x = *ex.source->initial;
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const auto& step = plan.steps[i];
        std::string where = fmt::format("step {} {}", i + 1, step.to_string());
        const auto* rule = ex.domain_ptr->find_rule(step.action);
        if (rule == nullptr || step.args.size() != rule->parameters.size()) {
            return fail(fmt::format(
                "{}: {}", where, rule == nullptr ? "no such action" : "wrong number of arguments"));
        }
        rewrite::MatchOptions opt;
        for (std::size_t j = 0; j < step.args.size(); ++j) {
            const auto& p = rule->parameters[j];
            auto part = x.find_part(p.ob, step.args[j]);
            if (!part) {
                return fail(fmt::format("{}: no {} named '{}'", where, x.schema().ob(p.ob).name,
                                        step.args[j]));
            }
            opt.initial.push_back({p.ob, p.part, *part});
        }
        NameSet names;
        auto xt = detail::find_things((*w)->rd, x, (*w)->marker_shapes, names, where);
        if (!xt) {
            return fail(xt.error());
        }
        auto matches = rewrite::find_matches(*rule, x, opt);
        std::erase_if(matches, [&](const auto& m) { return !expressed(**w, *rule, *xt, m); });
        if (matches.empty()) {
            return fail(fmt::format("{}: no match that the export expresses", where));
        }
        out.states.push_back(x);
        auto applied = rewrite::rewrite_in_place(*rule, x, matches[0]);
        if (!applied) {
            return fail(fmt::format("{}: {}", where, applied.error()));
        }
        out.matches.push_back(std::move(matches[0]));
        out.plan.steps.push_back(step);
    }
    auto g = plan::embed_goal(*ex.source->goal, x);
    if (!g) {
        return fail(fmt::format("goal not reached: {}", g.error()));
    }
    out.goal = std::move(*g);
    out.states.push_back(std::move(x));
    return out;
}

Result<IpcPlan> to_exported_plan(const Exported& ex, const plan::Plan& given) {
    auto w = writer_for(ex);
    auto r = replay_exported(ex, given);
    if (!w || !r) {
        return fail(w ? r.error() : w.error());
    }
    const plan::Plan& plan = r->plan;
    IpcPlan out;
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const auto& step = plan.steps[i];
        std::string base = step.action.substr(0, step.action.find('~'));
        const auto* a = find_action(ex, detail::pddl_name(base, "a"));
        if (a == nullptr || a->rule == nullptr) {
            return fail(fmt::format("step {} {}: the export has no one-rule action for it", i + 1,
                                    step.to_string()));
        }
        IpcStep s{ascii_lowercase(a->name), {}, {}};
        for (auto [ob, p] : a->params) {
            auto name = object_name(**w, r->states[i], ob, r->matches[i](ob, p),
                                    fmt::format("step {} {}", i + 1, step.to_string()));
            if (!name) {
                return fail(name.error());
            }
            s.args.push_back(*name);
        }
        out.push_back(std::move(s));
    }
    if (!ex.goal_action.empty()) {
        IpcStep s{ascii_lowercase(ex.goal_action), {}, {}};
        for (auto [ob, p] : ex.goal_params) {
            auto name = object_name(**w, r->states.back(), ob, r->goal(ob, p), "the goal");
            if (!name) {
                return fail(name.error());
            }
            s.args.push_back(*name);
        }
        out.push_back(std::move(s));
    }
    return out;
}

Result<plan::Plan> from_exported_plan(const Exported& ex, const IpcPlan& plan) {
    auto w = writer_for(ex);
    if (!w) {
        return fail(w.error());
    }
    NameSet names;
    const acset::ACSet& x = *ex.source->initial;
    auto things = detail::find_things((*w)->rd, x, (*w)->marker_shapes, names, "the initial state");
    if (!things) {
        return fail(things.error());
    }
    std::map<std::string, std::size_t> by_name;
    for (std::size_t i = 0; i < things->things.size(); ++i) {
        if (!things->things[i].marker) {
            by_name[ascii_lowercase(things->things[i].name)] = i;
        }
    }
    plan::Plan out;
    for (std::size_t i = 0; i < plan.size(); ++i) {
        const IpcStep& s = plan[i];
        if (!ex.goal_action.empty() &&
            ascii_lowercase(s.action) == ascii_lowercase(ex.goal_action)) {
            if (i + 1 != plan.size()) {
                return fail(fmt::format("step {} {}: the goal action is not the last step", i + 1,
                                        s.to_string()));
            }
            break;
        }
        const auto* a = find_action(ex, s.action);
        if (a == nullptr || a->rule == nullptr || s.args.size() != a->params.size()) {
            return fail(fmt::format("step {} {}: {}", i + 1, s.to_string(),
                                    a == nullptr ? "no such action in the export"
                                    : a->rule == nullptr
                                        ? "an action of several rules (read it with the PDDL "
                                          "import instead)"
                                        : "wrong number of arguments"));
        }
        NameSet scratch;
        auto L = detail::find_things((*w)->rd, a->rule->L, {}, scratch, a->rule->name);
        if (!L) {
            return fail(L.error());
        }
        plan::Step step{a->rule->name, {}, {}};
        for (const auto& param : a->rule->parameters) {
            std::size_t thing = L->at(param.ob, param.part);
            if (thing == Things::kNoThing) {
                return fail(fmt::format("step {} {}: the parameter {} is a fact, which the export "
                                        "does not name",
                                        i + 1, s.to_string(), param.name));
            }
            std::optional<std::size_t> index;
            for (std::size_t j = 0; j < a->params.size(); ++j) {
                if (L->at(a->params[j].first, a->params[j].second) == thing) {
                    index = j;
                }
            }
            auto it = index ? by_name.find(ascii_lowercase(s.args[*index])) : by_name.end();
            Part part =
                it == by_name.end() ? kNoPart : things->things[it->second].part[param.ob.index()];
            if (part == kNoPart || x.part_name(param.ob, part).empty()) {
                return fail(fmt::format("step {} {}: no named {} for the parameter {}", i + 1,
                                        s.to_string(), x.schema().ob(param.ob).name, param.name));
            }
            step.args.emplace_back(x.part_name(param.ob, part));
        }
        out.steps.push_back(std::move(step));
    }
    return out;
}

} // namespace catplan::pddl
