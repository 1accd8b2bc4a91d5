// Pictures compared as text with tests/dot/*.dot (CATPLAN_UPDATE_GOLDEN=1 rewrites them), plus
// unit tests of escaping, determinism and the readability heuristics. The ctest dot_render (in
// tests/dot) checks that every golden file renders with Graphviz.

#include "catplan/dot/dot.hpp"
#include "catplan/migrate/query.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace catplan::dot {
namespace {

using acset::ACSet;
using acset::Value;
using schema::Schema;
using schema::ValueKind;

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void expect_golden(const std::string& name, const std::string& actual) {
    std::filesystem::path path =
        std::filesystem::path(CATPLAN_SOURCE_DIR) / "tests" / "dot" / (name + ".dot");
    const char* update = std::getenv("CATPLAN_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        std::ofstream(path, std::ios::binary) << actual;
        return;
    }
    ASSERT_TRUE(std::filesystem::exists(path)) << "missing " << path << "; the output was:\n"
                                               << actual;
    EXPECT_EQ(read(path), actual) << "rerun with CATPLAN_UPDATE_GOLDEN=1 to accept";
}

bool contains(const std::string& text, std::string_view part) {
    return text.find(part) != std::string::npos;
}

// ---- fixtures ---------------------------------------------------------------------------------

std::shared_ptr<Schema> graph_schema() {
    auto s = std::make_shared<Schema>("Graph");
    ObId v = s->add_ob("V"), e = s->add_ob("E");
    s->add_hom("src", e, v);
    s->add_hom("tgt", e, v);
    return s;
}

// The paper's appendix ColorBlocksworld (examples/colorblocksworld/colorblocksworld.cp).
struct Blocks {
    std::shared_ptr<Schema> s = std::make_shared<Schema>("ColorBlocksworld");
    ObId block = s->add_ob("Block");
    ObId empty = s->add_ob("Empty");
    ObId gripper = s->add_ob("Gripper");
    AttrTypeId color = s->add_attr_type("Color", ValueKind::String);
    AttrTypeId clear = s->add_attr_type("Clear", ValueKind::Bool);
    AttrTypeId on_table = s->add_attr_type("OnTable", ValueKind::Bool);
    ObId on = s->add_ob("On");
    HomId on_l = s->add_hom("on_l", on, block);
    HomId on_r = s->add_hom("on_r", on, block);
    HomId is_empty = s->add_hom("isEmpty", empty, block);
    HomId is_holding = s->add_hom("isHolding", gripper, block);
    AttrId has_color = s->add_attr("hasColor", block, color);
    AttrId is_clear = s->add_attr("isClear", block, clear);
    AttrId is_on_table = s->add_attr("isOnTable", block, on_table);

    Part add_block(ACSet& x, std::string_view name, std::optional<std::string_view> color_name,
                   std::optional<bool> is_clear_value, std::optional<bool> on_table_value) const {
        Part b = x.add_part(block, name);
        if (color_name) {
            x.set_subpart(has_color, b, Value::string(*color_name));
        }
        if (is_clear_value) {
            x.set_subpart(is_clear, b, Value::boolean(*is_clear_value));
        }
        if (on_table_value) {
            x.set_subpart(is_on_table, b, Value::boolean(*on_table_value));
        }
        return b;
    }

    void add_on(ACSet& x, std::string_view name, Part upper, Part lower) const {
        Part o = x.add_part(on, name);
        x.set_subpart(on_l, o, upper);
        x.set_subpart(on_r, o, lower);
    }

    // A part of the case study's initial state: C, D, E stacked (E on top), the gripper holding
    // an unnamed block whose colour is a named variable and whose other attributes are unknowns.
    ACSet initial() const {
        ACSet x(s);
        Part a = add_block(x, "A", "green", true, true);
        (void)a;
        add_block(x, "B", "red", true, true);
        Part c = add_block(x, "C", "yellow", false, true);
        Part d = add_block(x, "D", "purple", false, false);
        Part e = add_block(x, "E", "purple", true, false);
        add_on(x, "x1", e, d);
        add_on(x, "x2", d, c);
        Part hand = x.add_part(block);
        x.set_subpart(has_color, hand, x.add_var(color, "c"));
        x.set_subpart(is_clear, hand, x.add_var(clear));
        Part g = x.add_part(gripper, "gripper");
        x.set_subpart(is_holding, g, hand);
        Part em = x.add_part(empty, "empty");
        x.set_subpart(is_empty, em, hand);
        return x;
    }

    // unstack as in examples/colorblocksworld/colorblocksworld.cp.
    rewrite::Rule unstack() const {
        rewrite::Rule r(s);
        r.name = "unstack";
        // Pre
        Part g = r.L.add_part(gripper, "gripper");
        Part em = r.L.add_part(empty, "empty");
        Part b = add_block(r.L, "block", std::nullopt, true, std::nullopt);
        Part u = add_block(r.L, "underblock", std::nullopt, std::nullopt, std::nullopt);
        Part hand = r.L.add_part(block);
        add_on(r.L, "o", b, u);
        r.L.set_subpart(is_holding, g, hand);
        r.L.set_subpart(is_empty, em, hand);
        // Keep: the gripper (its isHolding is rewritten) and the two blocks.
        r.K.add_part(gripper, "gripper");
        r.K.add_part(block, "block");
        r.K.add_part(block, "underblock");
        // Eff
        Part g2 = r.R.add_part(gripper, "gripper");
        Part b2 = r.R.add_part(block, "block");
        add_block(r.R, "underblock", std::nullopt, true, std::nullopt);
        r.R.set_subpart(is_holding, g2, b2);
        // l and r: objects Block, Empty, Gripper, On; one variable component per type.
        r.l.components = {{b, u}, {}, {g}, {}};
        r.l.var_components = {{}, {}, {}};
        r.r.components = {{0, 1}, {}, {0}, {}};
        r.r.var_components = {{}, {}, {}};
        return r;
    }
};

// The slides' OntColorBlocksworld (reference §1.2), with predicate objects.
struct Slides {
    std::shared_ptr<Schema> s = std::make_shared<Schema>("OntColorBlocksworld");
    ObId block = s->add_ob("Block");
    ObId empty = s->add_ob("Empty");
    ObId gripper = s->add_ob("Gripper");
    ObId has_color_ob = s->add_ob("HasColor");
    ObId is_clear_ob = s->add_ob("IsClear");
    AttrTypeId color = s->add_attr_type("Color", ValueKind::String);
    AttrTypeId clear = s->add_attr_type("Clear", ValueKind::Bool);
    HomId is_empty = s->add_hom("isEmpty", empty, block);
    HomId is_holding = s->add_hom("isHolding", gripper, block);
    AttrId has_color = s->add_attr("hasColor", has_color_ob, color);
    HomId has_color_dom = s->add_hom("hasColorDom", has_color_ob, block);
    AttrId is_clear = s->add_attr("isClear", is_clear_ob, clear);
    HomId is_clear_dom = s->add_hom("isClearDom", is_clear_ob, block);
    ObId on = s->add_ob("On");
    HomId on_l = s->add_hom("onL", on, block);
    HomId on_r = s->add_hom("onR", on, block);

    Part add_block(ACSet& x, std::string_view name, Value colour, std::optional<bool> clear_value,
                   std::string_view clear_name = {}) const {
        Part b = x.add_part(block, name);
        Part hc = x.add_part(has_color_ob, std::string("color") + std::string(name));
        x.set_subpart(has_color_dom, hc, b);
        x.set_subpart(has_color, hc, colour);
        if (clear_value) {
            Part ic = x.add_part(is_clear_ob, clear_name);
            x.set_subpart(is_clear_dom, ic, b);
            x.set_subpart(is_clear, ic, Value::boolean(*clear_value));
        }
        return b;
    }

    ACSet state() const {
        ACSet x(s);
        Part null = x.add_part(block, "null");
        add_block(x, "A", Value::string("green"), true, "clearA");
        Part d = add_block(x, "D", Value::string("purple"), false, "clearD");
        Part e = add_block(x, "E", Value::string("purple"), true, "clearE");
        Part o = x.add_part(on, "x1");
        x.set_subpart(on_l, o, e);
        x.set_subpart(on_r, o, d);
        Part g = x.add_part(gripper, "gripper");
        x.set_subpart(is_holding, g, null);
        Part em = x.add_part(empty, "empty");
        x.set_subpart(is_empty, em, null);
        // A clear-ness fact whose block is not known yet: drawn as a node of its own.
        Part loose = x.add_part(is_clear_ob);
        x.set_subpart(is_clear, loose, Value::boolean(false));
        return x;
    }
};

// ---- golden pictures --------------------------------------------------------------------------

TEST(DotGolden, GraphSchema) {
    expect_golden("graph_schema", schema_to_dot(*graph_schema()));
}

TEST(DotGolden, ColorBlocksworldSchema) {
    Blocks b;
    expect_golden("colorblocksworld_schema", schema_to_dot(*b.s));
}

TEST(DotGolden, SlidesSchema) {
    Slides sl;
    expect_golden("slides_schema", schema_to_dot(*sl.s));
}

TEST(DotGolden, KitchenworldSchema) {
    auto s = std::make_shared<Schema>("KitchenWorld");
    ObId object = s->add_ob("Object"), receptacle = s->add_ob("Receptacle");
    ObId empty = s->add_ob("Empty"), gripper = s->add_ob("Gripper");
    s->add_hom("isHolding", gripper, object);
    s->add_hom("isEmpty", empty, object);
    AttrTypeId temperature = s->add_attr_type("Temperature", ValueKind::Float);
    AttrTypeId mass = s->add_attr_type("Mass", ValueKind::Float);
    AttrTypeId material = s->add_attr_type("Material", ValueKind::String);
    ObId in = s->add_ob("InReceptacle");
    s->add_hom("inReceptacle_l", in, object);
    s->add_hom("inReceptacle_r", in, receptacle);
    for (std::string kind : {"BreadSliced", "LettuceSliced", "TomatoSliced", "Plate", "Knife"}) {
        std::string lower = kind;
        lower[0] = char(lower[0] - 'A' + 'a');
        ObId x = s->add_ob(kind);
        s->add_hom(lower + "IsObject", x, object);
        if (kind != "Knife") {
            s->add_hom(lower + "IsReceptacle", x, receptacle);
        }
        s->add_attr(lower + "HasTemperature", x, temperature);
        s->add_attr(lower + "HasMass", x, mass);
        s->add_attr(lower + "HasMaterial", x, material);
    }
    // Fifteen attributes read best left to right.
    DotOptions o;
    o.left_to_right = true;
    expect_golden("kitchenworld_schema", schema_to_dot(*s, o));
}

TEST(DotGolden, SchemaWithEquations) {
    auto s = graph_schema();
    ObId v = *s->find_ob("V"), e = *s->find_ob("E");
    HomId src = *s->find_hom("src"), tgt = *s->find_hom("tgt");
    HomId inv = s->add_hom("inv", e, e);
    s->add_equation({"sym", {e, {inv, src}, {}}, {e, {tgt}, {}}, {}});
    s->add_equation({"", {e, {inv, inv}, {}}, {e, {}, {}}, {}});
    (void)v;
    expect_golden("schema_equations", schema_to_dot(*s));
}

TEST(DotGolden, BlocksState) {
    Blocks b;
    expect_golden("blocks_state", state_to_dot(b.initial(), "Initial"));
}

TEST(DotGolden, BlocksStateWithoutHeuristics) {
    Blocks b;
    DotOptions o;
    o.relation_edges = false;
    o.left_to_right = true;
    expect_golden("blocks_state_plain", state_to_dot(b.initial(), "Initial", o));
}

TEST(DotGolden, SlidesStateWithPredicateRows) {
    Slides sl;
    expect_golden("slides_state", state_to_dot(sl.state(), "state"));
}

TEST(DotGolden, UnstackRule) {
    Blocks b;
    expect_golden("unstack_rule", rule_to_dot(b.unstack()));
}

TEST(DotGolden, RuleWithNegativeCondition) {
    // putdown-like: holding a block -> not holding it, unless some block is already on the table
    // (a made-up condition that shows the picture of an application condition).
    Blocks b;
    rewrite::Rule r(b.s);
    r.name = "putdown";
    Part g = r.L.add_part(b.gripper, "gripper");
    Part blk = r.L.add_part(b.block, "block");
    r.L.set_subpart(b.is_holding, g, blk);
    r.K.add_part(b.gripper, "gripper");
    r.K.add_part(b.block, "block");
    r.R.add_part(b.gripper, "gripper");
    b.add_block(r.R, "block", std::nullopt, true, true);
    r.l.components = {{blk}, {}, {g}, {}};
    r.l.var_components = {{}, {}, {}};
    r.r.components = {{0}, {}, {0}, {}};
    r.r.var_components = {{}, {}, {}};
    rewrite::ApplicationCondition nac{"other_on_table", true, ACSet(b.s), {}, {}};
    nac.n_state = r.L;
    b.add_block(nac.n_state, "other", std::nullopt, std::nullopt, true);
    nac.n.components = {{0}, {}, {0}, {}};
    nac.n.var_components = {{}, {}, {}};
    r.conditions.push_back(nac);
    ASSERT_TRUE(rewrite::check_rule(r).empty());
    expect_golden("putdown_rule_nac", rule_to_dot(r));
}

TEST(DotGolden, RuleWithEmptyPreAndKeep) {
    // A rule that creates a block from nothing: empty panels keep their place and order.
    Blocks b;
    rewrite::Rule r(b.s);
    r.name = "create";
    b.add_block(r.R, "new", "white", true, true);
    r.l.components = {{}, {}, {}, {}};
    r.l.var_components = {{}, {}, {}};
    r.r = r.l;
    ASSERT_TRUE(rewrite::check_rule(r).empty());
    std::string dot = rule_to_dot(r);
    EXPECT_TRUE(contains(dot, "Pre__empty -> Keep__empty [style=invis];"));
    EXPECT_TRUE(contains(dot, "Keep__empty -> Eff_Block_1 [style=invis];"));
    expect_golden("create_rule", dot);
}

TEST(DotGolden, MorphismWithPredicateRowsAndVariables) {
    // The pattern "a clear block of unknown colour, on another block" into the slides' state.
    Slides sl;
    ACSet x = sl.state();
    ACSet p(sl.s);
    Part top = sl.add_block(p, "top", p.add_var(sl.color, "c"), true);
    Part below = p.add_part(sl.block, "below");
    Part o = p.add_part(sl.on);
    p.set_subpart(sl.on_l, o, top);
    p.set_subpart(sl.on_r, o, below);
    hom::ACSetMorphism f;
    // Objects: Block, Empty, Gripper, HasColor, IsClear, On. In x: Block null, A, D, E;
    // HasColor colorA, colorD, colorE; IsClear clearA, clearD, clearE, #4.
    f.components = {{3, 2}, {}, {}, {2}, {2}, {0}};
    f.var_components = {{Value::string("purple")}, {}};
    ASSERT_TRUE(hom::is_natural(f, p, x));
    expect_golden("match_morphism", morphism_to_dot(f, p, x, "match"));
}

TEST(DotGolden, Escaping) {
    auto s = std::make_shared<Schema>("Odd \"names\"");
    ObId thing = s->add_ob("Thing <1>");
    ObId node = s->add_ob("node");
    AttrTypeId text = s->add_attr_type("Text", ValueKind::String);
    AttrId says = s->add_attr("says", thing, text);
    s->add_hom("to", node, thing);
    ACSet x(s);
    Part t = x.add_part(thing, "a \"quoted\" \\ name & <tag>");
    x.set_subpart(says, t, Value::string("line1\nline2 \"q\" <b> & \\N"));
    Part u = x.add_part(thing, "Zürich ☃");
    x.set_subpart(says, u, Value::string("grüß"));
    Part n = x.add_part(node);
    x.set_subpart(*s->find_hom("to"), n, t);
    std::string dot = state_to_dot(x, "odd\\state");
    expect_golden("escaping_state", dot);
    expect_golden("escaping_schema", schema_to_dot(*s));
}

// The paper's map in small: Kitchen objects are blocks, InReceptacle is On, BreadSliced is the
// purple blocks (a query), Temperature a value kind with a constant attribute, and a query with
// a value variable and a path (the blocks on something, with their colour).
migrate::SchemaMap kitchen_map(const Blocks& b) {
    auto k = std::make_shared<Schema>("Kitchen");
    ObId object = k->add_ob("Object");
    ObId in = k->add_ob("InReceptacle");
    ObId bread = k->add_ob("BreadSliced");
    ObId stacked = k->add_ob("Stacked");
    ObId gripper = k->add_ob("Gripper");
    AttrTypeId temperature = k->add_attr_type("Temperature", ValueKind::Float);
    AttrTypeId shade = k->add_attr_type("Shade", ValueKind::String);
    HomId in_l = k->add_hom("inReceptacle_l", in, object);
    HomId in_r = k->add_hom("inReceptacle_r", in, object);
    HomId bread_is_object = k->add_hom("breadIsObject", bread, object);
    HomId holding = k->add_hom("isHolding", gripper, object);
    AttrId bread_temperature = k->add_attr("breadTemperature", bread, temperature);
    AttrId stacked_shade = k->add_attr("stackedShade", stacked, shade);
    migrate::SchemaMap f(k, b.s);
    f.map_ob(object, b.block);
    f.map_ob(in, b.on);
    f.map_ob(gripper, b.gripper);
    migrate::Query purple(b.s);
    purple.add_variable("block", b.block);
    purple.add_equation(migrate::Term::path("block", {}, b.has_color),
                        migrate::Term::constant(Value::string("purple")));
    f.map_ob(bread, std::move(purple));
    migrate::Query on_something(b.s);
    on_something.add_variable("o", b.on);
    on_something.add_value_variable("C", b.color);
    on_something.add_equation(migrate::Term::path("o", {b.on_l}, b.has_color),
                              migrate::Term::path("C"));
    f.map_ob(stacked, std::move(on_something));
    f.map_hom_path(in_l, {b.on_l});
    f.map_hom_path(in_r, {b.on_r});
    f.map_hom_path(holding, {b.is_holding});
    f.map_hom(bread_is_object, {migrate::Term::path("block")});
    f.map_attr_type(temperature, ValueKind::Float);
    f.map_attr_type(shade, b.color);
    f.map_attr_constant(bread_temperature, Value::real(0.0));
    f.map_attr(stacked_shade, migrate::Term::path("C"));
    for (const auto& p : f.finish()) {
        ADD_FAILURE() << p.message;
    }
    return f;
}

TEST(DotGolden, ConjunctiveMap) {
    Blocks b;
    expect_golden("kitchen_map", map_to_dot(kitchen_map(b), "ColorToKitchen"));
}

TEST(DotGolden, DeltaMap) {
    Blocks b;
    auto t = std::make_shared<Schema>("Stacks");
    ObId thing = t->add_ob("Block"); // the same name as the source object: ids stay apart
    ObId rel = t->add_ob("Above");
    HomId top = t->add_hom("top", rel, thing);
    HomId below = t->add_hom("below", rel, thing);
    AttrTypeId paint = t->add_attr_type("Paint", ValueKind::String);
    AttrId painted = t->add_attr("painted", thing, paint);
    migrate::SchemaMap f(t, b.s);
    f.map_ob(thing, b.block);
    f.map_ob(rel, b.on);
    f.map_hom_path(top, {b.on_l});
    f.map_hom_path(below, {b.on_r});
    f.map_attr_type(paint, b.color);
    f.map_attr(painted, migrate::Term::path("Block", {}, b.has_color));
    ASSERT_TRUE(f.finish().empty());
    expect_golden("delta_map", map_to_dot(f, "Swap"));
}

// ---- unit tests -------------------------------------------------------------------------------

TEST(DotId, BareOnlyForPlainIdentifiers) {
    EXPECT_EQ(dot_id("Block_3"), "Block_3");
    EXPECT_EQ(dot_id("_x9"), "_x9");
    EXPECT_EQ(dot_id("3a"), "\"3a\"");
    EXPECT_EQ(dot_id(""), "\"\"");
    EXPECT_EQ(dot_id("a b"), "\"a b\"");
    EXPECT_EQ(dot_id("node"), "\"node\"");
    EXPECT_EQ(dot_id("Subgraph"), "\"Subgraph\"");
    EXPECT_EQ(dot_id("nodes"), "nodes");
    EXPECT_EQ(dot_id("Blöck"), "\"Blöck\"");
    EXPECT_EQ(dot_id("a\"b\\c"), "\"a\\\"b\\\\c\"");
}

TEST(DotEscape, QuotedStrings) {
    EXPECT_EQ(escape_quoted("plain ünïcode"), "plain ünïcode");
    EXPECT_EQ(escape_quoted("say \"hi\""), "say \\\"hi\\\"");
    EXPECT_EQ(escape_quoted("\\N"), "\\\\N");
    EXPECT_EQ(escape_quoted("a\r\nb"), "a\\nb");
}

TEST(DotEscape, HtmlText) {
    EXPECT_EQ(escape_html("<a & \"b\">"), "&lt;a &amp; &quot;b&quot;&gt;");
    EXPECT_EQ(escape_html("x\ny"), "x<BR/>y");
    EXPECT_EQ(escape_html("&amp;"), "&amp;amp;");
    EXPECT_EQ(escape_html("☃"), "☃");
}

TEST(DotState, EscapesNamesAndValues) {
    auto s = std::make_shared<Schema>("S");
    ObId x = s->add_ob("X");
    AttrTypeId t = s->add_attr_type("T", ValueKind::String);
    AttrId a = s->add_attr("a", x, t);
    ACSet st(s);
    Part p = st.add_part(x, "<p>");
    st.set_subpart(a, p, Value::string("x<y"));
    st.add_part(x, "say \"hi\"");
    std::string dot = state_to_dot(st, "s");
    EXPECT_TRUE(contains(dot, "<B>&lt;p&gt;</B>"));
    EXPECT_TRUE(contains(dot, "a = &quot;x&lt;y&quot;"));
    EXPECT_TRUE(contains(dot, "X_2 [label=\"say \\\"hi\\\"\"];"));
}

TEST(DotState, DeterministicAndIndependentOfIndexes) {
    Blocks b;
    ACSet x = b.initial();
    std::string first = state_to_dot(x, "Initial");
    x.build_indexes();
    (void)x.incident(b.on_l, 4);
    EXPECT_EQ(state_to_dot(x, "Initial"), first);
    EXPECT_EQ(state_to_dot(b.initial(), "Initial"), first);
}

TEST(DotState, StableNodeIdsAndUnnamedParts) {
    Blocks b;
    std::string dot = state_to_dot(b.initial(), "Initial");
    EXPECT_TRUE(contains(dot, "Block_3 [shape=plain"));
    EXPECT_TRUE(contains(dot, "<B>#6</B>"));           // the unnamed block
    EXPECT_TRUE(contains(dot, ">hasColor = ?c</TD>")); // its variables
    EXPECT_TRUE(contains(dot, ">isClear = ?1</TD>"));
    EXPECT_TRUE(contains(dot, "Gripper_1 -> Block_6 [label=\"isHolding\"];"));
}

TEST(DotState, RelationObjectsAsEdges) {
    Blocks b;
    std::string folded = state_to_dot(b.initial(), "Initial");
    EXPECT_TRUE(contains(folded, "Block_5 -> Block_4 [label=\"On x1\""));
    EXPECT_FALSE(contains(folded, "cluster_On"));
    DotOptions o;
    o.relation_edges = false;
    std::string plain = state_to_dot(b.initial(), "Initial", o);
    EXPECT_TRUE(contains(plain, "subgraph cluster_On {"));
    EXPECT_TRUE(contains(plain, "On_1 -> Block_5 [label=\"on_l\"];"));
    EXPECT_TRUE(contains(plain, "On_1 -> Block_4 [label=\"on_r\"];"));
}

TEST(DotState, RelationPartWithAnUnsetEndIsANode) {
    Blocks b;
    ACSet x(b.s);
    Part a = x.add_part(b.block, "A");
    Part o = x.add_part(b.on, "half");
    x.set_subpart(b.on_l, o, a);
    std::string dot = state_to_dot(x, "partial");
    EXPECT_TRUE(contains(dot, "On_1 [label=\"half\"];"));
    EXPECT_TRUE(contains(dot, "On_1 -> Block_1 [label=\"on_l\"];"));
}

TEST(DotState, PredicateObjectsAsRows) {
    Slides sl;
    std::string rows = state_to_dot(sl.state(), "s");
    EXPECT_TRUE(contains(rows, "PORT=\"IsClear_1\""));
    EXPECT_TRUE(contains(rows, "isClear = true"));
    EXPECT_FALSE(contains(rows, "IsClear_1 ["));
    // The fact with no block is a node of its own.
    EXPECT_TRUE(contains(rows, "IsClear_4 [shape=plain"));
    DotOptions named;
    named.predicate_part_names = true;
    EXPECT_TRUE(contains(state_to_dot(sl.state(), "s", named), "clearA:</FONT> isClear = true"));
    DotOptions o;
    o.predicate_rows = false;
    std::string nodes = state_to_dot(sl.state(), "s", o);
    EXPECT_TRUE(contains(nodes, "IsClear_1 [shape=plain"));
    EXPECT_TRUE(contains(nodes, "IsClear_1 -> Block_2 [label=\"isClearDom\"];"));
}

// A Kitchenworld-like state: two sliced things (attributes make them things, not relations), each
// an Object and a Receptacle, one in the other, a knife (an Object only), a gripper holding it and
// a marker Object no thing is.
struct Kitchen {
    std::shared_ptr<Schema> s = std::make_shared<Schema>("Kitchen");
    ObId object = s->add_ob("Object"), receptacle = s->add_ob("Receptacle");
    ObId bread = s->add_ob("Bread"), knife = s->add_ob("Knife");
    ObId in = s->add_ob("InReceptacle"), gripper = s->add_ob("Gripper");
    HomId bread_object = s->add_hom("breadIsObject", bread, object);
    HomId bread_receptacle = s->add_hom("breadIsReceptacle", bread, receptacle);
    HomId knife_object = s->add_hom("knifeIsObject", knife, object);
    HomId in_l = s->add_hom("in_l", in, object), in_r = s->add_hom("in_r", in, receptacle);
    HomId holding = s->add_hom("isHolding", gripper, object);
    AttrTypeId mass = s->add_attr_type("Mass", ValueKind::Float);
    AttrId knife_mass = s->add_attr("knifeHasMass", knife, mass);
    // With no attribute, Bread would be a binary relation drawn as an edge.
    AttrId bread_mass = s->add_attr("breadHasMass", bread, mass);

    ACSet state() const {
        ACSet x(s);
        for (auto name : {"a", "b", "k", "marker"}) {
            x.add_part(object, name);
        }
        x.add_part(receptacle, "a");
        x.add_part(receptacle, "b");
        Part a = x.add_part(bread, "a"), b = x.add_part(bread, "b");
        x.set_subpart(bread_object, a, 0);
        x.set_subpart(bread_receptacle, a, 0);
        x.set_subpart(bread_object, b, 1);
        x.set_subpart(bread_receptacle, b, 1);
        Part k = x.add_part(knife, "k");
        x.set_subpart(knife_object, k, 2);
        x.set_subpart(knife_mass, k, Value::real(0.5));
        Part i = x.add_part(in, "x1");
        x.set_subpart(in_l, i, 0); // a is in b
        x.set_subpart(in_r, i, 1);
        Part g = x.add_part(gripper, "gripper");
        x.set_subpart(holding, g, 2);
        return x;
    }
};

TEST(DotState, FacetsAsRowsOfTheirEntity) {
    Kitchen kt;
    std::string dot = state_to_dot(kt.state(), "k");
    // Each sliced thing is one node with a row per facet; the knife's attribute makes it an
    // entity too, not a predicate row of its Object.
    EXPECT_TRUE(contains(dot, "Bread_1 [shape=plain"));
    EXPECT_TRUE(contains(dot, "PORT=\"Object_1\""));
    EXPECT_TRUE(contains(dot, "PORT=\"Receptacle_2\""));
    EXPECT_TRUE(contains(dot, "Knife_1 [shape=plain"));
    EXPECT_TRUE(contains(dot, "knifeHasMass = 0.5"));
    EXPECT_FALSE(contains(dot, "Object_1 ["));
    EXPECT_FALSE(contains(dot, "subgraph cluster_Bread"));
    // A thing in another is an edge between their rows: a tower reads as one.
    EXPECT_TRUE(
        contains(dot, "Bread_1:Object_1 -> Bread_2:Receptacle_2 [label=\"InReceptacle x1\""));
    EXPECT_TRUE(contains(dot, "Gripper_1 -> Knife_1:Object_3 [label=\"isHolding\"];"));
    EXPECT_FALSE(contains(dot, "label=\"breadIsObject\""));
    // An Object that no thing is stays a node of its own.
    EXPECT_TRUE(contains(dot, "Object_4 [label=\"marker\"];"));
    DotOptions o;
    o.facet_rows = false;
    std::string plain = state_to_dot(kt.state(), "k", o);
    EXPECT_TRUE(contains(plain, "Bread_1 -> Object_1 [label=\"breadIsObject\"];"));
    EXPECT_TRUE(contains(plain, "Object_1 -> Receptacle_2 [label=\"InReceptacle x1\""));
}

TEST(DotState, MarksAndLabelsOfFacetsGoToTheirEntity) {
    Kitchen kt;
    std::vector<PartClass> classes = {{kt.receptacle, 1, "matched"}};
    std::vector<PartLabel> labels = {{kt.object, 3, "isEmpty(empty)"}};
    std::string dot = state_to_dot(kt.state(), "k", {}, classes, labels);
    EXPECT_TRUE(contains(dot, "</TABLE>>, class=\"matched\"];")); // on Bread_2's node
    EXPECT_TRUE(contains(dot, "Object_4 [label=\"isEmpty(empty)\"];"));
}

TEST(DotState, HiddenAttributes) {
    Kitchen kt;
    DotOptions o;
    o.attributes_hidden = {"Knife"};
    EXPECT_FALSE(contains(state_to_dot(kt.state(), "k", o), "knifeHasMass"));
}

TEST(DotState, EmptyState) {
    Blocks b;
    std::string dot = state_to_dot(ACSet(b.s), "nothing");
    EXPECT_TRUE(contains(dot, "(empty)"));
}

TEST(DotRule, PanelsAndMaps) {
    Blocks b;
    std::string dot = rule_to_dot(b.unstack());
    EXPECT_TRUE(contains(dot, "subgraph cluster_Pre {"));
    EXPECT_TRUE(contains(dot, "subgraph cluster_Keep {"));
    EXPECT_TRUE(contains(dot, "subgraph cluster_Eff {"));
    // l drawn from Pre with dir=back (so Pre is on the left), r from Keep to Eff.
    EXPECT_TRUE(contains(dot, "Pre_Block_1 -> Keep_Block_1 [style=dashed"));
    EXPECT_TRUE(contains(dot, "Keep_Block_2 -> Eff_Block_2 [style=dashed"));
    EXPECT_TRUE(contains(dot, "Pre_Gripper_1 -> Keep_Gripper_1 [style=dashed"));
    // Keep has no On part: On is an edge in Pre.
    EXPECT_TRUE(contains(dot, "Pre_Block_1 -> Pre_Block_2 [label=\"On o\""));
}

TEST(DotMorphism, RelationPartsOfTheDomainAreNodes) {
    Slides sl;
    ACSet x(sl.s);
    Part a = x.add_part(sl.block, "a"), c = x.add_part(sl.block, "c");
    Part o = x.add_part(sl.on);
    x.set_subpart(sl.on_l, o, a);
    x.set_subpart(sl.on_r, o, c);
    std::string dot = morphism_to_dot(hom::identity(x), x, x, "id");
    EXPECT_TRUE(contains(dot, "dom_On_1 -> codom_On_1 [style=dashed"));
    EXPECT_TRUE(contains(dot, "dom_Block_2 -> codom_Block_2 [style=dashed"));
}

TEST(DotMap, QueryBoxesAndEdges) {
    Blocks b;
    std::string dot = map_to_dot(kitchen_map(b), "F");
    EXPECT_TRUE(contains(dot, "subgraph cluster_target {"));
    EXPECT_TRUE(contains(dot, "subgraph cluster_source {"));
    EXPECT_TRUE(contains(dot, "T_Object -> S_Block;"));
    EXPECT_TRUE(contains(dot, "T_BreadSliced -> Q_BreadSliced;"));
    EXPECT_TRUE(contains(dot, "block::Block"));
    EXPECT_TRUE(contains(dot, "hasColor(block) == &quot;purple&quot;"));
    EXPECT_TRUE(contains(dot, "Q_BreadSliced:v1:e -> S_Block"));
    // The value variable C ranges over the source type Color.
    EXPECT_TRUE(contains(dot, "C::Color"));
    EXPECT_TRUE(contains(dot, "-> S_Color [style=dotted"));
    EXPECT_TRUE(contains(dot, "T_Temperature -> K_Float;"));
    EXPECT_TRUE(contains(dot, "T_Shade -> S_Color;"));
    EXPECT_TRUE(contains(dot, "breadTemperature"));
}

} // namespace
} // namespace catplan::dot
