// The lookups every part of elaboration shares (detail/elaborator.hpp).

#include "catplan/lang/detail/elaborator.hpp"

#include <fmt/format.h>

namespace catplan::lang::detail {

using acset::Value;
using schema::GeneratorKind;
using schema::Schema;
using schema::ValueKind;

bool Elaborator::claim_name(const std::string& name, SourceRange range) {
    auto it = names.find(name);
    if (it != names.end()) {
        // Julia rebinds a name (`M = @migration ...` twice, a local SchGraph after `using
        // Catlab`): the later declaration wins, and what was elaborated with the earlier one
        // keeps it.
        auto& d = sink.warning(range, fmt::format("'{}' is already declared; this later "
                                                  "declaration replaces it",
                                                  name));
        d.notes.emplace_back(it->second, "first declared here");
        it->second = range;
        module.remove(name);
        schemas.erase(name);
        return true;
    }
    names.emplace(name, range);
    return true;
}

std::shared_ptr<Schema> Elaborator::lookup_schema(const Expr& name_expr, bool allow_yoneda) {
    std::string name = name_expr.text;
    auto it = schemas.find(name);
    if (it == schemas.end() && allow_yoneda && name.size() > 1 && name[0] == 'y') {
        // Catlab users write the representable-functor form yColorBlocksworld.
        it = schemas.find(name.substr(1));
    }
    if (it != schemas.end()) {
        return it->second;
    }
    if (module.find(name) != nullptr || file_instances.count(name)) {
        sink.error(name_expr.range, fmt::format("'{}' is an instance, not a schema", name));
    } else {
        sink.error(name_expr.range, fmt::format("unknown schema '{}'", name));
    }
    return nullptr;
}

const InferredKinds* Elaborator::inferred_kinds(const Schema& s) const {
    auto it = inferred.find(&s);
    return it == inferred.end() ? nullptr : &it->second;
}

Declaration new_declaration(DeclKind kind, std::string name, SourceRange range, bool imported,
                            schema::SchemaPtr schema) {
    Declaration d;
    d.kind = kind;
    d.name = std::move(name);
    d.range = range;
    d.imported = imported;
    d.schema = std::move(schema);
    return d;
}

// A Julia symbol (`:a`, what Catlab code writes for Symbol attributes) is a String literal.
bool is_literal(const Expr& e) {
    return e.kind == Expr::Kind::Int || e.kind == Expr::Kind::Float ||
           e.kind == Expr::Kind::String || e.kind == Expr::Kind::Bool ||
           e.kind == Expr::Kind::Symbol;
}

ValueKind literal_kind(const Expr& e) {
    switch (e.kind) {
    case Expr::Kind::Int:
        return ValueKind::Int;
    case Expr::Kind::Float:
        return ValueKind::Float;
    case Expr::Kind::String:
    case Expr::Kind::Symbol:
        return ValueKind::String;
    case Expr::Kind::Bool:
        return ValueKind::Bool;
    default:
        return ValueKind::Unknown;
    }
}

std::vector<const Expr*> declared_names(const Expr& lhs, DiagnosticSink& sink) {
    std::vector<const Expr*> out;
    if (lhs.kind == Expr::Kind::Name) {
        out.push_back(&lhs);
    } else if (lhs.kind == Expr::Kind::Tuple) {
        for (const auto& a : lhs.args) {
            if (a.kind == Expr::Kind::Name) {
                out.push_back(&a);
            } else {
                sink.error(a.range, fmt::format("expected a name, found '{}'", to_string(a)));
            }
        }
    } else {
        sink.error(lhs.range, fmt::format("expected a name or a tuple of names before '::', "
                                          "found '{}'",
                                          to_string(lhs)));
    }
    return out;
}

bool check_arity(const Expr& call, std::size_t n, DiagnosticSink& sink) {
    if (call.args.size() != n) {
        sink.error(call.range, fmt::format("'{}' takes {} argument{}, found {}", call.text, n,
                                           n == 1 ? "" : "s", call.args.size()));
        return false;
    }
    return true;
}

std::optional<Value> literal_value(const Schema& s, AttrTypeId t, const Expr& lit,
                                   const InferredKinds* inferred, DiagnosticSink& sink) {
    const auto& info = s.attr_type(t);
    ValueKind k = literal_kind(lit);
    if (info.kind == ValueKind::Unknown) {
        sink.error(lit.range, fmt::format("attribute type '{}' has no value kind; declare "
                                          "one, e.g. {}::AttrType(String)",
                                          info.name, info.name));
        return std::nullopt;
    }
    if (k == info.kind || (info.kind == ValueKind::Float && k == ValueKind::Int)) {
        switch (info.kind) {
        case ValueKind::Bool:
            return Value::boolean(lit.bool_value);
        case ValueKind::Int:
            return Value::integer(lit.int_value);
        case ValueKind::Float:
            return Value::real(k == ValueKind::Int ? static_cast<double>(lit.int_value)
                                                   : lit.float_value);
        case ValueKind::String:
            return Value::string(lit.text);
        case ValueKind::Unknown:
            break;
        }
    }
    auto& d = sink.error(lit.range, fmt::format("expected a {} value for '{}', found {} "
                                                "literal {}",
                                                schema::to_string(info.kind), info.name,
                                                schema::to_string(k), to_string(lit)));
    if (inferred != nullptr) {
        auto it = inferred->find(t.index());
        if (it != inferred->end()) {
            d.notes.emplace_back(
                it->second.range,
                fmt::format("the kind of '{}' was inferred from this literal", info.name));
            return std::nullopt;
        }
    }
    if (info.range.valid()) {
        d.notes.emplace_back(info.range, fmt::format("'{}' is declared here", info.name));
    }
    return std::nullopt;
}

} // namespace catplan::lang::detail
