#include "catplan/base/unicode.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <unicode/uchar.h>
#include <unicode/utf8.h>
#include <vector>

namespace catplan {

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

bool is_valid_utf8(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        CodePoint cp = decode_utf8(text, i);
        if (!cp.valid) {
            return false;
        }
        i += cp.length;
    }
    return true;
}

bool is_identifier_start(char32_t c) {
    return c == '_' || u_hasBinaryProperty(static_cast<UChar32>(c), UCHAR_XID_START);
}

bool is_identifier_continue(char32_t c) {
    return u_hasBinaryProperty(static_cast<UChar32>(c), UCHAR_XID_CONTINUE);
}

bool check_utf8(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink) {
    constexpr std::size_t kShown = 10;
    std::string_view text = sources.text(file);
    std::vector<SourceRange> bad;
    for (std::size_t i = 0; i < text.size();) {
        CodePoint cp = decode_utf8(text, i);
        if (!cp.valid) {
            auto b = static_cast<std::uint32_t>(i);
            auto e = static_cast<std::uint32_t>(i + cp.length);
            if (!bad.empty() && bad.back().end == b) {
                bad.back().end = e; // neighbouring ill-formed bytes are one problem
            } else {
                bad.push_back({file, b, e});
            }
        }
        i += cp.length;
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
