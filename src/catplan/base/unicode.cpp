#include "catplan/base/unicode.hpp"

#include "catplan/base/dynamic_library.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <optional>
#include <unicode/uchar.h>
#include <unicode/utf8.h>
#include <unicode/uvernum.h>
#include <utility>
#include <vector>

// A macro's value as a string literal (two steps, so that the macro is expanded first).
#define CATPLAN_ICU_STRING(x) CATPLAN_ICU_STRING_OF(x)
#define CATPLAN_ICU_STRING_OF(x) #x

namespace catplan {
namespace {

// ICU is loaded at the first code point beyond ASCII whose class is asked: most inputs are
// ASCII, and libicuuc with its data cost every command a millisecond of start-up when linked.
// The decoder (U8_NEXT) is an inline macro of ICU's header and needs no library.
struct Icu {
    decltype(&::u_hasBinaryProperty) has_binary_property = nullptr;
};

// ICU's functions are exported under versioned names (u_hasBinaryProperty_72, by the macros of
// urename.h) and its soname carries the major version: both are spelled from the header's own
// macros, so that they follow the ICU catplan is built with.
void bind_icu(SymbolBinder& b, Icu& icu) {
    b.function(icu.has_binary_property, CATPLAN_ICU_STRING(u_hasBinaryProperty));
}

LazyLibrary<Icu>& icu() {
    static LazyLibrary<Icu> lib(
        "libicuuc.so." CATPLAN_ICU_STRING(U_ICU_VERSION_MAJOR_NUM),
        "ICU (Debian's libicu" CATPLAN_ICU_STRING(U_ICU_VERSION_MAJOR_NUM) ")", bind_icu);
    return lib;
}

// Whether c has the binary property p; false when ICU cannot be loaded.
bool has_property(char32_t c, UProperty p) {
    std::string why;
    const Icu* f = icu().load(why);
    return f != nullptr && f->has_binary_property(static_cast<UChar32>(c), p);
}

bool is_ascii_letter(char32_t c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

} // namespace

CodePoint decode_utf8(std::string_view text, std::size_t i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
        return {c, 1, true};
    }
    // ICU's decoder follows the Unicode standard exactly: no overlong forms, no surrogates, nothing
    // above U+10FFFF; an ill-formed sequence is skipped as its maximal valid prefix.
    const auto* s = reinterpret_cast<const std::uint8_t*>(text.data());
    auto length = static_cast<std::int32_t>(std::min<std::size_t>(text.size(), INT32_MAX));
    auto at = static_cast<std::int32_t>(i);
    UChar32 value = 0;
    U8_NEXT(s, at, length, value);
    std::size_t used = static_cast<std::size_t>(at) - i;
    if (value < 0) {
        return {0, used == 0 ? 1 : used, false};
    }
    return {static_cast<char32_t>(value), used, true};
}

namespace {

// The first ill-formed sequence of text at or after byte i, as [begin, end); nullopt if none.
std::optional<std::pair<std::size_t, std::size_t>> next_ill_formed(std::string_view text,
                                                                   std::size_t i) {
    while (i < text.size()) {
        if (static_cast<unsigned char>(text[i]) < 0x80) {
            ++i; // ASCII, most of any source text
            continue;
        }
        CodePoint cp = decode_utf8(text, i);
        if (!cp.valid) {
            return std::pair{i, i + cp.length};
        }
        i += cp.length;
    }
    return std::nullopt;
}

} // namespace

bool is_valid_utf8(std::string_view text) {
    return !next_ill_formed(text, 0);
}

bool is_identifier_start(char32_t c) {
    if (c < 0x80) {
        return c == '_' || is_ascii_letter(c);
    }
    return has_property(c, UCHAR_XID_START);
}

bool is_identifier_continue(char32_t c) {
    if (c < 0x80) {
        return c == '_' || is_ascii_letter(c) || (c >= '0' && c <= '9');
    }
    return has_property(c, UCHAR_XID_CONTINUE);
}

std::string identifier_classes_unavailable() {
    std::string why;
    static_cast<void>(icu().load(why));
    return why;
}

bool check_utf8(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink) {
    constexpr std::size_t kShown = 10;
    std::string_view text = sources.text(file);
    std::vector<SourceRange> bad;
    for (auto seq = next_ill_formed(text, 0); seq; seq = next_ill_formed(text, seq->second)) {
        auto b = static_cast<std::uint32_t>(seq->first);
        auto e = static_cast<std::uint32_t>(seq->second);
        if (!bad.empty() && bad.back().end == b) {
            bad.back().end = e; // neighbouring ill-formed bytes are one problem
        } else {
            bad.push_back({file, b, e});
        }
    }
    for (std::size_t k = 0; k < bad.size() && k < kShown; ++k) {
        sink.error(bad[k], "invalid UTF-8: the file must be UTF-8 text");
    }
    if (bad.size() > kShown) {
        sink.error(bad[kShown], fmt::format("invalid UTF-8: {} more ill-formed sequences from here "
                                            "on are not shown",
                                            bad.size() - kShown));
    }
    return bad.empty();
}

} // namespace catplan
