#pragma once
// The PDDL reader's parts (pddl.hpp), private to the pddl layer: s-expressions (reader.cpp), the
// checks and typed lists every section shares (reader.cpp), and formulas, effects, costs and
// numeric values (formulas.cpp). parser.cpp reads the sections with them.

#include "catplan/pddl/pddl.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::pddl::detail {

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

/// The one top-level list of a file; nullopt after reporting a problem.
std::optional<SExpr> read_top(std::uint32_t file, const SourceManager& sources,
                              DiagnosticSink& sink);

/// A PDDL name: not a variable, keyword or `-`.
bool is_name(const SExpr& e);

/// `?x`.
bool is_variable(const SExpr& e);

/// The types a typed list may name: those of `known` (none in `:types` itself), and unions
/// `(either ...)` of them, added to `unions` (or found there when null: a problem's objects).
struct TypeScope {
    const Domain* known = nullptr;
    Domain* unions = nullptr;
};

class Parser {
public:
    explicit Parser(DiagnosticSink& sink) : sink_(sink) {}

    bool failed() const { return errors_ > 0; }

    /// Malformed input (exit 2).
    Diagnostic& error(SourceRange r, std::string message);

    /// Valid PDDL that catplan does not support (exit 3).
    Diagnostic& unsupported(SourceRange r, std::string message);

    /// Something the user should know that does not stop the reading.
    Diagnostic& warning(SourceRange r, std::string message);

    /// `a b - t c` (names or variables) into typed names; the type of each is checked against
    /// the scope (a union `(either a b)` becomes its type, see pddl.hpp).
    std::vector<TypedName> typed_list(const std::vector<SExpr>& items, std::size_t from,
                                      bool variables, const TypeScope& scope,
                                      std::string_view what);

    /// Reports each name of `names` declared before in `names` or in `earlier`; `what` is
    /// "parameter", "constant" or "object".
    void report_duplicates(const std::vector<TypedName>& names, std::string_view what,
                           const std::vector<TypedName>& earlier = {});

    /// Whether a list starts with the keyword.
    bool expect_head(const SExpr& e, std::string_view keyword, std::string_view what);

private:
    /// The type a `- T` names, or nullopt after an error.
    std::optional<std::string> type_of(const SExpr& t, const TypeScope& scope,
                                       std::string_view what);
    /// The union of the member types (their least set), added to d when new.
    std::optional<std::string> union_type(const SExpr& t, const TypeScope& scope);

    DiagnosticSink& sink_;
    int errors_ = 0;
};

/// Puts d.types in order, parents before children (declaration order otherwise), each type's
/// parents reduced to those that are no ancestor of another; false after reporting a cycle.
bool order_types(Parser& p, Domain& d);

/// The scope a formula is read in: the action's parameters (or none), and the known constants.
struct Scope {
    const Domain& domain;
    const std::vector<TypedName>* params = nullptr;
    const Problem* problem = nullptr;
    const ObjectIndex* objects = nullptr; ///< the domain's constants and the problem's objects
};

class FormulaReader {
public:
    FormulaReader(Parser& p, const Scope& s) : p_(p), s_(s) {}

    /// An atom of a declared predicate (or `(= x y)` when allowed), arguments checked.
    std::optional<Atom> atom(const SExpr& e, bool allow_equality);

    /// A conjunction of literals (`(and ...)`, one literal, or `()`).
    std::optional<std::vector<Literal>> conjunction(const SExpr& e, bool allow_equality,
                                                    bool allow_negative);

    /// A variable of the scope or a known constant or object.
    std::optional<Term> term(const SExpr& e);

    /// An action's effect into its add and delete lists and its cost; false after an error.
    bool effect(const SExpr& e, Action& a);

    /// `(= (f a b) N)` of a problem's :init into pr.values; false after an error.
    bool init_value(const SExpr& e, Problem& pr);

private:
    /// `(head terms...)` as an Atom, each term read (every error reported); nullopt after one.
    std::optional<Atom> with_terms(const SExpr& e);
    /// Whether the atom's arguments fit the parameters in number and type (else reported);
    /// `what` is "predicate" or "function".
    bool typed_args(const Atom& a, const std::vector<TypedName>& params, std::string_view what);
    /// A function term `(f a ...)` of a declared function, arguments checked.
    std::optional<Atom> function_term(const SExpr& e);
    /// The T of `(increase (total-cost) T)`.
    std::optional<CostTerm> cost_term(const SExpr& e);
    /// A whole non-negative number, or nullopt after an error naming `what`.
    std::optional<std::int64_t> number(const SExpr& e, std::string_view what);
    /// Reports `head` as a construct catplan does not support, when it is one; true if so.
    bool unsupported_construct(const SExpr& e);

    Parser& p_;
    const Scope& s_;
};

} // namespace catplan::pddl::detail
