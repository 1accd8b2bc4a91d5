// The attribute expressions of a rule's effect (docs/language.md, "Rules": computed attributes):
// `isClear(b) == !isClear(b)`, `count(c) == count(c) + 1`, typed at elaboration and evaluated
// when the rule is applied (rewrite::evaluate).

#include "catplan/lang/detail/rule_elaboration.hpp"

#include <fmt/format.h>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

namespace catplan::lang::detail {
namespace {

using acset::Value;
using schema::ValueKind;
using Op = rewrite::AttrExpr::Op;

bool numeric(ValueKind k) {
    return k == ValueKind::Int || k == ValueKind::Float;
}

rewrite::AttrExpr constant(const Expr& e, ValueKind& kind) {
    rewrite::AttrExpr out;
    out.range = e.range;
    kind = literal_kind(e);
    out.op = Op::Const;
    switch (e.kind) {
    case Expr::Kind::Int:
        out.constant = Value::integer(e.int_value);
        break;
    case Expr::Kind::Float:
        out.constant = Value::real(e.float_value);
        break;
    case Expr::Kind::String:
        out.constant = Value::string(e.text);
        break;
    default:
        out.constant = Value::boolean(e.bool_value);
        break;
    }
    return out;
}

// A cell of the presentation read by the expression: `isClear(b)`, or a named variable.
std::optional<rewrite::AttrExpr> input(Colimit& c, const Expr& e, ValueKind& kind,
                                       DiagnosticSink& sink) {
    auto t = c.eval(e, sink);
    if (!t) {
        return std::nullopt;
    }
    if (t->kind != Term::Kind::Value) {
        sink.error(e.range, fmt::format("expected a value in the expression, but '{}' "
                                        "is {}",
                                        to_string(e), c.describe(*t)));
        return std::nullopt;
    }
    rewrite::AttrExpr out;
    out.range = e.range;
    out.op = Op::Input;
    out.input_type = c.value_type(t->node);
    out.input_var = t->node;
    kind = c.schema().attr_type(out.input_type).kind;
    if (kind == ValueKind::Unknown) {
        sink.error(e.range, fmt::format("attribute type '{}' has no value kind; declare one",
                                        c.schema().attr_type(out.input_type).name));
        return std::nullopt;
    }
    return out;
}

std::optional<rewrite::AttrExpr> unary(Colimit& c, const Expr& e, ValueKind& kind,
                                       DiagnosticSink& sink) {
    ValueKind k = ValueKind::Unknown;
    auto arg = translate(c, e.args[0], k, sink);
    if (!arg) {
        return std::nullopt;
    }
    bool neg = e.text == "-";
    if (neg ? !numeric(k) : k != ValueKind::Bool) {
        sink.error(e.range, fmt::format("type error: '{}' needs {}, found {}", e.text,
                                        neg ? "a number" : "a Bool", kind_phrase(k)));
        return std::nullopt;
    }
    rewrite::AttrExpr out;
    out.range = e.range;
    out.op = neg ? Op::Neg : Op::Not;
    out.args.push_back(std::move(*arg));
    kind = k;
    return out;
}

// The operation and result kind of `a op b` on operands of kinds a and b; false when the kinds
// do not fit the operator.
bool type_binary(const std::string& op, ValueKind a, ValueKind b, Op& out, ValueKind& kind) {
    if (op == "+" || op == "-" || op == "/" || op == "*") {
        if (numeric(a) && numeric(b)) {
            // `/` gives a Float, also on two Ints, as in Julia; the rest stay Int on Ints.
            bool ints = a == ValueKind::Int && b == ValueKind::Int && op != "/";
            kind = ints ? ValueKind::Int : ValueKind::Float;
            out = op == "+" ? Op::Add : op == "-" ? Op::Sub : op == "*" ? Op::Mul : Op::Div;
            return true;
        }
        if (op == "*" && a == ValueKind::String && b == ValueKind::String) {
            kind = ValueKind::String; // Julia's string concatenation
            out = Op::Concat;
            return true;
        }
        return false;
    }
    if (op == "&&" || op == "||") {
        kind = ValueKind::Bool;
        out = op == "&&" ? Op::And : Op::Or;
        return a == ValueKind::Bool && b == ValueKind::Bool;
    }
    bool comparable = a == b || (numeric(a) && numeric(b));
    if (op != "==" && op != "!=") {
        comparable = comparable && a != ValueKind::Bool;
    }
    kind = ValueKind::Bool;
    out = op == "=="   ? Op::Eq
          : op == "!=" ? Op::Ne
          : op == "<"  ? Op::Lt
          : op == "<=" ? Op::Le
          : op == ">"  ? Op::Gt
                       : Op::Ge;
    return comparable;
}

std::optional<rewrite::AttrExpr> binary(Colimit& c, const Expr& e, ValueKind& kind,
                                        DiagnosticSink& sink) {
    ValueKind a = ValueKind::Unknown, b = ValueKind::Unknown;
    auto x = translate(c, e.args[0], a, sink);
    auto y = translate(c, e.args[1], b, sink);
    if (!x || !y) {
        return std::nullopt;
    }
    rewrite::AttrExpr out;
    out.range = e.range;
    if (!type_binary(e.text, a, b, out.op, kind)) {
        sink.error(e.range, fmt::format("type error: cannot apply '{}' to {} and {}", e.text,
                                        kind_phrase(a), kind_phrase(b)));
        return std::nullopt;
    }
    out.args.push_back(std::move(*x));
    out.args.push_back(std::move(*y));
    return out;
}

bool is_zero(const Value& v) {
    return (v.tag() == Value::Tag::Int && v.as_int() == 0) ||
           (v.tag() == Value::Tag::Float && v.as_float() == 0.0);
}

// The value of e when it is constant. A constant part whose evaluation fails (an Int overflow, a
// division by zero) and a division by a constant zero are reported at `at` (e's text); a part
// with an error counts as not constant, so each error is reported once.
std::optional<Value> fold(const rewrite::AttrExpr& e, SourceRange at, DiagnosticSink& sink) {
    if (e.op == Op::Const) {
        return e.constant;
    }
    if (e.op == Op::Input) {
        return std::nullopt;
    }
    std::vector<std::optional<Value>> args;
    bool constant = true;
    for (const auto& a : e.args) {
        args.push_back(fold(a, a.range, sink));
        constant = constant && args.back().has_value();
    }
    if (e.op == Op::Div && args[1] && is_zero(*args[1])) {
        sink.error(at, fmt::format("division by zero: the divisor is the constant {}",
                                   args[1]->to_string()));
        return std::nullopt;
    }
    if (!constant) {
        return std::nullopt;
    }
    // Every input is a constant, so evaluate never asks for a bound value.
    auto v = rewrite::evaluate(e, [](AttrTypeId, std::uint32_t) { return Value(); });
    if (!v) {
        sink.error(at, v.error());
        return std::nullopt;
    }
    return *v;
}

} // namespace

bool has_division(const Expr& e) {
    if (e.is_binary("/")) {
        return true;
    }
    for (const auto& a : e.args) {
        if (has_division(a)) {
            return true;
        }
    }
    return false;
}

void check_constants(const rewrite::AttrExpr& e, SourceRange at, DiagnosticSink& sink) {
    fold(e, at, sink);
}

bool is_operator_expr(const Expr& e) {
    if (e.kind == Expr::Kind::Unary) {
        return true;
    }
    if (e.kind != Expr::Kind::Binary) {
        return false;
    }
    static const std::set<std::string> ops = {"+",  "-",  "*", "/",  "&&", "||",
                                              "==", "!=", "<", "<=", ">",  ">="};
    return ops.count(e.text) > 0;
}

bool is_expression_statement(const Expr& st) {
    return st.is_binary("==") && (is_operator_expr(st.args[0]) || is_operator_expr(st.args[1]));
}

std::string kind_phrase(ValueKind k) {
    std::string name(schema::to_string(k));
    bool vowel = !name.empty() && std::string_view("AEIOU").find(name[0]) != std::string::npos;
    return fmt::format("{} {} value", vowel ? "an" : "a", name);
}

std::optional<rewrite::AttrExpr> translate(Colimit& c, const Expr& e, ValueKind& kind,
                                           DiagnosticSink& sink) {
    if (is_literal(e)) {
        return constant(e, kind);
    }
    if (e.kind == Expr::Kind::Name || e.kind == Expr::Kind::Call) {
        return input(c, e, kind, sink);
    }
    if (e.kind == Expr::Kind::Unary) {
        return unary(c, e, kind, sink);
    }
    if (e.kind == Expr::Kind::Binary && is_operator_expr(e)) {
        return binary(c, e, kind, sink);
    }
    sink.error(e.range, fmt::format("expected an expression over attributes of the "
                                    "precondition's parts, found '{}'",
                                    to_string(e)));
    return std::nullopt;
}

void fix_inputs(Colimit& c, rewrite::AttrExpr& e) {
    if (e.op == Op::Input) {
        Value v = c.built_value(e.input_var);
        if (v.is_var()) {
            e.input_var = v.var_index();
        } else {
            e.op = Op::Const;
            e.constant = v;
            e.input_var = 0;
        }
    }
    for (auto& a : e.args) {
        fix_inputs(c, a);
    }
}

} // namespace catplan::lang::detail
