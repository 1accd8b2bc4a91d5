#include "catplan/hom/forced.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/hom/detail/search_engine.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace catplan::hom {
namespace {

using acset::ACSet;
using acset::Value;

// Domains this small are what propagation is for (a rule's Pre); injectivity is checked by a
// scan of the parts already placed, which a larger domain would make cost more than a search.
constexpr std::size_t kMaxParts = 64;

// The parts of X placed so far (each forced), kept as the morphism's components.
class Propagation {
public:
    Propagation(const ACSet& x, const ACSet& y, const HomSearchOptions& opt)
        : x_(x), y_(y), s_(x.schema()), opt_(opt) {}

    Forced run();

private:
    bool supported() const;
    bool agrees(std::uint32_t ob, Part p, Part q) const;
    bool assign(std::uint32_t ob, Part p, Part q);
    bool propagate();
    bool monic(std::uint32_t ob) const;
    bool choose(std::uint32_t& ob, Part& p, std::optional<HomId>& f) const;
    Forced decide();

    const ACSet& x_;
    const ACSet& y_;
    const schema::Schema& s_;
    const HomSearchOptions& opt_;
    ACSetMorphism m_;
    // Placed parts whose homs are not followed yet (at most every part of X, once).
    std::array<std::pair<std::uint32_t, Part>, kMaxParts> work_;
    std::size_t pending_ = 0;
    std::size_t unassigned_ = 0;
};

// Options this reads, a domain without attribute variables, and bindings in range (the search
// asserts on those out of range).
bool Propagation::supported() const {
    if (opt_.iso || !opt_.iso_obs.empty() || !opt_.candidates.empty() ||
        !opt_.initial_vars.empty() || !opt_.monic_attr_types.empty() || opt_.node_limit != 0 ||
        opt_.initial.empty() || x_.total_parts() > kMaxParts) {
        return false;
    }
    for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
        if (x_.num_vars(AttrTypeId(t)) != 0) {
            return false;
        }
    }
    for (ObId ob : opt_.monic) {
        if (ob.index() >= s_.num_obs()) {
            return false;
        }
    }
    return std::all_of(opt_.initial.begin(), opt_.initial.end(), [&](const PartBinding& b) {
        return b.ob.index() < s_.num_obs() && b.dom < x_.num_parts(b.ob) &&
               b.codom < y_.num_parts(b.ob);
    });
}

// Whether p may go to q given the parts placed so far: injective where asked, accepted, equal
// concrete attribute values (an unset cell of X constrains nothing), and every hom of p into a
// placed part sent where that part went.
bool Propagation::agrees(std::uint32_t ob, Part p, Part q) const {
    const auto& placed = m_.components[ob];
    if (monic(ob) && std::find(placed.begin(), placed.end(), q) != placed.end()) {
        return false;
    }
    if (opt_.accept && !opt_.accept(ObId(ob), p, q)) {
        return false;
    }
    for (AttrId a : s_.attrs_from(ObId(ob))) {
        const Value& xv = x_.subpart(a, p);
        if (!xv.is_unset() && !(xv == y_.subpart(a, q))) {
            return false;
        }
    }
    for (HomId f : s_.homs_from(ObId(ob))) {
        Part t = x_.subpart(f, p);
        if (t == kNoPart) {
            continue; // an unset hom value of X constrains nothing
        }
        Part yt = y_.subpart(f, q);
        Part image = m_.components[s_.hom(f).codom.index()][t];
        if (yt == kNoPart || (image != kNoPart && image != yt)) {
            return false;
        }
    }
    return true;
}

// Places p at q; false when a part placed before forbids it (then no morphism exists, as every
// placement so far was forced).
bool Propagation::assign(std::uint32_t ob, Part p, Part q) {
    Part cur = m_.components[ob][p];
    if (cur != kNoPart) {
        return cur == q;
    }
    if (!agrees(ob, p, q)) {
        return false;
    }
    m_.components[ob][p] = q;
    --unassigned_;
    work_[pending_++] = {ob, p};
    return true;
}

bool Propagation::monic(std::uint32_t ob) const {
    return opt_.monic_all || std::any_of(opt_.monic.begin(), opt_.monic.end(),
                                         [&](ObId m) { return m.index() == ob; });
}

// Follows the homs out of every newly placed part: their images are forced.
bool Propagation::propagate() {
    while (pending_ > 0) {
        auto [ob, p] = work_[--pending_];
        Part q = m_.components[ob][p];
        for (HomId f : s_.homs_from(ObId(ob))) {
            Part t = x_.subpart(f, p);
            if (t != kNoPart && !assign(s_.hom(f).codom.index(), t, y_.subpart(f, q))) {
                return false;
            }
        }
    }
    return true;
}

// An unplaced part with a hom f into a placed part (its image is among the preimages of f), or
// else a part of an object without homs (a fact of no arguments: its image is among all the
// parts of its object in Y), f then unset.
bool Propagation::choose(std::uint32_t& ob, Part& p, std::optional<HomId>& f) const {
    std::optional<std::pair<std::uint32_t, Part>> nullary;
    for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
        bool no_homs = s_.homs_from(ObId(o)).empty();
        for (Part q = 0; q < x_.num_parts(ObId(o)); ++q) {
            if (m_.components[o][q] != kNoPart) {
                continue;
            }
            if (no_homs && !nullary) {
                nullary.emplace(o, q);
            }
            for (HomId g : s_.homs_from(ObId(o))) {
                Part t = x_.subpart(g, q);
                if (t != kNoPart && m_.components[s_.hom(g).codom.index()][t] != kNoPart) {
                    ob = o;
                    p = q;
                    f = g;
                    return true;
                }
            }
        }
    }
    if (nullary) {
        std::tie(ob, p) = *nullary;
        f.reset();
        return true;
    }
    return false;
}

Forced Propagation::decide() {
    Forced none{Forced::Kind::None, {}};
    for (const PartBinding& b : opt_.initial) {
        if (!assign(b.ob.index(), b.dom, b.codom) || !propagate()) {
            return none;
        }
    }
    while (unassigned_ > 0) {
        std::uint32_t ob = 0;
        Part p = kNoPart;
        std::optional<HomId> f;
        if (!choose(ob, p, f)) {
            return {}; // a part no hom from a placed part reaches: search
        }
        Part only = kNoPart;
        auto consider = [&](Part q) {
            if (!agrees(ob, p, q)) {
                return true;
            }
            if (only != kNoPart) {
                return false; // two candidates: search
            }
            only = q;
            return true;
        };
        if (f) {
            Part target = m_.components[s_.hom(*f).codom.index()][x_.subpart(*f, p)];
            for (Part q : y_.incident(*f, target)) {
                if (!consider(q)) {
                    return {};
                }
            }
        } else {
            for (Part q = 0; q < y_.num_parts(ObId(ob)); ++q) {
                if (!consider(q)) {
                    return {};
                }
            }
        }
        if (only == kNoPart || !assign(ob, p, only) || !propagate()) {
            return none;
        }
    }
    return {Forced::Kind::One, std::move(m_)};
}

Forced Propagation::run() {
    if (!supported()) {
        return {};
    }
    std::size_t nobs = s_.num_obs();
    m_.components.resize(nobs);
    for (std::uint32_t ob = 0; ob < nobs; ++ob) {
        m_.components[ob].assign(x_.num_parts(ObId(ob)), kNoPart);
        unassigned_ += x_.num_parts(ObId(ob));
    }
    m_.var_components.resize(s_.num_attr_types());
    return decide();
}

} // namespace

Forced forced_homomorphism(const ACSet& x, const ACSet& y, const HomSearchOptions& options) {
    CATPLAN_ASSERT(detail::searchable(x, y), "hom search between states on different schemas");
    return Propagation(x, y, options).run();
}

} // namespace catplan::hom
