#include "catplan/plan/entities.hpp"

#include <algorithm>

namespace catplan::plan {

namespace {

bool r_injective(const Rule& rule, ObId ob) {
    std::vector<bool> hit(rule.R.num_parts(ob), false);
    for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
        Part q = rule.r(ob, k);
        if (hit[q]) {
            return false;
        }
        hit[q] = true;
    }
    return true;
}

// Per hom: whether some rule makes it point into a kept part where it did not before (R sets it
// on a created part, or on a kept part whose K value is another or unset). A hom that no rule
// gains keeps every kept part's preimage under it from growing.
std::vector<bool> gainable_homs(const schema::Schema& s, const std::vector<RulePtr>& rules) {
    std::vector<bool> gained(s.num_homs(), false);
    for (const auto& rule : rules) {
        for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
            HomId f(h);
            ObId dom = s.hom(f).dom, cod = s.hom(f).codom;
            std::vector<Part> k_of_r(rule->R.num_parts(dom), kNoPart);
            for (Part k = 0; k < rule->K.num_parts(dom); ++k) {
                k_of_r[rule->r(dom, k)] = k;
            }
            std::vector<bool> kept_target(rule->R.num_parts(cod), false);
            for (Part k = 0; k < rule->K.num_parts(cod); ++k) {
                kept_target[rule->r(cod, k)] = true;
            }
            for (Part q = 0; q < rule->R.num_parts(dom); ++q) {
                Part t = rule->R.subpart(f, q);
                if (t == kNoPart || !kept_target[t]) {
                    continue;
                }
                Part k = k_of_r[q];
                Part before = k == kNoPart ? kNoPart : rule->K.subpart(f, k);
                if (before == kNoPart || rule->r(cod, before) != t) {
                    gained[h] = true;
                }
            }
        }
    }
    return gained;
}

// Per hom: whether some rule redirects it on a kept part (K unset, R set).
std::vector<bool> redirected_homs(const schema::Schema& s, const std::vector<RulePtr>& rules) {
    std::vector<bool> out(s.num_homs(), false);
    for (const auto& rule : rules) {
        for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
            HomId f(h);
            ObId dom = s.hom(f).dom;
            for (Part k = 0; k < rule->K.num_parts(dom); ++k) {
                if (rule->K.subpart(f, k) == kNoPart &&
                    rule->R.subpart(f, rule->r(dom, k)) != kNoPart) {
                    out[h] = true;
                }
            }
        }
    }
    return out;
}

struct Analysis {
    const schema::Schema& s;
    const std::vector<RulePtr>& rules;
    const ACSet& init;
    std::vector<bool> whole, gained, redirected;

    // Whether initial part p has an f-preimage that stays forever (entities.hpp, case b).
    bool pinned_by(HomId f, Part p) const {
        ObId dom = s.hom(f).dom;
        return whole[dom.index()] && !redirected[f.index()] && !init.incident(f, p).empty();
    }

    // Whether some rule's deleted L part of ob might match initial part p in a reachable state.
    bool deletable(ObId ob, Part p) const {
        for (const auto& rule : rules) {
            for (Part d : rule->deleted_parts(ob)) {
                bool excluded = false;
                for (HomId f : s.homs_into(ob)) {
                    bool needs = !rule->L.incident(f, d).empty();
                    if ((needs && !gained[f.index()] && init.incident(f, p).empty()) ||
                        pinned_by(f, p)) {
                        excluded = true;
                    }
                }
                if (!excluded) {
                    return true;
                }
            }
        }
        return false;
    }
};

} // namespace

bool Entities::is_entity(ObId ob, Part p) const {
    const auto& ps = parts[ob.index()];
    return std::binary_search(ps.begin(), ps.end(), p);
}

Entities find_entities(const Domain& domain, const ACSet& init) {
    const auto& s = init.schema();
    const auto& rules = domain.rules;
    Entities e;
    e.whole.assign(s.num_obs(), true);
    e.stable.assign(s.num_obs(), true);
    for (const auto& rule : rules) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            ObId ob(o);
            std::size_t nk = rule->K.num_parts(ob);
            bool injective = r_injective(*rule, ob);
            if (rule->L.num_parts(ob) != nk || rule->R.num_parts(ob) != nk || !injective) {
                e.whole[o] = false;
            }
            if (!injective) {
                e.stable[o] = false;
            }
        }
    }
    e.redirected = redirected_homs(s, rules);
    Analysis a{s, rules, init, e.whole, gainable_homs(s, rules), e.redirected};
    e.parts.assign(s.num_obs(), {});
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < init.num_parts(ob); ++p) {
            if (e.whole[o]) {
                e.parts[o].push_back(p);
                continue;
            }
            if (!e.stable[o]) {
                break; // a rule merges parts of ob: identities are not stable
            }
            auto name = init.part_name(ob, p);
            if (!name.empty() && init.find_part(ob, name) == p && !a.deletable(ob, p)) {
                e.parts[o].push_back(p);
            }
        }
    }
    return e;
}

} // namespace catplan::plan
