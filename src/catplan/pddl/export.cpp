// The domain side of the export: rules as actions (export.hpp says what each construct becomes).

#include "catplan/pddl/export.hpp"

#include "catplan/pddl/detail/export_writer.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>
#include <set>

namespace catplan::pddl::detail {

namespace {

bool in_image(const hom::ACSetMorphism& m, ObId ob, Part p) {
    const auto& c = m.components[ob.index()];
    return std::find(c.begin(), c.end(), p) != c.end();
}

Part preimage(const hom::ACSetMorphism& m, ObId ob, Part p) {
    const auto& c = m.components[ob.index()];
    auto it = std::find(c.begin(), c.end(), p);
    return it == c.end() ? kNoPart : static_cast<Part>(it - c.begin());
}

std::string conjunction(const std::vector<std::string>& items) {
    if (items.size() == 1) {
        return items[0];
    }
    return fmt::format("(and {})", fmt::join(items, " "));
}

/// How many of the thing's parts are in the image of m (a morphism into the thing's state).
std::pair<std::size_t, std::size_t> kept_parts(const Thing& t, const hom::ACSetMorphism& m) {
    std::size_t kept = 0, all = 0;
    for (std::size_t o = 0; o < t.part.size(); ++o) {
        if (t.part[o] != kNoPart) {
            ++all;
            kept += in_image(m, ObId(static_cast<std::uint32_t>(o)), t.part[o]) ? 1 : 0;
        }
    }
    return {kept, all};
}

} // namespace

Writer::Writer(const plan::Domain& d, const plan::Problem* p, Reading r, NameSet n)
    : domain(d), problem(p), rd(std::move(r)), preds(std::move(n)) {}

const std::string& Writer::presence(const std::string& shape) {
    auto it = marker_presence.find(shape);
    if (it == marker_presence.end()) {
        it = marker_presence.emplace(shape, preds.take(pddl_name("marker_" + shape, "p"))).first;
    }
    return it->second;
}

Result<std::string> Writer::atom(const ACSet& x, ObId ob, Part p,
                                 const std::function<TermText(ObId, Part)>& term) {
    const Schema& s = x.schema();
    std::vector<std::string> args, marker_homs, types;
    std::set<std::string> shapes;
    for (HomId h : s.homs_from(ob)) {
        Part q = x.subpart(h, p);
        if (q == kNoPart) {
            return fail(
                fmt::format("not expressible: {}({}) is left open (a fact names its arguments)",
                            s.hom(h).name, x.part_label(ob, p)));
        }
        TermText t = term(s.hom(h).codom, q);
        if (t.text.empty()) {
            marker_homs.push_back(pddl_name(s.hom(h).name, "f"));
            shapes.insert(t.shape);
        } else {
            args.push_back(t.text);
            types.push_back(rd.arg_type(s.hom(h).codom));
        }
    }
    std::string pred = rd.fact_predicate[ob.index()];
    for (AttrId a : s.attrs_from(ob)) {
        const AttrReading& ar = rd.attrs[a.index()];
        if (ar.use != AttrUse::Values) {
            continue;
        }
        const auto& v = x.subpart(a, p);
        if (!v.is_concrete()) {
            return fail(fmt::format("not expressible: {}({}) is not a known value, and the fact's "
                                    "value is part of its predicate",
                                    s.attr(a).name, x.part_label(ob, p)));
        }
        pred += "_" + ar.value_predicate.at(v.to_string());
    }
    if (pred != rd.fact_predicate[ob.index()]) {
        auto it = valued_facts.find(pred);
        if (it == valued_facts.end()) {
            valued_facts.emplace(pred, types);
            preds.take(pred);
        }
        pred = valued_facts.find(pred)->first;
    }
    if (!marker_homs.empty()) {
        std::string key = fmt::format("{}|{}", pred, fmt::join(marker_homs, "|"));
        auto it = marker_facts.find(key);
        if (it == marker_facts.end()) {
            std::string want = fmt::format("{}_{}_marker", pred, fmt::join(marker_homs, "_"));
            it = marker_facts.emplace(key, MarkerFact{preds.take(want), types, {}}).first;
        }
        it->second.shapes.insert(shapes.begin(), shapes.end());
        pred = it->second.predicate;
    }
    return args.empty() ? fmt::format("({})", pred)
                        : fmt::format("({} {})", pred, fmt::join(args, " "));
}

void Writer::attr_facts(const ACSet& x, const Thing& t, const std::string& term,
                        std::vector<std::pair<std::string, bool>>& out) const {
    const Schema& s = x.schema();
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        const auto& info = s.attr(AttrId(i));
        Part p = t.part[info.dom.index()];
        if (p == kNoPart || !x.subpart(AttrId(i), p).is_concrete()) {
            continue;
        }
        const AttrReading& ar = rd.attrs[i];
        const auto& v = x.subpart(AttrId(i), p);
        if (ar.use == AttrUse::Bool) {
            out.emplace_back(fmt::format("({} {})", ar.predicate, term), v.as_bool());
        } else if (ar.use == AttrUse::Values) {
            out.emplace_back(fmt::format("({} {})", ar.value_predicate.at(v.to_string()), term),
                             true);
        }
    }
}

bool Writer::may_coincide(const Thing& a, const Thing& b) const {
    if (a.component != b.component) {
        return false;
    }
    if (!rd.components[a.component].forest) {
        for (std::size_t o = 0; o < a.part.size(); ++o) {
            if (a.part[o] != kNoPart && b.part[o] != kNoPart) {
                return true;
            }
        }
        return false;
    }
    // In a forest a thing has its bottom's ancestors: they coincide when one is below the other.
    auto below = [&](ObId sub, ObId super) {
        for (std::optional<ObId> ob = sub; ob;) {
            if (*ob == super) {
                return true;
            }
            auto up = rd.parent[ob->index()];
            ob = up ? std::optional(rd.schema->hom(*up).codom) : std::nullopt;
        }
        return false;
    };
    return below(a.bottom, b.bottom) || below(b.bottom, a.bottom);
}

Result<bool> Writer::find_marker_shapes() {
    for (const auto& rule : domain.rules) {
        NameSet scratch;
        auto L = find_things(rd, rule->L, {}, scratch, "the precondition of " + rule->name);
        auto R = find_things(rd, rule->R, {}, scratch, "the effect of " + rule->name);
        if (!L || !R) {
            return fail(L ? R.error() : L.error());
        }
        for (const auto& t : L->things) {
            auto [kept, all] = kept_parts(t, rule->l);
            if (kept == 0) {
                marker_shapes.insert(t.shape);
            } else if (kept != all) {
                return fail(fmt::format("not expressible: {} deletes some parts of the thing {} "
                                        "({}) and keeps others",
                                        rule->name, t.name, t.shape));
            }
        }
        for (const auto& t : R->things) {
            auto [kept, all] = kept_parts(t, rule->r);
            if (kept == 0) {
                marker_shapes.insert(t.shape);
            } else if (kept != all) {
                return fail(fmt::format("not expressible: {} creates a part of the thing {} ({}) "
                                        "that it keeps",
                                        rule->name, t.name, t.shape));
            }
        }
    }
    return true;
}

namespace {

/// The rule's things and how they correspond.
Result<RuleThings> rule_things(const Reading& rd, const rewrite::Rule& rule, NameSet& names) {
    NameSet scratch;
    auto L = find_things(rd, rule.L, {}, names, "the precondition of " + rule.name);
    auto R = find_things(rd, rule.R, {}, scratch, "the effect of " + rule.name);
    if (!L || !R) {
        return fail(L ? R.error() : L.error());
    }
    RuleThings rt{std::move(*L), std::move(*R), {}};
    for (auto& t : rt.L.things) {
        t.marker = kept_parts(t, rule.l).first == 0;
    }
    std::vector<bool> used(rt.L.things.size(), false);
    for (auto& t : rt.R.things) {
        std::size_t to = kNone;
        for (std::size_t o = 0; o < t.part.size(); ++o) {
            ObId ob(static_cast<std::uint32_t>(o));
            Part k = t.part[o] == kNoPart ? kNoPart : preimage(rule.r, ob, t.part[o]);
            if (k == kNoPart) {
                continue;
            }
            std::size_t l = rt.L.at(ob, rule.l(ob, k));
            if (to != kNone && to != l) {
                return fail(
                    fmt::format("not expressible: {} glues two things into one", rule.name));
            }
            to = l;
        }
        t.marker = to == kNone;
        if (to != kNone && (used[to] || rt.L.things[to].shape != t.shape)) {
            return fail(fmt::format("not expressible: {} changes which parts the thing {} has",
                                    rule.name, rt.L.things[to].name));
        }
        if (to != kNone) {
            used[to] = true;
        }
        rt.r_to_l.push_back(to);
    }
    return rt;
}

/// The attributes of the thing's parts.
std::vector<AttrId> attrs_of(const ACSet& x, const Thing& t) {
    std::vector<AttrId> out;
    for (std::uint32_t i = 0; i < x.schema().num_attrs(); ++i) {
        if (t.part[x.schema().attr(AttrId(i)).dom.index()] != kNoPart) {
            out.emplace_back(i);
        }
    }
    return out;
}

/// Fails when a marker thing's attributes are read (a deleted marker must match any marker).
Result<bool> check_marker_attrs(const ACSet& x, const Thing& t, const std::string& rule) {
    const Schema& s = x.schema();
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        const auto& info = s.attr(AttrId(i));
        Part p = t.part[info.dom.index()];
        if (p == kNoPart) {
            continue;
        }
        const auto& v = x.subpart(AttrId(i), p);
        if (v.is_concrete() ||
            (v.is_var() && x.var_incident(info.codom, v.var_index()).size() > 1)) {
            return fail(fmt::format("not expressible: {} reads {} of the {} it deletes (a marker: "
                                    "not a PDDL object)",
                                    rule, info.name, t.shape));
        }
    }
    return true;
}

/// The attribute updates of a kept thing: its parts' values in R against L.
Result<bool> attr_updates(const Writer& w, const rewrite::Rule& rule, const Thing& lt,
                          const Thing& rt, const std::string& term, ActionText& a) {
    const Schema& s = rule.L.schema();
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        AttrId at(i);
        const auto& info = s.attr(at);
        const AttrReading& ar = w.rd.attrs[i];
        Part lp = lt.part[info.dom.index()], rp = rt.part[info.dom.index()];
        if (lp == kNoPart || ar.use == AttrUse::Dropped || ar.use == AttrUse::Name) {
            continue;
        }
        const auto &before = rule.L.subpart(at, lp), &now = rule.R.subpart(at, rp);
        if (now.is_unset() || (before.is_concrete() && now.is_concrete() && before == now)) {
            continue;
        }
        if (now.is_var()) {
            Part k = preimage(rule.r, info.dom, rp);
            const auto& kv = k == kNoPart ? now : rule.K.subpart(at, k);
            bool same = before.is_var() && k != kNoPart && kv.is_var() &&
                        rule.l.var(info.codom, kv.var_index()) == before &&
                        rule.r.var(info.codom, kv.var_index()) == now;
            if (same) {
                continue; // kept as it was (the same variable in L, K and R)
            }
            return fail(fmt::format("not expressible: {} sets {}({}) to a value it reads "
                                    "elsewhere or to an unknown",
                                    rule.name, info.name, term));
        }
        if (ar.use == AttrUse::Bool) {
            (now.as_bool() ? a.add : a.del).insert(fmt::format("({} {})", ar.predicate, term));
            continue;
        }
        for (const auto& [v, pred] : ar.value_predicate) {
            (v == now.to_string() ? a.add : a.del).insert(fmt::format("({} {})", pred, term));
        }
    }
    return true;
}

} // namespace

Result<ActionText> Writer::read_rule(const rewrite::Rule& rule) {
    NameSet names;
    auto things = rule_things(rd, rule, names);
    if (!things) {
        return fail(things.error());
    }
    const Things& L = things->L;
    const Things& R = things->R;
    ActionText a;
    a.name = pddl_name(rule.name.substr(0, rule.name.find('~')), "a");
    std::vector<std::string> term(L.things.size());
    auto add_param = [&](std::size_t i) {
        const Thing& t = L.things[i];
        if (t.marker || !term[i].empty()) {
            return;
        }
        term[i] = t.pinned ? t.name : "?" + t.name;
        if (t.pinned) {
            a.constants.insert(t.name + " - " + thing_type(rd, t));
            return;
        }
        a.params.emplace_back(term[i], thing_type(rd, t));
        a.param_parts.emplace_back(t.first, t.part[t.first.index()]);
        a.param_things.push_back(i);
    };
    for (const auto& p : rule.parameters) {
        if (L.at(p.ob, p.part) != Things::kNoThing) { // a fact parameter is in the precondition
            add_param(L.at(p.ob, p.part));
        }
    }
    for (std::size_t i = 0; i < L.things.size(); ++i) {
        add_param(i);
    }
    auto thing_term = [&](std::size_t i) { return TermText{term[i], L.things[i].shape}; };
    auto l_term = [&](ObId ob, Part p) { return thing_term(L.at(ob, p)); };
    auto r_term = [&](ObId ob, Part p) {
        std::size_t i = R.at(ob, p);
        std::size_t l = things->r_to_l[i];
        return l == kNone ? TermText{"", R.things[i].shape} : thing_term(l);
    };
    if (auto ok = rule_facts(rule, l_term, r_term, a); !ok) {
        return fail(ok.error());
    }
    if (auto ok = rule_things_conditions(rule, *things, term, a); !ok) {
        return fail(ok.error());
    }
    if (auto ok = rule_nacs(rule, l_term, a); !ok) {
        return fail(ok.error());
    }
    if (auto ok = rule_cost_terms(rule, L, term, a); !ok) {
        return fail(ok.error());
    }
    for (std::size_t i = 0; i < a.param_things.size(); ++i) {
        for (std::size_t j = i + 1; j < a.param_things.size(); ++j) {
            if (may_coincide(L.things[a.param_things[i]], L.things[a.param_things[j]])) {
                a.inequalities.push_back(
                    fmt::format("{}|{}", a.params[i].first, a.params[j].first));
            }
        }
    }
    return a;
}

Result<bool> Writer::rule_cost_terms(const rewrite::Rule& rule, const Things& L,
                                     const std::vector<std::string>& term, ActionText& a) {
    if (!rule.cost) {
        return true;
    }
    for (const auto& t : rule.cost->terms) {
        std::vector<std::string> args, types;
        for (const auto& arg : t.arguments) {
            if (arg.parameter < 0 && !arg.constant.empty()) {
                auto named = named_cost_argument(rule, L, t.function, arg.constant);
                if (!named) {
                    return fail(named.error());
                }
                a.constants.insert(named->first + " - " + named->second);
                args.push_back(named->first);
                types.push_back(named->second);
                continue;
            }
            std::size_t i = Things::kNoThing;
            if (arg.parameter >= 0) {
                const auto& p = rule.parameters[static_cast<std::size_t>(arg.parameter)];
                i = L.at(p.ob, p.part);
            }
            if (i == Things::kNoThing || term[i].empty()) {
                return fail(fmt::format("not expressible: the cost of {} reads {} of a part "
                                        "that is no parameter of the action",
                                        rule.name, t.function));
            }
            args.push_back(term[i]);
            types.push_back(thing_type(rd, L.things[i]));
        }
        std::string f = pddl_name(t.function, "f");
        functions.emplace(f, types);
        a.cost_terms.push_back(
            fmt::format("({}{}{})", f, args.empty() ? "" : " ", fmt::join(args, " ")));
    }
    return true;
}

Result<std::pair<std::string, std::string>> Writer::named_cost_argument(const rewrite::Rule& rule,
                                                                        const Things& L,
                                                                        const std::string& function,
                                                                        const std::string& name) {
    auto named = [&](const Thing& t) { return !t.marker && t.name == name; };
    for (const Thing& t : L.things) {
        if (t.pinned && named(t)) {
            return std::pair(name, thing_type(rd, t));
        }
    }
    if (problem == nullptr) {
        return fail(fmt::format("not expressible without a problem: the cost of {} reads {} of "
                                "{}, which no parameter names: the type of that constant is "
                                "the problem's (export the domain with a problem)",
                                rule.name, function, name));
    }
    if (!initial_things) {
        NameSet names;
        auto init = find_things(rd, *problem->initial, marker_shapes, names, "the initial state");
        if (!init) {
            return fail(init.error());
        }
        initial_things = std::move(*init);
    }
    for (const Thing& t : initial_things->things) {
        if (named(t)) {
            return std::pair(name, thing_type(rd, t));
        }
    }
    return fail(fmt::format("not expressible: the cost of {} reads {} of {}, which is no object "
                            "of the problem {}",
                            rule.name, function, name, problem->name));
}

std::string Writer::write_functions() const {
    std::string out = "(total-cost) - number";
    for (const auto& [f, types] : functions) {
        out += fmt::format("\n              ({}", f);
        for (std::size_t i = 0; i < types.size(); ++i) {
            out += fmt::format(" ?x{} - {}", i + 1, types[i]);
        }
        out += ") - number";
    }
    return fmt::format("  (:functions {})\n", out);
}

Result<bool> Writer::rule_facts(const rewrite::Rule& rule, const TermFn& l_term,
                                const TermFn& r_term, ActionText& a) {
    bool sets = false;
    for (ObId ob : rd.facts) {
        sets = std::find(rule.relations.begin(), rule.relations.end(), ob) != rule.relations.end();
        for (Part p = 0; p < rule.L.num_parts(ob); ++p) {
            auto f = atom(rule.L, ob, p, l_term);
            if (!f) {
                return fail(f.error());
            }
            a.pos.insert(*f);
            Part k = preimage(rule.l, ob, p);
            if (k == kNoPart) {
                a.del.insert(*f);
                continue;
            }
            auto g = atom(rule.R, ob, rule.r(ob, k), r_term); // a kept fact, maybe redirected
            if (!g) {
                return fail(g.error());
            }
            if (*g != *f) {
                a.del.insert(*f);
                a.add.insert(*g);
                if (!sets) {
                    a.neg.insert(*g);
                }
            }
        }
        for (Part p : rule.created_parts(ob)) {
            auto f = atom(rule.R, ob, p, r_term);
            if (!f) {
                return fail(f.error());
            }
            a.add.insert(*f);
            if (!sets && a.pos.count(*f) == 0) {
                a.neg.insert(*f); // a second equal part is not expressed
                creates_facts_not_sets = true;
            }
        }
    }
    return true;
}

Result<bool> Writer::rule_things_conditions(const rewrite::Rule& rule, const RuleThings& rt,
                                            const std::vector<std::string>& term, ActionText& a) {
    const Things& L = rt.L;
    std::set<std::string> deleted, created;
    for (std::size_t i = 0; i < L.things.size(); ++i) {
        const Thing& t = L.things[i];
        if (t.marker) {
            if (!deleted.insert(t.shape).second) {
                return fail(fmt::format("not expressible: {} deletes two {} things (at most one "
                                        "marker of a shape)",
                                        rule.name, t.shape));
            }
            if (auto ok = check_marker_attrs(rule.L, t, rule.name); !ok) {
                return fail(ok.error());
            }
            continue;
        }
        if (!rd.components[t.component].forest) {
            for (std::size_t o = 0; o < t.part.size(); ++o) {
                if (t.part[o] != kNoPart) {
                    a.pos.insert(fmt::format("({} {})", rd.member_predicate[o], term[i]));
                }
            }
        }
        std::vector<std::pair<std::string, bool>> values;
        attr_facts(rule.L, t, term[i], values);
        for (const auto& [f, v] : values) {
            (v ? a.pos : a.neg).insert(f);
        }
        for (std::uint32_t at = 0; at < rule.L.schema().num_attrs(); ++at) {
            const auto& info = rule.L.schema().attr(AttrId(at));
            Part p = t.part[info.dom.index()];
            if (p != kNoPart && rd.attrs[at].use == AttrUse::Values &&
                rule.L.subpart(AttrId(at), p).is_var() &&
                rule.L.var_incident(info.codom, rule.L.subpart(AttrId(at), p).var_index()).size() >
                    1) {
                return fail(fmt::format("not expressible: {} asks two values of {} to be equal",
                                        rule.name, info.name));
            }
        }
    }
    for (std::size_t i = 0; i < rt.R.things.size(); ++i) {
        const Thing& t = rt.R.things[i];
        if (rt.r_to_l[i] == kNone) {
            for (AttrId at : attrs_of(rule.R, t)) {
                if (rule.R.subpart(at, t.part[rule.R.schema().attr(at).dom.index()])
                        .is_concrete()) {
                    return fail(
                        fmt::format("not expressible: {} creates a {} with a known {} (a new "
                                    "object, which PDDL cannot make; only a marker, whose "
                                    "values are unknown, is expressed)",
                                    rule.name, t.shape, rule.R.schema().attr(at).name));
                }
            }
            if (!created.insert(t.shape).second) {
                return fail(fmt::format("not expressible: {} creates two {} things (at most one "
                                        "marker of a shape)",
                                        rule.name, t.shape));
            }
            continue;
        }
        if (auto ok = attr_updates(*this, rule, L.things[rt.r_to_l[i]], t, term[rt.r_to_l[i]], a);
            !ok) {
            return fail(ok.error());
        }
    }
    for (const auto& shape : deleted) {
        a.pos.insert(fmt::format("({})", presence(shape)));
        a.del.insert(fmt::format("({})", presence(shape)));
        a.deleted_markers.insert(shape);
    }
    for (const auto& shape : created) {
        a.add.insert(fmt::format("({})", presence(shape)));
        if (deleted.count(shape) == 0) {
            a.neg.insert(fmt::format("({})", presence(shape)));
        }
    }
    return true;
}

Result<bool> Writer::rule_nacs(const rewrite::Rule& rule, const TermFn& l_term, ActionText& a) {
    for (const auto& c : rule.conditions) {
        if (!c.negative) {
            return fail(
                fmt::format("not expressible: positive application condition of {}", rule.name));
        }
        const Schema& s = rule.L.schema();
        auto n_term = [&](ObId ob, Part p) {
            Part q = preimage(c.n, ob, p);
            return q == kNoPart ? TermText{"?", ""} : l_term(ob, q);
        };
        std::vector<std::string> extra;
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Part p = 0; p < c.n_state.num_parts(ObId(o)); ++p) {
                if (in_image(c.n, ObId(o), p)) {
                    continue;
                }
                if (rd.entity[o]) {
                    return fail(fmt::format("not expressible: the condition {} of {} needs a new "
                                            "object",
                                            c.name, rule.name));
                }
                auto f = atom(c.n_state, ObId(o), p, n_term);
                if (!f) {
                    return fail(f.error());
                }
                extra.push_back(*f);
            }
        }
        if (extra.size() != 1) {
            return fail(fmt::format("not expressible: the condition {} of {} forbids {} facts "
                                    "together",
                                    c.name, rule.name, extra.size()));
        }
        a.neg.insert(extra[0]);
    }
    return true;
}

Result<bool> Writer::marker_dangling(const std::string& rule, ActionText& a) {
    for (const auto& shape : a.deleted_markers) {
        for (const auto& [key, mf] : marker_facts) {
            if (mf.shapes.count(shape) == 0) {
                continue;
            }
            std::string f = fmt::format("({})", mf.predicate);
            if (!mf.types.empty()) {
                return fail(fmt::format("not expressible: {} deletes the {} marker, which facts "
                                        "({} ...) may refer to; STRIPS cannot ask that none does",
                                        rule, shape, mf.predicate));
            }
            if (a.del.count(f) == 0 || a.add.count(f) != 0) {
                a.neg.insert(f);
            }
        }
    }
    return true;
}

namespace {

/// Whether some rule of the group has one parameter standing for both ?x and ?y (`x=y`).
bool identified(const std::vector<const rewrite::Rule*>& group, std::string_view x,
                std::string_view y) {
    for (const auto* r : group) {
        for (const auto& p : r->parameters) {
            std::string names = "=" + p.name + "=";
            std::string xs = "=" + std::string(x) + "=", ys = "=" + std::string(y) + "=";
            if (names.find(xs) != std::string::npos && names.find(ys) != std::string::npos) {
                return true;
            }
        }
    }
    return false;
}

/// The rules grouped by action name (the text before `~`), in first-appearance order.
std::vector<std::vector<const rewrite::Rule*>> group_rules(const plan::Domain& d) {
    std::vector<std::vector<const rewrite::Rule*>> groups;
    std::map<std::string, std::size_t> index;
    for (const auto& r : d.rules) {
        std::string base = r->name.substr(0, r->name.find('~'));
        auto [it, fresh] = index.emplace(base, groups.size());
        if (fresh) {
            groups.emplace_back();
        }
        groups[it->second].push_back(r.get());
    }
    return groups;
}

/// The variants of one action merged (export.hpp): the finest variants' common preconditions.
ActionText merge(std::vector<ActionText> texts) {
    std::size_t finest = 0;
    for (const auto& t : texts) {
        finest = std::max(finest, t.params.size());
    }
    std::optional<ActionText> merged;
    for (auto& t : texts) {
        if (t.params.size() != finest) {
            continue;
        }
        if (!merged) {
            merged = std::move(t);
            continue;
        }
        auto keep_common = [](std::set<std::string>& a, const std::set<std::string>& b) {
            std::erase_if(a, [&](const std::string& x) { return b.count(x) == 0; });
        };
        keep_common(merged->pos, t.pos);
        keep_common(merged->neg, t.neg);
        merged->add.insert(t.add.begin(), t.add.end());
        merged->del.insert(t.del.begin(), t.del.end());
    }
    return std::move(*merged);
}

} // namespace

Result<std::string> Writer::write_actions(std::vector<Exported::Action>& actions,
                                          std::set<std::string>& constants) {
    std::string out;
    for (const auto& group : group_rules(domain)) {
        std::vector<ActionText> texts;
        for (const auto* r : group) {
            auto t = read_rule(*r);
            if (!t) {
                return fail(t.error());
            }
            if (auto ok = marker_dangling(r->name, *t); !ok) {
                return fail(ok.error());
            }
            constants.insert(t->constants.begin(), t->constants.end());
            texts.push_back(std::move(*t));
        }
        ActionText a = merge(std::move(texts));
        std::vector<std::string> pre(a.pos.begin(), a.pos.end());
        for (const auto& f : a.neg) {
            pre.push_back("(not " + f + ")");
        }
        if (!goal_predicate.empty()) {
            pre.push_back(fmt::format("(not ({}))", goal_predicate));
        }
        for (const auto& pair : a.inequalities) {
            std::string x = pair.substr(0, pair.find('|')), y = pair.substr(pair.find('|') + 1);
            if (!identified(group, x.substr(1), y.substr(1))) {
                pre.push_back(fmt::format("(not (= {} {}))", x, y));
            }
        }
        std::vector<std::string> eff(a.add.begin(), a.add.end());
        for (const auto& f : a.del) {
            if (a.add.count(f) == 0) {
                eff.push_back("(not " + f + ")");
            }
        }
        // The action's cost (its variants share it): a constant and function terms, as
        // :action-costs writes them.
        if (const auto& cost = group.front()->cost; cost && cost->constant != 0) {
            eff.push_back(fmt::format("(increase (total-cost) {})", cost->constant));
        }
        for (const auto& t : a.cost_terms) {
            eff.push_back(fmt::format("(increase (total-cost) {})", t));
        }
        std::string params;
        for (const auto& [v, t] : a.params) {
            params += fmt::format("{}{} - {}", params.empty() ? "" : " ", v, t);
        }
        out += fmt::format("  (:action {}\n    :parameters ({})\n", a.name, params);
        if (!pre.empty()) {
            out += fmt::format("    :precondition {}\n", conjunction(pre));
        }
        out += fmt::format("    :effect {})\n", eff.empty() ? "(and)" : conjunction(eff));
        actions.push_back({a.name, group.size() == 1 ? group[0] : nullptr, a.param_parts});
    }
    return out;
}

std::string Writer::write_types() const {
    std::string out;
    const Schema& s = *rd.schema;
    for (const auto& c : rd.components) {
        if (!c.forest) {
            out += fmt::format(" {} - object", c.type_name);
            continue;
        }
        for (ObId ob : c.obs) {
            if (rd.type_of_ob[ob.index()] == "object") {
                continue;
            }
            auto up = rd.parent[ob.index()];
            out += fmt::format(" {} - {}", rd.type_of_ob[ob.index()],
                               up ? rd.type_of_ob[s.hom(*up).codom.index()] : "object");
        }
    }
    return out;
}

std::string Writer::write_predicates() const {
    const Schema& s = *rd.schema;
    std::string out;
    for (ObId ob : rd.facts) {
        bool valued = std::any_of(s.attrs_from(ob).begin(), s.attrs_from(ob).end(), [&](AttrId a) {
            return rd.attrs[a.index()].use == AttrUse::Values;
        });
        if (valued) {
            continue; // its predicates are valued_facts
        }
        out += "    (" + rd.fact_predicate[ob.index()];
        int i = 1;
        for (HomId h : s.homs_from(ob)) {
            out += fmt::format(" ?x{} - {}", i++, rd.arg_type(s.hom(h).codom));
        }
        out += ")\n";
    }
    for (const auto& [pred, types] : valued_facts) {
        out += "    (" + pred;
        for (std::size_t i = 0; i < types.size(); ++i) {
            out += fmt::format(" ?x{} - {}", i + 1, types[i]);
        }
        out += ")\n";
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!rd.member_predicate[o].empty()) {
            out += fmt::format("    ({} ?x - {})\n", rd.member_predicate[o], rd.arg_type(ObId(o)));
        }
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        const auto& ar = rd.attrs[a];
        const std::string& type = rd.arg_type(s.attr(AttrId(a)).dom);
        if (ar.use == AttrUse::Bool) {
            out += fmt::format("    ({} ?x - {})\n", ar.predicate, type);
        }
        for (const auto& [v, pred] : ar.value_predicate) {
            if (rd.entity[s.attr(AttrId(a)).dom.index()]) {
                out += fmt::format("    ({} ?x - {})\n", pred, type);
            }
        }
    }
    for (const auto& [shape, pred] : marker_presence) {
        out += fmt::format("    ({})\n", pred);
    }
    for (const auto& [key, mf] : marker_facts) {
        out += "    (" + mf.predicate;
        for (std::size_t i = 0; i < mf.types.size(); ++i) {
            out += fmt::format(" ?x{} - {}", i + 1, mf.types[i]);
        }
        out += ")\n";
    }
    if (!goal_predicate.empty()) {
        out += fmt::format("    ({})\n", goal_predicate);
    }
    return out;
}

} // namespace catplan::pddl::detail
