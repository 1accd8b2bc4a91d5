#pragma once
// Matching and applying rules (double-pushout rewriting, with the update semantics of rule.hpp).
//
// find_matches enumerates the morphisms L -> X (monic by default) that satisfy the gluing
// conditions and the application conditions. The dangling condition is checked inside the search,
// as soon as a part to be deleted is assigned (its incident counts must match L's), so invalid
// matches are pruned rather than filtered; identification cannot fail for monic matches; NACs are
// checked once a match is complete.
//
// Two ways to apply a rule at a match, which agree up to isomorphism (a property test on seeded
// random rules and states) and reject the same matches for the same reasons:
//   - rewrite(): the reference, functional (X is unchanged). As AlgebraicRewriting's DPO: the
//     pushout complement Z = X - m(L - l(K)) (colimit::pushout_complement), then the pushout
//     Y = R +_K Z (colimit::pushout), then the values of R's expressions substituted (a pushout
//     along the variables, Catlab's sub_vars). The update semantics of rule.hpp live in the span
//     the colimits glue along: Z leaves open the cells the rule rewrites (a redirected hom, an
//     attribute R sets anew on a kept part), so R's value is the only one in the gluing. Y then
//     forgets the unknowns the step left without a cell. SPO rules delete the cascade in Z.
//     Numbering (Catlab's, from the pushout's coproduct [R, Z]): R's parts first, in R's order, a
//     kept part in the place of its R part; then the untouched parts of X in X's order. Unknowns
//     likewise: those of R that stay unknown (fresh, or bound to an unknown of X), then X's
//     remaining ones in X's order. Kept parts and unknowns keep X's names, created ones take R's.
//   - rewrite_in_place(): the fast path, used by planning and transfer. It mutates X; the cost is
//     proportional to the parts the rule touches (and their incident parts), not to the size of
//     X. Numbering: deleted parts are removed by pop-and-swap (ACSet::remove_part) in decreasing
//     id order per object, created parts are appended in R's order, kept parts keep their ids
//     unless moved by a pop-and-swap; unknowns left without a cell are removed the same way.
// Both check a match with match_problem's checks (one gluing mechanism: colimit::deletion) and
// compute R's values with one function, then reject a rule whose r glues two kept parts, or two
// kept values the match binds differently (not supported). rewrite_in_place can be told that its
// match comes from find_matches (CheckMatch::No), as planning and transfer apply the matches
// they find: the checks find_matches made are not made twice (they were a third of the
// instructions of an application in a transfer).

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

/// Why m : pattern -> x breaks one of the conditions (each n : pattern -> N: a negative one must
/// not extend m to a monic N -> x, a positive one must), or nullopt when it meets them all.
std::optional<std::string> condition_problem(const std::vector<ApplicationCondition>& conditions,
                                             const ACSet& pattern, const ACSet& x,
                                             const ACSetMorphism& m);

struct Rewrite {
    ACSet result;
    ACSetMorphism r_to_result; // R -> Y
};

/// Applies rule at match m functionally; fails with the reason when m is not a valid match.
Result<Rewrite> rewrite(const Rule& rule, const ACSet& x, const ACSetMorphism& m);

/// Whether rewrite_in_place checks its match first (AlgebraicRewriting's `check` keyword).
/// CheckMatch::No is for a match already checked against x as it is now: one find_matches
/// returned, or one match_problem accepted (naturality, the gluing and application conditions).
enum class CheckMatch { Yes, No };

/// Applies rule at match m to x in place and returns R -> x; on failure x is unchanged. With
/// CheckMatch::No, m must be a checked match (asserted: its components have L's sizes and land
/// in x's parts; the rest is not checked again).
Result<ACSetMorphism> rewrite_in_place(const Rule& rule, ACSet& x, const ACSetMorphism& m,
                                       CheckMatch check = CheckMatch::Yes);

} // namespace catplan::rewrite
