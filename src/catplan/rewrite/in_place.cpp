// The fast application of a rule (dpo.hpp, rewrite_in_place): X is edited where the rule touches
// it, so a step costs the parts it deletes, creates and updates (and their incident parts).

#include "catplan/base/assert.hpp"
#include "catplan/rewrite/detail/relations.hpp"
#include "catplan/rewrite/detail/shape.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <algorithm>
#include <functional>

namespace catplan::rewrite {

namespace {

using detail::Shape;

// One application at a checked match; r is monic and R's variables are resolved.
class InPlace {
public:
    InPlace(const Shape& shape, ACSet& x, const ACSetMorphism& m,
            const std::vector<std::vector<Value>>& r_var)
        : rule_(shape.rule),
          s_(x.schema()),
          x_(x),
          r_var_(r_var),
          orphan_candidates_(s_.num_attr_types()),
          fresh_(s_.num_attr_types()) {
        // R's kept parts point at their X parts; these ids follow the pop-and-swaps of delete().
        auto& r_to_x = out_.components;
        r_to_x.resize(s_.num_obs());
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            r_to_x[o].assign(rule_.R.num_parts(ob), kNoPart);
            for (Part rp = 0; rp < rule_.R.num_parts(ob); ++rp) {
                Part k = shape.k_of_r[o][rp];
                if (k != kNoPart) {
                    r_to_x[o][rp] = m(ob, rule_.l(ob, k));
                }
            }
        }
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            fresh_[t].assign(rule_.R.num_vars(AttrTypeId(t)), Value());
        }
    }

    // Deletes the given X parts, largest id first, so the part a pop-and-swap moves into a freed
    // slot is never one still to delete.
    void remove(const std::vector<std::vector<Part>>& deleted) {
        auto& r_to_x = out_.components;
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            for (auto it = deleted[o].rbegin(); it != deleted[o].rend(); ++it) {
                Part y = *it;
                for (AttrId a : s_.attrs_from(ob)) {
                    note_var(a, y);
                }
                Part moved = x_.remove_part(ob, y);
                if (moved != kNoPart) {
                    std::replace(r_to_x[o].begin(), r_to_x[o].end(), moved, y);
                }
            }
        }
    }

    // Creates R's new parts in R's order.
    void create() {
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            auto names = rule_.R.part_names(ob);
            for (Part rp : rule_.created_parts(ob)) {
                out_.components[o][rp] = x_.add_part(ob, rp < names.size() ? names[rp] : Symbol());
            }
        }
    }

    // Homs of R's parts: R's value wins; unset in R keeps x's value (a kept part's unchanged hom).
    void set_homs() {
        const auto& r_to_x = out_.components;
        for (std::uint32_t h = 0; h < s_.num_homs(); ++h) {
            HomId f(h);
            ObId dom = s_.hom(f).dom, codom = s_.hom(f).codom;
            for (Part rp = 0; rp < rule_.R.num_parts(dom); ++rp) {
                Part t = rule_.R.subpart(f, rp);
                if (t != kNoPart) {
                    x_.set_subpart(f, r_to_x[dom.index()][rp], r_to_x[codom.index()][t]);
                }
            }
        }
    }

    // Attributes of R's parts: R's constant, the value the match gives R's variable, or a fresh
    // unknown for a variable bound by nothing. Unset in R: a kept part's value is unchanged, a
    // created part's stays unset.
    void set_attrs() {
        for (std::uint32_t at = 0; at < s_.num_attrs(); ++at) {
            AttrId a(at);
            ObId dom = s_.attr(a).dom;
            for (Part rp = 0; rp < rule_.R.num_parts(dom); ++rp) {
                Value rv = rule_.R.subpart(a, rp);
                if (rv.is_unset()) {
                    continue;
                }
                Value v = rv.is_var() ? var_value(s_.attr(a).codom, rv.var_index()) : rv;
                Part target = out_.components[dom.index()][rp];
                if (!(x_.subpart(a, target) == v)) {
                    note_var(a, target);
                    x_.set_subpart(a, target, v);
                }
            }
        }
    }

    // R's variables in the result (for the returned morphism), after dropping the variables the
    // step left without a cell, highest index first so that a pop-and-swap never moves a
    // candidate still to be examined.
    ACSetMorphism finish() && {
        auto& r_vars = out_.var_components;
        r_vars.resize(s_.num_attr_types());
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            for (std::uint32_t j = 0; j < rule_.R.num_vars(AttrTypeId(t)); ++j) {
                Value v = r_var_[t][j];
                r_vars[t].push_back(v.is_unset() ? fresh_[t][j] : v);
            }
            auto& cands = orphan_candidates_[t];
            std::sort(cands.begin(), cands.end(), std::greater<>());
            cands.erase(std::unique(cands.begin(), cands.end()), cands.end());
            for (std::uint32_t j : cands) {
                if (!x_.var_incident(AttrTypeId(t), j).empty()) {
                    continue;
                }
                std::uint32_t moved = x_.remove_var(AttrTypeId(t), j);
                for (Value& v : r_vars[t]) {
                    if (v == Value::var(j)) {
                        v = Value(); // the variable is gone (an R variable used by no cell)
                    } else if (moved != UINT32_MAX && v == Value::var(moved)) {
                        v = Value::var(j);
                    }
                }
            }
        }
        return std::move(out_);
    }

private:
    // Variables that may lose their last cell: those held by deleted or overwritten cells.
    void note_var(AttrId a, Part p) {
        const Value& v = x_.subpart(a, p);
        if (v.is_var()) {
            orphan_candidates_[s_.attr(a).codom.index()].push_back(v.var_index());
        }
    }

    Value var_value(AttrTypeId ty, std::uint32_t j) {
        const Value& v = r_var_[ty.index()][j];
        if (!v.is_unset()) {
            return v;
        }
        Value& f = fresh_[ty.index()][j];
        if (f.is_unset()) {
            f = x_.add_var(ty, rule_.R.var_name(ty, j));
        }
        return f;
    }

    const Rule& rule_;
    const schema::Schema& s_;
    ACSet& x_;
    const std::vector<std::vector<Value>>& r_var_;
    std::vector<std::vector<std::uint32_t>> orphan_candidates_;
    std::vector<std::vector<Value>> fresh_;
    ACSetMorphism out_;
};

// The X parts a DPO step at a found match deletes (colimit::deleted_images), after asserting
// what an out-of-range match would otherwise read past.
std::vector<std::vector<Part>> deleted_images(const Shape& shape, const ACSet& x,
                                              const ACSetMorphism& m) {
    const auto& rule = shape.rule;
    const auto& s = x.schema();
    CATPLAN_ASSERT(m.components.size() == s.num_obs(), "a found match has a component per object");
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        const auto& component = m.components[o];
        CATPLAN_ASSERT(component.size() == rule.L.num_parts(ObId(o)),
                       "a found match has a part for each part of L");
        for (Part q : component) {
            CATPLAN_ASSERT(q < x.num_parts(ObId(o)), "a found match lands in the state's parts");
        }
    }
    return colimit::deleted_images(m, shape.gluing().outside_l);
}

} // namespace

Result<ACSetMorphism> rewrite_in_place(const Rule& rule, ACSet& x, const ACSetMorphism& m,
                                       CheckMatch check) {
    const Shape& shape = rule.shape();
    std::vector<std::vector<Part>> deleted;
    // An SPO rule's deletion cascades through x: colimit::deletion computes it, checks and all.
    if (check == CheckMatch::No && !shape.gluing().cascade) {
        deleted = deleted_images(shape, x, m);
    } else {
        auto failures = hom::naturality_failures(m, rule.L, x);
        if (!failures.empty()) {
            return fail("the match is not a morphism: " +
                        hom::describe(failures.front(), rule.L, x));
        }
        // The gluing conditions and the parts to delete come from one pass (colimit::deletion).
        auto deletion = colimit::deletion(rule.K, rule.L, x, rule.l, m, shape.gluing());
        if (!deletion.violations.empty()) {
            return fail(deletion.violations.front().reason);
        }
        if (auto problem = detail::condition_problem(rule, x, m)) {
            return fail(*problem);
        }
        deleted = std::move(deletion.parts);
    }
    // Resolve R's variables before touching x, so a failing expression leaves x unchanged.
    auto r_var = detail::application_values(shape, m);
    if (!r_var) {
        return fail(r_var.error());
    }
    InPlace step(shape, x, m, *r_var);
    step.remove(deleted);
    step.create();
    step.set_homs();
    step.set_attrs();
    ACSetMorphism r_to_x = std::move(step).finish();
    if (!rule.relations.empty()) {
        detail::merge_created_facts(rule, x, r_to_x);
    }
    return r_to_x;
}

} // namespace catplan::rewrite
