// Composition of schema maps: Δ_second ∘ Δ_first as one map.
//
// When `second` is a delta map (every object to an object c', every hom to a path of D'), each
// object takes first's query of c', each hom the composite of first's images along the path
// (re-expressed as terms of the domain's query), each attribute first's image transported along
// the path. When `first` is a delta map, each query of second (over D') is carried to D by
// translating every term through first (the left adjoint Σ on the query's shape): a part of the
// shape is named by its witness term, and each hom value and attribute cell of the shape becomes
// an equation.

#include "catplan/base/assert.hpp"
#include "catplan/migrate/detail/loc.hpp"
#include "catplan/migrate/schema_map.hpp"

#include <utility>

namespace catplan::migrate {

namespace {

std::string problems_text(const std::vector<MapProblem>& problems) {
    std::string s;
    for (const MapProblem& p : problems) {
        if (p.severity == Severity::Error) {
            s += (s.empty() ? "" : "; ") + p.message;
        }
    }
    return s;
}

using detail::Loc;
using detail::step_back;

Term loc_term(const Query& q, const Loc& loc, std::optional<AttrId> attr = std::nullopt) {
    Term w = q.witness(loc.ob, loc.part);
    w.homs.insert(w.homs.end(), loc.suffix.begin(), loc.suffix.end());
    w.attr = attr;
    return w;
}

// Carries a value of the query of a path's end to the query of its start; nullopt when a delta
// entry on the way has no values (which cannot happen for a value that is a query variable).
std::optional<Value> carry_value(const SchemaMap& m, const std::vector<HomId>& path, AttrTypeId t,
                                 Value v) {
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
        if (!v.is_var()) {
            return v;
        }
        const HomImage& im = m.hom_image(*it);
        if (!im.morphism) {
            return std::nullopt;
        }
        v = im.morphism->var(t, v.var_index());
    }
    return v;
}

Result<SchemaMap> second_delta(const SchemaMap& first, const SchemaMap& second) {
    const schema::Schema& t2 = *second.target();
    const schema::Schema& t1 = *first.target();
    SchemaMap out(second.target(), first.source());
    for (std::uint32_t c = 0; c < t2.num_obs(); ++c) {
        out.map_ob(ObId(c), first.query(second.plain_ob(ObId(c))));
    }
    for (std::uint32_t a = 0; a < t2.num_attr_types(); ++a) {
        AttrTypeId mid;
        if (auto img = second.attr_type_image(AttrTypeId(a))) {
            mid = *img;
        } else {
            out.map_attr_type(AttrTypeId(a), second.attr_type_kind(AttrTypeId(a)));
            continue;
        }
        if (auto img = first.attr_type_image(mid)) {
            out.map_attr_type(AttrTypeId(a), *img);
        } else {
            out.map_attr_type(AttrTypeId(a), first.attr_type_kind(mid));
        }
    }
    for (std::uint32_t h = 0; h < t2.num_homs(); ++h) {
        const std::vector<HomId>& path = *second.hom_image(HomId(h)).path;
        ObId c1 = second.plain_ob(t2.hom(HomId(h)).dom);
        ObId d1 = second.plain_ob(t2.hom(HomId(h)).codom);
        const Query& qc = first.query(c1);
        const Query& qd = first.query(d1);
        if (qc.is_empty()) {
            continue;
        }
        bool all_paths = true;
        std::vector<HomId> src_path;
        for (HomId g : path) {
            const HomImage& im = first.hom_image(g);
            all_paths = all_paths && im.path.has_value();
            if (im.path) {
                src_path.insert(src_path.end(), im.path->begin(), im.path->end());
            }
        }
        if (all_paths && qc.is_plain() && qd.is_plain()) {
            out.map_hom_path(HomId(h), src_path);
            continue;
        }
        std::vector<Term> terms;
        for (std::size_t n = 0; n < qd.nodes().size(); ++n) {
            QueryElement el = qd.locate_node(n);
            if (!el.is_value) {
                Loc loc{el.ob, el.part, {}, std::nullopt};
                for (auto it = path.rbegin(); it != path.rend(); ++it) {
                    loc = step_back(first, *it, loc);
                }
                terms.push_back(loc_term(qc, loc));
            } else {
                auto v = carry_value(first, path, el.type, el.value);
                if (!v) {
                    return fail("a value variable cannot be carried along '" +
                                t1.hom(path[0]).name + "'");
                }
                terms.push_back(qc.witness_value(el.type, *v));
            }
        }
        out.map_hom(HomId(h), std::move(terms));
    }
    for (std::uint32_t a = 0; a < t2.num_attrs(); ++a) {
        const AttrImage& im2 = second.attr_image(AttrId(a));
        ObId c1 = second.plain_ob(t2.attr(AttrId(a)).dom);
        const Query& qc = first.query(c1);
        if (qc.is_empty()) {
            continue;
        }
        if (im2.kind == AttrImage::Kind::Constant) {
            out.map_attr_constant(AttrId(a), im2.constant);
            continue;
        }
        CATPLAN_ASSERT(im2.kind == AttrImage::Kind::Path, "a delta map's attribute is a path");
        const AttrImage& im1 = first.attr_image(im2.attr);
        const std::vector<HomId>& path = im2.homs;
        switch (im1.kind) {
        case AttrImage::Kind::None:
            return fail("attribute '" + t1.attr(im2.attr).name + "' has no image");
        case AttrImage::Kind::Constant:
            out.map_attr_constant(AttrId(a), im1.constant);
            break;
        case AttrImage::Kind::Value: {
            auto v = carry_value(first, path, im1.type, im1.value);
            if (!v) {
                return fail("a value variable cannot be carried along a delta entry");
            }
            out.map_attr(AttrId(a), qc.witness_value(im1.type, *v));
            break;
        }
        case AttrImage::Kind::Path: {
            Loc loc{im1.start_ob, im1.start, im1.homs, std::nullopt};
            for (auto it = path.rbegin(); it != path.rend(); ++it) {
                loc = step_back(first, *it, loc);
            }
            out.map_attr(AttrId(a), loc_term(qc, loc, im1.attr));
            break;
        }
        }
    }
    auto problems = out.finish();
    if (!out.ok()) {
        return fail("the composite map is not valid: " + problems_text(problems));
    }
    return out;
}

bool same_term(const Term& a, const Term& b) {
    return a.var == b.var && a.homs == b.homs && a.attr == b.attr && a.literal == b.literal;
}

// A term over first's target carried to first's source (first is a delta map); a literal when it
// ends in an attribute that first sends to a constant.
Term translate(const SchemaMap& first, const Term& term) {
    if (term.is_literal()) {
        return term;
    }
    Term out = Term::path(term.var);
    for (HomId h : term.homs) {
        const auto& p = *first.hom_image(h).path;
        out.homs.insert(out.homs.end(), p.begin(), p.end());
    }
    if (term.attr) {
        const AttrImage& im = first.attr_image(*term.attr);
        if (im.kind == AttrImage::Kind::Constant) {
            return Term::constant(im.constant);
        }
        out.homs.insert(out.homs.end(), im.homs.begin(), im.homs.end());
        out.attr = im.attr;
    }
    return out;
}

// The query of the composite at an object: q2's variables over first's images, q2's shape's
// structure as equations.
Result<Query> composite_query(const SchemaMap& first, const Query& q2) {
    const schema::Schema& t1 = *first.target();
    Query q(first.source());
    if (q2.is_empty()) {
        q.set_empty();
    }
    for (const QueryNode& n : q2.nodes()) {
        if (!n.is_value) {
            q.add_variable(n.name, first.plain_ob(n.ob), n.range);
        } else if (auto img = first.attr_type_image(n.type)) {
            q.add_value_variable(n.name, *img, n.range);
        } else {
            return fail("value variable '" + n.name + "' is over '" + t1.attr_type(n.type).name +
                        "', which is sent to a value kind alone");
        }
    }
    // A value variable fixed to a literal keeps its literal.
    for (std::size_t n = 0; n < q2.nodes().size(); ++n) {
        QueryElement el = q2.locate_node(n);
        if (el.is_value && el.value.is_concrete()) {
            q.add_equation(Term::path(q2.nodes()[n].name), Term::constant(el.value));
        }
    }
    const ACSet& shape = q2.state();
    for (std::uint32_t h = 0; h < t1.num_homs(); ++h) {
        ObId dom = t1.hom(HomId(h)).dom;
        for (Part p = 0; p < shape.num_parts(dom); ++p) {
            Part v = shape.subpart(HomId(h), p);
            if (v == kNoPart) {
                continue;
            }
            Term lhs = q2.witness(dom, p);
            lhs.homs.push_back(HomId(h));
            q.add_equation(translate(first, lhs),
                           translate(first, q2.witness(t1.hom(HomId(h)).codom, v)));
        }
    }
    for (std::uint32_t a = 0; a < t1.num_attrs(); ++a) {
        ObId dom = t1.attr(AttrId(a)).dom;
        AttrTypeId ty = t1.attr(AttrId(a)).codom;
        for (Part p = 0; p < shape.num_parts(dom); ++p) {
            const Value& v = shape.subpart(AttrId(a), p);
            if (v.is_unset()) {
                continue;
            }
            Term lhs = q2.witness(dom, p);
            lhs.attr = AttrId(a);
            Term l = translate(first, lhs);
            Term r = translate(first, q2.witness_value(ty, v));
            if (l.is_literal() && r.is_literal()) {
                if (!(l.literal == r.literal)) {
                    q.set_empty(); // a constant attribute fails the literal: no tuples
                }
                continue;
            }
            if (l.is_literal()) {
                std::swap(l, r);
            }
            if (same_term(l, r)) {
                continue;
            }
            q.add_equation(l, r);
        }
    }
    return q;
}

// The composite's hom images: a path through first's images, or the terms of q2's morphism.
void composite_homs(const SchemaMap& first, const SchemaMap& second, SchemaMap& out) {
    const schema::Schema& t2 = *second.target();
    for (std::uint32_t h = 0; h < t2.num_homs(); ++h) {
        const HomImage& im = second.hom_image(HomId(h));
        ObId c2 = t2.hom(HomId(h)).dom, d2 = t2.hom(HomId(h)).codom;
        const Query& qc = second.query(c2);
        const Query& qd = second.query(d2);
        if (qc.is_empty()) {
            continue;
        }
        if (im.path) {
            Term w = translate(first, Term::path(qc.nodes()[0].name, *im.path));
            if (qc.is_plain() && qd.is_plain()) {
                out.map_hom_path(HomId(h), std::move(w.homs)); // plain to plain stays a path
            } else {
                out.map_hom(HomId(h), {std::move(w)});
            }
            continue;
        }
        std::vector<Term> terms;
        for (std::size_t n = 0; n < qd.nodes().size(); ++n) {
            QueryElement el = qd.locate_node(n);
            if (!el.is_value) {
                terms.push_back(
                    translate(first, qc.witness(el.ob, (*im.morphism)(el.ob, el.part))));
            } else {
                Value v =
                    el.value.is_var() ? im.morphism->var(el.type, el.value.var_index()) : el.value;
                terms.push_back(translate(first, qc.witness_value(el.type, v)));
            }
        }
        out.map_hom(HomId(h), std::move(terms));
    }
}

// The composite's attribute images, through first's.
void composite_attrs(const SchemaMap& first, const SchemaMap& second, SchemaMap& out) {
    const schema::Schema& t2 = *second.target();
    for (std::uint32_t a = 0; a < t2.num_attrs(); ++a) {
        const AttrImage& im = second.attr_image(AttrId(a));
        const Query& qc = second.query(t2.attr(AttrId(a)).dom);
        if (qc.is_empty()) {
            continue;
        }
        switch (im.kind) {
        case AttrImage::Kind::None:
            break;
        case AttrImage::Kind::Constant:
            out.map_attr_constant(AttrId(a), im.constant);
            break;
        case AttrImage::Kind::Value:
            out.map_attr(AttrId(a), translate(first, qc.witness_value(im.type, im.value)));
            break;
        case AttrImage::Kind::Path: {
            Term w = qc.witness(im.start_ob, im.start);
            w.homs.insert(w.homs.end(), im.homs.begin(), im.homs.end());
            w.attr = im.attr;
            out.map_attr(AttrId(a), translate(first, w));
            break;
        }
        }
    }
}

Result<SchemaMap> first_delta(const SchemaMap& first, const SchemaMap& second) {
    const schema::Schema& t2 = *second.target();
    SchemaMap out(second.target(), first.source());
    for (std::uint32_t a = 0; a < t2.num_attr_types(); ++a) {
        if (auto mid = second.attr_type_image(AttrTypeId(a))) {
            if (auto img = first.attr_type_image(*mid)) {
                out.map_attr_type(AttrTypeId(a), *img);
            } else {
                out.map_attr_type(AttrTypeId(a), first.attr_type_kind(*mid));
            }
        } else {
            out.map_attr_type(AttrTypeId(a), second.attr_type_kind(AttrTypeId(a)));
        }
    }
    for (std::uint32_t c = 0; c < t2.num_obs(); ++c) {
        auto q = composite_query(first, second.query(ObId(c)));
        if (!q) {
            return fail(q.error());
        }
        out.map_ob(ObId(c), std::move(*q));
    }
    composite_homs(first, second, out);
    composite_attrs(first, second, out);
    auto problems = out.finish();
    if (!out.ok()) {
        return fail("the composite map is not valid: " + problems_text(problems));
    }
    return out;
}

} // namespace

Result<SchemaMap> compose(const SchemaMap& first, const SchemaMap& second) {
    CATPLAN_ASSERT(first.ok() && second.ok(), "compose: both maps must be finished without errors");
    CATPLAN_ASSERT(second.source() == first.target(),
                   "compose: second's source schema must be first's target schema");
    if (second.is_delta()) {
        return second_delta(first, second);
    }
    if (first.is_delta()) {
        return first_delta(first, second);
    }
    return fail("composing two conjunctive schema maps is not supported (one of them must be a "
                "delta map)");
}

} // namespace catplan::migrate
