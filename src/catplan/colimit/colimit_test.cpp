#include "catplan/colimit/colimit.hpp"

#include <gtest/gtest.h>

namespace catplan::colimit {
namespace {

using acset::Value;

// Graphs with a string label on vertices.
struct Labelled {
    std::shared_ptr<schema::Schema> s = std::make_shared<schema::Schema>("LGraph");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId tgt = s->add_hom("tgt", e, v);
    AttrTypeId name_t = s->add_attr_type("Name", schema::ValueKind::String);
    AttrId label = s->add_attr("label", v, name_t);

    // n vertices with the given labels (empty string = a fresh variable) and edges i -> i+1.
    ACSet path(const std::vector<std::string>& labels) const {
        ACSet x(s);
        for (const auto& l : labels) {
            Part p = x.add_part(v);
            x.set_subpart(label, p, l.empty() ? x.add_var(name_t) : Value::string(l));
        }
        for (Part i = 0; i + 1 < labels.size(); ++i) {
            Part ed = x.add_part(e);
            x.set_subpart(src, ed, i);
            x.set_subpart(tgt, ed, i + 1);
        }
        return x;
    }

    ACSetMorphism map(std::vector<Part> vs, std::vector<Part> es, std::vector<Value> vars) const {
        ACSetMorphism f;
        f.components = {std::move(vs), std::move(es)};
        f.var_components = {std::move(vars)};
        return f;
    }
};

TEST(Pushout, GluesTwoEdgesIntoAPath) {
    Labelled g;
    ACSet a = g.path({""});       // one vertex with an unknown label
    ACSet b = g.path({"x", "y"}); // x -> y
    ACSet c = g.path({"", "z"});  // ? -> z
    auto f = g.map({1}, {}, {Value::string("y")});
    auto h = g.map({0}, {}, {Value::var(0)});
    ASSERT_TRUE(hom::is_natural(f, a, b));
    ASSERT_TRUE(hom::is_natural(h, a, c));
    auto p = pushout(a, b, c, f, h);
    ASSERT_TRUE(p.has_value()) << p.error();
    EXPECT_EQ(p->apex.num_parts(g.v), 3u);
    EXPECT_EQ(p->apex.num_parts(g.e), 2u);
    // B's parts first, then C's remaining ones; C's variable is now the constant "y".
    EXPECT_EQ(p->apex.subpart(g.label, 1), Value::string("y"));
    EXPECT_EQ(p->apex.subpart(g.label, 2), Value::string("z"));
    EXPECT_EQ(p->apex.num_vars(g.name_t), 0u);
    EXPECT_TRUE(hom::is_natural(p->left, b, p->apex));
    EXPECT_TRUE(hom::is_natural(p->right, c, p->apex));
    EXPECT_EQ(hom::compose(f, p->left), hom::compose(h, p->right)) << "the square commutes";
}

TEST(Pushout, FailsWhenTwoConstantsAreGlued) {
    Labelled g;
    ACSet a = g.path({""});
    ACSet b = g.path({"red"});
    ACSet c = g.path({"green"});
    auto p = pushout(a, b, c, g.map({0}, {}, {Value::string("red")}),
                     g.map({0}, {}, {Value::string("green")}));
    ASSERT_FALSE(p.has_value());
    EXPECT_NE(p.error().find("\"red\""), std::string::npos);
}

TEST(Pushout, ClosesUnderHomsWhenEdgesAreGlued) {
    // Gluing the edges of two single-edge graphs glues their endpoints too.
    Labelled g;
    auto s2 = std::make_shared<schema::Schema>("Graph");
    ObId v = s2->add_ob("V"), e = s2->add_ob("E");
    HomId src = s2->add_hom("src", e, v), tgt = s2->add_hom("tgt", e, v);
    ACSet a(s2);
    a.add_part(e); // an edge with unset ends: gluing it imposes the closure
    ACSet b(s2);
    b.add_parts(v, 2);
    b.add_part(e);
    b.set_subpart(src, 0, 0);
    b.set_subpart(tgt, 0, 1);
    ACSet c = b;
    ACSetMorphism f;
    f.components = {{}, {0}};
    auto p = pushout(a, b, c, f, f);
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->apex.num_parts(e), 1u);
    EXPECT_EQ(p->apex.num_parts(v), 2u);
}

TEST(Coproduct, PutsBPartsFirst) {
    Labelled g;
    auto cp = coproduct(g.path({"a", "b"}), g.path({"", "c"}));
    EXPECT_EQ(cp.apex.num_parts(g.v), 4u);
    EXPECT_EQ(cp.apex.num_parts(g.e), 2u);
    EXPECT_EQ(cp.apex.num_vars(g.name_t), 1u);
    EXPECT_EQ(cp.right(g.v, 0), 2u);
    EXPECT_EQ(cp.apex.subpart(g.label, 2), Value::var(0));
}

TEST(PushoutComplement, DeletesAnEdgeKeepingItsEnds) {
    Labelled g;
    ACSet l = g.path({"x", "y"}); // L: x -> y
    ACSet k = g.path({"x"});      // K: the two vertices
    k.add_part(g.v);
    k.set_subpart(g.label, 1, Value::string("y"));
    ACSet x = g.path({"x", "y", "w"}); // X: x -> y -> w
    auto lk = g.map({0, 1}, {}, {});
    auto m = g.map({0, 1}, {0}, {});
    ASSERT_TRUE(hom::is_natural(lk, k, l));
    ASSERT_TRUE(hom::is_natural(m, l, x));
    auto pc = pushout_complement(k, l, x, lk, m);
    ASSERT_TRUE(pc.has_value()) << pc.error();
    EXPECT_EQ(pc->z.num_parts(g.v), 3u);
    ASSERT_EQ(pc->z.num_parts(g.e), 1u);
    EXPECT_EQ(pc->z.subpart(g.src, 0), 1u) << "the surviving edge y -> w, renumbered";
    EXPECT_TRUE(hom::is_natural(pc->k_to_z, k, pc->z));
    EXPECT_TRUE(hom::is_natural(pc->z_to_x, pc->z, x));
    EXPECT_EQ(hom::compose(pc->k_to_z, pc->z_to_x), hom::compose(lk, m));
}

TEST(PushoutComplement, ReportsDanglingEdgeNamingPartAndHom) {
    Labelled g;
    ACSet l = g.path({"y"}); // delete vertex y
    ACSet k(g.s);
    ACSet x = g.path({"x", "y"});
    x.set_part_name(g.e, 0, "e1");
    auto lk = g.map({}, {}, {});
    auto m = g.map({1}, {}, {});
    auto v = gluing_violations(k, l, x, lk, m);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0].kind, GluingViolationKind::Dangling);
    EXPECT_EQ(v[0].hom, g.tgt);
    EXPECT_EQ(v[0].part, 0u);
    EXPECT_EQ(v[0].reason, "dangling: E e1 refers through tgt to V #2, which the rule deletes");
    EXPECT_FALSE(pushout_complement(k, l, x, lk, m).has_value());
}

TEST(PushoutComplement, ReportsIdentificationOfADeletedPart) {
    Labelled g;
    ACSet l = g.path({"", ""}); // two vertices, one edge; keep vertex 0, delete vertex 1
    l.remove_part(g.e, 0);
    ACSet k(g.s);
    k.add_part(g.v);
    k.set_subpart(g.label, 0, k.add_var(g.name_t));
    ACSet x = g.path({"a"});
    auto lk = g.map({0}, {}, {Value::var(0)});
    auto m = g.map({0, 0}, {}, {Value::string("a"), Value::string("a")});
    ASSERT_TRUE(hom::is_natural(lk, k, l));
    ASSERT_TRUE(hom::is_natural(m, l, x));
    auto v = gluing_violations(k, l, x, lk, m);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0].kind, GluingViolationKind::Identification);
    EXPECT_EQ(v[0].part, 1u);
    EXPECT_EQ(v[0].other, 0u);
}

} // namespace
} // namespace catplan::colimit

namespace catplan::colimit {
namespace {

// A kept edge whose target is deleted: dangling, unless the complement opens that hom (the rule
// redirects it); an open attribute is unset in Z, the others keep X's value.
TEST(PushoutComplement, ReportsALeftLegThatIsNotMonic) {
    Labelled g;
    ACSet k = g.path({"", ""}); // two vertices and the edge between them, both kept as one vertex
    k.remove_part(g.e, 0);
    ACSet l = g.path({""});
    ACSet x = g.path({"a"});
    auto lk = g.map({0, 0}, {}, {Value::var(0), Value::var(0)});
    auto m = g.map({0}, {}, {Value::string("a")});
    ASSERT_TRUE(hom::is_natural(lk, k, l));
    ASSERT_TRUE(hom::is_natural(m, l, x));
    auto v = gluing_violations(k, l, x, lk, m);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0].kind, GluingViolationKind::NotMonic);
    EXPECT_EQ(v[0].ob, g.v);
    EXPECT_EQ(v[0].part, 0u);
    EXPECT_FALSE(pushout_complement(k, l, x, lk, m).has_value());
}

TEST(PushoutComplement, OpenCellsAreUnsetAndNeverDangle) {
    Labelled g;
    ACSet l = g.path({"x", "y"}); // L: x -> y, delete y, keep x and the edge
    ACSet k(g.s);
    k.add_part(g.v);
    Part ke = k.add_part(g.e);
    k.set_subpart(g.src, ke, 0); // the target is left unset in K
    ACSet x = g.path({"x", "y"});
    x.set_subpart(g.label, x.add_part(g.v), Value::string("w"));
    auto lk = g.map({0}, {0}, {});
    auto m = g.map({0, 1}, {0}, {});
    ASSERT_EQ(gluing_violations(k, l, x, lk, m).size(), 1u);
    ComplementOptions open;
    open.open.homs.resize(2);
    open.open.homs[g.tgt.index()] = {0};
    open.open.attrs.resize(1);
    open.open.attrs[g.label.index()] = {0};
    auto d = deletion(k, l, x, lk, m, open);
    EXPECT_TRUE(d.violations.empty());
    EXPECT_EQ(d.parts[g.v.index()], std::vector<Part>{1});
    auto pc = pushout_complement(k, l, x, lk, m, open);
    ASSERT_TRUE(pc.has_value()) << pc.error();
    EXPECT_EQ(pc->z.num_parts(g.v), 2u);
    ASSERT_EQ(pc->z.num_parts(g.e), 1u);
    EXPECT_EQ(pc->z.subpart(g.src, 0), 0u);
    EXPECT_EQ(pc->z.subpart(g.tgt, 0), kNoPart) << "the open hom";
    EXPECT_TRUE(pc->z.subpart(g.label, 0).is_unset()) << "the open attribute";
    EXPECT_EQ(pc->z.subpart(g.label, 1), Value::string("w"));
    EXPECT_TRUE(hom::is_natural(pc->k_to_z, k, pc->z));
}

// SPO: deleting the middle vertex of x -> y -> w deletes both edges; with a kept edge into it
// the cascade is a violation naming the kept edge.
TEST(Deletion, CascadeDeletesReferringPartsAndStopsAtKeptOnes) {
    Labelled g;
    ACSet l = g.path({"y"});
    ACSet k(g.s);
    ACSet x = g.path({"x", "y", "w"});
    ComplementOptions spo;
    spo.cascade = true;
    auto d = deletion(k, l, x, g.map({}, {}, {}), g.map({1}, {}, {}), spo);
    EXPECT_TRUE(d.violations.empty());
    EXPECT_EQ(d.parts[g.v.index()], std::vector<Part>{1});
    EXPECT_EQ(d.parts[g.e.index()], (std::vector<Part>{0, 1}));
    auto pc = pushout_complement(k, l, x, g.map({}, {}, {}), g.map({1}, {}, {}), spo);
    ASSERT_TRUE(pc.has_value());
    EXPECT_EQ(pc->z.num_parts(g.e), 0u);

    ACSet l2 = g.path({"x", "y"}); // keep the edge and x, delete y
    ACSet k2(g.s);
    k2.add_part(g.v);
    k2.set_subpart(g.src, k2.add_part(g.e), 0);
    auto bad = deletion(k2, l2, x, g.map({0}, {0}, {}), g.map({0, 1}, {0}, {}), spo);
    ASSERT_EQ(bad.violations.size(), 1u);
    EXPECT_EQ(bad.violations[0].kind, GluingViolationKind::Cascade);
    EXPECT_EQ(bad.violations[0].part, 0u);
    EXPECT_EQ(bad.violations[0].hom, g.tgt);
}

} // namespace
} // namespace catplan::colimit
