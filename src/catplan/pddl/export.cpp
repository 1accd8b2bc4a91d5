#include "catplan/pddl/export.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <set>

namespace catplan::pddl {

namespace {

using acset::ACSet;
using schema::Schema;

/// How the schema reads as PDDL (export.hpp).
struct Reading {
    std::vector<bool> entity;                 // by object
    std::vector<std::optional<HomId>> parent; // the is-a hom of an entity type
    std::vector<std::vector<HomId>> children; // is-a homs into an entity type
    std::vector<AttrId> bool_attrs, name_attrs;
    std::vector<std::string> dropped; // attributes left out
    std::vector<ObId> predicates;
};

Result<Reading> read_schema(const Schema& s) {
    Reading r;
    r.entity.assign(s.num_obs(), false);
    r.parent.resize(s.num_obs());
    r.children.resize(s.num_obs());
    for (std::uint32_t f = 0; f < s.num_homs(); ++f) {
        r.entity[s.hom(HomId(f)).codom.index()] = true;
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        r.entity[s.attr(AttrId(a)).dom.index()] = true;
    }
    for (std::uint32_t f = 0; f < s.num_homs(); ++f) {
        const auto& h = s.hom(HomId(f));
        if (!r.entity[h.dom.index()]) {
            continue;
        }
        if (r.parent[h.dom.index()]) {
            return fail(fmt::format("not expressible: '{}' has two homs to entity types ({} and "
                                    "{}); PDDL types form a tree",
                                    s.ob(h.dom).name, s.hom(*r.parent[h.dom.index()]).name,
                                    h.name));
        }
        r.parent[h.dom.index()] = HomId(f);
        r.children[h.codom.index()].push_back(HomId(f));
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!r.entity[o]) {
            r.predicates.push_back(ObId(o));
        }
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        const auto& info = s.attr(AttrId(a));
        const auto& type = s.attr_type(info.codom);
        if (type.kind == schema::ValueKind::Bool) {
            r.bool_attrs.push_back(AttrId(a));
        } else if (type.name == "Name") {
            r.name_attrs.push_back(AttrId(a));
        } else {
            r.dropped.push_back(fmt::format("{} ({})", info.name, type.name));
        }
    }
    return r;
}

/// Names PDDL accepts: letters, digits, '-' and '_', starting with a letter.
std::string pddl_name(std::string_view s, std::string_view fallback) {
    std::string out;
    for (char c : s) {
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    }
    if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) {
        out = std::string(fallback) + out;
    }
    return out;
}

/// Terms and facts of one state read as PDDL.
class StateReader {
public:
    StateReader(const Reading& r, const ACSet& x, bool variables)
        : r_(r), x_(x), vars_(variables) {}

    /// The most specific part below p (the entity it is a part of).
    std::pair<ObId, Part> entity_of(ObId ob, Part p) const {
        for (HomId h : r_.children[ob.index()]) {
            auto below = x_.incident(h, p);
            if (!below.empty()) {
                return entity_of(x_.schema().hom(h).dom, below[0]);
            }
        }
        return {ob, p};
    }

    /// The name the entity's parts carry, if concrete.
    std::optional<std::string> pinned(ObId ob, Part p) const {
        for (;;) {
            for (AttrId a : r_.name_attrs) {
                if (x_.schema().attr(a).dom == ob && x_.subpart(a, p).is_concrete()) {
                    return std::string(x_.subpart(a, p).as_string());
                }
            }
            auto up = r_.parent[ob.index()];
            if (!up) {
                return std::nullopt;
            }
            p = x_.subpart(*up, p);
            ob = x_.schema().hom(*up).codom;
            if (p == kNoPart) {
                return std::nullopt;
            }
        }
    }

    /// `?x` for a rule's part, `a` for an object or a pinned part.
    std::string term(ObId ob, Part p) const {
        auto [eob, ep] = entity_of(ob, p);
        if (auto name = pinned(eob, ep)) {
            return pddl_name(*name, "o");
        }
        std::string n =
            pddl_name(x_.part_name(eob, ep),
                      fmt::format("{}{}-", pddl_name(x_.schema().ob(eob).name, "t"), ep + 1));
        return vars_ ? "?" + n : n;
    }

    /// Every entity (most specific part) of the state, in object then part order.
    std::vector<std::pair<ObId, Part>> entities() const {
        std::vector<std::pair<ObId, Part>> out;
        for (std::uint32_t o = 0; o < x_.schema().num_obs(); ++o) {
            for (Part p = 0; p < x_.num_parts(ObId(o)) && r_.entity[o]; ++p) {
                if (entity_of(ObId(o), p) == std::pair{ObId(o), p}) {
                    out.emplace_back(ObId(o), p);
                }
            }
        }
        return out;
    }

    /// `(on ?x ?y)` for a fact part; fails on an unset hom.
    Result<std::string> fact(ObId ob, Part p) const {
        const Schema& s = x_.schema();
        std::string out = "(" + pddl_name(s.ob(ob).name, "p");
        for (HomId h : s.homs_from(ob)) {
            Part q = x_.subpart(h, p);
            if (q == kNoPart) {
                return fail(fmt::format("not expressible: {}({}) is unset", s.hom(h).name,
                                        x_.part_label(ob, p)));
            }
            out += " " + term(s.hom(h).codom, q);
        }
        return out + ")";
    }

    /// Bool attribute values of an entity part (and its ancestors' parts): (fact, value).
    std::vector<std::pair<std::string, bool>> bools(ObId ob, Part p) const {
        std::vector<std::pair<std::string, bool>> out;
        for (AttrId a : r_.bool_attrs) {
            const auto& info = x_.schema().attr(a);
            if (info.dom == ob && x_.subpart(a, p).is_concrete()) {
                out.emplace_back(fmt::format("({} {})", pddl_name(info.name, "p"), term(ob, p)),
                                 x_.subpart(a, p).as_bool());
            }
        }
        return out;
    }

private:
    const Reading& r_;
    const ACSet& x_;
    bool vars_;
};

/// One rule read as an action.
struct ActionText {
    std::string name;
    std::vector<std::pair<std::string, std::string>> params; // ?x, type
    std::set<std::string> pos, neg, add, del;
    std::set<std::string> constants; // "c - type"
};

bool in_image(const hom::ACSetMorphism& m, ObId ob, Part p) {
    const auto& c = m.components[ob.index()];
    return std::find(c.begin(), c.end(), p) != c.end();
}

Part preimage(const hom::ACSetMorphism& m, ObId ob, Part p) {
    const auto& c = m.components[ob.index()];
    auto it = std::find(c.begin(), c.end(), p);
    return it == c.end() ? kNoPart : static_cast<Part>(it - c.begin());
}

Result<ActionText> read_rule(const Reading& rd, const rewrite::Rule& rule) {
    const Schema& s = rule.L.schema();
    StateReader L(rd, rule.L, true);
    ActionText a;
    a.name = pddl_name(rule.name.substr(0, rule.name.find('~')), "a");
    std::set<std::pair<ObId, Part>> seen;
    auto add_param = [&](ObId ob, Part p) {
        auto e = L.entity_of(ob, p);
        if (seen.insert(e).second) {
            std::string t = L.term(e.first, e.second);
            std::string type = pddl_name(s.ob(e.first).name, "t");
            if (t[0] == '?') {
                a.params.emplace_back(t, type);
            } else {
                a.constants.insert(t + " - " + type);
            }
        }
    };
    for (const auto& p : rule.parameters) {
        add_param(p.ob, p.part);
    }
    for (auto [ob, p] : L.entities()) {
        add_param(ob, p);
    }
    for (ObId ob : rd.predicates) {
        for (Part p = 0; p < rule.L.num_parts(ob); ++p) {
            auto f = L.fact(ob, p);
            if (!f) {
                return fail(f.error());
            }
            a.pos.insert(*f);
            if (!in_image(rule.l, ob, p)) {
                a.del.insert(*f);
            }
        }
    }
    for (auto [ob, p] : L.entities()) {
        for (auto [f, v] : L.bools(ob, p)) {
            (v ? a.pos : a.neg).insert(f);
        }
    }
    // R's parts, read through K in L's terms: created facts and changed Bool values.
    StateReader R(rd, rule.R, true);
    for (ObId ob : rd.predicates) {
        for (Part p = 0; p < rule.R.num_parts(ob); ++p) {
            if (in_image(rule.r, ob, p)) {
                continue;
            }
            std::string f = "(" + pddl_name(s.ob(ob).name, "p");
            for (HomId h : s.homs_from(ob)) {
                ObId to = s.hom(h).codom;
                Part k = preimage(rule.r, to, rule.R.subpart(h, p));
                if (k == kNoPart) {
                    return fail(fmt::format("not expressible: {} creates an object", rule.name));
                }
                f += " " + L.term(to, rule.l(to, k));
            }
            a.add.insert(f + ")");
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part k = 0; k < rule.K.num_parts(ObId(o)) && rd.entity[o]; ++k) {
            Part lp = rule.l(ObId(o), k), rp = rule.r(ObId(o), k);
            for (AttrId at : rd.bool_attrs) {
                if (s.attr(at).dom != ObId(o) || !rule.R.subpart(at, rp).is_concrete()) {
                    continue;
                }
                bool now = rule.R.subpart(at, rp).as_bool();
                const auto& before = rule.L.subpart(at, lp);
                if (before.is_concrete() && before.as_bool() == now) {
                    continue;
                }
                auto f =
                    fmt::format("({} {})", pddl_name(s.attr(at).name, "p"), L.term(ObId(o), lp));
                (now ? a.add : a.del).insert(f);
            }
        }
    }
    for (const auto& c : rule.conditions) {
        if (!c.negative) {
            return fail(
                fmt::format("not expressible: positive application condition of {}", rule.name));
        }
        StateReader N(rd, c.n_state, true);
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
                auto f = N.fact(ObId(o), p);
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
    return a;
}

bool comparable(const Schema& s, const Reading& rd, const std::string& a, const std::string& b) {
    auto is_below = [&](std::string_view sub, std::string_view super) {
        auto ob = s.find_ob(sub);
        while (ob) {
            if (pddl_name(s.ob(*ob).name, "t") == super) {
                return true;
            }
            auto up = rd.parent[ob->index()];
            ob = up ? std::optional(s.hom(*up).codom) : std::nullopt;
        }
        return false;
    };
    return is_below(a, b) || is_below(b, a);
}

/// Whether some rule of the group has one parameter standing for both ?x and ?y (`x=y`).
bool identified(const std::vector<const rewrite::Rule*>& group, std::string_view x,
                std::string_view y) {
    for (const auto* r : group) {
        for (const auto& p : r->parameters) {
            std::string names = "=" + p.name + "=";
            if (names.find("=" + std::string(x) + "=") != std::string::npos &&
                names.find("=" + std::string(y) + "=") != std::string::npos) {
                return true;
            }
        }
    }
    return false;
}

std::string conjunction(const std::vector<std::string>& items) {
    if (items.size() == 1) {
        return items[0];
    }
    return fmt::format("(and {})", fmt::join(items, " "));
}

/// One action from a group of variants (export.hpp).
Result<std::string> write_action(const Schema& s, const Reading& rd,
                                 const std::vector<const rewrite::Rule*>& group,
                                 std::set<std::string>& constants) {
    std::vector<ActionText> texts;
    for (const auto* r : group) {
        auto t = read_rule(rd, *r);
        if (!t) {
            return fail(t.error());
        }
        constants.insert(t->constants.begin(), t->constants.end());
        texts.push_back(std::move(*t));
    }
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
            merged = t;
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
    const ActionText& a = *merged;
    std::vector<std::string> pre(a.pos.begin(), a.pos.end());
    for (const auto& f : a.neg) {
        pre.push_back("(not " + f + ")");
    }
    for (std::size_t i = 0; i < a.params.size(); ++i) {
        for (std::size_t j = i + 1; j < a.params.size(); ++j) {
            const auto &p = a.params[i], &q = a.params[j];
            if (comparable(s, rd, p.second, q.second) &&
                !identified(group, p.first.substr(1), q.first.substr(1))) {
                pre.push_back(fmt::format("(not (= {} {}))", p.first, q.first));
            }
        }
    }
    std::vector<std::string> eff(a.add.begin(), a.add.end());
    for (const auto& f : a.del) {
        eff.push_back("(not " + f + ")");
    }
    // The action's cost (its variants share it): a constant, as :action-costs writes it.
    if (const auto& cost = group.front()->cost; cost && cost->constant != 0) {
        eff.push_back(fmt::format("(increase (total-cost) {})", cost->constant));
    }
    std::string params;
    for (const auto& [v, t] : a.params) {
        params += fmt::format("{}{} - {}", params.empty() ? "" : " ", v, t);
    }
    std::string out = fmt::format("  (:action {}\n    :parameters ({})\n", a.name, params);
    if (!pre.empty()) {
        out += fmt::format("    :precondition {}\n", conjunction(pre));
    }
    return out + fmt::format("    :effect {})\n", eff.empty() ? "(and)" : conjunction(eff));
}

std::string type_name(const Schema& s, ObId ob) {
    return pddl_name(s.ob(ob).name, "t");
}

std::string write_types(const Schema& s, const Reading& rd) {
    std::string out;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!rd.entity[o] || type_name(s, ObId(o)) == "object") {
            continue;
        }
        auto up = rd.parent[o];
        out += fmt::format(" {} - {}", type_name(s, ObId(o)),
                           up ? type_name(s, s.hom(*up).codom) : "object");
    }
    return out;
}

std::string write_predicates(const Schema& s, const Reading& rd) {
    std::string out;
    for (ObId ob : rd.predicates) {
        out += "    (" + pddl_name(s.ob(ob).name, "p");
        int i = 1;
        for (HomId h : s.homs_from(ob)) {
            out += fmt::format(" ?x{} - {}", i++, type_name(s, s.hom(h).codom));
        }
        out += ")\n";
    }
    for (AttrId a : rd.bool_attrs) {
        out += fmt::format("    ({} ?x - {})\n", pddl_name(s.attr(a).name, "p"),
                           type_name(s, s.attr(a).dom));
    }
    return out;
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

/// The facts of a state as PDDL atoms (Bool attributes true as facts, false left out unless
/// `negatives`, then written negated).
Result<std::vector<std::string>> state_facts(const Reading& rd, const ACSet& x, bool negatives) {
    StateReader sr(rd, x, false);
    std::vector<std::string> out;
    for (ObId ob : rd.predicates) {
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            auto f = sr.fact(ob, p);
            if (!f) {
                return fail(f.error());
            }
            out.push_back(*f);
        }
    }
    for (auto [ob, p] : sr.entities()) {
        for (auto [f, v] : sr.bools(ob, p)) {
            if (v || negatives) {
                out.push_back(v ? f : "(not " + f + ")");
            }
        }
    }
    return out;
}

} // namespace

Result<std::string> export_domain(const plan::Domain& domain) {
    const Schema& s = *domain.schema;
    auto rd = read_schema(s);
    if (!rd) {
        return fail(rd.error());
    }
    std::string actions;
    std::set<std::string> constants;
    bool costs = false;
    for (const auto& group : group_rules(domain)) {
        if (const auto& c = group.front()->cost; c && !c->depends_on.empty()) {
            return fail(fmt::format("not expressible by catplan's export: the cost of {} is {}, "
                                    "a value each problem gives, which the export does not write",
                                    group.front()->name, c->depends_on));
        }
        costs = costs || group.front()->cost.has_value();
        auto a = write_action(s, *rd, group, constants);
        if (!a) {
            return fail(a.error());
        }
        actions += *a;
    }
    std::string out = fmt::format("; Exported by catplan from the domain {}.\n", domain.name);
    if (!rd->dropped.empty()) {
        out += fmt::format("; Not expressible, left out: attributes {}.\n",
                           fmt::join(rd->dropped, ", "));
    }
    out += fmt::format("(define (domain {})\n", pddl_name(domain.name, "d"));
    out += fmt::format("  (:requirements :strips :typing :negative-preconditions :equality{})\n",
                       costs ? " :action-costs" : "");
    out += fmt::format("  (:types{})\n", write_types(s, *rd));
    if (!constants.empty()) {
        out += fmt::format("  (:constants {})\n", fmt::join(constants, " "));
    }
    out += "  (:predicates\n" + write_predicates(s, *rd) + "  )\n";
    out += costs ? "  (:functions (total-cost) - number)\n" : "";
    out += actions + ")\n";
    return out;
}

Result<std::string> export_problem(const plan::Problem& problem) {
    if (!problem.goal_conditions.empty()) {
        return fail(fmt::format("not expressible by catplan's export: the goal's condition {} "
                                "(a negative goal), which the export does not write",
                                problem.goal_conditions.front().name));
    }
    const Schema& s = *problem.domain->schema;
    auto rd = read_schema(s);
    if (!rd) {
        return fail(rd.error());
    }
    std::set<std::string> constants;
    for (const auto& group : group_rules(*problem.domain)) {
        auto a = write_action(s, *rd, group, constants);
        if (!a) {
            return fail(a.error());
        }
    }
    StateReader init(*rd, *problem.initial, false);
    std::vector<std::string> objects;
    std::set<std::string> names;
    for (auto [ob, p] : init.entities()) {
        std::string n = init.term(ob, p);
        names.insert(n);
        std::string decl = n + " - " + type_name(s, ob);
        if (constants.count(decl) == 0) {
            objects.push_back(decl);
        }
    }
    auto facts = state_facts(*rd, *problem.initial, false);
    if (!facts) {
        return fail(facts.error());
    }
    StateReader goal(*rd, *problem.goal, false);
    for (auto [ob, p] : goal.entities()) {
        if (names.count(goal.term(ob, p)) == 0) {
            return fail(fmt::format("not expressible: the goal's {} names no object of the "
                                    "initial state (PDDL goals name objects)",
                                    problem.goal->part_label(ob, p)));
        }
    }
    auto goals = state_facts(*rd, *problem.goal, true);
    if (!goals) {
        return fail(goals.error());
    }
    // catplan goals are patterns (any parts that fit); PDDL goals name objects, so a goal part is
    // read as the initial object of the same name (exact for imported goals, which pin names).
    std::string out = fmt::format("; Exported by catplan from the problem {}; goal parts name the "
                                  "initial state's objects.\n",
                                  problem.name);
    out += fmt::format("(define (problem {})\n  (:domain {})\n", pddl_name(problem.name, "p"),
                       pddl_name(problem.domain->name, "d"));
    out += fmt::format("  (:objects {})\n", fmt::join(objects, " "));
    bool costs = std::any_of(problem.domain->rules.begin(), problem.domain->rules.end(),
                             [](const auto& r) { return r->cost.has_value(); });
    if (costs) {
        facts->emplace_back("(= (total-cost) 0)");
    }
    out += fmt::format("  (:init {})\n", fmt::join(*facts, "\n         "));
    out += fmt::format("  (:goal {}){}\n", goals->empty() ? "(and)" : conjunction(*goals),
                       costs ? "\n  (:metric minimize (total-cost)))" : ")");
    return out;
}

} // namespace catplan::pddl
