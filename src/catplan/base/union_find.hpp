#pragma once
// Disjoint sets over dense ids 0..n-1 with path halving. Used for congruence closure (free
// instances), pushouts and coequalizers. union_sets keeps the smaller id as the representative, so
// results are deterministic and "first declared wins".

#include <cstdint>
#include <numeric>
#include <vector>

namespace catplan {

class UnionFind {
public:
    explicit UnionFind(std::size_t n = 0) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
    }

    /// Adds a new singleton set and returns its id.
    std::uint32_t make_set() {
        auto id = static_cast<std::uint32_t>(parent_.size());
        parent_.push_back(id);
        return id;
    }

    std::size_t size() const { return parent_.size(); }

    /// The representative of x's set (the smallest id in it).
    std::uint32_t find(std::uint32_t x) {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];
            x = parent_[x];
        }
        return x;
    }

    /// Merges the sets of a and b; returns true when they were distinct.
    bool union_sets(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) {
            return false;
        }
        if (b < a) {
            std::swap(a, b);
        }
        parent_[b] = a;
        return true;
    }

private:
    std::vector<std::uint32_t> parent_;
};

} // namespace catplan
