// Pushout complements and the gluing conditions (colimit.hpp): what deleting m(L - l(K)) from X
// removes, what stands in the way, and the state Z that remains.

#include "catplan/base/assert.hpp"
#include "catplan/colimit/colimit.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <utility>

namespace catplan::colimit {

using acset::Value;

namespace {

bool contains(const std::vector<Part>& sorted, Part p) {
    return std::binary_search(sorted.begin(), sorted.end(), p);
}

void sort_unique(std::vector<Part>& parts) {
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
}

// The arguments of one deletion.
struct Span {
    const ACSet& k;
    const ACSet& l_state;
    const ACSet& x;
    const ACSetMorphism& l;
    const ACSetMorphism& m;
    const ComplementOptions& options;

    // Per hom (or attribute, by `attrs`): the X parts whose cell the options open, increasing.
    std::vector<std::vector<Part>> open_images(bool attrs) const {
        const auto& s = x.schema();
        const auto& open = attrs ? options.open.attrs : options.open.homs;
        std::vector<std::vector<Part>> out(attrs ? s.num_attrs() : s.num_homs());
        for (std::size_t i = 0; i < open.size() && i < out.size(); ++i) {
            ObId dom = attrs ? s.attr(AttrId(static_cast<std::uint32_t>(i))).dom
                             : s.hom(HomId(static_cast<std::uint32_t>(i))).dom;
            for (Part kp : open[i]) {
                out[i].push_back(m(dom, l(dom, kp)));
            }
            sort_unique(out[i]);
        }
        return out;
    }
};

// A left leg that is not monic, and the identification condition: a deleted part of L (one of
// `outside`) must not share its image with another part of L.
void check_left(const Span& in, const std::vector<std::vector<Part>>& outside, Deletion& out) {
    const auto& s = in.x.schema();
    // Per part of L, reused from object to object: kept once (kSeen), not kept at all (kDeleted).
    constexpr char kSeen = 1, kDeleted = 2;
    std::vector<char> flags;
    std::vector<std::pair<Part, Part>> by_image;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        if (in.l_state.num_parts(ob) == 0) {
            continue; // nor any of K, which l sends into L
        }
        flags.assign(in.l_state.num_parts(ob), 0);
        for (Part kp = 0; kp < in.k.num_parts(ob); ++kp) {
            Part lp = in.l(ob, kp);
            if (flags[lp] & kSeen) {
                out.violations.push_back(
                    {GluingViolationKind::NotMonic, ob, lp, kNoPart, HomId(), kNoPart,
                     fmt::format("the rule's left leg is not monic: two parts of {} are kept as {}",
                                 s.ob(ob).name, in.l_state.part_label(ob, lp))});
            }
            flags[lp] |= kSeen;
        }
        for (Part p : outside[o]) {
            flags[p] |= kDeleted;
        }
        // Group L's parts by image; each later member of a group is compared with the first.
        by_image.clear();
        for (Part p = 0; p < in.l_state.num_parts(ob); ++p) {
            by_image.emplace_back(in.m(ob, p), p);
        }
        std::sort(by_image.begin(), by_image.end());
        std::vector<std::pair<Part, GluingViolation>> found; // keyed by the later L part
        for (std::size_t i = 0, first = 0; i < by_image.size(); ++i) {
            auto [img, p] = by_image[i];
            if (img != by_image[first].first) {
                first = i;
            }
            Part q = by_image[first].second;
            if (first == i || !((flags[p] | flags[q]) & kDeleted)) {
                continue;
            }
            Part del = (flags[p] & kDeleted) ? p : q;
            Part other = del == p ? q : p;
            found.emplace_back(
                p, GluingViolation{
                       GluingViolationKind::Identification, ob, del, other, HomId(), img,
                       fmt::format("identification: {} {} is deleted but the match "
                                   "also sends {} to {}",
                                   s.ob(ob).name, in.l_state.part_label(ob, del),
                                   in.l_state.part_label(ob, other), in.x.part_label(ob, img))});
        }
        std::stable_sort(found.begin(), found.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (auto& [p, v] : found) {
            out.violations.push_back(std::move(v));
        }
    }
}

// The dangling condition: no part left in X refers through a hom that is not open to a deleted
// part. Visits the deleted parts' preimages only.
void check_dangling(const Span& in, Deletion& out) {
    const auto& s = in.x.schema();
    auto open = in.open_images(/*attrs=*/false);
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f(h);
        ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
        std::vector<std::pair<Part, Part>> found; // (referring part, deleted part)
        for (Part y : out.parts[codom.index()]) {
            for (Part q : in.x.incident(f, y)) {
                if (!contains(out.parts[dom.index()], q) && !contains(open[h], q)) {
                    found.emplace_back(q, y);
                }
            }
        }
        std::sort(found.begin(), found.end());
        for (auto [q, y] : found) {
            out.violations.push_back(
                {GluingViolationKind::Dangling, dom, q, kNoPart, f, y,
                 fmt::format("dangling: {} {} refers through {} to {} {}, which the rule deletes",
                             s.ob(dom).name, in.x.part_label(dom, q), s.hom(f).name,
                             s.ob(codom).name, in.x.part_label(codom, y))});
        }
    }
}

// Single-pushout deletion: the parts referring to a deleted part are deleted too, and so on; a
// kept part reached through a hom that is not open is a violation. Marks cost O(size of X).
void cascade(const Span& in, Deletion& out) {
    const auto& s = in.x.schema();
    auto open = in.open_images(/*attrs=*/false);
    std::vector<std::vector<char>> mark(s.num_obs()), kept(s.num_obs());
    std::vector<std::pair<ObId, Part>> work;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        mark[o].assign(in.x.num_parts(ob), 0);
        kept[o].assign(in.x.num_parts(ob), 0);
        for (Part kp = 0; kp < in.k.num_parts(ob); ++kp) {
            kept[o][in.m(ob, in.l(ob, kp))] = 1;
        }
        for (Part y : out.parts[o]) {
            mark[o][y] = 1;
            work.emplace_back(ob, y);
        }
    }
    while (!work.empty()) {
        auto [ob, y] = work.back();
        work.pop_back();
        for (HomId f : s.homs_into(ob)) {
            ObId dom = s.hom(f).dom;
            for (Part q : in.x.incident(f, y)) {
                if (mark[dom.index()][q] ||
                    (kept[dom.index()][q] && contains(open[f.index()], q))) {
                    continue;
                }
                if (kept[dom.index()][q]) {
                    out.violations.push_back(
                        {GluingViolationKind::Cascade, dom, q, kNoPart, f, y,
                         fmt::format("SPO: deleting {} {} would delete {} {}, which the rule keeps",
                                     s.ob(ob).name, in.x.part_label(ob, y), s.ob(dom).name,
                                     in.x.part_label(dom, q))});
                    continue;
                }
                mark[dom.index()][q] = 1;
                out.parts[dom.index()].push_back(q);
                work.emplace_back(dom, q);
            }
        }
    }
    for (auto& parts : out.parts) {
        std::sort(parts.begin(), parts.end());
    }
}

} // namespace

std::vector<std::vector<Part>> deleted_images(const ACSetMorphism& m,
                                              const std::vector<std::vector<Part>>& outside_l) {
    std::vector<std::vector<Part>> out(outside_l.size());
    for (std::uint32_t o = 0; o < outside_l.size(); ++o) {
        for (Part p : outside_l[o]) {
            out[o].push_back(m(ObId(o), p));
        }
        sort_unique(out[o]);
    }
    return out;
}

Deletion deletion(const ACSet& k, const ACSet& l_state, const ACSet& x, const ACSetMorphism& l,
                  const ACSetMorphism& m, const ComplementOptions& options) {
    Span in{k, l_state, x, l, m, options};
    std::vector<std::vector<Part>> computed;
    if (options.outside_l.empty()) {
        computed = parts_outside_image(l, l_state);
    }
    const auto& outside = options.outside_l.empty() ? computed : options.outside_l;
    Deletion out;
    out.parts = deleted_images(m, outside);
    out.parts.resize(x.schema().num_obs());
    check_left(in, outside, out);
    if (options.cascade) {
        cascade(in, out);
    } else {
        check_dangling(in, out);
    }
    return out;
}

std::vector<GluingViolation> gluing_violations(const ACSet& k, const ACSet& l_state, const ACSet& x,
                                               const ACSetMorphism& l, const ACSetMorphism& m,
                                               const ComplementOptions& options) {
    return deletion(k, l_state, x, l, m, options).violations;
}

Result<PushoutComplement> pushout_complement(const ACSet& k, const ACSet& l_state, const ACSet& x,
                                             const ACSetMorphism& l, const ACSetMorphism& m,
                                             const ComplementOptions& options) {
    Deletion d = deletion(k, l_state, x, l, m, options);
    if (!d.violations.empty()) {
        std::string reason;
        for (const auto& v : d.violations) {
            reason += (reason.empty() ? "" : "; ") + v.reason;
        }
        return fail(reason);
    }
    const auto& s = x.schema();
    for (std::size_t h = 0; h < options.open.homs.size(); ++h) {
        for (Part kp : options.open.homs[h]) {
            CATPLAN_ASSERT(k.subpart(HomId(static_cast<std::uint32_t>(h)), kp) == kNoPart,
                           "an open hom must be unset in K");
        }
    }
    for (std::size_t a = 0; a < options.open.attrs.size(); ++a) {
        for (Part kp : options.open.attrs[a]) {
            CATPLAN_ASSERT(k.subpart(AttrId(static_cast<std::uint32_t>(a)), kp).is_unset(),
                           "an open attribute must be unset in K");
        }
    }
    Span in{k, l_state, x, l, m, options};
    auto open_homs = in.open_images(/*attrs=*/false);
    auto open_attrs = in.open_images(/*attrs=*/true);
    PushoutComplement out{ACSet(x.schema_ptr()), {}, {}};
    ACSet& z = out.z;
    out.z_to_x.components.resize(s.num_obs());
    std::vector<std::vector<Part>> renumber(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        renumber[o].assign(x.num_parts(ob), kNoPart);
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            if (!contains(d.parts[o], p)) {
                renumber[o][p] = z.add_part(ob, x.part_name(ob, p));
                out.z_to_x.components[o].push_back(p);
            }
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t j = 0; j < x.num_vars(ty); ++j) {
            z.add_var(ty, x.var_name(ty, j));
        }
    }
    out.z_to_x.var_components = hom::identity(z).var_components;
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f(h);
        ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
        for (Part p = 0; p < x.num_parts(dom); ++p) {
            Part t = x.subpart(f, p);
            if (renumber[dom.index()][p] == kNoPart || t == kNoPart || contains(open_homs[h], p)) {
                continue;
            }
            CATPLAN_ASSERT(renumber[codom.index()][t] != kNoPart, "a dangling hom survived");
            z.set_subpart(f, renumber[dom.index()][p], renumber[codom.index()][t]);
        }
    }
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId attr(at);
        ObId dom = s.attr(attr).dom;
        for (Part p = 0; p < x.num_parts(dom); ++p) {
            if (renumber[dom.index()][p] != kNoPart && !contains(open_attrs[at], p)) {
                z.set_subpart(attr, renumber[dom.index()][p], x.subpart(attr, p));
            }
        }
    }
    out.k_to_z.components.resize(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < k.num_parts(ob); ++p) {
            out.k_to_z.components[o].push_back(renumber[o][m(ob, l(ob, p))]);
        }
    }
    out.k_to_z.var_components.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t j = 0; j < k.num_vars(ty); ++j) {
            Value v = l.var(ty, j);
            out.k_to_z.var_components[t].push_back(v.is_var() ? m.var(ty, v.var_index()) : v);
        }
    }
    return out;
}

} // namespace catplan::colimit
