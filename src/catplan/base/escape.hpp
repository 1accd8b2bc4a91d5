#pragma once
// Character escaping for the text formats catplan writes (DOT, HTML labels, PostgreSQL COPY):
// one loop, each format giving only its table of replacements.

#include <optional>
#include <string>
#include <string_view>

namespace catplan {

/// `s` with every character for which `replace` gives a string written as that string; the
/// other characters are kept.
template <class Replace>
std::string escape_chars(std::string_view s, Replace replace) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        if (std::optional<std::string_view> r = replace(c)) {
            out += *r;
        } else {
            out += c;
        }
    }
    return out;
}

} // namespace catplan
