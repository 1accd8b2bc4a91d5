#pragma once
// A schema map in words, one line per target generator, for people: the one notation of maps
// everywhere (`catplan show`, transfer and migrate-domain output, the HTML report, the map's
// picture). An object goes to a source object or a query written as a set:
//   Object ⇒ Block
//   BreadSliced ⇒ {block::Block | hasColor(block) == "purple"}
// a hom to a path of source homs (`inReceptacle_l ⇒ on_l`, `under ⇒ on_l⋅below`, `id`) or, between
// queries, to where each element of its codomain's query goes (`breadSlicedIsObject ⇒ Object ↦
// block`); an attribute type to a source attribute type or a value kind (`Temperature ⇒ Float`);
// an attribute to a path ending in a source attribute (`on_l⋅hasColor`), a term of its domain's
// query (`hasColor(block)`), a variable of that query, or a constant (`x -> 0.0`).

#include "catplan/migrate/schema_map.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace catplan::migrate {

/// One line of the brief: a target generator and its image, in words.
struct MapLine {
    schema::Generator target;
    std::string name;  ///< the target generator's name
    std::string image; ///< its image, in words
};

/// Names for the elements of a query's shape: the variable that lands on an element, else the
/// shape's own label (#2).
class ShapeNames {
public:
    explicit ShapeNames(const Query& q);

    /// The name of part p of ob in the shape.
    std::string part(ObId ob, Part p) const;
    /// The name of value v of type t in the shape (a variable's name, or the value itself).
    std::string value(AttrTypeId t, const acset::Value& v) const;
    /// The query variable that lands on value v of type t, if one does.
    std::optional<std::string> variable(AttrTypeId t, const acset::Value& v) const;

private:
    const Query& q_;
    std::vector<std::pair<std::pair<std::uint32_t, Part>, std::string>> parts_;
    std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::string>> vars_;
};

/// The facts of a query's shape in words, part by part in the shape's order:
/// `hasColor(block) == "purple"`, `on_l(o) == block`.
std::vector<std::string> query_facts(const Query& q, const ShapeNames& names);

/// The image of a query, in words: the source object of a plain query, else its shape as a set
/// (`{block::Block | hasColor(block) == "purple"}`), `@unit` or `@empty`.
std::string describe_query(const Query& q);

/// Every target generator of a finished map with its image, in the target schema's order
/// (objects, homs, attribute types, attributes).
std::vector<MapLine> describe_map(const SchemaMap& f);

/// The lines as text, one `  name ⇒ image` per line.
std::string map_text(const std::vector<MapLine>& lines);

} // namespace catplan::migrate
