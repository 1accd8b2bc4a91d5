#pragma once
// ASCII case for names that formats compare without case (PDDL's names and keywords), whatever
// the process's locale: bytes outside A-Z, UTF-8's included, are kept.

#include <string>
#include <string_view>

namespace catplan {

/// c in lower case when it is an ASCII capital letter, else c.
constexpr char ascii_lower(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

/// text with its ASCII capital letters in lower case.
inline std::string ascii_lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        c = ascii_lower(c);
    }
    return out;
}

} // namespace catplan
