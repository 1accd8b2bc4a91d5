#include "catplan/lang/module.hpp"

#include <gtest/gtest.h>

namespace catplan::lang {
namespace {

using acset::ACSet;
using acset::Value;

struct Loaded {
    SourceManager sources;
    DiagnosticSink sink{sources};
    Module module;

    explicit Loaded(std::string text, LoadOptions options = {}) {
        module = load_source("test.cp", std::move(text), sources, sink, options);
    }

    const ACSet& instance(std::string_view name) const {
        const auto* d = module.find(name);
        EXPECT_NE(d, nullptr) << name;
        return *d->instance;
    }
};

const char* kPQR = R"(
@present S(FreeSchema) begin
  (P, Q, R)::Ob
  f::Hom(P, Q)
  g::Hom(Q, R)
  h::Hom(P, R)
  Name::AttrType(String)
  name::Attr(R, Name)
end
)";

ObId ob(const ACSet& x, std::string_view n) {
    return *x.schema().find_ob(n);
}

HomId hom(const ACSet& x, std::string_view n) {
    return *x.schema().find_hom(n);
}

AttrId attr(const ACSet& x, std::string_view n) {
    return *x.schema().find_attr(n);
}

TEST(FreeInstance, UndefinedHomsGetFreshPartsRecursively) {
    Loaded l(std::string(kPQR) + "@acset_colim I(S) begin\n  p::P\nend\n");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    const ACSet& x = l.instance("I");
    EXPECT_EQ(x.num_parts(ob(x, "P")), 1u);
    EXPECT_EQ(x.num_parts(ob(x, "Q")), 1u);
    // g(f(p)) and h(p) are two different fresh parts of R, each with its own variable.
    EXPECT_EQ(x.num_parts(ob(x, "R")), 2u);
    EXPECT_EQ(x.num_vars(*x.schema().find_attr_type("Name")), 2u);
    EXPECT_EQ(x.part_name(ob(x, "P"), 0), "p");
    EXPECT_EQ(x.part_name(ob(x, "Q"), 0), "");
    EXPECT_NE(x.subpart(hom(x, "g"), x.subpart(hom(x, "f"), 0)), x.subpart(hom(x, "h"), 0));
}

TEST(FreeInstance, EquationsMergeWithCongruenceClosure) {
    // p1 == p2 forces f(p1) == f(p2), hence g(f(p1)) == g(f(p2)): the two names meet.
    Loaded l(std::string(kPQR) + R"(
@acset_colim I(S) begin
  (p1, p2)::P
  name(g(f(p1))) == "one"
  h(p1) == g(f(p1))
  p1 == p2
end
)");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    const ACSet& x = l.instance("I");
    EXPECT_EQ(x.num_parts(ob(x, "P")), 1u);
    EXPECT_EQ(x.num_parts(ob(x, "Q")), 1u);
    EXPECT_EQ(x.num_parts(ob(x, "R")), 1u);
    EXPECT_EQ(x.part_name(ob(x, "P"), 0), "p1");
    EXPECT_EQ(x.subpart(attr(x, "name"), 0), Value::string("one"));
    EXPECT_EQ(x.num_vars(*x.schema().find_attr_type("Name")), 0u);
}

TEST(FreeInstance, CongruenceFindsConflictingLiterals) {
    Loaded l(std::string(kPQR) + R"(
@acset_colim I(S) begin
  (p1, p2)::P
  name(h(p1)) == "one"
  name(h(p2)) == "two"
  p1 == p2
end
)");
    ASSERT_EQ(l.sink.num_errors(), 1u);
    EXPECT_NE(l.sink.render().find("test.cp:15:3: error: conflicting values"), std::string::npos)
        << l.sink.render();
    EXPECT_EQ(l.module.find("I"), nullptr);
}

TEST(FreeInstance, MergedClassesKeepTheFirstGeneratorsPositionAndName) {
    Loaded l(std::string(kPQR) + R"(
@acset_colim I(S) begin
  (a, b, c)::R
  c == a
  n::Name
  name(b) == n
end
)");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    const ACSet& x = l.instance("I");
    ASSERT_EQ(x.num_parts(ob(x, "R")), 2u);
    EXPECT_EQ(x.part_name(ob(x, "R"), 0), "a");
    EXPECT_EQ(x.part_name(ob(x, "R"), 1), "b");
    auto name_type = *x.schema().find_attr_type("Name");
    // Named variable first, then the fresh one for name(a).
    ASSERT_EQ(x.num_vars(name_type), 2u);
    EXPECT_EQ(x.var_name(name_type, 0), "n");
    EXPECT_EQ(x.subpart(attr(x, "name"), 1), Value::var(0));
    EXPECT_EQ(x.subpart(attr(x, "name"), 0), Value::var(1));
}

TEST(FreeInstance, CyclicSchemaStopsWithALocatedError) {
    LoadOptions small;
    small.max_fresh_parts = 50;
    Loaded l("@present D(FreeSchema) begin\n  X::Ob\n  next::Hom(X, X)\nend\n"
             "@acset_colim Orbit(D) begin\n  x::X\nend\n"
             "@acset_colim Cycle(D) begin\n  x::X\n  next(next(x)) == x\nend\n",
             small);
    ASSERT_EQ(l.sink.num_errors(), 1u);
    EXPECT_NE(l.sink.render().find("test.cp:5:14: error: the free instance is infinite or too "
                                   "large: hom 'next'"),
              std::string::npos)
        << l.sink.render();
    // A cycle closed by an equation is finite.
    const ACSet& c = l.instance("Cycle");
    EXPECT_EQ(c.num_parts(ob(c, "X")), 2u);
}

TEST(LiteralInstance, CountsStopAtTenMillionPartsAndVariablesInAll) {
    Loaded l("@present G(FreeSchema) begin\n  V::Ob\n  W::AttrType(Int)\nend\n"
             "@acset AtTheLimit(G) begin\n  V = 9999999\n  W = 1\nend\n"
             "@acset OneMore(G) begin\n  V = 10000000\n  W = 1\nend\n"
             "@acset Huge(G) begin\n  V = 4294967296\nend\n");
    ASSERT_EQ(l.sink.num_errors(), 2u) << l.sink.render();
    std::string out = l.sink.render();
    EXPECT_NE(out.find("test.cp:11:7: error: too many parts: 'W = 1' would give this @acset "
                       "10000001 parts and variables, but at most 10000000 are allowed"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("test.cp:14:7: error: too many parts: 'V = 4294967296'"), std::string::npos)
        << out;
    const ACSet& x = l.instance("AtTheLimit");
    EXPECT_EQ(x.num_parts(ob(x, "V")), 9999999u);
    EXPECT_EQ(x.num_vars(*x.schema().find_attr_type("W")), 1u);
    EXPECT_EQ(l.module.find("OneMore"), nullptr);
    EXPECT_EQ(l.module.find("Huge"), nullptr);
}

TEST(LiteralInstance, TheLimitOnPartsIsALoadOption) {
    LoadOptions small;
    small.max_table_parts = 100;
    Loaded l("@present G(FreeSchema) begin\n  V::Ob\n  W::AttrType(Int)\nend\n"
             "@acset AtTheLimit(G) begin\n  V = 99\n  W = 1\nend\n"
             "@acset OneMore(G) begin\n  V = 100\n  W = 1\nend\n",
             small);
    ASSERT_EQ(l.sink.num_errors(), 1u) << l.sink.render();
    EXPECT_NE(l.sink.render().find("test.cp:11:7: error: too many parts: 'W = 1' would give this "
                                   "@acset 101 parts and variables, but at most 100 are allowed"),
              std::string::npos)
        << l.sink.render();
    EXPECT_EQ(l.instance("AtTheLimit").num_parts(ob(l.instance("AtTheLimit"), "V")), 99u);
}

TEST(ColorBlocksworld, InitialStateMatchesThePaper) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    Module m = load_file(std::string(CATPLAN_SOURCE_DIR) +
                             "/examples/colorblocksworld/colorblocksworld.cp",
                         sources, sink);
    ASSERT_FALSE(sink.has_errors()) << sink.render();
    const auto* d = m.find("Initial");
    ASSERT_NE(d, nullptr);
    const ACSet& x = *d->instance;
    ObId block = ob(x, "Block");
    EXPECT_EQ(x.num_parts(block), 7u);
    EXPECT_EQ(x.num_parts(ob(x, "Gripper")), 1u);
    EXPECT_EQ(x.num_parts(ob(x, "Empty")), 1u);
    EXPECT_EQ(x.num_parts(ob(x, "On")), 2u);
    const char* names[] = {"A", "B", "C", "D", "E", "F"};
    const char* colors[] = {"green", "red", "yellow", "purple", "purple", "blue"};
    bool on_table[] = {true, true, true, false, false, true};
    bool clear[] = {true, true, false, false, true, true};
    for (Part p = 0; p < 6; ++p) {
        EXPECT_EQ(x.part_name(block, p), names[p]);
        EXPECT_EQ(x.subpart(attr(x, "hasColor"), p), Value::string(colors[p]));
        EXPECT_EQ(x.subpart(attr(x, "isOnTable"), p), Value::boolean(on_table[p]));
        EXPECT_EQ(x.subpart(attr(x, "isClear"), p), Value::boolean(clear[p]));
    }
    // The "empty" block: unnamed, held by the gripper, pointed at by Empty, all unknown.
    EXPECT_EQ(x.part_name(block, 6), "");
    EXPECT_EQ(x.subpart(hom(x, "isHolding"), 0), 6u);
    EXPECT_EQ(x.subpart(hom(x, "isEmpty"), 0), 6u);
    EXPECT_TRUE(x.subpart(attr(x, "hasColor"), 6).is_var());
    EXPECT_TRUE(x.subpart(attr(x, "isClear"), 6).is_var());
    EXPECT_TRUE(x.subpart(attr(x, "isOnTable"), 6).is_var());
    // on_l(x1) == E, on_r(x1) == D, on_l(x2) == D, on_r(x2) == C
    EXPECT_EQ(x.subpart(hom(x, "on_l"), 0), 4u);
    EXPECT_EQ(x.subpart(hom(x, "on_r"), 0), 3u);
    EXPECT_EQ(x.subpart(hom(x, "on_l"), 1), 3u);
    EXPECT_EQ(x.subpart(hom(x, "on_r"), 1), 2u);
    EXPECT_EQ(summarize(*d), "instance Initial (ColorBlocksworld): 11 parts (Block 7, Empty 1, "
                             "Gripper 1, On 2), 3 variables");
}

TEST(Kitchenworld, LoadsAsWrittenInThePaper) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    Module m = load_file(std::string(CATPLAN_SOURCE_DIR) + "/examples/kitchenworld/kitchenworld.cp",
                         sources, sink);
    ASSERT_FALSE(sink.has_errors()) << sink.render();
    const auto* d = m.find("KitchenWorld");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(summarize(*d),
              "schema KitchenWorld: 10 objects, 13 homs, 3 attribute types, 15 attributes");
    EXPECT_EQ(d->schema->hom(*d->schema->find_hom("breadSlicedIsReceptacle")).dom,
              *d->schema->find_ob("BreadSliced"));
}

TEST(Kinds, AreSettledBeforeInstancesWhateverTheOrder) {
    // The Int literal comes first in the file but the Float one widens the kind for both.
    Loaded l(R"(
@acset_colim I(S) begin
  x::X
  w(x) == 1
end
@present S(FreeSchema) begin
  X::Ob
  W::AttrType
  w::Attr(X, W)
end
@acset_colim J(S) begin
  x::X
  w(x) == 2.5
end
)");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    const ACSet& x = l.instance("I");
    EXPECT_EQ(x.schema().attr_type(AttrTypeId(0)).kind, schema::ValueKind::Float);
    EXPECT_EQ(x.subpart(attr(x, "w"), 0), Value::real(1.0));
}

TEST(Module, DeclarationsAreInLoadOrderAndLookupsWork) {
    Loaded l(std::string(kPQR) + "G = @acset_colim yS begin\n  r::R\nend\n");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    const auto& ds = l.module.declarations();
    ASSERT_EQ(ds.size(), 2u);
    EXPECT_EQ(ds[0].kind, DeclKind::Schema);
    EXPECT_EQ(ds[1].kind, DeclKind::Instance);
    EXPECT_EQ(ds[1].schema, ds[0].schema);
    EXPECT_EQ(l.module.find("nope"), nullptr);
}

TEST(Printing, SchemaRoundTrips) {
    Loaded l(R"(
@present S(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  refl::Hom(V, E)
  refl ⋅ src == id(V)
  compose(refl, tgt) == id(V)
  L::AttrType(Symbol)
  label::Attr(E, L)
  compose(refl, label) == compose(refl, label)
  U::AttrType
end
)");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    std::string printed = print_schema(*l.module.find("S")->schema);
    Loaded again(printed);
    ASSERT_FALSE(again.sink.has_errors()) << again.sink.render() << printed;
    EXPECT_EQ(print_schema(*again.module.find("S")->schema), printed);
}

TEST(Printing, InstanceRoundTripsToAnEqualState) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    std::string path =
        std::string(CATPLAN_SOURCE_DIR) + "/examples/colorblocksworld/colorblocksworld.cp";
    Module m = load_file(path, sources, sink);
    ASSERT_FALSE(sink.has_errors()) << sink.render();
    const auto* d = m.find("Initial");
    std::string text = print_schema(*d->schema) + print_instance(*d->instance, "Again");
    Loaded again(text);
    ASSERT_FALSE(again.sink.has_errors()) << again.sink.render() << text;
    const ACSet& y = again.instance("Again");
    EXPECT_TRUE(y == *d->instance) << text;
    ObId block = ob(y, "Block");
    for (Part p = 0; p < 6; ++p) {
        EXPECT_EQ(y.part_name(block, p), d->instance->part_name(block, p));
    }
}

TEST(Printing, LiteralInstanceWithUnnamedPartsRoundTrips) {
    Loaded l(R"(
@present G(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  W::AttrType
  w::Attr(E, W)
end
@acset X(G) begin
  V = 3; E = 3
  src = [1, 2, 3]; tgt = [2, 3, 3]
  W = 2
  w = [AttrVar(2), 1.5, AttrVar(1)]
end
)");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    const ACSet& x = l.instance("X");
    std::string text = print_schema(x.schema()) + print_instance(x, "Y");
    Loaded again(text);
    ASSERT_FALSE(again.sink.has_errors()) << again.sink.render() << text;
    EXPECT_TRUE(again.instance("Y") == x) << text;
}

TEST(Printing, NamesThatAreNotIdentifiersRoundTripQuoted) {
    // PDDL's names (on-table, pick-up) are written var"on-table" and read back as they were.
    Loaded l(R"(
@present var"blocks-4ops"(FreeSchema) begin
  (block, var"on-table")::Ob
  var"on-table_1"::Hom(var"on-table", block)
end
@acset_colim var"state-1"(var"blocks-4ops") begin
  (a, b)::block
  (var"t-1")::var"on-table"
  var"on-table_1"(var"t-1") == b
end
)");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    const ACSet& x = l.instance("state-1");
    EXPECT_EQ(x.schema().name(), "blocks-4ops");
    std::string text = print_schema(x.schema()) + print_instance(x, "again-1");
    EXPECT_NE(text.find("var\"on-table_1\"::Hom(var\"on-table\", block)"), std::string::npos)
        << text;
    Loaded again(text);
    ASSERT_FALSE(again.sink.has_errors()) << again.sink.render() << text;
    EXPECT_TRUE(again.instance("again-1") == x) << text;
}

TEST(Import, ResolvesRelativeToTheImportingFile) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    Module m =
        load_source(std::string(CATPLAN_SOURCE_DIR) + "/tests/lang/main.cp",
                    "@import \"../../examples/kitchenworld/kitchenworld.cp\"\n", sources, sink);
    ASSERT_FALSE(sink.has_errors()) << sink.render();
    ASSERT_NE(m.find("KitchenWorld"), nullptr);
    EXPECT_TRUE(m.find("KitchenWorld")->imported);
}

} // namespace
} // namespace catplan::lang

namespace catplan::lang {
namespace {

// Every prefix of a real file must load without crashing, and every error must be located.
TEST(Robustness, EveryPrefixOfTheCaseStudyLoadsWithLocatedErrors) {
    std::string path =
        std::string(CATPLAN_SOURCE_DIR) + "/examples/colorblocksworld/colorblocksworld.cp";
    SourceManager files;
    auto id = files.add_file(path);
    ASSERT_TRUE(id.has_value());
    std::string text(files.text(*id));
    for (std::size_t n = 0; n <= text.size(); n += 7) {
        SourceManager sources;
        DiagnosticSink sink(sources);
        (void)load_source("prefix.cp", text.substr(0, n), sources, sink);
        for (const auto& d : sink.diagnostics()) {
            EXPECT_TRUE(d.range.valid()) << n << ": " << d.message;
        }
    }
}

} // namespace
} // namespace catplan::lang
