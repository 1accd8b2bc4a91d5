#pragma once
// Homomorphism search between states: all, first, count, exists, or a callback per morphism.
//
// A backtracking CSP (Russell & Norvig, Alg. 6.5, as in Catlab's BacktrackingSearch) over the
// parts of the domain X, with
//   - forward checking along homs: assigning x -> y assigns f(x) -> f(y) for every hom f out of
//     x, recursively, checking monic and attribute constraints on the way;
//   - a dynamic variable choice: the unassigned part with the fewest candidates goes next, where
//     candidates come from its candidate set, from a composite-key index of the codomain when
//     all homs out of the part already have images (one hash lookup), from the preimage index of
//     one hom with an assigned image, or else all parts of the object.
//
// Attribute rules (Catlab's `_assign_elem!`, reference §3.3):
//   - a concrete domain value matches only an equal concrete codomain value (never a variable);
//   - a domain variable binds to the first codomain value it meets (concrete or variable) and
//     every other cell holding it must then meet the same value;
//   - on an attribute type that is monic, variables go injectively to codomain variables only.
//     Object monicity never implies this (unlike Catlab's monic=true);
//   - an unset domain cell (attribute unset, or a hom value kNoPart) imposes no constraint; a
//     set domain cell never matches an unset codomain cell. With `iso`, unset must meet unset.
// A free-floating variable (used by no attribute cell of X) could go anywhere, so there are
// infinitely many morphisms: this is reported in `error` unless the variable is bound by
// `initial`, or its type is monic or no_bind, in which case it ranges over codomain variables
// (injectively when monic).
//
// Results come in a deterministic order (parts are tried in increasing order; the order of
// preimage lists is that of ACSet::incident).
//
//   HomSearchOptions opt;
//   opt.monic_all = true;
//   auto r = find_homomorphisms(pattern, state, opt);
//   for (const ACSetMorphism& m : r.morphisms) ...

#include "catplan/acset/acset.hpp"
#include "catplan/base/id.hpp"
#include "catplan/base/result.hpp"
#include "catplan/hom/morphism.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace catplan::hom {

/// A part of the domain bound in advance to a part of the codomain.
struct PartBinding {
    ObId ob;
    Part dom;
    Part codom;
};

/// A variable of the domain bound in advance to a codomain value (concrete or a variable).
struct VarBinding {
    AttrTypeId type;
    std::uint32_t var;
    Value value;
};

/// The codomain parts a domain part may go to (Catlab's `predicates`).
struct CandidateSet {
    ObId ob;
    Part dom;
    std::vector<Part> allowed;
};

struct HomSearchOptions {
    /// Objects whose components must be injective.
    std::vector<ObId> monic;
    /// Makes every object component injective (attribute types are not affected).
    bool monic_all = false;
    /// Attribute types whose variables must go injectively to codomain variables.
    std::vector<AttrTypeId> monic_attr_types;
    /// Objects whose components must be bijective (injective, and the sizes must be equal).
    std::vector<ObId> iso_obs;
    /// Bijective on every object and variables bijectively onto variables; unset cells must
    /// meet unset cells.
    bool iso = false;
    /// Attribute types whose free-floating variables range over codomain variables instead of
    /// being an error (bound variables still bind concrete values).
    std::vector<AttrTypeId> no_bind;
    /// Bindings fixed before the search starts.
    std::vector<PartBinding> initial;
    std::vector<VarBinding> initial_vars;
    /// Allowed images per domain part; parts without an entry may go anywhere.
    std::vector<CandidateSet> candidates;
    /// An extra test of each tentative assignment dom part -> codom part of an object (e.g. the
    /// dangling condition of a rewrite rule), called before the assignment is made; empty = none.
    std::function<bool(ObId ob, Part dom, Part codom)> accept;
    /// Stop after this many morphisms (0 = no limit).
    std::uint64_t max_results = 0;
    /// Stop after trying this many assignments (0 = no limit).
    std::uint64_t node_limit = 0;

    /// Adds an initial binding of part `dom` of `ob` to part `codom`.
    HomSearchOptions& bind(ObId ob, Part dom, Part codom) {
        initial.push_back({ob, dom, codom});
        return *this;
    }

    /// Adds an initial binding of variable `var` of `type` to `value`.
    HomSearchOptions& bind_var(AttrTypeId type, std::uint32_t var, Value value) {
        initial_vars.push_back({type, var, value});
        return *this;
    }

    /// Restricts part `dom` of `ob` to the given codomain parts.
    HomSearchOptions& restrict(ObId ob, Part dom, std::vector<Part> allowed) {
        candidates.push_back({ob, dom, std::move(allowed)});
        return *this;
    }
};

struct HomSearchStats {
    /// Assignments tried at choice points (forced assignments along homs are not counted).
    std::uint64_t nodes = 0;
};

struct HomSearchResult {
    /// The morphisms found, in search order (empty for count_homomorphisms).
    std::vector<ACSetMorphism> morphisms;
    /// How many morphisms were found.
    std::uint64_t count = 0;
    /// True when the whole search space was explored (no limit or callback stopped it).
    bool complete = true;
    /// Non-empty when the search could not run: the hom set is infinite (a free-floating
    /// variable); then nothing is found and complete is false.
    std::string error;
    HomSearchStats stats;
};

/// Every morphism X -> Y allowed by the options (up to max_results), in deterministic order.
HomSearchResult find_homomorphisms(const ACSet& x, const ACSet& y,
                                   const HomSearchOptions& options = {});

/// The first morphism X -> Y, or the reason there is none (none exists, a limit was reached, or
/// the hom set is infinite).
Result<ACSetMorphism> find_homomorphism(const ACSet& x, const ACSet& y,
                                        const HomSearchOptions& options = {});

/// The number of morphisms X -> Y (up to max_results), without storing them.
HomSearchResult count_homomorphisms(const ACSet& x, const ACSet& y,
                                    const HomSearchOptions& options = {});

/// Whether some morphism X -> Y exists (false also when the search reports an error).
bool is_homomorphic(const ACSet& x, const ACSet& y, const HomSearchOptions& options = {});

/// Calls fn on each morphism in search order until it returns false; the reference is only
/// valid during the call. The result's count is the number of calls, morphisms stays empty.
HomSearchResult for_each_homomorphism(const ACSet& x, const ACSet& y,
                                      const HomSearchOptions& options,
                                      const std::function<bool(const ACSetMorphism&)>& fn);

} // namespace catplan::hom
