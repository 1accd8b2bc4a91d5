// The reference application of a rule (dpo.hpp, rewrite): the double pushout computed by
// colimits, as AlgebraicRewriting computes it (pushout_complement, then pushout), with the update
// semantics of rule.hpp expressed through the span the colimits glue along.

#include "catplan/rewrite/detail/relations.hpp"
#include "catplan/rewrite/detail/shape.hpp"
#include "catplan/rewrite/dpo.hpp"

namespace catplan::rewrite {

namespace {

using detail::Shape;

// The span the colimits glue along. K° is K without attribute cells: a cell of a kept part is
// either one R sets anew (open in the complement, so X's old value does not survive) or one R
// leaves unset (so K leaves it unset too, and Z keeps X's value). K° keeps the variables r sends
// to variables of R, which carry the matched values into R; a variable r sends to a constant is
// an old value the rule overwrites, so it glues nothing. R° is R with its kept parts and kept
// variables unnamed, so that the names of X survive the gluing.
struct GluingSpan {
    ACSet k;
    ACSetMorphism l, r; // K° -> L, K° -> R°
    ACSet r_state;      // R°
    colimit::ComplementOptions options;
};

GluingSpan gluing_span(const Shape& shape) {
    const Rule& rule = shape.rule;
    const auto& s = rule.K.schema();
    GluingSpan out{ACSet(rule.K.schema_ptr()), {}, {}, rule.R, shape.gluing()};
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
            out.k.add_part(ob, rule.K.part_name(ob, k));
            out.r_state.set_part_name(ob, rule.r(ob, k), "");
        }
    }
    out.l.components = rule.l.components;
    out.r.components = rule.r.components;
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        for (Part k = 0; k < rule.K.num_parts(s.hom(HomId(h)).dom); ++k) {
            out.k.set_subpart(HomId(h), k, rule.K.subpart(HomId(h), k));
        }
    }
    out.l.var_components.resize(s.num_attr_types());
    out.r.var_components.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t v = 0; v < rule.K.num_vars(ty); ++v) {
            const Value& rv = rule.r.var(ty, v);
            if (rv.is_var()) {
                out.k.add_var(ty, rule.K.var_name(ty, v));
                out.l.var_components[t].push_back(rule.l.var(ty, v));
                out.r.var_components[t].push_back(rv);
                out.r_state.set_var_name(ty, rv.var_index(), "");
            }
        }
    }
    out.options.open.attrs.resize(s.num_attrs());
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        ObId dom = s.attr(AttrId(at)).dom;
        for (Part k = 0; k < rule.K.num_parts(dom); ++k) {
            if (!rule.R.subpart(AttrId(at), rule.r(dom, k)).is_unset()) {
                out.options.open.attrs[at].push_back(k);
            }
        }
    }
    return out;
}

// Replaces variables of y by constants (Catlab's sub_vars): the pushout of y <- V -> 0, where V
// holds one variable per substitution and the map to the empty state sends it to its constant.
// y's parts and its other variables keep their order.
Result<colimit::Pushout>
substitute(const ACSet& y, const std::vector<std::vector<std::pair<Value, Value>>>& subst) {
    const auto& s = y.schema();
    ACSet v(y.schema_ptr()), none(y.schema_ptr());
    ACSetMorphism to_y, to_none;
    to_y.components.resize(s.num_obs());
    to_none.components.resize(s.num_obs());
    to_y.var_components.resize(s.num_attr_types());
    to_none.var_components.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (const auto& [var, value] : subst[t]) {
            v.add_var(AttrTypeId(t));
            to_y.var_components[t].push_back(var);
            to_none.var_components[t].push_back(value);
        }
    }
    return colimit::pushout(v, y, none, to_y, to_none);
}

// y without the variables that no cell holds, except those `keep` marks; the others keep their
// order. image[t][j] becomes the new value of y's variable j (unset when it is dropped).
ACSet forget_unheld(const ACSet& y, const std::vector<std::vector<char>>& keep,
                    std::vector<std::vector<Value>>& image) {
    const auto& s = y.schema();
    ACSet out(y.schema_ptr());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < y.num_parts(ObId(o)); ++p) {
            out.add_part(ObId(o), y.part_name(ObId(o), p));
        }
    }
    image.assign(s.num_attr_types(), {});
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t j = 0; j < y.num_vars(ty); ++j) {
            bool held = !y.var_incident(ty, j).empty() || keep[t][j];
            image[t].push_back(held ? out.add_var(ty, y.var_name(ty, j)) : Value());
        }
    }
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        for (Part p = 0; p < y.num_parts(s.hom(HomId(h)).dom); ++p) {
            out.set_subpart(HomId(h), p, y.subpart(HomId(h), p));
        }
    }
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId a(at);
        for (Part p = 0; p < y.num_parts(s.attr(a).dom); ++p) {
            const Value& v = y.subpart(a, p);
            out.set_subpart(a, p, v.is_var() ? image[s.attr(a).codom.index()][v.var_index()] : v);
        }
    }
    return out;
}

Value mapped(const std::vector<std::vector<Value>>& image, AttrTypeId t, const Value& v) {
    return v.is_var() ? image[t.index()][v.var_index()] : v;
}

} // namespace

Result<Rewrite> rewrite(const Rule& rule, const ACSet& x, const ACSetMorphism& m) {
    if (auto problem = match_problem(rule, x, m, /*monic=*/false)) {
        return fail(*problem);
    }
    const Shape& shape = rule.shape();
    auto r_var = detail::application_values(shape, m);
    if (!r_var) {
        return fail(r_var.error());
    }
    // Z = X - m(L - l(K)), then Y = R +_K Z.
    GluingSpan span = gluing_span(shape);
    auto pc = colimit::pushout_complement(span.k, rule.L, x, span.l, m, span.options);
    if (!pc) {
        return fail(pc.error());
    }
    auto po = colimit::pushout(span.k, span.r_state, pc->z, span.r, pc->k_to_z);
    if (!po) {
        return fail(po.error());
    }
    // R's variables that an expression computes are still unknowns of Y: substitute them.
    const auto& s = x.schema();
    std::vector<std::vector<std::pair<Value, Value>>> subst(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < rule.R.num_vars(AttrTypeId(t)); ++j) {
            const Value& y_var = po->left.var(AttrTypeId(t), j);
            if ((*r_var)[t][j].is_concrete() && y_var.is_var()) {
                subst[t].emplace_back(y_var, (*r_var)[t][j]);
            }
        }
    }
    auto sub = substitute(po->apex, subst);
    if (!sub) {
        return fail(sub.error());
    }
    // Y forgets the unknowns the rewrite left without a cell (as rewrite_in_place does); an
    // unknown no cell of X held stays. Z's variables are X's, in order.
    std::vector<std::vector<char>> keep(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        keep[t].assign(sub->apex.num_vars(ty), 0);
        for (std::uint32_t j = 0; j < x.num_vars(ty); ++j) {
            Value v = mapped(sub->left.var_components, ty, po->right.var(ty, j));
            if (x.var_incident(ty, j).empty() && v.is_var()) {
                keep[t][v.var_index()] = 1;
            }
        }
    }
    std::vector<std::vector<Value>> image;
    Rewrite out{forget_unheld(sub->apex, keep, image), hom::compose(po->left, sub->left)};
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (Value& v : out.r_to_result.var_components[t]) {
            v = mapped(image, AttrTypeId(t), v);
        }
    }
    // In the subcategory of states that hold each fact once, the rewrite is followed by the
    // reflection, which merges created facts into equal ones (detail/relations.hpp).
    if (!rule.relations.empty()) {
        detail::merge_created_facts(rule, out.result, out.r_to_result);
    }
    return out;
}

} // namespace catplan::rewrite
