#include "catplan/plan/domain.hpp"

#include "catplan/base/unicode.hpp"
#include "catplan/plan/actions.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fmt/format.h>

namespace catplan::plan {

const Rule* Domain::find_rule(std::string_view rule_name) const {
    for (const auto& r : rules) {
        if (r->name == rule_name) {
            return r.get();
        }
    }
    return nullptr;
}

std::string Step::to_string() const {
    std::string s = action + "(";
    for (std::size_t i = 0; i < args.size(); ++i) {
        s += (i ? ", " : "") + args[i];
    }
    return s + ")";
}

std::string Plan::to_string() const {
    std::string s;
    for (const auto& step : steps) {
        s += step.to_string() + "\n";
    }
    return s;
}

namespace {

// A hand-written scanner: the plan syntax is one line of tokens per step, too small for the
// language's lexer, and its `#3` (an unnamed part) must not be read as a comment.
class PlanParser {
public:
    PlanParser(std::uint32_t file, std::string_view text, DiagnosticSink& sink)
        : file_(file), text_(text), sink_(sink) {}

    std::optional<Plan> parse() {
        Plan plan;
        bool ok = true;
        pos_ = bom_length(text_);
        while (true) {
            skip_blank(true);
            if (at_end()) {
                break;
            }
            if (peek() == ';') {
                ++pos_;
                continue;
            }
            auto step = parse_step();
            if (step) {
                plan.steps.push_back(std::move(*step));
            } else {
                ok = false;
                recover();
            }
        }
        if (!ok || !ok_) {
            return std::nullopt;
        }
        return plan;
    }

private:
    static bool is_name_char(char c) {
        return !(c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == ';' ||
                 c == '(' || c == ')' || c == '#');
    }

    bool ok_ = true; // false after an error that did not stop the step

    bool at_end() const { return pos_ >= text_.size(); }

    char peek() const { return text_[pos_]; }

    SourceRange range(std::size_t b, std::size_t e) const {
        return SourceRange{file_, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e)};
    }

    // A line ends at LF, CRLF or a lone CR.
    bool at_line_end() const { return !at_end() && (peek() == '\n' || peek() == '\r'); }

    // Skips spaces and comments; line ends too when `newlines`. Inside an argument list `#3` is an
    // unnamed part, not a comment.
    void skip_blank(bool newlines, bool in_args = false) {
        while (!at_end()) {
            char c = peek();
            if (c == ' ' || c == '\t' || (newlines && at_line_end())) {
                ++pos_;
            } else if (c == '#' && !(in_args && pos_ + 1 < text_.size() &&
                                     std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])))) {
                while (!at_end() && !at_line_end()) {
                    ++pos_;
                }
            } else {
                break;
            }
        }
    }

    // A name, or `#k` (the k-th part, 1-based, for a part without a name).
    std::optional<std::string> name() {
        std::size_t b = pos_;
        if (!at_end() && peek() == '#') {
            ++pos_;
            while (!at_end() && std::isdigit(static_cast<unsigned char>(peek()))) {
                ++pos_;
            }
            std::uint32_t k = 0;
            auto [end, ec] = std::from_chars(text_.data() + b + 1, text_.data() + pos_, k);
            if (ec != std::errc() || k == 0) {
                sink_.error(range(b, pos_), fmt::format("'{}' names no part: write #k with k "
                                                        "from 1 (the k-th part)",
                                                        text_.substr(b, pos_ - b)));
                ok_ = false;
            }
        } else {
            while (!at_end() && is_name_char(peek())) {
                ++pos_;
            }
        }
        if (pos_ == b) {
            return std::nullopt;
        }
        return std::string(text_.substr(b, pos_ - b));
    }

    void error_here(const std::string& what) {
        std::size_t e = at_end() ? pos_ : pos_ + 1;
        sink_.error(range(pos_, e), what);
    }

    std::optional<Step> parse_step() {
        std::size_t begin = pos_;
        Step step;
        auto action = name();
        if (!action || (*action)[0] == '#') {
            error_here("expected an action name");
            return std::nullopt;
        }
        step.action = std::move(*action);
        skip_blank(false);
        if (!at_end() && peek() == '(') {
            ++pos_;
            skip_blank(true, true);
            if (!at_end() && peek() == ')') {
                ++pos_;
            } else {
                while (true) {
                    skip_blank(true, true);
                    std::size_t arg_begin = pos_;
                    auto arg = name();
                    if (!arg) {
                        error_here(fmt::format("expected an argument of '{}'", step.action));
                        return std::nullopt;
                    }
                    step.args.push_back(std::move(*arg));
                    step.arg_ranges.push_back(range(arg_begin, pos_));
                    skip_blank(true);
                    if (!at_end() && peek() == ',') {
                        ++pos_;
                        continue;
                    }
                    if (!at_end() && peek() == ')') {
                        ++pos_;
                        break;
                    }
                    error_here(
                        fmt::format("expected ',' or ')' in the arguments of '{}'", step.action));
                    return std::nullopt;
                }
            }
        }
        step.range = range(begin, pos_);
        skip_blank(false);
        if (!at_end() && !at_line_end() && peek() != ';') {
            error_here(fmt::format("expected a new line or ';' after step '{}'", step.to_string()));
            return std::nullopt;
        }
        return step;
    }

    // After an error, resumes at the next step.
    void recover() {
        while (!at_end() && !at_line_end() && peek() != ';') {
            ++pos_;
        }
    }

    std::uint32_t file_;
    std::string_view text_;
    DiagnosticSink& sink_;
    std::size_t pos_ = 0;
};

} // namespace

std::optional<Plan> parse_plan(std::uint32_t file, const SourceManager& sources,
                               DiagnosticSink& sink) {
    if (!check_utf8(sources, file, sink)) {
        return std::nullopt;
    }
    return PlanParser(file, sources.text(file), sink).parse();
}

namespace {

// Whether some rule of the domain creates a part of `ob` (named `name`, when not empty).
bool some_rule_creates(const Domain& domain, ObId ob, std::string_view name) {
    for (const auto& r : domain.rules) {
        for (Part p = 0; p < r->R.num_parts(ob); ++p) {
            bool created =
                std::find(r->r.components[ob.index()].begin(), r->r.components[ob.index()].end(),
                          p) == r->r.components[ob.index()].end();
            if (created && (name.empty() || r->R.part_name(ob, p) == name)) {
                return true;
            }
        }
    }
    return false;
}

// What is wrong with argument i of a step of rule r, whatever the state; nullopt when nothing.
std::optional<std::string> argument_problem(const Domain& domain, const ACSet& initial,
                                            const Rule& r, const Step& step, std::size_t i) {
    const auto& param = r.parameters[i];
    const std::string& arg = step.args[i];
    std::string_view ob_name = domain.schema->ob(param.ob).name;
    if (arg.starts_with('#')) {
        std::uint32_t k = 0;
        std::from_chars(arg.data() + 1, arg.data() + arg.size(), k);
        if (k > initial.num_parts(param.ob) && !some_rule_creates(domain, param.ob, "")) {
            return fmt::format("argument {} ({}): '{}' names no part: there are {} {} parts and "
                               "no action creates one",
                               i + 1, param.name, arg, initial.num_parts(param.ob), ob_name);
        }
        return std::nullopt;
    }
    if (!initial.find_part(param.ob, arg) && !some_rule_creates(domain, param.ob, arg)) {
        return fmt::format("argument {} ({}): no {} named '{}' in the initial state, and no "
                           "action creates one",
                           i + 1, param.name, ob_name, arg);
    }
    return std::nullopt;
}

} // namespace

namespace {

/// The names of the domain's actions, each once.
std::vector<std::string> action_names(const Domain& domain) {
    std::vector<std::string> names;
    for (const auto& rule : domain.rules) {
        if (std::find(names.begin(), names.end(), rule->action_name()) == names.end()) {
            names.push_back(rule->action_name());
        }
    }
    return names;
}

/// What is wrong with the arguments of a step of rule r, located.
std::vector<std::pair<SourceRange, std::string>>
argument_problems(const Domain& domain, const ACSet& initial, const Rule& r, const Step& step) {
    if (step.args.size() != r.parameters.size()) {
        std::vector<std::string> names;
        for (const auto& p : r.parameters) {
            names.push_back(p.name);
        }
        return {{step.range, fmt::format("{} takes {} argument{} ({}), got {}", r.name,
                                         r.parameters.size(), r.parameters.size() == 1 ? "" : "s",
                                         fmt::join(names, ", "), step.args.size())}};
    }
    std::vector<std::pair<SourceRange, std::string>> out;
    for (std::size_t i = 0; i < step.args.size(); ++i) {
        if (auto why = argument_problem(domain, initial, r, step, i)) {
            out.emplace_back(i < step.arg_ranges.size() ? step.arg_ranges[i] : step.range, *why);
        }
    }
    return out;
}

/// What is wrong with a step of an action that is not one rule's own: the arguments must fit
/// one of its rules and there name possible parts (the first rule they fit says what is wrong).
std::vector<std::pair<SourceRange, std::string>>
action_step_problems(const Domain& domain, const ACSet& initial,
                     const std::vector<const Rule*>& rules, const Step& step) {
    std::size_t arity = rules.front()->action_arity();
    if (step.args.size() != arity) {
        return {{step.range, fmt::format("{} takes {} argument{}, got {}", step.action, arity,
                                         arity == 1 ? "" : "s", step.args.size())}};
    }
    std::optional<std::vector<std::pair<SourceRange, std::string>>> first;
    for (const Rule* r : rules) {
        if (auto s = rule_step(*r, step)) {
            auto problems = argument_problems(domain, initial, *r, *s);
            if (problems.empty()) {
                return {};
            }
            if (!first) {
                first = std::move(problems);
            }
        }
    }
    if (first) {
        return *first;
    }
    return {{step.range, fmt::format("no rule of the action {} takes these arguments (the "
                                     "action's rules identify some of them)",
                                     step.action)}};
}

} // namespace

bool check_plan(const Plan& plan, const Domain& domain, const ACSet& initial,
                DiagnosticSink& sink) {
    std::size_t before = sink.num_errors();
    for (const auto& step : plan.steps) {
        auto rules = action_rules(domain, step.action);
        const Rule* r = domain.find_rule(step.action);
        bool fits = !rules.empty() && rules.front()->action_arity() == step.args.size();
        std::vector<std::pair<SourceRange, std::string>> problems;
        // A step names an action; failing that, a rule by its own name (`stack~2(b, a)`).
        bool plain = rules.size() == 1 && !rules.front()->action;
        bool by_rule = r != nullptr && (r->parameters.size() == step.args.size() || rules.empty());
        if (plain || (!fits && by_rule)) {
            problems = argument_problems(domain, initial, plain ? *rules.front() : *r, step);
        } else if (!rules.empty()) {
            problems = action_step_problems(domain, initial, rules, step);
        } else {
            SourceRange action{step.range.file, step.range.begin,
                               step.range.begin + static_cast<std::uint32_t>(step.action.size())};
            problems.emplace_back(action, fmt::format("unknown action '{}' (domain {} has: {})",
                                                      step.action, domain.name,
                                                      fmt::join(action_names(domain), ", ")));
        }
        for (const auto& [range, message] : problems) {
            sink.error(range, message);
        }
    }
    return sink.num_errors() == before;
}

} // namespace catplan::plan
