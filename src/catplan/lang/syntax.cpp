#include "catplan/lang/syntax.hpp"

#include "catplan/base/unicode.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

namespace catplan::lang {
namespace {

// Thrown inside the parser only, to unwind to the statement being parsed; never escapes parse().
struct SyntaxError {};

// Thrown when the input nests too deeply: unwinds the whole parse (see parse()).
struct TooDeep {};

constexpr std::string_view kTooDeep = "nested deeper than 256 levels";
static_assert(kMaxNesting == 256, "kTooDeep names the limit");

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
            if (at_julia_statement()) {
                skip_julia_statement();
                continue;
            }
            try {
                forms.push_back(top_level());
                end_of_statement();
            } catch (const SyntaxError&) {
                recover();
            } catch (const TooDeep&) {
                break;
            }
        }
        return forms;
    }

    /// The Julia statements skipped, each with whether it is `using`/`import` of a Catlab module.
    struct Skipped {
        SourceRange range;
        bool uses_catlab;
    };

    const std::vector<Skipped>& skipped() const { return skipped_; }

private:
    // A statement that is not a declaration: Julia code pasted around the declarations (`using
    // Catlab`, `G = Graph(3)`, `function ... end`), skipped rather than reported. A declaration
    // starts with '@' or is `Name = @macro ...`; a statement starting with anything but a name
    // is no Julia worth skipping either, and stays an error.
    bool at_julia_statement() const {
        const Token& t = tokens_[pos_];
        if (t.kind != TokenKind::Ident) {
            return false;
        }
        const Token& t1 = tokens_[pos_ + 1];
        bool assigns_macro = t1.kind == TokenKind::Punct && t1.text == "=" &&
                             tokens_[pos_ + 2].kind == TokenKind::At;
        return !assigns_macro;
    }

    static bool opens_julia_block(std::string_view word) {
        static constexpr std::string_view kOpeners[] = {"begin", "function", "for",    "while",
                                                        "if",    "let",      "struct", "quote",
                                                        "try",   "do",       "macro"};
        return std::find(std::begin(kOpeners), std::end(kOpeners), word) != std::end(kOpeners);
    }

    // Skips one Julia statement: to the end of its line, or past the `end` of the blocks it opens.
    // A `module Name` line and a lone `end` are statements of their own, so that a file wrapped
    // in a Julia module keeps its declarations.
    void skip_julia_statement() {
        SourceRange range = tokens_[pos_].range;
        bool uses_catlab = false;
        if (tokens_[pos_].text == "using" || tokens_[pos_].text == "import") {
            const Token& module = tokens_[pos_ + 1];
            uses_catlab = module.kind == TokenKind::Ident &&
                          (module.text == "Catlab" || module.text == "DataMigrations" ||
                           module.text == "AlgebraicRewriting" || module.text == "ACSets");
        }
        int brackets = 0, blocks = 0;
        for (bool first = true;; first = false) {
            const Token& t = tokens_[pos_];
            if (t.kind == TokenKind::Eof) {
                break;
            }
            bool separator =
                t.kind == TokenKind::Newline || (t.kind == TokenKind::Punct && t.text == ";");
            if (separator && brackets == 0 && blocks == 0) {
                break;
            }
            if (t.kind == TokenKind::Punct && (t.text == "(" || t.text == "[" || t.text == "{")) {
                ++brackets;
            } else if (t.kind == TokenKind::Punct &&
                       (t.text == ")" || t.text == "]" || t.text == "}")) {
                brackets = std::max(0, brackets - 1);
            } else if (t.kind == TokenKind::Ident && brackets == 0 && !(first && t.text == "end")) {
                if (opens_julia_block(t.text)) {
                    ++blocks;
                } else if (t.text == "end") {
                    blocks = std::max(0, blocks - 1);
                }
            }
            range = range.merge(t.range);
            ++pos_;
        }
        skipped_.push_back({range, uses_catlab});
    }

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

    // One level of recursion of the parser, released when the guard goes out of scope; the
    // level past kMaxNesting is an error at `at`.
    class Level {
    public:
        Level(Parser& p, SourceRange at) : p_(p) {
            if (++p_.depth_ > kMaxNesting) {
                --p_.depth_;
                p_.too_deep(at);
            }
        }

        ~Level() { --p_.depth_; }

        Level(const Level&) = delete;
        Level& operator=(const Level&) = delete;

    private:
        Parser& p_;
    };

    [[noreturn]] void too_deep(SourceRange at) {
        sink_.error(at, std::string(kTooDeep));
        throw TooDeep{};
    }

    // A node built from its arguments (and macro): its height, checked against the limit.
    Expr sealed(Expr e, SourceRange at) {
        std::uint32_t below = 0;
        for (const auto& a : e.args) {
            below = std::max(below, a.height);
        }
        if (e.macro) {
            for (const auto* list : {&e.macro->header, &e.macro->body}) {
                for (const auto& a : *list) {
                    below = std::max(below, a.height);
                }
            }
        }
        e.height = below + 1;
        if (e.height > kMaxNesting) {
            too_deep(at);
        }
        return e;
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
        Level level(*this, peek().range);
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
        Level level(*this, opener);
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

    // Binary operators by precedence, lowest first; `=` and the arrows associate to the right,
    // the others to the left. The prefix operators - and ! bind between `* /` and `::`, and `.`
    // (composition) binds tightest, then calls and atoms. Precedence climbing keeps the recursion
    // to a few frames per level of nesting, which bounds the stack a deep input needs.
    struct OperatorLevel {
        std::array<std::string_view, 6> ops; // unused entries are empty
        bool right;
    };

    static constexpr std::array<OperatorLevel, 11> kLevels{{
        {{"=", ":="}, true}, // `name := f ⋅ g == h` names an equation, as GATlab does
        {{"=>", "->"}, true},
        {{"|>"}, false}, // Julia's pipe, `x |> (a -> false)`: first x, then the function
        {{"||"}, false},
        {{"&&"}, false},
        {{"==", "!=", "<", "<=", ">", ">="}, false},
        {{"<:"}, false},
        {{"+", "-"}, false},
        {{"*", "/"}, false},
        {{"::"}, false},
        {{"."}, false},
    }};
    // The level a prefix operator's operand is read at, and above which operands are atoms.
    static constexpr std::size_t kPrefixOperand = 9;

    Expr expr() { return binary_expr(0); }

    // The level of the binary operator at the cursor, or kLevels.size() when there is none.
    std::size_t operator_level() {
        const Token& t = peek();
        for (std::size_t i = 0; t.kind == TokenKind::Punct && i < kLevels.size(); ++i) {
            for (auto op : kLevels[i].ops) {
                if (!op.empty() && t.text == op) {
                    return i;
                }
            }
        }
        return kLevels.size();
    }

    // An expression whose binary operators are all at `min` or above.
    Expr binary_expr(std::size_t min) {
        Expr lhs = min <= kPrefixOperand ? prefixed() : primary();
        for (std::size_t level = operator_level(); level >= min && level < kLevels.size();
             level = operator_level()) {
            lhs = extended(std::move(lhs), level);
        }
        return lhs;
    }

    // lhs, the operator of `level` at the cursor and its right operand.
    [[gnu::noinline]] Expr extended(Expr lhs, std::size_t level) {
        Token op = next();
        std::optional<Level> guard; // a right-associative chain recurses once per operator
        if (kLevels[level].right) {
            guard.emplace(*this, op.range);
        }
        Expr rhs = binary_expr(kLevels[level].right ? level : level + 1);
        return binary(op, std::move(lhs), std::move(rhs));
    }

    // `op` is the operator's token, where a tree too deep is reported.
    Expr binary(const Token& op, Expr lhs, Expr rhs) {
        Expr e;
        e.kind = Expr::Kind::Binary;
        e.text = op.text;
        e.range = lhs.range.merge(rhs.range);
        e.args.push_back(std::move(lhs));
        e.args.push_back(std::move(rhs));
        return sealed(std::move(e), op.range);
    }

    // An operand with its prefix operators: `-x`, `!done`, `-1` (a negative literal).
    [[gnu::noinline]] Expr prefixed() {
        if (!at_punct("-") && !at_punct("!")) {
            return primary();
        }
        Token op = next();
        Level level(*this, op.range);
        Expr arg = binary_expr(kPrefixOperand);
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
        return sealed(std::move(e), op.range);
    }

    std::vector<Expr> list(std::string_view close, SourceRange& range) {
        Level level(*this, range);
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
            unclosed(close);
        }
        --nest_;
        range = range.merge(next().range);
        return items;
    }

    [[noreturn, gnu::noinline]] void unclosed(std::string_view close) {
        fail_at(peek(), fmt::format("expected ',' or '{}', found {}", close, describe(peek())));
    }

    // A named edge of a query, `(f: x → y)` (DataMigrations' @join syntax), just after its '(':
    // Binary ":" of the name and the arrow; nullopt (consuming nothing) for anything else.
    [[gnu::noinline]] std::optional<Expr> named_edge(SourceRange& range) {
        ++nest_;
        const Token& name = peek();
        std::size_t colon_at = pos_ + 1;
        while (colon_at < tokens_.size() && tokens_[colon_at].kind == TokenKind::Newline) {
            ++colon_at;
        }
        if (name.kind != TokenKind::Ident || colon_at >= tokens_.size() ||
            tokens_[colon_at].kind != TokenKind::Punct || tokens_[colon_at].text != ":") {
            --nest_;
            return std::nullopt;
        }
        Expr lhs;
        lhs.kind = Expr::Kind::Name;
        lhs.range = name.range;
        lhs.text = next().text;
        Token colon = next();
        Level level(*this, colon.range);
        Expr arrow = expr();
        if (!at_punct(")")) {
            fail_at(peek(), fmt::format("expected ')' after the edge, found {}", describe(peek())));
        }
        --nest_;
        range = range.merge(next().range);
        Expr e = binary(colon, std::move(lhs), std::move(arrow));
        e.range = range;
        return e;
    }

    // Calls and atoms. Each kind has its own function, kept out of line (as are the error
    // paths), so that the frames on the recursion of a deep input stay small.
    Expr primary() {
        const Token& t = peek();
        switch (t.kind) {
        case TokenKind::Int:
        case TokenKind::Float:
        case TokenKind::String:
            return literal();
        case TokenKind::At:
            return macro_expr();
        case TokenKind::Ident:
            return t.text == "begin" ? block_expr() : name_or_call();
        case TokenKind::Punct:
            if (t.text == "(") {
                return parenthesized();
            }
            if (t.text == ":") {
                return symbol();
            }
            if (t.text == "[") {
                return vector();
            }
            if (t.text == "-") {
                return negative_number();
            }
            break;
        default:
            break;
        }
        unexpected_token();
    }

    [[noreturn, gnu::noinline]] void unexpected_token() {
        fail_at(peek(), fmt::format("expected an expression, found {}", describe(peek())));
    }

    [[gnu::noinline]] Expr literal() {
        Token t = next();
        Expr e;
        e.range = t.range;
        e.kind = t.kind == TokenKind::Int     ? Expr::Kind::Int
                 : t.kind == TokenKind::Float ? Expr::Kind::Float
                                              : Expr::Kind::String;
        e.int_value = t.int_value;
        e.float_value = t.float_value;
        e.text = std::move(t.text);
        return e;
    }

    [[gnu::noinline]] Expr macro_expr() {
        Expr e;
        e.kind = Expr::Kind::Macro;
        e.macro = std::make_shared<MacroCall>(macro_call());
        e.range = e.macro->range;
        SourceRange at = e.macro->name_range;
        return sealed(std::move(e), at);
    }

    [[gnu::noinline]] Expr block_expr() {
        Expr e;
        e.kind = Expr::Kind::Block;
        SourceRange opener = peek().range;
        e.range = opener;
        e.args = block(e.range, opener, "'begin'");
        return sealed(std::move(e), opener);
    }

    [[gnu::noinline]] Expr name_or_call() {
        if (at_ident("end")) {
            fail_at(peek(), "unexpected 'end'");
        }
        Token name = next();
        Expr e;
        e.range = name.range;
        if (name.text == "true" || name.text == "false") {
            e.kind = Expr::Kind::Bool;
            e.bool_value = name.text == "true";
            return e;
        }
        e.text = std::move(name.text);
        // A call needs the '(' right after the name, as in Julia: `f (x)` is not a call.
        if (at_punct("(") && peek().range.begin == name.range.end) {
            next();
            e.kind = Expr::Kind::Call;
            e.name_range = name.range;
            e.args = list(")", e.range);
            return sealed(std::move(e), name.range);
        }
        e.kind = Expr::Kind::Name;
        // Julia type parameters, `LabeledGraph{String}`: kept as the name's arguments.
        if (at_punct("{") && peek().range.begin == name.range.end) {
            next();
            e.args = list("}", e.range);
            return sealed(std::move(e), name.range);
        }
        return e;
    }

    // `(x)` (the inner expression, its range widened), a tuple `(a, b)` or a named edge.
    [[gnu::noinline]] Expr parenthesized() {
        Expr e;
        e.range = next().range;
        SourceRange open = e.range;
        if (auto edge = named_edge(e.range)) {
            return std::move(*edge);
        }
        e.args = list(")", e.range);
        if (e.args.size() == 1) {
            Expr inner = std::move(e.args[0]);
            inner.range = e.range;
            return inner;
        }
        e.kind = Expr::Kind::Tuple;
        return sealed(std::move(e), open);
    }

    [[gnu::noinline]] Expr symbol() {
        Token colon = next();
        const Token& n = peek();
        if (n.kind != TokenKind::Ident || n.range.begin != colon.range.end) {
            fail_at(colon, "expected a name right after ':' (a symbol such as :unstack)");
        }
        Expr e;
        e.kind = Expr::Kind::Symbol;
        e.text = n.text;
        e.range = colon.range.merge(next().range);
        return e;
    }

    [[gnu::noinline]] Expr vector() {
        Expr e;
        e.kind = Expr::Kind::Vector;
        e.range = next().range;
        SourceRange open = e.range;
        e.args = list("]", e.range);
        return sealed(std::move(e), open);
    }

    // `-1` where an atom is expected (after `::` or `.`).
    [[gnu::noinline]] Expr negative_number() {
        Token minus = next();
        const Token& n = peek();
        if (n.kind != TokenKind::Int && n.kind != TokenKind::Float) {
            fail_at(minus, "expected a number after '-'");
        }
        Expr e = literal();
        e.int_value = -e.int_value;
        e.float_value = -e.float_value;
        e.text = "-" + e.text;
        e.range = minus.range.merge(e.range);
        return e;
    }

    std::vector<Token> tokens_;
    DiagnosticSink& sink_;
    std::vector<Skipped> skipped_;
    std::size_t pos_ = 0;
    int nest_ = 0;
    std::uint32_t depth_ = 0; // levels of recursion, see Level
};

} // namespace

ParsedFile parse(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink) {
    ParsedFile out;
    out.file = file;
    // Lexical errors inside skipped Julia statements (a `?:` or `$` the language lacks) are
    // dropped with the statement, so the lexer's diagnostics wait for the parse.
    DiagnosticSink lexical(sources);
    Parser parser(lex(sources, file, lexical), sink);
    out.forms = parser.file();
    const auto& skipped = parser.skipped();
    for (const Diagnostic& d : lexical.diagnostics()) {
        bool in_julia = std::any_of(skipped.begin(), skipped.end(), [&](const auto& j) {
            return d.range.begin >= j.range.begin && d.range.end <= j.range.end;
        });
        if (!in_julia) {
            sink.add(d);
        }
    }
    // One note per run of skipped statements.
    for (std::size_t i = 0; i < skipped.size();) {
        std::size_t j = i;
        SourceRange run = skipped[i].range;
        while (j + 1 < skipped.size() &&
               sources.line_col(file, skipped[j + 1].range.begin).line <=
                   sources.line_col(file, skipped[j].range.end).line + 1) {
            run = run.merge(skipped[++j].range);
        }
        std::uint32_t lines =
            sources.line_col(file, run.end).line - sources.line_col(file, run.begin).line + 1;
        sink.note(SourceRange{file, run.begin, run.begin},
                  fmt::format("skipped {} line{} of Julia code (catplan reads the declarations "
                              "only)",
                              lines, lines == 1 ? "" : "s"));
        i = j + 1;
    }
    for (const auto& j : skipped) {
        if (j.uses_catlab && !out.catlab_using.valid()) {
            out.catlab_using = j.range;
        }
    }
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
        return e.args.empty() ? e.text : fmt::format("{}{{{}}}", e.text, join(e.args));
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

} // namespace catplan::lang
