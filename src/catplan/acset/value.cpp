#include "catplan/acset/value.hpp"

#include "catplan/base/hash.hpp"

#include <bit>
#include <fmt/format.h>

namespace catplan::acset {

schema::ValueKind Value::kind() const {
    switch (tag_) {
    case Tag::Bool:
        return schema::ValueKind::Bool;
    case Tag::Int:
        return schema::ValueKind::Int;
    case Tag::Float:
        return schema::ValueKind::Float;
    case Tag::String:
        return schema::ValueKind::String;
    default:
        return schema::ValueKind::Unknown;
    }
}

std::uint64_t Value::hash() const {
    std::uint64_t payload = 0;
    switch (tag_) {
    case Tag::Unset:
        break;
    case Tag::Var:
        payload = u_.var;
        break;
    case Tag::Bool:
        payload = u_.b ? 1 : 0;
        break;
    case Tag::Int:
        payload = static_cast<std::uint64_t>(u_.i);
        break;
    case Tag::Float:
        // +0.0 and -0.0 are ==, so they must hash alike.
        payload = u_.f == 0.0 ? 0 : std::bit_cast<std::uint64_t>(u_.f);
        break;
    case Tag::String:
        payload = u_.s.id();
        break;
    }
    return hash_combine(static_cast<std::uint64_t>(tag_), hash_mix(payload));
}

namespace {

std::string quote(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
        }
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

} // namespace

std::string Value::to_string() const {
    switch (tag_) {
    case Tag::Unset:
        return "_";
    case Tag::Var:
        return fmt::format("?{}", u_.var + 1);
    case Tag::Bool:
        return u_.b ? "true" : "false";
    case Tag::Int:
        return fmt::format("{}", u_.i);
    case Tag::Float: {
        // Shortest round-trip form, always with a decimal point so it reads back as Float.
        auto s = fmt::format("{}", u_.f);
        if (s.find_first_of(".eEn") == std::string::npos) {
            s += ".0";
        }
        return s;
    }
    case Tag::String:
        return quote(u_.s.str());
    }
    return "_";
}

} // namespace catplan::acset
