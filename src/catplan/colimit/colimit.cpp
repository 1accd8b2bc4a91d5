// Pushouts and coproducts (colimit.hpp), presented by generators and equations: a generator for
// each part and variable of B and C, their homs and cells, and an equation for each part and
// variable of A (colimit::Presentation closes them under congruence).

#include "catplan/colimit/colimit.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/colimit/presentation.hpp"

#include <fmt/format.h>
#include <optional>

namespace catplan::colimit {

using acset::Value;

namespace {

// The generators of the two feet: per foot (B, C), per object the node of each part, per
// attribute type the node of each variable.
struct Feet {
    std::vector<std::vector<Node>> parts[2];
    std::vector<std::vector<Node>> vars[2];
};

Feet generators(Presentation& p, const ACSet* feet[2]) {
    const auto& s = p.schema();
    Feet out;
    for (int i = 0; i < 2; ++i) {
        out.parts[i].resize(s.num_obs());
        out.vars[i].resize(s.num_attr_types());
    }
    // B's parts, then C's; B's variables, then C's: the numbering of the result.
    for (int i = 0; i < 2; ++i) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Part q = 0; q < feet[i]->num_parts(ObId(o)); ++q) {
                out.parts[i][o].push_back(p.add_part(ObId(o), feet[i]->part_name(ObId(o), q)));
            }
        }
    }
    for (int i = 0; i < 2; ++i) {
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            for (std::uint32_t j = 0; j < feet[i]->num_vars(AttrTypeId(t)); ++j) {
                out.vars[i][t].push_back(
                    p.add_value(AttrTypeId(t), feet[i]->var_name(AttrTypeId(t), j)));
            }
        }
    }
    return out;
}

// The node of a foot's value (a variable's node, or a new node holding the constant).
Node value_node(Presentation& p, const Feet& feet, int foot, AttrTypeId t, const Value& v) {
    if (v.is_var()) {
        return feet.vars[foot][t.index()][v.var_index()];
    }
    Node n = p.add_value(t);
    p.set_literal(n, v);
    return n;
}

// The homs and cells of both feet.
void relations(Presentation& p, const Feet& feet, const ACSet* xs[2]) {
    const auto& s = p.schema();
    for (int i = 0; i < 2; ++i) {
        for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
            HomId f(h);
            ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
            for (Part q = 0; q < xs[i]->num_parts(dom); ++q) {
                Part t = xs[i]->subpart(f, q);
                if (t != kNoPart) {
                    p.set_hom(feet.parts[i][dom.index()][q], f, feet.parts[i][codom.index()][t]);
                }
            }
        }
        for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
            AttrId a(at);
            ObId dom = s.attr(a).dom;
            for (Part q = 0; q < xs[i]->num_parts(dom); ++q) {
                const Value& v = xs[i]->subpart(a, q);
                if (!v.is_unset()) {
                    p.set_attr(feet.parts[i][dom.index()][q], a,
                               value_node(p, feet, i, s.attr(a).codom, v));
                }
            }
        }
    }
}

} // namespace

std::vector<std::vector<Part>> parts_outside_image(const ACSetMorphism& f, const ACSet& codom) {
    const auto& s = codom.schema();
    std::vector<std::vector<Part>> out(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        std::vector<char> hit(codom.num_parts(ObId(o)), 0);
        if (o < f.components.size()) {
            for (Part p : f.components[o]) {
                hit[p] = 1;
            }
        }
        for (Part p = 0; p < hit.size(); ++p) {
            if (!hit[p]) {
                out[o].push_back(p);
            }
        }
    }
    return out;
}

Coproduct coproduct(const ACSet& b, const ACSet& c) {
    ACSet a(b.schema_ptr());
    ACSetMorphism f = hom::identity(a), g = hom::identity(a);
    auto p = pushout(a, b, c, f, g);
    CATPLAN_ASSERT(p.has_value(), "a coproduct always exists");
    return {std::move(p->apex), std::move(p->left), std::move(p->right)};
}

Result<Pushout> pushout(const ACSet& a, const ACSet& b, const ACSet& c, const ACSetMorphism& f,
                        const ACSetMorphism& g) {
    const auto& s = a.schema();
    Presentation p(a.schema_ptr());
    const ACSet* xs[2] = {&b, &c};
    Feet feet = generators(p, xs);
    // Variables of A glue their images first, so that a clash is named by the variable.
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t j = 0; j < a.num_vars(ty); ++j) {
            const Value &x = f.var(ty, j), &y = g.var(ty, j);
            if (x.is_unset() || y.is_unset()) {
                continue;
            }
            bool clash = x.is_concrete() && y.is_concrete() && !(x == y);
            if (!clash && (x.is_var() || y.is_var())) {
                p.equate_values(value_node(p, feet, 0, ty, x), value_node(p, feet, 1, ty, y));
                clash = !p.problems().empty();
            }
            if (clash) {
                return fail(fmt::format("no pushout: variable {} of {} is sent to {} and to {}",
                                        a.value_label(ty, Value::var(j)), s.attr_type(ty).name,
                                        x.to_string(), y.to_string()));
            }
        }
    }
    relations(p, feet, xs);
    // Parts of A glue their images; the closure glues what they reach, and their cells.
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part q = 0; q < a.num_parts(ObId(o)); ++q) {
            p.equate_parts(feet.parts[0][o][f(ObId(o), q)], feet.parts[1][o][g(ObId(o), q)]);
        }
    }
    if (!p.problems().empty()) {
        AttrId attr = p.problems().front().attr;
        CATPLAN_ASSERT(attr != AttrId(), "a pushout's values meet only in glued cells");
        return fail(fmt::format("no pushout: glued parts of {} get two different values of {}",
                                s.ob(s.attr(attr).dom).name, s.attr(attr).name));
    }
    auto built = p.build();
    Pushout result{std::move(built.state), {}, {}};
    ACSetMorphism* legs[2] = {&result.left, &result.right};
    for (int i = 0; i < 2; ++i) {
        legs[i]->components.resize(s.num_obs());
        legs[i]->var_components.resize(s.num_attr_types());
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Node n : feet.parts[i][o]) {
                legs[i]->components[o].push_back(built.part_of[n]);
            }
        }
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            for (Node n : feet.vars[i][t]) {
                legs[i]->var_components[t].push_back(built.value_of[n]);
            }
        }
    }
    return result;
}

} // namespace catplan::colimit
