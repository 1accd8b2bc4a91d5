#include "catplan/plan/domain.hpp"

#include <cctype>
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
        if (!ok) {
            return std::nullopt;
        }
        return plan;
    }

private:
    static bool is_name_char(char c) {
        return !(c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == ';' ||
                 c == '(' || c == ')' || c == '#');
    }

    bool at_end() const { return pos_ >= text_.size(); }

    char peek() const { return text_[pos_]; }

    SourceRange range(std::size_t b, std::size_t e) const {
        return SourceRange{file_, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e)};
    }

    // Skips spaces and comments; newlines too when `newlines`. Inside an argument list `#3` is an
    // unnamed part, not a comment.
    void skip_blank(bool newlines, bool in_args = false) {
        while (!at_end()) {
            char c = peek();
            if (c == ' ' || c == '\t' || c == '\r' || (newlines && c == '\n')) {
                ++pos_;
            } else if (c == '#' && !(in_args && pos_ + 1 < text_.size() &&
                                     std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])))) {
                while (!at_end() && peek() != '\n') {
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
                    auto arg = name();
                    if (!arg) {
                        error_here(fmt::format("expected an argument of '{}'", step.action));
                        return std::nullopt;
                    }
                    step.args.push_back(std::move(*arg));
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
        if (!at_end() && peek() != '\n' && peek() != ';') {
            error_here(fmt::format("expected a new line or ';' after step '{}'", step.to_string()));
            return std::nullopt;
        }
        return step;
    }

    // After an error, resumes at the next step.
    void recover() {
        while (!at_end() && peek() != '\n' && peek() != ';') {
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
    return PlanParser(file, sources.text(file), sink).parse();
}

} // namespace catplan::plan
