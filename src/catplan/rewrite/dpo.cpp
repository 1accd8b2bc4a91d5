// Matching (dpo.hpp) and what both applications of a rule share (detail/shape.hpp).

#include "catplan/rewrite/dpo.hpp"

#include "catplan/hom/forced.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/rewrite/detail/shape.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::rewrite {

namespace detail {

Shape::Shape(const Rule& r) : rule(r) {
    const auto& s = r.L.schema();
    colimit::ComplementOptions gluing;
    gluing.open.homs.resize(s.num_homs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        deletes.emplace_back(r.L.num_parts(ob), 0);
        for (Part p : r.deleted_parts(ob)) {
            deletes[o][p] = 1;
        }
        gluing.outside_l.push_back(r.deleted_parts(ob));
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
            if (r.K.subpart(f, k) != kNoPart) {
                continue;
            }
            if (r.L.subpart(f, r.l(dom, k)) != kNoPart) {
                dangling_by_counts = false; // a kept part's hom K leaves unset: check it fully
            }
            if (r.R.subpart(f, r.r(dom, k)) != kNoPart) {
                gluing.open.homs[h].push_back(k); // redirected by the rule
            }
        }
        l_incident.push_back(std::move(counts));
    }
    gluing_by_semantics = {gluing, gluing};
    gluing_by_semantics[1].cascade = true;
}

} // namespace detail

const detail::Shape& Rule::shape() const {
    const auto& shape = shape_.get([&] { return detail::Shape(*this); });
    for (std::uint32_t o = 0; o < shape.deletes.size(); ++o) {
        CATPLAN_ASSERT(shape.deletes[o].size() == L.num_parts(ObId(o)) &&
                           shape.k_of_r[o].size() == R.num_parts(ObId(o)),
                       "a rule's states changed after it was matched or applied");
    }
    return shape;
}

namespace detail {

bool is_injective(const ACSetMorphism& m, const ACSet& dom) {
    const auto& s = dom.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        std::vector<Part> images = m.components[o];
        std::sort(images.begin(), images.end());
        if (std::adjacent_find(images.begin(), images.end()) != images.end()) {
            return false;
        }
    }
    return true;
}

std::optional<std::string> condition_problem(const Rule& rule, const ACSet& x,
                                             const ACSetMorphism& m) {
    return rewrite::condition_problem(rule.conditions, rule.L, x, m);
}

std::optional<std::string> validity_problem(const Shape& shape, const ACSet& x,
                                            const ACSetMorphism& m) {
    const Rule& rule = shape.rule;
    auto violations = colimit::gluing_violations(rule.K, rule.L, x, rule.l, m, shape.gluing());
    if (!violations.empty()) {
        return violations.front().reason;
    }
    return condition_problem(rule, x, m);
}

namespace {

// Per attribute type, per variable of R: the value the match gives it, or unset (a fresh unknown).
Result<std::vector<std::vector<Value>>> r_values(const Rule& rule, const ACSetMorphism& m) {
    const auto& s = rule.R.schema();
    std::vector<std::vector<Value>> out(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        out[t].assign(rule.R.num_vars(ty), Value());
        for (std::uint32_t k = 0; k < rule.K.num_vars(ty); ++k) {
            const Value& rv = rule.r.var(ty, k);
            if (!rv.is_var()) {
                continue; // a kept value the rule overwrites with a constant
            }
            const Value& lv = rule.l.var(ty, k);
            Value bound = lv.is_var() ? m.var(ty, lv.var_index()) : lv;
            Value& slot = out[t][rv.var_index()];
            if (!slot.is_unset() && !(slot == bound)) {
                return fail(fmt::format("Eff merges kept values that the match binds to {} and "
                                        "{}; rules that glue kept values are not supported",
                                        slot.to_string(), bound.to_string()));
            }
            slot = bound;
        }
        for (std::uint32_t j = 0; j < rule.R.num_vars(ty); ++j) {
            bool has_expr =
                t < rule.exprs.size() && j < rule.exprs[t].size() && rule.exprs[t][j].has_value();
            if (!out[t][j].is_unset() || !has_expr) {
                continue;
            }
            auto v = evaluate(*rule.exprs[t][j],
                              [&](AttrTypeId type, std::uint32_t var) { return m.var(type, var); });
            if (!v) {
                return fail(fmt::format("cannot compute the value of {} in Eff: {}",
                                        rule.R.value_label(ty, Value::var(j)), v.error()));
            }
            out[t][j] = *v;
        }
    }
    return out;
}

// What an R cell of a kept part writes into the result: an X part, a created R part, a value,
// or a fresh unknown of R; equal for two cells exactly when they write the same thing.
struct Written {
    enum class Kind : std::uint8_t { None, XPart, Created, Value, Fresh } kind = Kind::None;
    Part part = kNoPart;
    Value value;

    friend bool operator==(const Written&, const Written&) = default;
};

Written written_hom(const Shape& shape, const ACSetMorphism& m, HomId f, Part rp) {
    const Rule& rule = shape.rule;
    Part t = rule.R.subpart(f, rp);
    if (t == kNoPart) {
        return {};
    }
    ObId codom = rule.R.schema().hom(f).codom;
    Part k = shape.k_of_r[codom.index()][t];
    if (k == kNoPart) {
        return {Written::Kind::Created, t, Value()};
    }
    return {Written::Kind::XPart, m(codom, rule.l(codom, k)), Value()};
}

Written written_attr(const Rule& rule, const std::vector<std::vector<Value>>& r_var, AttrId a,
                     Part rp) {
    Value v = rule.R.subpart(a, rp);
    if (v.is_unset()) {
        return {};
    }
    if (v.is_var()) {
        const Value& bound = r_var[rule.R.schema().attr(a).codom.index()][v.var_index()];
        if (bound.is_unset()) {
            return {Written::Kind::Fresh, v.var_index(), Value()};
        }
        v = bound;
    }
    return {Written::Kind::Value, kNoPart, v};
}

// Whether m may send two kept parts of ob to one part of X: a few kept parts are compared
// pairwise; more are left to the sort (true).
bool identifies_kept_parts(const Rule& rule, const ACSetMorphism& m, ObId ob) {
    std::size_t n = rule.K.num_parts(ob);
    if (n > 32) {
        return true;
    }
    for (Part k = 1; k < n; ++k) {
        Part image = m(ob, rule.l(ob, k));
        for (Part j = 0; j < k; ++j) {
            if (m(ob, rule.l(ob, j)) == image) {
                return true;
            }
        }
    }
    return false;
}

// Why the match cannot be applied because it sends several kept parts to one part of X and Eff
// gives them different values of a hom or attribute, which the pushout would glue.
std::optional<std::string> identified_kept_problem(const Shape& shape, const ACSetMorphism& m,
                                                   const std::vector<std::vector<Value>>& r_var) {
    const Rule& rule = shape.rule;
    const auto& s = rule.K.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        if (!identifies_kept_parts(rule, m, ob)) {
            continue; // no two kept parts share an image: nothing to glue
        }
        std::vector<std::pair<Part, Part>> by_image; // (X part, R part of a kept part)
        for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
            by_image.emplace_back(m(ob, rule.l(ob, k)), rule.r(ob, k));
        }
        std::sort(by_image.begin(), by_image.end());
        // Within a group of kept parts with one image, every cell Eff sets must agree with the
        // first one set; `first` is the group's first R part with that cell set.
        auto conflict = [&](std::size_t begin, std::size_t end, auto written) {
            std::optional<std::pair<Part, Written>> first;
            for (std::size_t i = begin; i < end; ++i) {
                Written w = written(by_image[i].second);
                if (w.kind == Written::Kind::None) {
                    continue;
                }
                if (!first) {
                    first.emplace(by_image[i].second, w);
                } else if (!(first->second == w)) {
                    return std::optional<std::pair<Part, Part>>({first->first, by_image[i].second});
                }
            }
            return std::optional<std::pair<Part, Part>>();
        };
        for (std::size_t begin = 0, end = 0; begin < by_image.size(); begin = end) {
            while (end < by_image.size() && by_image[end].first == by_image[begin].first) {
                ++end;
            }
            if (end - begin < 2) {
                continue;
            }
            std::optional<std::pair<Part, Part>> pair;
            std::string what;
            for (HomId f : s.homs_from(ob)) {
                if (!pair && (pair = conflict(begin, end, [&](Part rp) {
                                  return written_hom(shape, m, f, rp);
                              }))) {
                    what = s.hom(f).name;
                }
            }
            for (AttrId at : s.attrs_from(ob)) {
                if (!pair && (pair = conflict(begin, end, [&](Part rp) {
                                  return written_attr(rule, r_var, at, rp);
                              }))) {
                    what = s.attr(at).name;
                }
            }
            if (pair) {
                return fmt::format(
                    "the match sends the kept parts {} and {} of {} to one part, and "
                    "Eff gives them different values of {}: not supported",
                    rule.R.part_label(ob, pair->first), rule.R.part_label(ob, pair->second),
                    s.ob(ob).name, what);
            }
        }
    }
    return std::nullopt;
}

} // namespace

Result<std::vector<std::vector<Value>>> application_values(const Shape& shape,
                                                           const ACSetMorphism& m) {
    if (!shape.r_monic) {
        return fail(kGluingKeptParts);
    }
    auto r_var = r_values(shape.rule, m);
    if (!r_var) {
        return r_var;
    }
    if (auto problem = identified_kept_problem(shape, m, *r_var)) {
        return fail(*problem);
    }
    return r_var;
}

} // namespace detail

std::optional<std::string> condition_problem(const std::vector<ApplicationCondition>& conditions,
                                             const ACSet& pattern, const ACSet& x,
                                             const ACSetMorphism& m) {
    const auto& s = pattern.schema();
    for (const auto& c : conditions) {
        hom::HomSearchOptions opt;
        opt.monic_all = true;
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Part p = 0; p < pattern.num_parts(ObId(o)); ++p) {
                opt.bind(ObId(o), c.n(ObId(o), p), m(ObId(o), p));
            }
        }
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            AttrTypeId ty(t);
            for (std::uint32_t v = 0; v < pattern.num_vars(ty); ++v) {
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

std::vector<ACSetMorphism> find_matches(const Rule& rule, const ACSet& x,
                                        const MatchOptions& options) {
    const detail::Shape& shape = rule.shape();
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
    auto valid = [&](const ACSetMorphism& m) {
        return only_conditions ? !detail::condition_problem(rule, x, m).has_value()
                               : !detail::validity_problem(shape, x, m).has_value();
    };
    // A step's arguments most often bind everything a search would choose (hom/forced.hpp).
    if (auto forced = hom::forced_homomorphism(rule.L, x, opt);
        forced.kind != hom::Forced::Kind::Undecided) {
        if (forced.kind == hom::Forced::Kind::One && valid(forced.morphism)) {
            matches.push_back(std::move(forced.morphism));
        }
        return matches;
    }
    auto result = hom::for_each_homomorphism(rule.L, x, opt, [&](const ACSetMorphism& m) {
        if (valid(m)) {
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
    if (monic && !detail::is_injective(m, rule.L)) {
        return std::string("the match is not monic");
    }
    return detail::validity_problem(rule.shape(), x, m);
}

} // namespace catplan::rewrite
