#pragma once
// A presentation written in the language (generators `x::Block`, equations `f(x) == y`,
// `a(x) == "red"`) turned into a state by congruence closure: the colimit of its generators and
// equations. @acset_colim builds a free instance from it (undefined homs get new parts, undefined
// attributes new variables); rule blocks build partial states (undefined cells stay unset). This
// class reads the language and words its errors; the engine is colimit::Presentation.
//
// Each operation that can find bad input reports it to the sink it is given: a rule elaborates
// some blocks twice (Pre into L and into each condition) and reports each error only once.

#include "catplan/acset/acset.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/colimit/presentation.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/schema/schema.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace catplan::lang::detail {

/// A term of the presentation: a part node, a value node (both resolved to their class when
/// returned), or a literal.
struct Term {
    enum class Kind { Part, Value, Literal } kind;
    std::uint32_t node = 0;
    const Expr* expr = nullptr;
};

class Colimit {
public:
    /// An empty presentation on s; `inferred` (may be null) locates kinds inferred from literals.
    Colimit(std::shared_ptr<const schema::Schema> s, const InferredKinds* inferred);

    const schema::Schema& schema() const { return p_.schema(); }

    /// Declares the generators of `x::T` or `(x, y)::T` (T an object or an attribute type).
    void declare(const Expr& st, DiagnosticSink& sink);
    /// The term an expression denotes (a generator, a hom or attribute applied to a term, or a
    /// literal), creating the images it names; nullopt after an error.
    std::optional<Term> eval(const Expr& e, DiagnosticSink& sink);
    /// Imposes the equation `lhs == rhs` and closes under congruence.
    void equation(const Expr& st, DiagnosticSink& sink);
    /// Gives every undefined hom a new part and every undefined attribute a new variable; false
    /// (reported at `at`) when more than max_fresh new parts are needed.
    bool complete(SourceRange at, std::size_t max_fresh, DiagnosticSink& sink);

    /// "a part of Block", "a value of Color", "a literal".
    std::string describe(const Term& t);

    /// Rules: a named variable K takes over from Pre (so values flow by name to Eff).
    void declare_value(const std::string& name, AttrTypeId t, SourceRange range);

    /// Rules: a generator declared again with the same type is the same generator.
    void allow_redeclare() { allow_redeclare_ = true; }

    /// The nodes of a state added to the presentation.
    struct StateNodes {
        std::vector<std::vector<std::uint32_t>> parts; // per object, per part
        std::vector<std::vector<std::uint32_t>> vars;  // per attribute type, per variable
    };

    /// Adds a built state, part for part and cell for cell: its parts and variables become
    /// generators named as they are (a name that two share names neither), declared at `range`.
    StateNodes add_state(const acset::ACSet& x, SourceRange range);

    /// The generator with this name: its term (node resolved) and declaration range.
    std::optional<std::pair<Term, SourceRange>> generator(const std::string& name);

    /// The generators' names in declaration order.
    const std::vector<std::string>& generator_names() const { return gen_order_; }

    ObId part_ob(std::uint32_t node) const { return p_.part_ob(node); }

    AttrTypeId value_type(std::uint32_t node) const { return p_.value_type(node); }

    /// A partial presentation (rules): undefined homs and attributes stay unset.
    acset::ACSet build_partial();

    /// A free presentation (instances): after completion every hom and attribute is defined, so
    /// building it partially gives the whole state.
    acset::ACSet build() { return build_partial(); }

    /// After a build: the part or value a node became.
    Part built_part(std::uint32_t node) const { return built_->part_of[node]; }

    acset::Value built_value(std::uint32_t node) const { return built_->value_of[node]; }

private:
    struct Gen {
        Term term;
        SourceRange range;
    };

    Term resolved(Term t) const;
    void report_problems(DiagnosticSink& sink);

    const InferredKinds* inferred_;
    colimit::Presentation p_;
    std::size_t problems_reported_ = 0; // the presentation's problems already reported
    std::unordered_map<std::string, Gen> gens_;
    std::vector<std::string> gen_order_;
    bool allow_redeclare_ = false;
    std::optional<colimit::Presentation::Instance> built_;
};

} // namespace catplan::lang::detail
