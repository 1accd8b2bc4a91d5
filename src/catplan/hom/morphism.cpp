#include "catplan/hom/morphism.hpp"

#include "catplan/base/assert.hpp"

#include <fmt/format.h>

namespace catplan::hom {

using schema::Schema;

ACSetMorphism identity(const ACSet& x) {
    const Schema& s = x.schema();
    ACSetMorphism id;
    id.components.resize(s.num_obs());
    for (std::uint32_t ob = 0; ob < s.num_obs(); ++ob) {
        auto& c = id.components[ob];
        c.resize(x.num_parts(ObId(ob)));
        for (Part p = 0; p < c.size(); ++p) {
            c[p] = p;
        }
    }
    id.var_components.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        auto& c = id.var_components[t];
        c.resize(x.num_vars(AttrTypeId(t)));
        for (std::uint32_t j = 0; j < c.size(); ++j) {
            c[j] = Value::var(j);
        }
    }
    return id;
}

ACSetMorphism compose(const ACSetMorphism& f, const ACSetMorphism& g) {
    CATPLAN_ASSERT(f.components.size() == g.components.size(), "compose: object counts differ");
    CATPLAN_ASSERT(f.var_components.size() == g.var_components.size(),
                   "compose: attribute type counts differ");
    ACSetMorphism h;
    h.components.resize(f.components.size());
    for (std::size_t ob = 0; ob < f.components.size(); ++ob) {
        const auto& gc = g.components[ob];
        auto& hc = h.components[ob];
        hc.reserve(f.components[ob].size());
        for (Part p : f.components[ob]) {
            CATPLAN_ASSERT(p < gc.size(), "compose: f's image is not in g's domain");
            hc.push_back(gc[p]);
        }
    }
    h.var_components.resize(f.var_components.size());
    for (std::size_t t = 0; t < f.var_components.size(); ++t) {
        const auto& gc = g.var_components[t];
        auto& hc = h.var_components[t];
        hc.reserve(f.var_components[t].size());
        for (const Value& v : f.var_components[t]) {
            if (v.is_var()) {
                CATPLAN_ASSERT(v.var_index() < gc.size(),
                               "compose: f's variable not in g's domain");
                hc.push_back(gc[v.var_index()]);
            } else {
                hc.push_back(v); // a concrete value is its own image
            }
        }
    }
    return h;
}

namespace {

// The image of a domain cell value under the variable components, or Unset when the variable has
// no valid image (that failure is reported separately, as VarImageInvalid).
Value image_of(const ACSetMorphism& f, AttrTypeId t, const Value& v) {
    if (!v.is_var()) {
        return v;
    }
    if (t.index() >= f.var_components.size() ||
        v.var_index() >= f.var_components[t.index()].size()) {
        return Value();
    }
    return f.var_components[t.index()][v.var_index()];
}

} // namespace

std::vector<NaturalityFailure> naturality_failures(const ACSetMorphism& f, const ACSet& x,
                                                   const ACSet& y) {
    const Schema& s = x.schema();
    std::vector<NaturalityFailure> out;
    // Components whose size is wrong are reported once and their squares skipped, since every
    // other check on them would only repeat the same problem.
    std::vector<bool> ob_ok(s.num_obs(), true);
    for (std::uint32_t ob = 0; ob < s.num_obs(); ++ob) {
        ObId o(ob);
        std::size_t size = ob < f.components.size() ? f.components[ob].size() : 0;
        if (size != x.num_parts(o)) {
            NaturalityFailure nf;
            nf.kind = NaturalityFailureKind::ComponentSize;
            nf.ob = o;
            nf.part = static_cast<Part>(size);
            nf.expected = static_cast<Part>(x.num_parts(o));
            out.push_back(nf);
            ob_ok[ob] = false;
            continue;
        }
        for (Part p = 0; p < size; ++p) {
            Part q = f.components[ob][p];
            if (q >= y.num_parts(o)) {
                NaturalityFailure nf;
                nf.kind = NaturalityFailureKind::PartOutOfRange;
                nf.ob = o;
                nf.part = p;
                nf.found = q;
                out.push_back(nf);
                ob_ok[ob] = false;
            }
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        std::size_t size = t < f.var_components.size() ? f.var_components[t].size() : 0;
        if (size != x.num_vars(ty)) {
            NaturalityFailure nf;
            nf.kind = NaturalityFailureKind::VarComponentSize;
            nf.type = ty;
            nf.part = static_cast<Part>(size);
            nf.expected = static_cast<Part>(x.num_vars(ty));
            out.push_back(nf);
            continue;
        }
        schema::ValueKind kind = s.attr_type(ty).kind;
        for (std::uint32_t j = 0; j < size; ++j) {
            const Value& v = f.var_components[t][j];
            bool bad = v.is_unset() || (v.is_var() && v.var_index() >= y.num_vars(ty));
            bool wrong_kind =
                v.is_concrete() && kind != schema::ValueKind::Unknown && v.kind() != kind;
            if (bad || wrong_kind) {
                NaturalityFailure nf;
                nf.kind = bad ? NaturalityFailureKind::VarImageInvalid
                              : NaturalityFailureKind::VarImageWrongKind;
                nf.type = ty;
                nf.part = j;
                nf.found_value = v;
                out.push_back(nf);
            }
        }
    }
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId hom(h);
        ObId a = s.hom(hom).dom, b = s.hom(hom).codom;
        if (!ob_ok[a.index()] || !ob_ok[b.index()]) {
            continue;
        }
        for (Part p = 0; p < x.num_parts(a); ++p) {
            Part xp = x.subpart(hom, p);
            if (xp == kNoPart) {
                continue; // an unset domain hom value constrains nothing
            }
            Part expected = y.subpart(hom, f.components[a.index()][p]);
            Part found = f.components[b.index()][xp];
            if (expected != found) {
                NaturalityFailure nf;
                nf.kind = NaturalityFailureKind::HomMismatch;
                nf.ob = a;
                nf.hom = hom;
                nf.part = p;
                nf.expected = expected;
                nf.found = found;
                out.push_back(nf);
            }
        }
    }
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId attr(at);
        ObId a = s.attr(attr).dom;
        AttrTypeId ty = s.attr(attr).codom;
        if (!ob_ok[a.index()]) {
            continue;
        }
        for (Part p = 0; p < x.num_parts(a); ++p) {
            const Value& xv = x.subpart(attr, p);
            if (xv.is_unset()) {
                continue; // an unset domain cell constrains nothing
            }
            Value expected = image_of(f, ty, xv);
            const Value& found = y.subpart(attr, f.components[a.index()][p]);
            if (expected.is_unset()) {
                continue; // already reported as VarImageInvalid or VarComponentSize
            }
            if (!(expected == found)) {
                NaturalityFailure nf;
                nf.kind = NaturalityFailureKind::AttrMismatch;
                nf.ob = a;
                nf.attr = attr;
                nf.type = ty;
                nf.part = p;
                nf.expected_value = expected;
                nf.found_value = found;
                out.push_back(nf);
            }
        }
    }
    return out;
}

std::string describe(const NaturalityFailure& nf, const ACSet& x, const ACSet& y) {
    const Schema& s = x.schema();
    switch (nf.kind) {
    case NaturalityFailureKind::ComponentSize:
        return fmt::format("component {} has {} entries, but the domain has {} parts of {}",
                           s.ob(nf.ob).name, nf.part, nf.expected, s.ob(nf.ob).name);
    case NaturalityFailureKind::PartOutOfRange:
        return fmt::format("{} part {} is sent to {}, which is not a part of the codomain "
                           "(it has {} parts of {})",
                           s.ob(nf.ob).name, x.part_label(nf.ob, nf.part),
                           nf.found == kNoPart ? std::string("nothing")
                                               : fmt::format("#{}", nf.found + 1),
                           y.num_parts(nf.ob), s.ob(nf.ob).name);
    case NaturalityFailureKind::HomMismatch: {
        ObId b = s.hom(nf.hom).codom;
        const std::string& fname = s.hom(nf.hom).name;
        std::string xp = x.part_label(nf.ob, nf.part);
        return fmt::format("hom {} at {} part {}: {}({}) = {} is sent to {} part {}, but {} of "
                           "the image of {} is {} part {}",
                           fname, s.ob(nf.ob).name, xp, fname, xp,
                           x.part_label(b, x.subpart(nf.hom, nf.part)), s.ob(b).name,
                           y.part_label(b, nf.found), fname, xp, s.ob(b).name,
                           y.part_label(b, nf.expected));
    }
    case NaturalityFailureKind::VarComponentSize:
        return fmt::format("variable component {} has {} entries, but the domain has {} "
                           "variables of {}",
                           s.attr_type(nf.type).name, nf.part, nf.expected,
                           s.attr_type(nf.type).name);
    case NaturalityFailureKind::VarImageInvalid:
        return fmt::format("variable {} of {} is sent to {}, which is not a codomain value",
                           x.value_label(nf.type, Value::var(nf.part)), s.attr_type(nf.type).name,
                           nf.found_value.to_string());
    case NaturalityFailureKind::VarImageWrongKind:
        return fmt::format("variable {} of {} is sent to {}, a {} value, but {} holds {} values",
                           x.value_label(nf.type, Value::var(nf.part)), s.attr_type(nf.type).name,
                           nf.found_value.to_string(), schema::to_string(nf.found_value.kind()),
                           s.attr_type(nf.type).name, schema::to_string(s.attr_type(nf.type).kind));
    case NaturalityFailureKind::AttrMismatch:
        return fmt::format("attribute {} at {} part {}: expected {}, found {}",
                           s.attr(nf.attr).name, s.ob(nf.ob).name, x.part_label(nf.ob, nf.part),
                           y.value_label(nf.type, nf.expected_value),
                           y.value_label(nf.type, nf.found_value));
    }
    CATPLAN_UNREACHABLE("unknown naturality failure kind");
}

bool is_natural(const ACSetMorphism& f, const ACSet& x, const ACSet& y) {
    return naturality_failures(f, x, y).empty();
}

bool is_monic(const ACSetMorphism& f, const ACSet& x, const ACSet& y) {
    const Schema& s = x.schema();
    for (std::uint32_t ob = 0; ob < s.num_obs(); ++ob) {
        std::vector<bool> hit(y.num_parts(ObId(ob)), false);
        for (Part q : f.components[ob]) {
            if (q >= hit.size() || hit[q]) {
                return false;
            }
            hit[q] = true;
        }
    }
    return true;
}

bool is_iso(const ACSetMorphism& f, const ACSet& x, const ACSet& y) {
    const Schema& s = x.schema();
    for (std::uint32_t ob = 0; ob < s.num_obs(); ++ob) {
        if (f.components[ob].size() != y.num_parts(ObId(ob))) {
            return false;
        }
    }
    if (!is_monic(f, x, y)) {
        return false;
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        const auto& c = f.var_components[t];
        if (c.size() != y.num_vars(ty)) {
            return false;
        }
        std::vector<bool> hit(c.size(), false);
        for (const Value& v : c) {
            if (!v.is_var() || v.var_index() >= hit.size() || hit[v.var_index()]) {
                return false;
            }
            hit[v.var_index()] = true;
        }
    }
    return true;
}

} // namespace catplan::hom
