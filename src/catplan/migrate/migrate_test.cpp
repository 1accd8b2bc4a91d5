// Migration tests: the reference's examples (DataMigrations.jl test/Migrations.jl), the paper's
// case study, map validation, rules and matches, and seeded properties of Δ on morphisms.

#include "catplan/colimit/colimit.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>

namespace catplan::migrate {
namespace {

using schema::Schema;
using schema::ValueKind;

// ---- schemas -----------------------------------------------------------------------------------

struct Graph {
    SchemaPtr s;
    ObId v, e;
    HomId src, tgt;
    AttrTypeId weight_t;
    AttrId weight;
};

Graph graph_schema(bool weighted) {
    auto s = std::make_shared<Schema>(weighted ? "WeightedGraph" : "Graph");
    Graph g;
    g.v = s->add_ob("V");
    g.e = s->add_ob("E");
    g.src = s->add_hom("src", g.e, g.v);
    g.tgt = s->add_hom("tgt", g.e, g.v);
    if (weighted) {
        g.weight_t = s->add_attr_type("Weight", ValueKind::Float);
        g.weight = s->add_attr("weight", g.e, g.weight_t);
    }
    g.s = s;
    return g;
}

ACSet path_graph(const Graph& g, std::size_t n, std::vector<double> weights = {}) {
    ACSet x(g.s);
    x.add_parts(g.v, n);
    for (Part i = 0; i + 1 < n; ++i) {
        Part e = x.add_part(g.e);
        x.set_subpart(g.src, e, i);
        x.set_subpart(g.tgt, e, i + 1);
        if (!weights.empty()) {
            x.set_subpart(g.weight, e, Value::real(weights[i]));
        }
    }
    return x;
}

std::vector<MapProblem> errors_of(const std::vector<MapProblem>& ps) {
    std::vector<MapProblem> out;
    for (const auto& p : ps) {
        if (p.severity == Severity::Error) {
            out.push_back(p);
        }
    }
    return out;
}

std::string describe(const std::vector<MapProblem>& ps) {
    std::string s;
    for (const auto& p : ps) {
        s += p.message + "\n";
    }
    return s;
}

// ---- (a) paths of length 2 ---------------------------------------------------------------------

SchemaMap paths_of_length_two(const Graph& g) {
    SchemaMap m(g.s, g.s);
    m.map_ob(g.v, g.v);
    Query q(g.s);
    q.add_variable("v", g.v);
    q.add_variable("e1", g.e);
    q.add_variable("e2", g.e);
    q.add_equation(Term::path("e1", {g.tgt}), Term::path("v"));
    q.add_equation(Term::path("e2", {g.src}), Term::path("v"));
    if (g.weight_t.index() != UINT32_MAX) {
        q.add_value_variable("w", g.weight_t);
        q.add_equation(Term::path("e1", {}, g.weight), Term::path("w"));
        q.add_equation(Term::path("e2", {}, g.weight), Term::path("w"));
        m.map_attr_type(g.weight_t, g.weight_t);
        m.map_attr(g.weight, Term::path("w"));
    }
    m.map_ob(g.e, std::move(q));
    m.map_hom(g.src, {Term::path("e1", {g.src})});
    m.map_hom(g.tgt, {Term::path("e2", {g.tgt})});
    auto problems = m.finish();
    EXPECT_TRUE(m.ok()) << describe(problems);
    return m;
}

TEST(ReferenceExamples, PathsOfLengthTwo) {
    Graph g = graph_schema(false);
    SchemaMap m = paths_of_length_two(g);
    EXPECT_FALSE(m.is_delta());
    ACSet h = migrate(m, path_graph(g, 5));
    ASSERT_EQ(h.num_parts(g.v), 5u);
    ASSERT_EQ(h.num_parts(g.e), 3u);
    std::vector<std::pair<Part, Part>> edges;
    for (Part e = 0; e < 3; ++e) {
        edges.emplace_back(h.subpart(g.src, e), h.subpart(g.tgt, e));
    }
    // Already in order: tuples are sorted by (v, e1, e2).
    EXPECT_EQ(edges, (std::vector<std::pair<Part, Part>>{{0, 2}, {1, 3}, {2, 4}}));
}

TEST(ReferenceExamples, WeightedPathsOfLengthTwo) {
    Graph g = graph_schema(true);
    SchemaMap m = paths_of_length_two(g);
    ACSet h = migrate(m, path_graph(g, 6, {0.5, 0.5, 1.5, 1.5, 1.5}));
    ASSERT_EQ(h.num_parts(g.v), 6u);
    ASSERT_EQ(h.num_parts(g.e), 3u);
    std::vector<std::tuple<Part, Part, double>> edges;
    for (Part e = 0; e < 3; ++e) {
        edges.emplace_back(h.subpart(g.src, e), h.subpart(g.tgt, e),
                           h.subpart(g.weight, e).as_float());
    }
    std::sort(edges.begin(), edges.end());
    EXPECT_EQ(edges,
              (std::vector<std::tuple<Part, Part, double>>{{0, 2, 0.5}, {2, 4, 1.5}, {3, 5, 1.5}}));
}

// ---- (b) filter and constant attributes --------------------------------------------------------

TEST(ReferenceExamples, FilterAndConstantAttributes) {
    auto src = std::make_shared<Schema>("AttrSet");
    ObId x = src->add_ob("X");
    AttrTypeId label = src->add_attr_type("Label", ValueKind::String);
    AttrId has_label = src->add_attr("hasLabel", x, label);
    AttrTypeId my_bool = src->add_attr_type("MyBool", ValueKind::Bool);
    AttrTypeId my_string = src->add_attr_type("MyString", ValueKind::String);
    auto tgt = std::make_shared<Schema>("AttrSet2");
    ObId tx = tgt->add_ob("X"), ty = tgt->add_ob("Y");
    HomId m_hom = tgt->add_hom("m", ty, tx);
    AttrTypeId a = tgt->add_attr_type("A"), b = tgt->add_attr_type("B");
    AttrId f = tgt->add_attr("f", ty, a), gattr = tgt->add_attr("g", ty, b);

    SchemaMap m(tgt, src);
    m.map_ob(tx, x);
    Query q(src);
    q.add_variable("x", x);
    q.add_value_variable("L", label);
    q.add_equation(Term::path("x", {}, has_label), Term::path("L"));
    q.add_equation(Term::path("L"), Term::constant(Value::string("foo")));
    m.map_ob(ty, std::move(q));
    m.map_hom(m_hom, {Term::path("x")});
    m.map_attr_type(a, my_bool);
    m.map_attr_constant(f, Value::boolean(false));
    m.map_attr_type(b, my_string);
    m.map_attr_constant(gattr, Value::string("unknown"));
    auto problems = m.finish();
    ASSERT_TRUE(m.ok()) << describe(problems);

    ACSet t(src);
    t.add_parts(x, 2);
    t.set_subpart(has_label, 0, Value::string("foo"));
    t.set_subpart(has_label, 1, Value::string("bar"));
    ACSet s = migrate(m, t);
    ASSERT_EQ(s.num_parts(ty), 1u);
    EXPECT_EQ(s.num_parts(tx), 2u);
    EXPECT_EQ(s.subpart(m_hom, 0), 0u);
    EXPECT_EQ(s.subpart(f, 0), Value::boolean(false));
    EXPECT_EQ(s.subpart(gattr, 0), Value::string("unknown"));
}

TEST(ReferenceExamples, ConstantAttributeIntoSchemaWithoutEdges) {
    auto src = std::make_shared<Schema>("NattrSet");
    ObId x = src->add_ob("X");
    AttrTypeId at = src->add_attr_type("A", ValueKind::Float);
    Graph g = graph_schema(true);
    SchemaMap m(g.s, src);
    m.map_ob(g.v, x);
    m.map_ob(g.e, x);
    m.map_hom_path(g.src, {});
    m.map_hom_path(g.tgt, {});
    m.map_attr_type(g.weight_t, at);
    m.map_attr_constant(g.weight, Value::real(7.0));
    auto problems = m.finish();
    ASSERT_TRUE(m.ok()) << describe(problems);
    // id(X) images are legal but reported as warnings.
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_EQ(problems[0].kind, MapProblemKind::IdentityImage);
    EXPECT_EQ(problems[0].severity, Severity::Warning);
    EXPECT_TRUE(m.is_delta());
    ACSet n(src);
    n.add_parts(x, 5);
    ACSet y = migrate(m, n);
    EXPECT_EQ(y.num_parts(g.v), 5u);
    EXPECT_EQ(y.num_parts(g.e), 5u);
    for (Part e = 0; e < 5; ++e) {
        EXPECT_EQ(y.subpart(g.weight, e), Value::real(7.0));
        EXPECT_EQ(y.subpart(g.src, e), e);
    }
}

// ---- (c) filter-split into is-a homs -----------------------------------------------------------

struct Split {
    SchemaPtr src, tgt;
    ObId x, thing, a, b;
    AttrId has_label;
    HomId a_is, b_is;
};

Split split_schemas() {
    Split s;
    auto src = std::make_shared<Schema>("WithLabel");
    s.x = src->add_ob("X");
    AttrTypeId label = src->add_attr_type("Label", ValueKind::String);
    s.has_label = src->add_attr("hasLabel", s.x, label);
    auto tgt = std::make_shared<Schema>("SplitWithDefault");
    s.thing = tgt->add_ob("Thing");
    s.a = tgt->add_ob("A");
    s.b = tgt->add_ob("B");
    s.a_is = tgt->add_hom("aIsThing", s.a, s.thing);
    s.b_is = tgt->add_hom("bIsThing", s.b, s.thing);
    s.src = src;
    s.tgt = tgt;
    return s;
}

SchemaMap split_map(const Split& s) {
    SchemaMap m(s.tgt, s.src);
    m.map_ob(s.thing, s.x);
    for (auto [ob, hom, lit] : {std::tuple{s.a, s.a_is, "A"}, std::tuple{s.b, s.b_is, "B"}}) {
        Query q(s.src);
        q.add_variable("x", s.x);
        q.add_value_variable("L", AttrTypeId(0));
        q.add_equation(Term::path("x", {}, s.has_label), Term::path("L"));
        q.add_equation(Term::path("L"), Term::constant(Value::string(lit)));
        m.map_ob(ob, std::move(q));
        m.map_hom(hom, {Term::path("x")});
    }
    auto problems = m.finish();
    EXPECT_TRUE(m.ok()) << describe(problems);
    return m;
}

TEST(ReferenceExamples, FilterSplit) {
    Split s = split_schemas();
    SchemaMap m = split_map(s);
    ACSet data1(s.src);
    data1.add_part(s.x, "x");
    data1.set_subpart(s.has_label, 0, Value::string("A"));
    ACSet out1 = migrate(m, data1);
    EXPECT_EQ(out1.num_parts(s.thing), 1u);
    EXPECT_EQ(out1.num_parts(s.a), 1u);
    EXPECT_EQ(out1.num_parts(s.b), 0u);
    EXPECT_EQ(out1.subpart(s.a_is, 0), 0u);
    EXPECT_EQ(out1.part_name(s.a, 0), "x");

    ACSet data2(s.src);
    data2.add_part(s.x, "x1");
    data2.add_part(s.x, "x2");
    data2.set_subpart(s.has_label, 0, Value::string("A"));
    data2.set_subpart(s.has_label, 1, Value::string("C"));
    ACSet out2 = migrate(m, data2);
    EXPECT_EQ(out2.num_parts(s.thing), 2u);
    EXPECT_EQ(out2.num_parts(s.a), 1u);
    EXPECT_EQ(out2.num_parts(s.b), 0u);
}

TEST(ReferenceExamples, VariableNeverPassesALiteralFilter) {
    Split s = split_schemas();
    SchemaMap m = split_map(s);
    ACSet data(s.src);
    data.add_part(s.x, "x");
    data.set_subpart(s.has_label, 0, data.add_var(AttrTypeId(0)));
    ACSet out = migrate(m, data);
    EXPECT_EQ(out.num_parts(s.thing), 1u);
    EXPECT_EQ(out.num_parts(s.a), 0u);
    EXPECT_EQ(out.num_parts(s.b), 0u);
}

// ---- (d) unit and empty queries ----------------------------------------------------------------

TEST(ReferenceExamples, BouquetFromUnit) {
    auto set = std::make_shared<Schema>("Set");
    ObId x = set->add_ob("X");
    Graph g = graph_schema(false);
    SchemaMap m(g.s, set);
    m.map_ob(g.v, Query(set)); // @unit
    m.map_ob(g.e, x);
    m.map_hom(g.src, {});
    m.map_hom(g.tgt, {});
    auto problems = m.finish();
    ASSERT_TRUE(m.ok()) << describe(problems);
    ACSet five(set);
    five.add_parts(x, 5);
    ACSet y = migrate(m, five);
    EXPECT_EQ(y.num_parts(g.v), 1u);
    ASSERT_EQ(y.num_parts(g.e), 5u);
    for (Part e = 0; e < 5; ++e) {
        EXPECT_EQ(y.subpart(g.src, e), 0u);
        EXPECT_EQ(y.subpart(g.tgt, e), 0u);
    }
}

TEST(ReferenceExamples, EmptyQuery) {
    auto set = std::make_shared<Schema>("Set");
    ObId x = set->add_ob("X");
    Graph g = graph_schema(false);
    SchemaMap m(g.s, set);
    m.map_ob(g.v, x);
    Query empty(set);
    empty.set_empty();
    m.map_ob(g.e, std::move(empty)); // src and tgt need no image
    auto problems = m.finish();
    ASSERT_TRUE(m.ok()) << describe(problems);
    ACSet five(set);
    five.add_parts(x, 5);
    ACSet y = migrate(m, five);
    EXPECT_EQ(y.num_parts(g.v), 5u);
    EXPECT_EQ(y.num_parts(g.e), 0u);
}

// ---- validation --------------------------------------------------------------------------------

TEST(Validation, ReportsEveryProblemWithItsGenerator) {
    Graph g = graph_schema(true);
    auto src = std::make_shared<Schema>("Src");
    ObId a = src->add_ob("A"), b = src->add_ob("B");
    HomId ab = src->add_hom("ab", a, b);
    AttrTypeId str = src->add_attr_type("Str", ValueKind::String);
    AttrId name = src->add_attr("name", a, str);
    SchemaMap m(g.s, src);
    m.map_ob(g.v, b);
    m.map_ob(g.e, a);
    m.map_hom_path(g.src, {ab});
    m.map_hom_path(g.tgt, {}); // wrong ends: id(A) does not end at B
    m.map_attr_type(g.weight_t, ValueKind::Float);
    m.map_attr(g.weight, Term::path("E", {}, name)); // not a constant into a kind-only type
    auto problems = errors_of(m.finish());
    ASSERT_EQ(problems.size(), 2u) << describe(problems);
    EXPECT_EQ(problems[0].kind, MapProblemKind::WrongEnds);
    EXPECT_EQ(problems[0].target.kind, GeneratorKind::Hom);
    EXPECT_EQ(problems[0].target.index, g.tgt.index());
    EXPECT_EQ(problems[1].kind, MapProblemKind::NotConstant);
    EXPECT_EQ(problems[1].target.kind, GeneratorKind::Attr);
    EXPECT_FALSE(m.ok());

    SchemaMap unmapped(g.s, src);
    unmapped.map_ob(g.v, b);
    auto ps = errors_of(unmapped.finish());
    // E, Weight, src, tgt, weight.
    EXPECT_EQ(ps.size(), 5u) << describe(ps);
    for (const auto& p : ps) {
        EXPECT_EQ(p.kind, MapProblemKind::Unmapped);
    }
}

TEST(Validation, WrongKindConstantAndConflictingLiterals) {
    Split s = split_schemas();
    SchemaMap m(s.tgt, s.src);
    m.map_ob(s.thing, s.x);
    Query q(s.src);
    q.add_variable("x", s.x);
    q.add_equation(Term::path("x", {}, s.has_label), Term::constant(Value::string("A")));
    EXPECT_FALSE(
        q.add_equation(Term::path("x", {}, s.has_label), Term::constant(Value::string("B"))));
    m.map_ob(s.a, std::move(q));
    m.map_ob(s.b, s.x);
    m.map_hom(s.a_is, {Term::path("x")});
    m.map_hom(s.b_is, {Term::path("nope")});
    auto ps = errors_of(m.finish());
    ASSERT_EQ(ps.size(), 2u) << describe(ps);
    EXPECT_EQ(ps[0].kind, MapProblemKind::BadQuery); // two literals
    EXPECT_EQ(ps[0].target.index, s.a.index());
    EXPECT_EQ(ps[1].kind, MapProblemKind::BadQuery); // unknown variable
    EXPECT_EQ(ps[1].target.kind, GeneratorKind::Hom);
}

TEST(Validation, EquationsMustBePreserved) {
    // Target: a reflexive graph (refl ; src == id, refl ; tgt == id).
    auto rg = std::make_shared<Schema>("ReflexiveGraph");
    ObId v = rg->add_ob("V"), e = rg->add_ob("E");
    HomId src = rg->add_hom("src", e, v), tgt = rg->add_hom("tgt", e, v);
    HomId refl = rg->add_hom("refl", v, e);
    rg->add_equation({"", {v, {refl, src}, std::nullopt}, {v, {}, std::nullopt}, {}});
    rg->add_equation({"", {v, {refl, tgt}, std::nullopt}, {v, {}, std::nullopt}, {}});
    Graph g = graph_schema(false);
    // E => E, V => V, refl => ? has no delta image in Graph; map V => E as well to test paths.
    SchemaMap good(rg, g.s);
    good.map_ob(v, g.v);
    good.map_ob(e, g.v);
    good.map_hom_path(src, {});
    good.map_hom_path(tgt, {});
    good.map_hom_path(refl, {});
    auto ps = errors_of(good.finish());
    EXPECT_TRUE(ps.empty()) << describe(ps);

    // Every target generator to E and identities: the equations hold too.
    SchemaMap worse(rg, g.s);
    worse.map_ob(v, g.e);
    worse.map_ob(e, g.e);
    worse.map_hom_path(src, {});
    worse.map_hom_path(tgt, {});
    worse.map_hom_path(refl, {});
    EXPECT_TRUE(errors_of(worse.finish()).empty());

    auto loop = std::make_shared<Schema>("Loop");
    ObId l = loop->add_ob("L");
    HomId next = loop->add_hom("next", l, l);
    SchemaMap broken(rg, loop);
    broken.map_ob(v, l);
    broken.map_ob(e, l);
    broken.map_hom_path(src, {});
    broken.map_hom_path(tgt, {next});
    broken.map_hom_path(refl, {});
    auto bps = errors_of(broken.finish());
    ASSERT_EQ(bps.size(), 1u) << describe(bps);
    EXPECT_EQ(bps[0].kind, MapProblemKind::EquationNotPreserved);
}

// ---- the paper's case study --------------------------------------------------------------------

struct Blocks {
    SchemaPtr s;
    ObId block, empty, gripper, on;
    AttrTypeId color, clear, on_table;
    HomId on_l, on_r, is_empty, is_holding;
    AttrId has_color, is_clear, is_on_table;
};

Blocks blocks_schema() {
    auto s = std::make_shared<Schema>("ColorBlocksworld");
    Blocks b;
    b.block = s->add_ob("Block");
    b.empty = s->add_ob("Empty");
    b.gripper = s->add_ob("Gripper");
    b.color = s->add_attr_type("Color", ValueKind::String);
    b.clear = s->add_attr_type("Clear", ValueKind::Bool);
    b.on_table = s->add_attr_type("OnTable", ValueKind::Bool);
    b.on = s->add_ob("On");
    b.on_l = s->add_hom("on_l", b.on, b.block);
    b.on_r = s->add_hom("on_r", b.on, b.block);
    b.is_empty = s->add_hom("isEmpty", b.empty, b.block);
    b.is_holding = s->add_hom("isHolding", b.gripper, b.block);
    b.has_color = s->add_attr("hasColor", b.block, b.color);
    b.is_clear = s->add_attr("isClear", b.block, b.clear);
    b.is_on_table = s->add_attr("isOnTable", b.block, b.on_table);
    b.s = s;
    return b;
}

// Table 1, left column: the hand-empty marker is the block isHolding(gripper) == isEmpty(empty),
// an unnamed block whose attributes are unknown.
ACSet initial_state(const Blocks& b) {
    ACSet x(b.s);
    const char* names[] = {"A", "B", "C", "D", "E", "F"};
    const char* colors[] = {"green", "red", "yellow", "purple", "purple", "blue"};
    const bool table[] = {true, true, true, false, false, true};
    const bool clear[] = {true, true, false, false, true, true};
    for (int i = 0; i < 6; ++i) {
        Part p = x.add_part(b.block, names[i]);
        x.set_subpart(b.has_color, p, Value::string(colors[i]));
        x.set_subpart(b.is_on_table, p, Value::boolean(table[i]));
        x.set_subpart(b.is_clear, p, Value::boolean(clear[i]));
    }
    Part null = x.add_part(b.block);
    x.set_subpart(b.has_color, null, x.add_var(b.color));
    x.set_subpart(b.is_clear, null, x.add_var(b.clear));
    x.set_subpart(b.is_on_table, null, x.add_var(b.on_table));
    Part gr = x.add_part(b.gripper, "gripper");
    Part em = x.add_part(b.empty, "empty");
    x.set_subpart(b.is_holding, gr, null);
    x.set_subpart(b.is_empty, em, null);
    Part x1 = x.add_part(b.on, "x1"), x2 = x.add_part(b.on, "x2");
    x.set_subpart(b.on_l, x1, 4); // E on D
    x.set_subpart(b.on_r, x1, 3);
    x.set_subpart(b.on_l, x2, 3); // D on C
    x.set_subpart(b.on_r, x2, 2);
    return x;
}

struct Kitchen {
    SchemaPtr s;
    ObId object, receptacle, empty, gripper, in_receptacle;
    HomId is_holding, is_empty, in_l, in_r;
    AttrTypeId temperature, mass, material;

    struct Food {
        std::string name, color;
        ObId ob;
        HomId is_object;
        std::optional<HomId> is_receptacle;
        AttrId temp, mass, material;
    };

    std::vector<Food> foods;
};

Kitchen kitchen_schema() {
    auto s = std::make_shared<Schema>("KitchenWorld");
    Kitchen k;
    k.object = s->add_ob("Object");
    k.receptacle = s->add_ob("Receptacle");
    k.empty = s->add_ob("Empty");
    k.gripper = s->add_ob("Gripper");
    k.is_holding = s->add_hom("isHolding", k.gripper, k.object);
    k.is_empty = s->add_hom("isEmpty", k.empty, k.object);
    k.temperature = s->add_attr_type("Temperature", ValueKind::Float);
    k.mass = s->add_attr_type("Mass", ValueKind::Float);
    k.material = s->add_attr_type("Material", ValueKind::String);
    k.in_receptacle = s->add_ob("InReceptacle");
    k.in_l = s->add_hom("inReceptacle_l", k.in_receptacle, k.object);
    k.in_r = s->add_hom("inReceptacle_r", k.in_receptacle, k.receptacle);
    for (auto [name, color, recept] :
         {std::tuple{"BreadSliced", "purple", true}, std::tuple{"LettuceSliced", "green", true},
          std::tuple{"TomatoSliced", "red", true}, std::tuple{"Plate", "yellow", true},
          std::tuple{"Knife", "blue", false}}) {
        Kitchen::Food f;
        f.name = name;
        f.color = color;
        f.ob = s->add_ob(name);
        f.is_object = s->add_hom(f.name + "IsObject", f.ob, k.object);
        if (recept) {
            f.is_receptacle = s->add_hom(f.name + "IsReceptacle", f.ob, k.receptacle);
        }
        f.temp = s->add_attr(f.name + "HasTemperature", f.ob, k.temperature);
        f.mass = s->add_attr(f.name + "HasMass", f.ob, k.mass);
        f.material = s->add_attr(f.name + "HasMaterial", f.ob, k.material);
        k.foods.push_back(f);
    }
    k.s = s;
    return k;
}

SchemaMap kitchen_map(const Blocks& b, const Kitchen& k) {
    SchemaMap m(k.s, b.s);
    m.map_ob(k.object, b.block);
    m.map_ob(k.receptacle, b.block);
    m.map_ob(k.gripper, b.gripper);
    m.map_ob(k.empty, b.empty);
    m.map_ob(k.in_receptacle, b.on);
    m.map_hom_path(k.is_holding, {b.is_holding});
    m.map_hom_path(k.is_empty, {b.is_empty});
    m.map_hom_path(k.in_l, {b.on_l});
    m.map_hom_path(k.in_r, {b.on_r});
    m.map_attr_type(k.temperature, ValueKind::Float);
    m.map_attr_type(k.mass, ValueKind::Float);
    m.map_attr_type(k.material, ValueKind::String);
    for (const auto& f : k.foods) {
        // The paper's form: block::Block; C::Color; (hc: block → C)::hasColor; C == colour.
        Query q(b.s);
        q.add_variable("block", b.block);
        q.add_value_variable("C", b.color);
        q.add_equation(Term::path("block", {}, b.has_color), Term::path("C"));
        q.add_equation(Term::path("C"), Term::constant(Value::string(f.color)));
        m.map_ob(f.ob, std::move(q));
        m.map_hom(f.is_object, {Term::path("block")});
        if (f.is_receptacle) {
            m.map_hom(*f.is_receptacle, {Term::path("block")});
        }
        m.map_attr_constant(f.temp, Value::real(0.0));
        m.map_attr_constant(f.mass, Value::real(0.0));
        m.map_attr_constant(f.material, Value::string("Unknown"));
    }
    auto problems = m.finish();
    EXPECT_TRUE(problems.empty()) << describe(problems);
    return m;
}

TEST(CaseStudy, TransferredInitialStateIsTableOneRightColumn) {
    Blocks b = blocks_schema();
    Kitchen k = kitchen_schema();
    SchemaMap m = kitchen_map(b, k);
    EXPECT_FALSE(m.is_delta());
    ACSet x = initial_state(b);
    ACSet y = migrate(m, x);
    auto names = [&](ObId ob) {
        std::vector<std::string> out;
        for (Part p = 0; p < y.num_parts(ob); ++p) {
            out.emplace_back(y.part_label(ob, p));
        }
        return out;
    };
    using V = std::vector<std::string>;
    EXPECT_EQ(names(k.foods[0].ob), (V{"D", "E"}));
    EXPECT_EQ(names(k.foods[1].ob), (V{"A"}));
    EXPECT_EQ(names(k.foods[2].ob), (V{"B"}));
    EXPECT_EQ(names(k.foods[3].ob), (V{"C"}));
    EXPECT_EQ(names(k.foods[4].ob), (V{"F"}));
    // Every block is an Object and a Receptacle, the hand-empty marker too (the reference's trap).
    EXPECT_EQ(names(k.object), (V{"A", "B", "C", "D", "E", "F", "#7"}));
    EXPECT_EQ(names(k.receptacle), names(k.object));
    EXPECT_EQ(names(k.gripper), (V{"gripper"}));
    EXPECT_EQ(names(k.empty), (V{"empty"}));
    ASSERT_EQ(names(k.in_receptacle), (V{"x1", "x2"}));
    // x1: E on D, x2: D on C.
    EXPECT_EQ(y.part_label(k.object, y.subpart(k.in_l, 0)), "E");
    EXPECT_EQ(y.part_label(k.receptacle, y.subpart(k.in_r, 0)), "D");
    EXPECT_EQ(y.part_label(k.object, y.subpart(k.in_l, 1)), "D");
    EXPECT_EQ(y.part_label(k.receptacle, y.subpart(k.in_r, 1)), "C");
    // isHolding(gripper) == isEmpty(empty).
    EXPECT_EQ(y.subpart(k.is_holding, 0), y.subpart(k.is_empty, 0));
    // BreadSlicedIsObject(E) is the Object E; PlateIsReceptacle(C) the Receptacle C.
    EXPECT_EQ(y.part_label(k.object, y.subpart(k.foods[0].is_object, 1)), "E");
    EXPECT_EQ(y.part_label(k.receptacle, y.subpart(*k.foods[3].is_receptacle, 0)), "C");
    for (const auto& f : k.foods) {
        for (Part p = 0; p < y.num_parts(f.ob); ++p) {
            EXPECT_EQ(y.subpart(f.temp, p), Value::real(0.0));
            EXPECT_EQ(y.subpart(f.mass, p), Value::real(0.0));
            EXPECT_EQ(y.subpart(f.material, p), Value::string("Unknown"));
        }
    }
    // Clear and OnTable are not carried: the kitchen has no such types.
    EXPECT_EQ(y.total_parts(), 7u * 2 + 1 + 1 + 2 + 6);
}

TEST(CaseStudy, MigratedRuleAndMatch) {
    Blocks b = blocks_schema();
    Kitchen k = kitchen_schema();
    SchemaMap m = kitchen_map(b, k);
    // unstack(block, underblock): the hand is empty (holds the marker), block is clear and on
    // underblock; afterwards the gripper holds block, underblock is clear, On is deleted.
    rewrite::Rule rule(b.s);
    rule.name = "unstack";
    auto fill = [&](ACSet& s, bool pre) {
        Part blk = s.add_part(b.block, "block");
        Part under = s.add_part(b.block, "underblock");
        Part null = s.add_part(b.block, "null");
        for (Part p : {blk, under, null}) {
            (void)p;
        }
        return std::tuple{blk, under, null, pre};
    };
    auto [lb, lu, ln, _1] = fill(rule.L, true);
    Part lg = rule.L.add_part(b.gripper, "gripper");
    rule.L.set_subpart(b.is_holding, lg, ln);
    Part lo = rule.L.add_part(b.on, "o");
    rule.L.set_subpart(b.on_l, lo, lb);
    rule.L.set_subpart(b.on_r, lo, lu);
    rule.L.set_subpart(b.is_clear, lb, Value::boolean(true));
    rule.L.set_subpart(b.has_color, lb, rule.L.add_var(b.color, "c"));
    fill(rule.K, false);
    rule.K.set_subpart(b.has_color, 0, rule.K.add_var(b.color, "c"));
    fill(rule.R, false);
    rule.R.set_subpart(b.has_color, 0, rule.R.add_var(b.color, "c"));
    Part rg = rule.R.add_part(b.gripper, "gripper");
    rule.R.set_subpart(b.is_holding, rg, 0);
    rule.R.set_subpart(b.is_clear, 1, Value::boolean(true));
    rule.l = hom::identity(rule.K);
    rule.l.components[b.gripper.index()] = {};
    rule.l.components[b.on.index()] = {};
    rule.r = rule.l;
    rule.parameters = {{"block", b.block, lb}, {"underblock", b.block, lu}};
    ASSERT_TRUE(rewrite::check_rule(rule).empty());

    auto migrated = migrate(m, rule);
    ASSERT_TRUE(migrated) << migrated.error();
    const rewrite::Rule& kr = *migrated;
    EXPECT_EQ(kr.L.num_parts(k.object), 3u);
    EXPECT_EQ(kr.L.num_parts(k.in_receptacle), 1u);
    EXPECT_EQ(kr.K.num_parts(k.in_receptacle), 0u);
    // The colour is a variable, so no food type appears in the migrated rule.
    EXPECT_EQ(kr.L.num_parts(k.foods[0].ob), 0u);
    EXPECT_TRUE(hom::is_natural(kr.l, kr.K, kr.L));
    EXPECT_TRUE(hom::is_natural(kr.r, kr.K, kr.R));
    EXPECT_TRUE(rewrite::check_rule(kr).empty());
    // Parameters are carried by name to Object and Receptacle.
    ASSERT_EQ(kr.parameters.size(), 4u);
    EXPECT_EQ(kr.parameters[0].name, "block");
    EXPECT_EQ(kr.parameters[0].ob, k.object);
    EXPECT_EQ(kr.parameters[1].ob, k.receptacle);
    EXPECT_FALSE(kr.action.has_value());

    // The action a rule carries out comes along, each argument now the first migrated parameter
    // of its name (underblock's Object is parameter 2), so a step still names the action.
    rewrite::Rule variant = rule;
    variant.action = rewrite::ActionOf{"take", {{1, {}}, {0, {}}, {-1, "table"}}};
    auto mv = migrate(m, variant);
    ASSERT_TRUE(mv) << mv.error();
    ASSERT_TRUE(mv->action.has_value());
    EXPECT_EQ(mv->action->name, "take");
    using Arg = rewrite::ActionOf::Argument;
    EXPECT_EQ(mv->action->arguments, (std::vector<Arg>{{2, {}}, {0, {}}, {-1, "table"}}));
    ASSERT_EQ(mv->parameters[2].name, "underblock");

    // The match unstack(E, D) in the initial state, migrated, is a match of the migrated rule.
    ACSet x = initial_state(b);
    rewrite::MatchOptions opt;
    opt.initial = {{b.block, lb, 4}, {b.block, lu, 3}};
    auto matches = rewrite::find_matches(rule, x, opt);
    ASSERT_EQ(matches.size(), 1u);
    auto mm = migrate_match(m, rule, matches[0], x);
    ASSERT_TRUE(mm) << mm.error();
    ACSet y = migrate(m, x);
    EXPECT_TRUE(hom::is_natural(*mm, kr.L, y));
    EXPECT_EQ(rewrite::match_problem(kr, y, *mm), std::nullopt);
    // The step commutes with the migration (Object/Receptacle parts are a delta part of the map).
    auto step = rewrite::rewrite(rule, x, matches[0]);
    ASSERT_TRUE(step);
    auto kstep = rewrite::rewrite(kr, y, *mm);
    ASSERT_TRUE(kstep) << kstep.error();
    EXPECT_TRUE(hom::is_isomorphic(kstep->result, migrate(m, step->result)));
}

// ---- properties --------------------------------------------------------------------------------

constexpr int kSeeds = 100;

struct Gen {
    std::mt19937_64 rng;

    explicit Gen(std::uint64_t seed) : rng(seed) {}

    std::size_t below(std::size_t n) { return n == 0 ? 0 : rng() % n; }

    ACSet graph(const Graph& g, std::size_t max_v, std::size_t max_e) {
        ACSet x(g.s);
        std::size_t nv = 1 + below(max_v), ne = below(max_e + 1);
        x.add_parts(g.v, nv);
        for (std::size_t i = 0; i < ne; ++i) {
            Part e = x.add_part(g.e);
            x.set_subpart(g.src, e, static_cast<Part>(below(nv)));
            x.set_subpart(g.tgt, e, static_cast<Part>(below(nv)));
        }
        return x;
    }

    // A random morphism out of x: vertices to a random graph's vertices, each edge to a new edge
    // with the right ends, plus a few extra edges.
    std::pair<ACSet, hom::ACSetMorphism> morphism_from(const Graph& g, const ACSet& x) {
        ACSet y(g.s);
        std::size_t nv = 1 + below(x.num_parts(g.v) + 1);
        y.add_parts(g.v, nv);
        hom::ACSetMorphism a;
        a.components.resize(2);
        a.var_components.resize(g.s->num_attr_types());
        for (Part v = 0; v < x.num_parts(g.v); ++v) {
            a.components[g.v.index()].push_back(static_cast<Part>(below(nv)));
        }
        std::size_t extra = below(3);
        for (std::size_t i = 0; i < extra; ++i) {
            Part e = y.add_part(g.e);
            y.set_subpart(g.src, e, static_cast<Part>(below(nv)));
            y.set_subpart(g.tgt, e, static_cast<Part>(below(nv)));
        }
        for (Part e = 0; e < x.num_parts(g.e); ++e) {
            Part s = a.components[g.v.index()][x.subpart(g.src, e)];
            Part t = a.components[g.v.index()][x.subpart(g.tgt, e)];
            // Sometimes reuse an existing edge with the same ends (a non-injective component).
            Part image = kNoPart;
            if (below(2) == 0) {
                for (Part f = 0; f < y.num_parts(g.e); ++f) {
                    if (y.subpart(g.src, f) == s && y.subpart(g.tgt, f) == t) {
                        image = f;
                        break;
                    }
                }
            }
            if (image == kNoPart) {
                image = y.add_part(g.e);
                y.set_subpart(g.src, image, s);
                y.set_subpart(g.tgt, image, t);
            }
            a.components[g.e.index()].push_back(image);
        }
        return {std::move(y), std::move(a)};
    }
};

// A delta map Graph -> Graph: reverse the edges.
SchemaMap reverse_map(const Graph& g) {
    SchemaMap m(g.s, g.s);
    m.map_ob(g.v, g.v);
    m.map_ob(g.e, g.e);
    m.map_hom_path(g.src, {g.tgt});
    m.map_hom_path(g.tgt, {g.src});
    EXPECT_TRUE(errors_of(m.finish()).empty());
    return m;
}

TEST(Properties, IdentityAndCompositionAreMigrated) {
    Graph g = graph_schema(false);
    SchemaMap maps[] = {reverse_map(g), paths_of_length_two(g)};
    for (int seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen gen(static_cast<std::uint64_t>(seed));
        ACSet x = gen.graph(g, 5, 7);
        auto [y, f] = gen.morphism_from(g, x);
        auto [z, h] = gen.morphism_from(g, y);
        ASSERT_TRUE(hom::is_natural(f, x, y));
        ASSERT_TRUE(hom::is_natural(h, y, z));
        for (const SchemaMap& m : maps) {
            MigratedState mx = migrate_state(m, x), my = migrate_state(m, y),
                          mz = migrate_state(m, z);
            auto id = migrate(m, hom::identity(x), mx, mx);
            ASSERT_TRUE(id);
            EXPECT_EQ(*id, hom::identity(mx.state));
            auto df = migrate(m, f, mx, my);
            auto dh = migrate(m, h, my, mz);
            auto dfh = migrate(m, hom::compose(f, h), mx, mz);
            ASSERT_TRUE(df && dh && dfh);
            EXPECT_TRUE(hom::is_natural(*df, mx.state, my.state));
            EXPECT_TRUE(hom::is_natural(*dh, my.state, mz.state));
            EXPECT_EQ(*dfh, hom::compose(*df, *dh));
        }
    }
}

TEST(Properties, DeltaMapsPreservePushouts) {
    Graph g = graph_schema(false);
    SchemaMap m = reverse_map(g);
    // Also a map that duplicates: V => V, E => E, with src and tgt both sent to src.
    SchemaMap squash(g.s, g.s);
    squash.map_ob(g.v, g.v);
    squash.map_ob(g.e, g.e);
    squash.map_hom_path(g.src, {g.src});
    squash.map_hom_path(g.tgt, {g.src});
    ASSERT_TRUE(errors_of(squash.finish()).empty());
    for (int seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen gen(static_cast<std::uint64_t>(seed) + 1000);
        ACSet a = gen.graph(g, 3, 3);
        auto [b, f] = gen.morphism_from(g, a);
        auto [c, h] = gen.morphism_from(g, a);
        auto po = colimit::pushout(a, b, c, f, h);
        ASSERT_TRUE(po);
        for (const SchemaMap* map : {&m, &squash}) {
            MigratedState ma = migrate_state(*map, a), mb = migrate_state(*map, b),
                          mc = migrate_state(*map, c);
            auto df = migrate(*map, f, ma, mb);
            auto dh = migrate(*map, h, ma, mc);
            ASSERT_TRUE(df && dh);
            auto dpo = colimit::pushout(ma.state, mb.state, mc.state, *df, *dh);
            ASSERT_TRUE(dpo);
            EXPECT_TRUE(hom::is_isomorphic(dpo->apex, migrate(*map, po->apex)));
        }
    }
}

// A delta map whose migration exercises every column kind: swapped homs, a path of length two
// through a partial hom, an identity path, attributes read along paths (constants, variables,
// unset), a constant attribute, names of parts and variables.
TEST(Properties, DeltaCarriesNamesVariablesAndPartialValues) {
    auto s = std::make_shared<Schema>("Source");
    ObId v = s->add_ob("V"), e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v), tgt = s->add_hom("tgt", e, v);
    HomId parent = s->add_hom("parent", v, v);
    AttrTypeId wt = s->add_attr_type("W", ValueKind::Float);
    AttrTypeId lt = s->add_attr_type("L", ValueKind::String);
    AttrId weight = s->add_attr("weight", e, wt);
    AttrId label = s->add_attr("label", v, lt);
    auto t = std::make_shared<Schema>("Target");
    ObId v2 = t->add_ob("V2"), e2 = t->add_ob("E2");
    HomId s2 = t->add_hom("s", e2, v2), t2 = t->add_hom("t", e2, v2);
    HomId grand = t->add_hom("grand", e2, v2), self = t->add_hom("self", v2, v2);
    AttrTypeId wt2 = t->add_attr_type("W2", ValueKind::Float);
    AttrTypeId lt2 = t->add_attr_type("L2", ValueKind::String);
    AttrId w2 = t->add_attr("w", e2, wt2), src_label = t->add_attr("srcLabel", e2, lt2);
    AttrId one = t->add_attr("one", e2, wt2), vlabel = t->add_attr("label", v2, lt2);
    SchemaMap m(t, s);
    m.map_ob(v2, v);
    m.map_ob(e2, e);
    m.map_hom_path(s2, {tgt});
    m.map_hom_path(t2, {src});
    m.map_hom_path(grand, {src, parent});
    m.map_hom_path(self, {});
    m.map_attr_type(wt2, wt);
    m.map_attr_type(lt2, lt);
    m.map_attr(w2, Term::path("E2", {}, weight));
    m.map_attr(src_label, Term::path("E2", {src}, label));
    m.map_attr_constant(one, Value::real(1.5));
    m.map_attr(vlabel, Term::path("V2", {}, label));
    ASSERT_TRUE(errors_of(m.finish()).empty());
    ASSERT_TRUE(m.is_delta());

    for (int seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen gen(static_cast<std::uint64_t>(seed) + 5000);
        ACSet x(s);
        std::size_t nv = 1 + gen.below(6), ne = gen.below(9);
        std::size_t nw = gen.below(3), nl = gen.below(3);
        auto name = [](char c, std::size_t i) {
            std::string n(1, c);
            n += std::to_string(i);
            return n;
        };
        for (std::size_t j = 0; j < nw; ++j) {
            x.add_var(wt, gen.below(2) ? name('w', j) : "");
        }
        for (std::size_t j = 0; j < nl; ++j) {
            x.add_var(lt, gen.below(2) ? name('l', j) : "");
        }
        auto value = [&](bool text, std::size_t nvars) {
            std::size_t k = gen.below(nvars + 3);
            if (k < nvars) {
                return Value::var(static_cast<std::uint32_t>(k));
            }
            if (k == nvars) {
                return Value();
            }
            return text ? Value::string(name('s', k)) : Value::real(double(k));
        };
        auto part = [&](std::size_t n) {
            return gen.below(4) == 0 ? kNoPart : static_cast<Part>(gen.below(n));
        };
        for (std::size_t i = 0; i < nv; ++i) {
            x.add_part(v, gen.below(2) ? name('v', i) : "");
        }
        for (std::size_t i = 0; i < ne; ++i) {
            x.add_part(e, gen.below(2) ? name('e', i) : "");
        }
        for (Part p = 0; p < nv; ++p) {
            x.set_subpart(parent, p, part(nv));
            x.set_subpart(label, p, value(true, nl));
        }
        for (Part p = 0; p < ne; ++p) {
            x.set_subpart(src, p, part(nv));
            x.set_subpart(tgt, p, part(nv));
            x.set_subpart(weight, p, value(false, nw));
        }
        if (gen.below(2)) {
            x.build_indexes(); // the source's indexes play no part
        }

        // The expected migration, cell by cell.
        ACSet want(t);
        for (std::uint32_t j = 0; j < nw; ++j) {
            want.add_var(wt2, x.var_name(wt, j));
        }
        for (std::uint32_t j = 0; j < nl; ++j) {
            want.add_var(lt2, x.var_name(lt, j));
        }
        for (Part p = 0; p < nv; ++p) {
            want.add_part(v2, x.part_name(v, p));
            want.set_subpart(vlabel, p, x.subpart(label, p));
        }
        for (Part p = 0; p < nv; ++p) {
            want.set_subpart(self, p, p);
        }
        for (Part p = 0; p < ne; ++p) {
            want.add_part(e2, x.part_name(e, p));
            want.set_subpart(s2, p, x.subpart(tgt, p));
            want.set_subpart(t2, p, x.subpart(src, p));
            Part q = x.subpart(src, p);
            want.set_subpart(grand, p, q == kNoPart ? kNoPart : x.subpart(parent, q));
            want.set_subpart(w2, p, x.subpart(weight, p));
            want.set_subpart(src_label, p, q == kNoPart ? Value() : x.subpart(label, q));
            want.set_subpart(one, p, Value::real(1.5));
        }

        MigratedState out = migrate_state(m, x);
        const ACSet& y = out.state;
        ASSERT_EQ(y, want);
        for (ObId o : {v2, e2}) {
            for (Part p = 0; p < y.num_parts(o); ++p) {
                EXPECT_EQ(y.part_name(o, p), want.part_name(o, p));
            }
        }
        for (AttrTypeId ty : {wt2, lt2}) {
            for (std::uint32_t j = 0; j < y.num_vars(ty); ++j) {
                EXPECT_EQ(y.var_name(ty, j), want.var_name(ty, j));
            }
        }
        // The migrated state's indexes agree with its columns.
        for (HomId h : {s2, t2, grand, self}) {
            ObId d = t->hom(h).codom;
            for (Part q = 0; q < y.num_parts(d); ++q) {
                std::vector<Part> got(y.incident(h, q).begin(), y.incident(h, q).end());
                std::sort(got.begin(), got.end());
                std::vector<Part> expect;
                for (Part p = 0; p < y.num_parts(t->hom(h).dom); ++p) {
                    if (y.subpart(h, p) == q) {
                        expect.push_back(p);
                    }
                }
                EXPECT_EQ(got, expect);
            }
        }
        for (std::uint32_t j = 0; j < y.num_vars(wt2); ++j) {
            std::size_t cells = 0;
            for (Part p = 0; p < ne; ++p) {
                cells += y.subpart(w2, p) == Value::var(j) ? 1 : 0;
            }
            EXPECT_EQ(y.var_incident(wt2, j).size(), cells);
        }
        // Morphisms still migrate through the tuples (plain: the same components).
        auto id = migrate(m, hom::identity(x), out, out);
        ASSERT_TRUE(id);
        EXPECT_EQ(*id, hom::identity(y));
        auto origins = tuple_origins(m, out, e2);
        ASSERT_TRUE(origins);
        EXPECT_EQ(origins->parts.size(), ne);
    }
}

// ---- composition of maps -----------------------------------------------------------------------

TEST(Compose, DeltaThenConjunctiveAndBack) {
    Graph g = graph_schema(false);
    SchemaMap rev = reverse_map(g);
    SchemaMap paths = paths_of_length_two(g);
    for (int seed = 0; seed < 20; ++seed) {
        SCOPED_TRACE(seed);
        Gen gen(static_cast<std::uint64_t>(seed) + 77);
        ACSet x = gen.graph(g, 5, 8);
        for (auto [first, second] :
             {std::pair{&rev, &paths}, std::pair{&paths, &rev}, std::pair{&rev, &rev}}) {
            auto c = compose(*first, *second);
            ASSERT_TRUE(c) << c.error();
            EXPECT_TRUE(hom::is_isomorphic(migrate(*c, x), migrate(*second, migrate(*first, x))));
        }
    }
    EXPECT_FALSE(compose(paths, paths));
}

TEST(Compose, PlainEntriesStayPlainAfterADeltaMap) {
    // Graph -> LoopedGraph (V, E plain; Loop the edges whose ends agree, a query) after the
    // reverse map: V, E and src, tgt must stay a plain object and paths in the composite.
    Graph g = graph_schema(false);
    auto looped = std::make_shared<Schema>("LoopedGraph");
    ObId v = looped->add_ob("V"), e = looped->add_ob("E"), loop = looped->add_ob("Loop");
    HomId src = looped->add_hom("src", e, v), tgt = looped->add_hom("tgt", e, v);
    HomId at = looped->add_hom("at", loop, v);
    SchemaMap second(looped, g.s);
    second.map_ob(v, g.v);
    second.map_ob(e, g.e);
    second.map_hom_path(src, {g.src});
    second.map_hom_path(tgt, {g.tgt});
    Query q(g.s);
    q.add_variable("l", g.e);
    q.add_equation(Term::path("l", {g.src}), Term::path("l", {g.tgt}));
    second.map_ob(loop, std::move(q));
    second.map_hom(at, {Term::path("l", {g.src})});
    ASSERT_TRUE(errors_of(second.finish()).empty());
    SchemaMap rev = reverse_map(g);
    auto c = compose(rev, second);
    ASSERT_TRUE(c) << c.error();
    EXPECT_FALSE(c->is_delta());
    EXPECT_TRUE(c->query(e).is_plain());
    ASSERT_TRUE(c->hom_image(src).path);
    EXPECT_EQ(*c->hom_image(src).path, std::vector<HomId>{g.tgt}); // reversed
    Gen gen(5);
    for (int i = 0; i < 20; ++i) {
        ACSet x = gen.graph(g, 4, 8);
        EXPECT_TRUE(hom::is_isomorphic(migrate(*c, x), migrate(second, migrate(rev, x))));
    }
}

TEST(Compose, CaseStudyThroughAnAbstractDomain) {
    // ColorBlocksworld -> Kitchenworld, then Kitchenworld -> a plain "Stack" domain by delta.
    Blocks b = blocks_schema();
    Kitchen k = kitchen_schema();
    SchemaMap m = kitchen_map(b, k);
    auto stack = std::make_shared<Schema>("Stack");
    ObId item = stack->add_ob("Item"), bread = stack->add_ob("Bread");
    HomId bread_item = stack->add_hom("breadItem", bread, item);
    AttrTypeId mass = stack->add_attr_type("Mass", ValueKind::Float);
    AttrId bread_mass = stack->add_attr("breadMass", bread, mass);
    SchemaMap d(stack, k.s);
    d.map_ob(item, k.object);
    d.map_ob(bread, k.foods[0].ob);
    d.map_hom_path(bread_item, {k.foods[0].is_object});
    d.map_attr_type(mass, k.mass);
    d.map_attr(bread_mass, Term::path("Bread", {}, k.foods[0].mass));
    ASSERT_TRUE(errors_of(d.finish()).empty());
    auto c = compose(m, d);
    ASSERT_TRUE(c) << c.error();
    ACSet x = initial_state(b);
    ACSet direct = migrate(*c, x);
    EXPECT_EQ(direct.num_parts(bread), 2u);
    EXPECT_EQ(direct.part_label(item, direct.subpart(bread_item, 1)), "E");
    EXPECT_EQ(direct.subpart(bread_mass, 0), Value::real(0.0));
    EXPECT_TRUE(hom::is_isomorphic(direct, migrate(d, migrate(m, x))));
}

} // namespace
} // namespace catplan::migrate
