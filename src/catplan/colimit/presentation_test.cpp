#include "catplan/colimit/presentation.hpp"

#include <gtest/gtest.h>

namespace catplan::colimit {
namespace {

// Graphs with a string label on vertices, and a reflexive graph (refl ⋅ src == id == refl ⋅ tgt).
struct Graphs {
    std::shared_ptr<schema::Schema> s = std::make_shared<schema::Schema>("LGraph");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId tgt = s->add_hom("tgt", e, v);
    AttrTypeId name_t = s->add_attr_type("Name", schema::ValueKind::String);
    AttrId label = s->add_attr("label", v, name_t);
};

SourceRange at(std::uint32_t begin) {
    return {0, begin, begin + 1};
}

// The paper's Table 1 in small: generators, a hom equation, an attribute literal, and an equation
// that merges two generators (congruence: their labels meet, one literal wins).
TEST(Presentation, GeneratorsAndEquationsGiveTheFreeState) {
    Graphs g;
    Presentation p(g.s);
    Node a = p.add_part(g.v, "a"), b = p.add_part(g.v, "b"), c = p.add_part(g.v, "c");
    Node e = p.add_part(g.e, "e");
    p.set_hom(e, g.src, a);
    p.set_hom(e, g.tgt, c);
    p.set_literal(p.attr(a, g.label), Value::string("red"), at(1));
    p.equate_parts(b, c, at(2));
    EXPECT_EQ(p.find_part(c), b) << "the class's first node stands for it";
    auto x = p.instance();
    ASSERT_TRUE(x.has_value()) << x.error();
    const ACSet& st = x->state;
    ASSERT_EQ(st.num_parts(g.v), 2u);
    EXPECT_EQ(st.part_name(g.v, 1), "b");
    EXPECT_EQ(x->part_of[c], 1u);
    EXPECT_EQ(st.subpart(g.tgt, x->part_of[e]), 1u);
    EXPECT_EQ(st.subpart(g.label, 0), Value::string("red"));
    EXPECT_TRUE(st.subpart(g.label, 1).is_unset()) << "a partial state: no completion asked";
}

TEST(Presentation, TwoLiteralsForOneCellAreAProblemAsData) {
    Graphs g;
    Presentation p(g.s);
    Node e1 = p.add_part(g.e), e2 = p.add_part(g.e);
    p.set_literal(p.attr(p.hom(e1, g.src), g.label), Value::string("one"), at(1), at(10));
    p.set_literal(p.attr(p.hom(e2, g.src), g.label), Value::string("two"), at(2), at(20));
    ASSERT_TRUE(p.problems().empty());
    p.equate_parts(e1, e2, at(30)); // so their sources, so their labels
    ASSERT_EQ(p.problems().size(), 1u);
    const auto& problem = p.problems()[0];
    EXPECT_EQ(problem.kind, PresentationProblemKind::ConflictingLiterals);
    EXPECT_EQ(problem.first, Value::string("one"));
    EXPECT_EQ(problem.second, Value::string("two"));
    EXPECT_EQ(problem.first_range.begin, 1u);
    EXPECT_EQ(problem.where.begin, 30u);
    EXPECT_EQ(problem.attr, g.label);
    EXPECT_FALSE(p.instance().has_value());
    EXPECT_EQ(p.build().state.num_parts(g.v), 1u) << "build gives the state regardless";
}

TEST(Presentation, CompletionMakesPartsAndUnknownsForWhatIsUndefined) {
    Graphs g;
    Presentation p(g.s);
    Node e = p.add_part(g.e, "e");
    p.set_literal(p.attr(p.hom(e, g.tgt), g.label), Value::string("z"));
    p.complete(/*equations=*/false);
    auto x = p.instance();
    ASSERT_TRUE(x.has_value());
    // e's target (made by the literal's path) comes first, then the source completion made.
    EXPECT_EQ(x->state.num_parts(g.v), 2u);
    EXPECT_EQ(x->state.subpart(g.tgt, 0), 0u);
    EXPECT_EQ(x->state.subpart(g.src, 0), 1u);
    EXPECT_EQ(x->state.subpart(g.label, 1), Value::var(0)) << "an unknown label";
    EXPECT_EQ(x->state.num_vars(g.name_t), 1u);
}

TEST(Presentation, TheChaseImposesPathEquationsAndStopsAtTheLimit) {
    auto s = std::make_shared<schema::Schema>("ReflGraph");
    ObId v = s->add_ob("V"), e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v), tgt = s->add_hom("tgt", e, v);
    HomId refl = s->add_hom("refl", v, e);
    s->add_equation({"", {v, {refl, src}, std::nullopt}, {v, {}, std::nullopt}, {}});
    s->add_equation({"", {v, {refl, tgt}, std::nullopt}, {v, {}, std::nullopt}, {}});
    Presentation p(s);
    p.add_part(v, "x");
    p.complete(/*equations=*/true);
    auto x = p.instance();
    ASSERT_TRUE(x.has_value()) << x.error();
    EXPECT_EQ(x->state.num_parts(v), 1u);
    EXPECT_EQ(x->state.num_parts(e), 1u) << "the loop refl(x), whose ends are x";
    EXPECT_EQ(x->state.subpart(src, 0), 0u);

    Presentation q(s); // without the equations every new edge needs two new vertices
    q.add_part(v);
    q.set_max_parts(20);
    q.complete(/*equations=*/false);
    ASSERT_FALSE(q.problems().empty());
    EXPECT_EQ(q.problems().back().kind, PresentationProblemKind::TooManyParts);
    EXPECT_TRUE(q.limit_reached());
    EXPECT_EQ(q.num_part_nodes(), 20u);
}

TEST(Presentation, VariablesAreNumberedByNodeOrByFirstCell) {
    Graphs g;
    Presentation p(g.s);
    Node a = p.add_part(g.v), b = p.add_part(g.v);
    Node u = p.add_value(g.name_t, "u"), w = p.add_value(g.name_t, "w");
    p.set_attr(a, g.label, w);
    p.set_attr(b, g.label, u);
    auto by_node = p.build();
    EXPECT_EQ(by_node.state.subpart(g.label, 0), Value::var(1));
    EXPECT_EQ(by_node.state.var_name(g.name_t, 0), "u");
    auto by_cell = p.build(Presentation::VariableOrder::Cells);
    EXPECT_EQ(by_cell.state.subpart(g.label, 0), Value::var(0));
    EXPECT_EQ(by_cell.state.var_name(g.name_t, 0), "w");
    EXPECT_EQ(by_cell.value_of[u], Value::var(1));
}

} // namespace
} // namespace catplan::colimit
