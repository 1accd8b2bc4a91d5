#pragma once
// The syntax of .cp files: tokens, a generic AST and the parser. It knows no macro: every top-level
// form is a macro call `@name header... begin statements... end` (or `Name = @name ...`), and the
// elaborator (module.hpp) gives each macro its meaning. That keeps new declaration kinds (@rule,
// @migration, plans) a matter of elaboration only.
//
//   @present Graph(FreeSchema) begin        MacroCall{name "present",
//     (V, E)::Ob                              header [Call Graph(FreeSchema)],
//     (src, tgt)::Hom(E, V)                   body [Binary "::" (Tuple V E) Ob, ...]}
//   end

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::lang {

enum class TokenKind { Ident, Int, Float, String, Punct, At, Newline, Eof };

struct Token {
    TokenKind kind = TokenKind::Eof;
    SourceRange range;
    /// Identifier text, decoded string contents, or the punctuation ("::", "==", "⋅", ...).
    std::string text;
    std::int64_t int_value = 0;
    double float_value = 0.0;
};

/// Splits a buffer into tokens ending with Eof; bad characters, unterminated strings and block
/// comments, numbers out of range are reported to `sink` and skipped. Composition dots `⋅` and `·`
/// become ".", `→` "->". A byte-order mark at the start is skipped; a file that is not UTF-8 gives
/// its encoding errors and no tokens.
std::vector<Token> lex(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink);

struct MacroCall;

struct Expr {
    enum class Kind {
        Name,   // text; args: the Julia type parameters of `Name{T, U}`, if any
        Int,    // int_value
        Float,  // float_value
        String, // text
        Bool,   // bool_value
        Call,   // text(args...)
        Tuple,  // (args...)
        Vector, // [args...]
        Binary, // args[0] text args[1], text one of = => -> == <: :: . and the expression
                // operators || && != < <= > >= + - * / and the pipe |>
        Unary,  // text args[0], text one of - !
        Symbol, // :text (a Julia symbol such as :unstack)
        Block,  // begin args... end (statements)
        Macro,  // macro
    };
    Kind kind = Kind::Name;
    SourceRange range;
    /// For Call, the range of the callee name.
    SourceRange name_range;
    std::string text;
    std::int64_t int_value = 0;
    double float_value = 0.0;
    bool bool_value = false;
    std::vector<Expr> args;
    std::shared_ptr<MacroCall> macro;
    /// The levels of the tree from this node down (1 for a leaf); never above kMaxNesting.
    std::uint32_t height = 1;

    bool is_binary(std::string_view op) const { return kind == Kind::Binary && text == op; }
};

/// `@name header... [begin body... end]`, possibly the right side of `assigned = @name ...`.
/// The call form `@name(a, b, begin ... end)` has header [a, b] and the block as its body.
struct MacroCall {
    std::string name; // without '@'
    SourceRange name_range;
    SourceRange range;
    std::vector<Expr> header;
    bool has_body = false;
    std::vector<Expr> body;
    std::string assigned; // "" unless written `Name = @macro ...`
    SourceRange assigned_range;
};

struct ParsedFile {
    std::uint32_t file = SourceRange::kNoFile;
    std::vector<MacroCall> forms;
    /// The first `using Catlab...` (or DataMigrations, AlgebraicRewriting, ACSets) line, which
    /// makes Catlab's schemas visible as `@import catlab` does; invalid when there is none.
    SourceRange catlab_using;
};

/// Lexes and parses a buffer; syntax errors go to `sink` and the parser resumes at the next
/// statement, so the result holds every form that parsed. A statement that starts with a name and
/// is not `Name = @macro ...` is Julia code pasted around the declarations: it is skipped (with
/// its blocks, up to their `end`) and each run of them gets one note. Nesting deeper than
/// kMaxNesting (source.hpp) is an error that ends the parse, since where the nested form ends is
/// unknown.
ParsedFile parse(const SourceManager& sources, std::uint32_t file, DiagnosticSink& sink);

/// The expression as source-like text (for messages and tests): `f(x) == "red"`.
std::string to_string(const Expr& e);

/// Whether `s` lexes as one identifier that is not a keyword.
bool is_identifier(std::string_view s);

/// `s` as the language writes a name: itself when it is an identifier, else Julia's quoted form
/// `var"on-table"` (a '"' or '\\' in it escaped).
std::string quoted_name(std::string_view s);

} // namespace catplan::lang
