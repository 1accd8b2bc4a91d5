#include "catplan/hom/isomorphism.hpp"

#include "catplan/base/hash.hpp"
#include "catplan/hom/hom_search.hpp"

#include <algorithm>
#include <bit>
#include <unordered_map>
#include <vector>

namespace catplan::hom {

namespace {

using schema::Schema;

constexpr std::uint64_t kUnsetMark = 0x6a09e667f3bcc908ULL;
constexpr std::uint64_t kVarMark = 0xbb67ae8584caa73bULL;
constexpr std::uint64_t kPartSeed = 0x3c6ef372fe94f82bULL;
constexpr std::uint64_t kVarSeed = 0xa54ff53a5f1d36f1ULL;

// A hash of a concrete value that does not depend on interning order (Value::hash hashes a
// string by its symbol id, which differs between runs).
std::uint64_t stable_value_hash(const Value& v) {
    if (v.tag() != Value::Tag::String) {
        return v.hash();
    }
    std::uint64_t h = 0xcbf29ce484222325ULL; // FNV-1a
    for (char c : v.as_string()) {
        h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    }
    return hash_combine(static_cast<std::uint64_t>(Value::Tag::String), hash_mix(h));
}

// Colours of every part (per object) and every variable (per attribute type) of one state.
class Refiner {
public:
    explicit Refiner(const ACSet& x) : x_(x), s_(x.schema()) {
        std::size_t nobs = s_.num_obs(), ntypes = s_.num_attr_types();
        parts_.resize(nobs);
        vars_.resize(ntypes);
        for (std::uint32_t ob = 0; ob < nobs; ++ob) {
            auto& c = parts_[ob];
            c.resize(x.num_parts(ObId(ob)));
            for (Part p = 0; p < c.size(); ++p) {
                std::uint64_t h = hash_combine(kPartSeed, ob);
                for (AttrId a : s_.attrs_from(ObId(ob))) {
                    const Value& v = x.subpart(a, p);
                    h = hash_combine(h, v.is_unset() ? kUnsetMark
                                        : v.is_var() ? kVarMark
                                                     : stable_value_hash(v));
                }
                c[p] = h;
            }
        }
        for (std::uint32_t t = 0; t < ntypes; ++t) {
            vars_[t].assign(x.num_vars(AttrTypeId(t)), hash_combine(kVarSeed, t));
        }
        classes_ = count_classes();
    }

    /// Refines once; returns whether the partition split further.
    bool step() {
        std::size_t nobs = s_.num_obs(), ntypes = s_.num_attr_types();
        // Incoming sums: commutative, so the order of the pointing parts does not matter.
        std::vector<std::vector<std::uint64_t>> in_parts(nobs), in_vars(ntypes);
        for (std::uint32_t ob = 0; ob < nobs; ++ob) {
            in_parts[ob].assign(parts_[ob].size(), 0);
        }
        for (std::uint32_t t = 0; t < ntypes; ++t) {
            in_vars[t].assign(vars_[t].size(), 0);
        }
        for (std::uint32_t f = 0; f < s_.num_homs(); ++f) {
            ObId a = s_.hom(HomId(f)).dom, b = s_.hom(HomId(f)).codom;
            auto col = x_.column(HomId(f));
            for (Part p = 0; p < col.size(); ++p) {
                if (col[p] != kNoPart) {
                    in_parts[b.index()][col[p]] += hash_mix(hash_combine(f, parts_[a.index()][p]));
                }
            }
        }
        for (std::uint32_t at = 0; at < s_.num_attrs(); ++at) {
            ObId a = s_.attr(AttrId(at)).dom;
            std::uint32_t t = s_.attr(AttrId(at)).codom.index();
            auto col = x_.column(AttrId(at));
            for (Part p = 0; p < col.size(); ++p) {
                if (col[p].is_var()) {
                    in_vars[t][col[p].var_index()] +=
                        hash_mix(hash_combine(at, parts_[a.index()][p]));
                }
            }
        }
        std::vector<std::vector<std::uint64_t>> next(nobs);
        for (std::uint32_t ob = 0; ob < nobs; ++ob) {
            next[ob].resize(parts_[ob].size());
            for (Part p = 0; p < parts_[ob].size(); ++p) {
                std::uint64_t h = hash_combine(parts_[ob][p], in_parts[ob][p]);
                for (HomId f : s_.homs_from(ObId(ob))) {
                    Part q = x_.subpart(f, p);
                    h = hash_combine(h, q == kNoPart ? kUnsetMark
                                                     : parts_[s_.hom(f).codom.index()][q]);
                }
                for (AttrId a : s_.attrs_from(ObId(ob))) {
                    const Value& v = x_.subpart(a, p);
                    if (v.is_var()) {
                        h = hash_combine(h, vars_[s_.attr(a).codom.index()][v.var_index()]);
                    }
                }
                next[ob][p] = h;
            }
        }
        for (std::uint32_t t = 0; t < ntypes; ++t) {
            for (std::uint32_t v = 0; v < vars_[t].size(); ++v) {
                vars_[t][v] = hash_combine(vars_[t][v], in_vars[t][v]);
            }
        }
        parts_ = std::move(next);
        std::size_t classes = count_classes();
        bool split = classes > classes_;
        classes_ = classes;
        return split;
    }

    /// Refines until the partition is stable.
    void refine() {
        while (step()) {
        }
    }

    /// All colours, sorted (the multiset that the hash summarises).
    std::vector<std::uint64_t> sorted_colours() const {
        std::vector<std::uint64_t> all;
        for (const auto& c : parts_) {
            all.insert(all.end(), c.begin(), c.end());
        }
        for (const auto& c : vars_) {
            all.insert(all.end(), c.begin(), c.end());
        }
        std::sort(all.begin(), all.end());
        return all;
    }

    const std::vector<std::vector<std::uint64_t>>& parts() const { return parts_; }

private:
    std::size_t count_classes() const {
        auto all = sorted_colours();
        return static_cast<std::size_t>(std::unique(all.begin(), all.end()) - all.begin());
    }

    const ACSet& x_;
    const Schema& s_;
    std::vector<std::vector<std::uint64_t>> parts_;
    std::vector<std::vector<std::uint64_t>> vars_;
    std::size_t classes_ = 0;
};

bool same_shape(const ACSet& x, const ACSet& y) {
    const Schema& s = x.schema();
    for (std::uint32_t ob = 0; ob < s.num_obs(); ++ob) {
        if (x.num_parts(ObId(ob)) != y.num_parts(ObId(ob))) {
            return false;
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        if (x.num_vars(AttrTypeId(t)) != y.num_vars(AttrTypeId(t))) {
            return false;
        }
    }
    return true;
}

} // namespace

std::optional<ACSetMorphism> find_isomorphism(const ACSet& x, const ACSet& y) {
    if (!same_shape(x, y)) {
        return std::nullopt;
    }
    // Refine both in lockstep so that colours are comparable round by round; an isomorphism
    // preserves colours, so each part may only go to a part of its own colour.
    Refiner rx(x), ry(y);
    while (true) {
        bool sx = rx.step(), sy = ry.step();
        if (sx != sy) {
            return std::nullopt; // isomorphic states split in the same rounds
        }
        if (!sx) {
            break;
        }
    }
    if (rx.sorted_colours() != ry.sorted_colours()) {
        return std::nullopt;
    }
    HomSearchOptions opt;
    opt.iso = true;
    const Schema& s = x.schema();
    for (std::uint32_t ob = 0; ob < s.num_obs(); ++ob) {
        std::unordered_map<std::uint64_t, std::vector<Part>> by_colour;
        const auto& cy = ry.parts()[ob];
        for (Part q = 0; q < cy.size(); ++q) {
            by_colour[cy[q]].push_back(q);
        }
        const auto& cx = rx.parts()[ob];
        for (Part p = 0; p < cx.size(); ++p) {
            opt.restrict(ObId(ob), p, by_colour[cx[p]]);
        }
    }
    auto r = find_homomorphism(x, y, opt);
    if (!r) {
        return std::nullopt;
    }
    return std::move(r).value();
}

bool is_isomorphic(const ACSet& x, const ACSet& y) {
    return find_isomorphism(x, y).has_value();
}

std::uint64_t canonical_hash(const ACSet& x) {
    Refiner r(x);
    r.refine();
    const Schema& s = x.schema();
    std::uint64_t h = hash_mix(s.num_obs());
    for (std::uint32_t ob = 0; ob < s.num_obs(); ++ob) {
        h = hash_combine(h, x.num_parts(ObId(ob)));
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        h = hash_combine(h, x.num_vars(AttrTypeId(t)));
    }
    for (std::uint64_t c : r.sorted_colours()) {
        h = hash_combine(h, c);
    }
    return h;
}

} // namespace catplan::hom
