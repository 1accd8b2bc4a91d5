#include "catplan/colimit/colimit.hpp"

#include "catplan/base/union_find.hpp"

#include <fmt/format.h>
#include <optional>

namespace catplan::colimit {

using acset::Value;

namespace {

// Gluing of two states B and C: per object a union-find over B's parts then C's parts, per
// attribute type a union-find over B's variables then C's, with an optional constant per class.
class Gluing {
public:
    Gluing(const ACSet& b, const ACSet& c) : b_(b), c_(c) {
        const auto& s = b.schema();
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            parts_.emplace_back(b.num_parts(ObId(o)) + c.num_parts(ObId(o)));
        }
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            auto n = b.num_vars(AttrTypeId(t)) + c.num_vars(AttrTypeId(t));
            vars_.emplace_back(n);
            bound_.emplace_back(n);
        }
    }

    static std::uint32_t part_b(ObId /*o*/, Part p) { return p; }

    std::uint32_t part_c(ObId o, Part p) const {
        return static_cast<std::uint32_t>(b_.num_parts(o)) + p;
    }

    void glue_parts(ObId o, std::uint32_t x, std::uint32_t y) {
        parts_[o.index()].union_sets(x, y);
    }

    // A value as seen in the glued world: a constant, or a variable class id (B's vars first).
    struct Term {
        bool is_var = false;
        std::uint32_t var = 0;
        Value value;
    };

    static std::optional<Term> term_b(const Value& v) { return term(v, 0); }

    std::optional<Term> term_c(AttrTypeId t, const Value& v) const {
        return term(v, static_cast<std::uint32_t>(b_.num_vars(t)));
    }

    // Unifies two terms of attribute type t; false when two different constants meet.
    bool unify(AttrTypeId t, const Term& x, const Term& y) {
        auto& uf = vars_[t.index()];
        auto& bound = bound_[t.index()];
        if (!x.is_var && !y.is_var) {
            return x.value == y.value;
        }
        if (x.is_var && y.is_var) {
            auto rx = uf.find(x.var), ry = uf.find(y.var);
            if (rx == ry) {
                return true;
            }
            auto bx = bound[rx], by = bound[ry];
            if (bx && by && !(*bx == *by)) {
                return false;
            }
            uf.union_sets(rx, ry);
            bound[uf.find(rx)] = bx ? bx : by;
            return true;
        }
        const Term& v = x.is_var ? x : y;
        const Term& c = x.is_var ? y : x;
        auto r = uf.find(v.var);
        if (bound[r] && !(*bound[r] == c.value)) {
            return false;
        }
        bound[r] = c.value;
        return true;
    }

    UnionFind& parts(ObId o) { return parts_[o.index()]; }

    UnionFind& vars(AttrTypeId t) { return vars_[t.index()]; }

    const std::optional<Value>& binding(AttrTypeId t, std::uint32_t root) const {
        return bound_[t.index()][root];
    }

private:
    static std::optional<Term> term(const Value& v, std::uint32_t offset) {
        if (v.is_unset()) {
            return std::nullopt;
        }
        if (v.is_var()) {
            return Term{true, offset + v.var_index(), Value()};
        }
        return Term{false, 0, v};
    }

    const ACSet& b_;
    const ACSet& c_;
    std::vector<UnionFind> parts_;
    std::vector<UnionFind> vars_;
    std::vector<std::vector<std::optional<Value>>> bound_;
};

// Glues the images of glued parts until nothing changes (a congruence), so homs are well defined.
void close_under_homs(const ACSet& b, const ACSet& c, Gluing& g) {
    const auto& s = b.schema();
    bool changed = true;
    while (changed) {
        changed = false;
        for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
            HomId f(h);
            ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
            auto nb = b.num_parts(dom), nc = c.num_parts(dom);
            // For each class, the first image met; later images are glued to it.
            std::vector<std::uint32_t> image(nb + nc, UINT32_MAX);
            for (std::uint32_t i = 0; i < nb + nc; ++i) {
                Part target = i < nb ? b.subpart(f, i) : c.subpart(f, static_cast<Part>(i - nb));
                if (target == kNoPart) {
                    continue;
                }
                std::uint32_t t = i < nb ? g.part_b(codom, target) : g.part_c(codom, target);
                auto root = g.parts(dom).find(i);
                if (image[root] == UINT32_MAX) {
                    image[root] = t;
                } else if (g.parts(codom).union_sets(image[root], t)) {
                    changed = true;
                }
            }
        }
    }
}

std::string describe_value(const Value& v) {
    return v.to_string();
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
    Gluing glue(b, c);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < a.num_parts(ob); ++p) {
            glue.glue_parts(ob, glue.part_b(ob, f(ob, p)), glue.part_c(ob, g(ob, p)));
        }
    }
    close_under_homs(b, c, glue);
    // Variables of A glue their images in B and C.
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t j = 0; j < a.num_vars(ty); ++j) {
            auto x = Gluing::term_b(f.var(ty, j));
            auto y = glue.term_c(ty, g.var(ty, j));
            if (x && y && !glue.unify(ty, *x, *y)) {
                return fail(fmt::format("no pushout: variable {} of {} is sent to {} and to {}",
                                        a.value_label(ty, Value::var(j)), s.attr_type(ty).name,
                                        describe_value(f.var(ty, j)),
                                        describe_value(g.var(ty, j))));
            }
        }
    }
    // Attribute cells of glued parts must agree; their variables are unified.
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId attr(at);
        ObId ob = s.attr(attr).dom;
        AttrTypeId ty = s.attr(attr).codom;
        auto nb = b.num_parts(ob), nc = c.num_parts(ob);
        std::vector<std::optional<Gluing::Term>> first(nb + nc);
        for (std::uint32_t i = 0; i < nb + nc; ++i) {
            auto term = i < nb ? Gluing::term_b(b.subpart(attr, i))
                               : glue.term_c(ty, c.subpart(attr, static_cast<Part>(i - nb)));
            if (!term) {
                continue;
            }
            auto root = glue.parts(ob).find(i);
            if (!first[root]) {
                first[root] = term;
            } else if (!glue.unify(ty, *first[root], *term)) {
                return fail(fmt::format("no pushout: glued parts of {} get two different values "
                                        "of {}",
                                        s.ob(ob).name, s.attr(attr).name));
            }
        }
    }

    Pushout result{ACSet(a.schema_ptr()), {}, {}};
    ACSet& p = result.apex;
    result.left.components.resize(s.num_obs());
    result.right.components.resize(s.num_obs());
    result.left.var_components.resize(s.num_attr_types());
    result.right.var_components.resize(s.num_attr_types());
    // Parts: one per class, in order of first member (B's parts first, then C's).
    std::vector<std::vector<Part>> class_part(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        auto nb = b.num_parts(ob), nc = c.num_parts(ob);
        class_part[o].assign(nb + nc, kNoPart);
        for (std::uint32_t i = 0; i < nb + nc; ++i) {
            auto root = glue.parts(ob).find(i);
            auto name = i < nb ? b.part_name(ob, i) : c.part_name(ob, static_cast<Part>(i - nb));
            if (class_part[o][root] == kNoPart) {
                class_part[o][root] = p.add_part(ob, name);
            } else if (p.part_name(ob, class_part[o][root]).empty() && !name.empty()) {
                p.set_part_name(ob, class_part[o][root], name);
            }
            Part image = class_part[o][root];
            if (i < nb) {
                result.left.components[o].push_back(image);
            } else {
                result.right.components[o].push_back(image);
            }
        }
    }
    // Variables: one per unbound class, in order of first member; bound classes become constants.
    std::vector<std::vector<Value>> var_image(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        auto nb = b.num_vars(ty), nc = c.num_vars(ty);
        std::vector<std::optional<Value>> class_value(nb + nc);
        for (std::uint32_t i = 0; i < nb + nc; ++i) {
            auto root = glue.vars(ty).find(i);
            auto name =
                i < nb ? b.var_name(ty, i) : c.var_name(ty, static_cast<std::uint32_t>(i - nb));
            if (!class_value[root]) {
                const auto& bound = glue.binding(ty, root);
                class_value[root] = bound ? *bound : p.add_var(ty, name);
            } else if (class_value[root]->is_var() &&
                       p.var_name(ty, class_value[root]->var_index()).empty() && !name.empty()) {
                p.set_var_name(ty, class_value[root]->var_index(), name);
            }
            var_image[t].push_back(*class_value[root]);
            (i < nb ? result.left : result.right).var_components[t].push_back(*class_value[root]);
        }
    }
    // Homs and attributes: from any member that has a value (they agree after the closure).
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f2(h);
        ObId dom = s.hom(f2).dom, codom = s.hom(f2).codom;
        auto nb = b.num_parts(dom), nc = c.num_parts(dom);
        for (std::uint32_t i = 0; i < nb + nc; ++i) {
            Part target = i < nb ? b.subpart(f2, i) : c.subpart(f2, static_cast<Part>(i - nb));
            if (target == kNoPart) {
                continue;
            }
            std::uint32_t ti = i < nb ? glue.part_b(codom, target) : glue.part_c(codom, target);
            Part src = class_part[dom.index()][glue.parts(dom).find(i)];
            p.set_subpart(f2, src, class_part[codom.index()][glue.parts(codom).find(ti)]);
        }
    }
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId attr(at);
        ObId ob = s.attr(attr).dom;
        AttrTypeId ty = s.attr(attr).codom;
        auto nb = b.num_parts(ob), nc = c.num_parts(ob);
        for (std::uint32_t i = 0; i < nb + nc; ++i) {
            Value v = i < nb ? b.subpart(attr, i) : c.subpart(attr, static_cast<Part>(i - nb));
            if (v.is_unset()) {
                continue;
            }
            if (v.is_var()) {
                auto offset = i < nb ? 0 : static_cast<std::uint32_t>(b.num_vars(ty));
                v = var_image[ty.index()][offset + v.var_index()];
            }
            p.set_subpart(attr, class_part[ob.index()][glue.parts(ob).find(i)], v);
        }
    }
    return result;
}

} // namespace catplan::colimit
