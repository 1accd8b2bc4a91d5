#include "catplan/plan/state_registry.hpp"

#include "catplan/hom/isomorphism.hpp"

namespace catplan::plan {

std::size_t approximate_bytes(const ACSet& x) {
    const auto& s = x.schema();
    std::size_t bytes = sizeof(ACSet);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        std::size_t n = x.num_parts(ob);
        // A hom column, its preimage lists (built by rewriting), an attribute column, a name.
        bytes += n * (s.homs_from(ob).size() * (sizeof(Part) * 3 + 24) +
                      s.attrs_from(ob).size() * sizeof(acset::Value) + sizeof(Symbol));
        bytes += 4 * 24; // the vectors themselves
    }
    return bytes;
}

StateRegistry::Insertion StateRegistry::insert(ACSet x) {
    std::uint64_t h = hom::canonical_hash(x);
    auto& bucket = by_hash_[h];
    for (StateId id : bucket) {
        if (states_[id] == x) {
            return {id, false};
        }
    }
    for (StateId id : bucket) {
        ++iso_tests_;
        if (hom::is_isomorphic(states_[id], x)) {
            return {id, false};
        }
    }
    auto id = static_cast<StateId>(states_.size());
    bytes_ += approximate_bytes(x) + sizeof(StateId) * 4;
    states_.push_back(std::move(x));
    bucket.push_back(id);
    return {id, true};
}

} // namespace catplan::plan
