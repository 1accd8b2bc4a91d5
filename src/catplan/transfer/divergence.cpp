#include "catplan/transfer/divergence.hpp"

#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/transfer/terms.hpp"

#include <algorithm>
#include <map>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using acset::Value;
using hom::ACSetMorphism;
using migrate::Query;

std::string value_text(const Value& v) {
    if (v.is_concrete()) {
        return v.to_string();
    }
    return v.is_var() ? "?" : "_";
}

// An assignment of a query in X: a morphism from its shape, or for a plain query the part its
// one variable takes.
struct Tuple {
    const ACSetMorphism* h = nullptr;
    Part plain = kNoPart;

    Part at(ObId ob, Part shape) const { return h ? (*h)(ob, shape) : plain; }

    Value var(AttrTypeId t, std::uint32_t j) const { return h ? h->var(t, j) : Value(); }
};

// Calls fn for every assignment of q in x that sends part `shape` of ob to p.
template <class Fn>
void for_each_tuple(const Query& q, const ACSet& x, ObId ob, Part shape, Part p, Fn&& fn) {
    if (q.is_plain()) {
        fn(Tuple{nullptr, p});
        return;
    }
    hom::HomSearchOptions opt;
    opt.bind(ob, shape, p);
    hom::for_each_homomorphism(q.state(), x, opt, [&](const ACSetMorphism& h) {
        fn(Tuple{&h, kNoPart});
        return true;
    });
}

// What a part of a target state states, with its hom values by the names of their targets:
// "name|target name of each hom|each attribute value".
std::string target_record(const ACSet& y, ObId c, Part q, bool with_name = true) {
    const auto& s = y.schema();
    std::string out(with_name ? y.part_name(c, q) : std::string_view());
    for (HomId f : s.homs_from(c)) {
        Part r = y.subpart(f, q);
        out += '|';
        out += r == kNoPart ? std::string("_") : std::string(y.part_name(s.hom(f).codom, r));
    }
    for (AttrId a : s.attrs_from(c)) {
        out += '|' + value_text(y.subpart(a, q));
    }
    return out;
}

// Every statement of x (terms.hpp), part by part in x's order.
std::vector<std::string> statements(const ACSet& x) {
    std::vector<std::string> out;
    for (std::uint32_t o = 0; o < x.schema().num_obs(); ++o) {
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            auto st = part_statements(x, ObId(o), p);
            out.insert(out.end(), st.begin(), st.end());
        }
    }
    return out;
}

// The statements of a that b does not make (as multisets), in a's order.
std::vector<std::string> only_in(const std::vector<std::string>& a,
                                 const std::vector<std::string>& b) {
    std::map<std::string_view, std::size_t> count;
    for (const auto& s : b) {
        ++count[s];
    }
    std::vector<std::string> out;
    for (const auto& s : a) {
        auto it = count.find(s);
        if (it != count.end() && it->second > 0) {
            --it->second;
        } else {
            out.push_back(s);
        }
    }
    return out;
}

// Whether every part of a and b has a name no other part of its object has, and the parts of
// each object state the same records: then "same name" is an isomorphism b -> a (up to which
// cells share an unknown). With facts_by_content, a part of an object nothing points into (a
// fact) is compared by its values alone, its name left out: then "same name" on the other parts
// and "same values" on the facts is an isomorphism (equal facts are interchangeable, since no
// part refers to them), though not one by names.
bool same_by_names(const ACSet& a, const ACSet& b, bool facts_by_content = false) {
    const auto& s = a.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId c(o);
        if (a.num_parts(c) != b.num_parts(c)) {
            return false;
        }
        bool by_content = facts_by_content && s.homs_into(c).empty();
        std::vector<std::string> ra, rb;
        std::vector<std::string_view> na, nb;
        for (Part p = 0; p < a.num_parts(c); ++p) {
            ra.push_back(target_record(a, c, p, !by_content));
            rb.push_back(target_record(b, c, p, !by_content));
            na.push_back(a.part_name(c, p));
            nb.push_back(b.part_name(c, p));
        }
        for (auto* names : {&na, &nb}) {
            std::sort(names->begin(), names->end());
            if (!by_content && (std::adjacent_find(names->begin(), names->end()) != names->end() ||
                                (!names->empty() && names->front().empty()))) {
                return false;
            }
        }
        std::sort(ra.begin(), ra.end());
        std::sort(rb.begin(), rb.end());
        if (ra != rb) {
            return false;
        }
    }
    return true;
}

} // namespace

DivergenceCheck::DivergenceCheck(const migrate::SchemaMap& f, const Renaming& renaming)
    : f_(f), renaming_(renaming), pins_(f.source()->num_obs()) {
    for (const auto& [from, to] : renaming) {
        inverse_.emplace(to, from);
    }
    const auto& t = *f.target();
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        const Query& q = f.query(ObId(c));
        if (q.is_empty() || !q.first_object_node()) {
            continue; // no tuples, or the one tuple of @unit, which no step changes
        }
        const ACSet& shape = q.state();
        for (std::uint32_t o = 0; o < shape.schema().num_obs(); ++o) {
            for (Part s = 0; s < shape.num_parts(ObId(o)); ++s) {
                pins_[o].push_back({ObId(c), s});
            }
        }
    }
    for (std::uint32_t h = 0; h < t.num_homs(); ++h) {
        const auto& im = f.hom_image(HomId(h));
        if (im.path && im.path->size() >= 2) {
            ObId c = t.hom(HomId(h)).dom;
            auto el = f.query(c).locate_node(0);
            reaches_.push_back({c, el.ob, el.part, *im.path, im.path->size() - 1});
        }
    }
    for (std::uint32_t a = 0; a < t.num_attrs(); ++a) {
        const auto& im = f.attr_image(AttrId(a));
        if (im.kind == migrate::AttrImage::Kind::Path && !im.homs.empty()) {
            reaches_.push_back(
                {t.attr(AttrId(a)).dom, im.start_ob, im.start, im.homs, im.homs.size()});
        }
    }
}

std::string DivergenceCheck::source_name(const ACSet& x, ObId ob, Part p) const {
    return p == kNoPart ? std::string("_") : renamed(renaming_, x.part_name(ob, p));
}

void DivergenceCheck::pinned_keys(const ACSet& x, ObId c, ObId ob, Part shape, Part p) {
    const Query& q = f_.query(c);
    auto el = q.locate_node(*q.first_object_node());
    for_each_tuple(q, x, ob, shape, p, [&](const Tuple& t) {
        keys_.emplace(c.index(), source_name(x, el.ob, t.at(el.ob, el.part)));
    });
}

void DivergenceCheck::source_keys(const ACSetMorphism& m, const ACSet& x) {
    const auto& s = x.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p : m.components[o]) {
            for (const Pin& pin : pins_[o]) {
                pinned_keys(x, pin.c, ObId(o), pin.shape, p);
            }
            // A path of the map that reads p at position j starts at the parts p is reached
            // from backwards along the path's first j homs.
            for (const Reach& r : reaches_) {
                for (std::size_t j = 1; j <= r.upto; ++j) {
                    if (s.hom(r.homs[j - 1]).codom != ObId(o)) {
                        continue;
                    }
                    std::vector<Part> at{p};
                    for (std::size_t k = j; k-- > 0;) {
                        std::vector<Part> back;
                        for (Part q : at) {
                            auto in = x.incident(r.homs[k], q);
                            back.insert(back.end(), in.begin(), in.end());
                        }
                        at = std::move(back);
                    }
                    for (Part start : at) {
                        pinned_keys(x, r.c, r.start_ob, r.start, start);
                    }
                }
            }
        }
    }
}

void DivergenceCheck::target_keys(const ACSetMorphism& mt, const ACSet& y) {
    for (std::uint32_t c = 0; c < y.schema().num_obs(); ++c) {
        for (Part q : mt.components[c]) {
            keys_.emplace(c, std::string(y.part_name(ObId(c), q)));
        }
    }
}

std::optional<bool> DivergenceCheck::agree(const Key& key, const NamedState& xn,
                                           const NamedState& yn) const {
    const auto& [ci, name] = key;
    ObId c(ci);
    const ACSet& x = xn.state();
    const ACSet& y = yn.state();
    if (name.empty() || yn.ambiguous(c, name)) {
        return std::nullopt;
    }
    const Query& q = f_.query(c);
    auto el = q.locate_node(*q.first_object_node());
    auto inv = inverse_.find(name);
    const std::string& xname = inv == inverse_.end() ? name : inv->second;
    if (xn.ambiguous(el.ob, xname)) {
        return std::nullopt;
    }
    // The record of each tuple of Δ_F(X) at the key.
    std::vector<std::string> records;
    if (Part p = xn.find(el.ob, xname); p != kNoPart) {
        const auto& t = *f_.target();
        for_each_tuple(q, x, el.ob, el.part, p, [&](const Tuple& tu) {
            std::string r = source_name(x, el.ob, tu.at(el.ob, el.part));
            for (HomId fh : t.homs_from(c)) {
                const auto& im = f_.hom_image(fh);
                r += '|';
                if (im.path) {
                    Part end = migrate::follow(x, tu.at(el.ob, el.part), *im.path);
                    ObId end_ob = im.path->empty() ? el.ob : x.schema().hom(im.path->back()).codom;
                    r += source_name(x, end_ob, end);
                } else if (auto dn = f_.query(t.hom(fh).codom).first_object_node()) {
                    auto eld = f_.query(t.hom(fh).codom).locate_node(*dn);
                    r += source_name(x, eld.ob, tu.at(eld.ob, (*im.morphism)(eld.ob, eld.part)));
                }
            }
            for (AttrId a : t.attrs_from(c)) {
                const auto& im = f_.attr_image(a);
                Value v;
                switch (im.kind) {
                case migrate::AttrImage::Kind::None:
                    break;
                case migrate::AttrImage::Kind::Constant:
                    v = im.constant;
                    break;
                case migrate::AttrImage::Kind::Value:
                    v = im.value.is_var() ? tu.var(im.type, im.value.var_index()) : im.value;
                    break;
                case migrate::AttrImage::Kind::Path: {
                    Part e = migrate::follow(x, tu.at(im.start_ob, im.start), im.homs);
                    v = e == kNoPart ? Value() : x.subpart(im.attr, e);
                    break;
                }
                }
                r += '|' + value_text(v);
            }
            records.push_back(std::move(r));
        });
    }
    if (records.size() > 1) {
        return std::nullopt;
    }
    Part q_y = yn.find(c, name);
    if (q_y == kNoPart || records.empty()) {
        return q_y == kNoPart && records.empty();
    }
    for (HomId fh : y.schema().homs_from(c)) {
        ObId d = y.schema().hom(fh).codom;
        Part r = y.subpart(fh, q_y);
        if (r != kNoPart && yn.ambiguous(d, y.part_name(d, r))) {
            return std::nullopt;
        }
    }
    return records.front() == target_record(y, c, q_y);
}

void DivergenceCheck::before(const ACSetMorphism& m, const NamedState& x, const ACSetMorphism& mt,
                             const NamedState& y) {
    if (local_) {
        source_keys(m, x.state());
        target_keys(mt, y.state());
    }
}

std::optional<Divergence> DivergenceCheck::after(std::size_t step, const ACSetMorphism& r,
                                                 const NamedState& x, const ACSetMorphism& rt,
                                                 const NamedState& y) {
    bool agreed = local_;
    if (agreed) {
        source_keys(r, x.state());
        target_keys(rt, y.state());
        for (const Key& key : keys_) {
            auto a = agree(key, x, y);
            if (!a || !*a) {
                agreed = false;
                break;
            }
        }
    }
    keys_.clear();
    if (agreed) {
        return std::nullopt;
    }
    return compare_whole(step, x, y);
}

std::optional<Divergence> DivergenceCheck::compare_whole(std::size_t step, const NamedState& xn,
                                                         const NamedState& yn) {
    ACSet z = migrate::migrate(f_, xn.state());
    rename_parts(z, renaming_);
    return compare_states(step, z, yn.state());
}

std::optional<Divergence> DivergenceCheck::compare_repaired(std::size_t step, const ACSet& z,
                                                            const NamedState& y,
                                                            bool holds_by_names) {
    keys_.clear();
    const ACSet& ys = y.state();
    bool bijective = holds_by_names;
    const auto& s = ys.schema();
    for (std::uint32_t o = 0; bijective && o < s.num_obs(); ++o) {
        bijective = z.num_parts(ObId(o)) == ys.num_parts(ObId(o));
    }
    for (std::uint32_t t = 0; bijective && t < s.num_attr_types(); ++t) {
        bijective = z.num_vars(AttrTypeId(t)) == 0 && ys.num_vars(AttrTypeId(t)) == 0;
    }
    if (!bijective) {
        return compare_states(step, z, ys);
    }
    ++whole_;
    local_ = false; // isomorphic, but not by names (a repair names what it creates its own way)
    return std::nullopt;
}

std::optional<Divergence> DivergenceCheck::compare_states(std::size_t step, const ACSet& z,
                                                          const ACSet& y) {
    ++whole_;
    local_ = same_by_names(z, y);
    if (local_ || same_by_names(z, y, true) ||
        (hom::canonical_hash(z) == hom::canonical_hash(y) && hom::is_isomorphic(z, y))) {
        return std::nullopt;
    }
    Divergence d;
    d.step = step;
    auto sy = statements(y);
    auto sz = statements(z);
    auto target = only_in(sy, sz);
    auto migrated = only_in(sz, sy);
    constexpr std::size_t kMax = Divergence::kMaxListed;
    std::size_t nm = std::min(migrated.size(), kMax / 2);
    std::size_t nt = std::min(target.size(), kMax - nm);
    nm = std::min(migrated.size(), kMax - nt);
    d.more = target.size() + migrated.size() - nt - nm;
    d.only_in_target.assign(target.begin(), target.begin() + static_cast<std::ptrdiff_t>(nt));
    d.only_in_migrated.assign(migrated.begin(), migrated.begin() + static_cast<std::ptrdiff_t>(nm));
    return d;
}

} // namespace catplan::transfer
