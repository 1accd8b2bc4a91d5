#pragma once
// The C-set search (search.hpp): forward search over attributed C-sets, one stored state per
// isomorphism class, successors by rewrite::find_matches and rewrite_in_place. It works for every
// domain; the grounded search (ground/) is faster where it applies.

#include "catplan/plan/search.hpp"

namespace catplan::plan {

/// Searches as find_plan does, over C-set states, within the budget.
SearchResult cset_search(const Problem& problem, const SearchOptions& options, Budget& budget);

} // namespace catplan::plan
