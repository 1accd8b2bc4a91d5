#pragma once
// Attribute values: a concrete Bool, Int, Float or String, an attribute variable (an unknown,
// Catlab's AttrVar), or unset. 16 bytes; strings are interned Symbols so equality is O(1).
// A variable never equals a constant.

#include "catplan/base/symbol.hpp"
#include "catplan/schema/schema.hpp"

#include <cstdint>
#include <string>

namespace catplan::acset {

class Value {
public:
    enum class Tag : std::uint8_t { Unset, Var, Bool, Int, Float, String };

    constexpr Value() = default;

    static constexpr Value var(std::uint32_t index) {
        Value v;
        v.tag_ = Tag::Var;
        v.u_.var = index;
        return v;
    }

    static constexpr Value boolean(bool b) {
        Value v;
        v.tag_ = Tag::Bool;
        v.u_.b = b;
        return v;
    }

    static constexpr Value integer(std::int64_t i) {
        Value v;
        v.tag_ = Tag::Int;
        v.u_.i = i;
        return v;
    }

    static constexpr Value real(double f) {
        Value v;
        v.tag_ = Tag::Float;
        v.u_.f = f;
        return v;
    }

    static Value string(std::string_view s) { return symbol(Symbol::intern(s)); }

    static constexpr Value symbol(Symbol s) {
        Value v;
        v.tag_ = Tag::String;
        v.u_.s = s;
        return v;
    }

    constexpr Tag tag() const { return tag_; }

    constexpr bool is_unset() const { return tag_ == Tag::Unset; }

    constexpr bool is_var() const { return tag_ == Tag::Var; }

    /// A concrete value (not a variable, not unset).
    constexpr bool is_concrete() const { return tag_ >= Tag::Bool; }

    constexpr std::uint32_t var_index() const { return u_.var; }

    constexpr bool as_bool() const { return u_.b; }

    constexpr std::int64_t as_int() const { return u_.i; }

    constexpr double as_float() const { return u_.f; }

    constexpr Symbol as_symbol() const { return u_.s; }

    std::string_view as_string() const { return u_.s.str(); }

    /// Calls `f` with the payload of a concrete value (bool, std::int64_t, double or
    /// std::string_view) and returns its result; `otherwise` for a variable or unset.
    template <class R, class F>
    R visit_concrete(F&& f, R otherwise) const {
        switch (tag_) {
        case Tag::Bool:
            return f(as_bool());
        case Tag::Int:
            return f(as_int());
        case Tag::Float:
            return f(as_float());
        case Tag::String:
            return f(as_string());
        default:
            return otherwise;
        }
    }

    /// The kind of a concrete value (Unknown for a variable or unset).
    schema::ValueKind kind() const;

    /// Exact equality: same tag and payload (Float compared bitwise-equal as ==). Inline: the
    /// hom search and the comparisons by names compare attribute cells in their inner loops.
    friend bool operator==(const Value& a, const Value& b) {
        if (a.tag_ != b.tag_) {
            return false;
        }
        switch (a.tag_) {
        case Tag::Unset:
            return true;
        case Tag::Var:
            return a.u_.var == b.u_.var;
        case Tag::Bool:
            return a.u_.b == b.u_.b;
        case Tag::Int:
            return a.u_.i == b.u_.i;
        case Tag::Float:
            return a.u_.f == b.u_.f;
        case Tag::String:
            return a.u_.s == b.u_.s;
        }
        return false;
    }

    /// A hash consistent with ==.
    std::uint64_t hash() const;

    /// Display form: true, 3, 0.5, "red", ?2 (1-based variable), or _ for unset.
    std::string to_string() const;

private:
    Tag tag_ = Tag::Unset;

    union U {
        constexpr U() : i(0) {}

        bool b;
        std::int64_t i;
        double f;
        Symbol s;
        std::uint32_t var;
    } u_;
};

} // namespace catplan::acset
