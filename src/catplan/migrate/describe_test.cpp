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

} // namespace
} // namespace catplan::migrate
