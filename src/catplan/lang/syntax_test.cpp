#include "catplan/base/dynamic_library.hpp"
#include "catplan/lang/syntax.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace catplan::lang {
namespace {

struct Lexed {
    SourceManager sources;
    DiagnosticSink sink{sources};
    std::vector<Token> tokens;

    explicit Lexed(std::string text) {
        tokens = lex(sources, sources.add_buffer("t.cp", std::move(text)), sink);
    }

    std::vector<std::string> texts() const {
        std::vector<std::string> out;
        for (const auto& t : tokens) {
            if (t.kind != TokenKind::Newline && t.kind != TokenKind::Eof) {
                out.push_back(t.text);
            }
        }
        return out;
    }
};

TEST(Lexer, SplitsOperatorsAndNormalisesUnicode) {
    Lexed l("f::Hom(A,B) == g ⋅ h · k . m <: => -> → ; @x");
    EXPECT_FALSE(l.sink.has_errors());
    EXPECT_EQ(l.texts(), (std::vector<std::string>{"f",  "::", "Hom", "(",  "A", ",", "B", ")",
                                                   "==", "g",  ".",   "h",  ".", "k", ".", "m",
                                                   "<:", "=>", "->",  "->", ";", "@", "x"}));
}

TEST(Lexer, ReadsNumbersOfBothKinds) {
    Lexed l("0 0.0 42 1e3 2.5E-1 1_000");
    ASSERT_FALSE(l.sink.has_errors());
    EXPECT_EQ(l.tokens[0].kind, TokenKind::Int);
    EXPECT_EQ(l.tokens[1].kind, TokenKind::Float);
    EXPECT_DOUBLE_EQ(l.tokens[1].float_value, 0.0);
    EXPECT_EQ(l.tokens[2].int_value, 42);
    EXPECT_EQ(l.tokens[3].kind, TokenKind::Float);
    EXPECT_DOUBLE_EQ(l.tokens[3].float_value, 1000.0);
    EXPECT_DOUBLE_EQ(l.tokens[4].float_value, 0.25);
    EXPECT_EQ(l.tokens[5].int_value, 1000);
}

TEST(Lexer, DecodesStringEscapes) {
    Lexed l(R"("a\"b\\c\nd" "→")");
    ASSERT_FALSE(l.sink.has_errors());
    EXPECT_EQ(l.tokens[0].text, "a\"b\\c\nd");
    EXPECT_EQ(l.tokens[1].text, "→");
}

TEST(Lexer, SkipsLineAndNestedBlockComments) {
    Lexed l("a # comment\n#= outer #= inner =# still =# b");
    EXPECT_FALSE(l.sink.has_errors());
    EXPECT_EQ(l.texts(), (std::vector<std::string>{"a", "b"}));
}

TEST(Lexer, AcceptsUnicodeIdentifiers) {
    Lexed l("dü_2 Größe");
    EXPECT_FALSE(l.sink.has_errors());
    EXPECT_EQ(l.texts(), (std::vector<std::string>{"dü_2", "Größe"}));
}

TEST(Lexer, ReadsJuliasQuotedIdentifiers) {
    // var"..." is an identifier whatever it holds (PDDL's hyphens), located over the whole form.
    Lexed l(R"(var"on-table"::Ob var"a\"b" var x)");
    ASSERT_FALSE(l.sink.has_errors()) << l.sink.render();
    EXPECT_EQ(l.texts(), (std::vector<std::string>{"on-table", "::", "Ob", "a\"b", "var", "x"}));
    EXPECT_EQ(l.tokens[0].kind, TokenKind::Ident);
    EXPECT_EQ(l.tokens[0].range.end - l.tokens[0].range.begin, 13U);
    EXPECT_EQ(quoted_name("on-table"), "var\"on-table\"");
    EXPECT_EQ(quoted_name("a\"b"), R"(var"a\"b")");
    EXPECT_EQ(quoted_name("block"), "block");
    EXPECT_EQ(quoted_name("end"), "var\"end\"");
}

TEST(Lexer, RejectsQuotedIdentifiersThatNameNothingOrAKeyword) {
    Lexed l(R"(var"" var"end" var"open)");
    EXPECT_EQ(l.sink.num_errors(), 3U);
    std::string all = l.sink.render();
    EXPECT_NE(all.find("names nothing"), std::string::npos) << all;
    EXPECT_NE(all.find("is the keyword end"), std::string::npos) << all;
    EXPECT_NE(all.find("unterminated string"), std::string::npos) << all;
}

TEST(Lexer, ReportsBadInputWithLocations) {
    Lexed l("a $ \"open\n#= never closed");
    EXPECT_EQ(l.sink.num_errors(), 3u);
    auto text = l.sink.render();
    EXPECT_NE(text.find("t.cp:1:3: error: unexpected character '$'"), std::string::npos);
    EXPECT_NE(text.find("t.cp:1:5: error: unterminated string"), std::string::npos);
    EXPECT_NE(text.find("t.cp:2:1: error: unterminated block comment"), std::string::npos);
}

struct Parsed {
    SourceManager sources;
    DiagnosticSink sink{sources};
    ParsedFile file;

    explicit Parsed(std::string text) {
        file = parse(sources, sources.add_buffer("t.cp", std::move(text)), sink);
    }
};

TEST(Parser, ReadsMacroCallsWithHeaderAndBody) {
    Parsed p("@present S(FreeSchema) begin\n  (A, B)::Ob\n  f::Hom(\n    A, B)\n"
             "  compose(f, g) == h; f ⋅ g == h\nend\n");
    ASSERT_FALSE(p.sink.has_errors()) << p.sink.render();
    ASSERT_EQ(p.file.forms.size(), 1u);
    const auto& m = p.file.forms[0];
    EXPECT_EQ(m.name, "present");
    ASSERT_EQ(m.header.size(), 1u);
    EXPECT_EQ(to_string(m.header[0]), "S(FreeSchema)");
    ASSERT_EQ(m.body.size(), 4u);
    EXPECT_EQ(to_string(m.body[0]), "(A, B)::Ob");
    EXPECT_EQ(to_string(m.body[1]), "f::Hom(A, B)");
    EXPECT_EQ(to_string(m.body[2]), "compose(f, g) == h");
    EXPECT_EQ(to_string(m.body[3]), "f⋅g == h");
    EXPECT_TRUE(m.body[3].is_binary("=="));
    EXPECT_TRUE(m.body[3].args[0].is_binary("."));
}

TEST(Parser, ReadsAssignedMacrosAndLiterals) {
    Parsed p("X = @acset_colim yS begin\n  a(x) == -1.5; b(x) == true\n  v = [1, 0, AttrVar(2)]\n"
             "end\n@import \"other.cp\"\n");
    ASSERT_FALSE(p.sink.has_errors()) << p.sink.render();
    ASSERT_EQ(p.file.forms.size(), 2u);
    const auto& m = p.file.forms[0];
    EXPECT_EQ(m.assigned, "X");
    EXPECT_EQ(m.name, "acset_colim");
    EXPECT_EQ(to_string(m.header[0]), "yS");
    EXPECT_EQ(m.body[0].args[1].kind, Expr::Kind::Float);
    EXPECT_DOUBLE_EQ(m.body[0].args[1].float_value, -1.5);
    EXPECT_EQ(m.body[1].args[1].kind, Expr::Kind::Bool);
    EXPECT_EQ(to_string(m.body[2]), "v = [1, 0, AttrVar(2)]");
    EXPECT_EQ(p.file.forms[1].name, "import");
    EXPECT_FALSE(p.file.forms[1].has_body);
    EXPECT_EQ(p.file.forms[1].header[0].text, "other.cp");
}

TEST(Parser, NestsMacrosForLaterDeclarationKinds) {
    Parsed p("@rule unstack begin\n  Pre => @join begin\n    x::Block\n  end\nend\n");
    ASSERT_FALSE(p.sink.has_errors()) << p.sink.render();
    const auto& body = p.file.forms[0].body;
    ASSERT_EQ(body.size(), 1u);
    ASSERT_TRUE(body[0].is_binary("=>"));
    ASSERT_EQ(body[0].args[1].kind, Expr::Kind::Macro);
    EXPECT_EQ(body[0].args[1].macro->name, "join");
    EXPECT_EQ(body[0].args[1].macro->body.size(), 1u);
}

TEST(Parser, ReadsTheCallFormOfAMacroWithABlockArgument) {
    Parsed p("@domain D(S) begin\n  :unstack => @migration(Ont, begin\n    Pre => begin x::B; "
             "y::B end; Keep => @join begin x::B end\n  end)\nend\n");
    ASSERT_FALSE(p.sink.has_errors()) << p.sink.render();
    const auto& st = p.file.forms[0].body[0];
    ASSERT_TRUE(st.is_binary("=>"));
    EXPECT_EQ(st.args[0].kind, Expr::Kind::Symbol);
    EXPECT_EQ(to_string(st.args[0]), ":unstack");
    const auto& m = *st.args[1].macro;
    EXPECT_EQ(m.name, "migration");
    ASSERT_EQ(m.header.size(), 1u);
    EXPECT_EQ(m.header[0].text, "Ont");
    ASSERT_TRUE(m.has_body);
    ASSERT_EQ(m.body.size(), 2u);
    EXPECT_EQ(m.body[0].args[1].kind, Expr::Kind::Block);
    EXPECT_EQ(m.body[0].args[1].args.size(), 2u);
}

TEST(Parser, ExpressionOperatorsFollowJuliaPrecedence) {
    Parsed p("@rule r begin\n  w(e) == w(a) + w(b) * 2 - -1\n  f(x) == (!g(x) && h(x) < 3 || "
             "k(x) != 1)\n  n(x) == -m(x)\nend\n");
    ASSERT_FALSE(p.sink.has_errors()) << p.sink.render();
    const auto& body = p.file.forms[0].body;
    ASSERT_EQ(body.size(), 3u);
    const Expr& sum = body[0].args[1];
    ASSERT_TRUE(sum.is_binary("-"));
    ASSERT_TRUE(sum.args[0].is_binary("+"));
    EXPECT_TRUE(sum.args[0].args[1].is_binary("*"));
    EXPECT_EQ(sum.args[1].kind, Expr::Kind::Int);
    EXPECT_EQ(sum.args[1].int_value, -1);
    const Expr& logic = body[1].args[1];
    ASSERT_TRUE(body[1].is_binary("=="));
    ASSERT_TRUE(logic.is_binary("||"));
    ASSERT_TRUE(logic.args[0].is_binary("&&"));
    EXPECT_EQ(logic.args[0].args[0].kind, Expr::Kind::Unary);
    EXPECT_TRUE(logic.args[0].args[1].is_binary("<"));
    EXPECT_TRUE(logic.args[1].is_binary("!="));
    EXPECT_EQ(body[2].args[1].kind, Expr::Kind::Unary);
    EXPECT_EQ(to_string(body[2].args[1]), "-m(x)");
}

TEST(Parser, RangesCoverTheirText) {
    Parsed p("@present S(FreeSchema) begin\n  f::Hom(A, B)\nend\n");
    const auto& st = p.file.forms[0].body[0];
    auto text = p.sources.text(st.range.file);
    EXPECT_EQ(text.substr(st.range.begin, st.range.end - st.range.begin), "f::Hom(A, B)");
    const auto& call = st.args[1];
    EXPECT_EQ(text.substr(call.name_range.begin, call.name_range.end - call.name_range.begin),
              "Hom");
}

TEST(Parser, RecoversAtTheNextStatement) {
    Parsed p("@present S(FreeSchema) begin\n  A::Ob )\n  B::Ob\n  C:: \nend\n");
    EXPECT_EQ(p.sink.num_errors(), 2u) << p.sink.render();
    ASSERT_EQ(p.file.forms.size(), 1u);
    // A::Ob parsed before the stray token and B::Ob after it; "C::" is dropped.
    EXPECT_EQ(p.file.forms[0].body.size(), 2u);
}

TEST(Parser, ReportsMissingEnd) {
    Parsed p("@present S(FreeSchema) begin\n  A::Ob\n");
    ASSERT_EQ(p.sink.num_errors(), 1u);
    EXPECT_NE(p.sink.render().find("missing 'end' for '@present'"), std::string::npos);
}

TEST(Lexer, IdentifiersHoldLettersAsUnicodeDefinesThem) {
    Lexed l("λ積 x\u0308 _a1");
    EXPECT_FALSE(l.sink.has_errors()) << l.sink.render();
    EXPECT_EQ(l.texts(), (std::vector<std::string>{"λ積", "x\u0308", "_a1"}));
    Lexed emoji("bread🍞 = 1");
    ASSERT_EQ(emoji.sink.num_errors(), 1u);
    EXPECT_NE(emoji.sink.render().find("t.cp:1:6: error: unexpected character '🍞' (U+1F35E)"),
              std::string::npos)
        << emoji.sink.render();
}

// Whether ICU's library is mapped into this process (it is loaded at the first letter beyond
// ASCII, not linked).
bool icu_is_loaded() {
    return catplan::library_is_mapped("libicuuc");
}

TEST(Lexer, NeedsIcuOnlyForLettersBeyondAscii) {
    // A fresh process (the test binary run again for this test alone): no earlier test has
    // loaded ICU. Operators, strings and comments beyond ASCII do not need it.
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            Lexed ascii("# Größe\nf::Hom(A, B) == g ⋅ h → k; c = \"grün\" #= ∀ =#\n");
            bool without = !ascii.sink.has_errors() && !icu_is_loaded();
            Lexed letters("Größe::Ob");
            bool with = !letters.sink.has_errors() && icu_is_loaded();
            std::exit(without && with ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST(Lexer, RejectsInvalidUtf8BeforeAnythingElse) {
    Lexed l("@present S(FreeSchema) begin\n  X\xFF::Ob\n  \"\xC0\xAF\"\nend\n");
    ASSERT_EQ(l.sink.num_errors(), 2u) << l.sink.render();
    auto text = l.sink.render();
    EXPECT_NE(text.find("t.cp:2:4: error: invalid UTF-8"), std::string::npos) << text;
    EXPECT_NE(text.find("t.cp:3:4: error: invalid UTF-8"), std::string::npos) << text;
}

TEST(Lexer, SkipsAByteOrderMark) {
    Lexed l("\xEF\xBB\xBFX Y");
    EXPECT_FALSE(l.sink.has_errors()) << l.sink.render();
    EXPECT_EQ(l.texts(), (std::vector<std::string>{"X", "Y"}));
    Lexed twice("\xEF\xBB\xBF\xEF\xBB\xBFX"); // only the first is a byte-order mark
    EXPECT_EQ(twice.sink.num_errors(), 1u);
}

TEST(Lexer, EndsLinesAtLfCrlfAndLoneCr) {
    Lexed l("a\rb # comment\rc\r\nd");
    EXPECT_FALSE(l.sink.has_errors());
    std::vector<std::string> kinds;
    for (const auto& t : l.tokens) {
        kinds.push_back(t.kind == TokenKind::Newline ? "NL" : t.text);
    }
    EXPECT_EQ(kinds, (std::vector<std::string>{"a", "NL", "b", "NL", "c", "NL", "d", "NL", ""}));
    EXPECT_EQ(l.sources.line_col(l.tokens[6].range.file, l.tokens[6].range.begin).line, 4u);
}

TEST(Lexer, RejectsNumbersOutOfRange) {
    Lexed l("1e999 -1e999 1e-999 9223372036854775808 1.5e308 4.9e-324 0e-999 "
            "9223372036854775807");
    auto text = l.sink.render();
    EXPECT_EQ(l.sink.num_errors(), 4u) << text;
    EXPECT_NE(text.find("t.cp:1:1: error: number '1e999' is out of range"), std::string::npos)
        << text;
    EXPECT_NE(text.find("t.cp:1:8: error: number '1e999' is out of range"), std::string::npos);
    EXPECT_NE(text.find("t.cp:1:14: error: number '1e-999' underflows"), std::string::npos);
    EXPECT_NE(text.find("t.cp:1:21: error: integer '9223372036854775808' is too large"),
              std::string::npos);
    EXPECT_EQ(l.tokens[8].int_value, INT64_MAX);
}

// A form nesting `depth` levels of `open` ... `close` around x.
std::string nested(const std::string& open, const std::string& close, std::size_t depth) {
    std::string s;
    for (std::size_t i = 0; i < depth; ++i) {
        s += open;
    }
    s += "x";
    for (std::size_t i = 0; i < depth; ++i) {
        s += close;
    }
    return "@present S(FreeSchema) begin\n  " + s + "\nend\n";
}

TEST(Parser, NestingIsLimitedWithALocatedError) {
    // Deep enough to overflow the stack without a limit (about 2,000 levels did).
    for (auto [open, close] : std::vector<std::pair<std::string, std::string>>{{"(", ")"},
                                                                               {"f(", ")"},
                                                                               {"[", "]"},
                                                                               {"-", ""},
                                                                               {"!", ""},
                                                                               {"x = ", ""},
                                                                               {"x -> ", ""},
                                                                               {"begin ", " end"},
                                                                               {"@m(", ")"}}) {
        Parsed deep(nested(open, close, 100000));
        ASSERT_TRUE(deep.sink.has_errors()) << open;
        EXPECT_NE(deep.sink.render().find("error: nested deeper than 256 levels"),
                  std::string::npos)
            << open << deep.sink.render().substr(0, 500);
    }
}

TEST(Parser, ALongOperatorChainCountsAsNesting) {
    // `1 + 1 + ...` is a left-deep tree: its destructor and the elaborator recurse on it.
    std::string chain = "1";
    for (int i = 0; i < 100000; ++i) {
        chain += " + 1";
    }
    Parsed p("@present S(FreeSchema) begin\n  x == " + chain + "\nend\n");
    ASSERT_TRUE(p.sink.has_errors());
    EXPECT_NE(p.sink.render().find("t.cp:2:"), std::string::npos);
    EXPECT_NE(p.sink.render().find("nested deeper than 256 levels"), std::string::npos);
    // Parentheses around chains add up.
    std::string sum = "1";
    for (int i = 0; i < 10; ++i) {
        sum.insert(0, "(");
        for (int k = 0; k < 30; ++k) {
            sum += " + 1";
        }
        sum += ")";
    }
    Parsed q("@present S(FreeSchema) begin\n  x == " + sum + "\nend\n");
    EXPECT_NE(q.sink.render().find("nested deeper than 256 levels"), std::string::npos);
}

TEST(Parser, NestingUpToTheLimitParses) {
    // 255 parentheses inside the statement (whose `x` and `::` make the rest of the 256 levels).
    Parsed p(nested("(", ")", 200));
    EXPECT_FALSE(p.sink.has_errors()) << p.sink.render().substr(0, 300);
    Parsed f(nested("f(", ")", 250));
    EXPECT_FALSE(f.sink.has_errors()) << f.sink.render().substr(0, 300);
}

TEST(Identifier, RejectsKeywordsAndOperators) {
    EXPECT_TRUE(is_identifier("gripper"));
    EXPECT_TRUE(is_identifier("_x1"));
    EXPECT_FALSE(is_identifier("end"));
    EXPECT_FALSE(is_identifier("true"));
    EXPECT_FALSE(is_identifier("1x"));
    EXPECT_FALSE(is_identifier("a b"));
    EXPECT_FALSE(is_identifier("a⋅b"));
    EXPECT_FALSE(is_identifier(""));
    EXPECT_TRUE(is_identifier("Größe"));
    EXPECT_FALSE(is_identifier("🍞"));
    EXPECT_FALSE(is_identifier("a\xFF"));
}

} // namespace
} // namespace catplan::lang
