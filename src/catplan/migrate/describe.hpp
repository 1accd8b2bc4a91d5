#pragma once
// A schema map in brief, one line per target generator, for people (the CLI's transfer and
// migrate-domain output, the HTML report): `Object ⇒ Block`, `BreadSliced ⇒ {block::Block |
// hasColor(block) == "purple"}`, `isHolding ⇒ isHolding`, `breadSlicedIsObject ⇒ x ↦ block`,
// `Temperature ⇒ Float64`, `breadSlicedHasTemperature ⇒ x -> 0.0`.

#include "catplan/migrate/schema_map.hpp"

#include <string>
#include <vector>

namespace catplan::migrate {

/// One line of the brief: a target generator and its image, in words.
struct MapLine {
    schema::Generator target;
    std::string name;  ///< the target generator's name
    std::string image; ///< its image, in words
};

/// The image of a query, in words: the source object of a plain query, else its shape.
std::string describe_query(const Query& q);

/// Every target generator of a finished map with its image, in the target schema's order
/// (objects, homs, attribute types, attributes).
std::vector<MapLine> describe_map(const SchemaMap& f);

} // namespace catplan::migrate
