#pragma once
// Isomorphism of states and a canonical hash for deduplicating them (the planner keeps one
// state per isomorphism class: equal hash, then is_isomorphic).
//
// The hash is colour refinement (1-dimensional Weisfeiler-Lehman) over the parts and attribute
// variables of a state: a part starts with its object and its concrete attribute values, a
// variable with its type; each round adds the colours of the hom values out of a part, of the
// parts pointing into it (by hom) and of the variables in its cells (and, for a variable, of
// the cells holding it), until the partition stops splitting. The hash is that of the sorted
// multiset of final colours. Names are ignored, variables are anonymous but their sharing
// pattern counts. Isomorphic states always get equal hashes; unequal states usually, not always,
// get different ones.

#include "catplan/acset/acset.hpp"
#include "catplan/hom/morphism.hpp"

#include <cstdint>
#include <optional>

namespace catplan::hom {

/// An isomorphism x -> y (bijective on parts and on variables, unset cells to unset cells), or
/// nullopt when there is none.
std::optional<ACSetMorphism> find_isomorphism(const ACSet& x, const ACSet& y);

/// Whether x and y are isomorphic (names ignored).
bool is_isomorphic(const ACSet& x, const ACSet& y);

/// A 64-bit hash equal for isomorphic states (names ignored, variables anonymous). Strings are
/// hashed by content, so the value does not depend on interning order.
std::uint64_t canonical_hash(const ACSet& x);

} // namespace catplan::hom
