#include "catplan/schema/printer.hpp"
#include "catplan/schema/schema.hpp"

#include <gtest/gtest.h>

namespace catplan::schema {
namespace {

TEST(Schema, KeepsDeclarationOrderAndLooksUpNames) {
    Schema s("Graph");
    ObId v = s.add_ob("V");
    ObId e = s.add_ob("E");
    HomId src = s.add_hom("src", e, v);
    HomId tgt = s.add_hom("tgt", e, v);
    EXPECT_EQ(s.find_ob("E"), e);
    EXPECT_EQ(s.find_hom("tgt"), tgt);
    EXPECT_FALSE(s.find_ob("src"));
    ASSERT_EQ(s.homs_from(e).size(), 2u);
    EXPECT_EQ(s.homs_from(e)[0], src);
    EXPECT_EQ(s.homs_into(v).size(), 2u);
    EXPECT_FALSE(s.is_cyclic());
}

TEST(Schema, ParsesJuliaKindNames) {
    EXPECT_EQ(parse_value_kind("Float64"), ValueKind::Float);
    EXPECT_EQ(parse_value_kind("Symbol"), ValueKind::String);
    EXPECT_FALSE(parse_value_kind("Complex"));
}

TEST(Schema, DecidesPathEqualityModuloEquations) {
    // A commutative square: f;g == h;k, plus a third path through it.
    Schema s("Square");
    ObId a = s.add_ob("A"), b = s.add_ob("B"), c = s.add_ob("C"), d = s.add_ob("D");
    ObId e = s.add_ob("E");
    HomId f = s.add_hom("f", a, b), g = s.add_hom("g", b, d);
    HomId h = s.add_hom("h", a, c), k = s.add_hom("k", c, d);
    HomId m = s.add_hom("m", d, e);
    HomId z = s.add_hom("z", e, e);
    (void)z;
    Path fg{a, {f, g}, {}}, hk{a, {h, k}, {}};
    EXPECT_FALSE(s.paths_equal(fg, hk));
    s.add_equation({"", fg, hk, {}});
    EXPECT_TRUE(s.paths_equal(fg, hk));
    EXPECT_TRUE(s.paths_equal(Path{a, {f, g, m}, {}}, Path{a, {h, k, m}, {}}));
    EXPECT_FALSE(s.paths_equal(Path{a, {f}, {}}, Path{a, {h}, {}}));
    EXPECT_TRUE(s.is_cyclic());
    EXPECT_EQ(s.path_to_string(fg), "f ⋅ g");
    EXPECT_EQ(s.path_to_string(Path{a, {}, {}}), "id(A)");
}

TEST(Schema, DescribesItselfAsLists) {
    Schema s("LSet");
    ObId x = s.add_ob("X");
    AttrTypeId d = s.add_attr_type("D", ValueKind::String);
    s.add_attr("f", x, d);
    EXPECT_EQ(describe(s), "schema LSet\n"
                           "  objects (1): X\n"
                           "  homs (0):\n"
                           "  attribute types (1): D (String)\n"
                           "  attributes (1):\n"
                           "    f : X → D\n");
}

} // namespace
} // namespace catplan::schema
