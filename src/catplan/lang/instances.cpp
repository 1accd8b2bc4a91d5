// Instances (docs/language.md, "States by generators and equations" and "States as tables"):
// `@acset_colim Name(Schema) begin ... end`, a presentation by generators and equations whose
// free instance is the state (detail/colimit.hpp), and `@acset Name(Schema) begin ... end`, a
// state written as tables (counts and columns).

#include "catplan/lang/detail/colimit.hpp"
#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"

#include <cstdint>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <vector>

namespace catplan::lang::detail {
namespace {

using acset::ACSet;
using acset::Value;
using schema::GeneratorKind;
using schema::Schema;

// The name in `Schema`, `Schema{T}` or Julia's qualified `Catlab.Graphs.Graph` (its last part).
const Expr* schema_name_of(const Expr& e) {
    if (e.kind == Expr::Kind::Name) {
        return &e;
    }
    if (e.is_binary(".") && e.args[1].kind == Expr::Kind::Name) {
        const Expr* left = &e.args[0];
        while (left->is_binary(".")) {
            left = &left->args[0];
        }
        return left->kind == Expr::Kind::Name ? &e.args[1] : nullptr;
    }
    return nullptr;
}

// `@acset WeightedGraph{Float64}`: Julia's type parameters are the kinds of the schema's
// attribute types, in order. The file's own schemas take them as if inferred; an imported
// schema (whose kinds are fixed) is copied with them. nullptr after an error.
std::shared_ptr<Schema> with_type_parameters(Elaborator& ctx, const Expr& name,
                                             std::shared_ptr<Schema> s) {
    if (name.args.empty()) {
        return s;
    }
    if (name.args.size() != s->num_attr_types()) {
        ctx.sink.error(name.range, fmt::format("'{}' has {} attribute type{}, but {} type "
                                               "parameter{} are given",
                                               s->name(), s->num_attr_types(),
                                               s->num_attr_types() == 1 ? "" : "s",
                                               name.args.size(), name.args.size() == 1 ? "" : "s"));
        return nullptr;
    }
    std::vector<std::pair<AttrTypeId, schema::ValueKind>> given;
    for (std::uint32_t i = 0; i < name.args.size(); ++i) {
        const Expr& p = name.args[i];
        AttrTypeId t(i);
        auto k = p.kind == Expr::Kind::Name && p.args.empty() ? schema::parse_value_kind(p.text)
                                                              : std::nullopt;
        if (!k) {
            ctx.sink.error(p.range, fmt::format("type parameter '{}' is not a value kind (Bool, "
                                                "Int64, Float64, String or Symbol)",
                                                to_string(p)));
            return nullptr;
        }
        auto declared = s->attr_type(t).kind;
        if (declared != schema::ValueKind::Unknown && declared != *k) {
            ctx.sink.error(p.range, fmt::format("attribute type '{}' has kind {}, not {}",
                                                s->attr_type(t).name, schema::to_string(declared),
                                                schema::to_string(*k)));
            return nullptr;
        }
        if (declared == schema::ValueKind::Unknown) {
            given.emplace_back(t, *k);
        }
    }
    if (given.empty()) {
        return s;
    }
    if (ctx.local_schemas.count(s.get())) {
        auto& table = ctx.inferred[s.get()];
        for (auto [t, k] : given) {
            table.emplace(t.index(), InferredKind{k, name.args[t.index()].range, true});
        }
        return s;
    }
    auto copy = std::make_shared<Schema>(*s);
    for (auto [t, k] : given) {
        copy->set_kind(t, k);
    }
    return copy;
}

bool resolve_instance_header(Elaborator& ctx, const MacroCall& form, std::string& name,
                             SourceRange& range, std::shared_ptr<Schema>& schema) {
    const Expr* schema_name = nullptr;
    if (!form.assigned.empty()) {
        name = form.assigned;
        range = form.assigned_range;
        if (form.header.size() == 1) {
            schema_name = schema_name_of(form.header[0]);
        }
    } else if (form.header.size() == 1 && form.header[0].kind == Expr::Kind::Call &&
               form.header[0].args.size() == 1 && form.header[0].args[0].kind == Expr::Kind::Name) {
        name = form.header[0].text;
        range = form.header[0].name_range;
        schema_name = &form.header[0].args[0];
    }
    if (schema_name == nullptr || !form.has_body) {
        ctx.sink.error(form.range, fmt::format("expected '@{0} Name(Schema) begin ... end' or "
                                               "'Name = @{0} Schema begin ... end'",
                                               form.name));
        return false;
    }
    schema = ctx.lookup_schema(*schema_name, true);
    if (schema != nullptr) {
        schema = with_type_parameters(ctx, *schema_name, std::move(schema));
    }
    return schema != nullptr;
}

// ---- @acset_colim -------------------------------------------------------------------------------

std::optional<ACSet> build_colimit(Elaborator& ctx, const MacroCall& form,
                                   const std::shared_ptr<Schema>& s, SourceRange name_range) {
    DiagnosticSink& sink = ctx.sink;
    std::size_t errors = sink.num_errors();
    Colimit c(s, ctx.inferred_kinds(*s));
    // Generators first, wherever they are written, so that they come first in part order.
    for (const auto& st : form.body) {
        if (st.is_binary("::")) {
            c.declare(st, sink);
        }
    }
    for (const auto& st : form.body) {
        if (st.is_binary("::")) {
            continue;
        }
        if (st.is_binary("==")) {
            c.equation(st, sink);
        } else {
            sink.error(st.range, fmt::format("expected a generator (x::Block) or an "
                                             "equation (f(x) == y), found '{}'",
                                             to_string(st)));
        }
    }
    if (sink.num_errors() != errors || !c.complete(name_range, ctx.options.max_fresh_parts, sink)) {
        return std::nullopt;
    }
    return c.build();
}

// ---- @acset -------------------------------------------------------------------------------------

// A table being read: the state, its schema, and where errors go. The parts and variables it
// may declare in all (LoadOptions::max_table_parts) are checked before anything is allocated, so a
// count such as 3000000000 is a located error rather than an exhausted memory.
struct Table {
    ACSet& x;
    const Schema& s;
    const InferredKinds* inferred;
    DiagnosticSink& sink;
    std::uint64_t max_parts;
    std::uint64_t declared = 0; // parts and variables so far
};

// `Ob = n` and `AttrType = n` (counts) into the state; returns the column statements, which need
// every count first. Nothing is allocated until every count is read: a table whose counts go
// past the limit is not built (its columns are not read either: they could only say that their
// parts are out of range), so ten million parts declared before the count that crosses the
// limit cost nothing.
std::vector<const Expr*> read_counts(Table& t, const MacroCall& form) {
    std::map<std::string, SourceRange> seen;
    std::vector<const Expr*> columns;
    std::vector<std::pair<schema::Generator, std::uint64_t>> counts;
    bool over_limit = false;
    for (const auto& st : form.body) {
        if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Name) {
            t.sink.error(st.range, fmt::format("expected 'Name = value' (an object count, a "
                                               "column, or a number of variables), found '{}'",
                                               to_string(st)));
            continue;
        }
        const Expr& lhs = st.args[0];
        const Expr& rhs = st.args[1];
        auto [it, fresh] = seen.emplace(lhs.text, lhs.range);
        if (!fresh) {
            auto& d = t.sink.error(lhs.range, fmt::format("'{}' is given twice", lhs.text));
            d.notes.emplace_back(it->second, "first given here");
            continue;
        }
        auto g = t.s.find(lhs.text);
        if (!g) {
            t.sink.error(lhs.range,
                         fmt::format("unknown name '{}' in schema '{}'", lhs.text, t.s.name()));
            continue;
        }
        if (g->kind != GeneratorKind::Ob && g->kind != GeneratorKind::AttrType) {
            columns.push_back(&st);
            continue;
        }
        if (rhs.kind != Expr::Kind::Int || rhs.int_value < 0) {
            t.sink.error(rhs.range, fmt::format("expected a count (an integer ≥ 0) for "
                                                "'{}', found '{}'",
                                                lhs.text, to_string(rhs)));
            continue;
        }
        auto count = static_cast<std::uint64_t>(rhs.int_value);
        if (count > t.max_parts - t.declared) {
            t.sink.error(rhs.range, fmt::format("too many parts: '{} = {}' would give this @acset "
                                                "{} parts and variables, but at most {} are "
                                                "allowed",
                                                lhs.text, count, t.declared + count, t.max_parts));
            over_limit = true;
            continue;
        }
        t.declared += count;
        counts.emplace_back(*g, count);
    }
    if (over_limit) {
        return {};
    }
    for (const auto& [g, count] : counts) {
        if (g.kind == GeneratorKind::Ob) {
            t.x.add_parts(ObId(g.index), static_cast<std::size_t>(count));
        } else {
            for (std::uint64_t i = 0; i < count; ++i) {
                t.x.add_var(AttrTypeId(g.index));
            }
        }
    }
    return columns;
}

// One cell of hom column `f` (1-based part, 0 for unset); false after an error.
bool hom_cell(Table& t, HomId f, const Expr& lhs, Part p, const Expr& item) {
    ObId codom = t.s.hom(f).codom;
    std::size_t m = t.x.num_parts(codom);
    if (item.kind != Expr::Kind::Int || item.int_value < 0 ||
        static_cast<std::uint64_t>(item.int_value) > m) {
        t.sink.error(item.range, fmt::format("'{}' must be a part of {} (1 to {}, or 0 for "
                                             "unset), found '{}'",
                                             lhs.text, t.s.ob(codom).name, m, to_string(item)));
        return false;
    }
    t.x.set_subpart(f, p, item.int_value == 0 ? kNoPart : static_cast<Part>(item.int_value - 1));
    return true;
}

// One cell of attribute column `a` (a literal or AttrVar(n)); false after an error that a
// broadcast scalar would repeat on every part.
bool attr_cell(Table& t, AttrId a, const Expr& lhs, Part p, const Expr& item) {
    AttrTypeId type = t.s.attr(a).codom;
    if (item.kind == Expr::Kind::Call && item.text == "AttrVar") {
        std::size_t k = t.x.num_vars(type);
        if (item.args.size() != 1 || item.args[0].kind != Expr::Kind::Int ||
            item.args[0].int_value < 1 || static_cast<std::uint64_t>(item.args[0].int_value) > k) {
            t.sink.error(item.range, fmt::format("AttrVar needs one index from 1 to {} (the "
                                                 "number of variables of {}), found '{}'",
                                                 k, t.s.attr_type(type).name, to_string(item)));
            return false;
        }
        t.x.set_subpart(a, p, Value::var(static_cast<std::uint32_t>(item.args[0].int_value - 1)));
        return true;
    }
    if (!is_literal(item)) {
        t.sink.error(item.range, fmt::format("expected a literal or AttrVar(n) for "
                                             "'{}', found '{}'",
                                             lhs.text, to_string(item)));
        return true; // reported for each part, a broadcast scalar included
    }
    auto v = literal_value(t.s, type, item, t.inferred, t.sink);
    if (!v) {
        return false;
    }
    t.x.set_subpart(a, p, *v);
    return true;
}

// A column `f = [v1, v2, ...]` (one value per part of f's domain) or `f = v` (broadcast).
void read_column(Table& t, const Expr& st) {
    const Expr& lhs = st.args[0];
    const Expr& rhs = st.args[1];
    auto hom = t.s.find_hom(lhs.text);
    auto attr = t.s.find_attr(lhs.text);
    ObId dom = hom ? t.s.hom(*hom).dom : t.s.attr(*attr).dom;
    std::size_t n = t.x.num_parts(dom);
    std::vector<const Expr*> items;
    if (rhs.kind == Expr::Kind::Vector) {
        for (const auto& item : rhs.args) {
            items.push_back(&item);
        }
        if (items.size() != n) {
            t.sink.error(rhs.range,
                         fmt::format("column '{}' has {} value{} but {} has {} "
                                     "part{}",
                                     lhs.text, items.size(), items.size() == 1 ? "" : "s",
                                     t.s.ob(dom).name, n, n == 1 ? "" : "s"));
            return;
        }
    } else {
        items.assign(n, &rhs); // a scalar is broadcast to the whole column
    }
    for (Part p = 0; p < n; ++p) {
        const Expr& item = *items[p];
        bool ok = hom ? hom_cell(t, *hom, lhs, p, item) : attr_cell(t, *attr, lhs, p, item);
        if (!ok && &item == &rhs) {
            break; // a broadcast scalar's error is reported once
        }
    }
}

std::optional<ACSet> build_literal(Elaborator& ctx, const MacroCall& form,
                                   const std::shared_ptr<Schema>& s) {
    std::size_t errors = ctx.sink.num_errors();
    ACSet x(s);
    Table t{x, *s, ctx.inferred_kinds(*s), ctx.sink, ctx.options.max_table_parts};
    for (const Expr* st : read_counts(t, form)) {
        read_column(t, *st);
    }
    if (ctx.sink.num_errors() != errors) {
        return std::nullopt;
    }
    return x;
}

} // namespace

std::vector<InstanceForm> instance_headers(Elaborator& ctx,
                                           const std::vector<const MacroCall*>& forms) {
    ctx.file_instances.clear();
    for (const auto* form : forms) {
        if (!form->assigned.empty()) {
            ctx.file_instances.insert(form->assigned);
        } else if (form->header.size() == 1 && form->header[0].kind == Expr::Kind::Call) {
            ctx.file_instances.insert(form->header[0].text);
        }
    }
    std::vector<InstanceForm> out;
    for (const auto* form : forms) {
        InstanceForm p{form, {}, {}, nullptr};
        if (resolve_instance_header(ctx, *form, p.name, p.name_range, p.schema)) {
            out.push_back(std::move(p));
        }
    }
    return out;
}

void elaborate_instances(Elaborator& ctx, const std::vector<InstanceForm>& instances,
                         bool imported) {
    for (const auto& p : instances) {
        std::optional<ACSet> x;
        if (p.form->name == "acset_colim") {
            x = build_colimit(ctx, *p.form, p.schema, p.name_range);
        } else {
            x = build_literal(ctx, *p.form, p.schema);
        }
        if (x && !ctx.broken.count(p.schema.get()) && ctx.claim_name(p.name, p.name_range)) {
            Declaration d =
                new_declaration(DeclKind::Instance, p.name, p.name_range, imported, p.schema);
            d.instance = std::make_shared<const ACSet>(std::move(*x));
            ctx.module.add(std::move(d));
        }
    }
}

} // namespace catplan::lang::detail
