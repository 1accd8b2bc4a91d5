#include "catplan/base/unicode.hpp"
#include "catplan/pddl/pddl.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <unordered_map>
#include <unordered_set>

namespace catplan::pddl {

namespace {

// ---- s-expressions ----------------------------------------------------------------------------

struct SExpr {
    bool list = false;
    std::string atom; // lower-cased (PDDL names are case-insensitive)
    std::vector<SExpr> items;
    SourceRange range;

    bool is_atom(std::string_view s) const { return !list && atom == s; }

    /// The head keyword of a list, or "".
    std::string_view head() const {
        return list && !items.empty() && !items[0].list ? std::string_view(items[0].atom) : "";
    }
};

class Reader {
public:
    Reader(std::uint32_t file, std::string_view text, DiagnosticSink& sink)
        : file_(file), text_(text), sink_(sink) {}

    /// The one top-level list of the file; nullopt after reporting a problem.
    std::optional<SExpr> read_file(const SourceManager& sources) {
        if (!check_utf8(sources, file_, sink_)) {
            return std::nullopt;
        }
        i_ = bom_length(text_);
        skip();
        if (i_ >= text_.size()) {
            sink_.error(range(0, 0), "empty PDDL file: expected '(define ...)'");
            return std::nullopt;
        }
        auto e = read(1);
        if (!e) {
            return std::nullopt;
        }
        skip();
        if (i_ < text_.size()) {
            sink_.error(range(i_, i_ + 1), text_[i_] == ')'
                                               ? "unbalanced parentheses: unexpected ')'"
                                               : "unexpected text after the definition");
            return std::nullopt;
        }
        return e;
    }

private:
    SourceRange range(std::size_t b, std::size_t e) const {
        return {file_, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e)};
    }

    void skip() {
        while (i_ < text_.size()) {
            if (std::isspace(static_cast<unsigned char>(text_[i_]))) {
                ++i_;
            } else if (text_[i_] == ';') {
                while (i_ < text_.size() && text_[i_] != '\n' && text_[i_] != '\r') {
                    ++i_;
                }
            } else {
                break;
            }
        }
    }

    // The expression at i_, `depth` levels down (the top level is 1): deeper than kMaxNesting is an
    // error, so that neither this recursion nor the tree's destructor exhausts the stack.
    std::optional<SExpr> read(std::uint32_t depth) {
        SExpr e;
        std::size_t start = i_;
        if (text_[i_] == ')') {
            sink_.error(range(i_, i_ + 1), "unbalanced parentheses: unexpected ')'");
            return std::nullopt;
        }
        if (text_[i_] != '(') {
            while (i_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[i_])) &&
                   text_[i_] != '(' && text_[i_] != ')' && text_[i_] != ';') {
                e.atom += static_cast<char>(std::tolower(static_cast<unsigned char>(text_[i_])));
                ++i_;
            }
            e.range = range(start, i_);
            return e;
        }
        if (depth > kMaxNesting) {
            sink_.error(range(i_, i_ + 1), "nested deeper than 256 levels");
            return std::nullopt;
        }
        e.list = true;
        ++i_;
        for (;;) {
            skip();
            if (i_ >= text_.size()) {
                sink_.error(range(start, start + 1),
                            "unbalanced parentheses: this '(' is never closed");
                return std::nullopt;
            }
            if (text_[i_] == ')') {
                ++i_;
                e.range = range(start, i_);
                return e;
            }
            auto item = read(depth + 1);
            if (!item) {
                return std::nullopt;
            }
            e.items.push_back(std::move(*item));
        }
    }

    std::uint32_t file_;
    std::string_view text_;
    DiagnosticSink& sink_;
    std::size_t i_ = 0;
};

// ---- shared helpers ---------------------------------------------------------------------------

const std::unordered_set<std::string> kSupported = {":strips", ":typing", ":negative-preconditions",
                                                    ":equality"};

bool is_name(const SExpr& e) {
    return !e.list && !e.atom.empty() && e.atom[0] != '?' && e.atom[0] != ':' && e.atom != "-";
}

bool is_variable(const SExpr& e) {
    return !e.list && e.atom.size() > 1 && e.atom[0] == '?';
}

class Parser {
public:
    explicit Parser(DiagnosticSink& sink) : sink_(sink) {}

    bool failed() const { return errors_ > 0; }

    Diagnostic& error(SourceRange r, std::string message) {
        ++errors_;
        return sink_.error(r, std::move(message));
    }

    /// `a b - t c` (names or variables) into typed names; `(either ...)` is refused.
    std::vector<TypedName> typed_list(const std::vector<SExpr>& items, std::size_t from,
                                      bool variables, const Domain* d, std::string_view what) {
        std::vector<TypedName> out;
        std::size_t untyped_from = 0;
        for (std::size_t i = from; i < items.size(); ++i) {
            const SExpr& e = items[i];
            if (e.is_atom("-")) {
                if (i + 1 >= items.size()) {
                    error(e.range, fmt::format("expected a type after '-' in {}", what));
                    return out;
                }
                const SExpr& t = items[++i];
                if (t.list) {
                    error(t.range, t.head() == "either"
                                       ? "unsupported construct 'either' (union types)"
                                       : fmt::format("expected a type name in {}", what));
                    continue;
                }
                if (d != nullptr && d->find_type(t.atom) == nullptr) {
                    error(t.range, fmt::format("unknown type '{}'", t.atom));
                }
                for (std::size_t k = untyped_from; k < out.size(); ++k) {
                    out[k].type = t.atom;
                }
                untyped_from = out.size();
                continue;
            }
            bool ok = variables ? is_variable(e) : is_name(e);
            if (!ok) {
                error(e.range,
                      fmt::format("expected {} in {}", variables ? "a variable" : "a name", what));
                continue;
            }
            out.push_back({variables ? e.atom.substr(1) : e.atom, "object", e.range});
        }
        return out;
    }

    /// Reports each name of `names` declared before in `names` or in `earlier`; `what` is
    /// "parameter", "constant" or "object".
    void report_duplicates(const std::vector<TypedName>& names, std::string_view what,
                           const std::vector<TypedName>& earlier = {}) {
        auto first = [&](std::size_t i) -> const TypedName* {
            for (const auto& e : earlier) {
                if (e.name == names[i].name) {
                    return &e;
                }
            }
            for (std::size_t k = 0; k < i; ++k) {
                if (names[k].name == names[i].name) {
                    return &names[k];
                }
            }
            return nullptr;
        };
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (const TypedName* f = first(i)) {
                error(names[i].range, fmt::format("the {} '{}{}' is declared twice", what,
                                                  what == "parameter" ? "?" : "", names[i].name))
                    .notes.emplace_back(f->range, "first declared here");
            }
        }
    }

    /// Whether a list starts with the keyword.
    bool expect_head(const SExpr& e, std::string_view keyword, std::string_view what) {
        if (!e.list || e.head() != keyword) {
            error(e.range, fmt::format("expected '({} ...)' {}", keyword, what));
            return false;
        }
        return true;
    }

    DiagnosticSink& sink_;
    int errors_ = 0;
};

// ---- formulas ---------------------------------------------------------------------------------

/// The scope a formula is read in: the action's parameters (or none), and the known constants.
struct Scope {
    const Domain& domain;
    const std::vector<TypedName>* params = nullptr;
    const Problem* problem = nullptr;
};

std::string type_of_term(const Scope& s, const Term& t) {
    if (t.variable) {
        for (const auto& p : *s.params) {
            if (p.name == t.name) {
                return p.type;
            }
        }
        return "";
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

class FormulaReader {
public:
    FormulaReader(Parser& p, const Scope& s) : p_(p), s_(s) {}

    std::optional<Atom> atom(const SExpr& e, bool allow_equality) {
        if (!e.list || e.items.empty() || e.items[0].list) {
            p_.error(e.range, "expected an atom '(predicate args...)'");
            return std::nullopt;
        }
        Atom a;
        a.predicate = e.items[0].atom;
        a.range = e.range;
        static const std::unordered_set<std::string> kUnsupported = {
            "or", "imply", "exists", "forall", "when", "increase", "decrease", "assign"};
        if (kUnsupported.count(a.predicate) != 0) {
            p_.error(e.items[0].range, fmt::format("unsupported construct '{}'", a.predicate));
            return std::nullopt;
        }
        bool ok = true;
        for (std::size_t i = 1; i < e.items.size(); ++i) {
            auto t = term(e.items[i]);
            ok = ok && t.has_value();
            if (t) {
                a.args.push_back(*t);
            }
        }
        if (!ok) {
            return std::nullopt;
        }
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
        if (pred->params.size() != a.args.size()) {
            p_.error(e.range, fmt::format("wrong arity: '{}' takes {} argument{}, not {}",
                                          a.predicate, pred->params.size(),
                                          pred->params.size() == 1 ? "" : "s", a.args.size()));
            return std::nullopt;
        }
        for (std::size_t i = 0; i < a.args.size(); ++i) {
            std::string t = type_of_term(s_, a.args[i]);
            // An unknown type was reported where it was declared.
            if (s_.domain.find_type(t) != nullptr &&
                !s_.domain.is_subtype(t, pred->params[i].type)) {
                p_.error(a.args[i].range,
                         fmt::format("type mismatch: argument {} of '{}' must be a {}, and '{}' "
                                     "is a {}",
                                     i + 1, a.predicate, pred->params[i].type,
                                     (a.args[i].variable ? "?" : "") + a.args[i].name, t));
                return std::nullopt;
            }
        }
        return a;
    }

    /// A conjunction of literals (`(and ...)`, one literal, or `()`).
    std::optional<std::vector<Literal>> conjunction(const SExpr& e, bool allow_equality,
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
                p_.error(e.range, "unsupported construct 'not' here (negative goals)");
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

    std::optional<Term> term(const SExpr& e) {
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

private:
    Parser& p_;
    const Scope& s_;
};

// ---- domains ----------------------------------------------------------------------------------

void read_requirements(Parser& p, const SExpr& e, Domain& d) {
    for (std::size_t i = 1; i < e.items.size(); ++i) {
        const SExpr& r = e.items[i];
        if (r.list || r.atom.empty() || r.atom[0] != ':') {
            p.error(r.range, "expected a requirement such as ':typing'");
            continue;
        }
        if (kSupported.count(r.atom) == 0) {
            p.error(r.range, fmt::format("unsupported requirement '{}' (catplan reads :strips, "
                                         ":typing, :negative-preconditions and :equality)",
                                         r.atom));
            continue;
        }
        d.requirements.push_back(r.atom);
    }
}

void read_types(Parser& p, const SExpr& e, Domain& d) {
    auto list = p.typed_list(e.items, 1, false, nullptr, "(:types ...)");
    // Parents named only as parents are declared implicitly, as most planners do.
    std::vector<Type> declared;
    for (const auto& t : list) {
        declared.push_back({t.name, t.type, t.range});
    }
    // A domain may have several (:types ...) sections: the earlier ones' types are known here.
    for (const auto& t : list) {
        bool known = d.find_type(t.type) != nullptr ||
                     std::any_of(declared.begin(), declared.end(),
                                 [&](const Type& x) { return x.name == t.type; });
        if (!known) {
            declared.push_back({t.type, "object", t.range});
        }
    }
    // Parents before children (a cycle is reported once).
    std::unordered_set<std::string> placed;
    for (const auto& t : d.types) {
        placed.insert(t.name);
    }
    while (!declared.empty()) {
        auto it = std::find_if(declared.begin(), declared.end(),
                               [&](const Type& t) { return placed.count(t.parent) != 0; });
        if (it == declared.end()) {
            p.error(declared[0].range,
                    fmt::format("the type '{}' is its own ancestor", declared[0].name));
            return;
        }
        if (it->name == "object" || placed.count(it->name) != 0) {
            if (it->name != "object") {
                p.error(it->range, fmt::format("the type '{}' is declared twice", it->name));
            }
        } else {
            placed.insert(it->name);
            d.types.push_back(*it);
        }
        declared.erase(it);
    }
}

void read_predicates(Parser& p, const SExpr& e, Domain& d) {
    for (std::size_t i = 1; i < e.items.size(); ++i) {
        const SExpr& pe = e.items[i];
        if (!pe.list || pe.items.empty() || !is_name(pe.items[0])) {
            p.error(pe.range, "expected a predicate '(name ?x - type ...)'");
            continue;
        }
        if (d.find_predicate(pe.items[0].atom) != nullptr) {
            p.error(pe.range,
                    fmt::format("the predicate '{}' is declared twice", pe.items[0].atom));
            continue;
        }
        d.predicates.push_back(
            {pe.items[0].atom, p.typed_list(pe.items, 1, true, &d, "a predicate"), pe.range});
        p.report_duplicates(d.predicates.back().params, "parameter");
    }
}

/// The add and delete lists of an effect `(and (p ...) (not (q ...)))`.
bool read_effect(Parser& p, FormulaReader& fr, const SExpr& e, Action& a) {
    if (e.list && e.items.empty()) {
        return true;
    }
    if (e.head() == "and") {
        bool ok = true;
        for (std::size_t i = 1; i < e.items.size(); ++i) {
            ok = read_effect(p, fr, e.items[i], a) && ok;
        }
        return ok;
    }
    if (e.head() == "not") {
        if (e.items.size() != 2) {
            p.error(e.range, "'not' takes one atom");
            return false;
        }
        auto atom = fr.atom(e.items[1], false);
        if (atom) {
            a.del.push_back(*atom);
        }
        return atom.has_value();
    }
    auto atom = fr.atom(e, false);
    if (atom) {
        a.add.push_back(*atom);
    }
    return atom.has_value();
}

void read_action(Parser& p, const SExpr& e, Domain& d) {
    if (e.items.size() < 2 || !is_name(e.items[1])) {
        p.error(e.range, "expected an action name after ':action'");
        return;
    }
    Action a;
    a.name = e.items[1].atom;
    a.range = e.items[1].range;
    bool has_effect = false;
    for (std::size_t i = 2; i + 1 < e.items.size() + 1; i += 2) {
        const SExpr& key = e.items[i];
        if (i + 1 >= e.items.size()) {
            p.error(key.range, "expected a value after this keyword");
            return;
        }
        const SExpr& value = e.items[i + 1];
        Scope scope{d, &a.params};
        FormulaReader fr(p, scope);
        if (key.is_atom(":parameters")) {
            if (!value.list) {
                p.error(value.range, "expected a parameter list '(?x - type ...)'");
                return;
            }
            a.params = p.typed_list(value.items, 0, true, &d, "the parameters");
            p.report_duplicates(a.params, "parameter");
        } else if (key.is_atom(":precondition")) {
            auto pre = fr.conjunction(value, true, true);
            if (pre) {
                a.precondition = *pre;
            }
        } else if (key.is_atom(":effect")) {
            has_effect = true;
            read_effect(p, fr, value, a);
        } else {
            p.error(key.range, fmt::format("unsupported action field '{}'", key.atom));
        }
    }
    if (!has_effect) {
        p.error(e.range, fmt::format("the action '{}' has no ':effect'", a.name));
    }
    if (d.find_action(a.name) != nullptr) {
        p.error(a.range, fmt::format("the action '{}' is declared twice", a.name));
        return;
    }
    d.actions.push_back(std::move(a));
}

void read_domain_section(Parser& p, const SExpr& e, Domain& d) {
    std::string_view h = e.head();
    if (h == ":requirements") {
        read_requirements(p, e, d);
    } else if (h == ":types") {
        read_types(p, e, d);
    } else if (h == ":constants") {
        auto more = p.typed_list(e.items, 1, false, &d, "(:constants ...)");
        p.report_duplicates(more, "constant", d.constants);
        d.constants.insert(d.constants.end(), more.begin(), more.end());
    } else if (h == ":predicates") {
        read_predicates(p, e, d);
    } else if (h == ":action") {
        read_action(p, e, d);
    } else {
        p.error(e.range, h.empty() ? std::string("expected a domain section '(:keyword ...)'")
                                   : fmt::format("unsupported domain section '{}'", h));
    }
}

/// `(define (KIND name) sections...)`: the name, or nullopt after an error.
std::optional<std::string> read_define(Parser& p, const SExpr& top, std::string_view kind) {
    if (!p.expect_head(top, "define", "at the top of the file")) {
        return std::nullopt;
    }
    if (top.items.size() < 2 || top.items[1].head() != kind || top.items[1].items.size() != 2 ||
        !is_name(top.items[1].items[1])) {
        p.error(top.items.size() < 2 ? top.range : top.items[1].range,
                fmt::format("expected '({} NAME)' after 'define'", kind));
        return std::nullopt;
    }
    return top.items[1].items[1].atom;
}

std::optional<SExpr> read_top(std::uint32_t file, const SourceManager& sources,
                              DiagnosticSink& sink) {
    Reader r(file, sources.text(file), sink);
    return r.read_file(sources);
}

} // namespace

// ---- public -------------------------------------------------------------------------------------

std::string Atom::to_string() const {
    std::string s = "(" + predicate;
    for (const auto& t : args) {
        s += " " + std::string(t.variable ? "?" : "") + t.name;
    }
    return s + ")";
}

std::string Literal::to_string() const {
    return positive ? atom.to_string() : "(not " + atom.to_string() + ")";
}

const Type* Domain::find_type(std::string_view type_name) const {
    for (const auto& t : types) {
        if (t.name == type_name) {
            return &t;
        }
    }
    return nullptr;
}

const Predicate* Domain::find_predicate(std::string_view predicate_name) const {
    for (const auto& p : predicates) {
        if (p.name == predicate_name) {
            return &p;
        }
    }
    return nullptr;
}

const Action* Domain::find_action(std::string_view action_name) const {
    for (const auto& a : actions) {
        if (a.name == action_name) {
            return &a;
        }
    }
    return nullptr;
}

bool Domain::is_subtype(std::string_view sub, std::string_view super) const {
    for (std::string_view t = sub; !t.empty();) {
        if (t == super) {
            return true;
        }
        const Type* info = find_type(t);
        t = info != nullptr ? std::string_view(info->parent) : std::string_view();
    }
    return false;
}

std::optional<Domain> parse_domain(std::uint32_t file, const SourceManager& sources,
                                   DiagnosticSink& sink) {
    auto top = read_top(file, sources, sink);
    if (!top) {
        return std::nullopt;
    }
    Parser p(sink);
    auto name = read_define(p, *top, "domain");
    if (!name) {
        return std::nullopt;
    }
    Domain d;
    d.name = *name;
    d.range = top->items[1].range;
    d.types.push_back({"object", "", {}});
    for (std::size_t i = 2; i < top->items.size(); ++i) {
        read_domain_section(p, top->items[i], d);
    }
    if (p.failed()) {
        return std::nullopt;
    }
    return d;
}

std::optional<Problem> parse_problem(std::uint32_t file, const Domain& domain,
                                     const SourceManager& sources, DiagnosticSink& sink) {
    auto top = read_top(file, sources, sink);
    if (!top) {
        return std::nullopt;
    }
    Parser p(sink);
    auto name = read_define(p, *top, "problem");
    if (!name) {
        return std::nullopt;
    }
    Problem pr;
    pr.name = *name;
    pr.range = top->items[1].range;
    Scope scope{domain, nullptr, &pr};
    FormulaReader fr(p, scope);
    for (std::size_t i = 2; i < top->items.size(); ++i) {
        const SExpr& e = top->items[i];
        std::string_view h = e.head();
        if (h == ":domain" && e.items.size() == 2 && is_name(e.items[1])) {
            pr.domain_name = e.items[1].atom;
            if (pr.domain_name != domain.name) {
                p.error(e.items[1].range, fmt::format("the problem is for domain '{}', not '{}'",
                                                      pr.domain_name, domain.name));
            }
        } else if (h == ":requirements") {
            Domain scratch;
            read_requirements(p, e, scratch);
        } else if (h == ":objects") {
            auto more = p.typed_list(e.items, 1, false, &domain, "(:objects ...)");
            auto earlier = domain.constants;
            earlier.insert(earlier.end(), pr.objects.begin(), pr.objects.end());
            p.report_duplicates(more, "object", earlier);
            pr.objects.insert(pr.objects.end(), more.begin(), more.end());
        } else if (h == ":init") {
            for (std::size_t k = 1; k < e.items.size(); ++k) {
                if (auto a = fr.atom(e.items[k], false)) {
                    pr.init.push_back(*a);
                }
            }
        } else if (h == ":goal" && e.items.size() == 2) {
            if (auto g = fr.conjunction(e.items[1], false, false)) {
                pr.goal = *g;
            }
        } else {
            p.error(e.range, h.empty() ? std::string("expected a problem section '(:keyword ...)'")
                                       : fmt::format("unsupported problem section '{}'", h));
        }
    }
    if (p.failed()) {
        return std::nullopt;
    }
    return pr;
}

const TypedName* find_object(const Domain& d, const Problem& p, std::string_view name) {
    for (const auto& c : d.constants) {
        if (c.name == name) {
            return &c;
        }
    }
    for (const auto& o : p.objects) {
        if (o.name == name) {
            return &o;
        }
    }
    return nullptr;
}

} // namespace catplan::pddl
