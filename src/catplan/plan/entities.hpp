#pragma once
// Entities: the parts of a problem's initial state that keep their identity in every reachable
// state, so that a planner can name them once (heuristic.hpp, ground/).
//
//   - An *entity object* is one no rule creates, deletes or merges parts of (every part of it in
//     L and R comes from K, injectively): Block in the STRIPS blocks world, every PDDL type. Its
//     parts keep their ids in every reachable state.
//   - In another object whose parts no rule merges (Block in the paper's domain, where a marker
//     block is deleted and recreated), an initial part is an entity when it is uniquely named and
//     no rule can ever delete it. A rule's deleted L part d cannot match initial part p when, for
//     some hom f into the object,
//       (a) d has an f-preimage in L, p has none initially, and no rule makes f point into a kept
//           part where it did not before (so p never gains one: a monic match sends L's preimage
//           to one of p's), or
//       (b) p has an f-preimage q in an entity object and no rule ever redirects f: q refers to p
//           forever, and since no rule deletes q or redirects its f, the dangling condition
//           forbids deleting p.
//   Such entities are followed by name, since pop-and-swap deletions move ids.

#include "catplan/plan/domain.hpp"

#include <vector>

namespace catplan::plan {

struct Entities {
    /// Per object: every part is an entity (an entity object).
    std::vector<bool> whole;
    /// Per object: no rule merges its parts (r is injective on it), so identities are stable.
    std::vector<bool> stable;
    /// Per object: the initial parts that are entities, sorted.
    std::vector<std::vector<Part>> parts;
    /// Per hom: some rule redirects it on a kept part (K leaves it unset, R sets it).
    std::vector<bool> redirected;

    /// Whether initial part p of ob is an entity.
    bool is_entity(ObId ob, Part p) const;
};

/// The entities of the initial state under the domain's rules.
Entities find_entities(const Domain& domain, const ACSet& initial);

} // namespace catplan::plan
