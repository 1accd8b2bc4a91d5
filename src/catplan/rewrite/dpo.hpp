#pragma once
// Matching and applying rules (double-pushout rewriting, with the update semantics of rule.hpp).
//
// find_matches enumerates the morphisms L -> X (monic by default) that satisfy the gluing
// conditions and the application conditions. The dangling condition is checked inside the search,
// as soon as a part to be deleted is assigned (its incident counts must match L's), so invalid
// matches are pruned rather than filtered; identification cannot fail for monic matches; NACs are
// checked once a match is complete.
//
// Two ways to apply a rule at a match:
//   - rewrite(): functional, X is unchanged. Y's parts are numbered as Catlab numbers a pushout:
//     R's parts first (kept parts take the place of their R part), then the untouched parts of X in
//     X's order. This is the mathematical reference.
//   - rewrite_in_place(): mutates X; the cost is proportional to the parts the rule touches (and
//     their incident parts), not to the size of X. Numbering: deleted parts are removed by
//     pop-and-swap (ACSet::remove_part) in decreasing id order per object, created parts are
//     appended in R's order, kept parts keep their ids unless moved by a pop-and-swap. The planner
//     uses this. Both give isomorphic results (tested).

#include "catplan/hom/hom_search.hpp"
#include "catplan/rewrite/rule.hpp"

#include <optional>
#include <string>
#include <vector>

namespace catplan::rewrite {

struct MatchOptions {
    /// Injective on every object (the planning default); false allows non-monic matches.
    bool monic = true;
    /// When monic is false: objects on which the match must still be injective.
    std::vector<ObId> monic_objects;
    /// Parts of L bound in advance (e.g. the arguments of a plan step).
    std::vector<hom::PartBinding> initial;
    /// Stop after this many matches (0 = all).
    std::uint64_t max_results = 0;
};

/// The valid matches of rule's L in x, in deterministic order.
std::vector<ACSetMorphism> find_matches(const Rule& rule, const ACSet& x,
                                        const MatchOptions& options = {});

/// Why m : L -> x is not a valid match (not natural, not monic when required, a gluing
/// violation, an application condition), or nullopt when it is valid.
std::optional<std::string> match_problem(const Rule& rule, const ACSet& x, const ACSetMorphism& m,
                                         bool monic = true);

struct Rewrite {
    ACSet result;
    ACSetMorphism r_to_result; // R -> Y
};

/// Applies rule at match m functionally; fails with the reason when m is not a valid match.
Result<Rewrite> rewrite(const Rule& rule, const ACSet& x, const ACSetMorphism& m);

/// Applies rule at match m to x in place and returns R -> x; on failure x is unchanged.
Result<ACSetMorphism> rewrite_in_place(const Rule& rule, ACSet& x, const ACSetMorphism& m);

} // namespace catplan::rewrite
