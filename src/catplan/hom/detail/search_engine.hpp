#pragma once
// The backtracking engine behind hom_search.hpp (private to the hom layer).

#include "catplan/hom/hom_search.hpp"

#include <functional>

namespace catplan::hom::detail {

/// What the engine does with each morphism it finds.
enum class SearchMode : std::uint8_t { Collect, Count, Callback };

/// Whether x and y are states on one schema, or on schemas of the same shape (the same counts of
/// objects, homs, attributes and attribute types): what a search between them presumes.
inline bool searchable(const ACSet& x, const ACSet& y) {
    const auto &sx = x.schema(), &sy = y.schema();
    return &sx == &sy ||
           (sy.num_obs() == sx.num_obs() && sy.num_homs() == sx.num_homs() &&
            sy.num_attrs() == sx.num_attrs() && sy.num_attr_types() == sx.num_attr_types());
}

/// Runs one search; `fn` is used only in Callback mode.
HomSearchResult run_search(const ACSet& x, const ACSet& y, const HomSearchOptions& options,
                           SearchMode mode,
                           const std::function<bool(const ACSetMorphism&)>* fn = nullptr);

} // namespace catplan::hom::detail
