#pragma once
// Presentations of states by generators and equations: the one engine behind the language's
// @acset_colim and rule blocks, conjunctive queries' shapes, Σ's pushforward and pushouts.
//
// A presentation has part nodes (each of an object) and value nodes (each of an attribute type),
// dense ids in creation order, separately for parts and values. A part node has at most one image
// under each hom (a part node) and each attribute (a value node): hom() and attr() make it when
// there is none, set_hom() and set_attr() give it. Equations identify two part nodes or two value
// nodes; the closure under congruence follows at once (identified parts have identified images).
// A literal makes a value concrete; two different literals for one value are a problem.
//
//   Presentation p(schema);
//   Node b = p.add_part(block, "b");                        // a generator b::Block
//   p.set_literal(p.attr(b, has_color), Value::string("red"));   // hasColor(b) == "red"
//   p.equate_parts(p.hom(b, on), p.add_part(block, "c"));   // on(b) == c
//   auto x = p.instance();                                  // the state, or the problem
//
// The state (build) has one part per class of part nodes, in the order of each class's first node,
// and one variable per class of value nodes without a literal, in the order of its first node or
// (VariableOrder::Cells) of the first cell that holds it; a part or variable takes the name of the
// first named node of its class. A hom or attribute no node defines stays unset (a partial state,
// as a rule block is); complete() first gives every part a part for each hom and a value for each
// attribute, and with `equations` imposes the schema's path equations (a chase), so that the
// state is the free instance of the presentation.
//
// Problems are data (problems()): two literals that meet (with both values and where each was
// given), and a part limit that an infinite free instance reaches. The caller words them.

#include "catplan/acset/acset.hpp"
#include "catplan/base/result.hpp"
#include "catplan/base/source.hpp"
#include "catplan/base/union_find.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::colimit {

using acset::ACSet;
using acset::Value;

/// A part node or a value node of a presentation.
using Node = std::uint32_t;
/// No node: what hom() returns once the part limit is reached.
inline constexpr Node kNoNode = std::numeric_limits<Node>::max();

enum class PresentationProblemKind : std::uint8_t {
    ConflictingLiterals, // two different literals for one value
    TooManyParts,        // the part limit was reached
};

/// One problem of a presentation, as data.
struct PresentationProblem {
    PresentationProblemKind kind = PresentationProblemKind::ConflictingLiterals;
    Value first;             // ConflictingLiterals: the value's literal
    Value second;            // ConflictingLiterals: the different literal that met it
    SourceRange first_range; // ConflictingLiterals: where `first` was given
    SourceRange where;       // ConflictingLiterals: the equation or literal that made them meet
    AttrId attr;             // ConflictingLiterals: the attribute of two identified parts whose
                             // values met, when that is how they met (else invalid)
    HomId hom;               // TooManyParts: the hom that needed one part more
    std::string message;     // in words
};

class Presentation {
public:
    explicit Presentation(schema::SchemaPtr schema);

    const schema::Schema& schema() const { return *schema_; }

    /// A new part node of ob (a generator when named); kNoNode past the part limit.
    Node add_part(ObId ob, std::string_view name = {});
    /// A new value node of type t (an unknown; a generator when named).
    Node add_value(AttrTypeId t, std::string_view name = {});

    std::size_t num_part_nodes() const { return parts_.size(); }

    std::size_t num_value_nodes() const { return values_.size(); }

    ObId part_ob(Node n) const { return parts_[n].ob; }

    AttrTypeId value_type(Node v) const { return values_[v].type; }

    /// The part node h reaches from part node n (its class), made when there is none; kNoNode
    /// past the part limit.
    Node hom(Node n, HomId h);
    /// The value node attribute a holds at part node n, made when there is none.
    Node attr(Node n, AttrId a);
    /// The end of the path `homs` from part node n, made as needed; kNoNode past the part limit.
    Node path(Node n, const std::vector<HomId>& homs);
    /// The equation h(n) == target.
    void set_hom(Node n, HomId h, Node target, SourceRange where = {});
    /// The equation a(n) == value.
    void set_attr(Node n, AttrId a, Node value, SourceRange where = {});
    /// The equation a == b between part nodes of one object, closed under congruence.
    void equate_parts(Node a, Node b, SourceRange where = {});
    /// The equation a == b between value nodes of one type.
    void equate_values(Node a, Node b, SourceRange where = {});
    /// The equation v == literal (given at `range`, imposed by the statement at `where`).
    void set_literal(Node v, Value literal, SourceRange range = {}, SourceRange where = {});

    /// The first node of n's class.
    Node find_part(Node n) const { return parts_uf_.find(n); }

    Node find_value(Node v) const { return values_uf_.find(v); }

    /// The literal of v's class, if it has one.
    std::optional<Value> literal(Node v) const { return values_[find_value(v)].literal; }

    /// At most `max` part nodes in all (counting those made so far); reaching it is a problem.
    void set_max_parts(std::size_t max) { max_parts_ = max; }

    /// The free completion: each class of part nodes, in order (new ones included), gets a part
    /// for each hom it lacks; with `equations` the schema's path equations are imposed at it;
    /// then it gets a value for each attribute it lacks. Stops at the part limit.
    void complete(bool equations);

    /// Every problem so far, in the order met.
    const std::vector<PresentationProblem>& problems() const { return problems_; }

    /// Whether the part limit was reached (nothing more is made after that).
    bool limit_reached() const { return limit_reached_; }

    enum class VariableOrder : std::uint8_t { Nodes, Cells };

    struct Instance {
        ACSet state;
        std::vector<Part> part_of;   // per part node: its part of state
        std::vector<Value> value_of; // per value node: its value in state (literal or variable)
    };

    /// The presented state, also when there are problems (a class keeps the first literal it
    /// met): for callers that report problems themselves.
    Instance build(VariableOrder order = VariableOrder::Nodes) const;
    /// The presented state, or the first problem in words.
    Result<Instance> instance(VariableOrder order = VariableOrder::Nodes) const;

private:
    static constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();

    struct PartNode {
        ObId ob;
        std::vector<Node> homs;  // by position in homs_from(ob); kUnset when undefined
        std::vector<Node> attrs; // value nodes, by position in attrs_from(ob)
    };

    struct ValueNode {
        AttrTypeId type;
        std::optional<Value> literal; // meaningful at the first node of a class
        SourceRange literal_range;
    };

    struct PendingValues {
        Node a, b;
        AttrId attr; // the attribute whose cells met, if that is why
    };

    Node new_part(ObId ob, std::string_view name, HomId needed_by);
    void give_literal(Node v, Value literal, SourceRange range, SourceRange where, AttrId attr);
    void merge_parts(Node a, Node b);
    void close(SourceRange where);
    void impose_equations(Node n);
    std::vector<std::string_view> class_names(bool values) const;

    schema::SchemaPtr schema_;
    std::vector<std::uint32_t> slot_; // per hom, then per attribute: its position at its object
    std::vector<PartNode> parts_;
    std::vector<ValueNode> values_;
    std::vector<std::string> part_names_, value_names_;
    mutable UnionFind parts_uf_, values_uf_;
    std::vector<std::pair<Node, Node>> pending_parts_;
    std::vector<PendingValues> pending_values_;
    std::vector<PresentationProblem> problems_;
    std::size_t max_parts_ = std::numeric_limits<std::size_t>::max();
    bool limit_reached_ = false;
};

} // namespace catplan::colimit
