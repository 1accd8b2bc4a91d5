#include "catplan/transfer/named_state.hpp"

#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::transfer {
NamedState::NamedState(acset::ACSet x)
    : x_(std::move(x)),
      index_(x_.schema().num_obs()),
      ambiguous_(index_.size(), 0),
      suffix_hints_(index_.size()) {
    for (std::uint32_t o = 0; o < index_.size(); ++o) {
        index_[o].reserve(x_.num_parts(ObId(o)));
        for (Part p = 0; p < x_.num_parts(ObId(o)); ++p) {
            add(ObId(o), p);
        }
    }
}

Result<hom::ACSetMorphism> NamedState::apply(const rewrite::Rule& rule, const hom::ACSetMorphism& m,
                                             const std::function<std::string(ObId, Part)>& name_of,
                                             rewrite::CheckMatch check) {
    const auto& s = x_.schema();
    // The parts to be deleted (the images of the parts the rule deletes), unnamed now. The parts
    // that survive the deletion keep the ids below survivors[o]; a created part is at or above
    // it, unless it is a fact merged into one already there (Rule::relations).
    std::vector<std::pair<ObId, Part>> deleted;
    std::vector<Part> survivors(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        const auto& parts = rule.deleted_parts(ObId(o));
        for (Part p : parts) {
            deleted.emplace_back(ObId(o), m.components[o][p]);
            remove(ObId(o), m.components[o][p]);
        }
        survivors[o] = static_cast<Part>(x_.num_parts(ObId(o)) - parts.size());
    }
    auto r_to_x = rewrite::rewrite_in_place(rule, x_, m, check);
    if (!r_to_x) {
        return r_to_x;
    }
    // Pop-and-swap moved surviving parts into deleted slots below the count of survivors;
    // the created parts come after them (R's order) and are named below. A moved part's
    // entry still holds its old id: point it at the slot it sits in now.
    for (auto [ob, p] : deleted) {
        if (p < survivors[ob.index()]) {
            moved(ob, p, survivors[ob.index()]);
        }
    }
    name_created(rule, *r_to_x, survivors, name_of);
    return r_to_x;
}

std::string NamedState::fresh_name(ObId ob, const std::string& base) {
    if (!taken(ob, base)) {
        return base;
    }
    auto& hints = suffix_hints_[ob.index()];
    auto it =
        std::lower_bound(hints.begin(), hints.end(), base,
                         [](const auto& hint, const std::string& b) { return hint.first < b; });
    if (it == hints.end() || it->first != base) {
        it = hints.emplace(it, base, 2);
    }
    for (std::uint64_t k = it->second;; ++k) {
        std::string name = fmt::format("{}{}", base, k);
        if (!taken(ob, name)) {
            it->second = k + 1; // the caller gives the name to a part at once
            return name;
        }
    }
}

void NamedState::add(ObId ob, Part p) {
    std::string_view n = x_.part_name(ob, p);
    if (n.empty()) {
        return;
    }
    auto [e, fresh] = index_[ob.index()].emplace(n, p);
    if (!fresh && *e != p) {
        ambiguous_[ob.index()] += *e != kNoPart;
        *e = kNoPart;
    }
}

// Forgets p's name (a shared name stays taken: which part keeps it is not known).
void NamedState::remove(ObId ob, Part p) {
    std::string_view n = x_.part_name(ob, p);
    auto& idx = index_[ob.index()];
    const Part* e = idx.find(n);
    if (e != nullptr && *e == p) {
        idx.erase(n);
        freed(ob, n);
    }
}

// The part now at slot p (p < survivors) was moved there by a pop-and-swap from an id at or
// above survivors. Its entry points at that old id, unless the name is shared with another
// surviving part (ambiguous, kNoPart, or held by a part below survivors that has the name).
void NamedState::moved(ObId ob, Part p, Part survivors) {
    std::string_view n = x_.part_name(ob, p);
    if (n.empty()) {
        return;
    }
    auto [entry, fresh] = index_[ob.index()].emplace(n, p);
    Part& e = *entry;
    if (fresh || e == p) {
        return;
    }
    bool shared = e == kNoPart || (e < survivors && x_.part_name(ob, e) == n);
    ambiguous_[ob.index()] += shared && e != kNoPart;
    e = shared ? kNoPart : p;
}

// A name base<k> no longer taken lowers the hint of base to k.
void NamedState::freed(ObId ob, std::string_view name) {
    for (auto& [base, hint] : suffix_hints_[ob.index()]) {
        if (name.size() <= base.size() || name.substr(0, base.size()) != base) {
            continue;
        }
        std::string_view digits = name.substr(base.size());
        if (digits[0] == '0' || digits.size() > 18 ||
            !std::all_of(digits.begin(), digits.end(),
                         [](char c) { return c >= '0' && c <= '9'; })) {
            continue;
        }
        std::uint64_t k = std::stoull(std::string(digits));
        if (k >= 2 && k < hint) {
            hint = k;
        }
    }
}

// A created fact merged into one already there (Rule::relations) is not new and keeps its name.
void NamedState::name_created(const rewrite::Rule& rule, const hom::ACSetMorphism& r_to_x,
                              const std::vector<Part>& survivors,
                              const std::function<std::string(ObId, Part)>& name_of) {
    const auto& s = x_.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part q : rule.created_parts(ObId(o))) {
            Part p = r_to_x.components[o][q];
            if (p < survivors[o]) {
                continue;
            }
            x_.set_part_name(ObId(o), p, name_of(ObId(o), q));
            add(ObId(o), p);
        }
    }
}

Result<hom::ACSetMorphism> match_by_names(const rewrite::Rule& rule, const NamedState& x,
                                          const plan::Step& step) {
    rewrite::MatchOptions opt;
    bool all_bound = step.args.size() == rule.parameters.size();
    for (std::size_t i = 0; all_bound && i < step.args.size(); ++i) {
        const auto& param = rule.parameters[i];
        Part p = x.find(param.ob, step.args[i]);
        all_bound = p != kNoPart;
        opt.initial.push_back({param.ob, param.part, p});
    }
    if (all_bound) {
        opt.max_results = 2;
        auto matches = rewrite::find_matches(rule, x.state(), opt);
        if (matches.size() == 1) {
            return std::move(matches[0]);
        }
    }
    return plan::resolve_step(rule, x.state(), step);
}

} // namespace catplan::transfer
