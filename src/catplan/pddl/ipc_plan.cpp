#include "catplan/pddl/ipc_plan.hpp"

#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <cctype>
#include <fmt/format.h>

namespace catplan::pddl {

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (auto& c : out) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

/// One line's step `(name args...)` between `open` and its `)`; nullopt after an error.
std::optional<IpcStep> parse_step(std::string_view line, std::size_t open, std::uint32_t file,
                                  std::uint32_t line_start, DiagnosticSink& sink) {
    std::size_t close = line.find(')', open);
    auto at = [&](std::size_t b, std::size_t e) {
        return SourceRange{file, static_cast<std::uint32_t>(line_start + b),
                           static_cast<std::uint32_t>(line_start + e)};
    };
    if (close == std::string_view::npos) {
        sink.error(at(open, open + 1), "unbalanced parentheses: this '(' is never closed");
        return std::nullopt;
    }
    if (line.find('(', open + 1) < close) {
        sink.error(at(open, close + 1), "expected a ground action '(name object ...)'");
        return std::nullopt;
    }
    IpcStep step;
    step.range = at(open, close + 1);
    std::size_t i = open + 1;
    while (i < close) {
        while (i < close && std::isspace(static_cast<unsigned char>(line[i]))) {
            ++i;
        }
        std::size_t b = i;
        while (i < close && !std::isspace(static_cast<unsigned char>(line[i]))) {
            ++i;
        }
        if (b < i) {
            (step.action.empty() ? step.action : step.args.emplace_back()) =
                lower(line.substr(b, i - b));
        }
    }
    if (step.action.empty()) {
        sink.error(step.range, "expected an action name in '()'");
        return std::nullopt;
    }
    return step;
}

/// The variant of `av` the step's arguments are consistent with, as a rule-level step.
std::optional<plan::Step> rule_step(const Variant& v, const IpcStep& s) {
    plan::Step step{v.rule->name, std::vector<std::string>(v.rule->parameters.size()), s.range};
    for (std::size_t i = 0; i < s.args.size(); ++i) {
        if (v.param_of[i] < 0) {
            if (s.args[i] != v.constant_of[i]) {
                return std::nullopt;
            }
            continue;
        }
        auto& slot = step.args[static_cast<std::size_t>(v.param_of[i])];
        if (!slot.empty() && slot != s.args[i]) {
            return std::nullopt;
        }
        slot = s.args[i];
    }
    return step;
}

/// The action's atom with the step's arguments in place of its parameters.
Atom ground(const Action& a, const Atom& atom, const IpcStep& s) {
    Atom g = atom;
    for (auto& t : g.args) {
        for (std::size_t i = 0; t.variable && i < a.params.size(); ++i) {
            if (a.params[i].name == t.name) {
                t = Term{s.args[i], false, t.range};
            }
        }
    }
    return g;
}

/// Why a step cannot apply in PDDL terms (arity, objects, types, the first false
/// precondition), or nullopt when its precondition holds.
std::optional<std::string> pddl_problem(const Import& im, const acset::ACSet& x, const Action& a,
                                        const IpcStep& s) {
    if (s.args.size() != a.params.size()) {
        return fmt::format("'{}' takes {} argument{}, got {}", a.name, a.params.size(),
                           a.params.size() == 1 ? "" : "s", s.args.size());
    }
    for (std::size_t i = 0; i < s.args.size(); ++i) {
        const TypedName* o = find_object(im.pddl_domain, *im.pddl_problem, s.args[i]);
        if (o == nullptr) {
            return fmt::format("unknown object '{}'", s.args[i]);
        }
        if (!im.pddl_domain.is_subtype(o->type, a.params[i].type)) {
            return fmt::format("argument {} (?{}) must be a {}, and '{}' is a {}", i + 1,
                               a.params[i].name, a.params[i].type, o->name, o->type);
        }
    }
    for (const auto& l : a.precondition) {
        Atom g = ground(a, l.atom, s);
        bool h = g.predicate == "=" ? g.args[0].name == g.args[1].name : holds(im, x, g);
        if (h != l.positive) {
            return fmt::format("precondition {} does not hold",
                               Literal{g, l.positive, {}}.to_string());
        }
    }
    return std::nullopt;
}

} // namespace

std::string IpcStep::to_string() const {
    std::string s = "(" + action;
    for (const auto& a : args) {
        s += " " + a;
    }
    return s + ")";
}

std::optional<IpcPlan> parse_ipc_plan(std::uint32_t file, const SourceManager& sources,
                                      DiagnosticSink& sink) {
    std::string_view text = sources.text(file);
    IpcPlan plan;
    bool ok = true;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        line = line.substr(0, std::min(line.find(';'), line.size()));
        std::size_t open = line.find('(');
        std::size_t first = line.find_first_not_of(" \t\r");
        if (open != std::string_view::npos) {
            // Anything before '(' must be a time stamp `0.000:`; after ')', a duration `[1]`.
            auto step = parse_step(line, open, file, static_cast<std::uint32_t>(start), sink);
            ok = ok && step.has_value();
            if (step) {
                plan.push_back(std::move(*step));
            }
        } else if (first != std::string_view::npos) {
            sink.error(SourceRange{file, static_cast<std::uint32_t>(start + first),
                                   static_cast<std::uint32_t>(end)},
                       "expected a ground action '(name object ...)'");
            ok = false;
        }
        start = end + 1;
    }
    return ok ? std::optional(plan) : std::nullopt;
}

std::string write_ipc_plan(const IpcPlan& plan) {
    std::string out;
    for (const auto& s : plan) {
        out += s.to_string() + "\n";
    }
    return out + fmt::format("; cost = {} (unit cost)\n", plan.size());
}

Result<IpcPlan> to_ipc_plan(const Import& import, const plan::Plan& plan) {
    IpcPlan out;
    for (const auto& step : plan.steps) {
        auto found = import.find_rule(step.action);
        if (!found) {
            return fail(fmt::format("'{}' is not a rule of the imported domain", step.action));
        }
        const Variant& v = *found->second;
        IpcStep s{found->first->action, {}, {}};
        for (std::size_t i = 0; i < v.param_of.size(); ++i) {
            s.args.push_back(v.param_of[i] < 0
                                 ? v.constant_of[i]
                                 : step.args[static_cast<std::size_t>(v.param_of[i])]);
        }
        out.push_back(std::move(s));
    }
    return out;
}

bool holds(const Import& import, const acset::ACSet& x, const Atom& atom) {
    const Predicate* pred = import.pddl_domain.find_predicate(atom.predicate);
    ObId ob = import.predicate_ob.at(atom.predicate);
    if (atom.args.empty()) {
        return x.num_parts(ob) > 0;
    }
    std::vector<Part> parts;
    for (std::size_t i = 0; i < atom.args.size(); ++i) {
        auto p = x.find_part(import.type_ob.at(pred->params[i].type), atom.args[i].name);
        if (!p) {
            return false;
        }
        parts.push_back(*p);
    }
    const auto& homs = import.predicate_homs.at(atom.predicate);
    for (Part f : x.incident(homs[0], parts[0])) {
        bool all = true;
        for (std::size_t i = 1; i < homs.size() && all; ++i) {
            all = x.subpart(homs[i], f) == parts[i];
        }
        if (all) {
            return true;
        }
    }
    return false;
}

IpcValidation validate_ipc_plan(const Import& im, const IpcPlan& plan) {
    CATPLAN_ASSERT(im.problem != nullptr, "validation needs an imported problem");
    IpcValidation v;
    acset::ACSet x = *im.problem->initial;
    for (std::size_t i = 0; i < plan.size() && !v.failed_step; ++i) {
        const IpcStep& s = plan[i];
        auto prefix = fmt::format("step {} {}", i + 1, s.to_string());
        const ActionVariants* av = im.find_action(s.action);
        const Action* a = im.pddl_domain.find_action(s.action);
        if (av == nullptr || a == nullptr) {
            v.failed_step = i;
            v.reason = fmt::format("{}: unknown action '{}'", prefix, s.action);
            break;
        }
        if (auto why = pddl_problem(im, x, *a, s)) {
            v.failed_step = i;
            v.reason = fmt::format("{}: {}", prefix, *why);
            break;
        }
        std::string last = "no rule variant fits the arguments";
        bool applied = false;
        for (const auto& var : av->variants) {
            auto step = rule_step(var, s);
            if (!step) {
                continue;
            }
            auto m = plan::resolve_step(*var.rule, x, *step);
            if (!m) {
                last = m.error();
                continue;
            }
            auto r = rewrite::rewrite_in_place(*var.rule, x, *m);
            CATPLAN_ASSERT(r.has_value(), "a resolved match applies");
            v.plan.steps.push_back(std::move(*step));
            applied = true;
            break;
        }
        if (!applied) {
            // The PDDL precondition holds, so some variant should have applied: a bug.
            v.failed_step = i;
            v.reason = fmt::format("{}: internal error: no rule applies ({})", prefix, last);
        }
    }
    if (!v.failed_step) {
        v.goal_reached = true;
        for (const auto& l : im.pddl_problem->goal) {
            if (!holds(im, x, l.atom)) {
                v.goal_reached = false;
                v.reason = fmt::format("goal not reached: {} does not hold", l.atom.to_string());
                break;
            }
        }
        v.valid = v.goal_reached;
    }
    v.final_state = std::move(x);
    return v;
}

} // namespace catplan::pddl
