#pragma once
// A morphism that its initial bindings force: matching a rule at a plan step whose arguments
// bind every part a search would choose (a transfer replays thousands of such steps). Each
// further part is found by propagation alone: along the homs out of a bound part, or as the only
// part of Y that agrees with everything bound so far among the preimages of a hom into a bound
// part (or, for a part of an object without homs, a fact of no arguments, among all the parts
// of its object). Where that decides the hom set (no morphism, or exactly one), it is the answer of
// hom_search.hpp's search with the same options, at a fraction of a search's set-up; where it
// does not (a part with two candidates, a part no hom reaches, options it does not read), the
// answer is Undecided and the caller searches.

#include "catplan/acset/acset.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/morphism.hpp"

namespace catplan::hom {

/// What the initial bindings decide alone.
struct Forced {
    enum class Kind : std::uint8_t {
        Undecided, ///< propagation does not decide: search
        None,      ///< no morphism extends the bindings
        One,       ///< exactly one does: `morphism`
    };
    Kind kind = Kind::Undecided;
    ACSetMorphism morphism;
};

/// The morphisms X -> Y of `options` when its initial bindings force them (Forced::None or
/// Forced::One: then find_homomorphisms finds exactly those), else Undecided. Reads `initial`,
/// `monic_all`, `monic` and `accept`; options beyond these (iso, candidate sets, variable
/// bindings or a node limit) and a domain with attribute variables are Undecided.
Forced forced_homomorphism(const acset::ACSet& x, const acset::ACSet& y,
                           const HomSearchOptions& options);

} // namespace catplan::hom
