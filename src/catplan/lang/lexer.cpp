// The lexer of the language (syntax.hpp, lex): tokens with their source ranges.

#include "catplan/base/unicode.hpp"
#include "catplan/lang/syntax.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

namespace catplan::lang {
namespace {

// The multi-byte operators that must not be taken for identifier characters.
struct Utf8Op {
    std::string_view bytes;
    std::string_view punct;
};

constexpr Utf8Op kUtf8Ops[] = {{"⋅", "."}, {"·", "."}, {"→", "->"}, {"∘", "∘"}};

const Utf8Op* utf8_op_at(std::string_view text, std::size_t i) {
    for (const auto& op : kUtf8Ops) {
        if (text.substr(i, op.bytes.size()) == op.bytes) {
            return &op;
        }
    }
    return nullptr;
}

// The byte length of the identifier character at text[i] (a start character when `start`), or 0.
// ASCII is decided here; other code points by their Unicode identifier properties (unicode.hpp),
// except the operators `⋅ · → ∘` (`·` is XID_Continue).
std::size_t ident_char_at(std::string_view text, std::size_t i, bool start) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
        return std::isalpha(c) || c == '_' || (!start && std::isdigit(c)) ? 1 : 0;
    }
    if (utf8_op_at(text, i) != nullptr) {
        return 0;
    }
    CodePoint cp = decode_utf8(text, i);
    bool ok =
        cp.valid && (start ? is_identifier_start(cp.value) : is_identifier_continue(cp.value));
    // Julia also continues a name with sub- and superscript digits and primes (`e₁`, `M′`),
    // which Catlab code uses throughout.
    auto julia_continue = [](char32_t v) {
        return (v >= 0x2070 && v <= 0x2079) || (v >= 0x2080 && v <= 0x2089) || v == 0x00B2 ||
               v == 0x00B3 || v == 0x00B9 || (v >= 0x2032 && v <= 0x2037);
    };
    ok = ok || (cp.valid && !start && julia_continue(cp.value));
    return ok ? cp.length : 0;
}

// The end of the identifier that starts at text[i] (i itself when none starts there).
std::size_t ident_end(std::string_view text, std::size_t i) {
    std::size_t n = i < text.size() ? ident_char_at(text, i, true) : 0;
    if (n == 0) {
        return i;
    }
    i += n;
    while (i < text.size() && (n = ident_char_at(text, i, false)) > 0) {
        i += n;
    }
    return i;
}

class Lexer {
public:
    Lexer(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink)
        : sources_(sources), file_(file), text_(sources.text(file)), sink_(sink) {}

    std::vector<Token> run() {
        // An encoding error makes every later message doubtful: report those alone.
        if (check_utf8(sources_, file_, sink_)) {
            i_ = bom_length(text_);
            while (i_ < text_.size()) {
                step();
            }
        }
        push(TokenKind::Newline, i_, i_, "");
        push(TokenKind::Eof, i_, i_, "");
        return std::move(tokens_);
    }

private:
    SourceRange range(std::size_t b, std::size_t e) const {
        return {file_, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e)};
    }

    Token& push(TokenKind kind, std::size_t b, std::size_t e, std::string text) {
        tokens_.push_back(Token{kind, range(b, e), std::move(text), 0, 0.0});
        return tokens_.back();
    }

    void step() {
        auto c = static_cast<unsigned char>(text_[i_]);
        std::size_t b = i_;
        if (c == '\n' || c == '\r') {
            // LF, CRLF and a lone CR each end a line.
            i_ += text_.substr(i_, 2) == "\r\n" ? 2 : 1;
            push(TokenKind::Newline, b, i_, "");
            return;
        }
        if (c == ' ' || c == '\t') {
            ++i_;
            return;
        }
        if (c == '#') {
            comment();
            return;
        }
        if (const auto* op = utf8_op_at(text_, i_)) {
            i_ += op->bytes.size();
            push(TokenKind::Punct, b, i_, std::string(op->punct));
            return;
        }
        if (std::size_t e = ident_end(text_, i_); e > i_) {
            i_ = e;
            if (text_.substr(b, e - b) == "var" && e < text_.size() && text_[e] == '"') {
                quoted_identifier(b);
                return;
            }
            push(TokenKind::Ident, b, i_, std::string(text_.substr(b, i_ - b)));
            return;
        }
        if (std::isdigit(c)) {
            number();
            return;
        }
        if (c == '"') {
            string();
            return;
        }
        if (c == '@') {
            ++i_;
            push(TokenKind::At, b, i_, "@");
            return;
        }
        static constexpr std::string_view kTwo[] = {"::", ":=", "==", "<:", "=>", "->",
                                                    "!=", "<=", ">=", "&&", "||", "|>"};
        for (auto op : kTwo) {
            if (text_.substr(i_, 2) == op) {
                i_ += 2;
                push(TokenKind::Punct, b, i_, std::string(op));
                return;
            }
        }
        if (std::string_view("()[]{},;=.-+*/!<>:").find(static_cast<char>(c)) !=
            std::string_view::npos) {
            ++i_;
            push(TokenKind::Punct, b, i_, std::string(1, static_cast<char>(c)));
            return;
        }
        // One code point, so the caret covers the whole character.
        CodePoint cp = decode_utf8(text_, i_);
        i_ += cp.length;
        if (c < 0x80) {
            sink_.error(range(b, i_),
                        fmt::format("unexpected character '{}'", text_.substr(b, i_ - b)));
            return;
        }
        // Without ICU no character beyond ASCII is known to be a letter: say so, rather than
        // calling a name's letter unexpected.
        std::string unknown = identifier_classes_unavailable();
        sink_.error(
            range(b, i_),
            fmt::format("unexpected character '{}' (U+{:04X}){}", text_.substr(b, i_ - b),
                        static_cast<std::uint32_t>(cp.value),
                        unknown.empty() ? "" : "; letters beyond ASCII are unknown: " + unknown));
    }

    void comment() {
        std::size_t b = i_;
        if (text_.substr(i_, 2) == "#=") {
            // Julia block comments nest.
            int depth = 0;
            while (i_ < text_.size()) {
                if (text_.substr(i_, 2) == "#=") {
                    ++depth;
                    i_ += 2;
                } else if (text_.substr(i_, 2) == "=#") {
                    i_ += 2;
                    if (--depth == 0) {
                        return;
                    }
                } else {
                    ++i_;
                }
            }
            sink_.error(range(b, b + 2), "unterminated block comment '#='");
            return;
        }
        while (i_ < text_.size() && text_[i_] != '\n' && text_[i_] != '\r') {
            ++i_;
        }
    }

    void number() {
        std::size_t b = i_;
        bool is_float = false;
        auto digits = [&] {
            while (i_ < text_.size() &&
                   (std::isdigit(static_cast<unsigned char>(text_[i_])) || text_[i_] == '_')) {
                ++i_;
            }
        };
        digits();
        if (i_ + 1 < text_.size() && text_[i_] == '.' &&
            std::isdigit(static_cast<unsigned char>(text_[i_ + 1]))) {
            is_float = true;
            ++i_;
            digits();
        }
        if (i_ < text_.size() && (text_[i_] == 'e' || text_[i_] == 'E')) {
            std::size_t j = i_ + 1;
            if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) {
                ++j;
            }
            if (j < text_.size() && std::isdigit(static_cast<unsigned char>(text_[j]))) {
                is_float = true;
                i_ = j;
                digits();
            }
        }
        std::string spelled;
        for (char ch : text_.substr(b, i_ - b)) {
            if (ch != '_') {
                spelled += ch;
            }
        }
        if (std::size_t e = ident_end(text_, i_); e > i_) {
            sink_.error(range(b, e), fmt::format("malformed number '{}'", text_.substr(b, e - b)));
            i_ = e;
            return;
        }
        auto& t = push(is_float ? TokenKind::Float : TokenKind::Int, b, i_, spelled);
        if (is_float) {
            t.float_value = std::strtod(spelled.c_str(), nullptr);
            check_float(t);
        } else {
            errno = 0;
            t.int_value = std::strtoll(spelled.c_str(), nullptr, 10);
            if (errno == ERANGE) {
                sink_.error(t.range, fmt::format("integer '{}' is too large (an Int is at most "
                                                 "9223372036854775807)",
                                                 spelled));
            }
        }
    }

    // As Julia does, a float literal must not overflow to infinity nor underflow to zero.
    void check_float(const Token& t) {
        if (std::isinf(t.float_value)) {
            sink_.error(t.range, fmt::format("number '{}' is out of range (a Float is at most "
                                             "about 1.8e308)",
                                             t.text));
        } else if (t.float_value == 0 &&
                   t.text.substr(0, t.text.find_first_of("eE")).find_first_of("123456789") !=
                       std::string::npos) {
            sink_.error(t.range, fmt::format("number '{}' underflows to 0 (a Float other than 0 "
                                             "is at least about 4.9e-324)",
                                             t.text));
        }
    }

    // Julia's var"name": an identifier spelled as a string, for a name that is not an identifier
    // (PDDL's on-table, pick-up), as catplan prints such names.
    void quoted_identifier(std::size_t b) {
        std::size_t errors = sink_.num_errors();
        string();
        Token& t = tokens_.back();
        t.kind = TokenKind::Ident;
        t.range = range(b, i_);
        if (sink_.num_errors() == errors && t.text.empty()) {
            sink_.error(t.range, "var\"\" names nothing: a quoted identifier needs a name");
        } else if (sink_.num_errors() == errors && !is_identifier(t.text) &&
                   ident_end(t.text, 0) == t.text.size()) {
            sink_.error(t.range, fmt::format("var\"{}\" is the keyword {}: it cannot name a "
                                             "generator",
                                             t.text, t.text));
        }
    }

    void string() {
        std::size_t b = i_++;
        std::string out;
        while (i_ < text_.size() && text_[i_] != '"' && text_[i_] != '\n' && text_[i_] != '\r') {
            char ch = text_[i_++];
            if (ch != '\\') {
                out += ch;
                continue;
            }
            if (i_ >= text_.size()) {
                break;
            }
            char esc = text_[i_++];
            switch (esc) {
            case 'n':
                out += '\n';
                break;
            case 't':
                out += '\t';
                break;
            case 'r':
                out += '\r';
                break;
            case '0':
                out += '\0';
                break;
            case '\\':
            case '"':
            case '$':
            case '\'':
                out += esc;
                break;
            default:
                sink_.error(range(i_ - 2, i_), fmt::format("unknown escape '\\{}'", esc));
            }
        }
        if (i_ >= text_.size() || text_[i_] != '"') {
            sink_.error(range(b, b + 1), "unterminated string");
            // Keep the token so the statement still parses and the error does not cascade.
            push(TokenKind::String, b, i_, std::move(out));
            return;
        }
        ++i_;
        push(TokenKind::String, b, i_, std::move(out));
    }

    const SourceManager& sources_;
    std::uint32_t file_;
    std::string_view text_;
    DiagnosticSink& sink_;
    std::size_t i_ = 0;
    std::vector<Token> tokens_;
};

} // namespace

std::vector<Token> lex(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink) {
    return Lexer(sources, file, sink).run();
}

bool is_identifier(std::string_view s) {
    return !s.empty() && ident_end(s, 0) == s.size() && s != "begin" && s != "end" && s != "true" &&
           s != "false";
}

std::string quoted_name(std::string_view s) {
    if (is_identifier(s)) {
        return std::string(s);
    }
    std::string out = "var\"";
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
        }
        out += c;
    }
    return out + "\"";
}

} // namespace catplan::lang
