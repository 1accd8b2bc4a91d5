// Created facts merged into equal ones (detail/relations.hpp).

#include "catplan/rewrite/detail/relations.hpp"

#include <algorithm>

namespace catplan::rewrite::detail {
namespace {

using acset::ACSet;

// Whether parts p and q of ob have the same value under every hom and attribute out of ob.
bool same_values(const ACSet& x, ObId ob, Part p, Part q) {
    const auto& s = x.schema();
    for (HomId f : s.homs_from(ob)) {
        if (x.subpart(f, p) != x.subpart(f, q)) {
            return false;
        }
    }
    for (AttrId a : s.attrs_from(ob)) {
        if (!(x.subpart(a, p) == x.subpart(a, q))) {
            return false;
        }
    }
    return true;
}

// Whether some part refers to p (then it is not merged: its referrers would have to move).
bool referred_to(const ACSet& x, ObId ob, Part p) {
    for (HomId f : x.schema().homs_into(ob)) {
        if (!x.incident(f, p).empty()) {
            return true;
        }
    }
    return false;
}

// A part of ob other than p with p's values, that is not itself to be removed; kNoPart if none.
Part equal_part(const ACSet& x, ObId ob, Part p, const std::vector<Part>& removed) {
    auto homs = x.schema().homs_from(ob);
    auto fits = [&](Part q) {
        return q != p && std::find(removed.begin(), removed.end(), q) == removed.end() &&
               same_values(x, ob, p, q);
    };
    if (!homs.empty()) {
        Part target = x.subpart(homs[0], p);
        if (target == kNoPart) {
            return kNoPart;
        }
        for (Part q : x.incident(homs[0], target)) {
            if (fits(q)) {
                return q;
            }
        }
        return kNoPart;
    }
    for (Part q = 0; q < x.num_parts(ob); ++q) {
        if (fits(q)) {
            return q;
        }
    }
    return kNoPart;
}

} // namespace

void merge_created_facts(const Rule& rule, ACSet& x, hom::ACSetMorphism& r_to_x) {
    for (ObId ob : rule.relations) {
        auto& images = r_to_x.components[ob.index()];
        std::vector<Part> removed;
        for (Part rp : rule.created_parts(ob)) {
            Part p = images[rp];
            if (referred_to(x, ob, p)) {
                continue;
            }
            Part q = equal_part(x, ob, p, removed);
            if (q != kNoPart) {
                removed.push_back(p);
                std::replace(images.begin(), images.end(), p, q);
            }
        }
        // Largest id first, so the part a pop-and-swap moves is never one still to remove.
        std::sort(removed.begin(), removed.end(), std::greater<>());
        for (Part p : removed) {
            Part moved = x.remove_part(ob, p);
            if (moved != kNoPart) {
                std::replace(images.begin(), images.end(), moved, p);
            }
        }
    }
}

} // namespace catplan::rewrite::detail
