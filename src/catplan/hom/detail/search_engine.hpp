#pragma once
// The backtracking engine behind hom_search.hpp (private to the hom layer).

#include "catplan/hom/hom_search.hpp"

#include <functional>

namespace catplan::hom::detail {

/// What the engine does with each morphism it finds.
enum class SearchMode : std::uint8_t { Collect, Count, Callback };

/// Runs one search; `fn` is used only in Callback mode.
HomSearchResult run_search(const ACSet& x, const ACSet& y, const HomSearchOptions& options,
                           SearchMode mode,
                           const std::function<bool(const ACSetMorphism&)>* fn = nullptr);

} // namespace catplan::hom::detail
