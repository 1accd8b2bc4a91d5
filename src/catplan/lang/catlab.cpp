// Catlab compatibility (docs/language.md, "Pasting Catlab code"): the schemas Catlab ships
// (SchGraph, SchReflexiveGraph, ...) as a library that `@import catlab` or a pasted `using
// Catlab` line brings in, and `@acset_type Name(Schema)`, which names a schema again as the Julia
// type of its acsets.

#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/detail/map_elaboration.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <set>

namespace catplan::lang::detail {
namespace {

// The schemas as Catlab's Graphs, DDS and port graph modules declare them (same generator names,
// order and equations), written in this language. Attribute types have no kind: Catlab makes
// them type parameters, so a file gives them with `@acset WeightedGraph{Float64}` or by
// redeclaring them (`Weight::AttrType(Float)`) in a schema that inherits.
constexpr std::string_view kCatlabSchemas = R"(# Catlab's standard schemas (@import catlab)
@present SchGraph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
end

@present SchSymmetricGraph <: SchGraph begin
  inv::Hom(E, E)
  inv ⋅ inv == id(E)
  inv ⋅ src == tgt
  inv ⋅ tgt == src
end

@present SchReflexiveGraph <: SchGraph begin
  refl::Hom(V, E)
  refl ⋅ src == id(V)
  refl ⋅ tgt == id(V)
end

@present SchSymmetricReflexiveGraph <: SchReflexiveGraph begin
  inv::Hom(E, E)
  inv ⋅ inv == id(E)
  inv ⋅ src == tgt
  inv ⋅ tgt == src
  refl ⋅ inv == refl
end

@present SchHalfEdgeGraph(FreeSchema) begin
  (V, H)::Ob
  vertex::Hom(H, V)
  inv::Hom(H, H)
  inv ⋅ inv == id(H)
end

@present SchBipartiteGraph(FreeSchema) begin
  (V₁, V₂, E₁₂, E₂₁)::Ob
  src₁::Hom(E₁₂, V₁)
  tgt₂::Hom(E₁₂, V₂)
  src₂::Hom(E₂₁, V₂)
  tgt₁::Hom(E₂₁, V₁)
end

@present SchWeightedGraph <: SchGraph begin
  Weight::AttrType
  weight::Attr(E, Weight)
end

@present SchLabeledGraph <: SchGraph begin
  Label::AttrType
  label::Attr(V, Label)
end

@present SchNamedGraph <: SchGraph begin
  (VName, EName)::AttrType
  vname::Attr(V, VName)
  ename::Attr(E, EName)
end

@present SchDDS(FreeSchema) begin
  X::Ob
  Φ::Hom(X, X)
end

@present SchCPortGraph(FreeSchema) begin
  (Box, Port, Wire)::Ob
  box::Hom(Port, Box)
  (src, tgt)::Hom(Wire, Port)
end

@acset_type Graph(SchGraph, index=[:src, :tgt]) <: AbstractGraph
@acset_type SymmetricGraph(SchSymmetricGraph, index=[:src]) <: AbstractSymmetricGraph
@acset_type ReflexiveGraph(SchReflexiveGraph, index=[:src, :tgt]) <: AbstractReflexiveGraph
@acset_type SymmetricReflexiveGraph(SchSymmetricReflexiveGraph, index=[:src])
@acset_type HalfEdgeGraph(SchHalfEdgeGraph, index=[:vertex])
@acset_type BipartiteGraph(SchBipartiteGraph, index=[:src₁, :tgt₂, :src₂, :tgt₁])
@acset_type WeightedGraph(SchWeightedGraph, index=[:src, :tgt]) <: AbstractGraph
@acset_type LabeledGraph(SchLabeledGraph, index=[:src, :tgt]) <: AbstractGraph
@acset_type NamedGraph(SchNamedGraph, index=[:src, :tgt]) <: AbstractGraph
@acset_type DDS(SchDDS, index=[:Φ])
@acset_type CPortGraph(SchCPortGraph, index=[:box, :src, :tgt])
)";

constexpr const char* kCatlabKey = "<catlab>";

} // namespace

std::string_view catlab_library_text() {
    return kCatlabSchemas;
}

void import_catlab(Elaborator& ctx) {
    if (ctx.loaded.count(kCatlabKey)) {
        return;
    }
    std::uint32_t file = ctx.sources.add_buffer(kCatlabKey, std::string(kCatlabSchemas));
    load_buffer(ctx, file, kCatlabKey, true);
}

void elaborate_acset_type(Elaborator& ctx, const MacroCall& form) {
    if (form.name == "abstract_acset_type") {
        return; // a Julia supertype: nothing for catplan to know
    }
    // `@acset_type Name(Schema, index=[...]) <: Super`: the keyword arguments tune Julia's
    // indexes and the supertype places it in Julia's type tree; only the schema matters here.
    const Expr* call = form.header.size() == 1 ? &form.header[0] : nullptr;
    if (call != nullptr && call->is_binary("<:")) {
        call = &call->args[0];
    }
    if (call == nullptr || call->kind != Expr::Kind::Call || call->args.empty() ||
        call->args[0].kind != Expr::Kind::Name || form.has_body) {
        ctx.sink.error(form.range, "expected '@acset_type Name(Schema)'");
        return;
    }
    auto schema = ctx.lookup_schema(call->args[0], false);
    if (schema == nullptr || !ctx.claim_name(call->text, call->name_range)) {
        return;
    }
    ctx.schemas[call->text] = schema;
}

} // namespace catplan::lang::detail

// ---- DataMigrations' one-argument @migration ---------------------------------------------------

namespace catplan::lang::detail {
namespace {

bool is_rule_block_name(const std::string& name) {
    static const std::set<std::string> kBlocks = {"Pre", "Keep", "Eff", "NAC", "PAC",
                                                  "L",   "K",    "R",   "l",   "r"};
    return kBlocks.count(name) > 0;
}

// `(f: A → B)`, the typed left side of an entry: its name and ends, or nullptr.
const Expr* typed_entry(const Expr& lhs, const Expr*& dom, const Expr*& codom) {
    if (!lhs.is_binary(":") || lhs.args[0].kind != Expr::Kind::Name ||
        !lhs.args[1].is_binary("->") || lhs.args[1].args[0].kind != Expr::Kind::Name ||
        lhs.args[1].args[1].kind != Expr::Kind::Name) {
        return nullptr;
    }
    dom = &lhs.args[1].args[0];
    codom = &lhs.args[1].args[1];
    return &lhs.args[0];
}

// Whether an object entry's image is an attribute type of the source (or a value kind), which
// makes the entry's left side an attribute type of the target.
bool is_attr_type_image(const schema::Schema& source, const Expr& rhs) {
    return rhs.kind == Expr::Kind::Name &&
           (source.find_attr_type(rhs.text) || schema::parse_value_kind(rhs.text));
}

// The target schema the entries declare: objects and attribute types from `X => ...`, homs and
// attributes from `(f: A → B) => ...`; the entries are rewritten to `f => ...` for the map.
std::shared_ptr<schema::Schema> target_from_entries(const std::string& name,
                                                    const schema::Schema& source,
                                                    const std::vector<Expr>& body,
                                                    std::vector<Expr>& entries,
                                                    DiagnosticSink& sink) {
    auto t = std::make_shared<schema::Schema>(name);
    std::size_t errors = sink.num_errors();
    for (const Expr& st : body) {
        const Expr *dom = nullptr, *codom = nullptr;
        if (!st.is_binary("=>") || typed_entry(st.args[0], dom, codom) != nullptr) {
            continue;
        }
        const Expr& lhs = st.args[0];
        if (lhs.kind != Expr::Kind::Name) {
            sink.error(lhs.range, fmt::format("expected an object, an attribute type or "
                                              "'(f: A → B)' on the left, found '{}'",
                                              to_string(lhs)));
        } else if (t->find(lhs.text)) {
            sink.error(lhs.range, fmt::format("'{}' has two entries", lhs.text));
        } else if (source.find_hom(st.args[1].text) || source.find_attr(st.args[1].text)) {
            sink.error(lhs.range, fmt::format("a hom needs its ends in a one-argument "
                                              "@migration: write '({}: A → B) => {}'",
                                              lhs.text, to_string(st.args[1])));
        } else if (is_attr_type_image(source, st.args[1])) {
            t->add_attr_type(lhs.text, schema::ValueKind::Unknown, lhs.range);
        } else {
            t->add_ob(lhs.text, lhs.range);
        }
    }
    for (const Expr& st : body) {
        const Expr *dom = nullptr, *codom = nullptr;
        const Expr* f = st.is_binary("=>") ? typed_entry(st.args[0], dom, codom) : nullptr;
        if (f == nullptr) {
            entries.push_back(st);
            continue;
        }
        auto a = t->find_ob(dom->text);
        auto b = t->find(codom->text);
        if (!a || !b ||
            (b->kind != schema::GeneratorKind::Ob && b->kind != schema::GeneratorKind::AttrType)) {
            const Expr& bad = !a ? *dom : *codom;
            sink.error(bad.range, fmt::format("'{}' has no entry of its own: add '{} => ...'",
                                              bad.text, bad.text));
            continue;
        }
        if (t->find(f->text)) {
            sink.error(f->range, fmt::format("'{}' has two entries", f->text));
            continue;
        }
        if (b->kind == schema::GeneratorKind::Ob) {
            t->add_hom(f->text, *a, ObId(b->index), f->range);
        } else {
            t->add_attr(f->text, *a, AttrTypeId(b->index), f->range);
        }
        Expr entry = st;
        entry.args[0] = *f;
        entries.push_back(std::move(entry));
    }
    return sink.num_errors() == errors ? t : nullptr;
}

} // namespace

bool is_one_argument_map(const MacroCall& form) {
    if (form.name != "migration" || form.assigned.empty() || form.header.size() != 1 ||
        form.header[0].kind != Expr::Kind::Name || form.header[0].text == "SchRule" ||
        !form.has_body) {
        return false;
    }
    // A rule's body is blocks (L => ..., Pre => ...); a map's body maps generators.
    return std::none_of(form.body.begin(), form.body.end(), [](const Expr& st) {
        return st.is_binary("=>") && st.args[0].kind == Expr::Kind::Name &&
               is_rule_block_name(st.args[0].text);
    });
}

void elaborate_one_argument_map(Elaborator& ctx, const MacroCall& form, bool imported) {
    auto source = ctx.lookup_schema(form.header[0], false);
    if (!source || ctx.broken.count(source.get())) {
        return;
    }
    MapForm mf;
    mf.name = form.assigned;
    mf.name_range = form.assigned_range;
    std::vector<Expr> entries;
    mf.target =
        target_from_entries(form.assigned + "_domain", *source, form.body, entries, ctx.sink);
    if (!mf.target) {
        return;
    }
    mf.source = source;
    mf.body = &entries;
    auto map = elaborate_map(mf, ctx.sink);
    if (map && ctx.claim_name(mf.name, mf.name_range)) {
        Declaration d =
            new_declaration(DeclKind::Map, mf.name, mf.name_range, imported, map->target());
        d.map = std::move(map);
        ctx.module.add(std::move(d));
    }
}

} // namespace catplan::lang::detail
