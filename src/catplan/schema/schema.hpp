#pragma once
// Schemas: finitely presented categories with attributes (the paper's domain ontology D).
//
//   Ob        types                      Block::Ob
//   Hom       functional predicates      isHolding::Hom(Gripper, Block)
//   AttrType  value types, with a kind   Color::AttrType      (kind String, declared or inferred)
//   Attr      attributes                 hasColor::Attr(Block, Color)
//   Equation  equal paths                compose(isHolding, hasColor) == ...
//
// Declaration order is kept: it fixes table order, JSON order and output order. A Schema is built
// by the language elaborator or the JSON reader with the add_* functions and is then shared
// immutably (std::shared_ptr<const Schema>) by every state on it.
//
//   auto s = std::make_shared<Schema>("Graph");
//   ObId v = s->add_ob("V"), e = s->add_ob("E");
//   s->add_hom("src", e, v);  s->add_hom("tgt", e, v);

#include "catplan/base/id.hpp"
#include "catplan/base/source.hpp"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace catplan::schema {

/// The kind of value an attribute type holds. Unknown until declared or inferred from a literal.
enum class ValueKind : std::uint8_t { Unknown, Bool, Int, Float, String };

/// "Bool", "Int", "Float", "String" or "Unknown".
std::string_view to_string(ValueKind kind);
/// Parses a kind name, accepting Julia's spellings (Float64, Int64, Symbol); nullopt if unknown.
std::optional<ValueKind> parse_value_kind(std::string_view name);

struct ObInfo {
    std::string name;
    SourceRange range;
};

struct HomInfo {
    std::string name;
    ObId dom;
    ObId codom;
    SourceRange range;
};

struct AttrTypeInfo {
    std::string name;
    ValueKind kind = ValueKind::Unknown;
    SourceRange range;
};

struct AttrInfo {
    std::string name;
    ObId dom;
    AttrTypeId codom;
    SourceRange range;
};

/// A path of homs from `dom`, optionally ending with one attribute. The empty path is id(dom).
struct Path {
    ObId dom;
    std::vector<HomId> homs;
    std::optional<AttrId> attr;

    friend bool operator==(const Path&, const Path&) = default;
};

/// An equation between two paths with the same ends.
struct Equation {
    std::string name; // may be empty
    Path lhs;
    Path rhs;
    SourceRange range;
};

/// What a name refers to in a schema.
enum class GeneratorKind { Ob, Hom, AttrType, Attr };

/// The kind as a noun with its article, for messages: "an object", "a hom", ...
const char* kind_noun(GeneratorKind k);

struct Generator {
    GeneratorKind kind;
    std::uint32_t index;
};

class Schema {
public:
    explicit Schema(std::string name) : name_(std::move(name)) {}

    const std::string& name() const { return name_; }

    void set_name(std::string name) { name_ = std::move(name); }

    /// Adds an object; the name must be new (checked by the caller, asserted here).
    ObId add_ob(std::string name, SourceRange range = {});
    /// Adds a hom between existing objects.
    HomId add_hom(std::string name, ObId dom, ObId codom, SourceRange range = {});
    /// Adds an attribute type of the given kind.
    AttrTypeId add_attr_type(std::string name, ValueKind kind = ValueKind::Unknown,
                             SourceRange range = {});
    /// Adds an attribute from an object to an attribute type.
    AttrId add_attr(std::string name, ObId dom, AttrTypeId codom, SourceRange range = {});
    /// Adds an equation; both paths must have the same domain and codomain (asserted).
    void add_equation(Equation eq);

    /// Fixes the kind of an attribute type (used when a kind is inferred from a literal).
    void set_kind(AttrTypeId t, ValueKind kind) { attr_types_[t.index()].kind = kind; }

    std::size_t num_obs() const { return obs_.size(); }

    std::size_t num_homs() const { return homs_.size(); }

    std::size_t num_attr_types() const { return attr_types_.size(); }

    std::size_t num_attrs() const { return attrs_.size(); }

    const ObInfo& ob(ObId x) const { return obs_[x.index()]; }

    const HomInfo& hom(HomId f) const { return homs_[f.index()]; }

    const AttrTypeInfo& attr_type(AttrTypeId t) const { return attr_types_[t.index()]; }

    const AttrInfo& attr(AttrId a) const { return attrs_[a.index()]; }

    const std::vector<Equation>& equations() const { return equations_; }

    /// What a name refers to, if anything.
    std::optional<Generator> find(std::string_view name) const;
    std::optional<ObId> find_ob(std::string_view name) const;
    std::optional<HomId> find_hom(std::string_view name) const;
    std::optional<AttrTypeId> find_attr_type(std::string_view name) const;
    std::optional<AttrId> find_attr(std::string_view name) const;

    /// Homs out of an object, in declaration order.
    std::span<const HomId> homs_from(ObId x) const { return homs_from_[x.index()]; }

    /// Homs into an object, in declaration order.
    std::span<const HomId> homs_into(ObId x) const { return homs_into_[x.index()]; }

    /// Attributes of an object, in declaration order.
    std::span<const AttrId> attrs_from(ObId x) const { return attrs_from_[x.index()]; }

    /// Attributes valued in an attribute type, in declaration order.
    std::span<const AttrId> attrs_into(AttrTypeId t) const { return attrs_into_[t.index()]; }

    /// The object a hom-only path ends at (asserts the path has no attribute).
    ObId path_codom_ob(const Path& p) const;
    /// Whether the path's arrows compose (each hom starts where the previous one ends).
    bool is_well_formed(const Path& p) const;
    /// Whether two paths are equal modulo the equations. Exact on acyclic schemas, where paths
    /// are short; on cyclic ones the search is bounded and a "no" may be a "don't know".
    bool paths_equal(const Path& a, const Path& b) const;
    /// Whether the hom graph has a cycle (then free instances may be infinite).
    bool is_cyclic() const;
    /// "f ⋅ g ⋅ a" or "id(X)".
    std::string path_to_string(const Path& p) const;

private:
    std::string name_;
    std::vector<ObInfo> obs_;
    std::vector<HomInfo> homs_;
    std::vector<AttrTypeInfo> attr_types_;
    std::vector<AttrInfo> attrs_;
    std::vector<Equation> equations_;
    std::vector<std::vector<HomId>> homs_from_, homs_into_;
    std::vector<std::vector<AttrId>> attrs_from_;
    std::vector<std::vector<AttrId>> attrs_into_;
    std::unordered_map<std::string, Generator> names_;
};

using SchemaPtr = std::shared_ptr<const Schema>;

} // namespace catplan::schema
