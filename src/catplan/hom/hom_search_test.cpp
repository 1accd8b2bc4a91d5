#include "catplan/hom/detail/test_instances.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/morphism.hpp"

#include <gtest/gtest.h>

namespace catplan::hom {
namespace {

using namespace catplan::hom::testing;
using schema::ValueKind;

// ---- LSet: X::Ob, D::AttrType, f::Attr(X, D) (reference §3.3) ------------------------------

SchemaPtr lset_schema() {
    static SchemaPtr s = [] {
        auto l = std::make_shared<Schema>("LSet");
        ObId x = l->add_ob("X");
        AttrTypeId d = l->add_attr_type("D", ValueKind::String);
        l->add_attr("f", x, d);
        return SchemaPtr(l);
    }();
    return s;
}

constexpr ObId kX{0};
constexpr AttrTypeId kD{0};
constexpr AttrId kF{0};

// An LSet with the given cells; `nvars` variables of D.
ACSet lset(std::size_t nvars, const std::vector<Value>& cells) {
    ACSet a(lset_schema());
    for (std::size_t i = 0; i < nvars; ++i) {
        a.add_var(kD);
    }
    for (const Value& v : cells) {
        Part p = a.add_part(kX);
        a.set_subpart(kF, p, v);
    }
    return a;
}

Value sym(std::string_view s) {
    return Value::string(s);
}

HomSearchOptions monic_d() {
    HomSearchOptions o;
    o.monic_attr_types = {kD};
    return o;
}

TEST(HomSearchLSet, MonicAttrTypeMakesVariablesInjectiveIntoVariables) {
    ACSet a = lset(2, {Value::var(0), Value::var(1)});
    ACSet b = lset(1, {Value::var(0)});
    EXPECT_EQ(find_homomorphisms(a, b, monic_d()).count, 0u);
    EXPECT_EQ(find_homomorphisms(b, a, monic_d()).count, 2u);
    EXPECT_EQ(find_homomorphisms(a, a, monic_d()).count, 2u);
    // Without monic on D both cells may share the one variable of b.
    EXPECT_EQ(find_homomorphisms(a, b).count, 1u);
}

struct GH {
    ACSet g = lset(2, {sym("a"), Value::var(0), Value::var(1)});
    ACSet h = lset(2, {sym("a"), sym("b"), Value::var(0), Value::var(1)});
    ACSet g_prime = [this] {
        ACSet gp = g;
        gp.add_var(kD); // a free-floating variable
        return gp;
    }();

    GH() { h.add_var(kD); } // H has three variables of D, the third unused
};

TEST(HomSearchLSet, VariablesBindToAnyValue) {
    GH t;
    auto r = find_homomorphisms(t.g, t.h);
    EXPECT_EQ(r.count, 16u);
    EXPECT_EQ(r.morphisms.size(), 16u);
    EXPECT_TRUE(r.complete);
    for (const auto& m : r.morphisms) {
        EXPECT_TRUE(is_natural(m, t.g, t.h));
        EXPECT_EQ(m(kX, 0), 0u); // the concrete :a only matches :a
    }
}

TEST(HomSearchLSet, FreeFloatingVariableIsReported) {
    GH t;
    auto r = find_homomorphisms(t.g_prime, t.h);
    EXPECT_EQ(r.count, 0u);
    EXPECT_FALSE(r.complete);
    EXPECT_NE(r.error.find("infinitely many"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("?3"), std::string::npos) << r.error;
    EXPECT_FALSE(is_homomorphic(t.g_prime, t.h));
    auto first = find_homomorphism(t.g_prime, t.h);
    ASSERT_FALSE(first.has_value());
    EXPECT_EQ(first.error(), r.error);
}

TEST(HomSearchLSet, InitialBindsVariables) {
    GH t;
    HomSearchOptions all_b;
    for (std::uint32_t j = 0; j < 3; ++j) {
        all_b.bind_var(kD, j, sym("b"));
    }
    auto r = find_homomorphisms(t.g_prime, t.h, all_b);
    ASSERT_EQ(r.count, 1u);
    EXPECT_EQ(r.morphisms[0].components[0], (std::vector<Part>{0, 1, 1}));
    EXPECT_EQ(r.morphisms[0].var_components[0], (std::vector<Value>{sym("b"), sym("b"), sym("b")}));

    HomSearchOptions third_b;
    third_b.bind_var(kD, 2, sym("b"));
    EXPECT_EQ(find_homomorphisms(t.g_prime, t.h, third_b).count, 16u);
}

TEST(HomSearchLSet, MonicAttrTypeEnumeratesFloatingVariablesInjectively) {
    GH t;
    EXPECT_EQ(find_homomorphisms(t.g, t.h, monic_d()).count, 2u);
    auto r = find_homomorphisms(t.g_prime, t.h, monic_d());
    EXPECT_EQ(r.count, 2u);
    for (const auto& m : r.morphisms) {
        EXPECT_TRUE(is_natural(m, t.g_prime, t.h));
        EXPECT_EQ(m.var(kD, 2), Value::var(2)); // the only variable left
    }
}

TEST(HomSearchLSet, NoBindEnumeratesFloatingVariablesOverCodomainVariables) {
    GH t;
    HomSearchOptions o;
    o.no_bind = {kD};
    auto r = find_homomorphisms(t.g_prime, t.h, o);
    EXPECT_EQ(r.count, 48u); // 4 * 4 * 3: bound variables still bind concrete values
    EXPECT_TRUE(r.error.empty());
}

// ---- WeightedGraph{Bool} -------------------------------------------------------------------

SchemaPtr weighted_graph_schema() {
    static SchemaPtr s = [] {
        auto g = std::make_shared<Schema>("WeightedGraph");
        ObId v = g->add_ob("V"), e = g->add_ob("E");
        g->add_hom("src", e, v);
        g->add_hom("tgt", e, v);
        AttrTypeId w = g->add_attr_type("Weight", ValueKind::Bool);
        g->add_attr("weight", e, w);
        return SchemaPtr(g);
    }();
    return s;
}

ACSet loops_with_weights(std::size_t nvars, const std::vector<Value>& weights) {
    ACSet g = make_graph(weighted_graph_schema(), 1, {});
    for (std::size_t i = 0; i < nvars; ++i) {
        g.add_var(AttrTypeId(0));
    }
    for (const Value& w : weights) {
        Part e = g.add_part(kE);
        g.set_subpart(kSrc, e, 0);
        g.set_subpart(kTgt, e, 0);
        g.set_subpart(AttrId(0), e, w);
    }
    return g;
}

TEST(HomSearchWeightedGraph, ConcreteMatchesEqualAndVariableMatchesAnything) {
    Value t = Value::boolean(true), f = Value::boolean(false);
    ACSet a = loops_with_weights(1, {t, Value::var(0)});
    ACSet b = loops_with_weights(2, {t, f, Value::var(1)});
    EXPECT_EQ(find_homomorphisms(a, b).count, 3u);
}

TEST(HomSearchWeightedGraph, SharedVariableMustAgree) {
    Value t = Value::boolean(true), f = Value::boolean(false);
    ACSet a = loops_with_weights(1, {f, Value::var(0), Value::var(0)});
    ACSet b = loops_with_weights(2, {f, t, t, Value::var(1)});
    auto r = find_homomorphisms(a, b);
    EXPECT_EQ(r.count, 6u);
    for (const auto& m : r.morphisms) {
        EXPECT_TRUE(is_natural(m, a, b));
    }
}

// ---- C-sets ----------------------------------------------------------------------------------

// g1 = path_graph(3) plus a loop on each vertex and a second 2 -> 3 edge; g2 = two 1 -> 2 edges.
struct G1G2 {
    ACSet g1 = make_graph(3, {{0, 1}, {1, 2}, {0, 0}, {1, 1}, {2, 2}, {1, 2}});
    ACSet g2 = make_graph(2, {{0, 1}, {0, 1}});
};

TEST(HomSearchCSet, Counts) {
    G1G2 t;
    EXPECT_EQ(count_homomorphisms(t.g2, t.g1).count, 8u);
    HomSearchOptions monic_v;
    monic_v.monic = {kV};
    EXPECT_EQ(count_homomorphisms(t.g2, t.g1, monic_v).count, 5u);
    HomSearchOptions monic_e;
    monic_e.monic = {kE};
    EXPECT_EQ(count_homomorphisms(t.g2, t.g1, monic_e).count, 2u);
    HomSearchOptions iso_e;
    iso_e.iso_obs = {kE};
    EXPECT_EQ(count_homomorphisms(t.g2, t.g1, iso_e).count, 0u);
    HomSearchOptions iso;
    iso.iso = true;
    EXPECT_EQ(count_homomorphisms(t.g2, t.g1, iso).count, 0u);
}

TEST(HomSearchCSet, CandidateSets) {
    G1G2 t;
    HomSearchOptions pv;
    pv.restrict(kV, 0, {0, 2});
    EXPECT_EQ(count_homomorphisms(t.g2, t.g1, pv).count, 3u);
    HomSearchOptions pe;
    pe.restrict(kE, 0, {0, 2});
    auto r = find_homomorphisms(t.g2, t.g1, pe);
    EXPECT_EQ(r.count, 2u);
    for (const auto& m : r.morphisms) {
        Part e0 = m(kE, 0);
        EXPECT_TRUE(e0 == 0 || e0 == 2);
    }
}

TEST(HomSearchCSet, CountDoesNotStoreMorphisms) {
    G1G2 t;
    auto r = count_homomorphisms(t.g2, t.g1);
    EXPECT_EQ(r.count, 8u);
    EXPECT_TRUE(r.morphisms.empty());
    EXPECT_TRUE(r.complete);
}

SchemaPtr symmetric_graph_schema() {
    static SchemaPtr s = [] {
        auto g = std::make_shared<Schema>("SymmetricGraph");
        ObId v = g->add_ob("V"), e = g->add_ob("E");
        HomId src = g->add_hom("src", e, v);
        HomId tgt = g->add_hom("tgt", e, v);
        HomId inv = g->add_hom("inv", e, e);
        g->add_equation({"", schema::Path{e, {inv, inv}, {}}, schema::Path{e, {}, {}}, {}});
        g->add_equation({"", schema::Path{e, {inv, src}, {}}, schema::Path{e, {tgt}, {}}, {}});
        return SchemaPtr(g);
    }();
    return s;
}

// Catlab's path_graph(SymmetricGraph, n): edge i and its inverse n-1+i.
ACSet symmetric_path(std::size_t n) {
    std::vector<std::pair<Part, Part>> edges;
    for (Part i = 0; i + 1 < n; ++i) {
        edges.emplace_back(i, i + 1);
    }
    for (Part i = 0; i + 1 < n; ++i) {
        edges.emplace_back(i + 1, i);
    }
    ACSet g = make_graph(symmetric_graph_schema(), n, edges);
    Part m = static_cast<Part>(n - 1);
    for (Part i = 0; i < m; ++i) {
        g.set_subpart(HomId(2), i, i + m);
        g.set_subpart(HomId(2), i + m, i);
    }
    return g;
}

TEST(HomSearchCSet, SymmetricPathEndomorphismsAndAutomorphisms) {
    ACSet p = symmetric_path(4);
    EXPECT_EQ(count_homomorphisms(p, p).count, 16u);
    HomSearchOptions iso;
    iso.iso = true;
    auto autos = find_homomorphisms(p, p, iso);
    ASSERT_EQ(autos.count, 2u);
    EXPECT_EQ(autos.morphisms[0], identity(p));
    EXPECT_EQ(autos.morphisms[1].components[0], (std::vector<Part>{3, 2, 1, 0}));
    EXPECT_TRUE(is_iso(autos.morphisms[1], p, p));
}

TEST(HomSearchCSet, GraphColouring) {
    EXPECT_TRUE(is_homomorphic(cycle_graph(5), complete_graph(3)));
    EXPECT_FALSE(is_homomorphic(cycle_graph(5), complete_graph(2)));
    EXPECT_TRUE(is_homomorphic(cycle_graph(6), complete_graph(2)));
    auto m = find_homomorphism(cycle_graph(5), complete_graph(3));
    ASSERT_TRUE(m.has_value());
    EXPECT_TRUE(is_natural(*m, cycle_graph(5), complete_graph(3)));
    auto none = find_homomorphism(cycle_graph(5), complete_graph(2));
    ASSERT_FALSE(none.has_value());
    EXPECT_EQ(none.error(), "no homomorphism exists");
}

TEST(HomSearchCSet, ResultOrderIsDeterministicAndLexicographic) {
    auto r = find_homomorphisms(path_graph(3), path_graph(4));
    ASSERT_EQ(r.count, 2u);
    EXPECT_EQ(r.morphisms[0].components[0], (std::vector<Part>{0, 1, 2}));
    EXPECT_EQ(r.morphisms[0].components[1], (std::vector<Part>{0, 1}));
    EXPECT_EQ(r.morphisms[1].components[0], (std::vector<Part>{1, 2, 3}));
    EXPECT_EQ(r.morphisms[1].components[1], (std::vector<Part>{1, 2}));
}

TEST(HomSearchCSet, InitialPartBindings) {
    HomSearchOptions o;
    o.bind(kV, 0, 1);
    auto r = find_homomorphisms(path_graph(3), path_graph(4), o);
    ASSERT_EQ(r.count, 1u);
    EXPECT_EQ(r.morphisms[0].components[0], (std::vector<Part>{1, 2, 3}));
    HomSearchOptions bad;
    bad.bind(kV, 0, 3); // vertex 4 has no outgoing edge
    EXPECT_EQ(count_homomorphisms(path_graph(3), path_graph(4), bad).count, 0u);
    HomSearchOptions clash;
    clash.bind(kE, 0, 0).bind(kV, 1, 2); // edge 1 -> 1 forces vertex 2 -> 2
    EXPECT_EQ(count_homomorphisms(path_graph(3), path_graph(4), clash).count, 0u);
}

TEST(HomSearchCSet, UnsetDomainHomValueImposesNoConstraint) {
    ACSet x = make_graph(1, {});
    Part e = x.add_part(kE);
    x.set_subpart(kSrc, e, 0); // tgt unset
    ACSet y = make_graph(2, {{0, 1}, {1, 1}});
    // e may go to either edge of y, and vertex 1 follows its source.
    EXPECT_EQ(count_homomorphisms(x, y).count, 2u);
    // A set domain value never meets an unset codomain value.
    ACSet y2 = make_graph(2, {});
    Part e2 = y2.add_part(kE);
    y2.set_subpart(kTgt, e2, 0);
    EXPECT_EQ(count_homomorphisms(x, y2).count, 0u);
}

TEST(HomSearchCSet, MaxResultsAndNodeLimitStopTheSearch) {
    ACSet x = make_graph(3, {});
    ACSet y = make_graph(3, {});
    HomSearchOptions o;
    o.max_results = 5;
    auto r = find_homomorphisms(x, y, o);
    EXPECT_EQ(r.count, 5u);
    EXPECT_EQ(r.morphisms.size(), 5u);
    EXPECT_FALSE(r.complete);
    HomSearchOptions n;
    n.node_limit = 4;
    auto rn = count_homomorphisms(x, y, n);
    EXPECT_FALSE(rn.complete);
    EXPECT_LE(rn.stats.nodes, 4u);
    EXPECT_LT(rn.count, 27u);
    EXPECT_EQ(count_homomorphisms(x, y).count, 27u);
    auto first = find_homomorphism(x, y, n);
    EXPECT_TRUE(first.has_value());
}

TEST(HomSearchCSet, CallbackCanStop) {
    std::vector<std::vector<Part>> seen;
    auto r =
        for_each_homomorphism(path_graph(2), complete_graph(3), {}, [&](const ACSetMorphism& m) {
            seen.push_back(m.components[0]);
            return seen.size() < 4;
        });
    EXPECT_EQ(r.count, 4u);
    EXPECT_FALSE(r.complete);
    EXPECT_TRUE(r.morphisms.empty());
    ASSERT_EQ(seen.size(), 4u);
    EXPECT_EQ(seen[0], (std::vector<Part>{0, 1}));
    auto all = count_homomorphisms(path_graph(2), complete_graph(3));
    EXPECT_EQ(all.count, 6u);
}

// A thread's searches reuse the tables of the ones before (search_engine.cpp): a search inside
// another's callback, and searches between states of other sizes, count as if each were first.
TEST(HomSearchCSet, NestedAndSuccessiveSearchesEachCountAlone) {
    HomSearchOptions monic;
    monic.monic_all = true;
    HomSearchOptions bound;
    bound.bind(kV, 0, 2).bind(kV, 1, 3); // the edge 2 -> 3 of K4
    std::vector<std::uint64_t> inner;
    auto outer =
        for_each_homomorphism(path_graph(2), complete_graph(3), {}, [&](const ACSetMorphism&) {
            inner.push_back(count_homomorphisms(cycle_graph(3), complete_graph(4), monic).count);
            inner.push_back(count_homomorphisms(path_graph(2), complete_graph(4), bound).count);
            return true;
        });
    EXPECT_EQ(outer.count, 6u);
    ASSERT_EQ(inner.size(), 12u);
    for (std::size_t i = 0; i < inner.size(); i += 2) {
        EXPECT_EQ(inner[i], 24u);
        EXPECT_EQ(inner[i + 1], 1u);
    }
    // Larger, then smaller, then larger again: no stale image, candidate or index survives.
    EXPECT_EQ(count_homomorphisms(path_graph(3), complete_graph(5), monic).count, 60u);
    EXPECT_EQ(count_homomorphisms(path_graph(2), complete_graph(2), monic).count, 2u);
    EXPECT_EQ(count_homomorphisms(path_graph(2), complete_graph(4), bound).count, 1u);
    EXPECT_EQ(count_homomorphisms(cycle_graph(3), complete_graph(4), monic).count, 24u);
}

TEST(HomSearchCSet, EmptyDomainHasExactlyOneMorphism) {
    ACSet empty(graph_schema());
    EXPECT_EQ(count_homomorphisms(empty, complete_graph(3)).count, 1u);
    EXPECT_EQ(count_homomorphisms(empty, empty).count, 1u);
    EXPECT_EQ(count_homomorphisms(path_graph(1), empty).count, 0u);
}

TEST(HomSearchCSet, TrianglesInCompleteGraph) {
    HomSearchOptions o;
    o.monic_all = true;
    // Directed 3-cycles in K4 (both directions present): 4 * 3 * 2 ordered triples.
    EXPECT_EQ(count_homomorphisms(cycle_graph(3), complete_graph(4), o).count, 24u);
}

TEST(HomSearchCSet, CompositeKeyLookupKeepsTheSearchSmall) {
    // Once both ends of the closing edge of a 3-cycle are fixed, its candidates come from one
    // hash lookup: the search tries about |V| * deg^2 assignments, not |V| * deg^2 * |E|.
    ACSet g = random_graph(30, 0.5, 3);
    HomSearchOptions o;
    o.monic_all = true;
    auto r = count_homomorphisms(cycle_graph(3), g, o);
    EXPECT_GT(r.count, 0u);
    EXPECT_LT(r.stats.nodes, 20000u); // about 9000; trying every edge would be 900000
}

// A small pattern in a large state takes the sparse paths of the engine (injectivity by a scan,
// no composite-key index); the counts must not change.
TEST(HomSearchLarge, SmallPatternInALargeStateCountsExactly) {
    std::vector<std::pair<Part, Part>> edges;
    Part n = 0;
    for (int t = 0; t < 1000; ++t, n += 3) {
        edges.push_back({n, n + 1});
        edges.push_back({n + 1, n + 2});
        edges.push_back({n + 2, n});
    }
    for (int l = 0; l < 500; ++l, ++n) {
        edges.push_back({n, n});
    }
    ACSet big = make_graph(n, edges);
    ACSet c3 = cycle_graph(3);
    HomSearchOptions monic;
    monic.monic_all = true;
    EXPECT_EQ(count_homomorphisms(c3, big, monic).count, 3000u);
    EXPECT_EQ(count_homomorphisms(c3, big).count, 3500u);
    HomSearchOptions bound = monic;
    bound.bind(ObId(0), 0, 3); // vertex a at the first vertex of the second triangle
    EXPECT_EQ(count_homomorphisms(c3, big, bound).count, 1u);
}

} // namespace
} // namespace catplan::hom
