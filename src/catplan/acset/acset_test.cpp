#include "catplan/acset/acset.hpp"
#include "catplan/acset/printer.hpp"

#include <gtest/gtest.h>

#include <random>

namespace catplan::acset {
namespace {

struct Graph {
    std::shared_ptr<Schema> s = std::make_shared<Schema>("Graph");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId tgt = s->add_hom("tgt", e, v);
};

std::vector<Part> sorted(std::span<const Part> xs) {
    std::vector<Part> v(xs.begin(), xs.end());
    std::sort(v.begin(), v.end());
    return v;
}

TEST(ACSet, IncidentFollowsSetSubpart) {
    Graph g;
    ACSet x(g.s);
    x.add_parts(g.v, 3);
    x.add_parts(g.e, 3);
    x.set_subpart(g.src, 0, 0);
    x.set_subpart(g.src, 1, 0);
    x.set_subpart(g.src, 2, 1);
    EXPECT_EQ(sorted(x.incident(g.src, 0)), (std::vector<Part>{0, 1}));
    x.set_subpart(g.src, 1, 2);
    EXPECT_EQ(sorted(x.incident(g.src, 0)), (std::vector<Part>{0}));
    EXPECT_EQ(sorted(x.incident(g.src, 2)), (std::vector<Part>{1}));
    Part v3 = x.add_part(g.v);
    EXPECT_TRUE(x.incident(g.src, v3).empty());
}

TEST(ACSet, RemovePartIsPopAndSwap) {
    Graph g;
    ACSet x(g.s);
    x.add_part(g.v, "a");
    x.add_part(g.v, "b");
    x.add_part(g.v, "c");
    x.add_parts(g.e, 2);
    x.set_subpart(g.src, 0, 0); // a -> c
    x.set_subpart(g.tgt, 0, 2);
    x.set_subpart(g.src, 1, 1); // b -> b
    x.set_subpart(g.tgt, 1, 1);
    // Removing a: c moves into slot 0, edge 0's source becomes unset.
    EXPECT_EQ(x.remove_part(g.v, 0), 2u);
    EXPECT_EQ(x.num_parts(g.v), 2u);
    EXPECT_EQ(x.part_name(g.v, 0), "c");
    EXPECT_EQ(x.subpart(g.src, 0), kNoPart);
    EXPECT_EQ(x.subpart(g.tgt, 0), 0u);
    EXPECT_EQ(x.subpart(g.src, 1), 1u);
    EXPECT_EQ(sorted(x.incident(g.tgt, 0)), (std::vector<Part>{0}));
    // Removing the last part returns kNoPart.
    EXPECT_EQ(x.remove_part(g.e, 1), kNoPart);
    EXPECT_EQ(x.num_parts(g.e), 1u);
}

TEST(ACSet, RemovalKeepsIndexConsistentOnRandomEdits) {
    Graph g;
    std::mt19937 rng(7);
    ACSet x(g.s);
    x.add_parts(g.v, 20);
    for (int i = 0; i < 60; ++i) {
        Part e = x.add_part(g.e);
        x.set_subpart(g.src, e, rng() % 20);
        x.set_subpart(g.tgt, e, rng() % 20);
    }
    for (int round = 0; round < 15; ++round) {
        x.remove_part(g.v, static_cast<Part>(rng() % x.num_parts(g.v)));
        x.remove_part(g.e, static_cast<Part>(rng() % x.num_parts(g.e)));
        for (HomId f : {g.src, g.tgt}) {
            for (Part v = 0; v < x.num_parts(g.v); ++v) {
                std::vector<Part> expect;
                for (Part e = 0; e < x.num_parts(g.e); ++e) {
                    if (x.subpart(f, e) == v) {
                        expect.push_back(e);
                    }
                }
                ASSERT_EQ(sorted(x.incident(f, v)), expect) << "round " << round;
            }
        }
    }
}

TEST(ACSet, VariablesAndEquality) {
    auto s = std::make_shared<Schema>("LSet");
    ObId xo = s->add_ob("X");
    AttrTypeId d = s->add_attr_type("D", schema::ValueKind::String);
    AttrId f = s->add_attr("f", xo, d);
    ACSet a(s);
    a.add_parts(xo, 3);
    Value v1 = a.add_var(d);
    Value v2 = a.add_var(d, "c");
    a.set_subpart(f, 0, Value::string("a"));
    a.set_subpart(f, 1, v1);
    a.set_subpart(f, 2, v2);
    ACSet b = a;
    EXPECT_EQ(a, b);
    b.set_part_name(xo, 0, "named");
    EXPECT_EQ(a, b) << "names are ignored by equality";
    b.set_subpart(f, 0, Value::string("b"));
    EXPECT_FALSE(a == b);
    EXPECT_EQ(a.remove_var(d, 0), 1u);
    EXPECT_EQ(a.subpart(f, 1), Value());
    EXPECT_EQ(a.subpart(f, 2), Value::var(0));
    EXPECT_EQ(a.value_label(d, a.subpart(f, 2)), "?c");
}

TEST(ACSet, PrintsTables) {
    Graph g;
    ACSet x(g.s);
    x.add_part(g.v, "a");
    x.add_part(g.v);
    Part e = x.add_part(g.e, "e1");
    x.set_subpart(g.src, e, 0);
    x.set_subpart(g.tgt, e, 1);
    EXPECT_EQ(to_tables(x), "V (2 parts)\n"
                            "  id  name\n"
                            "  1   a\n"
                            "  2\n"
                            "E (1 part)\n"
                            "  id  name  src  tgt\n"
                            "  1   e1    a    #2\n");
}

TEST(ACSet, SetColumnReplacesAColumnAndItsIndex) {
    Graph g;
    ACSet x(g.s);
    EXPECT_EQ(x.add_parts(g.v, 3), 0u);
    EXPECT_EQ(x.add_parts(g.e, 4), 0u);
    EXPECT_EQ(x.add_parts(g.e, 0), 4u);
    EXPECT_EQ(x.column(g.src).size(), 4u);
    EXPECT_EQ(x.subpart(g.src, 3), kNoPart) << "add_parts leaves homs unset";
    x.set_subpart(g.src, 0, 2);
    EXPECT_EQ(sorted(x.incident(g.src, 2)), (std::vector<Part>{0})); // index built
    x.set_column(g.src, std::vector<Part>{1, kNoPart, 1, 0});
    EXPECT_EQ(x.subpart(g.src, 0), 1u);
    EXPECT_EQ(x.subpart(g.src, 1), kNoPart);
    EXPECT_TRUE(x.incident(g.src, 2).empty()) << "the old index is not used";
    EXPECT_EQ(sorted(x.incident(g.src, 1)), (std::vector<Part>{0, 2}));
    EXPECT_EQ(sorted(x.incident(g.src, 0)), (std::vector<Part>{3}));
    // The rebuilt index is kept in step by the per-cell edits as before.
    x.set_subpart(g.src, 1, 0);
    Part e = x.add_part(g.e);
    x.set_subpart(g.src, e, 2);
    EXPECT_EQ(sorted(x.incident(g.src, 0)), (std::vector<Part>{1, 3}));
    EXPECT_EQ(x.remove_part(g.v, 1), 2u); // edges into 1 become unset, 2 is renumbered 1
    EXPECT_EQ(x.column(g.src)[0], kNoPart);
    EXPECT_EQ(sorted(x.incident(g.src, 1)), (std::vector<Part>{4}));
    EXPECT_EQ(sorted(x.incident(g.src, 0)), (std::vector<Part>{1, 3}));
    // A column set before any index exists.
    x.set_column(g.tgt, std::vector<Part>{0, 0, 1, 1, 0});
    EXPECT_EQ(sorted(x.incident(g.tgt, 0)), (std::vector<Part>{0, 1, 4}));
    // Bulk-added parts extend built indexes.
    x.add_parts(g.v, 2);
    x.add_parts(g.e, 2);
    EXPECT_TRUE(x.incident(g.tgt, 3).empty());
    x.set_subpart(g.tgt, 6, 3);
    EXPECT_EQ(sorted(x.incident(g.tgt, 3)), (std::vector<Part>{6}));
    ACSet y(g.s);
    y.add_parts(g.v, 4);
    y.add_parts(g.e, 7);
    y.set_column(g.src, x.column(g.src)); // from another state
    for (Part p = 0; p < 7; ++p) {
        y.set_subpart(g.tgt, p, x.subpart(g.tgt, p));
    }
    EXPECT_EQ(x, y);
    x.set_column(g.tgt, x.column(g.tgt)); // from itself: no change but the index
    EXPECT_EQ(x, y);
    EXPECT_EQ(sorted(x.incident(g.tgt, 3)), (std::vector<Part>{6}));
}

TEST(ACSet, SetColumnOfAnAttribute) {
    auto s = std::make_shared<Schema>("TwoAttrs");
    ObId xo = s->add_ob("X");
    AttrTypeId d = s->add_attr_type("D", schema::ValueKind::Int);
    AttrId f = s->add_attr("f", xo, d);
    AttrId g = s->add_attr("g", xo, d);
    ACSet a(s);
    a.add_parts(xo, 3);
    a.add_var(d);
    a.add_var(d, "b");
    EXPECT_EQ(a.subpart(f, 2), Value()) << "add_parts leaves attributes unset";
    a.set_subpart(g, 0, Value::var(1));
    EXPECT_EQ(a.var_incident(d, 1).size(), 1u); // index built
    a.set_column(f, std::vector<Value>{Value::var(1), Value::integer(4), Value::var(0)});
    EXPECT_EQ(a.subpart(f, 1), Value::integer(4));
    EXPECT_EQ(a.var_incident(d, 1).size(), 2u) << "cells of both attributes";
    EXPECT_EQ(a.var_incident(d, 0).size(), 1u);
    EXPECT_EQ(a.var_incident(d, 0)[0], (ACSet::Cell{f, 2}));
    // Kept in step afterwards.
    EXPECT_EQ(a.remove_var(d, 0), 1u);
    EXPECT_EQ(a.subpart(f, 0), Value::var(0));
    EXPECT_EQ(a.subpart(f, 2), Value());
    EXPECT_EQ(a.subpart(g, 0), Value::var(0));
    EXPECT_EQ(a.var_incident(d, 0).size(), 2u);
    EXPECT_EQ(a.value_label(d, a.subpart(f, 0)), "?b");
    EXPECT_EQ(a.var_name(d, 0), "b");
    a.add_var(d, "");
    EXPECT_EQ(a.var_name(d, 1), "");
    a.add_parts(xo, 1);
    a.set_subpart(f, 3, Value::var(0));
    EXPECT_EQ(a.var_incident(d, 0).size(), 3u);
}

TEST(ACSet, PartNamesInBulk) {
    Graph g;
    ACSet x(g.s);
    x.add_parts(g.v, 2);
    x.add_part(g.v);
    x.set_part_name(g.v, 1, "");
    EXPECT_TRUE(x.part_names(g.v).empty()) << "no names stored while no part is named";
    EXPECT_EQ(x.part_name(g.v, 2), "");
    EXPECT_EQ(x.find_part(g.v, "a"), std::nullopt);
    x.set_part_name(g.v, 1, "b");
    ASSERT_EQ(x.part_names(g.v).size(), 3u);
    EXPECT_EQ(x.part_names(g.v)[0], Symbol());
    EXPECT_EQ(x.part_names(g.v)[1], Symbol::intern("b"));
    EXPECT_EQ(x.remove_part(g.v, 0), 2u);
    EXPECT_EQ(x.part_name(g.v, 1), "b");
    x.set_part_names(g.v, {});
    EXPECT_TRUE(x.part_names(g.v).empty());
    EXPECT_EQ(x.part_name(g.v, 1), "");
    x.remove_part(g.v, 0);
    x.remove_part(g.v, 0);
    ASSERT_EQ(x.num_parts(g.v), 0u);

    x.add_part(g.v, "a");
    x.add_parts(g.v, 2);
    x.add_part(g.v, "");
    std::span<const Symbol> names = x.part_names(g.v);
    ASSERT_EQ(names.size(), 4u);
    EXPECT_EQ(names[0], Symbol::intern("a"));
    EXPECT_EQ(names[1], Symbol());
    EXPECT_EQ(names[3], Symbol()) << "an empty name is no name";
    EXPECT_EQ(x.part_name(g.v, 1), "");
    x.set_part_names(g.v, {Symbol(), Symbol::intern("b"), Symbol(), Symbol::intern("a")});
    EXPECT_EQ(x.part_name(g.v, 0), "");
    EXPECT_EQ(x.part_name(g.v, 1), "b");
    EXPECT_EQ(x.find_part(g.v, "a"), 3u);
    EXPECT_EQ(x.part_label(g.v, 2), "#3");
    // Names move with their parts.
    EXPECT_EQ(x.remove_part(g.v, 1), 3u);
    EXPECT_EQ(x.part_name(g.v, 1), "a");
    EXPECT_EQ(x.part_names(g.v).size(), 3u);
    x.add_parts(g.v, 2);
    EXPECT_EQ(x.part_names(g.v).size(), 5u);
    EXPECT_EQ(x.part_name(g.v, 4), "");
}

TEST(Value, DisplayAndKinds) {
    EXPECT_EQ(Value::real(0.0).to_string(), "0.0");
    EXPECT_EQ(Value::real(2.5).to_string(), "2.5");
    EXPECT_EQ(Value::string("red").to_string(), "\"red\"");
    EXPECT_EQ(Value::var(0).to_string(), "?1");
    EXPECT_EQ(Value::boolean(true).kind(), schema::ValueKind::Bool);
    EXPECT_NE(Value::var(0), Value::string("a"));
    EXPECT_EQ(Value::real(0.0).hash(), Value::real(-0.0).hash());
}

} // namespace
} // namespace catplan::acset

namespace catplan::acset {
namespace {

TEST(ACSet, VariableIndexStaysInStepUnderEdits) {
    auto s = std::make_shared<Schema>("TwoAttrs");
    ObId xo = s->add_ob("X");
    AttrTypeId d = s->add_attr_type("D", schema::ValueKind::Int);
    AttrId f = s->add_attr("f", xo, d);
    AttrId g = s->add_attr("g", xo, d);
    std::mt19937 rng(11);
    ACSet a(s);
    a.add_parts(xo, 12);
    for (int i = 0; i < 5; ++i) {
        a.add_var(d);
    }
    auto random_value = [&] {
        auto k = static_cast<std::uint32_t>(rng() % (a.num_vars(d) + 2));
        return k < a.num_vars(d) ? Value::var(k) : Value::integer(static_cast<int>(k));
    };
    for (Part p = 0; p < 12; ++p) {
        a.set_subpart(f, p, random_value());
        a.set_subpart(g, p, random_value());
    }
    a.var_incident(d, 0); // build the index, then edit
    for (int round = 0; round < 40; ++round) {
        switch (rng() % 4) {
        case 0:
            a.set_subpart(rng() % 2 ? f : g, static_cast<Part>(rng() % a.num_parts(xo)),
                          random_value());
            break;
        case 1:
            if (a.num_parts(xo) > 2) {
                a.remove_part(xo, static_cast<Part>(rng() % a.num_parts(xo)));
            }
            break;
        case 2:
            if (a.num_vars(d) > 1) {
                a.remove_var(d, static_cast<std::uint32_t>(rng() % a.num_vars(d)));
            }
            break;
        default:
            a.add_var(d);
            a.set_subpart(f, a.add_part(xo),
                          Value::var(static_cast<std::uint32_t>(a.num_vars(d) - 1)));
            break;
        }
        for (std::uint32_t j = 0; j < a.num_vars(d); ++j) {
            std::vector<std::pair<std::uint32_t, Part>> expect, found;
            for (AttrId at : {f, g}) {
                for (Part p = 0; p < a.num_parts(xo); ++p) {
                    if (a.subpart(at, p) == Value::var(j)) {
                        expect.emplace_back(at.index(), p);
                    }
                }
            }
            for (const auto& c : a.var_incident(d, j)) {
                found.emplace_back(c.attr.index(), c.part);
            }
            std::sort(found.begin(), found.end());
            ASSERT_EQ(found, expect) << "round " << round << " var " << j;
        }
    }
}

} // namespace
} // namespace catplan::acset
