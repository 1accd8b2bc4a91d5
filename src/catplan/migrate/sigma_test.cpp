// Σ along delta maps: free reflexive graphs (path equations), connected components (merging),
// disjoint edges (totality), attributes (constants, shared and new variables, a clash), an
// infinite Σ, and the adjunction Hom(Σ Y, X) ≅ Hom(Y, Δ X) counted on seeded random graphs.

#include "catplan/hom/hom_search.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/migrate/sigma.hpp"

#include <gtest/gtest.h>

#include <random>

namespace catplan::migrate {
namespace {

using schema::Schema;
using schema::ValueKind;

struct Graphs {
    SchemaPtr graph, refl, set;
    ObId v, e, rv, re, x;
    HomId src, tgt, rsrc, rtgt, loop;
};

// Graph (V, E, src, tgt); ReflexiveGraph, the same with refl : V -> E, refl⋅src = refl⋅tgt = id;
// Set, one object X.
Graphs graphs() {
    Graphs g;
    auto graph = std::make_shared<Schema>("Graph");
    g.v = graph->add_ob("V");
    g.e = graph->add_ob("E");
    g.src = graph->add_hom("src", g.e, g.v);
    g.tgt = graph->add_hom("tgt", g.e, g.v);
    auto refl = std::make_shared<Schema>("ReflexiveGraph");
    g.rv = refl->add_ob("V");
    g.re = refl->add_ob("E");
    g.rsrc = refl->add_hom("src", g.re, g.rv);
    g.rtgt = refl->add_hom("tgt", g.re, g.rv);
    g.loop = refl->add_hom("refl", g.rv, g.re);
    refl->add_equation({"", {g.rv, {g.loop, g.rsrc}, std::nullopt}, {g.rv, {}, std::nullopt}, {}});
    refl->add_equation({"", {g.rv, {g.loop, g.rtgt}, std::nullopt}, {g.rv, {}, std::nullopt}, {}});
    auto set = std::make_shared<Schema>("Set");
    g.x = set->add_ob("X");
    g.graph = graph;
    g.refl = refl;
    g.set = set;
    return g;
}

SchemaMap finished(SchemaMap m) {
    (void)m.finish();
    EXPECT_TRUE(m.ok());
    EXPECT_TRUE(m.is_delta());
    return m;
}

// The inclusion of Graph into ReflexiveGraph: Σ adds a loop at every vertex.
SchemaMap inclusion(const Graphs& g) {
    SchemaMap m(g.graph, g.refl);
    m.map_ob(g.v, g.rv);
    m.map_ob(g.e, g.re);
    m.map_hom_path(g.src, {g.rsrc});
    m.map_hom_path(g.tgt, {g.rtgt});
    return finished(std::move(m));
}

// Graph to Set, every vertex and edge an element and both ends the element itself: Σ is the
// set of connected components.
SchemaMap collapse(const Graphs& g) {
    SchemaMap m(g.graph, g.set);
    m.map_ob(g.v, g.x);
    m.map_ob(g.e, g.x);
    m.map_hom_path(g.src, {});
    m.map_hom_path(g.tgt, {});
    (void)m.finish(); // sending src and tgt to identities warns
    EXPECT_TRUE(m.ok());
    return m;
}

ACSet path_graph(const Graphs& g, std::size_t n) {
    ACSet y(g.graph);
    y.add_parts(g.v, n);
    for (Part i = 0; i + 1 < n; ++i) {
        Part e = y.add_part(g.e);
        y.set_subpart(g.src, e, i);
        y.set_subpart(g.tgt, e, i + 1);
    }
    return y;
}

TEST(Sigma, FreeReflexiveGraphAddsOneLoopPerVertexAndKeepsNames) {
    Graphs g = graphs();
    ACSet y = path_graph(g, 3);
    y.set_part_name(g.v, 0, "a");
    auto x = sigma(inclusion(g), y);
    ASSERT_TRUE(x) << x.error();
    EXPECT_EQ(x->num_parts(g.rv), 3u);
    EXPECT_EQ(x->num_parts(g.re), 5u); // 2 edges and 3 loops
    EXPECT_EQ(x->part_name(g.rv, 0), "a");
    for (Part v = 0; v < 3; ++v) {
        Part l = x->subpart(g.loop, v);
        EXPECT_EQ(x->subpart(g.rsrc, l), v);
        EXPECT_EQ(x->subpart(g.rtgt, l), v);
    }
    EXPECT_EQ(x->subpart(g.rsrc, 0), 0u);
    EXPECT_EQ(x->subpart(g.rtgt, 0), 1u);
}

TEST(Sigma, CollapsingAGraphGivesItsConnectedComponents) {
    Graphs g = graphs();
    ACSet y = path_graph(g, 3); // one component
    Part lone = y.add_part(g.v);
    Part w = y.add_part(g.v);
    Part e = y.add_part(g.e); // a second component: an edge w -> lone
    y.set_subpart(g.src, e, w);
    y.set_subpart(g.tgt, e, lone);
    y.add_part(g.v); // a third: an isolated vertex
    auto x = sigma(collapse(g), y);
    ASSERT_TRUE(x) << x.error();
    EXPECT_EQ(x->num_parts(g.x), 3u);
}

TEST(Sigma, AnObjectSentToAnEdgeGetsBothEnds) {
    Graphs g = graphs();
    auto point = std::make_shared<Schema>("Point");
    ObId p = point->add_ob("P");
    SchemaMap m(point, g.graph);
    m.map_ob(p, g.e);
    m = finished(std::move(m));
    ACSet y(point);
    y.add_parts(p, 4);
    auto x = sigma(m, y);
    ASSERT_TRUE(x) << x.error();
    EXPECT_EQ(x->num_parts(g.e), 4u);
    EXPECT_EQ(x->num_parts(g.v), 8u);
}

struct Labelled {
    SchemaPtr plain, coloured;
    ObId block, cblock;
    AttrTypeId clear_t, cclear_t, colour_t;
    AttrId clear, cclear, colour;
};

// A plain block world (isClear) and a coloured one (isClear and hasColor).
Labelled labelled() {
    Labelled l;
    auto plain = std::make_shared<Schema>("Plain");
    l.block = plain->add_ob("Block");
    l.clear_t = plain->add_attr_type("Clear", ValueKind::Bool);
    l.clear = plain->add_attr("isClear", l.block, l.clear_t);
    auto coloured = std::make_shared<Schema>("Coloured");
    l.cblock = coloured->add_ob("Block");
    l.cclear_t = coloured->add_attr_type("Clear", ValueKind::Bool);
    l.colour_t = coloured->add_attr_type("Color", ValueKind::String);
    l.cclear = coloured->add_attr("isClear", l.cblock, l.cclear_t);
    l.colour = coloured->add_attr("hasColor", l.cblock, l.colour_t);
    l.plain = plain;
    l.coloured = coloured;
    return l;
}

TEST(Sigma, AttributesKeepConstantsAndSharedVariablesAndGetNewOnes) {
    Labelled l = labelled();
    SchemaMap forget(l.plain, l.coloured);
    forget.map_ob(l.block, l.cblock);
    forget.map_attr_type(l.clear_t, l.cclear_t);
    forget.map_attr(l.clear, Term::path("Block", {}, l.cclear));
    forget = finished(std::move(forget));
    ACSet y(l.plain);
    y.add_parts(l.block, 3);
    Value unknown = y.add_var(l.clear_t, "c");
    y.set_subpart(l.clear, 0, Value::boolean(true));
    y.set_subpart(l.clear, 1, unknown);
    y.set_subpart(l.clear, 2, unknown);
    auto x = sigma(forget, y);
    ASSERT_TRUE(x) << x.error();
    EXPECT_EQ(x->subpart(l.cclear, 0), Value::boolean(true));
    EXPECT_TRUE(x->subpart(l.cclear, 1).is_var());
    EXPECT_EQ(x->subpart(l.cclear, 1), x->subpart(l.cclear, 2)); // still one unknown
    EXPECT_EQ(x->var_name(l.cclear_t, x->subpart(l.cclear, 1).var_index()), "c");
    EXPECT_EQ(x->num_vars(l.colour_t), 3u); // each colour a new unknown
    EXPECT_EQ(x->num_vars(l.cclear_t), 1u);
}

TEST(Sigma, IdentifiedPartsWithDifferentConstantsFail) {
    auto labelled_graph = std::make_shared<Schema>("LabelledGraph");
    ObId v = labelled_graph->add_ob("V"), e = labelled_graph->add_ob("E");
    HomId src = labelled_graph->add_hom("src", e, v), tgt = labelled_graph->add_hom("tgt", e, v);
    AttrTypeId lt = labelled_graph->add_attr_type("Label", ValueKind::String);
    AttrId label = labelled_graph->add_attr("label", v, lt);
    auto labelled_set = std::make_shared<Schema>("LabelledSet");
    ObId x = labelled_set->add_ob("X");
    AttrTypeId st = labelled_set->add_attr_type("Label", ValueKind::String);
    AttrId slabel = labelled_set->add_attr("label", x, st);
    SchemaMap m(labelled_graph, labelled_set);
    m.map_ob(v, x);
    m.map_ob(e, x);
    m.map_hom_path(src, {});
    m.map_hom_path(tgt, {});
    m.map_attr_type(lt, st);
    m.map_attr(label, Term::path("V", {}, slabel));
    (void)m.finish();
    ASSERT_TRUE(m.ok());
    ACSet y(labelled_graph);
    y.add_parts(v, 2);
    y.set_subpart(label, 0, Value::string("red"));
    y.set_subpart(label, 1, Value::string("blue"));
    Part edge = y.add_part(e);
    y.set_subpart(src, edge, 0);
    y.set_subpart(tgt, edge, 1);
    auto r = sigma(m, y);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("identifies the constants"), std::string::npos) << r.error();
}

TEST(Sigma, ACycleOfHomsMakesSigmaInfinite) {
    auto chain = std::make_shared<Schema>("Chain");
    ObId n = chain->add_ob("N");
    chain->add_hom("next", n, n);
    auto point = std::make_shared<Schema>("Point");
    ObId p = point->add_ob("P");
    SchemaMap m(point, chain);
    m.map_ob(p, n);
    m = finished(std::move(m));
    ACSet y(point);
    y.add_part(p);
    auto r = sigma(m, y, 1000);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("infinite"), std::string::npos) << r.error();
}

TEST(Sigma, TheLimitStopsAWalkAlongAnAttributePath) {
    auto chain = std::make_shared<Schema>("Chain");
    ObId n = chain->add_ob("N");
    HomId next = chain->add_hom("next", n, n);
    AttrTypeId lt = chain->add_attr_type("Label", ValueKind::String);
    AttrId label = chain->add_attr("label", n, lt);
    auto point = std::make_shared<Schema>("Point");
    ObId p = point->add_ob("P");
    AttrTypeId pt = point->add_attr_type("Label", ValueKind::String);
    AttrId plabel = point->add_attr("far", p, pt);
    SchemaMap m(point, chain);
    m.map_ob(p, n);
    m.map_attr_type(pt, lt);
    m.map_attr(plabel, Term::path("P", {next, next, next}, label));
    m = finished(std::move(m));
    ACSet y(point);
    y.add_parts(p, 2);
    y.set_subpart(plabel, 0, Value::string("a"));
    y.set_subpart(plabel, 1, Value::string("b"));
    auto r = sigma(m, y, 3); // the first walk needs 4 parts
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("more than 3 parts"), std::string::npos) << r.error();
}

ACSet random_graph(const SchemaPtr& s, ObId v, ObId e, HomId src, HomId tgt, std::mt19937_64& rng,
                   std::size_t max_v, std::size_t max_e) {
    ACSet y(s);
    std::size_t nv = 1 + rng() % max_v, ne = rng() % (max_e + 1);
    y.add_parts(v, nv);
    for (std::size_t i = 0; i < ne; ++i) {
        Part p = y.add_part(e);
        y.set_subpart(src, p, static_cast<Part>(rng() % nv));
        y.set_subpart(tgt, p, static_cast<Part>(rng() % nv));
    }
    return y;
}

// A random reflexive graph: a loop at every vertex, then random edges.
ACSet random_reflexive(const Graphs& g, std::mt19937_64& rng) {
    ACSet x = random_graph(g.refl, g.rv, g.re, g.rsrc, g.rtgt, rng, 4, 5);
    for (Part v = 0; v < x.num_parts(g.rv); ++v) {
        Part l = x.add_part(g.re);
        x.set_subpart(g.rsrc, l, v);
        x.set_subpart(g.rtgt, l, v);
        x.set_subpart(g.loop, v, l);
    }
    return x;
}

TEST(Sigma, IsLeftAdjointToDeltaOnRandomGraphs) {
    Graphs g = graphs();
    SchemaMap inc = inclusion(g);
    SchemaMap col = collapse(g);
    std::uint64_t total = 0; // the counts must not all be 0 = 0
    for (int seed = 0; seed < 60; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 7919 + 1);
        ACSet y = random_graph(g.graph, g.v, g.e, g.src, g.tgt, rng, 4, 4);
        ACSet x = random_reflexive(g, rng);
        auto sy = sigma(inc, y);
        ASSERT_TRUE(sy) << sy.error();
        std::uint64_t n = hom::count_homomorphisms(*sy, x).count;
        EXPECT_EQ(n, hom::count_homomorphisms(y, migrate(inc, x)).count);
        total += n;
        ACSet set(g.set);
        set.add_parts(g.x, 1 + rng() % 3);
        auto cy = sigma(col, y);
        ASSERT_TRUE(cy) << cy.error();
        EXPECT_EQ(hom::count_homomorphisms(*cy, set).count,
                  hom::count_homomorphisms(y, migrate(col, set)).count);
    }
    EXPECT_GT(total, 60u);
}

TEST(Sigma, ConjunctiveMapsAreRefused) {
    Graphs g = graphs();
    SchemaMap m(g.graph, g.graph);
    m.map_ob(g.v, g.v);
    Query q(g.graph);
    q.add_variable("e1", g.e);
    q.add_variable("e2", g.e);
    q.add_equation(Term::path("e1", {g.tgt}), Term::path("e2", {g.src}));
    m.map_ob(g.e, std::move(q));
    m.map_hom(g.src, {Term::path("e1", {g.src})});
    m.map_hom(g.tgt, {Term::path("e2", {g.tgt})});
    (void)m.finish();
    ASSERT_TRUE(m.ok());
    auto r = sigma(m, path_graph(g, 3));
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("delta maps only"), std::string::npos);
}

} // namespace
} // namespace catplan::migrate
