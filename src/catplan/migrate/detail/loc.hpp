#pragma once
// A place in a query's shape reached from a part of another query, shared by the equation check of
// a schema map (schema_map.cpp) and composition of maps (compose.cpp).

#include "catplan/acset/acset.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/schema/schema.hpp"

#include <optional>
#include <vector>

namespace catplan::migrate::detail {

/// A part of a query's shape, a suffix of source homs not in the shape, and an attribute when the
/// path ends in one.
struct Loc {
    ObId ob;
    Part part = kNoPart;
    std::vector<HomId> suffix;
    std::optional<AttrId> attr;
};

/// `loc`, a place in the query of target hom f's codomain, carried to the query of f's domain
/// along m's image of f (its attribute kept).
Loc step_back(const SchemaMap& m, HomId f, Loc loc);

} // namespace catplan::migrate::detail
