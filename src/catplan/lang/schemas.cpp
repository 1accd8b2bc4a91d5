// Schemas (docs/language.md, "Schemas: `@present`"). A schema is built from its base schemas'
// generators (flattened) and its own statements: generators `X::Ob`, `f::Hom(A, B)`,
// `T::AttrType(Kind)`, `a::Attr(A, T)` and path equations `f ⋅ g == h`.

#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"

#include <fmt/format.h>
#include <optional>
#include <vector>

namespace catplan::lang::detail {
namespace {

using schema::GeneratorKind;
using schema::Path;
using schema::Schema;
using schema::ValueKind;

SourceRange generator_range(const Schema& s, schema::Generator g) {
    switch (g.kind) {
    case GeneratorKind::Ob:
        return s.ob(ObId(g.index)).range;
    case GeneratorKind::Hom:
        return s.hom(HomId(g.index)).range;
    case GeneratorKind::AttrType:
        return s.attr_type(AttrTypeId(g.index)).range;
    case GeneratorKind::Attr:
        return s.attr(AttrId(g.index)).range;
    }
    return {};
}

// Copies the base's generators (flattening); a name already present is skipped when it has
// the same meaning (diamond inheritance) and reported otherwise.
void inherit(Schema& s, const Schema& base, SourceRange at, DiagnosticSink& sink) {
    auto clash = [&](const std::string& n) {
        auto g = s.find(n);
        if (g) {
            sink.error(at, fmt::format("'{}' is declared by two base schemas", n));
        }
        return g.has_value();
    };
    for (std::uint32_t i = 0; i < base.num_obs(); ++i) {
        const auto& o = base.ob(ObId(i));
        if (s.find_ob(o.name)) {
            continue;
        }
        if (!clash(o.name)) {
            s.add_ob(o.name, o.range);
        }
    }
    for (std::uint32_t i = 0; i < base.num_attr_types(); ++i) {
        const auto& t = base.attr_type(AttrTypeId(i));
        if (s.find_attr_type(t.name)) {
            continue;
        }
        if (!clash(t.name)) {
            s.add_attr_type(t.name, t.kind, t.range);
        }
    }
    auto ob_of = [&](ObId x) { return *s.find_ob(base.ob(x).name); };
    auto hom_of = [&](HomId f) { return *s.find_hom(base.hom(f).name); };
    for (std::uint32_t i = 0; i < base.num_homs(); ++i) {
        const auto& h = base.hom(HomId(i));
        if (s.find_hom(h.name)) {
            continue;
        }
        if (!clash(h.name)) {
            s.add_hom(h.name, ob_of(h.dom), ob_of(h.codom), h.range);
        }
    }
    for (std::uint32_t i = 0; i < base.num_attrs(); ++i) {
        const auto& a = base.attr(AttrId(i));
        if (s.find_attr(a.name)) {
            continue;
        }
        if (!clash(a.name)) {
            s.add_attr(a.name, ob_of(a.dom), *s.find_attr_type(base.attr_type(a.codom).name),
                       a.range);
        }
    }
    for (const auto& eq : base.equations()) {
        auto map_path = [&](const Path& p) {
            Path q{ob_of(p.dom), {}, std::nullopt};
            for (HomId f : p.homs) {
                q.homs.push_back(hom_of(f));
            }
            if (p.attr) {
                q.attr = *s.find_attr(base.attr(*p.attr).name);
            }
            return q;
        };
        s.add_equation({eq.name, map_path(eq.lhs), map_path(eq.rhs), eq.range});
    }
}

bool check_new_generator(const Schema& s, const Expr& name, DiagnosticSink& sink) {
    if (auto g = s.find(name.text)) {
        auto& d = sink.error(name.range, fmt::format("duplicate generator '{}'", name.text));
        d.notes.emplace_back(generator_range(s, *g), "first declared here");
        return false;
    }
    return true;
}

std::optional<ObId> object_arg(const Schema& s, const Expr& e, DiagnosticSink& sink) {
    if (e.kind == Expr::Kind::Name) {
        if (auto x = s.find_ob(e.text)) {
            return x;
        }
        if (auto g = s.find(e.text)) {
            sink.error(e.range,
                       fmt::format("'{}' is {}, not an object", e.text, kind_noun(g->kind)));
            return std::nullopt;
        }
    }
    sink.error(e.range, fmt::format("unknown object '{}'", to_string(e)));
    return std::nullopt;
}

std::optional<AttrTypeId> attr_type_arg(const Schema& s, const Expr& e, DiagnosticSink& sink) {
    if (e.kind == Expr::Kind::Name) {
        if (auto t = s.find_attr_type(e.text)) {
            return t;
        }
        if (auto g = s.find(e.text)) {
            sink.error(e.range, fmt::format("'{}' is {}, not an attribute type", e.text,
                                            kind_noun(g->kind)));
            return std::nullopt;
        }
    }
    sink.error(e.range, fmt::format("unknown attribute type '{}'", to_string(e)));
    return std::nullopt;
}

// A path and whether it is still open (no attribute yet).
std::optional<Path> path(const Schema& s, const Expr& e, DiagnosticSink& sink) {
    if (e.kind == Expr::Kind::Name) {
        if (auto f = s.find_hom(e.text)) {
            return Path{s.hom(*f).dom, {*f}, std::nullopt};
        }
        if (auto a = s.find_attr(e.text)) {
            return Path{s.attr(*a).dom, {}, *a};
        }
        if (auto g = s.find(e.text)) {
            sink.error(e.range, fmt::format("'{}' is {}, not a hom or attribute", e.text,
                                            kind_noun(g->kind)));
        } else {
            sink.error(e.range, fmt::format("unknown hom or attribute '{}'", e.text));
        }
        return std::nullopt;
    }
    if (e.kind == Expr::Kind::Call && e.text == "id") {
        if (!check_arity(e, 1, sink)) {
            return std::nullopt;
        }
        auto x = object_arg(s, e.args[0], sink);
        if (!x) {
            return std::nullopt;
        }
        return Path{*x, {}, std::nullopt};
    }
    std::vector<const Expr*> parts;
    if (e.kind == Expr::Kind::Call && e.text == "compose" && !e.args.empty()) {
        for (const auto& a : e.args) {
            parts.push_back(&a);
        }
    } else if (e.is_binary(".")) {
        parts = {&e.args[0], &e.args[1]};
    } else {
        sink.error(e.range, fmt::format("expected a path (f, compose(f, g), f ⋅ g or id(X)), "
                                        "found '{}'",
                                        to_string(e)));
        return std::nullopt;
    }
    std::optional<Path> acc;
    for (const Expr* part : parts) {
        auto p = path(s, *part, sink);
        if (!p) {
            return std::nullopt;
        }
        if (!acc) {
            acc = std::move(p);
            continue;
        }
        if (acc->attr) {
            sink.error(part->range,
                       fmt::format("cannot compose after attribute '{}': an attribute ends "
                                   "a path",
                                   s.attr(*acc->attr).name));
            return std::nullopt;
        }
        ObId end = s.path_codom_ob(*acc);
        if (end != p->dom) {
            sink.error(part->range,
                       fmt::format("cannot compose: '{}' ends at {} but '{}' starts at {}",
                                   s.path_to_string(*acc), s.ob(end).name, s.path_to_string(*p),
                                   s.ob(p->dom).name));
            return std::nullopt;
        }
        acc->homs.insert(acc->homs.end(), p->homs.begin(), p->homs.end());
        acc->attr = p->attr;
    }
    return acc;
}

std::string path_end(const Schema& s, const Path& p) {
    return p.attr ? s.attr_type(s.attr(*p.attr).codom).name : s.ob(s.path_codom_ob(p)).name;
}

void equation(Schema& s, const Expr& st, DiagnosticSink& sink, std::string name = {}) {
    auto lhs = path(s, st.args[0], sink);
    auto rhs = path(s, st.args[1], sink);
    if (!lhs || !rhs) {
        return;
    }
    std::string lend = path_end(s, *lhs), rend = path_end(s, *rhs);
    if (lhs->dom != rhs->dom || lhs->attr.has_value() != rhs->attr.has_value() || lend != rend) {
        sink.error(st.range,
                   fmt::format("the sides of the equation have different ends: {} : {} → {} "
                               "but {} : {} → {}",
                               s.path_to_string(*lhs), s.ob(lhs->dom).name, lend,
                               s.path_to_string(*rhs), s.ob(rhs->dom).name, rend));
        return;
    }
    s.add_equation({std::move(name), std::move(*lhs), std::move(*rhs), st.range});
}

void schema_statement(Schema& s, const Expr& st, DiagnosticSink& sink) {
    if (st.is_binary("==")) {
        equation(s, st, sink);
        return;
    }
    if (st.is_binary(":=")) {
        if (st.args[0].kind != Expr::Kind::Name || !st.args[1].is_binary("==")) {
            sink.error(st.range, fmt::format("expected a named equation 'name := f ⋅ g == h', "
                                             "found '{}'",
                                             to_string(st)));
            return;
        }
        equation(s, st.args[1], sink, st.args[0].text);
        return;
    }
    if (!st.is_binary("::")) {
        sink.error(st.range, fmt::format("expected a generator (X::Ob, f::Hom(A, B), "
                                         "T::AttrType, a::Attr(A, T)) or an equation, "
                                         "found '{}'",
                                         to_string(st)));
        return;
    }
    const Expr& type = st.args[1];
    auto names = declared_names(st.args[0], sink);
    std::string head = type.text;
    if (type.kind == Expr::Kind::Name && head == "Ob") {
        for (const Expr* n : names) {
            if (check_new_generator(s, *n, sink)) {
                s.add_ob(n->text, n->range);
            }
        }
    } else if ((type.kind == Expr::Kind::Name || type.kind == Expr::Kind::Call) &&
               head == "AttrType") {
        ValueKind kind = ValueKind::Unknown;
        if (type.kind == Expr::Kind::Call) {
            if (!check_arity(type, 1, sink)) {
                return;
            }
            auto k = type.args[0].kind == Expr::Kind::Name
                         ? schema::parse_value_kind(type.args[0].text)
                         : std::nullopt;
            if (!k) {
                sink.error(type.args[0].range,
                           fmt::format("unknown value kind '{}' (expected Bool, Int, Int64, "
                                       "Float, Float64, String or Symbol)",
                                       to_string(type.args[0])));
                return;
            }
            kind = *k;
        }
        for (const Expr* n : names) {
            // An attribute type inherited without a kind (Catlab's are type parameters, as in
            // SchWeightedGraph) may be declared again with one.
            auto old = s.find_attr_type(n->text);
            if (old && kind != ValueKind::Unknown && s.attr_type(*old).kind == ValueKind::Unknown) {
                s.set_kind(*old, kind);
            } else if (check_new_generator(s, *n, sink)) {
                s.add_attr_type(n->text, kind, n->range);
            }
        }
    } else if (type.kind == Expr::Kind::Call && head == "Hom") {
        if (!check_arity(type, 2, sink)) {
            return;
        }
        auto dom = object_arg(s, type.args[0], sink);
        auto codom = object_arg(s, type.args[1], sink);
        for (const Expr* n : names) {
            if (check_new_generator(s, *n, sink) && dom && codom) {
                s.add_hom(n->text, *dom, *codom, n->range);
            }
        }
    } else if (type.kind == Expr::Kind::Call && head == "Attr") {
        if (!check_arity(type, 2, sink)) {
            return;
        }
        auto dom = object_arg(s, type.args[0], sink);
        auto codom = attr_type_arg(s, type.args[1], sink);
        for (const Expr* n : names) {
            if (check_new_generator(s, *n, sink) && dom && codom) {
                s.add_attr(n->text, *dom, *codom, n->range);
            }
        }
    } else {
        sink.error(type.range, fmt::format("unknown generator type '{}' (expected Ob, "
                                           "Hom(A, B), AttrType or Attr(A, T))",
                                           to_string(type)));
    }
}

} // namespace

void elaborate_schema(Elaborator& ctx, const MacroCall& form, bool imported) {
    DiagnosticSink& sink = ctx.sink;
    const Expr* name = nullptr;
    std::vector<const Expr*> bases;
    bool ok = true;
    if (form.header.size() == 1) {
        const Expr& h = form.header[0];
        if (h.kind == Expr::Kind::Call && h.args.size() == 1 &&
            h.args[0].kind == Expr::Kind::Name) {
            name = &h;
            if (h.args[0].text != "FreeSchema") {
                sink.error(h.args[0].range, fmt::format("unknown theory '{}' (expected FreeSchema)",
                                                        h.args[0].text));
                ok = false;
            }
        } else if (h.is_binary("<:") && h.args[0].kind == Expr::Kind::Name) {
            name = &h.args[0];
            const Expr& b = h.args[1];
            if (b.kind == Expr::Kind::Name) {
                bases.push_back(&b);
            } else if (b.kind == Expr::Kind::Tuple) {
                for (const auto& a : b.args) {
                    bases.push_back(&a);
                }
            }
        } else if (h.kind == Expr::Kind::Name) {
            name = &h;
        }
    }
    if (name == nullptr || !form.has_body || !form.assigned.empty()) {
        sink.error(form.range, "expected '@present Name(FreeSchema) begin ... end' or "
                               "'@present Name <: Base begin ... end'");
        return;
    }
    SourceRange name_range = name->kind == Expr::Kind::Call ? name->name_range : name->range;
    auto s = std::make_shared<Schema>(name->text);
    for (const Expr* b : bases) {
        if (b->kind != Expr::Kind::Name) {
            sink.error(b->range, "expected a schema name");
            ok = false;
            continue;
        }
        auto base = ctx.lookup_schema(*b, false);
        if (!base) {
            ok = false;
            continue;
        }
        inherit(*s, *base, b->range, sink);
    }
    std::size_t errors = sink.num_errors();
    for (const auto& st : form.body) {
        schema_statement(*s, st, sink);
    }
    if (!ok || !ctx.claim_name(s->name(), name_range)) {
        return;
    }
    // A schema with errors stays visible, so its instances are still checked, but neither
    // it nor they enter the module.
    ctx.schemas[s->name()] = s;
    ctx.local_schemas.insert(s.get());
    if (sink.num_errors() != errors) {
        ctx.broken.insert(s.get());
        return;
    }
    ctx.module.add(new_declaration(DeclKind::Schema, s->name(), name_range, imported, s));
}

} // namespace catplan::lang::detail
