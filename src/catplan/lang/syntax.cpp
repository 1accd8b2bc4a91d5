#include "catplan/lang/syntax.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

namespace catplan::lang {
namespace {

bool is_ident_start(unsigned char c) {
    return std::isalpha(c) || c == '_' || c >= 0x80;
}

bool is_ident_char(unsigned char c) {
    return is_ident_start(c) || std::isdigit(c);
}

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

class Lexer {
public:
    Lexer(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink)
        : file_(file), text_(sources.text(file)), sink_(sink) {}

    std::vector<Token> run() {
        while (i_ < text_.size()) {
            step();
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
        if (c == '\n') {
            push(TokenKind::Newline, b, b + 1, "");
            ++i_;
            return;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
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
        if (is_ident_start(c)) {
            while (i_ < text_.size() && is_ident_char(static_cast<unsigned char>(text_[i_])) &&
                   !utf8_op_at(text_, i_)) {
                ++i_;
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
        static constexpr std::string_view kTwo[] = {
            "::", "==", "<:", "=>", "->", "!=", "<=", ">=", "&&", "||", "|>"};
        for (auto op : kTwo) {
            if (text_.substr(i_, 2) == op) {
                i_ += 2;
                push(TokenKind::Punct, b, i_, std::string(op));
                return;
            }
        }
        if (std::string_view("()[],;=.-+*/!<>:").find(static_cast<char>(c)) !=
            std::string_view::npos) {
            ++i_;
            push(TokenKind::Punct, b, i_, std::string(1, static_cast<char>(c)));
            return;
        }
        // One code point, so the caret covers the whole character.
        ++i_;
        while (i_ < text_.size() && (static_cast<unsigned char>(text_[i_]) & 0xC0) == 0x80) {
            ++i_;
        }
        sink_.error(range(b, i_),
                    fmt::format("unexpected character '{}'", text_.substr(b, i_ - b)));
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
        while (i_ < text_.size() && text_[i_] != '\n') {
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
        if (i_ < text_.size() && is_ident_start(static_cast<unsigned char>(text_[i_])) &&
            !utf8_op_at(text_, i_)) {
            std::size_t e = i_;
            while (e < text_.size() && is_ident_char(static_cast<unsigned char>(text_[e]))) {
                ++e;
            }
            sink_.error(range(b, e), fmt::format("malformed number '{}'", text_.substr(b, e - b)));
            i_ = e;
            return;
        }
        auto& t = push(is_float ? TokenKind::Float : TokenKind::Int, b, i_, spelled);
        if (is_float) {
            t.float_value = std::strtod(spelled.c_str(), nullptr);
        } else {
            errno = 0;
            t.int_value = std::strtoll(spelled.c_str(), nullptr, 10);
            if (errno == ERANGE) {
                sink_.error(t.range, fmt::format("integer '{}' is too large", spelled));
            }
        }
    }

    void string() {
        std::size_t b = i_++;
        std::string out;
        while (i_ < text_.size() && text_[i_] != '"' && text_[i_] != '\n') {
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

    std::uint32_t file_;
    std::string_view text_;
    DiagnosticSink& sink_;
    std::size_t i_ = 0;
    std::vector<Token> tokens_;
};

// Thrown inside the parser only, to unwind to the statement being parsed; never escapes parse().
struct SyntaxError {};

class Parser {
public:
    Parser(std::vector<Token> tokens, DiagnosticSink& sink)
        : tokens_(std::move(tokens)), sink_(sink) {}

    std::vector<MacroCall> file() {
        std::vector<MacroCall> forms;
        while (true) {
            skip_separators();
            if (peek().kind == TokenKind::Eof) {
                break;
            }
            try {
                forms.push_back(top_level());
                end_of_statement();
            } catch (const SyntaxError&) {
                recover();
            }
        }
        return forms;
    }

private:
    // Inside () and [] newlines do not end anything, so peek() skips them there.
    const Token& peek() {
        if (nest_ > 0) {
            while (tokens_[pos_].kind == TokenKind::Newline) {
                ++pos_;
            }
        }
        return tokens_[pos_];
    }

    Token next() {
        const Token& t = peek();
        if (t.kind != TokenKind::Eof) {
            ++pos_;
        }
        return t;
    }

    bool at_punct(std::string_view p) {
        const Token& t = peek();
        return t.kind == TokenKind::Punct && t.text == p;
    }

    bool at_ident(std::string_view name) {
        const Token& t = peek();
        return t.kind == TokenKind::Ident && t.text == name;
    }

    bool at_separator() {
        const Token& t = peek();
        return t.kind == TokenKind::Newline || t.kind == TokenKind::Eof ||
               (t.kind == TokenKind::Punct && t.text == ";");
    }

    void skip_separators() {
        while (peek().kind == TokenKind::Newline || at_punct(";")) {
            ++pos_;
        }
    }

    [[noreturn]] void fail_at(const Token& t, std::string message) {
        sink_.error(t.range, std::move(message));
        throw SyntaxError{};
    }

    static std::string describe(const Token& t) {
        switch (t.kind) {
        case TokenKind::Ident:
            return fmt::format("'{}'", t.text);
        case TokenKind::Int:
        case TokenKind::Float:
            return fmt::format("number {}", t.text);
        case TokenKind::String:
            return "a string";
        case TokenKind::Punct:
            return fmt::format("'{}'", t.text);
        case TokenKind::At:
            return "'@'";
        case TokenKind::Newline:
            return "end of line";
        case TokenKind::Eof:
            return "end of file";
        }
        return "?";
    }

    Token expect_punct(std::string_view p) {
        if (!at_punct(p)) {
            fail_at(peek(), fmt::format("expected '{}', found {}", p, describe(peek())));
        }
        return next();
    }

    void end_of_statement() {
        if (!at_separator()) {
            fail_at(peek(), fmt::format("expected end of statement, found {}", describe(peek())));
        }
    }

    // Skips to the next statement separator at the current nesting, so one error does not
    // cascade into many.
    void recover() {
        nest_ = 0;
        while (!at_separator()) {
            ++pos_;
        }
    }

    MacroCall top_level() {
        const Token& t = peek();
        if (t.kind == TokenKind::Ident && tokens_[pos_ + 1].kind == TokenKind::Punct &&
            tokens_[pos_ + 1].text == "=" && tokens_[pos_ + 2].kind == TokenKind::At) {
            Token name = next();
            next();
            MacroCall m = macro_call();
            m.assigned = name.text;
            m.assigned_range = name.range;
            m.range = name.range.merge(m.range);
            return m;
        }
        if (t.kind != TokenKind::At) {
            fail_at(t,
                    fmt::format("expected a declaration starting with '@', found {}", describe(t)));
        }
        return macro_call();
    }

    MacroCall macro_call() {
        MacroCall m;
        Token at = next();
        const Token& name = peek();
        if (name.kind != TokenKind::Ident || name.range.begin != at.range.end) {
            fail_at(name, "expected a macro name right after '@'");
        }
        m.name = name.text;
        m.name_range = at.range.merge(name.range);
        next();
        m.range = m.name_range;
        if (at_punct("(") && peek().range.begin == name.range.end) {
            // Call form `@migration(Schema, begin ... end)`: a trailing block is the body.
            next();
            m.header = list(")", m.range);
            if (!m.header.empty() && m.header.back().kind == Expr::Kind::Block) {
                m.has_body = true;
                m.body = std::move(m.header.back().args);
                m.header.pop_back();
            }
            return m;
        }
        // Header: expressions up to `begin` or the end of the statement.
        while (!at_separator() && !at_ident("begin") && !at_punct(")") && !at_punct(",")) {
            Expr e = expr();
            m.range = m.range.merge(e.range);
            m.header.push_back(std::move(e));
        }
        if (at_ident("begin")) {
            m.has_body = true;
            m.body = block(m.range, m.name_range, fmt::format("'@{}'", m.name));
        }
        return m;
    }

    // `begin statements... end`, at the `begin`; `what` names the opener for a missing `end`.
    std::vector<Expr> block(SourceRange& range, SourceRange opener, const std::string& what) {
        std::vector<Expr> body;
        int saved = nest_;
        nest_ = 0;
        next();
        while (true) {
            skip_separators();
            const Token& t = peek();
            if (t.kind == TokenKind::Eof) {
                sink_.error(opener, fmt::format("missing 'end' for {} begun here", what));
                nest_ = saved;
                throw SyntaxError{};
            }
            if (at_ident("end")) {
                range = range.merge(next().range);
                break;
            }
            try {
                body.push_back(expr());
                if (!at_ident("end")) { // `begin x::B end` on one line, as Julia allows
                    end_of_statement();
                }
            } catch (const SyntaxError&) {
                recover();
            }
        }
        nest_ = saved;
        return body;
    }

    // Precedence, lowest first: = ; => -> ; || ; && ; == != < <= > >= ; <: ; + - ; * / ;
    // unary - ! ; :: ; . (composition) ; calls and atoms.
    Expr expr() { return assignment(); }

    Expr binary(std::string op, Expr lhs, Expr rhs) {
        Expr e;
        e.kind = Expr::Kind::Binary;
        e.text = std::move(op);
        e.range = lhs.range.merge(rhs.range);
        e.args.push_back(std::move(lhs));
        e.args.push_back(std::move(rhs));
        return e;
    }

    Expr assignment() {
        Expr lhs = arrow();
        if (at_punct("=")) {
            next();
            Expr rhs = assignment();
            return binary("=", std::move(lhs), std::move(rhs));
        }
        return lhs;
    }

    Expr arrow() {
        Expr lhs = pipe();
        if (at_punct("=>") || at_punct("->")) {
            std::string op = next().text;
            Expr rhs = arrow();
            return binary(op, std::move(lhs), std::move(rhs));
        }
        return lhs;
    }

    // Julia's pipe, `x |> (a -> false)`: first x, then the function.
    Expr pipe() {
        Expr lhs = logical_or();
        while (at_punct("|>")) {
            next();
            lhs = binary("|>", std::move(lhs), logical_or());
        }
        return lhs;
    }

    Expr logical_or() {
        Expr lhs = logical_and();
        while (at_punct("||")) {
            next();
            lhs = binary("||", std::move(lhs), logical_and());
        }
        return lhs;
    }

    Expr logical_and() {
        Expr lhs = equality();
        while (at_punct("&&")) {
            next();
            lhs = binary("&&", std::move(lhs), equality());
        }
        return lhs;
    }

    Expr equality() {
        Expr lhs = subtype();
        while (at_punct("==") || at_punct("!=") || at_punct("<") || at_punct("<=") ||
               at_punct(">") || at_punct(">=")) {
            std::string op = next().text;
            lhs = binary(op, std::move(lhs), subtype());
        }
        return lhs;
    }

    Expr subtype() {
        Expr lhs = additive();
        while (at_punct("<:")) {
            next();
            lhs = binary("<:", std::move(lhs), additive());
        }
        return lhs;
    }

    Expr additive() {
        Expr lhs = multiplicative();
        while (at_punct("+") || at_punct("-")) {
            std::string op = next().text;
            lhs = binary(op, std::move(lhs), multiplicative());
        }
        return lhs;
    }

    Expr multiplicative() {
        Expr lhs = unary();
        while (at_punct("*") || at_punct("/")) {
            std::string op = next().text;
            lhs = binary(op, std::move(lhs), unary());
        }
        return lhs;
    }

    Expr unary() {
        if (at_punct("-") || at_punct("!")) {
            Token op = next();
            Expr arg = unary();
            if (op.text == "-" && (arg.kind == Expr::Kind::Int || arg.kind == Expr::Kind::Float) &&
                arg.text.rfind('-', 0) != 0) {
                // A negative literal: -1 is the number, not an operation.
                arg.int_value = -arg.int_value;
                arg.float_value = -arg.float_value;
                arg.text = "-" + arg.text;
                arg.range = op.range.merge(arg.range);
                return arg;
            }
            Expr e;
            e.kind = Expr::Kind::Unary;
            e.text = op.text;
            e.range = op.range.merge(arg.range);
            e.args.push_back(std::move(arg));
            return e;
        }
        return typed();
    }

    Expr typed() {
        Expr lhs = composition();
        while (at_punct("::")) {
            next();
            lhs = binary("::", std::move(lhs), composition());
        }
        return lhs;
    }

    Expr composition() {
        Expr lhs = primary();
        while (at_punct(".")) {
            next();
            lhs = binary(".", std::move(lhs), primary());
        }
        return lhs;
    }

    std::vector<Expr> list(std::string_view close, SourceRange& range) {
        std::vector<Expr> items;
        ++nest_;
        while (!at_punct(close)) {
            items.push_back(expr());
            if (!at_punct(",") && !at_punct(";")) {
                break;
            }
            next();
        }
        if (!at_punct(close)) {
            fail_at(peek(), fmt::format("expected ',' or '{}', found {}", close, describe(peek())));
        }
        --nest_;
        range = range.merge(next().range);
        return items;
    }

    // A named edge of a query, `(f: x → y)` (DataMigrations' @join syntax), just after its '(':
    // Binary ":" of the name and the arrow; nullopt (consuming nothing) for anything else.
    std::optional<Expr> named_edge(SourceRange& range) {
        ++nest_;
        const Token& name = peek();
        std::size_t colon = pos_ + 1;
        while (colon < tokens_.size() && tokens_[colon].kind == TokenKind::Newline) {
            ++colon;
        }
        if (name.kind != TokenKind::Ident || colon >= tokens_.size() ||
            tokens_[colon].kind != TokenKind::Punct || tokens_[colon].text != ":") {
            --nest_;
            return std::nullopt;
        }
        Expr lhs;
        lhs.kind = Expr::Kind::Name;
        lhs.range = name.range;
        lhs.text = next().text;
        next(); // ':'
        Expr arrow = expr();
        if (!at_punct(")")) {
            fail_at(peek(), fmt::format("expected ')' after the edge, found {}", describe(peek())));
        }
        --nest_;
        range = range.merge(next().range);
        Expr e = binary(":", std::move(lhs), std::move(arrow));
        e.range = range;
        return e;
    }

    Expr primary() {
        const Token& t = peek();
        Expr e;
        e.range = t.range;
        switch (t.kind) {
        case TokenKind::Int:
            e.kind = Expr::Kind::Int;
            e.int_value = t.int_value;
            e.text = t.text;
            next();
            return e;
        case TokenKind::Float:
            e.kind = Expr::Kind::Float;
            e.float_value = t.float_value;
            e.text = t.text;
            next();
            return e;
        case TokenKind::String:
            e.kind = Expr::Kind::String;
            e.text = t.text;
            next();
            return e;
        case TokenKind::At: {
            e.kind = Expr::Kind::Macro;
            e.macro = std::make_shared<MacroCall>(macro_call());
            e.range = e.macro->range;
            return e;
        }
        case TokenKind::Ident: {
            if (t.text == "begin") {
                e.kind = Expr::Kind::Block;
                e.args = block(e.range, t.range, "'begin'");
                return e;
            }
            if (t.text == "end") {
                fail_at(t, fmt::format("unexpected '{}'", t.text));
            }
            Token name = next();
            if (name.text == "true" || name.text == "false") {
                e.kind = Expr::Kind::Bool;
                e.bool_value = name.text == "true";
                return e;
            }
            e.text = name.text;
            // A call needs the '(' right after the name, as in Julia: `f (x)` is not a call.
            if (at_punct("(") && peek().range.begin == name.range.end) {
                next();
                e.kind = Expr::Kind::Call;
                e.name_range = name.range;
                e.args = list(")", e.range);
                return e;
            }
            e.kind = Expr::Kind::Name;
            return e;
        }
        case TokenKind::Punct:
            if (t.text == "(") {
                next();
                if (auto edge = named_edge(e.range)) {
                    return std::move(*edge);
                }
                e.args = list(")", e.range);
                if (e.args.size() == 1) {
                    // Plain parentheses: keep the inner expression, widen its range.
                    Expr inner = std::move(e.args[0]);
                    inner.range = e.range;
                    return inner;
                }
                e.kind = Expr::Kind::Tuple;
                return e;
            }
            if (t.text == ":") {
                Token colon = next();
                const Token& n = peek();
                if (n.kind != TokenKind::Ident || n.range.begin != colon.range.end) {
                    fail_at(colon, "expected a name right after ':' (a symbol such as :unstack)");
                }
                e.kind = Expr::Kind::Symbol;
                e.text = n.text;
                e.range = colon.range.merge(next().range);
                return e;
            }
            if (t.text == "[") {
                next();
                e.kind = Expr::Kind::Vector;
                e.args = list("]", e.range);
                return e;
            }
            if (t.text == "-") {
                Token minus = next();
                const Token& n = peek();
                if (n.kind == TokenKind::Int || n.kind == TokenKind::Float) {
                    e = primary();
                    e.int_value = -e.int_value;
                    e.float_value = -e.float_value;
                    e.text = "-" + e.text;
                    e.range = minus.range.merge(e.range);
                    return e;
                }
                fail_at(minus, "expected a number after '-'");
            }
            break;
        default:
            break;
        }
        fail_at(t, fmt::format("expected an expression, found {}", describe(t)));
    }

    std::vector<Token> tokens_;
    DiagnosticSink& sink_;
    std::size_t pos_ = 0;
    int nest_ = 0;
};

} // namespace

std::vector<Token> lex(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink) {
    return Lexer(sources, file, sink).run();
}

ParsedFile parse(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink) {
    ParsedFile out;
    out.file = file;
    out.forms = Parser(lex(sources, file, sink), sink).file();
    return out;
}

namespace {

std::string join(const std::vector<Expr>& args) {
    std::string out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        out += (i ? ", " : "") + to_string(args[i]);
    }
    return out;
}

} // namespace

std::string to_string(const Expr& e) {
    switch (e.kind) {
    case Expr::Kind::Name:
    case Expr::Kind::Int:
    case Expr::Kind::Float:
        return e.text;
    case Expr::Kind::String: {
        std::string out = "\"";
        for (char c : e.text) {
            if (c == '"' || c == '\\') {
                out += '\\';
            }
            out += c;
        }
        return out + "\"";
    }
    case Expr::Kind::Bool:
        return e.bool_value ? "true" : "false";
    case Expr::Kind::Call:
        return fmt::format("{}({})", e.text, join(e.args));
    case Expr::Kind::Tuple:
        return fmt::format("({})", join(e.args));
    case Expr::Kind::Vector:
        return fmt::format("[{}]", join(e.args));
    case Expr::Kind::Binary:
        if (e.text == "::" || e.text == ".") {
            return fmt::format("{}{}{}", to_string(e.args[0]),
                               e.text == "." ? "⋅" : "::", to_string(e.args[1]));
        }
        return fmt::format("{} {} {}", to_string(e.args[0]), e.text, to_string(e.args[1]));
    case Expr::Kind::Unary:
        return e.text + to_string(e.args[0]);
    case Expr::Kind::Symbol:
        return ":" + e.text;
    case Expr::Kind::Block:
        return "begin ... end";
    case Expr::Kind::Macro:
        return fmt::format("@{} ...", e.macro->name);
    }
    return "?";
}

bool is_identifier(std::string_view s) {
    if (s.empty() || !is_ident_start(static_cast<unsigned char>(s[0])) || s == "begin" ||
        s == "end" || s == "true" || s == "false") {
        return false;
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!is_ident_char(static_cast<unsigned char>(s[i])) || utf8_op_at(s, i)) {
            return false;
        }
    }
    return true;
}

} // namespace catplan::lang
