#include "catplan/plan/validate.hpp"

#include "catplan/plan/actions.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <algorithm>
#include <charconv>
#include <fmt/format.h>

namespace catplan::plan {
namespace {

// One statement of a pattern: a part (with its hom values to the parts added before it) or an
// attribute value of a part already added.
struct Statement {
    bool is_attr = false;
    ObId ob;
    Part part = 0;
    AttrId attr;
};

// The statements of `pattern` in growth order: the bound parts first, then repeatedly the first
// part (object order, then part order) linked by a hom to a part already added, or failing that
// the first part not yet added; each part is followed by its attribute values.
std::vector<Statement> growth_order(const ACSet& pattern,
                                    const std::vector<hom::PartBinding>& initial) {
    const auto& s = pattern.schema();
    std::vector<std::vector<bool>> added(s.num_obs());
    std::size_t remaining = 0;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        added[o].assign(pattern.num_parts(ObId(o)), false);
        remaining += pattern.num_parts(ObId(o));
    }
    std::vector<Statement> order;
    auto add = [&](ObId ob, Part p) {
        added[ob.index()][p] = true;
        --remaining;
        order.push_back({false, ob, p, AttrId()});
        for (AttrId a : s.attrs_from(ob)) {
            if (!pattern.subpart(a, p).is_unset()) {
                order.push_back({true, ob, p, a});
            }
        }
    };
    for (const auto& b : initial) {
        if (!added[b.ob.index()][b.dom]) {
            add(b.ob, b.dom);
        }
    }
    auto linked = [&](ObId ob, Part p) {
        for (HomId f : s.homs_from(ob)) {
            Part q = pattern.subpart(f, p);
            if (q != kNoPart && added[s.hom(f).codom.index()][q]) {
                return true;
            }
        }
        for (HomId f : s.homs_into(ob)) {
            for (Part q : pattern.incident(f, p)) {
                if (added[s.hom(f).dom.index()][q]) {
                    return true;
                }
            }
        }
        return false;
    };
    while (remaining > 0) {
        std::optional<std::pair<ObId, Part>> next, fallback;
        for (std::uint32_t o = 0; o < s.num_obs() && !next; ++o) {
            for (Part p = 0; p < pattern.num_parts(ObId(o)); ++p) {
                if (added[o][p]) {
                    continue;
                }
                if (!fallback) {
                    fallback = {ObId(o), p};
                }
                if (linked(ObId(o), p)) {
                    next = {ObId(o), p};
                    break;
                }
            }
        }
        auto [ob, p] = next ? *next : *fallback;
        add(ob, p);
    }
    return order;
}

// The sub-pattern made of the first n statements: their parts, the hom values between them, their
// attribute values (variables renumbered in order of use). `index` receives old -> new part ids.
ACSet sub_pattern(const ACSet& pattern, const std::vector<Statement>& order, std::size_t n,
                  std::vector<std::vector<Part>>& index) {
    const auto& s = pattern.schema();
    ACSet sub(pattern.schema_ptr());
    index.assign(s.num_obs(), {});
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        index[o].assign(pattern.num_parts(ObId(o)), kNoPart);
    }
    std::vector<std::vector<std::uint32_t>> var_index(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        var_index[t].assign(pattern.num_vars(AttrTypeId(t)), UINT32_MAX);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const auto& st = order[i];
        if (!st.is_attr) {
            index[st.ob.index()][st.part] = sub.add_part(st.ob, pattern.part_name(st.ob, st.part));
        }
    }
    for (std::uint32_t f = 0; f < s.num_homs(); ++f) {
        const auto& h = s.hom(HomId(f));
        for (Part p = 0; p < pattern.num_parts(h.dom); ++p) {
            Part q = pattern.subpart(HomId(f), p);
            if (q == kNoPart) {
                continue;
            }
            Part np = index[h.dom.index()][p], nq = index[h.codom.index()][q];
            if (np != kNoPart && nq != kNoPart) {
                sub.set_subpart(HomId(f), np, nq);
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const auto& st = order[i];
        if (!st.is_attr) {
            continue;
        }
        AttrTypeId t = s.attr(st.attr).codom;
        acset::Value v = pattern.subpart(st.attr, st.part);
        if (v.is_var()) {
            auto& slot = var_index[t.index()][v.var_index()];
            if (slot == UINT32_MAX) {
                slot = sub.add_var(t, pattern.var_name(t, v.var_index())).var_index();
            }
            v = acset::Value::var(slot);
        }
        sub.set_subpart(st.attr, index[st.ob.index()][st.part], v);
    }
    return sub;
}

std::string describe_statement(const ACSet& pattern, const Statement& st,
                               const std::vector<std::vector<Part>>& index) {
    const auto& s = pattern.schema();
    std::string label = pattern.part_label(st.ob, st.part);
    if (st.is_attr) {
        AttrTypeId t = s.attr(st.attr).codom;
        return fmt::format("{}({}) == {}", s.attr(st.attr).name, label,
                           pattern.value_label(t, pattern.subpart(st.attr, st.part)));
    }
    std::vector<std::string> homs;
    for (HomId f : s.homs_from(st.ob)) {
        Part q = pattern.subpart(f, st.part);
        ObId cod = s.hom(f).codom;
        if (q != kNoPart && index[cod.index()][q] != kNoPart) {
            homs.push_back(
                fmt::format("{}({}) == {}", s.hom(f).name, label, pattern.part_label(cod, q)));
        }
    }
    for (HomId f : s.homs_into(st.ob)) {
        ObId dom = s.hom(f).dom;
        if (dom == st.ob) {
            continue; // a loop: already listed as an outgoing hom
        }
        for (Part q : pattern.incident(f, st.part)) {
            if (index[dom.index()][q] != kNoPart) {
                homs.push_back(
                    fmt::format("{}({}) == {}", s.hom(f).name, pattern.part_label(dom, q), label));
            }
        }
    }
    std::string text = fmt::format("{} {}", s.ob(st.ob).name, label);
    if (!homs.empty()) {
        text += " (" + fmt::format("{}", fmt::join(homs, ", ")) + ")";
    }
    return text;
}

hom::HomSearchOptions monic_options(const std::vector<hom::PartBinding>& initial) {
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    opt.initial = initial;
    opt.max_results = 1;
    return opt;
}

std::string plural(std::size_t n, std::string_view word) {
    return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

// The part of object `ob` that a step argument names: a part name, or `#k` (1-based).
std::optional<Part> find_argument(const ACSet& x, ObId ob, const std::string& arg) {
    if (arg.size() > 1 && arg[0] == '#') {
        std::uint32_t k = 0;
        auto [ptr, ec] = std::from_chars(arg.data() + 1, arg.data() + arg.size(), k);
        if (ec == std::errc() && ptr == arg.data() + arg.size() && k >= 1 && k <= x.num_parts(ob)) {
            return k - 1;
        }
        return std::nullopt;
    }
    return x.find_part(ob, arg);
}

} // namespace

std::optional<std::string> explain_no_embedding(const ACSet& pattern, const ACSet& x,
                                                const std::vector<hom::PartBinding>& initial) {
    auto order = growth_order(pattern, initial);
    std::vector<std::vector<Part>> index;
    for (std::size_t n = 1; n <= order.size(); ++n) {
        ACSet sub = sub_pattern(pattern, order, n, index);
        std::vector<hom::PartBinding> bound;
        for (const auto& b : initial) {
            Part d = index[b.ob.index()][b.dom];
            if (d != kNoPart) {
                bound.push_back({b.ob, d, b.codom});
            }
        }
        if (!hom::is_homomorphic(sub, x, monic_options(bound))) {
            return describe_statement(pattern, order[n - 1], index);
        }
    }
    if (order.empty() && !hom::is_homomorphic(pattern, x, monic_options(initial))) {
        return std::string("the empty pattern does not embed"); // unreachable in practice
    }
    return std::nullopt;
}

namespace {

// A part with its word and whether that word is more than its bare label.
struct Called {
    std::string word;
    bool readable = false;
};

Called call(const MatchWords& words, const ACSet& x, ObId ob, Part p) {
    std::string label = x.part_label(ob, p);
    if (!words.part) {
        return {label, false};
    }
    std::string word = words.part(x, ob, p);
    bool readable = word != label;
    return {std::move(word), readable};
}

// The first readable word of a side, else the first word.
const std::string& best(const std::vector<Called>& side) {
    for (const auto& c : side) {
        if (c.readable) {
            return c.word;
        }
    }
    return side.front().word;
}

// The bindings of one group of parts of l: one item when the readable words of their images
// agree, else one per part.
void group_items(const std::vector<Called>& from, const std::vector<Called>& to,
                 std::vector<std::string>& items) {
    std::vector<std::string> distinct;
    for (const auto& c : to) {
        if (c.readable && std::find(distinct.begin(), distinct.end(), c.word) == distinct.end()) {
            distinct.push_back(c.word);
        }
    }
    if (distinct.size() <= 1) {
        items.push_back(fmt::format("{} ↦ {}", best(from), best(to)));
        return;
    }
    for (std::size_t i = 0; i < from.size(); ++i) {
        items.push_back(fmt::format("{} ↦ {}", best(from), to[i].word));
    }
}

} // namespace

std::string describe_match(const ACSetMorphism& m, const ACSet& l, const ACSet& x,
                           const MatchWords& words) {
    const auto& s = l.schema();
    // Groups in the order of their first part: (key, the parts' words, their images' words).
    std::vector<std::optional<std::uint64_t>> keys;
    std::vector<std::pair<std::vector<Called>, std::vector<Called>>> groups;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < l.num_parts(ObId(o)); ++p) {
            auto key = words.group ? words.group(ObId(o), p) : std::nullopt;
            auto it = key ? std::find(keys.begin(), keys.end(), key) : keys.end();
            if (it == keys.end()) {
                keys.push_back(key);
                groups.emplace_back();
                it = std::prev(keys.end());
            }
            auto& g = groups[static_cast<std::size_t>(it - keys.begin())];
            g.first.push_back(call(words, l, ObId(o), p));
            g.second.push_back(call(words, x, ObId(o), m.components[o][p]));
        }
    }
    std::vector<std::string> items;
    for (const auto& [from, to] : groups) {
        group_items(from, to, items);
    }
    // Once each: a migrated rule has a part per target type of a source part, all named alike
    // (block ↦ bread2 for its Object and its Receptacle).
    std::vector<std::string> once;
    for (auto& item : items) {
        if (std::find(once.begin(), once.end(), item) == once.end()) {
            once.push_back(std::move(item));
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t j = 0; j < l.num_vars(ty) && j < m.var_components[t].size(); ++j) {
            once.push_back(fmt::format("{} ↦ {}", l.value_label(ty, acset::Value::var(j)),
                                       x.value_label(ty, m.var_components[t][j])));
        }
    }
    return fmt::format("{}", fmt::join(once, ", "));
}

namespace {

// resolve_step; *ambiguous tells whether it failed because the arguments leave several matches.
Result<ACSetMorphism> resolve(const Rule& rule, const ACSet& x, const Step& step, bool* ambiguous) {
    const auto& s = x.schema();
    if (step.args.size() != rule.parameters.size()) {
        std::vector<std::string> names;
        for (const auto& p : rule.parameters) {
            names.push_back(p.name);
        }
        return fail(fmt::format("{} takes {} ({}), got {}", rule.name,
                                plural(rule.parameters.size(), "argument"), fmt::join(names, ", "),
                                step.args.size()));
    }
    std::vector<hom::PartBinding> bindings;
    for (std::size_t i = 0; i < step.args.size(); ++i) {
        const auto& param = rule.parameters[i];
        auto part = find_argument(x, param.ob, step.args[i]);
        if (!part) {
            return fail(fmt::format("argument {} ({}): no {} named '{}' in the state", i + 1,
                                    param.name, s.ob(param.ob).name, step.args[i]));
        }
        for (std::size_t j = 0; j < bindings.size(); ++j) {
            if (bindings[j].ob == param.ob && bindings[j].codom == *part &&
                bindings[j].dom != param.part) {
                return fail(fmt::format("arguments {} ({}) and {} ({}) name the same part '{}', "
                                        "but a match is injective",
                                        j + 1, rule.parameters[j].name, i + 1, param.name,
                                        step.args[i]));
            }
        }
        bindings.push_back({param.ob, param.part, *part});
    }
    rewrite::MatchOptions opt;
    opt.initial = bindings;
    opt.max_results = 2;
    auto matches = rewrite::find_matches(rule, x, opt);
    if (matches.size() == 1) {
        return std::move(matches[0]);
    }
    if (matches.size() > 1) {
        *ambiguous = true;
        return fail(fmt::format("ambiguous: the arguments leave several matches, e.g. {{{}}} and "
                                "{{{}}}",
                                describe_match(matches[0], rule.L, x),
                                describe_match(matches[1], rule.L, x)));
    }
    // No valid match: either L does not embed (say which part is missing), or every embedding
    // breaks a gluing or application condition (say which).
    auto hopt = monic_options(bindings);
    auto embedding = hom::find_homomorphism(rule.L, x, hopt);
    if (embedding) {
        auto why = rewrite::match_problem(rule, x, *embedding);
        return fail(
            fmt::format("no valid match: {}", why ? *why : std::string("the match is rejected")));
    }
    auto missing = explain_no_embedding(rule.L, x, bindings);
    return fail(fmt::format("no match: {}", missing ? *missing : embedding.error()));
}

} // namespace

Result<ACSetMorphism> resolve_step(const Rule& rule, const ACSet& x, const Step& step) {
    bool ambiguous = false;
    return resolve(rule, x, step, &ambiguous);
}

Result<ACSetMorphism> embed_goal(const ACSet& goal, const ACSet& x) {
    auto opt = monic_options({});
    auto m = hom::find_homomorphism(goal, x, opt);
    if (m) {
        return m;
    }
    auto missing = explain_no_embedding(goal, x);
    return fail(missing ? fmt::format("nothing satisfies {}", *missing) : m.error());
}

Result<ACSetMorphism> embed_goal(const ACSet& goal,
                                 const std::vector<rewrite::ApplicationCondition>& conditions,
                                 const ACSet& x) {
    if (conditions.empty()) {
        return embed_goal(goal, x);
    }
    // The first embedding that meets the conditions; the reason the last one did not, else.
    std::optional<ACSetMorphism> found;
    std::string broken;
    hom::for_each_homomorphism(goal, x, monic_options({}), [&](const ACSetMorphism& m) {
        auto why = rewrite::condition_problem(conditions, goal, x, m);
        if (!why) {
            found = m;
            return false;
        }
        broken = *why;
        return true;
    });
    if (found) {
        return std::move(*found);
    }
    if (broken.empty()) {
        return embed_goal(goal, x);
    }
    return fail(broken);
}

Validation validate_plan(const Problem& problem, const Plan& plan, const ValidateOptions& options) {
    CATPLAN_ASSERT(problem.initial != nullptr && problem.domain != nullptr,
                   "a problem needs an initial state and a domain");
    Validation v;
    if (problem.step_cost) {
        v.cost = 0;
    }
    ACSet x = *problem.initial;
    if (options.keep_states) {
        v.states.push_back(x);
    }
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const Step& step = plan.steps[i];
        auto prefix = fmt::format("step {} {}", i + 1, describe_step(*problem.domain, step));
        const Rule* rule = problem.domain->find_rule(step.action);
        if (rule == nullptr) {
            std::vector<std::string> names;
            for (const auto& r : problem.domain->rules) {
                names.push_back(r->name);
            }
            v.failed_step = i;
            v.reason = fmt::format("{}: unknown action '{}' (domain {} has: {})", prefix,
                                   step.action, problem.domain->name, fmt::join(names, ", "));
            break;
        }
        auto m = resolve(*rule, x, step, &v.ambiguous);
        if (!m) {
            v.failed_step = i;
            v.reason = fmt::format("{}: {}", prefix, m.error());
            break;
        }
        auto cost = step_cost(problem, *rule, step.args);
        if (!cost) {
            v.failed_step = i;
            v.reason = fmt::format("{}: {}", prefix, cost.error());
            break;
        }
        if (v.cost) {
            v.cost = add_cost(*v.cost, *cost);
        }
        // m is resolve_step's: a match find_matches returned for x.
        auto applied = rewrite::rewrite_in_place(*rule, x, *m, rewrite::CheckMatch::No);
        if (!applied) {
            v.failed_step = i;
            v.reason = fmt::format("{}: cannot apply: {}", prefix, applied.error());
            break;
        }
        v.matches.push_back(std::move(*m));
        if (options.keep_states) {
            v.states.push_back(x);
        }
    }
    if (!v.failed_step) {
        if (problem.goal == nullptr) {
            v.goal_reached = true;
        } else {
            auto g = embed_goal(*problem.goal, problem.goal_conditions, x);
            v.goal_reached = g.has_value();
            if (!g) {
                v.reason = fmt::format("goal not reached: {}", g.error());
            }
        }
        v.valid = v.goal_reached;
    }
    v.final_state = std::move(x);
    return v;
}

} // namespace catplan::plan
