#pragma once
// Interned strings. A Symbol is a 32-bit handle into a process-wide table, so attribute values that
// are strings compare and hash in O(1) and a Value fits in 16 bytes. The table only grows.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace catplan {

class Symbol {
public:
    constexpr Symbol() = default;
    /// Interns the text (thread-safe) and returns its handle.
    static Symbol intern(std::string_view text);
    /// The interned text; valid for the life of the process.
    std::string_view str() const;

    constexpr std::uint32_t id() const { return id_; }

    friend constexpr bool operator==(Symbol a, Symbol b) = default;

private:
    constexpr explicit Symbol(std::uint32_t id) : id_(id) {}

    std::uint32_t id_ = 0; // 0 is the empty string
};

} // namespace catplan

template <>
struct std::hash<catplan::Symbol> {
    std::size_t operator()(catplan::Symbol s) const noexcept { return s.id(); }
};
