#include "catplan/json/detail/located_json.hpp"

#include <cstddef>
#include <fmt/format.h>
#include <iterator>
#include <nlohmann/json.hpp>

namespace catplan::json::detail {

namespace {

// A char iterator that publishes how far nlohmann's lexer has read. SAX callbacks carry no
// positions, but each one fires right after the lexer has read the token it reports, so "bytes
// consumed so far" is the end of that token (for a number, one past it: the lexer reads the
// delimiter before it knows the number has ended).
class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* p, const char** consumed) : p_(p), consumed_(consumed) {}

    reference operator*() const { return *p_; }

    CountingIterator& operator++() {
        ++p_;
        if (consumed_ != nullptr) {
            *consumed_ = p_;
        }
        return *this;
    }

    CountingIterator operator++(int) {
        CountingIterator old = *this;
        ++*this;
        return old;
    }

    friend bool operator==(const CountingIterator& a, const CountingIterator& b) {
        return a.p_ == b.p_;
    }

private:
    const char* p_;
    const char** consumed_;
};

bool is_number_char(char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// Builds the Node tree, in the manner of nlohmann's own json_sax_dom_parser. Only the innermost
// open container receives children, so the pointers on the stack stay valid.
class Builder {
public:
    Builder(std::uint32_t file, std::string_view text, DiagnosticSink& sink)
        : file_(file), text_(text), sink_(sink), consumed_(text.data()) {}

    const char** consumed() { return &consumed_; }

    Node& root() { return root_; }

    bool null() {
        add_scalar(Node{}, 4);
        return true;
    }

    bool boolean(bool b) {
        Node n;
        n.kind = Node::Kind::Bool;
        n.boolean = b;
        add_scalar(std::move(n), b ? 4 : 5);
        return true;
    }

    bool number_integer(std::int64_t i) {
        Node n;
        n.kind = Node::Kind::Int;
        n.integer = i;
        add_number(std::move(n));
        return true;
    }

    bool number_unsigned(std::uint64_t u) {
        Node n;
        if (u <= static_cast<std::uint64_t>(INT64_MAX)) {
            n.kind = Node::Kind::Int;
            n.integer = static_cast<std::int64_t>(u);
        } else {
            n.kind = Node::Kind::BigInt;
            n.real = static_cast<double>(u);
        }
        add_number(std::move(n));
        return true;
    }

    // nlohmann refuses a number that overflows (1e999) as a parse error.
    bool number_float(double f, const std::string& /*raw*/) {
        Node n;
        n.kind = Node::Kind::Float;
        n.real = f;
        add_number(std::move(n));
        return true;
    }

    bool string(std::string& s) {
        Node n;
        n.kind = Node::Kind::String;
        n.string = std::move(s);
        std::uint32_t end = offset();
        n.range = {file_, string_begin(end), end};
        add(std::move(n));
        return true;
    }

    bool binary(nlohmann::json::binary_t& /*unused*/) { return true; } // not produced by JSON text

    bool start_object(std::size_t /*unknown size*/) { return open(Node::Kind::Object); }

    bool start_array(std::size_t /*unknown size*/) { return open(Node::Kind::Array); }

    bool end_object() { return close(); }

    bool end_array() { return close(); }

    bool key(std::string& k) {
        Node& obj = *stack_.back();
        std::uint32_t end = offset();
        SourceRange range{file_, string_begin(end), end};
        for (std::size_t i = 0; i < obj.keys.size(); ++i) {
            if (obj.keys[i] == k) {
                sink_.error(range, fmt::format("duplicate key '{}'", k))
                    .notes.emplace_back(obj.key_ranges[i], "first given here");
                break;
            }
        }
        obj.keys.push_back(std::move(k));
        obj.key_ranges.push_back(range);
        return true;
    }

    bool parse_error(std::size_t position, const std::string& /*last token*/,
                     const nlohmann::json::exception& ex) {
        // nlohmann's position counts the characters read, so the offending one is the last.
        std::size_t at = position > 0 ? position - 1 : 0;
        at = std::min(at, text_.size());
        std::uint32_t begin = static_cast<std::uint32_t>(at);
        sink_.error({file_, begin, begin + 1}, "invalid JSON: " + clean_message(ex.what()));
        return false;
    }

private:
    std::uint32_t offset() const { return static_cast<std::uint32_t>(consumed_ - text_.data()); }

    // Walks back from a closing quote to its opening one: a quote inside a JSON string is always
    // escaped, i.e. preceded by an odd number of backslashes.
    std::uint32_t string_begin(std::uint32_t end) const {
        if (end < 2) {
            return 0;
        }
        std::size_t i = end - 1; // the closing quote
        while (i > 0) {
            --i;
            if (text_[i] != '"') {
                continue;
            }
            std::size_t backslashes = 0;
            while (backslashes < i && text_[i - 1 - backslashes] == '\\') {
                ++backslashes;
            }
            if (backslashes % 2 == 0) {
                return static_cast<std::uint32_t>(i);
            }
        }
        return 0;
    }

    void add_scalar(Node n, std::uint32_t length) {
        std::uint32_t end = offset();
        n.range = {file_, end >= length ? end - length : 0, end};
        add(std::move(n));
    }

    void add_number(Node n) {
        std::uint32_t end = offset();
        if (end > 0 && !is_number_char(text_[end - 1])) {
            --end; // the delimiter the lexer read past the number
        }
        std::uint32_t begin = end;
        while (begin > 0 && is_number_char(text_[begin - 1])) {
            --begin;
        }
        n.range = {file_, begin, end};
        add(std::move(n));
    }

    Node* add(Node n) {
        if (stack_.empty()) {
            root_ = std::move(n);
            return &root_;
        }
        stack_.back()->items.push_back(std::move(n));
        return &stack_.back()->items.back();
    }

    bool open(Node::Kind kind) {
        if (stack_.size() >= kMaxNesting) {
            // Deeper input is refused so that the tree's destructor and readers stay shallow.
            std::uint32_t end = offset();
            sink_.error({file_, end > 0 ? end - 1 : 0, end}, "nested deeper than 256 levels");
            return false;
        }
        Node n;
        n.kind = kind;
        std::uint32_t end = offset();
        n.range = {file_, end > 0 ? end - 1 : 0, end};
        stack_.push_back(add(std::move(n)));
        return true;
    }

    bool close() {
        stack_.back()->range.end = offset();
        stack_.pop_back();
        return true;
    }

    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." ->
    // "syntax error ...": our own diagnostic already gives the location.
    static std::string clean_message(std::string_view what) {
        if (auto bracket = what.find("] "); bracket != std::string_view::npos) {
            what.remove_prefix(bracket + 2);
        }
        if (what.starts_with("parse error")) {
            if (auto colon = what.find(": "); colon != std::string_view::npos) {
                what.remove_prefix(colon + 2);
            }
        }
        return std::string(what);
    }

    std::uint32_t file_;
    std::string_view text_;
    DiagnosticSink& sink_;
    const char* consumed_;
    Node root_;
    std::vector<Node*> stack_;
};

} // namespace

SourceRange Node::head() const {
    if (kind == Kind::Array || kind == Kind::Object) {
        return {range.file, range.begin, range.begin + 1};
    }
    return range;
}

const Node* Node::find(std::string_view key) const {
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (keys[i] == key) {
            return &items[i];
        }
    }
    return nullptr;
}

std::string Node::describe() const {
    switch (kind) {
    case Kind::Null:
        return "null";
    case Kind::Bool:
        return boolean ? "true" : "false";
    case Kind::Int:
        return fmt::format("the integer {}", integer);
    case Kind::BigInt:
        return "a too large integer";
    case Kind::Float:
        return fmt::format("the number {}", real);
    case Kind::String:
        return fmt::format("the string \"{}\"", string);
    case Kind::Array:
        return "an array";
    case Kind::Object:
        return "an object";
    }
    return "a value";
}

std::optional<Node> parse_located(std::uint32_t file, const SourceManager& sources,
                                  DiagnosticSink& sink) {
    std::string_view text = sources.text(file);
    Builder builder(file, text, sink);
    CountingIterator first(text.data(), builder.consumed());
    CountingIterator last(text.data() + text.size(), nullptr);
    if (!nlohmann::json::sax_parse(first, last, &builder)) {
        return std::nullopt;
    }
    return std::move(builder.root());
}

} // namespace catplan::json::detail
