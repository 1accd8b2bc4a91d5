#include "catplan/pddl/ipc_plan.hpp"

#include "catplan/base/ascii.hpp"
#include "catplan/base/unicode.hpp"
#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/steps.hpp"
#include "catplan/plan/actions.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <functional>
#include <unordered_set>

namespace catplan::pddl {

namespace {

// Reads the IPC plan lines: `[T:] (action object ...) [[D]]`, `;` comments, blank lines.
class IpcReader {
public:
    IpcReader(std::uint32_t file, std::string_view text, DiagnosticSink& sink)
        : file_(file), text_(text), sink_(sink) {}

    std::optional<IpcPlan> read() {
        IpcPlan plan;
        bool ok = true;
        for (i_ = bom_length(text_); i_ < text_.size();) {
            auto step = line();
            if (step == Line::Step) {
                plan.push_back(std::move(step_));
            }
            ok = ok && step != Line::Bad;
            // Past the rest of the line (after an error) and its end: LF, CRLF or CR.
            while (i_ < text_.size() && !at_line_end()) {
                ++i_;
            }
            i_ += text_.substr(i_, 2) == "\r\n" ? 2 : 1;
        }
        return ok ? std::optional(std::move(plan)) : std::nullopt;
    }

private:
    enum class Line { Blank, Step, Bad };

    bool at_line_end() const { return text_[i_] == '\n' || text_[i_] == '\r'; }

    bool at_end_of_line() const { return i_ >= text_.size() || at_line_end() || text_[i_] == ';'; }

    static bool is_name_char(char c) {
        return std::isspace(static_cast<unsigned char>(c)) == 0 &&
               std::string_view("()[];").find(c) == std::string_view::npos;
    }

    SourceRange range(std::size_t b, std::size_t e) const {
        return {file_, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e)};
    }

    void blanks() {
        while (i_ < text_.size() && (text_[i_] == ' ' || text_[i_] == '\t')) {
            ++i_;
        }
    }

    std::size_t name_end(std::size_t from) const {
        while (from < text_.size() && is_name_char(text_[from])) {
            ++from;
        }
        return from;
    }

    Line bad(std::size_t b, std::size_t e, std::string message) {
        sink_.error(range(b, std::max(e, b + 1)), std::move(message));
        return Line::Bad;
    }

    // A time stamp `T:` or a duration's `D`: a non-negative decimal number, finite.
    bool number() {
        std::size_t b = i_;
        auto digits = [&] {
            std::size_t from = i_;
            while (i_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i_]))) {
                ++i_;
            }
            return i_ > from;
        };
        bool whole = digits();
        bool fraction = false;
        if (i_ < text_.size() && text_[i_] == '.') {
            ++i_;
            fraction = digits();
        }
        if (!whole && !fraction) {
            i_ = b;
            return false;
        }
        if (i_ < text_.size() && (text_[i_] == 'e' || text_[i_] == 'E')) {
            ++i_;
            if (i_ < text_.size() && (text_[i_] == '+' || text_[i_] == '-')) {
                ++i_;
            }
            if (!digits()) {
                i_ = b;
                return false;
            }
        }
        std::string spelled(text_.substr(b, i_ - b));
        if (std::isinf(std::strtod(spelled.c_str(), nullptr))) {
            bad(b, i_, fmt::format("number '{}' is out of range", spelled));
            return false;
        }
        return true;
    }

    Line line() {
        blanks();
        if (at_end_of_line()) {
            return Line::Blank;
        }
        std::size_t b = i_;
        if (text_[i_] != '(') {
            // A time stamp, as temporal planners write: `0.000: (pick a)`.
            std::size_t errors = sink_.num_errors();
            if (!number() || i_ >= text_.size() || text_[i_] != ':') {
                return sink_.num_errors() > errors
                           ? Line::Bad
                           : bad(b, name_end(b), "expected a step '(action object ...)'");
            }
            ++i_;
            blanks();
            if (i_ >= text_.size() || text_[i_] != '(') {
                return bad(i_, name_end(i_),
                           "expected a step '(action object ...)' after the "
                           "time stamp");
            }
        }
        if (!step()) {
            return Line::Bad;
        }
        blanks();
        if (i_ < text_.size() && text_[i_] == '[' && !duration()) {
            return Line::Bad;
        }
        blanks();
        if (!at_end_of_line()) {
            std::size_t e = i_;
            while (e < text_.size() && text_[e] != '\n' && text_[e] != '\r' && text_[e] != ';') {
                ++e;
            }
            return bad(i_, e,
                       text_[i_] == '(' ? "expected one step per line, found a second '('"
                                        : "unexpected text after the step");
        }
        return Line::Step;
    }

    // `(name object ...)` at '('.
    bool step() {
        std::size_t open = i_++;
        step_ = IpcStep{};
        while (true) {
            blanks();
            if (at_end_of_line()) {
                bad(open, open + 1, "unbalanced parentheses: this '(' is never closed");
                return false;
            }
            if (text_[i_] == ')') {
                ++i_;
                break;
            }
            std::size_t e = name_end(i_);
            if (e == i_) {
                bad(i_, i_ + 1,
                    fmt::format("expected an object name or ')' in a step, found '{}'", text_[i_]));
                return false;
            }
            std::string word = ascii_lowercase(text_.substr(i_, e - i_));
            if (step_.action.empty()) {
                step_.action = std::move(word);
                step_.action_range = range(i_, e);
            } else {
                step_.args.push_back(std::move(word));
                step_.arg_ranges.push_back(range(i_, e));
            }
            i_ = e;
        }
        step_.range = range(open, i_);
        if (step_.action.empty()) {
            bad(open, i_, "expected an action name in '()'");
            return false;
        }
        return true;
    }

    // `[D]`, the duration of a temporal step, at '['.
    bool duration() {
        std::size_t b = i_++;
        blanks();
        std::size_t errors = sink_.num_errors();
        bool ok = number();
        blanks();
        if (!ok || i_ >= text_.size() || text_[i_] != ']') {
            if (sink_.num_errors() == errors) {
                bad(b, std::min(i_ + 1, text_.size()),
                    "expected a duration '[number]' after the step");
            }
            return false;
        }
        ++i_;
        return true;
    }

    std::uint32_t file_;
    std::string_view text_;
    DiagnosticSink& sink_;
    std::size_t i_ = 0;
    IpcStep step_;
};

struct StepProblem {
    SourceRange at;
    std::string message;
};

/// What is wrong with a step whatever the state: an unknown action (then nothing else), a wrong
/// number of arguments (then nothing else), each unknown object and each argument of a wrong type.
std::vector<StepProblem> static_problems(const Domain& d, const ObjectIndex& objects,
                                         const IpcStep& s) {
    auto at = [&](SourceRange r) { return r.valid() ? r : s.range; };
    const Action* a = d.find_action(s.action);
    if (a == nullptr) {
        std::vector<std::string> names;
        for (const auto& action : d.actions) {
            names.push_back(action.name);
        }
        return {{at(s.action_range), fmt::format("unknown action '{}' (domain {} has: {})",
                                                 s.action, d.name, fmt::join(names, ", "))}};
    }
    if (s.args.size() != a->params.size()) {
        return {{s.range, fmt::format("'{}' takes {} argument{}, got {}", a->name, a->params.size(),
                                      a->params.size() == 1 ? "" : "s", s.args.size())}};
    }
    std::vector<StepProblem> out;
    for (std::size_t i = 0; i < s.args.size(); ++i) {
        SourceRange arg = at(i < s.arg_ranges.size() ? s.arg_ranges[i] : SourceRange{});
        const TypedName* o = objects.find(s.args[i]);
        if (o == nullptr) {
            out.push_back({arg, fmt::format("unknown object '{}'", s.args[i])});
        } else if (!d.is_subtype(o->type, a->params[i].type)) {
            out.push_back(
                {arg, fmt::format("argument {} (?{}) must be a {}, and '{}' is a {}", i + 1,
                                  a->params[i].name, a->params[i].type, o->name, o->type)});
        }
    }
    return out;
}

// The step's argument for a term of the action's atom that is one of the action's parameters
// (the first of that name), or nullptr: what ground() puts in its place.
const std::string* bound_argument(const Action& a, const Term& t, const IpcStep& s) {
    for (std::size_t i = 0; t.variable && i < a.params.size(); ++i) {
        if (a.params[i].name == t.name) {
            return &s.args[i];
        }
    }
    return nullptr;
}

// A state as PDDL reads it: the ground atoms that hold, each kept as its predicate and arguments
// joined by spaces (names are lowered and have no spaces).
class Facts {
public:
    explicit Facts(const Problem& p) {
        for (const auto& atom : p.init) {
            atoms_.insert(key(atom));
        }
    }

    // Whether a ground atom holds; an equality holds when both sides name one object.
    bool holds(const Atom& g) const {
        return g.predicate == "=" ? g.args[0].name == g.args[1].name : atoms_.count(key(g)) > 0;
    }

    // The first precondition of the step's action that does not hold, in words. The atoms are
    // grounded as their keys (ground() only for the words).
    std::optional<std::string> false_precondition(const Action& a, const IpcStep& s) const {
        for (const auto& l : a.precondition) {
            const Atom& atom = l.atom;
            bool holds = atom.predicate == "="
                             ? argument(a, atom.args[0], s) == argument(a, atom.args[1], s)
                             : atoms_.count(key(a, atom, s)) > 0;
            if (holds != l.positive) {
                return fmt::format("precondition {} does not hold",
                                   Literal{ground(a, atom, s), l.positive, {}}.to_string());
            }
        }
        return std::nullopt;
    }

    // The step's effect: its deletes removed, then its adds added (an atom both deleted and added
    // holds after the step).
    void apply(const Action& a, const IpcStep& s) {
        for (const auto& atom : a.del) {
            atoms_.erase(key(a, atom, s));
        }
        for (const auto& atom : a.add) {
            atoms_.insert(key(a, atom, s));
        }
    }

    // Every atom that holds, sorted: "(on a b)".
    std::vector<std::string> sorted() const {
        std::vector<std::string> out;
        out.reserve(atoms_.size());
        for (const auto& k : atoms_) {
            out.push_back("(" + k + ")");
        }
        std::sort(out.begin(), out.end());
        return out;
    }

private:
    static std::string key(const Atom& g) {
        std::string k = g.predicate;
        for (const auto& t : g.args) {
            k += ' ';
            k += t.name;
        }
        return k;
    }

    // What a term of the action's atom names at the step (its name in ground(a, atom, s)).
    static const std::string& argument(const Action& a, const Term& t, const IpcStep& s) {
        const std::string* bound = bound_argument(a, t, s);
        return bound != nullptr ? *bound : t.name;
    }

    // The key of key(ground(a, atom, s)), without the ground atom.
    static std::string key(const Action& a, const Atom& atom, const IpcStep& s) {
        std::string k = atom.predicate;
        for (const auto& t : atom.args) {
            k += ' ';
            k += argument(a, t, s);
        }
        return k;
    }

    std::unordered_set<std::string> atoms_;
};

// A step's own rule-level work, beside PDDL's meaning: nullopt, or why the step failed.
using StepHook = std::function<std::optional<std::string>(std::size_t, const IpcStep&)>;

// The plan replayed with PDDL's meaning (Facts) from p's initial state, each step's static
// problems, precondition and cost checked before `hook` sees it, then the goal.
IpcValidation replay_ipc_plan(const Domain& d, const Problem& p, const IpcPlan& plan,
                              const StepHook& hook) {
    IpcValidation v;
    v.cost.unit = unit_cost(d, p);
    Facts facts(p);
    ObjectIndex objects(d, p);
    for (std::size_t i = 0; i < plan.size() && !v.failed_step; ++i) {
        const IpcStep& s = plan[i];
        auto fail_step = [&](const std::string& why) {
            v.failed_step = i;
            v.reason = fmt::format("step {} {}: {}", i + 1, s.to_string(), why);
        };
        if (auto problems = static_problems(d, objects, s); !problems.empty()) {
            fail_step(problems[0].message);
            break;
        }
        const Action& a = *d.find_action(s.action);
        if (auto why = facts.false_precondition(a, s)) {
            fail_step(*why);
            break;
        }
        auto cost = step_cost(d, p, s);
        if (!cost) {
            fail_step(cost.error());
            break;
        }
        if (auto why = hook ? hook(i, s) : std::nullopt) {
            fail_step(*why);
            break;
        }
        facts.apply(a, s);
        v.cost.steps.push_back(*cost);
        v.cost.total += *cost;
    }
    if (!v.failed_step) {
        v.goal_reached = true;
        for (const auto& l : p.goal) {
            if (facts.holds(l.atom) != l.positive) {
                v.goal_reached = false;
                v.reason = fmt::format("goal not reached: {} does not hold", l.to_string());
                break;
            }
        }
        v.valid = v.goal_reached;
    }
    v.final_facts = facts.sorted();
    return v;
}

} // namespace

Atom ground(const Action& a, const Atom& atom, const IpcStep& s) {
    Atom g = atom;
    for (auto& t : g.args) {
        if (const std::string* bound = bound_argument(a, t, s)) {
            t = Term{*bound, false, t.range};
        }
    }
    return g;
}

std::string IpcStep::to_string() const {
    std::size_t n = action.size() + 2;
    for (const auto& a : args) {
        n += a.size() + 1;
    }
    std::string s;
    s.reserve(n);
    s += '(';
    s += action;
    for (const auto& a : args) {
        s += ' ';
        s += a;
    }
    s += ')';
    return s;
}

std::optional<IpcPlan> parse_ipc_plan(std::uint32_t file, const SourceManager& sources,
                                      DiagnosticSink& sink) {
    if (!check_utf8(sources, file, sink)) {
        return std::nullopt;
    }
    return IpcReader(file, sources.text(file), sink).read();
}

bool check_ipc_plan(const Import& import, const IpcPlan& plan, DiagnosticSink& sink) {
    CATPLAN_ASSERT(import.pddl_problem.has_value(), "a plan is checked against a problem");
    bool ok = true;
    ObjectIndex objects(import.pddl_domain, *import.pddl_problem);
    for (const auto& step : plan) {
        for (auto& problem : static_problems(import.pddl_domain, objects, step)) {
            sink.error(problem.at, std::move(problem.message));
            ok = false;
        }
    }
    return ok;
}

std::string write_ipc_plan(const IpcPlan& plan) {
    PlanCost cost;
    cost.total = static_cast<std::int64_t>(plan.size());
    return write_ipc_plan(plan, cost);
}

std::string write_ipc_plan(const IpcPlan& plan, const PlanCost& cost) {
    std::string out;
    for (const auto& s : plan) {
        out += s.to_string() + "\n";
    }
    return out + cost_line(cost);
}

Result<IpcPlan> to_ipc_plan(const Import& import, const plan::Plan& plan) {
    IpcPlan out;
    for (const auto& step : plan.steps) {
        auto found = import.find_rule(step.action);
        if (!found) {
            return fail(fmt::format("'{}' is not a rule of the imported domain", step.action));
        }
        const rewrite::Rule& rule = *found->second->rule;
        if (rule.parameters.size() != step.args.size()) {
            return fail(fmt::format("rule '{}' takes {} arguments, got {}", rule.name,
                                    rule.parameters.size(), step.args.size()));
        }
        plan::Step a = plan::action_step(rule, step);
        out.push_back(IpcStep{std::move(a.action), std::move(a.args), {}});
    }
    return out;
}

IpcValidation simulate_ipc_plan(const Domain& domain, const Problem& problem, const IpcPlan& plan) {
    return replay_ipc_plan(domain, problem, plan, {});
}

IpcValidation validate_ipc_plan(const Import& im, const IpcPlan& plan) {
    CATPLAN_ASSERT(im.problem != nullptr, "validation needs an imported problem");
    acset::ACSet x = *im.problem->initial;
    plan::Plan rules;
    auto v = replay_ipc_plan(
        im.pddl_domain, *im.pddl_problem, plan,
        [&](std::size_t, const IpcStep& s) -> std::optional<std::string> {
            auto step =
                plan::apply_action_step(*im.domain, x, plan::Step{s.action, s.args, s.range});
            if (step) {
                rules.steps.push_back(std::move(*step));
                return std::nullopt;
            }
            // The PDDL precondition holds, so some variant should have applied: a bug.
            return fmt::format("internal error: no rule applies ({})", step.error());
        });
    v.plan = std::move(rules);
    v.final_state = std::move(x);
    return v;
}

} // namespace catplan::pddl
