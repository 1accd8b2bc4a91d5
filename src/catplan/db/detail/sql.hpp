#pragma once
// SQL text shared by the state tables and the migrations: paths of homs followed by joins.

#include "catplan/db/tables.hpp"

#include <optional>
#include <string>
#include <vector>

namespace catplan::db::detail {

/// Where a path ends in SQL: the joins it needs (LEFT JOINs, so an unset hom on the way gives
/// NULL) and the expressions of its end: the part's _id (hom paths), or the attribute's value
/// and variable columns (paths ending in an attribute).
struct SqlPath {
    std::string joins;
    std::string id;
    std::string value, var;
};

/// The start of a path: a table alias whose row is the part (empty when there is none) and the
/// expression of the part's _id.
struct SqlStart {
    std::string alias;
    std::string id;
};

/// Follows homs (then an attribute) from `start`, a part of `dom`, through the tables of
/// `layout`; new aliases are `prefix` followed by a counter.
SqlPath path_sql(const Layout& layout, ObId dom, SqlStart start, const std::vector<HomId>& homs,
                 std::optional<AttrId> attr, const std::string& prefix, int& counter);

/// The quoted column `column` of alias `alias`: a."column".
std::string col(const std::string& alias, std::string_view column);

} // namespace catplan::db::detail
