// Declarations of ontology maps (docs/language.md, "Ontology maps"): `@migration Name(Target,
// Source)`, `@compose H(F, G)` and `Name = @migrate Target X` resolve their headers here; the
// entries of a map are elaborated by maps.cpp (detail/map_elaboration.hpp).

#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/detail/map_elaboration.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/migrate/schema_map.hpp"

#include <fmt/format.h>
#include <memory>
#include <string>
#include <string_view>

namespace catplan::lang::detail {
namespace {

using acset::ACSet;

// The name and the two arguments of `@macro Name(A, B)` or `Name = @macro A B`; false after
// reporting a malformed header.
bool binary_header(DiagnosticSink& sink, const MacroCall& form, std::string_view usage,
                   std::string& name, SourceRange& name_range, const Expr*& first,
                   const Expr*& second) {
    const auto& h = form.header;
    if (!form.assigned.empty() && h.size() == 2) {
        name = form.assigned;
        name_range = form.assigned_range;
        first = &h[0];
        second = &h[1];
    } else if (form.assigned.empty() && h.size() == 1 && h[0].kind == Expr::Kind::Call &&
               h[0].args.size() == 2) {
        name = h[0].text;
        name_range = h[0].name_range;
        first = &h[0].args[0];
        second = &h[0].args[1];
    } else {
        sink.error(form.range, fmt::format("expected {}", usage));
        return false;
    }
    for (const Expr* e : {first, second}) {
        if (e->kind != Expr::Kind::Name) {
            sink.error(e->range, fmt::format("expected a name, found '{}'", to_string(*e)));
            return false;
        }
    }
    return true;
}

void add_map(Elaborator& ctx, const std::string& name, SourceRange range, bool imported,
             std::shared_ptr<const migrate::SchemaMap> map, MapSections sections = {}) {
    Declaration d = new_declaration(DeclKind::Map, name, range, imported, map->target());
    d.map = std::move(map);
    d.actions = std::move(sections.actions);
    d.functions = std::move(sections.functions);
    ctx.module.add(std::move(d));
}

const Declaration* find_map(Elaborator& ctx, const Expr& name) {
    DiagnosticSink& sink = ctx.sink;
    const Declaration* d = ctx.module.find(name.text);
    if (d == nullptr || d->kind != DeclKind::Map) {
        sink.error(name.range, d == nullptr ? fmt::format("unknown map '{}'", name.text)
                                            : fmt::format("'{}' is not a map", name.text));
        return nullptr;
    }
    return d;
}

} // namespace

// An ontology map rather than a rule: `@migration Name(Target, Source) begin ... end` or
// `Name = @migration Target Source begin ... end` (a rule names SchRule or one schema).
bool is_map_form(const MacroCall& form) {
    const auto& h = form.header;
    if (form.assigned.empty()) {
        return h.size() == 1 && h[0].kind == Expr::Kind::Call && h[0].args.size() == 2;
    }
    return h.size() == 2 && h[0].kind == Expr::Kind::Name && h[0].text != "SchRule";
}

void elaborate_map_declaration(Elaborator& ctx, const MacroCall& written, bool imported) {
    DiagnosticSink& sink = ctx.sink;
    MacroCall form = written;
    spell_pddl_names(ctx, form);
    detail::MapForm mf;
    const Expr *target = nullptr, *source = nullptr;
    if (!binary_header(ctx.sink, form, "'@migration Name(Target, Source) begin ... end'", mf.name,
                       mf.name_range, target, source)) {
        return;
    }
    if (!form.has_body) {
        sink.error(form.range, fmt::format("map '{}' needs its entries: '@migration "
                                           "{}({}, {}) begin ... end'",
                                           mf.name, mf.name, target->text, source->text));
        return;
    }
    auto t = ctx.lookup_schema(*target, false);
    auto s = ctx.lookup_schema(*source, false);
    if (!t || !s || ctx.broken.count(t.get()) || ctx.broken.count(s.get())) {
        return;
    }
    mf.target = t;
    mf.source = s;
    mf.body = &form.body;
    MapSections sections;
    add_pddl_hooks(ctx, mf, sections);
    auto map = elaborate_map(mf, sink);
    if (map && ctx.claim_name(mf.name, mf.name_range)) {
        add_map(ctx, mf.name, mf.name_range, imported, std::move(map), std::move(sections));
    }
}

// `Name = @migrate Target X begin ... end` (or `@migrate Name(Target, X) begin ... end`):
// the instance X migrated along the map the body gives, as DataMigrations' @migrate builds
// a map and runs it at once.
void elaborate_migrate(Elaborator& ctx, const MacroCall& form, bool imported) {
    DiagnosticSink& sink = ctx.sink;
    detail::MapForm mf;
    const Expr *target = nullptr, *source = nullptr;
    if (!binary_header(ctx.sink, form, "'Name = @migrate Target Instance begin ... end'", mf.name,
                       mf.name_range, target, source)) {
        return;
    }
    const Declaration* x = ctx.module.find(source->text);
    if (x == nullptr || x->kind != DeclKind::Instance) {
        sink.error(source->range, x == nullptr
                                      ? fmt::format("unknown instance '{}'", source->text)
                                      : fmt::format("'{}' is not an instance", source->text));
        return;
    }
    if (!form.has_body) {
        sink.error(form.range, fmt::format("'{}' needs the map's entries: '{} = @migrate "
                                           "{} {} begin ... end'",
                                           mf.name, mf.name, target->text, source->text));
        return;
    }
    auto t = ctx.lookup_schema(*target, false);
    if (!t || ctx.broken.count(t.get())) {
        return;
    }
    mf.target = t;
    mf.source = x->schema;
    mf.body = &form.body;
    auto map = elaborate_map(mf, sink);
    if (!map || !ctx.claim_name(mf.name, mf.name_range)) {
        return;
    }
    Declaration d = new_declaration(DeclKind::Instance, mf.name, mf.name_range, imported, t);
    d.instance = std::make_shared<const ACSet>(migrate::migrate(*map, *x->instance));
    ctx.module.add(std::move(d));
}

// `@compose H(F, G)`: H = F ∘ G as functors, so Δ_H migrates along F, then along G.
void elaborate_compose(Elaborator& ctx, const MacroCall& form, bool imported) {
    DiagnosticSink& sink = ctx.sink;
    std::string name;
    SourceRange name_range;
    const Expr *first = nullptr, *second = nullptr;
    if (!binary_header(ctx.sink, form,
                       "'@compose Name(F, G)' (the map F ∘ G: migrate along F, then G)", name,
                       name_range, first, second)) {
        return;
    }
    const Declaration* f = find_map(ctx, *first);
    const Declaration* g = find_map(ctx, *second);
    if (f == nullptr || g == nullptr) {
        return;
    }
    if (g->map->source() != f->map->target()) {
        sink.error(second->range,
                   fmt::format("cannot compose: '{}' is a map from {}, so '{}' must be a "
                               "map into {}, but it maps into {}",
                               first->text, f->map->target()->name(), second->text,
                               f->map->target()->name(), g->map->source()->name()));
        return;
    }
    auto h = migrate::compose(*f->map, *g->map);
    if (!h) {
        sink.error(form.range, fmt::format("cannot compose '{}' and '{}': {}", first->text,
                                           second->text, h.error()));
        return;
    }
    if (ctx.claim_name(name, name_range)) {
        add_map(ctx, name, name_range, imported,
                std::make_shared<const migrate::SchemaMap>(std::move(*h)));
    }
}

} // namespace catplan::lang::detail
