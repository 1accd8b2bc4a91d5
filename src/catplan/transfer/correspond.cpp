#include "catplan/transfer/correspond.hpp"

#include "catplan/hom/hom_search.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using hom::ACSetMorphism;
using rewrite::Rule;

/// The first object whose part counts differ, in words; nullopt when they agree.
std::optional<std::string> count_difference(const ACSet& a, const ACSet& b, std::string_view what) {
    const auto& s = a.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (a.num_parts(ObId(o)) != b.num_parts(ObId(o))) {
            return fmt::format("{} differ: {} against {} part(s) of {}", what, a.num_parts(ObId(o)),
                               b.num_parts(ObId(o)), s.ob(ObId(o)).name);
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        if (a.num_vars(AttrTypeId(t)) != b.num_vars(AttrTypeId(t))) {
            return fmt::format("{} differ in their unknowns of {}", what,
                               s.attr_type(AttrTypeId(t)).name);
        }
    }
    return std::nullopt;
}

bool has_expressions(const Rule& r) {
    for (const auto& per_type : r.exprs) {
        for (const auto& e : per_type) {
            if (e) {
                return true;
            }
        }
    }
    return false;
}

/// The part of K_t that l_t sends to p (kNoPart when p is not in l_t's image).
Part l_preimage(const Rule& r, ObId ob, Part p) {
    const auto& c = r.l.components[ob.index()];
    auto it = std::find(c.begin(), c.end(), p);
    return it == c.end() ? kNoPart : static_cast<Part>(it - c.begin());
}

class SpanIso {
public:
    SpanIso(const Rule& g, const rewrite::RulePtr& t) : g_(g), t_(t) {}

    Result<Correspondence> find() {
        if (auto why = shapes_differ()) {
            return fail(*why);
        }
        hom::HomSearchOptions opt;
        opt.iso = true;
        opt.max_results = kMaxIsos;
        std::optional<Correspondence> found;
        std::string why = "no isomorphism of the preconditions";
        hom::for_each_homomorphism(g_.L, t_->L, opt, [&](const ACSetMorphism& phi) {
            auto c = extend(phi);
            if (c) {
                found = std::move(*c);
                return false;
            }
            why = c.error();
            return true;
        });
        if (!found) {
            return fail(why);
        }
        return std::move(*found);
    }

private:
    static constexpr std::uint64_t kMaxIsos = 4096;

    std::optional<std::string> shapes_differ() const {
        if (has_expressions(g_) || has_expressions(*t_)) {
            return "attribute expressions are not compared";
        }
        for (auto [a, b, what] : {std::tuple{&g_.L, &t_->L, "the preconditions"},
                                  std::tuple{&g_.K, &t_->K, "the kept parts"},
                                  std::tuple{&g_.R, &t_->R, "the effects"}}) {
            if (auto d = count_difference(*a, *b, what)) {
                return d;
            }
        }
        if (g_.conditions.size() != t_->conditions.size()) {
            return fmt::format("{} against {} application condition(s)", g_.conditions.size(),
                               t_->conditions.size());
        }
        return std::nullopt;
    }

    /// The rest of the correspondence over an isomorphism of the preconditions, or why not.
    Result<Correspondence> extend(const ACSetMorphism& phi) const {
        const auto& s = g_.L.schema();
        // K: l_t⁻¹ ∘ φ ∘ l_g must be defined (and, the counts being equal, it is then a bijection).
        hom::HomSearchOptions ropt;
        ropt.iso = true;
        ropt.max_results = 1;
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            std::vector<bool> used(t_->K.num_parts(ObId(o)), false);
            for (Part k = 0; k < g_.K.num_parts(ObId(o)); ++k) {
                Part kt = l_preimage(*t_, ObId(o), phi(ObId(o), g_.l(ObId(o), k)));
                if (kt == kNoPart || used[kt]) {
                    return fail(fmt::format("the isomorphism of the preconditions does not keep "
                                            "the kept parts of {}",
                                            s.ob(ObId(o)).name));
                }
                used[kt] = true;
                ropt.bind(ObId(o), g_.r(ObId(o), k), t_->r(ObId(o), kt));
            }
        }
        auto r_iso = hom::find_homomorphism(g_.R, t_->R, ropt);
        if (!r_iso) {
            return fail("the effects differ over the same precondition");
        }
        if (auto why = conditions_differ(phi)) {
            return fail(*why);
        }
        Correspondence c{t_, phi, std::move(*r_iso), {}};
        for (const auto& p : t_->parameters) {
            Part pg = preimage(phi, p.ob, p.part);
            auto it = std::find_if(g_.parameters.begin(), g_.parameters.end(),
                                   [&](const auto& q) { return q.ob == p.ob && q.part == pg; });
            if (it == g_.parameters.end()) {
                return fail(fmt::format("the target's parameter {} is no parameter of the source "
                                        "action",
                                        p.name));
            }
            c.parameters.push_back(it->name);
        }
        return c;
    }

    static Part preimage(const ACSetMorphism& m, ObId ob, Part p) {
        const auto& c = m.components[ob.index()];
        return static_cast<Part>(std::find(c.begin(), c.end(), p) - c.begin());
    }

    /// Why the application conditions do not correspond over φ, or nullopt.
    std::optional<std::string> conditions_differ(const ACSetMorphism& phi) const {
        const auto& s = g_.L.schema();
        std::vector<bool> used(t_->conditions.size(), false);
        for (const auto& cg : g_.conditions) {
            bool matched = false;
            for (std::size_t j = 0; j < t_->conditions.size() && !matched; ++j) {
                const auto& ct = t_->conditions[j];
                if (used[j] || ct.negative != cg.negative ||
                    count_difference(cg.n_state, ct.n_state, "")) {
                    continue;
                }
                hom::HomSearchOptions opt;
                opt.iso = true;
                opt.max_results = 1;
                for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
                    for (Part p = 0; p < g_.L.num_parts(ObId(o)); ++p) {
                        opt.bind(ObId(o), cg.n(ObId(o), p), ct.n(ObId(o), phi(ObId(o), p)));
                    }
                }
                matched = hom::is_homomorphic(cg.n_state, ct.n_state, opt);
                used[j] = matched;
            }
            if (!matched) {
                return fmt::format("the condition {} has no counterpart", cg.name);
            }
        }
        return std::nullopt;
    }

    const Rule& g_;
    const rewrite::RulePtr& t_;
};

} // namespace

Result<Correspondence> corresponds(const Rule& generated, const rewrite::RulePtr& target) {
    CATPLAN_ASSERT(&generated.L.schema() == &target->L.schema(),
                   "a correspondence is between rules on one schema");
    return SpanIso(generated, target).find();
}

hom::ACSetMorphism transport(const hom::ACSetMorphism& m, const Correspondence& c) {
    hom::ACSetMorphism out;
    out.components.resize(m.components.size());
    for (std::size_t o = 0; o < m.components.size(); ++o) {
        out.components[o].resize(m.components[o].size());
        for (std::size_t p = 0; p < m.components[o].size(); ++p) {
            out.components[o][c.l_iso.components[o][p]] = m.components[o][p];
        }
    }
    out.var_components.resize(m.var_components.size());
    for (std::size_t t = 0; t < m.var_components.size(); ++t) {
        out.var_components[t].resize(m.var_components[t].size());
        for (std::size_t j = 0; j < m.var_components[t].size(); ++j) {
            const auto& image = c.l_iso.var_components[t][j];
            CATPLAN_ASSERT(image.is_var(), "an isomorphism sends unknowns to unknowns");
            out.var_components[t][image.var_index()] = m.var_components[t][j];
        }
    }
    return out;
}

Part generated_part(const Correspondence& c, ObId ob, Part target_part) {
    const auto& comp = c.r_iso.components[ob.index()];
    auto it = std::find(comp.begin(), comp.end(), target_part);
    CATPLAN_ASSERT(it != comp.end(), "an isomorphism is onto");
    return static_cast<Part>(it - comp.begin());
}

const Correspondence* TargetActions::find(std::string_view generated) const {
    auto it = table.find(generated);
    return it == table.end() || !it->second ? nullptr : &*it->second;
}

std::string TargetActions::name_of(std::string_view rule) const {
    return action_name ? action_name(rule) : std::string(rule);
}

TargetActions correspond_domain(const plan::Domain& generated, plan::DomainPtr target,
                                const std::vector<std::pair<std::string, std::string>>& named,
                                std::function<std::string(std::string_view)> action_name,
                                std::function<std::string(std::string_view)> source_action_name) {
    TargetActions out;
    out.domain = std::move(target);
    out.action_name = std::move(action_name);
    out.source_action_name = std::move(source_action_name);
    for (const auto& g : generated.rules) {
        std::string source =
            out.source_action_name ? out.source_action_name(g->name) : std::string(g->name);
        auto it = std::find_if(named.begin(), named.end(),
                               [&](const auto& n) { return n.first == source; });
        std::string why = "no target action has the same span";
        std::optional<Correspondence> found;
        for (const auto& t : out.domain->rules) {
            if (it != named.end() && out.name_of(t->name) != it->second) {
                continue;
            }
            auto c = corresponds(*g, t);
            if (c) {
                found = std::move(*c);
                break;
            }
            if (it != named.end()) {
                why = fmt::format("the map names {} for {}, but {}", it->second, source, c.error());
            }
        }
        if (found) {
            out.table.emplace(g->name, std::move(*found));
        } else {
            out.table.emplace(g->name, fail(why));
        }
    }
    return out;
}

} // namespace catplan::transfer
