#pragma once
// Rules as written (`@rule name(params) on Schema begin Pre => ... end`, the paper's
// `:name => @migration(Schema, begin ... end)` and the slides' `name = @migration SchRule Schema
// begin L => ... end`) and their elaboration into rewrite::Rule. rules.cpp builds L, K, R, the
// legs, conditions and parameters; rule_expressions.cpp types the attribute expressions of the
// effect (`isClear(b) == !isClear(b)`).

#include "catplan/lang/detail/colimit.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/schema/schema.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace catplan::lang::detail {

/// One block of a rule: `Pre => begin ... end`.
struct RuleBlock {
    std::string name;
    SourceRange range;
    const std::vector<Expr>* body = nullptr;
};

/// A rule as written, before elaboration.
struct RuleSource {
    std::string name;
    SourceRange name_range;
    SourceRange range;
    std::shared_ptr<schema::Schema> schema;
    bool span_form = false; // the authors' slide form: L, K, R, l, r
    bool has_params = false;
    std::vector<const Expr*> params;
    std::vector<RuleBlock> blocks;
    const Expr* cost = nullptr;   // `cost = 3`, what a step of the rule costs
    const Expr* action = nullptr; // `action = stack(x, x)`, the action a step of it is a step of
};

/// The statements of a block, `begin ... end` or `@join begin ... end`, or nullptr.
const std::vector<Expr>* block_body(const Expr& e);

/// The rule form `form` named `assigned` (from an assignment or a domain's `:name =>`), with
/// `default_schema` when the form names none (inside a domain). False after an error.
bool rule_source(Elaborator& ctx, const MacroCall& form, const std::string& assigned,
                 SourceRange assigned_range, const std::shared_ptr<schema::Schema>& default_schema,
                 RuleSource& src);

/// The rule, or nullptr after reporting every error found.
rewrite::RulePtr elaborate_rule(Elaborator& ctx, const RuleSource& src);

/// Records the name of a parameter `p` of a list; reports and returns false when the list named
/// it before (one part cannot be two parameters).
bool new_parameter(std::map<std::string, SourceRange>& seen, const Expr& p, DiagnosticSink& sink);

// ---- attribute expressions (rule_expressions.cpp) -----------------------------------------------

/// Whether the expression is an operator application (`a + b`, `!a`, `a < b`, ...).
bool is_operator_expr(const Expr& e);
/// `a(x) == <expression>`: an attribute computed from values the match bound.
bool is_expression_statement(const Expr& st);
/// "an Int value", "a Bool value".
std::string kind_phrase(schema::ValueKind k);

/// An expression of Eff over values of the cells of the presentation `c` (L's), typed: `kind` is
/// set to the kind it gives. Input nodes hold c's *value node* until c is built (fix_inputs).
/// nullopt after an error (reported to `sink`).
std::optional<rewrite::AttrExpr> translate(Colimit& c, const Expr& e, schema::ValueKind& kind,
                                           DiagnosticSink& sink);
/// Reports the parts of a translated expression that are constant but cannot be computed (an
/// Int overflow, a division by zero) and every division by a constant zero, each at its text;
/// `at` is the text of the whole expression.
void check_constants(const rewrite::AttrExpr& e, SourceRange at, DiagnosticSink& sink);
/// Whether the expression divides somewhere (for the hint that `/` gives a Float).
bool has_division(const Expr& e);
/// Replaces c's value nodes in Input nodes by the variables c was built into (or by the constant
/// the presentation gives them).
void fix_inputs(Colimit& c, rewrite::AttrExpr& e);

} // namespace catplan::lang::detail
