#pragma once
// The planner's store of states, one per isomorphism class (as Fast Downward's StateRegistry keeps
// one per packed state). A state is looked up by hom::canonical_hash; states with equal hashes are
// compared by exact equality first (cheap, and the common case: the same state reached by two
// paths with the same numbering) and then by hom::is_isomorphic.
//
// Names are ignored, as morphisms ignore them: two states that differ only by which block is
// called A are the same state. A domain whose part names matter must record them as attributes
// (the paper's HasLabel), which the hash and the isomorphism test do see.

#include "catplan/acset/acset.hpp"

#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

namespace catplan::plan {

using acset::ACSet;

using StateId = std::uint32_t;

/// An approximation of the bytes a stored state takes (columns, names, vectors' own size).
std::size_t approximate_bytes(const ACSet& x);

class StateRegistry {
public:
    struct Insertion {
        StateId id;
        bool is_new;
    };

    /// The id of the stored state isomorphic to x, inserting x when there is none.
    Insertion insert(ACSet x);

    /// The state with this id (a representative of its isomorphism class).
    const ACSet& state(StateId id) const { return states_[id]; }

    std::size_t size() const { return states_.size(); }

    /// Approximate bytes held by the stored states.
    std::size_t bytes() const { return bytes_; }

    /// Isomorphism tests run on hash collisions (equal hash, not exactly equal).
    std::uint64_t iso_tests() const { return iso_tests_; }

private:
    std::deque<ACSet> states_; // grows in blocks, never by doubling one large array
    std::unordered_map<std::uint64_t, std::vector<StateId>> by_hash_;
    std::size_t bytes_ = 0;
    std::uint64_t iso_tests_ = 0;
};

} // namespace catplan::plan
