// Formulas, effects, action costs and numeric values of the PDDL reader (detail/reader.hpp).

#include "catplan/pddl/detail/reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <unordered_map>

namespace catplan::pddl::detail {

namespace {

std::string type_of_term(const Scope& s, const Term& t) {
    if (t.variable) {
        for (const auto& p : *s.params) {
            if (p.name == t.name) {
                return p.type;
            }
        }
        return "";
    }
    if (s.objects != nullptr) {
        const TypedName* o = s.objects->find(t.name);
        return o == nullptr ? "" : o->type;
    }
    for (const auto& c : s.domain.constants) {
        if (c.name == t.name) {
            return c.type;
        }
    }
    if (s.problem != nullptr) {
        for (const auto& o : s.problem->objects) {
            if (o.name == t.name) {
                return o.type;
            }
        }
    }
    return "";
}

/// What catplan does not support of PDDL's formulas and effects, by head: the requirement or
/// feature it belongs to.
const std::unordered_map<std::string_view, std::string_view>& unsupported_heads() {
    static const std::unordered_map<std::string_view, std::string_view> heads = {
        {"or", "disjunctive formulas, :disjunctive-preconditions"},
        {"imply", "disjunctive formulas, :disjunctive-preconditions"},
        {"exists", "quantified formulas, :existential-preconditions"},
        {"forall", "quantified formulas and effects, :universal-preconditions and "
                   ":conditional-effects"},
        {"when", "conditional effects, :conditional-effects"},
        {"preference", "preferences, :preferences"},
        {"<", "numeric conditions, :numeric-fluents"},
        {"<=", "numeric conditions, :numeric-fluents"},
        {">", "numeric conditions, :numeric-fluents"},
        {">=", "numeric conditions, :numeric-fluents"},
        {"increase", "numeric effects other than an action's cost, :numeric-fluents"},
        {"decrease", "numeric effects, :numeric-fluents"},
        {"assign", "numeric effects, :numeric-fluents"},
        {"scale-up", "numeric effects, :numeric-fluents"},
        {"scale-down", "numeric effects, :numeric-fluents"},
    };
    return heads;
}

} // namespace

bool FormulaReader::unsupported_construct(const SExpr& e) {
    auto it = unsupported_heads().find(e.head());
    if (it == unsupported_heads().end()) {
        return false;
    }
    p_.unsupported(e.items[0].range,
                   fmt::format("unsupported construct '{}' ({})", it->first, it->second));
    return true;
}

std::optional<Atom> FormulaReader::with_terms(const SExpr& e) {
    Atom a;
    a.predicate = e.items[0].atom;
    a.range = e.range;
    bool ok = true;
    for (std::size_t i = 1; i < e.items.size(); ++i) {
        auto t = term(e.items[i]);
        ok = ok && t.has_value();
        if (t) {
            a.args.push_back(std::move(*t));
        }
    }
    return ok ? std::optional(std::move(a)) : std::nullopt;
}

std::optional<Atom> FormulaReader::atom(const SExpr& e, bool allow_equality) {
    if (!e.list || e.items.empty() || e.items[0].list) {
        p_.error(e.range, "expected an atom '(predicate args...)'");
        return std::nullopt;
    }
    if (unsupported_construct(e)) {
        return std::nullopt;
    }
    if (e.items[0].atom == "=" &&
        std::any_of(e.items.begin() + 1, e.items.end(), [](const SExpr& x) { return x.list; })) {
        p_.unsupported(e.items[0].range,
                       "unsupported construct '=' on numbers (numeric conditions, "
                       ":numeric-fluents)");
        return std::nullopt;
    }
    auto read = with_terms(e);
    if (!read) {
        return std::nullopt;
    }
    Atom& a = *read;
    if (a.predicate == "=") {
        if (!allow_equality) {
            p_.error(e.range, "equality '(= ...)' is allowed in preconditions only");
            return std::nullopt;
        }
        if (a.args.size() != 2) {
            p_.error(e.range,
                     fmt::format("wrong arity: '=' takes 2 arguments, not {}", a.args.size()));
            return std::nullopt;
        }
        return a;
    }
    const Predicate* pred = s_.domain.find_predicate(a.predicate);
    if (pred == nullptr) {
        p_.error(e.items[0].range, fmt::format("unknown predicate '{}'", a.predicate));
        return std::nullopt;
    }
    return typed_args(a, pred->params, "predicate") ? std::optional(std::move(a)) : std::nullopt;
}

bool FormulaReader::typed_args(const Atom& a, const std::vector<TypedName>& params,
                               std::string_view what) {
    if (params.size() != a.args.size()) {
        p_.error(a.range, fmt::format("wrong arity: {}'{}' takes {} argument{}, not {}",
                                      what == "function" ? "the function " : "", a.predicate,
                                      params.size(), params.size() == 1 ? "" : "s", a.args.size()));
        return false;
    }
    for (std::size_t i = 0; i < a.args.size(); ++i) {
        std::string t = type_of_term(s_, a.args[i]);
        // An unknown type was reported where it was declared.
        if (s_.domain.find_type(t) != nullptr && !s_.domain.is_subtype(t, params[i].type)) {
            p_.error(a.args[i].range,
                     fmt::format("type mismatch: argument {} of '{}' must be a {}, and '{}' "
                                 "is a {}",
                                 i + 1, a.predicate, params[i].type,
                                 (a.args[i].variable ? "?" : "") + a.args[i].name, t));
            return false;
        }
    }
    return true;
}

std::optional<std::vector<Literal>> FormulaReader::conjunction(const SExpr& e, bool allow_equality,
                                                               bool allow_negative) {
    std::vector<Literal> out;
    if (e.list && e.items.empty()) {
        return out;
    }
    if (e.head() == "and") {
        bool ok = true;
        for (std::size_t i = 1; i < e.items.size(); ++i) {
            auto more = conjunction(e.items[i], allow_equality, allow_negative);
            ok = ok && more.has_value();
            if (more) {
                out.insert(out.end(), more->begin(), more->end());
            }
        }
        return ok ? std::optional(out) : std::nullopt;
    }
    if (e.head() == "not") {
        if (!allow_negative) {
            p_.error(e.range, "'not' is not allowed here");
            return std::nullopt;
        }
        if (e.items.size() != 2) {
            p_.error(e.range, "'not' takes one atom");
            return std::nullopt;
        }
        auto a = atom(e.items[1], allow_equality);
        if (!a) {
            return std::nullopt;
        }
        out.push_back({*a, false, e.range});
        return out;
    }
    auto a = atom(e, allow_equality);
    if (!a) {
        return std::nullopt;
    }
    out.push_back({*a, true, e.range});
    return out;
}

std::optional<Term> FormulaReader::term(const SExpr& e) {
    if (is_variable(e)) {
        Term t{e.atom.substr(1), true, e.range};
        if (s_.params == nullptr || type_of_term(s_, t).empty()) {
            p_.error(e.range, fmt::format("unknown variable '{}'", e.atom));
            return std::nullopt;
        }
        return t;
    }
    if (!is_name(e)) {
        p_.error(e.range, "expected a variable or an object name");
        return std::nullopt;
    }
    Term t{e.atom, false, e.range};
    if (type_of_term(s_, t).empty()) {
        p_.error(e.range, fmt::format("unknown {} '{}'",
                                      s_.problem != nullptr ? "object" : "constant", e.atom));
        return std::nullopt;
    }
    return t;
}

// ---- effects and costs --------------------------------------------------------------------------

bool FormulaReader::effect(const SExpr& e, Action& a) {
    if (e.list && e.items.empty()) {
        return true;
    }
    if (e.head() == "and") {
        bool ok = true;
        for (std::size_t i = 1; i < e.items.size(); ++i) {
            ok = effect(e.items[i], a) && ok;
        }
        return ok;
    }
    if (e.head() == "not") {
        if (e.items.size() != 2) {
            p_.error(e.range, "'not' takes one atom");
            return false;
        }
        auto atom = this->atom(e.items[1], false);
        if (atom) {
            a.del.push_back(*atom);
        }
        return atom.has_value();
    }
    if (e.head() == "increase" && e.items.size() == 3 && e.items[1].list &&
        e.items[1].items.size() == 1 && e.items[1].items[0].is_atom("total-cost")) {
        if (s_.domain.find_function("total-cost") == nullptr) {
            p_.error(e.items[1].range, "unknown function 'total-cost' (declare it: "
                                       "(:functions (total-cost) - number))");
            return false;
        }
        auto c = cost_term(e.items[2]);
        if (c) {
            a.cost.push_back(std::move(*c));
        }
        return c.has_value();
    }
    auto atom = this->atom(e, false);
    if (atom) {
        a.add.push_back(*atom);
    }
    return atom.has_value();
}

std::optional<std::int64_t> FormulaReader::number(const SExpr& e, std::string_view what) {
    const std::string& s = e.atom;
    std::int64_t n = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (!e.list && ec == std::errc() && end == s.data() + s.size() && n >= 0) {
        return n;
    }
    char* stop = nullptr;
    double x = e.list || s.empty() ? 0.0 : std::strtod(s.c_str(), &stop);
    if (e.list || s.empty() || stop != s.c_str() + s.size()) {
        p_.error(e.range, fmt::format("expected a number for {}", what));
        return std::nullopt;
    }
    if (x < 0 || std::signbit(x)) {
        p_.error(e.range, fmt::format("{} must not be negative", what));
        return std::nullopt;
    }
    if (!std::isfinite(x) || x >= 9.2e18) {
        p_.error(e.range, fmt::format("number '{}' is out of range", s));
        return std::nullopt;
    }
    if (x != std::floor(x)) {
        p_.unsupported(e.range, fmt::format("unsupported number '{}' for {} (catplan's costs "
                                            "are whole numbers)",
                                            s, what));
        return std::nullopt;
    }
    return static_cast<std::int64_t>(x);
}

std::optional<Atom> FormulaReader::function_term(const SExpr& e) {
    if (!e.list || e.items.empty() || !is_name(e.items[0])) {
        p_.error(e.range, "expected a function term '(function args...)'");
        return std::nullopt;
    }
    if (unsupported_construct(e)) {
        return std::nullopt;
    }
    const Function* f = s_.domain.find_function(e.items[0].atom);
    if (f == nullptr) {
        p_.error(e.items[0].range, fmt::format("unknown function '{}'", e.items[0].atom));
        return std::nullopt;
    }
    auto a = with_terms(e);
    return a && typed_args(*a, f->params, "function") ? a : std::nullopt;
}

std::optional<CostTerm> FormulaReader::cost_term(const SExpr& e) {
    if (!e.list) {
        auto n = number(e, "an action's cost");
        return n ? std::optional(CostTerm{*n, std::nullopt, e.range}) : std::nullopt;
    }
    if (e.head() == "total-cost") {
        p_.unsupported(e.range, "unsupported cost '(total-cost)' (an action's cost is a number "
                                "or a function's value in the problem)");
        return std::nullopt;
    }
    auto f = function_term(e);
    return f ? std::optional(CostTerm{0, std::move(*f), e.range}) : std::nullopt;
}

bool FormulaReader::init_value(const SExpr& e, Problem& pr) {
    if (e.items.size() != 3 || !e.items[1].list) {
        p_.error(e.range, "expected a function's value '(= (function objects...) number)'");
        return false;
    }
    auto f = function_term(e.items[1]);
    auto n = f ? number(e.items[2], fmt::format("the value of {}", f->to_string()))
               : std::optional<std::int64_t>();
    if (!f || !n) {
        return false;
    }
    for (const auto& v : pr.values) {
        if (v.term.predicate == f->predicate && v.term.args == f->args) {
            p_.error(e.range, fmt::format("the value of {} is given twice", f->to_string()))
                .notes.emplace_back(v.range, "first given here");
            return false;
        }
    }
    pr.values.push_back({std::move(*f), *n, e.range});
    return true;
}

} // namespace catplan::pddl::detail
