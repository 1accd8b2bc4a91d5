#pragma once
// PDDL as written: domains and problems of the STRIPS fragment with :typing,
// :negative-preconditions and :equality, read into a small syntax tree with source ranges.
//
// The reader is hand-written: an s-expression lexer (`;` comments, case-insensitive names, which
// are lowered as PDDL prescribes) and one function per construct. Every error is a located
// Diagnostic naming the construct: unbalanced parentheses, an unknown predicate or type, a wrong
// arity, an unsupported requirement (`:conditional-effects`) or construct (`forall`, `or`), a
// parameter, constant or object declared twice. Meaning (types exist, arities agree) is checked
// here too, so the importer sees a sound tree. The text must be UTF-8 (a byte-order mark is
// skipped; LF, CRLF and CR end lines), and parentheses nest at most kMaxNesting (256) deep, so the
// recursive reader and the tree's destructor stay within the stack. docs/pddl-support.md lists
// what is accepted.
//
//   auto d = parse_domain(file, sources, sink);          // nullopt when there were errors
//   auto p = parse_problem(file2, *d, sources, sink);

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"

#include <optional>
#include <string>
#include <vector>

namespace catplan::pddl {

/// A name with its declared type (`?x - block`, `a - block`); the type is "object" when untyped.
struct TypedName {
    std::string name; // variables without the `?`
    std::string type;
    SourceRange range;
};

/// A term of an atom: a variable of the action (`?x`, stored without `?`) or a constant.
struct Term {
    std::string name;
    bool variable = false;
    SourceRange range;

    friend bool operator==(const Term& a, const Term& b) {
        return a.name == b.name && a.variable == b.variable;
    }
};

/// `(on ?x ?y)`, `(handempty)`, or the equality `(= ?x ?y)` (predicate "=").
struct Atom {
    std::string predicate;
    std::vector<Term> args;
    SourceRange range;

    /// "(on ?x ?y)" as written (variables with `?`).
    std::string to_string() const;
};

/// An atom or its negation.
struct Literal {
    Atom atom;
    bool positive = true;
    SourceRange range;

    /// "(on ?x ?y)" or "(not (on ?x ?y))".
    std::string to_string() const;
};

struct Type {
    std::string name;
    std::string parent; // empty for "object"
    SourceRange range;
};

struct Predicate {
    std::string name;
    std::vector<TypedName> params;
    SourceRange range;
};

struct Action {
    std::string name;
    std::vector<TypedName> params;
    std::vector<Literal> precondition; // a conjunction
    std::vector<Atom> add, del;
    SourceRange range;
};

struct Domain {
    std::string name;
    std::vector<std::string> requirements;
    std::vector<Type> types; // "object" first, then in declaration order, parents before children
    std::vector<TypedName> constants;
    std::vector<Predicate> predicates;
    std::vector<Action> actions;
    SourceRange range;

    const Type* find_type(std::string_view type_name) const;
    const Predicate* find_predicate(std::string_view predicate_name) const;
    const Action* find_action(std::string_view action_name) const;
    /// Whether `sub` is `super` or one of its descendants.
    bool is_subtype(std::string_view sub, std::string_view super) const;
};

struct Problem {
    std::string name;
    std::string domain_name;
    std::vector<TypedName> objects;
    std::vector<Atom> init;
    std::vector<Literal> goal; // a conjunction
    SourceRange range;
};

/// Reads a domain; every error goes to sink; nullopt when there was one.
std::optional<Domain> parse_domain(std::uint32_t file, const SourceManager& sources,
                                   DiagnosticSink& sink);

/// Reads a problem of `domain` (objects typed, atoms checked against its predicates); every error
/// goes to sink; nullopt when there was one.
std::optional<Problem> parse_problem(std::uint32_t file, const Domain& domain,
                                     const SourceManager& sources, DiagnosticSink& sink);

/// The type of a constant of the domain or an object of the problem, or nullptr.
const TypedName* find_object(const Domain& d, const Problem& p, std::string_view name);

} // namespace catplan::pddl
