#pragma once
// A JSON document tree whose every value and key remembers where it came from, so the readers can
// put semantic errors ("hom id out of range") at file:line:col. nlohmann parses; a SAX handler
// builds this tree and takes offsets from a counting input iterator (see located_json.cpp).

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::json::detail {

struct Node {
    enum class Kind : std::uint8_t { Null, Bool, Int, BigInt, Float, String, Array, Object };

    Kind kind = Kind::Null;
    bool boolean = false;
    std::int64_t integer = 0;
    double real = 0; // for Float and for BigInt (an unsigned integer above INT64_MAX)
    std::string string;
    /// Array elements, or object member values (in document order).
    std::vector<Node> items;
    /// Object member keys, parallel to items.
    std::vector<std::string> keys;
    std::vector<SourceRange> key_ranges;
    /// The whole value: a token, or from an opening bracket to its closing one.
    SourceRange range;

    bool is_object() const { return kind == Kind::Object; }

    bool is_array() const { return kind == Kind::Array; }

    /// The range of a single token, or of only the opening bracket of a container (a short caret).
    SourceRange head() const;
    /// The first member with this key, if this is an object that has one.
    const Node* find(std::string_view key) const;
    /// A short description for messages: "a string", "an array", "the integer 3", ...
    std::string describe() const;
};

/// Parses JSON text registered as `file`; nullopt after reporting a located syntax error (which
/// includes a number out of range, 1e999), or nesting deeper than kMaxNesting (source.hpp), to
/// sink. Duplicate keys are reported too, but the tree is still returned, so that a reader can
/// report its own errors in the same run.
std::optional<Node> parse_located(std::uint32_t file, const SourceManager& sources,
                                  DiagnosticSink& sink);

} // namespace catplan::json::detail
