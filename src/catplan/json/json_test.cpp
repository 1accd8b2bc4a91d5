#include "catplan/json/json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

namespace catplan::json {
namespace {

using acset::ACSet;
using acset::Value;
using schema::Schema;
using schema::SchemaPtr;
using schema::ValueKind;

// ---- schemas built in C++ (the language layer is separate) ----------------------------------

struct Graph {
    std::shared_ptr<Schema> s = std::make_shared<Schema>("Graph");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId tgt = s->add_hom("tgt", e, v);
};

struct LabeledDDS {
    explicit LabeledDDS(ValueKind kind = ValueKind::String) {
        label_type = s->add_attr_type("Label", kind);
        label = s->add_attr("label", x, label_type);
    }

    std::shared_ptr<Schema> s = std::make_shared<Schema>("LabeledDDS");
    ObId x = s->add_ob("X");
    HomId phi = s->add_hom("Φ", x, x);
    AttrTypeId label_type;
    AttrId label;
};

// OntColorBlocksworld, reference §1.2, in declaration order.
struct ColorBlocksworld {
    explicit ColorBlocksworld(bool kinds = true) {
        auto k = [&](ValueKind v) { return kinds ? v : ValueKind::Unknown; };
        color = s->add_attr_type("Color", k(ValueKind::String));
        clear = s->add_attr_type("Clear", k(ValueKind::Bool));
        on_table = s->add_attr_type("OnTable", k(ValueKind::Bool));
        label = s->add_attr_type("Label", k(ValueKind::String));
        is_empty = s->add_hom("isEmpty", empty, block);
        is_holding = s->add_hom("isHolding", gripper, block);
        has_color = s->add_attr("hasColor", has_color_ob, color);
        has_color_dom = s->add_hom("hasColorDom", has_color_ob, block);
        is_clear = s->add_attr("isClear", is_clear_ob, clear);
        is_clear_dom = s->add_hom("isClearDom", is_clear_ob, block);
        is_on_table = s->add_attr("isOnTable", is_on_table_ob, on_table);
        is_on_table_dom = s->add_hom("isOnTableDom", is_on_table_ob, block);
        has_label = s->add_attr("hasLabel", has_label_ob, label);
        has_label_dom = s->add_hom("hasLabelDom", has_label_ob, block);
        on = s->add_ob("On");
        on_l = s->add_hom("onL", on, block);
        on_r = s->add_hom("onR", on, block);
    }

    std::shared_ptr<Schema> s = std::make_shared<Schema>("OntColorBlocksworld");
    ObId block = s->add_ob("Block");
    ObId empty = s->add_ob("Empty");
    ObId gripper = s->add_ob("Gripper");
    ObId has_color_ob = s->add_ob("HasColor");
    ObId is_clear_ob = s->add_ob("IsClear");
    ObId is_on_table_ob = s->add_ob("IsOnTable");
    ObId has_label_ob = s->add_ob("HasLabel");
    ObId on;
    AttrTypeId color, clear, on_table, label;
    HomId is_empty, is_holding, has_color_dom, is_clear_dom, is_on_table_dom, has_label_dom, on_l,
        on_r;
    AttrId has_color, is_clear, is_on_table, has_label;
};

// ---- helpers --------------------------------------------------------------------------------

// Parses `text` as a state on `schema`; the rendered diagnostics land in `errors`.
std::optional<ACSet> read(const SchemaPtr& schema, const std::string& text,
                          std::string* errors = nullptr) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer("x.json", text);
    auto x = read_acset(schema, file, sources, sink);
    if (errors != nullptr) {
        *errors = sink.render();
    } else {
        EXPECT_FALSE(sink.has_errors()) << sink.render();
    }
    EXPECT_EQ(x.has_value(), !sink.has_errors());
    return x;
}

// The rendered diagnostics of reading `text` as a state on `schema` (which must fail).
std::string acset_errors(const SchemaPtr& schema, const std::string& text) {
    std::string errors;
    auto x = read(schema, text, &errors);
    EXPECT_FALSE(x.has_value());
    return errors;
}

SchemaPtr read_schema_text(const std::string& text, std::string* errors = nullptr) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer("s.json", text);
    auto s = read_schema("S", file, sources, sink);
    if (errors != nullptr) {
        *errors = sink.render();
    } else {
        EXPECT_FALSE(sink.has_errors()) << sink.render();
    }
    EXPECT_EQ(s != nullptr, !sink.has_errors());
    return s;
}

std::string schema_errors(const std::string& text) {
    std::string errors;
    EXPECT_EQ(read_schema_text(text, &errors), nullptr);
    return errors;
}

// write(x) == expected, read(expected) == x, and write(read(expected)) == expected.
void expect_round_trip(const ACSet& x, const std::string& expected) {
    EXPECT_EQ(write_acset(x), expected);
    auto back = read(x.schema_ptr(), expected);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, x);
    EXPECT_EQ(write_acset(*back), expected);
    // Pretty output is the same document.
    EXPECT_EQ(nlohmann::ordered_json::parse(write_acset(x, true)),
              nlohmann::ordered_json::parse(expected));
}

// ---- the three examples of the reference, §2.5 ----------------------------------------------

TEST(AcsetJson, GraphExampleRoundTrips) {
    Graph g;
    ACSet x(g.s);
    x.add_parts(g.v, 4);
    x.add_parts(g.e, 2);
    x.set_subpart(g.src, 0, 0);
    x.set_subpart(g.src, 1, 1);
    x.set_subpart(g.tgt, 0, 1);
    x.set_subpart(g.tgt, 1, 2);
    expect_round_trip(x, R"({"V":[{"_id":1},{"_id":2},{"_id":3},{"_id":4}],)"
                         R"("E":[{"_id":1,"src":1,"tgt":2},{"_id":2,"src":2,"tgt":3}]})");
}

ACSet labeled_dds(const LabeledDDS& d) {
    ACSet x(d.s);
    x.add_parts(d.x, 4);
    for (Part p = 0; p < 4; ++p) {
        x.set_subpart(d.phi, p, (p + 1) % 4);
    }
    Value v1 = x.add_var(d.label_type);
    Value v2 = x.add_var(d.label_type);
    x.set_subpart(d.label, 0, v1);
    x.set_subpart(d.label, 1, Value::string("a"));
    x.set_subpart(d.label, 2, Value::string("b"));
    x.set_subpart(d.label, 3, v2);
    return x;
}

const std::string kLabeledDDSJson =
    R"({"X":[{"_id":1,"Φ":2,"label":{"_var":1}},{"_id":2,"Φ":3,"label":"a"},)"
    R"({"_id":3,"Φ":4,"label":"b"},{"_id":4,"Φ":1,"label":{"_var":2}}],)"
    R"("Label":[{"_id":1},{"_id":2}]})";

TEST(AcsetJson, LabeledDDSExampleRoundTripsWithVariables) {
    LabeledDDS d;
    expect_round_trip(labeled_dds(d), kLabeledDDSJson);
}

TEST(AcsetJson, ReadingInfersAnUnknownKindIntoACopyOfTheSchema) {
    LabeledDDS unknown(ValueKind::Unknown);
    auto x = read(unknown.s, kLabeledDDSJson);
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->schema().attr_type(unknown.label_type).kind, ValueKind::String);
    EXPECT_NE(x->schema_ptr(), SchemaPtr(unknown.s));
    EXPECT_EQ(unknown.s->attr_type(unknown.label_type).kind, ValueKind::Unknown); // untouched
    EXPECT_EQ(x->subpart(unknown.label, 1), Value::string("a"));
    EXPECT_EQ(x->subpart(unknown.label, 3), Value::var(1));
    EXPECT_EQ(write_acset(*x), kLabeledDDSJson);

    // A known kind keeps the very same schema.
    LabeledDDS known;
    auto y = read(known.s, kLabeledDDSJson);
    ASSERT_TRUE(y.has_value());
    EXPECT_EQ(y->schema_ptr(), SchemaPtr(known.s));
}

const std::string kColorBlocksJson =
    R"({"Block":[{"_id":1},{"_id":2}],)"
    R"("Empty":[{"_id":1,"isEmpty":1}],)"
    R"("Gripper":[{"_id":1,"isHolding":1}],)"
    R"("HasColor":[{"_id":1,"hasColorDom":2,"hasColor":"green"}],)"
    R"("IsClear":[{"_id":1,"isClearDom":2,"isClear":true}],)"
    R"("IsOnTable":[{"_id":1,"isOnTableDom":2,"isOnTable":true}],)"
    R"("HasLabel":[{"_id":1,"hasLabelDom":1,"hasLabel":"null"},{"_id":2,"hasLabelDom":2,"hasLabel":"A"}],)"
    R"("On":[],)"
    R"("Color":[],"Clear":[],"OnTable":[],"Label":[]})";

TEST(AcsetJson, ColorBlocksworldExampleRoundTrips) {
    ColorBlocksworld c;
    ACSet x(c.s);
    Part null = x.add_part(c.block, "null");
    Part a = x.add_part(c.block, "A");
    x.set_subpart(c.is_empty, x.add_part(c.empty), null);
    x.set_subpart(c.is_holding, x.add_part(c.gripper), null);
    Part hc = x.add_part(c.has_color_ob);
    x.set_subpart(c.has_color_dom, hc, a);
    x.set_subpart(c.has_color, hc, Value::string("green"));
    Part ic = x.add_part(c.is_clear_ob);
    x.set_subpart(c.is_clear_dom, ic, a);
    x.set_subpart(c.is_clear, ic, Value::boolean(true));
    Part it = x.add_part(c.is_on_table_ob);
    x.set_subpart(c.is_on_table_dom, it, a);
    x.set_subpart(c.is_on_table, it, Value::boolean(true));
    Part hl0 = x.add_part(c.has_label_ob);
    x.set_subpart(c.has_label_dom, hl0, null);
    x.set_subpart(c.has_label, hl0, Value::string("null"));
    Part hl1 = x.add_part(c.has_label_ob);
    x.set_subpart(c.has_label_dom, hl1, a);
    x.set_subpart(c.has_label, hl1, Value::string("A"));
    expect_round_trip(x, kColorBlocksJson);

    // Without declared kinds each is inferred: Color, Label String; Clear, OnTable Bool.
    ColorBlocksworld unknown(false);
    auto y = read(unknown.s, kColorBlocksJson);
    ASSERT_TRUE(y.has_value());
    EXPECT_EQ(*y, x);
    EXPECT_EQ(y->schema().attr_type(unknown.color).kind, ValueKind::String);
    EXPECT_EQ(y->schema().attr_type(unknown.clear).kind, ValueKind::Bool);
    EXPECT_EQ(y->schema().attr_type(unknown.on_table).kind, ValueKind::Bool);
    EXPECT_EQ(y->schema().attr_type(unknown.label).kind, ValueKind::String);
}

// ---- values ---------------------------------------------------------------------------------

struct Weighted {
    explicit Weighted(ValueKind kind) { s->set_kind(t, kind); }

    std::shared_ptr<Schema> s = std::make_shared<Schema>("Weighted");
    ObId x = s->add_ob("X");
    AttrTypeId t = s->add_attr_type("W");
    AttrId w = s->add_attr("w", x, t);
};

TEST(AcsetJson, FloatsReadBackExactly) {
    Weighted d(ValueKind::Float);
    ACSet x(d.s);
    const std::vector<double> values = {0.0,  -0.0, 0.1,  1.0 / 3.0, 1e-300,
                                        5e22, -2.5, 1e16, 4.9e-324};
    for (double f : values) {
        x.set_subpart(d.w, x.add_part(d.x), Value::real(f));
    }
    std::string text = write_acset(x);
    EXPECT_NE(text.find(R"("w":0.0})"), std::string::npos) << text; // 0.0 stays a float
    EXPECT_NE(text.find(R"("w":0.1})"), std::string::npos) << text; // shortest form
    auto back = read(d.s, text);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, x);
    EXPECT_TRUE(std::signbit(back->subpart(d.w, 1).as_float()));
    EXPECT_EQ(write_acset(*back), text);
}

TEST(AcsetJson, IntegersAreAcceptedForFloatAttributes) {
    Weighted d(ValueKind::Float);
    auto x = read(d.s, R"({"X":[{"_id":1,"w":2},{"_id":2,"w":2.5},{"_id":3,"w":null}],"W":[]})");
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->subpart(d.w, 0), Value::real(2.0));
    EXPECT_EQ(x->subpart(d.w, 1), Value::real(2.5));
    EXPECT_TRUE(x->subpart(d.w, 2).is_unset());
    EXPECT_EQ(write_acset(*x),
              R"({"X":[{"_id":1,"w":2.0},{"_id":2,"w":2.5},{"_id":3,"w":null}],"W":[]})");
}

TEST(AcsetJson, InferenceWidensIntToFloatAndKeepsInt) {
    Weighted mixed(ValueKind::Unknown);
    auto x = read(mixed.s, R"({"X":[{"_id":1,"w":2},{"_id":2,"w":2.5}],"W":[]})");
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->schema().attr_type(mixed.t).kind, ValueKind::Float);
    EXPECT_EQ(x->subpart(mixed.w, 0), Value::real(2.0));

    Weighted ints(ValueKind::Unknown);
    auto y = read(ints.s, R"({"X":[{"_id":1,"w":-7},{"_id":2,"w":9007199254740993}],"W":[]})");
    ASSERT_TRUE(y.has_value());
    EXPECT_EQ(y->schema().attr_type(ints.t).kind, ValueKind::Int);
    EXPECT_EQ(y->subpart(ints.w, 1), Value::integer(9007199254740993));
}

TEST(AcsetJson, UnsetHomsAndAttributesAndMissingColumns) {
    LabeledDDS d;
    ACSet x(d.s);
    x.add_parts(d.x, 2);
    x.set_subpart(d.phi, 0, 1);
    x.set_subpart(d.label, 1, Value::string("q\"uote\\ \u00e9"));
    std::string text = write_acset(x);
    EXPECT_EQ(text, R"({"X":[{"_id":1,"Φ":2,"label":null},{"_id":2,"Φ":0,"label":"q\"uote\\ é"}],)"
                    R"("Label":[]})");
    auto back = read(d.s, text);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, x);
    // As in Catlab, a column left out of a row is unset.
    auto sparse =
        read(d.s, R"({"X":[{"_id":1,"Φ":2},{"_id":2,"label":"q\"uote\\ é"}],"Label":[]})");
    ASSERT_TRUE(sparse.has_value());
    EXPECT_EQ(*sparse, x);
}

TEST(AcsetJson, OlderValSpellingOfVariablesIsAccepted) {
    LabeledDDS d;
    auto x = read(d.s, R"({"X":[{"_id":1,"Φ":1,"label":{"val":1}}],"Label":[{"_id":1}]})");
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->subpart(d.label, 0), Value::var(0));
    EXPECT_EQ(x->num_vars(d.label_type), 1u);
}

// ---- the author's older files ---------------------------------------------------------------

// BreadWorld (reference §1.9) with the BreadSlice object of its AAAI variant, in the object
// order of the author's cache files.
struct BreadWorld {
    explicit BreadWorld(bool with_slice) {
        if (with_slice) {
            slice = s->add_ob("BreadSlice");
        }
        counter = s->add_ob("Countertop");
        stool = s->add_ob("Stool");
        loaf_is = s->add_hom("BreadLoafIsThing", loaf, thing);
        counter_is = s->add_hom("CountertopIsThing", counter, thing);
        stool_is = s->add_hom("StoolIsThing", stool, thing);
        in_on = s->add_ob("InOn");
        in_on_l = s->add_hom("inOn_l", in_on, thing);
        in_on_r = s->add_hom("inOn_r", in_on, thing);
    }

    std::shared_ptr<Schema> s = std::make_shared<Schema>("OntBreadWorld");
    ObId thing = s->add_ob("Thing");
    ObId loaf = s->add_ob("BreadLoaf");
    ObId slice, counter, stool, in_on;
    HomId loaf_is, counter_is, stool_is, in_on_l, in_on_r;
};

TEST(AcsetJson, ReadsTheAuthorsInOnCacheFile) {
    const std::string in_on_json =
        R"({"Thing":[{"_id":1},{"_id":2}],"BreadLoaf":[],"BreadSlice":[],"Countertop":[],)"
        R"("Stool":[],"InOn":[{"_id":1,"inOn_l":1,"inOn_r":2}]})";
    BreadWorld b(true);
    auto x = read(b.s, in_on_json);
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->num_parts(b.thing), 2u);
    EXPECT_EQ(x->num_parts(b.in_on), 1u);
    EXPECT_EQ(x->subpart(b.in_on_l, 0), 0u);
    EXPECT_EQ(x->subpart(b.in_on_r, 0), 1u);
    EXPECT_EQ(write_acset(*x), in_on_json);

    // §1.9's schema has no BreadSlice: the file does not fit it.
    BreadWorld plain(false);
    EXPECT_EQ(acset_errors(plain.s, in_on_json),
              "x.json:1:47: error: unknown object or attribute type 'BreadSlice' in schema "
              "'OntBreadWorld'\n"
              "    1 | " +
                  in_on_json +
                  "\n"
                  "      |                                               ^~~~~~~~~~~~\n");
}

TEST(AcsetJson, BreadWorldStateRoundTrips) {
    BreadWorld b(false);
    ACSet x(b.s);
    x.add_parts(b.thing, 4);
    x.set_subpart(b.loaf_is, x.add_part(b.loaf), 0);
    x.set_subpart(b.counter_is, x.add_part(b.counter), 1);
    x.set_subpart(b.counter_is, x.add_part(b.counter), 2);
    x.set_subpart(b.stool_is, x.add_part(b.stool), 3);
    Part io = x.add_part(b.in_on);
    x.set_subpart(b.in_on_l, io, 0);
    x.set_subpart(b.in_on_r, io, 1);
    expect_round_trip(
        x, R"({"Thing":[{"_id":1},{"_id":2},{"_id":3},{"_id":4}],)"
           R"("BreadLoaf":[{"_id":1,"BreadLoafIsThing":1}],)"
           R"("Countertop":[{"_id":1,"CountertopIsThing":2},{"_id":2,"CountertopIsThing":3}],)"
           R"("Stool":[{"_id":1,"StoolIsThing":4}],"InOn":[{"_id":1,"inOn_l":1,"inOn_r":2}]})");
}

// ---- schemas --------------------------------------------------------------------------------

const std::string kSchGraphJson =
    R"({"version":{"ACSetSchema":"0.0.1","ACSets":"0.2.27"},)"
    R"("Ob":[{"name":"V"},{"name":"E"}],)"
    R"("Hom":[{"name":"src","dom":"E","codom":"V"},{"name":"tgt","dom":"E","codom":"V"}],)"
    R"("AttrType":[],"Attr":[],"equations":[]})";

// ---- what older Catlab wrote, and what catplan adds -----------------------------------------

TEST(AcsetJson, RowsWithoutIdAndEmptyVariableRowsAreAccepted) {
    // Catlab before 2023: no "_id", and a variable written as {}.
    LabeledDDS d(ValueKind::String);
    auto x = read(d.s, R"({"X":[{"Φ":2,"label":"a"},{"Φ":1,"label":{"_var":1}}],"Label":[{}]})");
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->num_parts(d.x), 2u);
    EXPECT_EQ(x->num_vars(d.label_type), 1u);
    EXPECT_EQ(x->subpart(d.phi, 0), 1u);
    EXPECT_EQ(x->subpart(d.label, 1), Value::var(0));
    EXPECT_EQ(write_acset(*x),
              R"({"X":[{"_id":1,"Φ":2,"label":"a"},{"_id":2,"Φ":1,"label":{"_var":1}}],)"
              R"("Label":[{"_id":1}]})");
}

TEST(AcsetJson, AMissingTableHasNoParts) {
    Graph g;
    auto x = read(g.s, R"({"V":[{"_id":1}]})");
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->num_parts(g.v), 1u);
    EXPECT_EQ(x->num_parts(g.e), 0u);
    // An edge cannot point into a table that is absent.
    EXPECT_EQ(acset_errors(g.s, R"({"E":[{"src":1,"tgt":0}]})"),
              "x.json:1:14: error: hom 'src' of E #1 points to V #1, but 'V' has 0 parts\n"
              "    1 | {\"E\":[{\"src\":1,\"tgt\":0}]}\n"
              "      |              ^\n");
}

TEST(AcsetJson, NamesRoundTripWhenAskedFor) {
    LabeledDDS d(ValueKind::String);
    ACSet x(d.s);
    x.add_part(d.x, "A");
    x.add_part(d.x);
    Value v = x.add_var(d.label_type, "c");
    x.set_subpart(d.phi, 0, 1);
    x.set_subpart(d.label, 0, v);
    // Without names the file is what ACSets.jl reads; with them each named row has "_name".
    EXPECT_EQ(write_acset(x), R"({"X":[{"_id":1,"Φ":2,"label":{"_var":1}},)"
                              R"({"_id":2,"Φ":0,"label":null}],"Label":[{"_id":1}]})");
    std::string named = write_acset(x, false, true);
    EXPECT_EQ(named, R"({"X":[{"_id":1,"_name":"A","Φ":2,"label":{"_var":1}},)"
                     R"({"_id":2,"Φ":0,"label":null}],"Label":[{"_id":1,"_name":"c"}]})");
    auto back = read(d.s, named);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->part_name(d.x, 0), "A");
    EXPECT_EQ(back->part_name(d.x, 1), "");
    EXPECT_EQ(back->var_name(d.label_type, 0), "c");
    EXPECT_EQ(write_acset(*back, false, true), named);
    EXPECT_EQ(acset_errors(d.s, R"({"X":[{"_name":7}],"Label":[]})"),
              "x.json:1:16: error: \"_name\" must be a string, found the integer 7\n"
              "    1 | {\"X\":[{\"_name\":7}],\"Label\":[]}\n"
              "      |                ^\n");
}

// A reflexive graph: refl ⋅ src == id(V), named.
struct Reflexive {
    std::shared_ptr<Schema> s = std::make_shared<Schema>("Reflexive");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId refl = s->add_hom("refl", v, e);

    Reflexive() {
        s->add_equation({"loop", {v, {refl, src}, std::nullopt}, {v, {}, std::nullopt}, {}});
    }
};

TEST(AcsetJson, AStateThatBreaksAnEquationIsRejectedAtItsRow) {
    Reflexive r;
    EXPECT_TRUE(read(r.s, R"({"V":[{"refl":1},{"refl":2}],"E":[{"src":1},{"src":2}]})"));
    // An unset hom leaves the equation unchecked.
    EXPECT_TRUE(read(r.s, R"({"V":[{"refl":0}],"E":[]})"));
    EXPECT_EQ(acset_errors(r.s, "{\"V\":[{\"refl\":1},\n {\"refl\":1}],\"E\":[{\"src\":1}]}"),
              "x.json:2:2: error: row 2 of 'V' breaks the equation loop: refl ⋅ src == id(V) of "
              "schema 'Reflexive': refl ⋅ src gives V #1, id(V) gives V #2\n"
              "    2 |  {\"refl\":1}],\"E\":[{\"src\":1}]}\n"
              "      |  ^\n");
}

TEST(AcsetJson, AttributeEquationsCompareValuesAndVariables) {
    auto s = std::make_shared<Schema>("W");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    AttrTypeId w = s->add_attr_type("Weight", ValueKind::Int);
    AttrId vw = s->add_attr("vw", v, w);
    AttrId ew = s->add_attr("ew", e, w);
    s->add_equation({"", {e, {src}, vw}, {e, {}, ew}, {}});
    EXPECT_TRUE(
        read(s, R"({"V":[{"vw":{"_var":1}}],"E":[{"src":1,"ew":{"_var":1}}],"Weight":[{}]})"));
    EXPECT_EQ(acset_errors(s, R"({"V":[{"vw":3}],"E":[{"src":1,"ew":4}],"Weight":[]})"),
              "x.json:1:22: error: row 1 of 'E' breaks the equation src ⋅ vw == ew of schema 'W': "
              "src ⋅ vw gives 3, ew gives 4\n"
              "    1 | {\"V\":[{\"vw\":3}],\"E\":[{\"src\":1,\"ew\":4}],\"Weight\":[]}\n"
              "      |                      ^\n");
}

TEST(SchemaJson, KindsRoundTripInAKeyACSetsIgnores) {
    LabeledDDS d(ValueKind::Float);
    std::string text = write_schema(*d.s);
    EXPECT_NE(text.find(R"("AttrType":[{"name":"Label","kind":"Float"}])"), std::string::npos)
        << text;
    auto back = read_schema_text(text);
    ASSERT_NE(back, nullptr);
    EXPECT_EQ(back->attr_type(AttrTypeId(0)).kind, ValueKind::Float);
    EXPECT_EQ(write_schema(*back), text);
    EXPECT_EQ(
        schema_errors(R"({"Ob":[],"Hom":[],"AttrType":[{"name":"T","kind":"Complex"}]})"),
        "s.json:1:50: error: \"kind\" of an attribute type must be one of \"Bool\", \"Int\", "
        "\"Float\", \"String\", found the string \"Complex\"\n"
        "    1 | {\"Ob\":[],\"Hom\":[],\"AttrType\":[{\"name\":\"T\",\"kind\":\"Complex\"}]}\n"
        "      |                                                  ^~~~~~~~~\n");
}

TEST(SchemaJson, SchGraphIsWrittenAsCatlabDoes) {
    Graph g;
    EXPECT_EQ(nlohmann::json::parse(write_schema(*g.s)), nlohmann::json::parse(kSchGraphJson));
    EXPECT_EQ(write_schema(*g.s), kSchGraphJson); // and our key order is Catlab's listing
    EXPECT_EQ(nlohmann::json::parse(write_schema(*g.s, true)),
              nlohmann::json::parse(kSchGraphJson));
}

TEST(SchemaJson, SchGraphReadsBackWhateverTheInnerKeyOrder) {
    auto s = read_schema_text(
        R"({"Hom":[{"codom":"V","name":"src","dom":"E"},{"dom":"E","codom":"V","name":"tgt"}],)"
        R"("Ob":[{"name":"V"},{"name":"E"}],"AttrType":[],"Attr":[],"equations":[],)"
        R"("version":{"ACSets":"0.2.27","ACSetSchema":"0.0.1"}})");
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->name(), "S");
    ASSERT_EQ(s->num_obs(), 2u);
    EXPECT_EQ(s->ob(ObId(0)).name, "V");
    ASSERT_EQ(s->num_homs(), 2u);
    EXPECT_EQ(s->hom(HomId(1)).name, "tgt");
    EXPECT_EQ(s->hom(HomId(1)).dom, ObId(1));
    EXPECT_EQ(s->hom(HomId(1)).codom, ObId(0));
    EXPECT_EQ(write_schema(*s), kSchGraphJson);
}

TEST(SchemaJson, OlderDomainCodomainSpellingAndNoEquations) {
    auto s = read_schema_text(
        R"({"version":{"ACSetSchema":"0.0.1","Catlab":"0.14.0"},"Ob":[{"name":"V"},{"name":"E"}],)"
        R"("Hom":[{"name":"src","domain":"E","codomain":"V"},{"name":"tgt","domain":"E","codomain":"V"}],)"
        R"("AttrType":[],"Attr":[]})");
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(write_schema(*s), kSchGraphJson);
}

TEST(SchemaJson, EquationsAndAttributesRoundTrip) {
    // A reflexive graph: refl ⋅ src = id(V) = refl ⋅ tgt, and a weight equation through src.
    auto s = std::make_shared<Schema>("ReflWeighted");
    ObId v = s->add_ob("V");
    ObId e = s->add_ob("E");
    HomId src = s->add_hom("src", e, v);
    HomId tgt = s->add_hom("tgt", e, v);
    HomId refl = s->add_hom("refl", v, e);
    AttrTypeId weight = s->add_attr_type("Weight");
    AttrId vw = s->add_attr("vweight", v, weight);
    AttrId ew = s->add_attr("eweight", e, weight);
    s->add_equation({"", {v, {refl, src}, std::nullopt}, {v, {}, std::nullopt}, {}});
    s->add_equation({"", {v, {refl, tgt}, std::nullopt}, {v, {}, std::nullopt}, {}});
    s->add_equation({"w", {e, {src}, vw}, {e, {}, ew}, {}});
    std::string text = write_schema(*s);
    EXPECT_EQ(
        text,
        R"({"version":{"ACSetSchema":"0.0.1","ACSets":"0.2.27"},)"
        R"("Ob":[{"name":"V"},{"name":"E"}],)"
        R"("Hom":[{"name":"src","dom":"E","codom":"V"},{"name":"tgt","dom":"E","codom":"V"},)"
        R"({"name":"refl","dom":"V","codom":"E"}],)"
        R"("AttrType":[{"name":"Weight"}],)"
        R"("Attr":[{"name":"vweight","dom":"V","codom":"Weight"},)"
        R"({"name":"eweight","dom":"E","codom":"Weight"}],)"
        R"("equations":[{"dom":"V","codom":"V","name":null,"paths":[["refl","src"],[]]},)"
        R"({"dom":"V","codom":"V","name":null,"paths":[["refl","tgt"],[]]},)"
        R"({"dom":"E","codom":"Weight","name":"w","paths":[["src","vweight"],["eweight"]]}]})");
    auto back = read_schema_text(text);
    ASSERT_NE(back, nullptr);
    ASSERT_EQ(back->equations().size(), 3u);
    const auto& w = back->equations()[2];
    EXPECT_EQ(w.name, "w");
    EXPECT_EQ(w.lhs, (schema::Path{e, {src}, vw}));
    EXPECT_EQ(w.rhs, (schema::Path{e, {}, ew}));
    EXPECT_EQ(back->equations()[0].lhs, (schema::Path{v, {refl, src}, std::nullopt}));
    EXPECT_EQ(back->equations()[0].name, "");
    EXPECT_EQ(back->attr(AttrId(1)).codom, weight);
    EXPECT_EQ(write_schema(*back), text);
}

TEST(SchemaJson, ColorBlocksworldSchemaRoundTripsAndKeepsLocations) {
    ColorBlocksworld c;
    std::string text = write_schema(*c.s, true);
    auto back = read_schema_text(text);
    ASSERT_NE(back, nullptr);
    EXPECT_EQ(write_schema(*back, true), text);
    EXPECT_EQ(back->num_obs(), 8u);
    EXPECT_EQ(back->num_homs(), 8u);
    EXPECT_EQ(back->attr(c.has_label).name, "hasLabel");
    // Declarations remember where they were read, for later diagnostics.
    EXPECT_TRUE(back->ob(c.on).range.valid());
    // A state written on the original reads on the schema read back.
    auto x = read(back, kColorBlocksJson);
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(write_acset(*x), kColorBlocksJson);
}

TEST(SchemaJson, LooksLikeSchemaTellsSchemasFromInstances) {
    EXPECT_TRUE(looks_like_schema(kSchGraphJson));
    EXPECT_TRUE(looks_like_schema(R"({"Ob":[],"Hom":[]})"));
    EXPECT_FALSE(looks_like_schema(kColorBlocksJson));
    EXPECT_FALSE(looks_like_schema(R"({"Ob":[{"_id":1}],"Hom":[]})")); // objects named Ob, Hom
    EXPECT_FALSE(looks_like_schema("not json"));
    EXPECT_FALSE(looks_like_schema("[1, 2]"));
}

// ---- errors: located, rendered, all at once -------------------------------------------------

TEST(JsonErrors, SyntaxErrorIsLocated) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, "{\"V\": [{\"_id\": 1},\n  ]}"),
              "x.json:2:3: error: invalid JSON: syntax error while parsing value - unexpected "
              "']'; expected '[', '{', or a literal\n"
              "    2 |   ]}\n"
              "      |   ^\n");
}

TEST(JsonErrors, TruncatedInputIsLocatedAtTheEnd) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, "{\"V\": [{\"_id\": 1}"),
              "x.json:1:18: error: invalid JSON: syntax error while parsing array - unexpected "
              "end of input; expected ']'\n"
              "    1 | {\"V\": [{\"_id\": 1}\n"
              "      |                  ^\n");
}

TEST(JsonErrors, TopLevelMustBeAnObject) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, "[1]"),
              "x.json:1:1: error: expected a JSON object with one array per object and attribute "
              "type of schema 'Graph', found an array\n"
              "    1 | [1]\n"
              "      | ^\n");
}

TEST(JsonErrors, UnknownKeys) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, R"({"V":[],"F":[],"src":[]})"),
              "x.json:1:9: error: unknown object or attribute type 'F' in schema 'Graph'\n"
              "    1 | {\"V\":[],\"F\":[],\"src\":[]}\n"
              "      |         ^~~\n"
              "x.json:1:16: error: 'src' is a hom of schema 'Graph', not an object or attribute "
              "type\n"
              "    1 | {\"V\":[],\"F\":[],\"src\":[]}\n"
              "      |                ^~~~~\n");
}

TEST(JsonErrors, RowIdsMustBeRowNumbers) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, R"({"V":[{"_id":1},{"_id":3}],"E":[]})"),
              "x.json:1:24: error: \"_id\" of row 2 of 'V' must be 2 (ids are the 1-based row "
              "numbers), found the integer 3\n"
              "    1 | {\"V\":[{\"_id\":1},{\"_id\":3}],\"E\":[]}\n"
              "      |                        ^\n");
}

TEST(JsonErrors, HomIdOutOfRangeAndNotAnId) {
    Graph g;
    std::string text = "{\"V\":[{\"_id\":1}],\n"
                       " \"E\":[{\"_id\":1,\"src\":2,\"tgt\":1},\n"
                       "      {\"_id\":2,\"src\":1,\"tgt\":\"a\"}]}";
    EXPECT_EQ(acset_errors(g.s, text),
              "x.json:2:22: error: hom 'src' of E #1 points to V #2, but 'V' has 1 part\n"
              "    2 |  \"E\":[{\"_id\":1,\"src\":2,\"tgt\":1},\n"
              "      |                      ^\n"
              "x.json:3:30: error: hom 'tgt' needs a part id of 'V' (an integer, 0 for unset), "
              "found the string \"a\"\n"
              "    3 |       {\"_id\":2,\"src\":1,\"tgt\":\"a\"}]}\n"
              "      |                              ^~~\n");
}

TEST(JsonErrors, ValueOfTheWrongKind) {
    LabeledDDS d;
    EXPECT_EQ(acset_errors(d.s, R"({"X":[{"_id":1,"Φ":1,"label":true}],"Label":[]})"),
              "x.json:1:30: error: attribute 'label' has type 'Label' of kind String, but found "
              "true\n"
              "    1 | {\"X\":[{\"_id\":1,\"Φ\":1,\"label\":true}],\"Label\":[]}\n"
              "      |                              ^~~~\n");
}

TEST(JsonErrors, InferredKindMismatchPointsAtTheValueItCameFrom) {
    LabeledDDS d(ValueKind::Unknown);
    EXPECT_EQ(acset_errors(d.s, "{\"X\":[{\"_id\":1,\"Φ\":1,\"label\":\"a\"},\n"
                                "      {\"_id\":2,\"Φ\":1,\"label\":2.5}],\"Label\":[]}"),
              "x.json:2:30: error: attribute 'label' has type 'Label' of kind String, but found "
              "the number 2.5\n"
              "    2 |       {\"_id\":2,\"Φ\":1,\"label\":2.5}],\"Label\":[]}\n"
              "      |                              ^~~\n"
              "x.json:1:30: note: the kind of 'Label' was inferred from this value\n"
              "    1 | {\"X\":[{\"_id\":1,\"Φ\":1,\"label\":\"a\"},\n"
              "      |                              ^~~\n");
}

TEST(JsonErrors, VariableOutOfRange) {
    LabeledDDS d;
    EXPECT_EQ(
        acset_errors(d.s, R"({"X":[{"_id":1,"Φ":1,"label":{"_var":2}}],"Label":[{"_id":1}]})"),
        "x.json:1:38: error: attribute 'label' of X #1 names variable 2 of 'Label', but "
        "'Label' has 1 variable\n"
        "    1 | {\"X\":[{\"_id\":1,\"Φ\":1,\"label\":{\"_var\":2}}],\"Label\":[{\"_id\":1}]}\n"
        "      |                                      ^\n");
}

TEST(JsonErrors, ForeignColumnAndDuplicateKey) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, R"({"V":[{"_id":1,"src":1}],"E":[],"V":[]})"),
              "x.json:1:16: error: 'src' is not a hom or attribute out of object 'V'\n"
              "    1 | {\"V\":[{\"_id\":1,\"src\":1}],\"E\":[],\"V\":[]}\n"
              "      |                ^~~~~\n"
              "x.json:1:33: error: duplicate key 'V'\n"
              "    1 | {\"V\":[{\"_id\":1,\"src\":1}],\"E\":[],\"V\":[]}\n"
              "      |                                 ^~~\n"
              "x.json:1:2: note: first given here\n"
              "    1 | {\"V\":[{\"_id\":1,\"src\":1}],\"E\":[],\"V\":[]}\n"
              "      |  ^~~\n");
}

TEST(JsonErrors, AllSemanticErrorsAreReportedAtOnce) {
    ColorBlocksworld c;
    std::string text = R"({"Block":[{"_id":1}],"Empty":[{"_id":1,"isEmpty":5}],"Gripper":[],)"
                       R"("HasColor":[{"_id":1,"hasColorDom":1,"hasColor":7}],"IsClear":[],)"
                       R"("IsOnTable":[],"HasLabel":[{"_id":2}],"On":[],)"
                       R"("Color":[],"Clear":[],"OnTable":[],"Label":[]})";
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer("x.json", text);
    EXPECT_FALSE(read_acset(c.s, file, sources, sink).has_value());
    EXPECT_EQ(sink.num_errors(), 3u) << sink.render();
}

TEST(JsonErrors, SchemaHomDomainMustBeAnObject) {
    EXPECT_EQ(
        schema_errors("{\"Ob\":[{\"name\":\"V\"}],\"AttrType\":[{\"name\":\"T\"}],\n"
                      " \"Hom\":[{\"name\":\"f\",\"dom\":\"T\",\"codom\":\"W\"}],\"Attr\":[]}"),
        "s.json:2:27: error: the domain of 'f' must be an object, but 'T' is an attribute "
        "type\n"
        "    2 |  \"Hom\":[{\"name\":\"f\",\"dom\":\"T\",\"codom\":\"W\"}],\"Attr\":[]}\n"
        "      |                           ^~~\n"
        "s.json:2:39: error: the codomain of 'f' must be an object, but 'W' is not "
        "declared\n"
        "    2 |  \"Hom\":[{\"name\":\"f\",\"dom\":\"T\",\"codom\":\"W\"}],\"Attr\":[]}\n"
        "      |                                       ^~~\n");
}

TEST(JsonErrors, SchemaDuplicateNames) {
    EXPECT_EQ(schema_errors(R"({"Ob":[{"name":"V"},{"name":"E"},{"name":"V"}],)"
                            R"("Hom":[{"name":"E","dom":"V","codom":"V"}]})"),
              "s.json:1:42: error: duplicate name 'V'\n"
              "    1 | {\"Ob\":[{\"name\":\"V\"},{\"name\":\"E\"},{\"name\":\"V\"}],\"Hom\":"
              "[{\"name\":\"E\",\"dom\":\"V\",\"codom\":\"V\"}]}\n"
              "      |                                          ^~~\n"
              "s.json:1:16: note: first declared here\n"
              "    1 | {\"Ob\":[{\"name\":\"V\"},{\"name\":\"E\"},{\"name\":\"V\"}],\"Hom\":"
              "[{\"name\":\"E\",\"dom\":\"V\",\"codom\":\"V\"}]}\n"
              "      |                ^~~\n"
              "s.json:1:63: error: duplicate name 'E'\n"
              "    1 | {\"Ob\":[{\"name\":\"V\"},{\"name\":\"E\"},{\"name\":\"V\"}],\"Hom\":"
              "[{\"name\":\"E\",\"dom\":\"V\",\"codom\":\"V\"}]}\n"
              "      |                                                               ^~~\n"
              "s.json:1:29: note: first declared here\n"
              "    1 | {\"Ob\":[{\"name\":\"V\"},{\"name\":\"E\"},{\"name\":\"V\"}],\"Hom\":"
              "[{\"name\":\"E\",\"dom\":\"V\",\"codom\":\"V\"}]}\n"
              "      |                             ^~~\n");
}

TEST(JsonErrors, SchemaEquationPathsMustCompose) {
    std::string errors = schema_errors(
        R"({"Ob":[{"name":"V"},{"name":"E"}],"Hom":[{"name":"src","dom":"E","codom":"V"}],)"
        R"("equations":[{"dom":"E","codom":"V","name":null,"paths":[["src","src"],["src"]]},)"
        R"({"dom":"E","codom":"E","name":null,"paths":[["src"],[]]}]})");
    EXPECT_NE(errors.find("s.json:1:144: error: 'src' starts at 'E', but the path is at 'V' here"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("error: this path ends at 'V', but the equation's codomain is 'E'"),
              std::string::npos)
        << errors;
}

TEST(JsonErrors, EdgeCasesOfTheInputAreLocated) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, ""),
              "x.json:1:1: error: invalid JSON: syntax error while parsing value - unexpected end "
              "of input; expected '[', '{', or a literal\n"
              "    1 | \n"
              "      | ^\n");
    EXPECT_EQ(acset_errors(g.s, R"({"V":[],"E":[{"_id":1e999}]})").substr(0, 60),
              "x.json:1:25: error: invalid JSON: number overflow parsing '1");
    // A byte-order mark is skipped, as by nlohmann.
    EXPECT_TRUE(read(g.s, "\xEF\xBB\xBF{\"V\":[],\"E\":[]}").has_value());
    // Invalid UTF-8 inside a string is a syntax error, not an exception.
    EXPECT_NE(acset_errors(g.s, "{\"V\":[],\"E\":[],\"\xFF\":[]}").find("x.json:1:"),
              std::string::npos);
}

// Mutated documents never crash the reader, never yield a state together with errors, and
// every diagnostic is located.
TEST(JsonErrors, MutatedDocumentsGiveLocatedDiagnosticsOnly) {
    ColorBlocksworld c(false);
    LabeledDDS d;
    const std::string alphabet = "{}[],:\"0123456789-.eEtrufalsn_ \\";

    struct Case {
        SchemaPtr schema;
        std::string text;
    };

    const std::vector<Case> cases = {{c.s, kColorBlocksJson}, {d.s, kLabeledDDSJson}};
    for (std::uint32_t seed = 0; seed < 300; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937 rng(seed);
        const Case& base = cases[seed % cases.size()];
        std::string text = base.text;
        int edits = 1 + static_cast<int>(rng() % 3);
        for (int i = 0; i < edits && !text.empty(); ++i) {
            std::size_t at = rng() % text.size();
            char ch = alphabet[rng() % alphabet.size()];
            switch (rng() % 3) {
            case 0:
                text.erase(at, 1);
                break;
            case 1:
                text.insert(at, 1, ch);
                break;
            default:
                text[at] = ch;
                break;
            }
        }
        SourceManager sources;
        DiagnosticSink sink(sources);
        auto file = sources.add_buffer("m.json", text);
        auto x = read_acset(base.schema, file, sources, sink);
        EXPECT_EQ(x.has_value(), !sink.has_errors()) << text << "\n" << sink.render();
        for (const auto& diag : sink.diagnostics()) {
            EXPECT_TRUE(diag.range.valid()) << diag.message;
            EXPECT_LE(diag.range.begin, text.size());
        }
        if (x) { // whatever was accepted writes back to a document that reads the same
            auto again = read(x->schema_ptr(), write_acset(*x));
            ASSERT_TRUE(again.has_value());
            EXPECT_EQ(*again, *x);
        }
        auto s = read_schema("M", file, sources, sink); // not a schema: must fail cleanly
        EXPECT_EQ(s, nullptr);
    }
}

TEST(JsonErrors, DeepNestingIsLocatedNotACrash) {
    Graph g;
    // 300,000 levels overflowed the stack in the parsed tree's destructor.
    std::string deep = std::string(300000, '[') + std::string(300000, ']');
    auto errors = acset_errors(g.s, deep);
    EXPECT_EQ(errors.substr(0, 51), "x.json:1:257: error: nested deeper than 256 levels\n");
    // Within the limit the document parses (and is then refused as no ACSet).
    std::string ok = std::string(255, '[') + std::string(255, ']');
    EXPECT_NE(acset_errors(g.s, ok).find("x.json:1:1: error: expected a JSON object"),
              std::string::npos);
    std::string objects;
    for (int i = 0; i < 300; ++i) {
        objects += "{\"a\":";
    }
    EXPECT_NE(
        schema_errors(objects + "1" + std::string(300, '}')).find("nested deeper than 256 levels"),
        std::string::npos);
}

TEST(JsonErrors, LineEndsAreLfCrlfOrCr) {
    Graph g;
    EXPECT_EQ(acset_errors(g.s, "{\"V\": [],\r\"E\": [],\r\n\"X\": []}").substr(0, 52),
              "x.json:3:1: error: unknown object or attribute type ");
}

TEST(JsonOutput, InvalidUtf8IsReplacedNotThrown) {
    nlohmann::json j = {{"step", "pick\xFF(a)"}};
    EXPECT_EQ(dump(j), "{\"step\":\"pick\xEF\xBF\xBD(a)\"}");
    nlohmann::ordered_json o = {{"z", "\xC0"}, {"a", 1}};
    EXPECT_EQ(dump(o, 1), "{\n \"z\": \"\xEF\xBF\xBD\",\n \"a\": 1\n}");
    LabeledDDS d;
    ACSet x(d.s);
    Part p = x.add_part(d.x);
    x.set_subpart(d.phi, p, p);
    x.set_subpart(d.label, p,
                  Value::string("a\xFF"
                                "b"));
    auto text = write_acset(x);
    EXPECT_NE(text.find("a\xEF\xBF\xBD"
                        "b"),
              std::string::npos)
        << text;
    EXPECT_TRUE(read(d.s, text).has_value());
}

} // namespace
} // namespace catplan::json
