#include "catplan/rewrite/dpo.hpp"

#include "catplan/hom/hom_search.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <unordered_map>

namespace catplan::rewrite {

namespace {

// TODO(#3): merge the kept parts that r sends to one R part (a true pushout).
constexpr const char* kGluingKeptParts =
    "rules whose Eff glues two kept parts into one are not supported";

// Facts about a rule that matching and application need, computed once per call (rules are
// small, so this is cheap next to the search).
struct Shape {
    explicit Shape(const Rule& rule);

    const Rule& rule;
    std::vector<std::vector<char>> deletes; // per ob, per L part: whether the rule deletes it
    std::vector<std::vector<Part>> k_of_r;  // per ob, per R part: the first K part sent to it
    std::vector<std::uint32_t> unset_in_l;  // per hom: L parts whose value is unset
    std::vector<std::vector<std::uint32_t>> l_incident; // per hom, per L part: |L.incident(h, p)|
    bool r_monic = true;
    /// Whether, for a monic match, the pruning in find_matches already implies the dangling
    /// condition: no hom of L is unset on any part (the pruning allows those), so the only X parts
    /// referring to a deleted part are images of L parts, which a well-formed l deletes too or
    /// keeps with a hom that L and K agree on.
    bool dangling_by_counts = true;

    bool deleted(ObId o, Part p) const { return deletes[o.index()][p] != 0; }

    /// Whether kept K part k has hom h redirected by the rule (unset in K, set in R).
    bool redirects(HomId h, Part k) const {
        return rule.K.subpart(h, k) == kNoPart &&
               rule.R.subpart(h, rule.r(rule.K.schema().hom(h).dom, k)) != kNoPart;
    }
};

Shape::Shape(const Rule& r) : rule(r) {
    const auto& s = r.L.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        deletes.emplace_back(r.L.num_parts(ob), 0);
        for (Part p : r.deleted_parts(ob)) {
            deletes[o][p] = 1;
        }
        k_of_r.emplace_back(r.R.num_parts(ob), kNoPart);
        for (Part k = 0; k < r.K.num_parts(ob); ++k) {
            Part rp = r.r(ob, k);
            if (k_of_r[o][rp] != kNoPart) {
                r_monic = false;
            } else {
                k_of_r[o][rp] = k;
            }
        }
    }
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f(h);
        ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
        std::uint32_t unset = 0;
        std::vector<std::uint32_t> counts(r.L.num_parts(codom), 0);
        for (Part p = 0; p < r.L.num_parts(dom); ++p) {
            Part t = r.L.subpart(f, p);
            if (t == kNoPart) {
                ++unset;
            } else {
                ++counts[t];
            }
        }
        unset_in_l.push_back(unset);
        if (unset > 0) {
            dangling_by_counts = false;
        }
        for (Part k = 0; k < r.K.num_parts(dom); ++k) {
            if (r.K.subpart(f, k) == kNoPart && r.L.subpart(f, r.l(dom, k)) != kNoPart) {
                dangling_by_counts = false; // a kept part's hom K leaves unset: check it fully
            }
        }
        l_incident.push_back(std::move(counts));
    }
}

// The X parts a match deletes, per object, sorted; small, so lookups are binary searches.
std::vector<std::vector<Part>> deleted_parts(const Shape& shape, const ACSetMorphism& m) {
    const auto& s = shape.rule.L.schema();
    std::vector<std::vector<Part>> out(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p : shape.rule.deleted_parts(ObId(o))) {
            out[o].push_back(m(ObId(o), p));
        }
        std::sort(out[o].begin(), out[o].end());
        out[o].erase(std::unique(out[o].begin(), out[o].end()), out[o].end());
    }
    return out;
}

bool contains(const std::vector<Part>& sorted, Part p) {
    return std::binary_search(sorted.begin(), sorted.end(), p);
}

// SPO: the parts a match deletes, closed under "refers to a deleted part" (reference §4.5);
// fails with a reason when the closure reaches the image of a kept part whose reference the rule
// does not redirect. Costs O(size of X) for the marks, which SPO rules alone pay.
Result<std::vector<std::vector<Part>>> cascade(const Shape& shape, const ACSet& x,
                                               const ACSetMorphism& m) {
    const auto& rule = shape.rule;
    const auto& s = x.schema();
    auto deleted = deleted_parts(shape, m);
    std::vector<std::vector<char>> mark(s.num_obs());
    std::vector<std::vector<Part>> kept_at(s.num_obs()); // per ob, per X part: K part or kNoPart
    std::vector<std::pair<ObId, Part>> work;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        mark[o].assign(x.num_parts(ob), 0);
        kept_at[o].assign(x.num_parts(ob), kNoPart);
        for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
            kept_at[o][m(ob, rule.l(ob, k))] = k;
        }
        for (Part y : deleted[o]) {
            mark[o][y] = 1;
            work.emplace_back(ob, y);
        }
    }
    while (!work.empty()) {
        auto [ob, y] = work.back();
        work.pop_back();
        for (HomId f : s.homs_into(ob)) {
            ObId dom = s.hom(f).dom;
            for (Part q : x.incident(f, y)) {
                if (mark[dom.index()][q]) {
                    continue;
                }
                Part k = kept_at[dom.index()][q];
                if (k != kNoPart) {
                    if (shape.redirects(f, k)) {
                        continue;
                    }
                    return fail(fmt::format("SPO: deleting {} {} would delete {} {}, which the "
                                            "rule keeps",
                                            s.ob(ob).name, x.part_label(ob, y), s.ob(dom).name,
                                            x.part_label(dom, q)));
                }
                mark[dom.index()][q] = 1;
                deleted[dom.index()].push_back(q);
                work.emplace_back(dom, q);
            }
        }
    }
    for (auto& d : deleted) {
        std::sort(d.begin(), d.end());
    }
    return deleted;
}

// The parts applying the rule at m deletes, per object, sorted (the cascade under SPO).
Result<std::vector<std::vector<Part>>> parts_to_delete(const Shape& shape, const ACSet& x,
                                                       const ACSetMorphism& m) {
    if (shape.rule.semantics == Semantics::SPO) {
        return cascade(shape, x, m);
    }
    return deleted_parts(shape, m);
}

std::optional<std::string> identification_problem(const Shape& shape, const ACSet& x,
                                                  const ACSetMorphism& m) {
    const auto& rule = shape.rule;
    const auto& s = rule.L.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        std::unordered_map<Part, Part> first;
        for (Part p = 0; p < rule.L.num_parts(ob); ++p) {
            auto [it, fresh] = first.emplace(m(ob, p), p);
            if (!fresh && (shape.deleted(ob, p) || shape.deleted(ob, it->second))) {
                return fmt::format("identification: the match sends {} and {} of {} to the same "
                                   "part {}, and the rule deletes one of them",
                                   rule.L.part_label(ob, it->second), rule.L.part_label(ob, p),
                                   s.ob(ob).name, x.part_label(ob, m(ob, p)));
            }
        }
    }
    return std::nullopt;
}

std::optional<std::string> dangling_problem(const Shape& shape, const ACSet& x,
                                            const ACSetMorphism& m) {
    const auto& rule = shape.rule;
    const auto& s = rule.L.schema();
    auto deleted = deleted_parts(shape, m);
    // The kept L part matched to each X part that the rule keeps (for the redirect exemption).
    std::vector<std::unordered_map<Part, Part>> kept_at(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part k = 0; k < rule.K.num_parts(ObId(o)); ++k) {
            kept_at[o].emplace(m(ObId(o), rule.l(ObId(o), k)), k);
        }
    }
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f(h);
        ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
        for (Part y : deleted[codom.index()]) {
            for (Part q : x.incident(f, y)) {
                if (contains(deleted[dom.index()], q)) {
                    continue;
                }
                auto it = kept_at[dom.index()].find(q);
                if (it != kept_at[dom.index()].end() && shape.redirects(f, it->second)) {
                    continue;
                }
                return fmt::format("dangling: {} {} refers through {} to {} {}, which the rule "
                                   "deletes",
                                   s.ob(dom).name, x.part_label(dom, q), s.hom(f).name,
                                   s.ob(codom).name, x.part_label(codom, y));
            }
        }
    }
    return std::nullopt;
}

std::optional<std::string> condition_problem(const Rule& rule, const ACSet& x,
                                             const ACSetMorphism& m) {
    const auto& s = rule.L.schema();
    for (const auto& c : rule.conditions) {
        hom::HomSearchOptions opt;
        opt.monic_all = true;
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Part p = 0; p < rule.L.num_parts(ObId(o)); ++p) {
                opt.bind(ObId(o), c.n(ObId(o), p), m(ObId(o), p));
            }
        }
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            AttrTypeId ty(t);
            for (std::uint32_t v = 0; v < rule.L.num_vars(ty); ++v) {
                const Value& nv = c.n.var(ty, v);
                if (nv.is_var()) {
                    opt.bind_var(ty, nv.var_index(), m.var(ty, v));
                }
            }
        }
        bool extends = hom::is_homomorphic(c.n_state, x, opt);
        std::string label = c.name.empty() ? "an application condition" : "'" + c.name + "'";
        if (c.negative && extends) {
            return fmt::format("the negative condition {} holds", label);
        }
        if (!c.negative && !extends) {
            return fmt::format("the positive condition {} fails", label);
        }
    }
    return std::nullopt;
}

// Everything but naturality and monicity: gluing conditions, then application conditions.
std::optional<std::string> validity_problem(const Shape& shape, const ACSet& x,
                                            const ACSetMorphism& m) {
    if (auto p = identification_problem(shape, x, m)) {
        return p;
    }
    if (shape.rule.semantics == Semantics::SPO) {
        if (auto d = cascade(shape, x, m); !d) {
            return d.error();
        }
    } else if (auto p = dangling_problem(shape, x, m)) {
        return p;
    }
    return condition_problem(shape.rule, x, m);
}

bool is_injective(const ACSetMorphism& m, const ACSet& x) {
    const auto& s = x.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        std::vector<Part> images = m.components[o];
        std::sort(images.begin(), images.end());
        if (std::adjacent_find(images.begin(), images.end()) != images.end()) {
            return false;
        }
    }
    return true;
}

// The value an attribute cell of R gives the result: R's constant, the matched value flowing
// through K, or an expression of matched values; nullopt for "a fresh unknown".
class RValues {
public:
    RValues(const Rule& rule, const ACSetMorphism& m) : rule_(rule), m_(m) {
        const auto& s = rule.R.schema();
        through_k_.resize(s.num_attr_types());
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            AttrTypeId ty(t);
            through_k_[t].assign(rule.R.num_vars(ty), Value());
            for (std::uint32_t k = 0; k < rule.K.num_vars(ty); ++k) {
                const Value& rv = rule.r.var(ty, k);
                if (rv.is_var()) {
                    through_k_[t][rv.var_index()] = matched(ty, rule.l.var(ty, k));
                }
            }
        }
    }

    // The X value the match gives an L value.
    Value matched(AttrTypeId ty, const Value& l_value) const {
        return l_value.is_var() ? m_.var(ty, l_value.var_index()) : l_value;
    }

    // The value of R variable j, or unset for "a fresh unknown"; fails if an expression fails.
    Result<Value> var_value(AttrTypeId ty, std::uint32_t j) const {
        const Value& v = through_k_[ty.index()][j];
        if (!v.is_unset()) {
            return v;
        }
        const auto& exprs = rule_.exprs;
        if (ty.index() < exprs.size() && j < exprs[ty.index()].size() &&
            exprs[ty.index()][j].has_value()) {
            return evaluate(*exprs[ty.index()][j],
                            [&](AttrTypeId t, std::uint32_t var) { return m_.var(t, var); });
        }
        return Value();
    }

private:
    const Rule& rule_;
    const ACSetMorphism& m_;
    std::vector<std::vector<Value>> through_k_;
};

struct InPlaceOutcome {
    ACSetMorphism r_to_x;
    std::vector<std::vector<Part>> origin; // per ob, per result part: its X id, or kNoPart if new
};

// The in-place application proper; the match has been checked and r is monic.
Result<InPlaceOutcome> apply_in_place(const Shape& shape, ACSet& x, const ACSetMorphism& m,
                                      bool track_origin) {
    const Rule& rule = shape.rule;
    const auto& s = x.schema();
    RValues values(rule, m);
    // Resolve R's variables before touching x, so a failing expression leaves x unchanged.
    std::vector<std::vector<Value>> r_var(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < rule.R.num_vars(AttrTypeId(t)); ++j) {
            auto v = values.var_value(AttrTypeId(t), j);
            if (!v) {
                return fail(fmt::format("cannot compute the value of {} in Eff: {}",
                                        rule.R.value_label(AttrTypeId(t), Value::var(j)),
                                        v.error()));
            }
            r_var[t].push_back(*v);
        }
    }
    InPlaceOutcome out;
    if (track_origin) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            std::vector<Part> ids(x.num_parts(ObId(o)));
            for (Part p = 0; p < ids.size(); ++p) {
                ids[p] = p;
            }
            out.origin.push_back(std::move(ids));
        }
    }
    // R's kept parts point at their X parts; these ids follow the pop-and-swaps below.
    auto& r_to_x = out.r_to_x.components;
    r_to_x.resize(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        r_to_x[o].assign(rule.R.num_parts(ob), kNoPart);
        for (Part rp = 0; rp < rule.R.num_parts(ob); ++rp) {
            Part k = shape.k_of_r[o][rp];
            if (k != kNoPart) {
                r_to_x[o][rp] = m(ob, rule.l(ob, k));
            }
        }
    }
    // Variables that may lose their last cell: those held by deleted or overwritten cells.
    std::vector<std::vector<std::uint32_t>> orphan_candidates(s.num_attr_types());
    auto note_var = [&](AttrId a, Part p) {
        const Value& v = x.subpart(a, p);
        if (v.is_var()) {
            orphan_candidates[s.attr(a).codom.index()].push_back(v.var_index());
        }
    };
    // Delete, largest id first, so the part moved into a freed slot is never one to delete.
    auto to_delete = parts_to_delete(shape, x, m);
    if (!to_delete) {
        return fail(to_delete.error());
    }
    auto& deleted = *to_delete;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (auto it = deleted[o].rbegin(); it != deleted[o].rend(); ++it) {
            Part y = *it;
            for (AttrId a : s.attrs_from(ob)) {
                note_var(a, y);
            }
            Part moved = x.remove_part(ob, y);
            if (track_origin) {
                out.origin[o][y] = out.origin[o].back();
                out.origin[o].pop_back();
            }
            if (moved != kNoPart) {
                std::replace(r_to_x[o].begin(), r_to_x[o].end(), moved, y);
            }
        }
    }
    // Create R's new parts in R's order.
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part rp : rule.created_parts(ob)) {
            r_to_x[o][rp] = x.add_part(ob, rule.R.part_name(ob, rp));
            if (track_origin) {
                out.origin[o].push_back(kNoPart);
            }
        }
    }
    // Homs of R's parts: R's value wins; unset in R keeps x's value (a kept part's unchanged hom).
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f(h);
        ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
        for (Part rp = 0; rp < rule.R.num_parts(dom); ++rp) {
            Part t = rule.R.subpart(f, rp);
            if (t != kNoPart) {
                x.set_subpart(f, r_to_x[dom.index()][rp], r_to_x[codom.index()][t]);
            }
        }
    }
    // Attributes of R's parts; a fresh unknown for each R variable bound by nothing.
    std::vector<std::vector<Value>> fresh(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        fresh[t].assign(rule.R.num_vars(AttrTypeId(t)), Value());
    }
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId a(at);
        ObId dom = s.attr(a).dom;
        AttrTypeId ty = s.attr(a).codom;
        for (Part rp = 0; rp < rule.R.num_parts(dom); ++rp) {
            Value rv = rule.R.subpart(a, rp);
            Part target = r_to_x[dom.index()][rp];
            Value v;
            if (rv.is_concrete()) {
                v = rv;
            } else if (rv.is_var()) {
                v = r_var[ty.index()][rv.var_index()];
                if (v.is_unset()) {
                    auto& f = fresh[ty.index()][rv.var_index()];
                    if (f.is_unset()) {
                        f = x.add_var(ty, rule.R.var_name(ty, rv.var_index()));
                    }
                    v = f;
                }
            } else {
                continue; // unset in R: a kept part's value is unchanged, a created part's unset
            }
            if (!(x.subpart(a, target) == v)) {
                note_var(a, target);
                x.set_subpart(a, target, v);
            }
        }
    }
    // R's variables in the result (for the returned morphism), then drop orphaned variables,
    // highest index first so a pop-and-swap never moves a candidate still to be examined.
    auto& r_vars = out.r_to_x.var_components;
    r_vars.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < rule.R.num_vars(AttrTypeId(t)); ++j) {
            Value v = r_var[t][j];
            r_vars[t].push_back(v.is_unset() ? fresh[t][j] : v);
        }
        auto& cands = orphan_candidates[t];
        std::sort(cands.begin(), cands.end(), std::greater<>());
        cands.erase(std::unique(cands.begin(), cands.end()), cands.end());
        for (std::uint32_t j : cands) {
            if (!x.var_incident(AttrTypeId(t), j).empty()) {
                continue;
            }
            std::uint32_t moved = x.remove_var(AttrTypeId(t), j);
            for (Value& v : r_vars[t]) {
                if (v == Value::var(j)) {
                    v = Value(); // the variable is gone (an R variable used by no cell)
                } else if (moved != UINT32_MAX && v == Value::var(moved)) {
                    v = Value::var(j);
                }
            }
        }
    }
    return out;
}

// Copies x with its parts reordered: order[o] lists the old ids in their new order.
ACSet permuted(const ACSet& x, const std::vector<std::vector<Part>>& order) {
    const auto& s = x.schema();
    ACSet y(x.schema_ptr());
    std::vector<std::vector<Part>> new_id(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        new_id[o].assign(x.num_parts(ObId(o)), kNoPart);
        for (Part old : order[o]) {
            new_id[o][old] = y.add_part(ObId(o), x.part_name(ObId(o), old));
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < x.num_vars(AttrTypeId(t)); ++j) {
            y.add_var(AttrTypeId(t), x.var_name(AttrTypeId(t), j));
        }
    }
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f(h);
        ObId dom = s.hom(f).dom, codom = s.hom(f).codom;
        for (Part p = 0; p < x.num_parts(dom); ++p) {
            Part t = x.subpart(f, p);
            y.set_subpart(f, new_id[dom.index()][p],
                          t == kNoPart ? kNoPart : new_id[codom.index()][t]);
        }
    }
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId a(at);
        ObId dom = s.attr(a).dom;
        for (Part p = 0; p < x.num_parts(dom); ++p) {
            y.set_subpart(a, new_id[dom.index()][p], x.subpart(a, p));
        }
    }
    return y;
}

} // namespace

std::vector<ACSetMorphism> find_matches(const Rule& rule, const ACSet& x,
                                        const MatchOptions& options) {
    Shape shape(rule);
    const auto& s = x.schema();
    hom::HomSearchOptions opt;
    opt.monic_all = options.monic;
    opt.monic = options.monic_objects;
    opt.initial = options.initial;
    if (options.monic && rule.semantics == Semantics::DPO) {
        // Dangling, checked as soon as a deleted part is placed: every X part referring to its
        // image must be the image of an L part referring to it, or of an L part whose hom is unset
        // (which the full check then examines). Valid for monic matches only.
        opt.accept = [&](ObId ob, Part l_part, Part x_part) {
            if (!shape.deleted(ob, l_part)) {
                return true;
            }
            for (HomId f : s.homs_into(ob)) {
                auto allowed = shape.l_incident[f.index()][l_part] + shape.unset_in_l[f.index()];
                if (x.incident(f, x_part).size() > allowed) {
                    return false;
                }
            }
            return true;
        };
    }
    std::vector<ACSetMorphism> matches;
    // Monic DPO matches cannot fail identification, and the pruning above decides dangling when
    // dangling_by_counts; then only application conditions remain (this saves the planner the
    // per-match maps of the full checks).
    bool only_conditions =
        options.monic && rule.semantics == Semantics::DPO && shape.dangling_by_counts;
    auto result = hom::for_each_homomorphism(rule.L, x, opt, [&](const ACSetMorphism& m) {
        bool valid = only_conditions ? !condition_problem(rule, x, m).has_value()
                                     : !validity_problem(shape, x, m).has_value();
        if (valid) {
            matches.push_back(m);
        }
        return options.max_results == 0 || matches.size() < options.max_results;
    });
    CATPLAN_ASSERT(result.error.empty(), "a rule's Pre has a free-floating variable");
    return matches;
}

std::optional<std::string> match_problem(const Rule& rule, const ACSet& x, const ACSetMorphism& m,
                                         bool monic) {
    auto failures = hom::naturality_failures(m, rule.L, x);
    if (!failures.empty()) {
        return "the match is not a morphism: " + hom::describe(failures.front(), rule.L, x);
    }
    if (monic && !is_injective(m, rule.L)) {
        return std::string("the match is not monic");
    }
    return validity_problem(Shape(rule), x, m);
}

Result<ACSetMorphism> rewrite_in_place(const Rule& rule, ACSet& x, const ACSetMorphism& m) {
    if (auto problem = match_problem(rule, x, m, /*monic=*/false)) {
        return fail(*problem);
    }
    Shape shape(rule);
    if (!shape.r_monic) {
        return fail(kGluingKeptParts);
    }
    auto out = apply_in_place(shape, x, m, /*track_origin=*/false);
    if (!out) {
        return fail(out.error());
    }
    return std::move(out->r_to_x);
}

Result<Rewrite> rewrite(const Rule& rule, const ACSet& x, const ACSetMorphism& m) {
    if (auto problem = match_problem(rule, x, m, /*monic=*/false)) {
        return fail(*problem);
    }
    Shape shape(rule);
    const auto& s = x.schema();
    if (!shape.r_monic) {
        return fail(kGluingKeptParts);
    }
    ACSet y = x;
    auto out = apply_in_place(shape, y, m, /*track_origin=*/true);
    if (!out) {
        return fail(out.error());
    }
    // Catlab's numbering: R's parts first (in R's order), then the untouched parts in X's order.
    std::vector<std::vector<Part>> order(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        std::vector<char> placed(y.num_parts(ObId(o)), 0);
        for (Part p : out->r_to_x.components[o]) {
            if (!placed[p]) {
                placed[p] = 1;
                order[o].push_back(p);
            }
        }
        std::vector<Part> rest;
        for (Part p = 0; p < y.num_parts(ObId(o)); ++p) {
            if (!placed[p]) {
                rest.push_back(p);
            }
        }
        std::sort(rest.begin(), rest.end(),
                  [&](Part a, Part b) { return out->origin[o][a] < out->origin[o][b]; });
        order[o].insert(order[o].end(), rest.begin(), rest.end());
    }
    Rewrite result{permuted(y, order), {}};
    result.r_to_result.var_components = out->r_to_x.var_components;
    result.r_to_result.components.resize(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        std::vector<Part> new_id(y.num_parts(ObId(o)));
        for (Part i = 0; i < order[o].size(); ++i) {
            new_id[order[o][i]] = i;
        }
        for (Part p : out->r_to_x.components[o]) {
            result.r_to_result.components[o].push_back(new_id[p]);
        }
    }
    return result;
}

} // namespace catplan::rewrite
