#include "catplan/base/diagnostic.hpp"
#include "catplan/base/dynamic_library.hpp"
#include "catplan/base/source.hpp"
#include "catplan/base/unicode.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace catplan {
namespace {

TEST(SourceManager, CountsLfCrlfAndLoneCrAsLineEnds) {
    SourceManager sm;
    auto f = sm.add_buffer("m.cp", "a\nbb\r\nccc\rdddd\r\r\ne");
    EXPECT_EQ(sm.line_col(f, 0).line, 1u);
    EXPECT_EQ(sm.line_col(f, 2).line, 2u); // bb
    EXPECT_EQ(sm.line_col(f, 6).line, 3u); // ccc after CRLF
    auto d = sm.line_col(f, 11);           // the second d, after a lone CR
    EXPECT_EQ(d.line, 4u);
    EXPECT_EQ(d.col, 2u);
    EXPECT_EQ(sm.line_col(f, 17).line, 6u); // e: CR then CRLF make an empty line 5
    EXPECT_EQ(sm.line_text(f, 2), "bb");
    EXPECT_EQ(sm.line_text(f, 3), "ccc");
    EXPECT_EQ(sm.line_text(f, 4), "dddd");
    EXPECT_EQ(sm.line_text(f, 5), "");
    EXPECT_EQ(sm.line_text(f, 6), "e");
}

TEST(SourceManager, AByteOrderMarkTakesNoColumn) {
    SourceManager sm;
    auto f = sm.add_buffer("b.cp", "\xEF\xBB\xBFX::Ob\n");
    EXPECT_EQ(bom_length(sm.text(f)), 3u);
    EXPECT_EQ(sm.line_col(f, 3).col, 1u);
    EXPECT_EQ(sm.line_col(f, 4).col, 2u);
    EXPECT_EQ(sm.line_text(f, 1), "X::Ob");
    EXPECT_EQ(bom_length("X"), 0u);
}

TEST(SourceManager, ADirectoryOrAMissingFileFailsWithTheReason) {
    SourceManager sm;
    auto dir = sm.add_file(std::filesystem::temp_directory_path().string());
    ASSERT_FALSE(dir.has_value());
    EXPECT_EQ(dir.error(), "Is a directory");
    auto missing = sm.add_file("/nonexistent/catplan/file.cp");
    ASSERT_FALSE(missing.has_value());
    EXPECT_EQ(missing.error(), "No such file or directory");
    EXPECT_EQ(sm.num_files(), 0u);
}

TEST(SourceManager, ReadsAFile) {
    auto path = std::filesystem::temp_directory_path() / "catplan_source_test.txt";
    std::FILE* out = std::fopen(path.c_str(), "wb");
    ASSERT_NE(out, nullptr);
    std::fputs("one\ntwo\n", out);
    std::fclose(out);
    SourceManager sm;
    auto f = sm.add_file(path.string());
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(sm.text(*f), "one\ntwo\n");
    EXPECT_EQ(sm.name(*f), path.string());
    std::filesystem::remove(path);
}

TEST(Unicode, DecodesUtf8AndRejectsIllFormedSequences) {
    EXPECT_EQ(decode_utf8("a", 0).value, U'a');
    auto arrow = decode_utf8("→", 0);
    EXPECT_TRUE(arrow.valid);
    EXPECT_EQ(arrow.value, U'→');
    EXPECT_EQ(arrow.length, 3u);
    EXPECT_FALSE(decode_utf8("\xFF", 0).valid);
    EXPECT_FALSE(decode_utf8("\xC0\xAF", 0).valid);     // overlong '/'
    EXPECT_FALSE(decode_utf8("\xED\xA0\x80", 0).valid); // a surrogate
    EXPECT_FALSE(decode_utf8("\xE2\x86", 0).valid);     // truncated
    EXPECT_TRUE(is_valid_utf8("Größe →"));
    EXPECT_FALSE(is_valid_utf8("ab\x80"));
}

TEST(Unicode, IdentifiersAreLettersDigitsMarksAndUnderscore) {
    EXPECT_TRUE(is_identifier_start(U'B'));
    EXPECT_TRUE(is_identifier_start(U'_'));
    EXPECT_TRUE(is_identifier_start(U'ö'));
    EXPECT_TRUE(is_identifier_start(U'λ'));
    EXPECT_TRUE(is_identifier_start(U'積'));
    EXPECT_FALSE(is_identifier_start(U'1'));
    EXPECT_FALSE(is_identifier_start(U'🍞'));
    EXPECT_FALSE(is_identifier_start(U'→'));
    EXPECT_FALSE(is_identifier_start(U'\u00A0')); // no-break space
    EXPECT_TRUE(is_identifier_continue(U'1'));
    EXPECT_TRUE(is_identifier_continue(U'\u0308')); // combining diaeresis
    EXPECT_FALSE(is_identifier_continue(U'🍞'));
    EXPECT_FALSE(is_identifier_continue(U'-'));
    EXPECT_EQ(identifier_classes_unavailable(), ""); // ICU is installed where the tests run
}

TEST(Unicode, AsciiIsDecidedWithoutIcuAsIcuWouldDecideIt) {
    for (char32_t c = 0; c < 0x80; ++c) {
        bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
        bool digit = c >= '0' && c <= '9';
        EXPECT_EQ(is_identifier_start(c), letter || c == '_') << static_cast<int>(c);
        EXPECT_EQ(is_identifier_continue(c), letter || digit || c == '_') << static_cast<int>(c);
    }
}

// Whether ICU's library is mapped into this process (it is loaded at the first letter beyond
// ASCII, not linked).
bool icu_is_loaded() {
    return catplan::library_is_mapped("libicuuc");
}

TEST(Unicode, IcuIsLoadedAtTheFirstCodePointBeyondAsciiOnly) {
    // A fresh process (the test binary run again for this test alone), so that no earlier test
    // has loaded ICU.
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            bool ascii = is_identifier_start(U'a') && is_identifier_continue(U'9') &&
                         !is_identifier_start(U'1') && is_valid_utf8("Größe → x");
            bool before = icu_is_loaded();
            bool lambda = is_identifier_start(U'λ');
            std::exit(ascii && !before && lambda && icu_is_loaded() ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST(Unicode, CheckReportsEachIllFormedRunOnceAndCapsTheList) {
    SourceManager sm;
    DiagnosticSink sink(sm);
    auto ok = sm.add_buffer("ok.cp", "X → Y\n");
    EXPECT_TRUE(check_utf8(sm, ok, sink));
    auto bad = sm.add_buffer("bad.cp", "a\xFF\xFE b\n\x80");
    EXPECT_FALSE(check_utf8(sm, bad, sink));
    EXPECT_EQ(sink.render(), "bad.cp:1:2: error: invalid UTF-8: the file must be UTF-8 text\n"
                             "    1 | a\xFF\xFE b\n"
                             "      |  ^~\n"
                             "bad.cp:2:1: error: invalid UTF-8: the file must be UTF-8 text\n"
                             "    2 | \x80\n"
                             "      | ^\n");
    DiagnosticSink many(sm);
    auto binary = sm.add_buffer("bin", std::string(30, '\xFF').insert(0, "x\xFF") + "\n");
    std::string text = "x";
    for (int i = 0; i < 30; ++i) {
        text += "\xFF ";
    }
    auto spread = sm.add_buffer("spread", text);
    EXPECT_FALSE(check_utf8(sm, binary, many));
    EXPECT_EQ(many.num_errors(), 1u);
    EXPECT_FALSE(check_utf8(sm, spread, many));
    EXPECT_EQ(many.num_errors(), 12u); // 10 shown, then one that counts the other 20
    EXPECT_NE(many.diagnostics().back().message.find("20 more"), std::string::npos);
}

} // namespace
} // namespace catplan
