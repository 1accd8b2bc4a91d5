#include "catplan/migrate/describe.hpp"

#include <gtest/gtest.h>

namespace catplan::migrate {
namespace {

using acset::Value;
using schema::Schema;

TEST(DescribeMap, OneLinePerTargetGenerator) {
    auto src = std::make_shared<Schema>("Blocks");
    ObId block = src->add_ob("Block");
    ObId gripper = src->add_ob("Gripper");
    HomId holding = src->add_hom("isHolding", gripper, block);
    AttrTypeId color = src->add_attr_type("Color", ValueKind::String);
    AttrId has_color = src->add_attr("hasColor", block, color);

    auto tgt = std::make_shared<Schema>("Kitchen");
    ObId object = tgt->add_ob("Object");
    ObId hand = tgt->add_ob("Gripper");
    ObId bread = tgt->add_ob("BreadSliced");
    HomId is_holding = tgt->add_hom("isHolding", hand, object);
    HomId is_object = tgt->add_hom("breadIsObject", bread, object);
    AttrTypeId temp = tgt->add_attr_type("Temperature", ValueKind::Float);
    AttrId has_temp = tgt->add_attr("breadHasTemperature", bread, temp);

    SchemaMap f(tgt, src);
    f.map_ob(object, Query::representable(src, block, "x"));
    f.map_ob(hand, Query::representable(src, gripper, "x"));
    Query q(src);
    q.add_variable("block", block);
    q.add_equation(Term::path("block", {}, has_color), Term::constant(Value::string("purple")));
    f.map_ob(bread, std::move(q));
    f.map_hom_path(is_holding, {holding});
    f.map_hom(is_object, {Term::path("block")});
    f.map_attr_type(temp, ValueKind::Float);
    f.map_attr_constant(has_temp, Value::real(0.0));
    ASSERT_TRUE(f.finish().empty());

    std::vector<std::string> lines;
    for (const auto& l : describe_map(f)) {
        lines.push_back(l.name + " ⇒ " + l.image);
    }
    EXPECT_EQ(lines, (std::vector<std::string>{
                         "Object ⇒ Block",
                         "Gripper ⇒ Gripper",
                         "BreadSliced ⇒ {block::Block | hasColor(block) == \"purple\"}",
                         "isHolding ⇒ isHolding",
                         "breadIsObject ⇒ x ↦ block",
                         "Temperature ⇒ Float",
                         "breadHasTemperature ⇒ x -> 0.0",
                     }));
}

TEST(DescribeMap, AttributesOfAQueryAreTermsOfItsVariables) {
    // Stacked is the query {o::On, C::Color | hasColor(on_r(o)) == C}: its shade is the variable
    // C, the colour below it the term hasColor(on_r(o)); inWorld goes into @unit, which has one
    // map into it.
    auto src = std::make_shared<Schema>("Blocks");
    ObId block = src->add_ob("Block");
    ObId on = src->add_ob("On");
    HomId on_r = src->add_hom("on_r", on, block);
    AttrTypeId color = src->add_attr_type("Color", ValueKind::String);
    AttrId has_color = src->add_attr("hasColor", block, color);

    auto tgt = std::make_shared<Schema>("Towers");
    ObId stacked = tgt->add_ob("Stacked");
    ObId world = tgt->add_ob("World");
    HomId in_world = tgt->add_hom("inWorld", stacked, world);
    AttrTypeId shade = tgt->add_attr_type("Shade", ValueKind::String);
    AttrId shade_of = tgt->add_attr("shadeOf", stacked, shade);
    AttrId below_color = tgt->add_attr("belowColor", stacked, shade);

    SchemaMap f(tgt, src);
    Query q(src);
    q.add_variable("o", on);
    q.add_value_variable("C", color);
    q.add_equation(Term::path("o", {on_r}, has_color), Term::path("C"));
    f.map_ob(stacked, std::move(q));
    f.map_ob(world, Query(src)); // @unit
    f.map_hom(in_world, {});
    f.map_attr_type(shade, color);
    f.map_attr(shade_of, Term::path("C"));
    f.map_attr(below_color, Term::path("o", {on_r}, has_color));
    for (const auto& p : f.finish()) {
        ADD_FAILURE() << p.message;
    }
    std::vector<std::string> lines;
    for (const auto& l : describe_map(f)) {
        lines.push_back(l.name + " ⇒ " + l.image);
    }
    const std::string stacked_line =
        "Stacked ⇒ {#1::Block, o::On, C::Color | hasColor(#1) == C, on_r(o) == #1}";
    EXPECT_EQ(lines, (std::vector<std::string>{
                         stacked_line,
                         "World ⇒ @unit",
                         "inWorld ⇒ (the unique map into @unit)",
                         "Shade ⇒ Color",
                         "shadeOf ⇒ C",
                         "belowColor ⇒ hasColor(on_r(o))",
                     }));
    std::string text = map_text(describe_map(f));
    EXPECT_EQ(text.rfind("  Stacked ⇒ {#1::Block, o::On", 0), 0u) << text;
    EXPECT_NE(text.find("\n  shadeOf ⇒ C\n"), std::string::npos) << text;
}

} // namespace
} // namespace catplan::migrate
