#pragma once
// PDDL as written: domains and problems of the STRIPS fragment with :typing,
// :negative-preconditions, :equality and :action-costs, read into a small syntax tree with source
// ranges.
//
// The reader is hand-written: an s-expression lexer (`;` comments, case-insensitive names, which
// are lowered as PDDL prescribes; a `?` starts a new token, so `aircraft?a` is a name and a
// variable, as other PDDL readers split it) and one function per construct. Meaning (types exist,
// arities agree) is checked here too, so the importer sees a sound tree. Every error is a located
// Diagnostic naming the construct, of one of two kinds:
//   - malformed input (exit 2): unbalanced parentheses, an unknown predicate, type or requirement,
//     a wrong arity, a parameter, constant or object declared twice;
//   - valid PDDL that catplan does not support (exit 3, Diagnostic::unsupported): a requirement
//     such as `:conditional-effects` or `:durative-actions`, and a construct such as `forall`,
//     `when`, `or` or a numeric fluent other than an action's cost, each by name.
// The text must be UTF-8 (a byte-order mark is skipped; LF, CRLF and CR end lines), and
// parentheses nest at most kMaxNesting (256) deep, so the recursive reader and the tree's
// destructor stay within the stack. docs/pddl-support.md lists what is accepted.
//
// Types form a directed acyclic graph below `object`: a type listed twice in `:types` (storage's
// `area - object` and `area - surface`) has every parent it is given, less those that are
// ancestors of another; a union `(either a b)` is a type of its own, named "(either a b)" (its
// members sorted), whose members a and b have it as a parent. An object is of its declared type
// and of every ancestor of it, so an object of type a or b fits a parameter of type (either a b).
//
//   auto d = parse_domain(file, sources, sink);          // nullopt when there were errors
//   auto p = parse_problem(file2, *d, sources, sink);

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
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
    std::string name; // "(either a b)" for a union type
    /// The types it is directly below: none for "object"; in the order declared.
    std::vector<std::string> parents;
    SourceRange range;
};

struct Predicate {
    std::string name;
    std::vector<TypedName> params;
    SourceRange range;
};

/// A numeric function `(road-length ?from ?to - location) - number`: total-cost, and the static
/// ones an action's cost reads.
struct Function {
    std::string name;
    std::vector<TypedName> params;
    SourceRange range;
};

/// What `(increase (total-cost) T)` adds: a number, or the value of a function in the problem
/// (`(road-length ?from ?to)`, an Atom whose predicate is the function).
struct CostTerm {
    std::int64_t number = 0;
    std::optional<Atom> fluent;
    SourceRange range;

    /// "5" or "(road-length ?from ?to)".
    std::string to_string() const;
};

struct Action {
    std::string name;
    std::vector<TypedName> params;
    std::vector<Literal> precondition; // a conjunction
    std::vector<Atom> add, del;
    /// What the action adds to total-cost, summed (none: it costs 0 under a cost metric).
    std::vector<CostTerm> cost;
    SourceRange range;
};

struct Domain {
    std::string name;
    std::vector<std::string> requirements;
    std::vector<Type> types; // "object" first, then in declaration order, parents before children
    std::vector<TypedName> constants;
    std::vector<Predicate> predicates;
    std::vector<Function> functions;
    std::vector<Action> actions;
    SourceRange range;

    const Type* find_type(std::string_view type_name) const;
    const Predicate* find_predicate(std::string_view predicate_name) const;
    const Function* find_function(std::string_view function_name) const;
    const Action* find_action(std::string_view action_name) const;
    /// Whether `sub` is `super` or one of its descendants.
    bool is_subtype(std::string_view sub, std::string_view super) const;
    /// Whether one object can be of both types (one is below the other, or a type is below both).
    bool may_share(std::string_view a, std::string_view b) const;
    /// Whether an action says what it costs (`(increase (total-cost) ...)`).
    bool has_costs() const;
};

/// `(= (road-length a b) 5)` in a problem's :init.
struct FunctionValue {
    Atom term;
    std::int64_t value = 0;
    SourceRange range;
};

struct Problem {
    std::string name;
    std::string domain_name;
    std::vector<TypedName> objects;
    std::vector<Atom> init;
    /// The values of the functions given in :init (total-cost's included).
    std::vector<FunctionValue> values;
    std::vector<Literal> goal; // a conjunction; a negative literal asks that the fact not hold
    /// `(:metric minimize (total-cost))`: steps cost what their actions say (else 1 each).
    bool metric = false;
    SourceRange range;
    /// Made from states (steps.hpp's problem_of): goal conditions no PDDL goal could say.
    std::size_t unwritten_goal_conditions = 0;

    /// The value :init gives a ground function term, or nullopt.
    std::optional<std::int64_t> value_of(const Atom& term) const;
};

/// Reads a domain; every error goes to sink; nullopt when there was one.
std::optional<Domain> parse_domain(std::uint32_t file, const SourceManager& sources,
                                   DiagnosticSink& sink);

/// Reads a problem of `domain` (objects typed, atoms checked against its predicates); every error
/// goes to sink; nullopt when there was one.
std::optional<Problem> parse_problem(std::uint32_t file, const Domain& domain,
                                     const SourceManager& sources, DiagnosticSink& sink);

/// The constants of a domain and the objects of a problem by name, in a hash table: a problem's
/// atoms and a plan's steps look up thousands of names among hundreds of objects. It follows the
/// domain and the problem as they grow (the table is made again when a list has grown or moved).
class ObjectIndex {
public:
    ObjectIndex(const Domain& d, const Problem& p) : d_(&d), p_(&p) {}

    /// The first constant of the domain with this name, else the first object of the problem, or
    /// nullptr.
    const TypedName* find(std::string_view name) const;

private:
    const Domain* d_;
    const Problem* p_;
    mutable std::unordered_map<std::string_view, const TypedName*> index_;
    // The lists the table was made from, and their lengths then.
    mutable const TypedName* constants_ = nullptr;
    mutable const TypedName* objects_ = nullptr;
    mutable std::size_t num_constants_ = 0, num_objects_ = 0;
};

} // namespace catplan::pddl
