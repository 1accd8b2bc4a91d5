#pragma once
// Conjunctive queries over a source schema D: the image of a target object under a schema map.
//
//   BreadSliced => @join begin block::Block; C::Color; hasColor(block) == C; C == "purple" end
//
// A query has named variables ("nodes"), each over a source object or a source attribute type,
// and equations between terms: a variable, a path of homs from a variable, an attribute of such a
// path, or a literal. Its *shape* is a state on D, the free (partial) instance of what the query
// mentions: every variable is a part (or, for a value variable, an attribute variable), a
// mentioned path creates the parts along it, equations merge parts and values (congruence
// closure), and a literal makes a value concrete; two different literals for one value are an
// error. An assignment of the query in a state X is a morphism Q -> X; Δ(X)(c') is the set of
// them (the limit in Set).
//
// Only what the query mentions is in its shape: a hom of a part that the query does not go
// through stays unset, and the homomorphism search treats an unset domain cell as no
// constraint. On total states this gives the same assignments as the fully free instance (the
// extra parts would be forced); on partial states (a rule's K) a part whose hom is unset still has
// its tuple unless the query goes through that hom, which matches delta migration.
//
//   Query q(colorblocks);
//   q.add_variable("block", block_ob);
//   q.add_equation(Term::path("block", {}, has_color), Term::constant(Value::string("purple")));

#include "catplan/acset/acset.hpp"
#include "catplan/acset/value.hpp"
#include "catplan/base/id.hpp"
#include "catplan/base/source.hpp"
#include "catplan/colimit/presentation.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::migrate {

using acset::ACSet;
using acset::Value;
using schema::SchemaPtr;

/// A term of a query: `var`, `var.h1...hn`, `var.h1...hn.attr`, or a literal constant.
struct Term {
    std::string var; // empty for a literal
    std::vector<HomId> homs;
    std::optional<AttrId> attr;
    Value literal; // a constant when var is empty
    SourceRange range;

    /// The term `var ⋅ homs (⋅ attr)`.
    static Term path(std::string var, std::vector<HomId> homs = {},
                     std::optional<AttrId> attr = std::nullopt, SourceRange range = {});
    /// A literal constant.
    static Term constant(Value value, SourceRange range = {});

    bool is_literal() const { return var.empty(); }
};

/// A named variable of a query and where it lives in the query's shape.
struct QueryNode {
    std::string name;
    bool is_value = false; // over an attribute type (value) or an object (part)
    ObId ob;               // object nodes
    AttrTypeId type;       // value nodes
    SourceRange range;
};

/// A problem found while building a query, located at the term or declaration.
struct QueryProblem {
    std::string message;
    SourceRange range;
};

/// Where a term lands in a query's shape: a part of an object, or a value (a variable of the
/// shape or, after a literal, a constant).
struct QueryElement {
    bool is_value = false;
    ObId ob;
    Part part = kNoPart;
    AttrTypeId type;
    Value value;
};

class Query {
public:
    /// An empty query (the terminal one, `@unit`, until variables are added) over a schema.
    explicit Query(SchemaPtr source);

    /// The query with one variable over `ob` and nothing else (a delta entry `c' => ob`).
    static Query representable(SchemaPtr source, ObId ob, std::string name = "x");

    const SchemaPtr& source() const { return source_; }

    /// Adds a variable over an object; false (with a problem) when the name is taken.
    bool add_variable(std::string name, ObId ob, SourceRange range = {});
    /// Adds a variable over an attribute type; false (with a problem) when the name is taken.
    bool add_value_variable(std::string name, AttrTypeId type, SourceRange range = {});
    /// Adds the equation lhs == rhs; false (with problems) when a term is ill-formed, the two
    /// sides have different types, or two different literals meet.
    bool add_equation(const Term& lhs, const Term& rhs, SourceRange range = {});
    /// Mentions a term (creating the parts along its path) and returns a handle for locate();
    /// nullopt (with a problem) when it is ill-formed.
    std::optional<std::uint32_t> add_term(const Term& term);

    /// Makes the query unsatisfiable (`@empty`): it has no assignments in any state.
    void set_empty() { empty_ = true; }

    bool is_empty() const { return empty_; }

    /// The variables, in declaration order.
    const std::vector<QueryNode>& nodes() const { return nodes_; }

    /// The index of the variable with this name.
    std::optional<std::size_t> find_node(std::string_view name) const;

    /// The first object variable, if any (the one a tuple of the query is named after).
    std::optional<std::size_t> first_object_node() const;

    /// Every problem met while building, in order.
    const std::vector<QueryProblem>& problems() const { return problems_; }

    /// The shape of the query (built on first use after an edit).
    const ACSet& state() const;
    /// Where a term handle (from add_term) lands in state().
    QueryElement locate(std::uint32_t handle) const;

    /// Where node i lands in state().
    QueryElement locate_node(std::size_t i) const;

    /// A term from a node that reaches part p of ob in state() (used to re-express morphisms).
    Term witness(ObId ob, Part p) const;
    /// A term that reaches value v of type t in state(): a literal for a constant, else a path
    /// from a node ending in an attribute, or a value node.
    Term witness_value(AttrTypeId t, const Value& v) const;

    /// One object variable, no equations, nothing else mentioned: Δ is the object's parts.
    bool is_plain() const;

private:
    // A node of the shape: a part or a value node of the presentation.
    struct Handle {
        bool is_value = false;
        colimit::Node node = colimit::kNoNode;
    };

    // How a node of the shape was first reached: from variable `node` along `homs` (then `attr`).
    struct Origin {
        std::uint32_t node;
        std::vector<HomId> homs;
        std::optional<AttrId> attr;
    };

    // A resolved term: a node of the shape, or a literal (which has no node of its own).
    struct Resolved {
        std::optional<Handle> handle;
        Value literal;
    };

    std::optional<Resolved> resolve(const Term& t, SourceRange where);
    colimit::Node follow(colimit::Node from, Origin origin);
    void take_problems();
    QueryElement locate(const Handle& h) const;
    void build() const;

    SchemaPtr source_;
    std::vector<QueryNode> nodes_;
    std::vector<Handle> node_handles_; // per variable
    std::vector<Handle> handles_;      // per add_term
    colimit::Presentation shape_;
    std::vector<Origin> part_origin_, value_origin_; // per node of the presentation
    std::size_t problems_taken_ = 0; // the presentation's problems already in problems_
    std::vector<QueryProblem> problems_;
    std::size_t num_equations_ = 0;
    bool empty_ = false;

    // Built shape.
    mutable std::optional<colimit::Presentation::Instance> built_;
    mutable std::vector<std::vector<colimit::Node>> reps_;  // per ob: the node of each part
    mutable std::vector<std::vector<colimit::Node>> vreps_; // per type: the node of each var
};

/// The part reached from p along a path of x's homs, or kNoPart once a hom on the way is unset.
Part follow(const ACSet& x, Part p, const std::vector<HomId>& homs);

} // namespace catplan::migrate
