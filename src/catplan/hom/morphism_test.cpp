#include "catplan/hom/detail/test_instances.hpp"
#include "catplan/hom/morphism.hpp"

#include <gtest/gtest.h>

namespace catplan::hom {
namespace {

using namespace catplan::hom::testing;
using schema::ValueKind;

// A labelled graph: Graph plus Label::AttrType (String) and label::Attr(V, Label).
SchemaPtr labelled_schema() {
    static SchemaPtr s = [] {
        auto g = std::make_shared<Schema>("LabelledGraph");
        ObId v = g->add_ob("V"), e = g->add_ob("E");
        g->add_hom("src", e, v);
        g->add_hom("tgt", e, v);
        AttrTypeId l = g->add_attr_type("Label", ValueKind::String);
        g->add_attr("label", v, l);
        return SchemaPtr(g);
    }();
    return s;
}

constexpr AttrTypeId kLabel{0};
constexpr AttrId kLabelAttr{0};

TEST(Morphism, IdentityIsNaturalMonicAndIso) {
    ACSet g = make_graph(labelled_schema(), 2, {{0, 1}});
    Value v = g.add_var(kLabel);
    g.set_subpart(kLabelAttr, 0, v);
    g.set_subpart(kLabelAttr, 1, Value::string("red"));
    ACSetMorphism id = identity(g);
    EXPECT_EQ(id.components[0], (std::vector<Part>{0, 1}));
    EXPECT_EQ(id.var_components[0], (std::vector<Value>{Value::var(0)}));
    EXPECT_TRUE(is_natural(id, g, g));
    EXPECT_TRUE(is_monic(id, g, g));
    EXPECT_TRUE(is_iso(id, g, g));
}

TEST(Morphism, ComposeFollowsVariablesThroughTheSecondMorphism) {
    ACSetMorphism f;
    f.components = {{1, 0}, {}};
    f.var_components = {{Value::var(1), Value::string("a")}};
    ACSetMorphism g;
    g.components = {{2, 2}, {}};
    g.var_components = {{Value::string("z"), Value::var(0)}};
    ACSetMorphism h = compose(f, g);
    EXPECT_EQ(h.components[0], (std::vector<Part>{2, 2}));
    // f sends ?1 to ?2, which g sends to ?1; f's concrete "a" stays "a".
    EXPECT_EQ(h.var_components[0], (std::vector<Value>{Value::var(0), Value::string("a")}));
}

TEST(Morphism, NaturalityFailuresAreReportedAsData) {
    ACSet x = make_graph(labelled_schema(), 2, {{0, 1}});
    x.set_part_name(kV, 0, "a");
    x.set_subpart(kLabelAttr, 0, Value::string("red"));
    Value xv = x.add_var(kLabel);
    x.set_subpart(kLabelAttr, 1, xv);
    ACSet y = make_graph(labelled_schema(), 3, {{0, 1}, {1, 2}});
    y.set_subpart(kLabelAttr, 0, Value::string("blue"));
    y.set_subpart(kLabelAttr, 1, Value::string("green"));
    y.set_subpart(kLabelAttr, 2, Value::string("red"));

    ACSetMorphism f;
    f.components = {{0, 2}, {0}};                // edge 1 -> 2 goes to y's edge 1 -> 2, but 2 -> 3
    f.var_components = {{Value::string("red")}}; // y(3) is red, but vertex 2 goes to 3: fine
    auto fails = naturality_failures(f, x, y);
    ASSERT_EQ(fails.size(), 2u);
    EXPECT_EQ(fails[0].kind, NaturalityFailureKind::HomMismatch);
    EXPECT_EQ(fails[0].hom, kTgt);
    EXPECT_EQ(fails[0].part, 0u);
    EXPECT_EQ(fails[0].expected, 1u);
    EXPECT_EQ(fails[0].found, 2u);
    EXPECT_EQ(fails[1].kind, NaturalityFailureKind::AttrMismatch);
    EXPECT_EQ(fails[1].part, 0u);
    EXPECT_EQ(fails[1].expected_value, Value::string("red"));
    EXPECT_EQ(fails[1].found_value, Value::string("blue"));
    EXPECT_FALSE(is_natural(f, x, y));
    EXPECT_EQ(describe(fails[0], x, y),
              "hom tgt at E part #1: tgt(#1) = #2 is sent to V part #3, but tgt of the image of "
              "#1 is V part #2");
    EXPECT_EQ(describe(fails[1], x, y),
              "attribute label at V part a: expected \"red\", found \"blue\"");

    ACSetMorphism ok;
    ok.components = {{2, 0}, {}};
    ok.var_components = {{Value::string("blue")}};
    // No edges in the domain of this one: use a graph without the edge.
    ACSet x2 = make_graph(labelled_schema(), 2, {});
    x2.set_subpart(kLabelAttr, 0, Value::string("red"));
    Value v2 = x2.add_var(kLabel);
    x2.set_subpart(kLabelAttr, 1, v2);
    EXPECT_TRUE(is_natural(ok, x2, y));
}

TEST(Morphism, SizeRangeAndVariableFailures) {
    ACSet x = make_graph(labelled_schema(), 2, {{0, 1}});
    Value xv = x.add_var(kLabel);
    x.set_subpart(kLabelAttr, 0, xv);
    ACSet y = make_graph(labelled_schema(), 2, {{0, 1}});
    Value yv = y.add_var(kLabel);
    y.set_subpart(kLabelAttr, 0, yv);

    ACSetMorphism f;
    f.components = {{0, 7}, {}};
    f.var_components = {{Value::var(5)}};
    auto fails = naturality_failures(f, x, y);
    ASSERT_EQ(fails.size(), 3u);
    EXPECT_EQ(fails[0].kind, NaturalityFailureKind::PartOutOfRange);
    EXPECT_EQ(fails[0].part, 1u);
    EXPECT_EQ(fails[0].found, 7u);
    EXPECT_EQ(fails[1].kind, NaturalityFailureKind::ComponentSize);
    EXPECT_EQ(fails[1].ob, kE);
    EXPECT_EQ(fails[1].part, 0u);
    EXPECT_EQ(fails[1].expected, 1u);
    EXPECT_EQ(fails[2].kind, NaturalityFailureKind::VarImageInvalid);
    EXPECT_EQ(fails[2].found_value, Value::var(5));
    EXPECT_NE(describe(fails[0], x, y).find("not a part of the codomain"), std::string::npos);
    EXPECT_NE(describe(fails[1], x, y).find("has 0 entries"), std::string::npos);

    ACSetMorphism g;
    g.components = {{0, 1}, {0}};
    g.var_components = {{Value::integer(3)}};
    auto gf = naturality_failures(g, x, y);
    ASSERT_GE(gf.size(), 1u);
    EXPECT_EQ(gf[0].kind, NaturalityFailureKind::VarImageWrongKind);
    EXPECT_NE(describe(gf[0], x, y).find("Int"), std::string::npos);
}

TEST(Morphism, MonicAndIso) {
    ACSet x = make_graph(2, {});
    ACSet y = make_graph(3, {});
    ACSetMorphism inj;
    inj.components = {{2, 0}, {}};
    EXPECT_TRUE(is_monic(inj, x, y));
    EXPECT_FALSE(is_iso(inj, x, y));
    ACSetMorphism collapse;
    collapse.components = {{1, 1}, {}};
    EXPECT_FALSE(is_monic(collapse, x, y));
    ACSetMorphism swap;
    swap.components = {{1, 0}, {}};
    EXPECT_TRUE(is_iso(swap, x, x));

    // A variable sent to a concrete value is not invertible.
    ACSet l = make_graph(labelled_schema(), 1, {});
    l.add_var(kLabel);
    ACSetMorphism to_concrete;
    to_concrete.components = {{0}, {}};
    to_concrete.var_components = {{Value::string("red")}};
    EXPECT_FALSE(is_iso(to_concrete, l, l));
}

} // namespace
} // namespace catplan::hom
