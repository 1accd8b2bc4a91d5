// The PDDL reader's s-expressions, typed lists and type graph (detail/reader.hpp).

#include "catplan/pddl/detail/reader.hpp"

#include "catplan/base/ascii.hpp"
#include "catplan/base/unicode.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <unordered_set>

namespace catplan::pddl::detail {

namespace {

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

    // A name or variable ends at a space, a parenthesis, a comment, or a `?` that is not its
    // first character: `aircraft?a` is two tokens, as other PDDL readers split it.
    bool ends_token(std::size_t start) const {
        char c = text_[i_];
        return std::isspace(static_cast<unsigned char>(c)) || c == '(' || c == ')' || c == ';' ||
               (c == '?' && i_ > start);
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
            while (i_ < text_.size() && !ends_token(start)) {
                ++i_;
            }
            e.atom.assign(text_.substr(start, i_ - start));
            for (char& c : e.atom) {
                c = ascii_lower(c);
            }
            e.range = range(start, i_);
            return e;
        }
        if (depth > kMaxNesting) {
            sink_.error(range(i_, i_ + 1), "nested deeper than 256 levels");
            return std::nullopt;
        }
        e.list = true;
        e.items.reserve(4); // most lists are an atom (head) and a few items: no regrowth
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

Type* find_mutable_type(Domain& d, std::string_view name) {
    for (auto& t : d.types) {
        if (t.name == name) {
            return &t;
        }
    }
    return nullptr;
}

} // namespace

std::optional<SExpr> read_top(std::uint32_t file, const SourceManager& sources,
                              DiagnosticSink& sink) {
    Reader r(file, sources.text(file), sink);
    return r.read_file(sources);
}

bool is_name(const SExpr& e) {
    return !e.list && !e.atom.empty() && e.atom[0] != '?' && e.atom[0] != ':' && e.atom != "-";
}

bool is_variable(const SExpr& e) {
    return !e.list && e.atom.size() > 1 && e.atom[0] == '?';
}

// ---- Parser -------------------------------------------------------------------------------------

Diagnostic& Parser::error(SourceRange r, std::string message) {
    ++errors_;
    return sink_.error(r, std::move(message));
}

Diagnostic& Parser::unsupported(SourceRange r, std::string message) {
    ++errors_;
    return sink_.unsupported(r, std::move(message));
}

Diagnostic& Parser::warning(SourceRange r, std::string message) {
    return sink_.warning(r, std::move(message));
}

std::optional<std::string> Parser::union_type(const SExpr& t, const TypeScope& scope) {
    if (scope.known == nullptr) {
        unsupported(t.range, "unsupported construct 'either' in (:types ...) (a type below a "
                             "union of types)");
        return std::nullopt;
    }
    const Domain& d = *scope.known;
    std::vector<std::string> members;
    bool ok = t.items.size() > 1;
    if (!ok) {
        error(t.range, "'either' needs at least one type");
    }
    for (std::size_t i = 1; i < t.items.size(); ++i) {
        const SExpr& m = t.items[i];
        if (!is_name(m)) {
            error(m.range, "expected a type name in '(either ...)'");
            ok = false;
        } else if (d.find_type(m.atom) == nullptr) {
            error(m.range, fmt::format("unknown type '{}'", m.atom));
            ok = false;
        } else {
            members.push_back(m.atom);
        }
    }
    if (!ok) {
        return std::nullopt;
    }
    // The least members: one below another adds nothing to the union.
    std::vector<std::string> least;
    for (const auto& m : members) {
        bool below = std::any_of(members.begin(), members.end(), [&](const std::string& other) {
            return other != m && d.is_subtype(m, other);
        });
        if (!below && std::find(least.begin(), least.end(), m) == least.end()) {
            least.push_back(m);
        }
    }
    std::sort(least.begin(), least.end());
    if (least.size() == 1) {
        return least[0];
    }
    std::string name = fmt::format("(either {})", fmt::join(least, " "));
    if (d.find_type(name) != nullptr) {
        return name;
    }
    if (scope.unions == nullptr) {
        unsupported(t.range, fmt::format("an object of type {}, a union of types the domain does "
                                         "not use (a problem's objects have the domain's types)",
                                         name));
        return std::nullopt;
    }
    Domain& u = *scope.unions;
    u.types.push_back({name, {"object"}, t.range});
    for (const auto& m : least) {
        find_mutable_type(u, m)->parents.push_back(name);
    }
    order_types(*this, u);
    return name;
}

std::optional<std::string> Parser::type_of(const SExpr& t, const TypeScope& scope,
                                           std::string_view what) {
    if (t.head() == "either") {
        return union_type(t, scope);
    }
    if (!is_name(t)) {
        error(t.range, fmt::format("expected a type name in {}", what));
        return std::nullopt;
    }
    if (scope.known != nullptr && scope.known->find_type(t.atom) == nullptr) {
        // Reported once here; the name is kept, so that its uses are not reported again.
        error(t.range, fmt::format("unknown type '{}'", t.atom));
    }
    return t.atom;
}

std::vector<TypedName> Parser::typed_list(const std::vector<SExpr>& items, std::size_t from,
                                          bool variables, const TypeScope& scope,
                                          std::string_view what) {
    std::vector<TypedName> out;
    std::size_t untyped_from = 0;
    for (std::size_t i = from; i < items.size(); ++i) {
        const SExpr& e = items[i];
        if (e.is_atom("-")) {
            if (i + 1 >= items.size()) {
                error(e.range, fmt::format("expected a type after '-' in {}", what));
                return out;
            }
            auto t = type_of(items[++i], scope, what);
            if (!t) {
                continue;
            }
            for (std::size_t k = untyped_from; k < out.size(); ++k) {
                out[k].type = *t;
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

void Parser::report_duplicates(const std::vector<TypedName>& names, std::string_view what,
                               const std::vector<TypedName>& earlier) {
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

bool Parser::expect_head(const SExpr& e, std::string_view keyword, std::string_view what) {
    if (!e.list || e.head() != keyword) {
        error(e.range, fmt::format("expected '({} ...)' {}", keyword, what));
        return false;
    }
    return true;
}

bool order_types(Parser& p, Domain& d) {
    std::vector<Type> pending = std::move(d.types);
    d.types.clear();
    std::unordered_set<std::string> placed;
    bool ok = true;
    while (!pending.empty()) {
        auto it = std::find_if(pending.begin(), pending.end(), [&](const Type& t) {
            return std::all_of(t.parents.begin(), t.parents.end(),
                               [&](const std::string& q) { return placed.count(q) != 0; });
        });
        if (it == pending.end()) {
            // A cycle: reported once, and cut (the type goes below object) so that the type
            // graph stays acyclic for the checks that follow.
            it = pending.begin();
            p.error(it->range, fmt::format("the type '{}' is its own ancestor", it->name));
            it->parents = {"object"};
            ok = false;
        }
        placed.insert(it->name);
        d.types.push_back(std::move(*it));
        pending.erase(it);
    }
    // A parent that is an ancestor of another parent says nothing more.
    for (auto& t : d.types) {
        std::vector<std::string> kept;
        for (const auto& q : t.parents) {
            bool implied = std::any_of(t.parents.begin(), t.parents.end(),
                                       [&](const auto& r) { return r != q && d.is_subtype(r, q); });
            if (!implied && std::find(kept.begin(), kept.end(), q) == kept.end()) {
                kept.push_back(q);
            }
        }
        t.parents = std::move(kept);
    }
    return ok;
}

} // namespace catplan::pddl::detail
