#include "catplan/acset/printer.hpp"
#include "catplan/colimit/colimit.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"
#include "catplan/rewrite/detail/shape.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <gtest/gtest.h>

#include <random>

namespace catplan::rewrite {
namespace {

struct Graphs {
    std::shared_ptr<schema::Schema> s = std::make_shared<schema::Schema>("WeightedGraph");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId tgt = s->add_hom("tgt", e, v);
    AttrTypeId weight_t = s->add_attr_type("Weight", schema::ValueKind::Int);
    AttrId weight = s->add_attr("weight", e, weight_t);

    // Catlab's `@acset Graph begin V=n; E=...; src=[...]; tgt=[...] end` (1-based ids).
    ACSet graph(std::size_t nv, const std::vector<Part>& srcs,
                const std::vector<Part>& tgts) const {
        ACSet g(s);
        g.add_parts(v, nv);
        for (std::size_t i = 0; i < srcs.size(); ++i) {
            Part ed = g.add_part(e);
            g.set_subpart(src, ed, srcs[i] - 1);
            g.set_subpart(tgt, ed, tgts[i] - 1);
        }
        return g;
    }

    ACSetMorphism map(std::vector<Part> vs, std::vector<Part> es,
                      std::vector<Value> vars = {}) const {
        ACSetMorphism f;
        for (auto& p : vs) {
            --p;
        }
        for (auto& p : es) {
            --p;
        }
        f.components = {std::move(vs), std::move(es)};
        f.var_components = {std::move(vars)};
        return f;
    }

    Rule rule(ACSet l_state, ACSet k_state, ACSet r_state, ACSetMorphism l, ACSetMorphism r) const {
        Rule rl(s);
        rl.L = std::move(l_state);
        rl.K = std::move(k_state);
        rl.R = std::move(r_state);
        rl.l = std::move(l);
        rl.r = std::move(r);
        return rl;
    }
};

// reference §4.3: `is_isomorphic(span_w_arrow, rewrite_match(Rule(L, R), m))` (add a reverse edge).
TEST(DPO, AddsAReverseEdge) {
    Graphs g;
    ACSet i2 = g.graph(2, {}, {});
    ACSet arr = g.graph(2, {1}, {2});
    ACSet biarr = g.graph(2, {1, 2}, {2, 1});
    ACSet span = g.graph(3, {2, 2}, {1, 3});
    ACSet span_w_arrow = g.graph(3, {1, 1, 2}, {2, 3, 1});
    Rule rule = g.rule(arr, i2, biarr, g.map({1, 2}, {}), g.map({1, 2}, {}));
    ASSERT_TRUE(check_rule(rule).empty());
    auto m = g.map({2, 1}, {1});
    auto y = rewrite(rule, span, m);
    ASSERT_TRUE(y.has_value()) << y.error();
    EXPECT_TRUE(hom::is_isomorphic(span_w_arrow, y->result));
    ACSet in_place = span;
    ASSERT_TRUE(rewrite_in_place(rule, in_place, m).has_value());
    EXPECT_TRUE(hom::is_isomorphic(span_w_arrow, in_place));
    // The rule keeps its shape; a copy computes its own, about itself.
    EXPECT_EQ(&rule.shape().rule, &rule);
    Rule copy = rule;
    EXPECT_EQ(&copy.shape().rule, &copy);
    ACSet again = span;
    ASSERT_TRUE(rewrite_in_place(copy, again, m).has_value());
    EXPECT_TRUE(hom::is_isomorphic(span_w_arrow, again));
}

// reference §4.3: a non-monic match deletes one loop of two.
TEST(DPO, DeletesALoopThroughANonMonicMatch) {
    Graphs g;
    ACSet i2 = g.graph(2, {}, {});
    ACSet arr = g.graph(2, {1}, {2});
    ACSet two_loops = g.graph(2, {1, 2}, {1, 2});
    ACSet one_loop = g.graph(2, {2}, {2});
    Rule rule = g.rule(arr, i2, i2, g.map({1, 2}, {}), g.map({1, 2}, {}));
    auto m = g.map({1, 1}, {1});
    auto y = rewrite(rule, two_loops, m);
    ASSERT_TRUE(y.has_value()) << y.error();
    EXPECT_TRUE(hom::is_isomorphic(one_loop, y->result));
    EXPECT_FALSE(match_problem(rule, two_loops, m, /*monic=*/false));
    EXPECT_EQ(*match_problem(rule, two_loops, m, /*monic=*/true), "the match is not monic");
}

// reference §4.3: two weighted edges merged into one whose weight is their sum, exact result.
TEST(DPO, ComputesAnAttributeWithAnExpression) {
    Graphs g;
    ACSet l_state = g.graph(2, {1, 1}, {2, 2});
    l_state.set_subpart(g.weight, 0, l_state.add_var(g.weight_t));
    l_state.set_subpart(g.weight, 1, l_state.add_var(g.weight_t));
    ACSet i_state = g.graph(2, {}, {});
    ACSet r_state = g.graph(2, {1}, {2});
    r_state.set_subpart(g.weight, 0, r_state.add_var(g.weight_t));
    auto l = hom::find_homomorphism(i_state, l_state,
                                    hom::HomSearchOptions().bind(g.v, 0, 0).bind(g.v, 1, 1));
    auto r = hom::find_homomorphism(i_state, r_state,
                                    hom::HomSearchOptions().bind(g.v, 0, 0).bind(g.v, 1, 1));
    ASSERT_TRUE(l && r);
    Rule rule = g.rule(l_state, i_state, r_state, *l, *r);
    AttrExpr sum{AttrExpr::Op::Add, {}, {}, 0, {}, {}};
    sum.args.push_back({AttrExpr::Op::Input, {}, g.weight_t, 0, {}, {}});
    sum.args.push_back({AttrExpr::Op::Input, {}, g.weight_t, 1, {}, {}});
    rule.exprs = {{sum}};
    ASSERT_TRUE(check_rule(rule).empty());

    ACSet state = g.graph(1, {1, 1, 1}, {1, 1, 1});
    for (Part i = 0; i < 3; ++i) {
        state.set_subpart(g.weight, i, Value::integer(std::array{10, 20, 100}[i]));
    }
    MatchOptions opt;
    opt.monic = false;
    opt.monic_objects = {g.e};
    auto matches = find_matches(rule, state, opt);
    ASSERT_FALSE(matches.empty());
    auto y = rewrite(rule, state, matches[0]);
    ASSERT_TRUE(y.has_value()) << y.error();
    ACSet expected = g.graph(1, {1, 1}, {1, 1});
    expected.set_subpart(g.weight, 0, Value::integer(30));
    expected.set_subpart(g.weight, 1, Value::integer(100));
    EXPECT_EQ(y->result, expected);

    // freevar=true in Catlab: without the expression the new weight is an unknown.
    rule.exprs.clear();
    auto z = rewrite(rule, state, matches[0]);
    ASSERT_TRUE(z.has_value());
    ACSet expected_var = g.graph(1, {1, 1}, {1, 1});
    expected_var.set_subpart(g.weight, 0, expected_var.add_var(g.weight_t));
    expected_var.set_subpart(g.weight, 1, Value::integer(100));
    EXPECT_EQ(z->result, expected_var);
}

// reference §4.4: PAC "at least two loops" and NAC "at least four loops" on a vertex match the
// vertices with two or three loops of two ⊕ three ⊕ two ⊕ four ⊕ five ⊕ one: 3 matches.
TEST(ApplicationConditions, PositiveAndNegativeConditionsTogether) {
    Graphs g;
    auto loops = [&](std::size_t n) {
        return g.graph(1, std::vector<Part>(n, 1), std::vector<Part>(n, 1));
    };
    ACSet state(g.s);
    for (std::size_t n : {2, 3, 2, 4, 5, 1}) {
        Part vtx = state.add_part(g.v);
        for (std::size_t i = 0; i < n; ++i) {
            Part ed = state.add_part(g.e);
            state.set_subpart(g.src, ed, vtx);
            state.set_subpart(g.tgt, ed, vtx);
        }
    }
    ACSet one = g.graph(1, {}, {});
    Rule rule = g.rule(one, one, one, g.map({1}, {}), g.map({1}, {}));
    rule.conditions.push_back({"two loops", false, loops(2), g.map({1}, {}), {}});
    rule.conditions.push_back({"four loops", true, loops(4), g.map({1}, {}), {}});
    auto matches = find_matches(rule, state);
    ASSERT_EQ(matches.size(), 3u);
    EXPECT_EQ(matches[0](g.v, 0), 0u);
    EXPECT_EQ(matches[1](g.v, 0), 1u);
    EXPECT_EQ(matches[2](g.v, 0), 2u);
    auto why = match_problem(rule, state, g.map({4}, {}));
    ASSERT_TRUE(why.has_value());
    EXPECT_EQ(*why, "the negative condition 'four loops' holds");
}

TEST(DPO, DanglingMatchesAreNeverReturnedAndExplained) {
    Graphs g;
    // Delete a vertex: only vertices without edges match.
    ACSet one = g.graph(1, {}, {});
    ACSet none(g.s);
    Rule rule = g.rule(one, none, none, g.map({}, {}), g.map({}, {}));
    ACSet state = g.graph(3, {1}, {2}); // vertex 3 is isolated
    auto matches = find_matches(rule, state);
    ASSERT_EQ(matches.size(), 1u);
    EXPECT_EQ(matches[0](g.v, 0), 2u);
    EXPECT_EQ(*match_problem(rule, state, g.map({1}, {})),
              "dangling: E #1 refers through src to V #1, which the rule deletes");
    EXPECT_FALSE(rewrite(rule, state, g.map({2}, {})).has_value());
}

TEST(DPO, KeptPartTakesUpdatedAttributeAndRedirectedHom) {
    // An edge kept by the rule gets a new weight and a new target (unset in K, set in R).
    Graphs g;
    ACSet l_state = g.graph(3, {1}, {2});
    l_state.set_subpart(g.weight, 0, l_state.add_var(g.weight_t));
    ACSet k_state = g.graph(3, {}, {});
    Part ke = k_state.add_part(g.e);
    k_state.set_subpart(g.src, ke, 0); // tgt left unset: redirected
    k_state.set_subpart(g.weight, ke, k_state.add_var(g.weight_t));
    ACSet r_state = g.graph(3, {1}, {3});
    r_state.set_subpart(g.weight, 0, Value::integer(7));
    Rule rule = g.rule(l_state, k_state, r_state, g.map({1, 2, 3}, {1}, {Value::var(0)}),
                       g.map({1, 2, 3}, {1}, {Value::integer(7)}));
    ASSERT_TRUE(check_rule(rule).empty());
    ACSet state = g.graph(3, {1, 2}, {2, 3});
    state.set_subpart(g.weight, 0, Value::integer(1));
    state.set_subpart(g.weight, 1, Value::integer(2));
    auto m = g.map({1, 2, 3}, {1}, {Value::integer(1)});
    ASSERT_FALSE(match_problem(rule, state, m));
    ACSet y = state;
    ASSERT_TRUE(rewrite_in_place(rule, y, m).has_value());
    EXPECT_EQ(y.num_parts(g.e), 2u);
    EXPECT_EQ(y.subpart(g.tgt, 0), 2u);
    EXPECT_EQ(y.subpart(g.weight, 0), Value::integer(7));
    EXPECT_EQ(y.subpart(g.weight, 1), Value::integer(2)) << "untouched edge keeps its weight";
}

TEST(DPO, DropsVariablesItOrphansAndKeepsOthers) {
    Graphs g;
    ACSet arr = g.graph(2, {1}, {2});
    ACSet i2 = g.graph(2, {}, {});
    Rule rule = g.rule(arr, i2, i2, g.map({1, 2}, {}), g.map({1, 2}, {}));
    ACSet state = g.graph(2, {1, 2}, {2, 1});
    state.set_subpart(g.weight, 0, state.add_var(g.weight_t, "a"));
    state.set_subpart(g.weight, 1, state.add_var(g.weight_t, "b"));
    ACSet y = state;
    ASSERT_TRUE(rewrite_in_place(rule, y, g.map({1, 2}, {1})).has_value());
    ASSERT_EQ(y.num_vars(g.weight_t), 1u);
    EXPECT_EQ(y.var_name(g.weight_t, 0), "b");
    EXPECT_EQ(y.subpart(g.weight, 0), Value::var(0));
}

// ---- properties on seeded random rules and states -------------------------------------------

struct RandomCase {
    Rule rule;
    ACSet state;
};

RandomCase random_case(const Graphs& g, std::mt19937& rng) {
    auto pick = [&](std::size_t n) { return static_cast<Part>(rng() % n); };
    // L: 1-3 vertices, 0-3 edges.
    ACSet l_state(g.s);
    std::size_t nv = 1 + rng() % 3;
    l_state.add_parts(g.v, nv);
    std::size_t ne = rng() % 4;
    for (std::size_t i = 0; i < ne; ++i) {
        Part ed = l_state.add_part(g.e);
        l_state.set_subpart(g.src, ed, pick(nv));
        l_state.set_subpart(g.tgt, ed, pick(nv));
    }
    // K: a sub-graph (kept vertices; kept edges need kept ends); l the inclusion.
    ACSet k_state(g.s);
    ACSetMorphism l;
    l.components.resize(2);
    l.var_components.resize(1);
    std::vector<Part> k_of(nv, kNoPart);
    for (Part p = 0; p < nv; ++p) {
        if (rng() % 3 != 0) {
            k_of[p] = k_state.add_part(g.v);
            l.components[0].push_back(p);
        }
    }
    for (Part ed = 0; ed < ne; ++ed) {
        Part s0 = k_of[l_state.subpart(g.src, ed)], t0 = k_of[l_state.subpart(g.tgt, ed)];
        if (s0 != kNoPart && t0 != kNoPart && rng() % 2 == 0) {
            Part ke = k_state.add_part(g.e);
            k_state.set_subpart(g.src, ke, s0);
            k_state.set_subpart(g.tgt, ke, t0);
            l.components[1].push_back(ed);
        }
    }
    // R: K plus 0-2 vertices and 0-2 edges; r the inclusion.
    ACSet r_state = k_state;
    ACSetMorphism r = hom::identity(k_state);
    std::size_t extra_v = rng() % 3;
    r_state.add_parts(g.v, extra_v);
    std::size_t rv = r_state.num_parts(g.v);
    if (rv > 0) {
        for (std::size_t i = rng() % 3; i > 0; --i) {
            Part ed = r_state.add_part(g.e);
            r_state.set_subpart(g.src, ed, pick(rv));
            r_state.set_subpart(g.tgt, ed, pick(rv));
        }
    }
    Rule rule = g.rule(std::move(l_state), std::move(k_state), std::move(r_state), l, r);
    // X: 3-5 vertices, 3-8 edges.
    std::size_t xv = 3 + rng() % 3;
    std::vector<Part> srcs, tgts;
    for (std::size_t i = 3 + rng() % 6; i > 0; --i) {
        srcs.push_back(pick(xv) + 1);
        tgts.push_back(pick(xv) + 1);
    }
    return {std::move(rule), g.graph(xv, srcs, tgts)};
}

TEST(DPOProperties, MatchesAreTheMonicHomsThatSatisfyTheGluingConditions) {
    Graphs g;
    for (unsigned seed = 1; seed <= 150; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937 rng(seed);
        auto c = random_case(g, rng);
        ASSERT_TRUE(check_rule(c.rule).empty());
        hom::HomSearchOptions monic;
        monic.monic_all = true;
        std::size_t expected = 0;
        for (const auto& m : hom::find_homomorphisms(c.rule.L, c.state, monic).morphisms) {
            if (colimit::gluing_violations(c.rule.K, c.rule.L, c.state, c.rule.l, m).empty()) {
                ++expected;
            }
        }
        EXPECT_EQ(find_matches(c.rule, c.state).size(), expected);
    }
}

TEST(DPOProperties, ResultIsThePushoutOfTheComplementAndBothApplicationsAgree) {
    Graphs g;
    int checked = 0;
    for (unsigned seed = 1; seed <= 150; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937 rng(seed);
        auto c = random_case(g, rng);
        for (const auto& m : find_matches(c.rule, c.state)) {
            auto pc = colimit::pushout_complement(c.rule.K, c.rule.L, c.state, c.rule.l, m);
            ASSERT_TRUE(pc.has_value()) << pc.error();
            auto po = colimit::pushout(c.rule.K, c.rule.R, pc->z, c.rule.r, pc->k_to_z);
            ASSERT_TRUE(po.has_value()) << po.error();
            auto y = rewrite(c.rule, c.state, m);
            ASSERT_TRUE(y.has_value()) << y.error();
            EXPECT_TRUE(hom::is_isomorphic(po->apex, y->result));
            EXPECT_TRUE(hom::is_natural(y->r_to_result, c.rule.R, y->result));
            ACSet in_place = c.state;
            auto r_to_x = rewrite_in_place(c.rule, in_place, m);
            ASSERT_TRUE(r_to_x.has_value());
            EXPECT_TRUE(hom::is_natural(*r_to_x, c.rule.R, in_place));
            EXPECT_TRUE(hom::is_isomorphic(in_place, y->result));
            ++checked;
        }
    }
    EXPECT_GT(checked, 50);
}

} // namespace
} // namespace catplan::rewrite

namespace catplan::rewrite {
namespace {

// reference §4.6 (rules from migrations, Representable.jl): L = two loops e1, e2 at one vertex,
// K = that vertex v, R = one edge e with r(v) = src(e) (so tgt(e) is new); SPO, monic, and the
// new weight given by the expression `vs -> 0.`. On a path 1 -> 2 with two loops at 2 (weights
// -1, 10, 10) the result is isomorphic to V=3, E=2, src=[1,2], tgt=[2,3], weight=[-1., 0.].
TEST(SPO, ReferenceRepresentableExample) {
    auto s = std::make_shared<schema::Schema>("WeightedGraph");
    ObId v = s->add_ob("V"), e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v), tgt = s->add_hom("tgt", e, v);
    AttrTypeId wt = s->add_attr_type("Weight", schema::ValueKind::Float);
    AttrId weight = s->add_attr("weight", e, wt);
    auto edge = [&](ACSet& g, Part a, Part b, Value w) {
        Part ed = g.add_part(e);
        g.set_subpart(src, ed, a);
        g.set_subpart(tgt, ed, b);
        g.set_subpart(weight, ed, w);
    };
    Rule rule(s);
    rule.semantics = Semantics::SPO;
    Part lv = rule.L.add_part(v);
    edge(rule.L, lv, lv, rule.L.add_var(wt));
    edge(rule.L, lv, lv, rule.L.add_var(wt));
    rule.K.add_part(v);
    Part rs = rule.R.add_part(v), rt = rule.R.add_part(v);
    edge(rule.R, rs, rt, rule.R.add_var(wt));
    rule.l.components = {{lv}, {}};
    rule.l.var_components = {{}};
    rule.r.components = {{rs}, {}};
    rule.r.var_components = {{}};
    AttrExpr zero;
    zero.constant = Value::real(0.0);
    rule.exprs = {{zero}};
    ASSERT_TRUE(check_rule(rule).empty());

    ACSet g(s);
    g.add_parts(v, 2);
    edge(g, 0, 1, Value::real(-1));
    edge(g, 1, 1, Value::real(10));
    edge(g, 1, 1, Value::real(10));
    auto matches = find_matches(rule, g);
    ASSERT_FALSE(matches.empty());
    auto y = rewrite(rule, g, matches[0]);
    ASSERT_TRUE(y.has_value()) << y.error();
    ACSet expected(s);
    expected.add_parts(v, 3);
    edge(expected, 0, 1, Value::real(-1));
    edge(expected, 1, 2, Value::real(0));
    EXPECT_TRUE(hom::is_isomorphic(expected, y->result));
    ACSet in_place = g;
    ASSERT_TRUE(rewrite_in_place(rule, in_place, matches[0]).has_value());
    EXPECT_TRUE(hom::is_isomorphic(expected, in_place));
}

// Deleting the middle vertex of a path 1 -> 2 -> 3: DPO finds no match (dangling edges), SPO
// deletes the vertex and both edges.
TEST(SPO, DeletesDanglingEdgesWhereDpoRejects) {
    Graphs g;
    ACSet one = g.graph(1, {}, {}), none = g.graph(0, {}, {});
    Rule rule = g.rule(one, none, none, g.map({}, {}), g.map({}, {}));
    ACSet path = g.graph(3, {1, 2}, {2, 3});
    auto m = g.map({2}, {});
    EXPECT_TRUE(find_matches(rule, path).empty()); // every vertex has an edge
    EXPECT_TRUE(match_problem(rule, path, m).has_value());
    rule.semantics = Semantics::SPO;
    EXPECT_EQ(find_matches(rule, path).size(), 3u);
    EXPECT_FALSE(match_problem(rule, path, m).has_value());
    auto y = rewrite(rule, path, m);
    ASSERT_TRUE(y.has_value()) << y.error();
    EXPECT_TRUE(hom::is_isomorphic(g.graph(2, {}, {}), y->result));
    ACSet in_place = path;
    ASSERT_TRUE(rewrite_in_place(rule, in_place, m).has_value());
    EXPECT_TRUE(hom::is_isomorphic(g.graph(2, {}, {}), in_place));
}

// SPO never deletes what the rule keeps: deleting vertex 1 of an edge 1 -> 2 that the rule keeps
// is rejected with a reason.
TEST(SPO, RejectsACascadeIntoAKeptPart) {
    Graphs g;
    ACSet arr = g.graph(2, {1}, {2});
    Rule rule = g.rule(arr, g.graph(1, {}, {}), g.graph(1, {}, {}), g.map({2}, {}), g.map({1}, {}));
    rule.semantics = Semantics::SPO;
    // K keeps vertex 2 only, so the edge (in L, not in K) is deleted with vertex 1: fine.
    ACSet x = g.graph(2, {1, 1}, {2, 2}); // a second edge 1 -> 2 dangles and is deleted too
    auto matches = find_matches(rule, x);
    ASSERT_EQ(matches.size(), 2u);
    auto y = rewrite(rule, x, matches[0]);
    ASSERT_TRUE(y.has_value()) << y.error();
    EXPECT_TRUE(hom::is_isomorphic(g.graph(1, {}, {}), y->result));
    // A rule deleting vertex a but keeping an edge a -> b whose src K leaves unset (a partial
    // state) and R does not redirect: the cascade would delete the kept edge, so no match.
    ACSet k(g.s);
    Part kb = k.add_part(g.v);
    k.set_subpart(g.tgt, k.add_part(g.e), kb);
    Rule bad = g.rule(arr, k, k, g.map({2}, {1}), g.map({1}, {1}));
    bad.semantics = Semantics::SPO;
    auto m = g.map({1, 2}, {1});
    auto problem = match_problem(bad, x, m);
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("which the rule keeps"), std::string::npos) << *problem;
    EXPECT_TRUE(find_matches(bad, x).empty());
}

} // namespace
} // namespace catplan::rewrite

namespace catplan::rewrite {
namespace {

// ---- the reference (pushout complement, then pushout) and the fast path agree ----------------

// Graphs with an Int weight on edges and a String label on vertices.
struct Attributed {
    std::shared_ptr<schema::Schema> s = std::make_shared<schema::Schema>("AttributedGraph");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId tgt = s->add_hom("tgt", e, v);
    AttrTypeId weight_t = s->add_attr_type("Weight", schema::ValueKind::Int);
    AttrTypeId label_t = s->add_attr_type("Label", schema::ValueKind::String);
    AttrId weight = s->add_attr("weight", e, weight_t);
    AttrId label = s->add_attr("label", v, label_t);
};

struct Dice {
    std::mt19937 rng;

    explicit Dice(unsigned seed) : rng(seed) {}

    std::size_t below(std::size_t n) { return n == 0 ? 0 : rng() % n; }

    bool one_in(std::size_t n) { return below(n) == 0; }

    Value constant(const Attributed& g, AttrTypeId t) {
        return t == g.weight_t ? Value::integer(static_cast<std::int64_t>(1 + below(3)))
                               : Value::string(one_in(2) ? "a" : "b");
    }
};

// The cells of a random state: a constant, a variable (sometimes one already used), or unset.
void fill_cells(const Attributed& g, ACSet& x, Dice& d, bool partial) {
    for (AttrId a : {g.weight, g.label}) {
        AttrTypeId t = g.s->attr(a).codom;
        for (Part p = 0; p < x.num_parts(g.s->attr(a).dom); ++p) {
            std::size_t roll = d.below(partial ? 4 : 3);
            if (roll == 0) {
                bool reuse = x.num_vars(t) > 0 && d.one_in(4);
                x.set_subpart(a, p,
                              reuse ? Value::var(static_cast<std::uint32_t>(d.below(x.num_vars(t))))
                                    : x.add_var(t));
            } else if (roll < 3) {
                x.set_subpart(a, p, d.constant(g, t));
            }
        }
    }
}

ACSet random_graph(const Attributed& g, Dice& d, std::size_t nv, std::size_t ne, bool partial) {
    ACSet x(g.s);
    x.add_parts(g.v, nv);
    for (std::size_t i = 0; i < ne; ++i) {
        Part ed = x.add_part(g.e);
        x.set_subpart(g.src, ed, static_cast<Part>(d.below(nv)));
        x.set_subpart(g.tgt, ed, static_cast<Part>(d.below(nv)));
    }
    fill_cells(g, x, d, partial);
    return x;
}

// K: kept vertices and edges of L (l the inclusion), a kept edge's end sometimes left unset (R
// may redirect it), kept cells carried by K variables or constants, and K variables that carry
// an L variable without holding a cell.
void random_keep(const Attributed& g, Rule& rule, Dice& d, std::vector<std::vector<Value>>& k_var) {
    std::vector<Part> k_of(rule.L.num_parts(g.v), kNoPart);
    rule.l.components.assign(2, {});
    rule.l.var_components.assign(2, {});
    k_var.assign(2, std::vector<Value>());
    for (std::uint32_t t = 0; t < 2; ++t) {
        k_var[t].assign(rule.L.num_vars(AttrTypeId(t)), Value());
    }
    auto carry = [&](AttrTypeId t, const Value& lv) {
        if (!lv.is_var()) {
            return lv;
        }
        Value& kv = k_var[t.index()][lv.var_index()];
        if (kv.is_unset()) {
            kv = rule.K.add_var(t);
            rule.l.var_components[t.index()].push_back(lv);
        }
        return kv;
    };
    auto keep_cell = [&](AttrId a, Part lp, Part kp) {
        Value lv = rule.L.subpart(a, lp);
        if (!lv.is_unset() && !d.one_in(4)) {
            rule.K.set_subpart(a, kp, carry(g.s->attr(a).codom, lv));
        }
    };
    for (Part p = 0; p < rule.L.num_parts(g.v); ++p) {
        if (!d.one_in(3)) {
            k_of[p] = rule.K.add_part(g.v);
            rule.l.components[g.v.index()].push_back(p);
            keep_cell(g.label, p, k_of[p]);
        }
    }
    for (Part ed = 0; ed < rule.L.num_parts(g.e); ++ed) {
        // A kept edge whose end is deleted leaves that end unset in K (a partial state).
        Part s0 = k_of[rule.L.subpart(g.src, ed)], t0 = k_of[rule.L.subpart(g.tgt, ed)];
        if ((s0 == kNoPart || t0 == kNoPart ? !d.one_in(3) : d.one_in(2))) {
            continue;
        }
        Part ke = rule.K.add_part(g.e);
        rule.l.components[g.e.index()].push_back(ed);
        rule.K.set_subpart(g.src, ke, d.one_in(5) ? kNoPart : s0);
        rule.K.set_subpart(g.tgt, ke, d.one_in(5) ? kNoPart : t0);
        keep_cell(g.weight, ed, ke);
    }
    for (std::uint32_t t = 0; t < 2; ++t) {
        if (rule.L.num_vars(AttrTypeId(t)) > 0 && d.one_in(3)) {
            auto i = static_cast<std::uint32_t>(d.below(rule.L.num_vars(AttrTypeId(t))));
            carry(AttrTypeId(t), Value::var(i)); // a K variable without a cell
        }
    }
}

// A value for an R cell that K leaves unset: a constant, a fresh unknown, a value carried through
// K, or (weights) the expression `w + 1` of a weight the match binds.
Value random_r_value(const Attributed& g, Rule& rule, Dice& d, AttrTypeId t,
                     const std::vector<Value>& carried) {
    switch (d.below(4)) {
    case 0:
        return d.constant(g, t);
    case 1:
        if (!carried.empty()) {
            return carried[d.below(carried.size())];
        }
        return rule.R.add_var(t);
    case 2:
        if (t == g.weight_t && rule.L.num_vars(t) > 0) {
            Value j = rule.R.add_var(t);
            AttrExpr sum{AttrExpr::Op::Add, {}, {}, 0, {}, {}};
            auto i = static_cast<std::uint32_t>(d.below(rule.L.num_vars(t)));
            sum.args.push_back({AttrExpr::Op::Input, {}, t, i, {}, {}});
            sum.args.push_back({AttrExpr::Op::Const, Value::integer(1), {}, 0, {}, {}});
            rule.exprs[t.index()].resize(j.var_index() + 1);
            rule.exprs[t.index()][j.var_index()] = sum;
            return j;
        }
        return rule.R.add_var(t);
    default:
        return rule.R.add_var(t);
    }
}

// R: K (r the inclusion) plus new vertices and edges. A kept edge's end that K leaves unset is
// sometimes redirected; a kept cell's variable is sometimes overwritten by a constant (r sends it
// there); cells that K leaves unset are sometimes set anew.
void random_effect(const Attributed& g, Rule& rule, Dice& d) {
    rule.R = rule.K;
    rule.r = hom::identity(rule.K);
    rule.exprs.assign(2, {});
    std::vector<std::vector<Value>> carried(2); // R variables that K binds
    for (std::uint32_t t = 0; t < 2; ++t) {
        AttrTypeId ty(t);
        for (std::uint32_t k = 0; k < rule.K.num_vars(ty); ++k) {
            bool held = !rule.K.var_incident(ty, k).empty();
            if (held && d.one_in(4)) {
                Value c = d.constant(g, ty); // an update: the kept value is overwritten
                rule.r.var_components[t][k] = c;
                for (auto cell : std::vector(rule.K.var_incident(ty, k).begin(),
                                             rule.K.var_incident(ty, k).end())) {
                    rule.R.set_subpart(cell.attr, cell.part, c);
                }
            } else {
                carried[t].push_back(Value::var(k));
            }
        }
    }
    std::size_t kept_v = rule.R.num_parts(g.v), kept_e = rule.R.num_parts(g.e);
    rule.R.add_parts(g.v, d.below(3));
    std::size_t rv = rule.R.num_parts(g.v);
    for (std::size_t i = d.below(3); i > 0 && rv > 0; --i) {
        Part ed = rule.R.add_part(g.e);
        rule.R.set_subpart(g.src, ed, static_cast<Part>(d.below(rv)));
        rule.R.set_subpart(g.tgt, ed, static_cast<Part>(d.below(rv)));
    }
    for (Part ed = 0; ed < kept_e; ++ed) {
        for (HomId h : {g.src, g.tgt}) {
            if (rule.R.subpart(h, ed) == kNoPart && rv > 0 && d.one_in(2)) {
                rule.R.set_subpart(h, ed, static_cast<Part>(d.below(rv)));
            }
        }
    }
    for (AttrId a : {g.weight, g.label}) {
        AttrTypeId t = g.s->attr(a).codom;
        std::size_t kept = a == g.weight ? kept_e : kept_v;
        for (Part p = 0; p < rule.R.num_parts(g.s->attr(a).dom); ++p) {
            if (rule.R.subpart(a, p).is_unset() && (p >= kept || d.one_in(2))) {
                rule.R.set_subpart(a, p, random_r_value(g, rule, d, t, carried[t.index()]));
            }
        }
        rule.exprs[t.index()].resize(rule.R.num_vars(t));
    }
}

Rule random_attributed_rule(const Attributed& g, Dice& d) {
    Rule rule(g.s);
    rule.L = random_graph(g, d, 1 + d.below(3), d.below(4), /*partial=*/true);
    std::vector<std::vector<Value>> k_var;
    random_keep(g, rule, d, k_var);
    random_effect(g, rule, d);
    if (d.one_in(4)) {
        rule.semantics = Semantics::SPO;
    }
    if (d.one_in(6)) {
        ACSet n = rule.L; // the NAC: no further edge from L's first vertex to itself
        Part ed = n.add_part(g.e);
        n.set_subpart(g.src, ed, 0);
        n.set_subpart(g.tgt, ed, 0);
        rule.conditions.push_back({"loop", true, n, hom::identity(rule.L), {}});
        rule.conditions.back().n.components[g.e.index()].resize(rule.L.num_parts(g.e));
    }
    return rule;
}

std::string describe_case(const Rule& rule, const ACSet& x, const ACSetMorphism& m) {
    std::string out = "\nL:\n" + acset::to_tables(rule.L) + "K:\n" + acset::to_tables(rule.K) +
                      "R:\n" + acset::to_tables(rule.R) + "X:\n" + acset::to_tables(x) + "m:";
    for (const auto& c : m.components) {
        for (Part p : c) {
            out += " " + std::to_string(p + 1);
        }
        out += ";";
    }
    return out + "\n";
}

// The reference's Y and the fast path's Y are isomorphic by an isomorphism that carries the
// reference's R -> Y to the fast path's R -> Y (on parts and on variables).
testing::AssertionResult same_up_to_iso(const Rule& rule, const Rewrite& ref, const ACSet& fast,
                                        const ACSetMorphism& fast_r) {
    const auto& s = rule.R.schema();
    hom::HomSearchOptions opt;
    opt.iso = true;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < rule.R.num_parts(ObId(o)); ++p) {
            opt.bind(ObId(o), ref.r_to_result(ObId(o), p), fast_r(ObId(o), p));
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < rule.R.num_vars(AttrTypeId(t)); ++j) {
            const Value& a = ref.r_to_result.var(AttrTypeId(t), j);
            const Value& b = fast_r.var(AttrTypeId(t), j);
            if (a.is_var() && b.is_var()) {
                opt.bind_var(AttrTypeId(t), a.var_index(), b);
            } else if (!(a == b)) {
                return testing::AssertionFailure() << "R's variable " << j << " goes to "
                                                   << a.to_string() << " and to " << b.to_string();
            }
        }
    }
    auto iso = hom::find_homomorphism(ref.result, fast, opt);
    if (!iso) {
        return testing::AssertionFailure() << "no isomorphism over R: " << iso.error();
    }
    return testing::AssertionSuccess();
}

TEST(DPOProperties, ReferenceAndFastPathAgreeOnRandomRulesWithAttributes) {
    Attributed g;
    int applied = 0, rejected = 0, updated = 0, redirected = 0, spo = 0;
    for (unsigned seed = 1; seed <= 400; ++seed) {
        SCOPED_TRACE(seed);
        Dice d(seed);
        Rule rule = random_attributed_rule(g, d);
        auto problems = check_rule(rule);
        ASSERT_TRUE(problems.empty()) << problems.front().message;
        ACSet x = random_graph(g, d, 3 + d.below(3), 3 + d.below(6), /*partial=*/false);
        hom::HomSearchOptions opt;
        opt.max_results = 40; // every morphism, monic or not: many are not valid matches
        for (const auto& m : hom::find_homomorphisms(rule.L, x, opt).morphisms) {
            auto ref = rewrite(rule, x, m);
            ACSet fast = x;
            auto fast_r = rewrite_in_place(rule, fast, m);
            ASSERT_EQ(ref.has_value(), fast_r.has_value())
                << (ref ? fast_r.error() : ref.error()) << describe_case(rule, x, m);
            if (!ref) {
                EXPECT_EQ(ref.error(), fast_r.error());
                EXPECT_EQ(fast, x) << "a rejected match leaves the state unchanged";
                ++rejected;
                continue;
            }
            ASSERT_TRUE(same_up_to_iso(rule, *ref, fast, *fast_r))
                << describe_case(rule, x, m) << "reference:\n"
                << acset::to_tables(ref->result) << "fast path:\n"
                << acset::to_tables(fast);
            ++applied;
            spo += rule.semantics == Semantics::SPO;
        }
        for (std::uint32_t t = 0; t < 2; ++t) {
            for (const Value& v : rule.r.var_components[t]) {
                updated += v.is_concrete();
            }
        }
        for (Part k = 0; k < rule.K.num_parts(g.e); ++k) {
            redirected += rule.K.subpart(g.tgt, k) == kNoPart &&
                          rule.R.subpart(g.tgt, rule.r(g.e, k)) != kNoPart;
        }
    }
    // The generator reaches every feature (figures at the time of writing: 599 applied, 726
    // rejected, 39 updated values, 42 redirected homs, 247 SPO applications).
    EXPECT_GT(applied, 400);
    EXPECT_GT(rejected, 400);
    EXPECT_GT(updated, 20);
    EXPECT_GT(redirected, 20);
    EXPECT_GT(spo, 120);
}

// A match find_matches returned needs no second check: applied unchecked, it gives the state,
// names, comatch and failures (an expression, an unsupported step) that the checked application
// gives, monic or not, DPO or SPO.
TEST(DPOProperties, FoundMatchesApplyAsCheckedOnesDo) {
    Attributed g;
    int applied = 0, spo = 0, non_monic = 0;
    for (unsigned seed = 1; seed <= 400; ++seed) {
        SCOPED_TRACE(seed);
        Dice d(seed);
        Rule rule = random_attributed_rule(g, d);
        ACSet x = random_graph(g, d, 3 + d.below(3), 3 + d.below(6), /*partial=*/false);
        MatchOptions opt;
        opt.monic = seed % 2 == 0;
        for (const auto& m : find_matches(rule, x, opt)) {
            ACSet checked = x, unchecked = x;
            auto a = rewrite_in_place(rule, checked, m, CheckMatch::Yes);
            auto b = rewrite_in_place(rule, unchecked, m, CheckMatch::No);
            ASSERT_EQ(a.has_value(), b.has_value()) << describe_case(rule, x, m);
            if (!a) {
                EXPECT_EQ(a.error(), b.error());
                continue;
            }
            EXPECT_EQ(checked, unchecked) << describe_case(rule, x, m);
            EXPECT_EQ(acset::to_tables(checked), acset::to_tables(unchecked));
            EXPECT_EQ(a->components, b->components);
            EXPECT_EQ(a->var_components, b->var_components);
            ++applied;
            spo += rule.semantics == Semantics::SPO;
            non_monic += !detail::is_injective(m, rule.L);
        }
    }
    EXPECT_GT(applied, 300);
    EXPECT_GT(spo, 50);
    EXPECT_GT(non_monic, 20);
}

TEST(DPODeathTest, AnUncheckedMatchOutsideTheStateIsAnAssertion) {
    Graphs g;
    Rule rule = g.rule(g.graph(1, {}, {}), g.graph(0, {}, {}), g.graph(0, {}, {}), g.map({}, {}),
                       g.map({}, {}));
    ACSet x = g.graph(2, {}, {});
    EXPECT_EXIT((void)rewrite_in_place(rule, x, g.map({7}, {}), CheckMatch::No),
                testing::ExitedWithCode(70), "a found match lands in the state's parts");
}

} // namespace
} // namespace catplan::rewrite
