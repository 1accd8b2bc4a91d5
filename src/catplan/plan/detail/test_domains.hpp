#pragma once
// Blocks worlds built in C++ for the plan layer's tests and the planner benchmark (header-only).
//
// Schema Blocks: Block, On (onL, onR : On -> Block), Clear (clearOf), OnTable (tableOf),
// Holding (held), HandEmpty; with `labelled`, Block has an attribute label : Block -> Name, so
// that states tell blocks apart up to isomorphism (without it, only the shape of the towers
// counts). The rules are the STRIPS blocks world: pickup(b), putdown(b), unstack(b, u),
// stack(b, u), each deleting and creating predicate parts and keeping the blocks.

#include "catplan/hom/hom_search.hpp"
#include "catplan/plan/domain.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace catplan::plan::testing {

using acset::Value;
using schema::Schema;

struct BlocksIds {
    ObId block{0}, on{1}, clear{2}, table{3}, holding{4}, hand{5};
    HomId on_l{0}, on_r{1}, clear_of{2}, table_of{3}, held{4};
    AttrId label{0};
    AttrTypeId name{0};
};

inline constexpr BlocksIds kB{};

inline schema::SchemaPtr blocks_schema(bool labelled) {
    auto s = std::make_shared<Schema>(labelled ? "LabelledBlocks" : "Blocks");
    ObId b = s->add_ob("Block"), on = s->add_ob("On"), cl = s->add_ob("Clear"),
         tb = s->add_ob("OnTable"), ho = s->add_ob("Holding");
    s->add_ob("HandEmpty");
    s->add_hom("onL", on, b);
    s->add_hom("onR", on, b);
    s->add_hom("clearOf", cl, b);
    s->add_hom("tableOf", tb, b);
    s->add_hom("held", ho, b);
    if (labelled) {
        auto t = s->add_attr_type("Name", schema::ValueKind::String);
        s->add_attr("label", b, t);
    }
    return s;
}

inline bool is_labelled(const ACSet& x) {
    return x.schema().num_attrs() > 0;
}

/// Adds a block named `name`; its label is the name (labelled schema) or, with `var`, a fresh
/// variable (a rule's block, whose label is whatever the match finds).
inline Part add_block(ACSet& x, const std::string& name, bool var = false) {
    Part p = x.add_part(kB.block, name);
    if (is_labelled(x)) {
        x.set_subpart(kB.label, p, var ? x.add_var(kB.name) : Value::string(name));
    }
    return p;
}

inline Part add_fact(ACSet& x, ObId ob, HomId f, Part b, const std::string& name) {
    Part p = x.add_part(ob, name);
    x.set_subpart(f, p, b);
    return p;
}

inline Part add_on(ACSet& x, Part top, Part below, const std::string& name) {
    Part p = x.add_part(kB.on, name);
    x.set_subpart(kB.on_l, p, top);
    x.set_subpart(kB.on_r, p, below);
    return p;
}

/// The morphism a -> b sending each named part of a to b's part of that name (found by hom
/// search with the names as initial bindings; variables follow the cells).
inline hom::ACSetMorphism by_names(const ACSet& a, const ACSet& b) {
    hom::HomSearchOptions opt;
    for (std::uint32_t o = 0; o < a.schema().num_obs(); ++o) {
        for (Part p = 0; p < a.num_parts(ObId(o)); ++p) {
            auto q = b.find_part(ObId(o), a.part_name(ObId(o), p));
            CATPLAN_ASSERT(q.has_value(), "a part of K has no counterpart");
            opt.bind(ObId(o), p, *q);
        }
    }
    auto m = hom::find_homomorphism(a, b, opt);
    CATPLAN_ASSERT(m.has_value(), "K does not map to L or R by names");
    return *m;
}

/// A rule whose K holds the blocks `params` of L and R (same names), with those as parameters.
inline RulePtr make_rule(const std::string& name, const ACSet& l, const ACSet& r,
                         const std::vector<std::string>& params) {
    auto rule = std::make_shared<Rule>(l.schema_ptr());
    rule->name = name;
    rule->L = l;
    rule->R = r;
    for (const auto& p : params) {
        add_block(rule->K, p, true);
    }
    rule->l = by_names(rule->K, rule->L);
    rule->r = by_names(rule->K, rule->R);
    for (const auto& p : params) {
        rule->parameters.push_back({p, kB.block, *rule->L.find_part(kB.block, p)});
    }
    return rule;
}

inline DomainPtr blocks_domain(bool labelled) {
    auto s = blocks_schema(labelled);
    auto d = std::make_shared<Domain>();
    d->name = "Blocks";
    d->schema = s;
    {
        ACSet l(s), r(s);
        Part b = add_block(l, "b", true);
        add_fact(l, kB.clear, kB.clear_of, b, "cb");
        add_fact(l, kB.table, kB.table_of, b, "tb");
        l.add_part(kB.hand, "he");
        Part rb = add_block(r, "b", true);
        add_fact(r, kB.holding, kB.held, rb, "h");
        d->rules.push_back(make_rule("pickup", l, r, {"b"}));
    }
    {
        ACSet l(s), r(s);
        Part b = add_block(l, "b", true);
        add_fact(l, kB.holding, kB.held, b, "h");
        Part rb = add_block(r, "b", true);
        add_fact(r, kB.clear, kB.clear_of, rb, "cb");
        add_fact(r, kB.table, kB.table_of, rb, "tb");
        r.add_part(kB.hand, "he");
        d->rules.push_back(make_rule("putdown", l, r, {"b"}));
    }
    {
        ACSet l(s), r(s);
        Part b = add_block(l, "b", true), u = add_block(l, "u", true);
        add_on(l, b, u, "o");
        add_fact(l, kB.clear, kB.clear_of, b, "cb");
        l.add_part(kB.hand, "he");
        Part rb = add_block(r, "b", true), ru = add_block(r, "u", true);
        add_fact(r, kB.holding, kB.held, rb, "h");
        add_fact(r, kB.clear, kB.clear_of, ru, "cu");
        d->rules.push_back(make_rule("unstack", l, r, {"b", "u"}));
    }
    {
        ACSet l(s), r(s);
        Part b = add_block(l, "b", true), u = add_block(l, "u", true);
        add_fact(l, kB.holding, kB.held, b, "h");
        add_fact(l, kB.clear, kB.clear_of, u, "cu");
        Part rb = add_block(r, "b", true), ru = add_block(r, "u", true);
        add_on(r, rb, ru, "o");
        add_fact(r, kB.clear, kB.clear_of, rb, "cb");
        r.add_part(kB.hand, "he");
        d->rules.push_back(make_rule("stack", l, r, {"b", "u"}));
    }
    return d;
}

/// Towers of blocks (each listed bottom to top, by index into names), the hand empty unless
/// `holding` names a block (which is then in no tower).
inline ACSet blocks_state(schema::SchemaPtr s, const std::vector<std::string>& names,
                          const std::vector<std::vector<int>>& towers,
                          std::optional<int> holding = std::nullopt) {
    ACSet x(std::move(s));
    std::vector<Part> b;
    for (const auto& n : names) {
        b.push_back(add_block(x, n));
    }
    for (const auto& t : towers) {
        for (std::size_t i = 0; i < t.size(); ++i) {
            if (i == 0) {
                add_fact(x, kB.table, kB.table_of, b[t[i]], "");
            } else {
                add_on(x, b[t[i]], b[t[i - 1]], "");
            }
        }
        if (!t.empty()) {
            add_fact(x, kB.clear, kB.clear_of, b[t.back()], "");
        }
    }
    if (holding) {
        add_fact(x, kB.holding, kB.held, b[*holding], "");
    } else {
        x.add_part(kB.hand);
    }
    return x;
}

/// A goal: the blocks and the On facts of the towers (nothing about the table or the hand).
inline ACSet blocks_goal(schema::SchemaPtr s, const std::vector<std::string>& names,
                         const std::vector<std::vector<int>>& towers) {
    ACSet x(std::move(s));
    std::vector<Part> b;
    for (const auto& n : names) {
        b.push_back(add_block(x, n));
    }
    for (const auto& t : towers) {
        for (std::size_t i = 1; i < t.size(); ++i) {
            add_on(x, b[t[i]], b[t[i - 1]], "");
        }
    }
    return x;
}

inline ProblemPtr blocks_problem(const DomainPtr& d, const std::vector<std::string>& names,
                                 const std::vector<std::vector<int>>& init,
                                 const std::vector<std::vector<int>>& goal) {
    auto p = std::make_shared<Problem>();
    p->name = "P";
    p->domain = d;
    p->initial = std::make_shared<ACSet>(blocks_state(d->schema, names, init));
    p->goal = std::make_shared<ACSet>(blocks_goal(d->schema, names, goal));
    return p;
}

/// Random towers of n blocks (seeded): each block goes on the table or on a random tower top.
inline std::vector<std::vector<int>> random_towers(int n, std::mt19937_64& rng) {
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i) {
        order[i] = i;
    }
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::vector<int>> towers;
    for (int b : order) {
        std::uniform_int_distribution<std::size_t> pick(0, towers.size());
        std::size_t t = pick(rng);
        if (t == towers.size()) {
            towers.push_back({b});
        } else {
            towers[t].push_back(b);
        }
    }
    return towers;
}

inline std::vector<std::string> block_names(int n) {
    std::vector<std::string> names;
    for (int i = 0; i < n; ++i) {
        names.push_back("b" + std::to_string(i + 1));
    }
    return names;
}

/// A seeded blocks world with a gripper: n blocks b1..bn from random towers to random towers.
inline ProblemPtr random_blocks_problem(int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto init = random_towers(n, rng);
    auto goal = random_towers(n, rng);
    return blocks_problem(blocks_domain(true), block_names(n), init, goal);
}

// ---- The paper's ColorBlocksworld (examples/colorblocksworld/colorblocksworld.cp)
// ---------------- Built here because the plan layer may not use the language layer: Block, Empty,
// Gripper, On (on_l, on_r : On -> Block), isEmpty : Empty -> Block, isHolding : Gripper -> Block,
// and the attributes hasColor, isClear, isOnTable of Block. "The hand is empty" is an unnamed
// marker block that isHolding(gripper) and isEmpty(empty) both point at; taking a block deletes
// `empty` and the marker, putting one down creates new ones. The rules are those of the .cp file.

struct PaperIds {
    ObId block{0}, empty{1}, gripper{2}, on{3};
    HomId on_l{0}, on_r{1}, is_empty{2}, is_holding{3};
    AttrId color{0}, clear{1}, table{2};
    AttrTypeId color_t{0}, clear_t{1}, table_t{2};
};

inline constexpr PaperIds kP{};

inline schema::SchemaPtr paper_schema() {
    auto s = std::make_shared<Schema>("ColorBlocksworld");
    ObId b = s->add_ob("Block"), e = s->add_ob("Empty"), g = s->add_ob("Gripper"),
         on = s->add_ob("On");
    s->add_hom("on_l", on, b);
    s->add_hom("on_r", on, b);
    s->add_hom("isEmpty", e, b);
    s->add_hom("isHolding", g, b);
    auto c = s->add_attr_type("Color", schema::ValueKind::String);
    auto cl = s->add_attr_type("Clear", schema::ValueKind::Bool);
    auto t = s->add_attr_type("OnTable", schema::ValueKind::Bool);
    s->add_attr("hasColor", b, c);
    s->add_attr("isClear", b, cl);
    s->add_attr("isOnTable", b, t);
    return s;
}

/// A block whose attributes are the given values, a fresh variable where not given.
inline Part paper_block(ACSet& x, const std::string& name, std::optional<Value> color = {},
                        std::optional<bool> clear = {}, std::optional<bool> table = {}) {
    Part p = x.add_part(kP.block, name);
    x.set_subpart(kP.color, p, color ? *color : x.add_var(kP.color_t));
    x.set_subpart(kP.clear, p, clear ? Value::boolean(*clear) : x.add_var(kP.clear_t));
    x.set_subpart(kP.table, p, table ? Value::boolean(*table) : x.add_var(kP.table_t));
    return p;
}

/// The gripper (named) and, when `empty`, the hand-empty marker: `empty` and an unnamed block.
inline Part paper_hand(ACSet& x, bool empty) {
    Part g = x.add_part(kP.gripper, "gripper");
    if (empty) {
        Part m = paper_block(x, "");
        x.set_subpart(kP.is_empty, x.add_part(kP.empty, "empty"), m);
        x.set_subpart(kP.is_holding, g, m);
    }
    return g;
}

inline Part paper_on(ACSet& x, Part top, Part below, const std::string& name) {
    Part p = x.add_part(kP.on, name);
    x.set_subpart(kP.on_l, p, top);
    x.set_subpart(kP.on_r, p, below);
    return p;
}

/// A rule of the paper's domain: K holds the gripper (its hom unset: the rule redirects it) and
/// the blocks `params`, each attribute a variable; l and r follow the names.
inline RulePtr paper_rule(const std::string& name, const ACSet& l, const ACSet& r,
                          const std::vector<std::string>& params) {
    auto rule = std::make_shared<Rule>(l.schema_ptr());
    rule->name = name;
    rule->L = l;
    rule->R = r;
    rule->K.add_part(kP.gripper, "gripper");
    for (const auto& p : params) {
        paper_block(rule->K, p);
    }
    rule->l = by_names(rule->K, rule->L);
    rule->r = by_names(rule->K, rule->R);
    for (const auto& p : params) {
        rule->parameters.push_back({p, kP.block, *rule->L.find_part(kP.block, p)});
    }
    return rule;
}

inline DomainPtr paper_domain() {
    auto s = paper_schema();
    auto d = std::make_shared<Domain>();
    d->name = "Blocksworld";
    d->schema = s;
    {
        ACSet l(s), r(s);
        paper_hand(l, true);
        Part b = paper_block(l, "block", {}, true), u = paper_block(l, "underblock");
        paper_on(l, b, u, "o");
        Part g = paper_hand(r, false);
        Part rb = paper_block(r, "block");
        paper_block(r, "underblock", {}, true);
        r.set_subpart(kP.is_holding, g, rb);
        d->rules.push_back(paper_rule("unstack", l, r, {"block", "underblock"}));
    }
    {
        ACSet l(s), r(s);
        Part g = paper_hand(l, false);
        Part b = paper_block(l, "block");
        paper_block(l, "underblock", {}, true);
        l.set_subpart(kP.is_holding, g, b);
        paper_hand(r, true);
        Part rb = paper_block(r, "block"), ru = paper_block(r, "underblock", {}, false);
        paper_on(r, rb, ru, "o");
        d->rules.push_back(paper_rule("stack", l, r, {"block", "underblock"}));
    }
    {
        ACSet l(s), r(s);
        paper_hand(l, true);
        paper_block(l, "block", {}, true, true);
        Part g = paper_hand(r, false);
        Part rb = paper_block(r, "block", {}, {}, false);
        r.set_subpart(kP.is_holding, g, rb);
        d->rules.push_back(paper_rule("pickup", l, r, {"block"}));
    }
    {
        ACSet l(s), r(s);
        Part g = paper_hand(l, false);
        l.set_subpart(kP.is_holding, g, paper_block(l, "block"));
        paper_hand(r, true);
        paper_block(r, "block", {}, true, true);
        d->rules.push_back(paper_rule("putdown", l, r, {"block"}));
    }
    return d;
}

/// The case study: towers E on D on C, and A, B, F on the table; the goal a tower coloured,
/// from top to bottom, purple, green, red, purple, yellow.
inline ProblemPtr paper_case_study() {
    auto d = paper_domain();
    auto p = std::make_shared<Problem>();
    p->name = "CaseStudy";
    p->domain = d;
    ACSet x(d->schema);
    paper_hand(x, true);
    auto str = [](const char* c) { return Value::string(c); };
    Part a = paper_block(x, "A", str("green"), true, true);
    Part b = paper_block(x, "B", str("red"), true, true);
    Part c = paper_block(x, "C", str("yellow"), false, true);
    Part dd = paper_block(x, "D", str("purple"), false, false);
    Part e = paper_block(x, "E", str("purple"), true, false);
    paper_block(x, "F", str("blue"), true, true);
    (void)a;
    (void)b;
    paper_on(x, e, dd, "x1");
    paper_on(x, dd, c, "x2");
    p->initial = std::make_shared<ACSet>(std::move(x));
    ACSet g(d->schema);
    std::vector<Part> t;
    for (const char* col : {"purple", "green", "red", "purple", "yellow"}) {
        t.push_back(paper_block(g, "", str(col)));
    }
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
        paper_on(g, t[i], t[i + 1], "");
    }
    p->goal = std::make_shared<ACSet>(std::move(g));
    return p;
}

} // namespace catplan::plan::testing
