// Value kinds inferred from literals (docs/language.md, "Value kinds"): an attribute type
// declared `T::AttrType` without a kind takes the kind of the literals written for it, in any
// instance, rule or domain of the file that declares the schema; the first literal wins, except
// that a later Float widens an Int. Kinds are inferred before any instance is built, so the order
// of declarations in a file does not change their meaning.

#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"

#include <optional>
#include <string>
#include <unordered_map>

namespace catplan::lang::detail {
namespace {

using schema::Schema;
using schema::ValueKind;

class KindInference {
public:
    explicit KindInference(Elaborator& ctx) : ctx_(ctx) {}

    void infer(Schema& s, AttrTypeId t, const Expr& lit) {
        if (s.attr_type(t).kind != ValueKind::Unknown) {
            return;
        }
        auto& table = ctx_.inferred[&s];
        auto it = table.find(t.index());
        ValueKind k = literal_kind(lit);
        if (it == table.end()) {
            table.emplace(t.index(), InferredKind{k, lit.range, ctx_.local_schemas.count(&s) > 0});
        } else if (it->second.kind == ValueKind::Int && k == ValueKind::Float) {
            it->second.kind = ValueKind::Float; // an Int literal is also a Float
        }
    }

    // Records the kind each literal suggests for its attribute type (the first one wins, except
    // that a later Float widens an Int).
    void instance(const MacroCall& form, Schema& s) {
        if (form.name == "acset") {
            for (const auto& st : form.body) {
                if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Name) {
                    continue;
                }
                auto a = s.find_attr(st.args[0].text);
                if (!a) {
                    continue;
                }
                const Expr& rhs = st.args[1];
                if (is_literal(rhs)) {
                    infer(s, s.attr(*a).codom, rhs);
                }
                if (rhs.kind == Expr::Kind::Vector) {
                    for (const auto& item : rhs.args) {
                        if (is_literal(item)) {
                            infer(s, s.attr(*a).codom, item);
                        }
                    }
                }
            }
            return;
        }
        statements(form.body, s);
    }

    // Kinds from the literals of `@acset_colim`-style statements (instances and rule blocks).
    void statements(const std::vector<Expr>& body, Schema& s) {
        std::unordered_map<std::string, AttrTypeId> var_types;
        for (const auto& st : body) {
            if (st.is_binary("::") && st.args[1].kind == Expr::Kind::Name) {
                if (auto t = s.find_attr_type(st.args[1].text)) {
                    DiagnosticSink quiet(ctx_.sources);
                    for (const Expr* n : declared_names(st.args[0], quiet)) {
                        var_types.emplace(n->text, *t);
                    }
                }
            }
        }
        auto type_of = [&](const Expr& e) -> std::optional<AttrTypeId> {
            if (e.kind == Expr::Kind::Call) {
                if (auto a = s.find_attr(e.text)) {
                    return s.attr(*a).codom;
                }
            }
            if (e.kind == Expr::Kind::Name) {
                auto it = var_types.find(e.text);
                if (it != var_types.end()) {
                    return it->second;
                }
            }
            return std::nullopt;
        };
        for (const auto& st : body) {
            if (!st.is_binary("==")) {
                continue;
            }
            for (int side = 0; side < 2; ++side) {
                const Expr& lit = st.args[side];
                if (is_literal(lit)) {
                    if (auto t = type_of(st.args[1 - side])) {
                        infer(s, *t, lit);
                    }
                }
            }
        }
    }

    // The kinds attribute types take from the literals in a rule's blocks.
    void rule(const MacroCall& form, const std::shared_ptr<Schema>& default_schema) {
        std::shared_ptr<Schema> s = default_schema;
        const Expr* schema_name = nullptr;
        const auto& h = form.header;
        if (form.name == "rule" && h.size() == 3 && h[2].kind == Expr::Kind::Name) {
            schema_name = &h[2];
        } else if (form.name == "migration" && !h.empty() && h.back().kind == Expr::Kind::Name) {
            schema_name = &h.back();
        }
        if (schema_name != nullptr) {
            auto it = ctx_.schemas.find(schema_name->text);
            s = it == ctx_.schemas.end() ? nullptr : it->second;
        }
        if (!s) {
            return;
        }
        for (const auto& st : form.body) {
            if (!st.is_binary("=>")) {
                continue;
            }
            const Expr& rhs = st.args[1];
            if (rhs.kind == Expr::Kind::Block) {
                statements(rhs.args, *s);
            } else if (rhs.kind == Expr::Kind::Macro && rhs.macro->has_body) {
                statements(rhs.macro->body, *s);
            }
        }
    }

    void domain(const MacroCall& form) {
        std::shared_ptr<Schema> s;
        if (form.header.size() == 1 && form.header[0].kind == Expr::Kind::Call &&
            form.header[0].args.size() == 1) {
            auto it = ctx_.schemas.find(form.header[0].args[0].text);
            if (it != ctx_.schemas.end()) {
                s = it->second;
            }
        }
        for (const auto& st : form.body) {
            if (st.kind == Expr::Kind::Macro) {
                rule(*st.macro, s);
            } else if (st.is_binary("=>") && st.args[1].kind == Expr::Kind::Macro) {
                rule(*st.args[1].macro, s);
            }
        }
    }

private:
    Elaborator& ctx_;
};

} // namespace

void infer_kinds(Elaborator& ctx, const std::vector<InstanceForm>& instances,
                 const std::vector<const MacroCall*>& rules,
                 const std::vector<const MacroCall*>& domains) {
    KindInference infer(ctx);
    for (const auto& p : instances) {
        infer.instance(*p.form, *p.schema);
    }
    for (const auto* form : rules) {
        infer.rule(*form, nullptr);
    }
    for (const auto* form : domains) {
        infer.domain(*form);
    }
    for (auto& [schema, inferred] : ctx.inferred) {
        for (auto& [t, info] : inferred) {
            if (info.local && schema->attr_type(AttrTypeId(t)).kind == ValueKind::Unknown) {
                schema->set_kind(AttrTypeId(t), info.kind);
            }
        }
    }
}

} // namespace catplan::lang::detail
