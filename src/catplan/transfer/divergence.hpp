#pragma once
// Comparing a transfer's target trajectory with the migrated source trajectory (semantics.md
// "Plan transfer", 3b): after step i, is Y_i isomorphic to Δ_F(X_i)? For a delta map and DPO
// rules without application conditions it always is (paper Appendix A); a conjunctive map need
// not preserve pushouts (a rule that sets an attribute a filter reads cannot move the part from
// one filtered target object to another), and then the transfer must say where and what differs.
//
// Comparing whole states after every step would cost the size of the state per step; a transfer
// step costs what it touches (transfer.hpp). So the check is local and exact where it can be:
//   - Y_0 = Δ_F(X_0), and the bijection "same name" between their parts is an isomorphism (a
//     tuple of Δ_F(X) is named after the part of X its first object variable takes, renamed as
//     the target is). While that holds, a step can change only the tuples whose assignment meets
//     a part the source step matched or created (or reads an attribute or hom of one along a
//     path of the map), and only the target parts its migrated step matched or created. Their
//     names are the keys of the step; at each key, the tuple of Δ_F(X_i) and the part of Y_i of
//     that name must agree: their hom values by the names of their targets, their attribute
//     values (concrete values equal, unknowns against unknowns). When they do, the bijection is
//     still an isomorphism, and the check cost a few searches pinned at the touched parts.
//   - When they do not, or a key's name is not unique (then the bijection is not defined there),
//     the whole states are compared: Δ_F(X_i) is computed and renamed, compared by names first,
//     then by hom::canonical_hash and, when the hashes agree, hom::is_isomorphic. Isomorphic
//     states are not a divergence (the later steps are then compared whole, until the names
//     agree again); others are, and what differs is listed as statements (terms.hpp) that one
//     state makes and the other does not.
// Unknowns are compared as unknowns by the local check: two states that differ only in which
// cells share an unknown value pass it.

#include "catplan/hom/morphism.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/transfer/named_state.hpp"
#include "catplan/transfer/rename.hpp"
#include "catplan/transfer/verdict.hpp"

#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace catplan::transfer {

class DivergenceCheck {
public:
    /// A check along f for states renamed by `renaming` (both must outlive the check).
    DivergenceCheck(const migrate::SchemaMap& f, const Renaming& renaming);

    /// Before step i rewrites: m : L -> X_{i-1} and mt : Δ_F(L) -> Y_{i-1}, the matches.
    void before(const hom::ACSetMorphism& m, const NamedState& x, const hom::ACSetMorphism& mt,
                const NamedState& y);

    /// After step i rewrote both: r : R -> X_i and rt : Δ_F(R) -> Y_i, the comatches. The
    /// divergence, when Y_i is not isomorphic to Δ_F(X_i) (its where is left empty).
    std::optional<Divergence> after(std::size_t step, const hom::ACSetMorphism& r,
                                    const NamedState& x, const hom::ACSetMorphism& rt,
                                    const NamedState& y);

    /// Compares Y_i with Δ_F(X_i) whole (after a step the local check cannot follow, a repair).
    std::optional<Divergence> compare(std::size_t step, const NamedState& x, const NamedState& y) {
        keys_.clear();
        return compare_whole(step, x, y);
    }

    /// Compares Y_i with z = Δ_F(X_i) (renamed) after a repair; with `holds_by_names`, the repair
    /// checked that z embeds in Y_i sending each part that homs point into to its namesake, and
    /// then, when both have as many parts of each object and no attribute variable, that
    /// embedding is an isomorphism (monic and as many parts: bijective; a bijective morphism of
    /// C-sets is invertible) and nothing more is compared.
    std::optional<Divergence> compare_repaired(std::size_t step, const acset::ACSet& z,
                                               const NamedState& y, bool holds_by_names);

    /// Y is Δ_F(X) with the same names (after Y := Δ_F(X)): the local check is exact again.
    void reset() { local_ = true; }

    /// How many steps were compared whole.
    std::size_t whole_comparisons() const { return whole_; }

private:
    struct Pin {
        ObId c;     // the target object
        Part shape; // the part of Q_c's shape pinned
    };

    // A path of the map from a part of Q_c's shape: the parts along it at positions 1..upto are
    // read (their homs or attribute), so a change there changes the tuple's record.
    struct Reach {
        ObId c;
        ObId start_ob;
        Part start;
        std::vector<HomId> homs;
        std::size_t upto;
    };

    using Key = std::pair<std::uint32_t, std::string>; // target object, name

    void source_keys(const hom::ACSetMorphism& m, const acset::ACSet& x);
    void target_keys(const hom::ACSetMorphism& mt, const acset::ACSet& y);
    void pinned_keys(const acset::ACSet& x, ObId c, ObId ob, Part shape, Part p);
    /// Whether the tuple of Δ_F(X) and the part of Y at key agree; nullopt when the name is not
    /// unique on a side (the check cannot decide).
    std::optional<bool> agree(const Key& key, const NamedState& x, const NamedState& y) const;
    std::optional<Divergence> compare_whole(std::size_t step, const NamedState& x,
                                            const NamedState& y);
    std::optional<Divergence> compare_states(std::size_t step, const acset::ACSet& z,
                                             const acset::ACSet& y);
    std::string source_name(const acset::ACSet& x, ObId ob, Part p) const;

    const migrate::SchemaMap& f_;
    const Renaming& renaming_;
    std::unordered_map<std::string, std::string> inverse_; // target name -> source name
    std::vector<std::vector<Pin>> pins_;                   // by source object
    std::vector<Reach> reaches_;
    std::set<Key> keys_;
    bool local_ = true;
    std::size_t whole_ = 0;
};

} // namespace catplan::transfer
