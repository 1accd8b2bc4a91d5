#include "catplan/lang/module.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/base/union_find.hpp"
#include "catplan/lang/syntax.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

namespace catplan::lang {

using acset::ACSet;
using acset::Value;
using schema::GeneratorKind;
using schema::Path;
using schema::Schema;
using schema::ValueKind;

const Declaration* Module::find(std::string_view name) const {
    for (const auto& d : decls_) {
        if (d.name == name) {
            return &d;
        }
    }
    return nullptr;
}

void Module::add(Declaration d) {
    CATPLAN_ASSERT(find(d.name) == nullptr, "duplicate declaration name");
    decls_.push_back(std::move(d));
}

namespace {

const char* kind_noun(GeneratorKind k) {
    switch (k) {
    case GeneratorKind::Ob:
        return "an object";
    case GeneratorKind::Hom:
        return "a hom";
    case GeneratorKind::AttrType:
        return "an attribute type";
    case GeneratorKind::Attr:
        return "an attribute";
    }
    return "a generator";
}

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

bool is_literal(const Expr& e) {
    return e.kind == Expr::Kind::Int || e.kind == Expr::Kind::Float ||
           e.kind == Expr::Kind::String || e.kind == Expr::Kind::Bool;
}

ValueKind literal_kind(const Expr& e) {
    switch (e.kind) {
    case Expr::Kind::Int:
        return ValueKind::Int;
    case Expr::Kind::Float:
        return ValueKind::Float;
    case Expr::Kind::String:
        return ValueKind::String;
    case Expr::Kind::Bool:
        return ValueKind::Bool;
    default:
        return ValueKind::Unknown;
    }
}

// The names on the left of `x::T` or `(x, y)::T`; reports anything else.
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

// ---- loading ------------------------------------------------------------------------------------

class Loader {
public:
    Loader(SourceManager& sources, DiagnosticSink& sink, const LoadOptions& options)
        : sources_(sources), sink_(sink), options_(options) {}

    void load_root_file(const std::string& path) {
        auto file = sources_.add_file(path);
        if (!file) {
            sink_.error(fmt::format("cannot read file '{}'", path));
            return;
        }
        load_buffer(*file, canonical(path), false);
    }

    void load_root_source(std::uint32_t file) {
        load_buffer(file, canonical(std::string(sources_.name(file))), false);
    }

    Module take() { return std::move(module_); }

private:
    static std::string canonical(const std::string& path) {
        std::error_code ec;
        auto p = std::filesystem::weakly_canonical(path, ec);
        return ec ? path : p.string();
    }

    void load_buffer(std::uint32_t file, const std::string& key, bool imported) {
        stack_.push_back(key);
        loaded_.insert(key);
        ParsedFile parsed = parse(sources_, file, sink_);
        for (const auto& form : parsed.forms) {
            if (form.name == "import") {
                import(form, file);
            }
        }
        elaborate_file(parsed, imported);
        stack_.pop_back();
    }

    void import(const MacroCall& form, std::uint32_t file) {
        if (form.header.size() != 1 || form.header[0].kind != Expr::Kind::String || form.has_body ||
            !form.assigned.empty()) {
            sink_.error(form.range, "expected @import \"path/to/file.cp\"");
            return;
        }
        const Expr& arg = form.header[0];
        std::filesystem::path base = std::filesystem::path(sources_.name(file)).parent_path();
        std::string path = (base / arg.text).lexically_normal().string();
        std::string key = canonical(path);
        for (std::size_t i = 0; i < stack_.size(); ++i) {
            if (stack_[i] == key) {
                std::string chain;
                for (std::size_t j = i; j < stack_.size(); ++j) {
                    chain += std::filesystem::path(stack_[j]).filename().string() + " -> ";
                }
                sink_.error(arg.range, fmt::format("import cycle: {}{}", chain,
                                                   std::filesystem::path(key).filename().string()));
                return;
            }
        }
        if (loaded_.count(key)) {
            return; // already loaded through another import
        }
        auto imported = sources_.add_file(path);
        if (!imported) {
            sink_.error(arg.range, fmt::format("cannot read imported file '{}'", path));
            return;
        }
        load_buffer(*imported, key, true);
    }

    // A name must be new in the whole module (all files); reports and returns false otherwise.
    bool claim_name(const std::string& name, SourceRange range) {
        auto it = names_.find(name);
        if (it != names_.end()) {
            auto& d = sink_.error(range, fmt::format("'{}' is already declared", name));
            d.notes.emplace_back(it->second, "first declared here");
            return false;
        }
        names_.emplace(name, range);
        return true;
    }

    void elaborate_file(const ParsedFile& parsed, bool imported) {
        // Schemas first, then kinds are inferred from every literal of the file, then instances:
        // so the order of declarations in a file does not change the meaning.
        std::vector<const MacroCall*> instances;
        for (const auto& form : parsed.forms) {
            if (form.name == "import") {
                continue;
            }
            if (form.name == "present") {
                elaborate_schema(form, imported);
            } else if (form.name == "acset_colim" || form.name == "acset") {
                instances.push_back(&form);
            } else {
                sink_.error(form.name_range,
                            fmt::format("unknown macro '@{}' (expected @present, @acset_colim, "
                                        "@acset or @import)",
                                        form.name));
            }
        }

        struct Pending {
            const MacroCall* form;
            std::string name;
            SourceRange name_range;
            std::shared_ptr<Schema> schema;
        };

        std::vector<Pending> pending;
        file_instances_.clear();
        for (const auto* form : instances) {
            if (!form->assigned.empty()) {
                file_instances_.insert(form->assigned);
            } else if (form->header.size() == 1 && form->header[0].kind == Expr::Kind::Call) {
                file_instances_.insert(form->header[0].text);
            }
        }
        for (const auto* form : instances) {
            Pending p{form, {}, {}, nullptr};
            if (resolve_instance_header(*form, p.name, p.name_range, p.schema)) {
                pending.push_back(std::move(p));
            }
        }
        for (const auto& p : pending) {
            infer_kinds(*p.form, *p.schema);
        }
        for (auto& [schema, inferred] : inferred_) {
            for (auto& [t, info] : inferred) {
                if (info.local && schema->attr_type(AttrTypeId(t)).kind == ValueKind::Unknown) {
                    schema->set_kind(AttrTypeId(t), info.kind);
                }
            }
        }
        for (const auto& p : pending) {
            std::optional<ACSet> x;
            if (p.form->name == "acset_colim") {
                x = build_colimit(*p.form, p.schema, p.name_range);
            } else {
                x = build_literal(*p.form, p.schema);
            }
            if (x && !broken_.count(p.schema.get()) && claim_name(p.name, p.name_range)) {
                Declaration d;
                d.kind = DeclKind::Instance;
                d.name = p.name;
                d.range = p.name_range;
                d.imported = imported;
                d.schema = p.schema;
                d.instance = std::make_shared<const ACSet>(std::move(*x));
                module_.add(std::move(d));
            }
        }
        local_schemas_.clear();
    }

    // ---- schemas --------------------------------------------------------------------------------

    std::shared_ptr<Schema> lookup_schema(const Expr& name_expr, bool allow_yoneda) {
        std::string name = name_expr.text;
        auto it = schemas_.find(name);
        if (it == schemas_.end() && allow_yoneda && name.size() > 1 && name[0] == 'y') {
            // Catlab users write the representable-functor form yColorBlocksworld.
            it = schemas_.find(name.substr(1));
        }
        if (it != schemas_.end()) {
            return it->second;
        }
        if (module_.find(name) != nullptr || file_instances_.count(name)) {
            sink_.error(name_expr.range, fmt::format("'{}' is an instance, not a schema", name));
        } else {
            sink_.error(name_expr.range, fmt::format("unknown schema '{}'", name));
        }
        return nullptr;
    }

    void elaborate_schema(const MacroCall& form, bool imported) {
        const Expr* name = nullptr;
        std::vector<const Expr*> bases;
        bool ok = true;
        if (form.header.size() == 1) {
            const Expr& h = form.header[0];
            if (h.kind == Expr::Kind::Call && h.args.size() == 1 &&
                h.args[0].kind == Expr::Kind::Name) {
                name = &h;
                if (h.args[0].text != "FreeSchema") {
                    sink_.error(
                        h.args[0].range,
                        fmt::format("unknown theory '{}' (expected FreeSchema)", h.args[0].text));
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
            sink_.error(form.range, "expected '@present Name(FreeSchema) begin ... end' or "
                                    "'@present Name <: Base begin ... end'");
            return;
        }
        SourceRange name_range = name->kind == Expr::Kind::Call ? name->name_range : name->range;
        auto s = std::make_shared<Schema>(name->text);
        for (const Expr* b : bases) {
            if (b->kind != Expr::Kind::Name) {
                sink_.error(b->range, "expected a schema name");
                ok = false;
                continue;
            }
            auto base = lookup_schema(*b, false);
            if (!base) {
                ok = false;
                continue;
            }
            inherit(*s, *base, b->range);
        }
        std::size_t errors = sink_.num_errors();
        for (const auto& st : form.body) {
            schema_statement(*s, st);
        }
        if (!ok || !claim_name(s->name(), name_range)) {
            return;
        }
        // A schema with errors stays visible, so its instances are still checked, but neither
        // it nor they enter the module.
        schemas_[s->name()] = s;
        local_schemas_.insert(s.get());
        if (sink_.num_errors() != errors) {
            broken_.insert(s.get());
            return;
        }
        Declaration d;
        d.kind = DeclKind::Schema;
        d.name = s->name();
        d.range = name_range;
        d.imported = imported;
        d.schema = s;
        module_.add(std::move(d));
    }

    // Copies the base's generators (flattening); a name already present is skipped when it has
    // the same meaning (diamond inheritance) and reported otherwise.
    void inherit(Schema& s, const Schema& base, SourceRange at) {
        auto clash = [&](const std::string& n) {
            auto g = s.find(n);
            if (g) {
                sink_.error(at, fmt::format("'{}' is declared by two base schemas", n));
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

    bool check_new_generator(const Schema& s, const Expr& name) {
        if (auto g = s.find(name.text)) {
            auto& d = sink_.error(name.range, fmt::format("duplicate generator '{}'", name.text));
            d.notes.emplace_back(generator_range(s, *g), "first declared here");
            return false;
        }
        return true;
    }

    std::optional<ObId> object_arg(const Schema& s, const Expr& e) {
        if (e.kind == Expr::Kind::Name) {
            if (auto x = s.find_ob(e.text)) {
                return x;
            }
            if (auto g = s.find(e.text)) {
                sink_.error(e.range,
                            fmt::format("'{}' is {}, not an object", e.text, kind_noun(g->kind)));
                return std::nullopt;
            }
        }
        sink_.error(e.range, fmt::format("unknown object '{}'", to_string(e)));
        return std::nullopt;
    }

    std::optional<AttrTypeId> attr_type_arg(const Schema& s, const Expr& e) {
        if (e.kind == Expr::Kind::Name) {
            if (auto t = s.find_attr_type(e.text)) {
                return t;
            }
            if (auto g = s.find(e.text)) {
                sink_.error(e.range, fmt::format("'{}' is {}, not an attribute type", e.text,
                                                 kind_noun(g->kind)));
                return std::nullopt;
            }
        }
        sink_.error(e.range, fmt::format("unknown attribute type '{}'", to_string(e)));
        return std::nullopt;
    }

    bool check_arity(const Expr& call, std::size_t n) {
        if (call.args.size() != n) {
            sink_.error(call.range, fmt::format("'{}' takes {} argument{}, found {}", call.text, n,
                                                n == 1 ? "" : "s", call.args.size()));
            return false;
        }
        return true;
    }

    void schema_statement(Schema& s, const Expr& st) {
        if (st.is_binary("==")) {
            equation(s, st);
            return;
        }
        if (!st.is_binary("::")) {
            sink_.error(st.range, fmt::format("expected a generator (X::Ob, f::Hom(A, B), "
                                              "T::AttrType, a::Attr(A, T)) or an equation, "
                                              "found '{}'",
                                              to_string(st)));
            return;
        }
        const Expr& type = st.args[1];
        auto names = declared_names(st.args[0], sink_);
        std::string head = type.text;
        if (type.kind == Expr::Kind::Name && head == "Ob") {
            for (const Expr* n : names) {
                if (check_new_generator(s, *n)) {
                    s.add_ob(n->text, n->range);
                }
            }
        } else if ((type.kind == Expr::Kind::Name || type.kind == Expr::Kind::Call) &&
                   head == "AttrType") {
            ValueKind kind = ValueKind::Unknown;
            if (type.kind == Expr::Kind::Call) {
                if (!check_arity(type, 1)) {
                    return;
                }
                auto k = type.args[0].kind == Expr::Kind::Name
                             ? schema::parse_value_kind(type.args[0].text)
                             : std::nullopt;
                if (!k) {
                    sink_.error(type.args[0].range,
                                fmt::format("unknown value kind '{}' (expected Bool, Int, Int64, "
                                            "Float, Float64, String or Symbol)",
                                            to_string(type.args[0])));
                    return;
                }
                kind = *k;
            }
            for (const Expr* n : names) {
                if (check_new_generator(s, *n)) {
                    s.add_attr_type(n->text, kind, n->range);
                }
            }
        } else if (type.kind == Expr::Kind::Call && head == "Hom") {
            if (!check_arity(type, 2)) {
                return;
            }
            auto dom = object_arg(s, type.args[0]);
            auto codom = object_arg(s, type.args[1]);
            for (const Expr* n : names) {
                if (check_new_generator(s, *n) && dom && codom) {
                    s.add_hom(n->text, *dom, *codom, n->range);
                }
            }
        } else if (type.kind == Expr::Kind::Call && head == "Attr") {
            if (!check_arity(type, 2)) {
                return;
            }
            auto dom = object_arg(s, type.args[0]);
            auto codom = attr_type_arg(s, type.args[1]);
            for (const Expr* n : names) {
                if (check_new_generator(s, *n) && dom && codom) {
                    s.add_attr(n->text, *dom, *codom, n->range);
                }
            }
        } else {
            sink_.error(type.range, fmt::format("unknown generator type '{}' (expected Ob, "
                                                "Hom(A, B), AttrType or Attr(A, T))",
                                                to_string(type)));
        }
    }

    // A path and whether it is still open (no attribute yet).
    std::optional<Path> path(const Schema& s, const Expr& e) {
        if (e.kind == Expr::Kind::Name) {
            if (auto f = s.find_hom(e.text)) {
                return Path{s.hom(*f).dom, {*f}, std::nullopt};
            }
            if (auto a = s.find_attr(e.text)) {
                return Path{s.attr(*a).dom, {}, *a};
            }
            if (auto g = s.find(e.text)) {
                sink_.error(e.range, fmt::format("'{}' is {}, not a hom or attribute", e.text,
                                                 kind_noun(g->kind)));
            } else {
                sink_.error(e.range, fmt::format("unknown hom or attribute '{}'", e.text));
            }
            return std::nullopt;
        }
        if (e.kind == Expr::Kind::Call && e.text == "id") {
            if (!check_arity(e, 1)) {
                return std::nullopt;
            }
            auto x = object_arg(s, e.args[0]);
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
            sink_.error(e.range, fmt::format("expected a path (f, compose(f, g), f ⋅ g or id(X)), "
                                             "found '{}'",
                                             to_string(e)));
            return std::nullopt;
        }
        std::optional<Path> acc;
        for (const Expr* part : parts) {
            auto p = path(s, *part);
            if (!p) {
                return std::nullopt;
            }
            if (!acc) {
                acc = std::move(p);
                continue;
            }
            if (acc->attr) {
                sink_.error(part->range,
                            fmt::format("cannot compose after attribute '{}': an attribute ends "
                                        "a path",
                                        s.attr(*acc->attr).name));
                return std::nullopt;
            }
            ObId end = s.path_codom_ob(*acc);
            if (end != p->dom) {
                sink_.error(part->range,
                            fmt::format("cannot compose: '{}' ends at {} but '{}' starts at {}",
                                        s.path_to_string(*acc), s.ob(end).name,
                                        s.path_to_string(*p), s.ob(p->dom).name));
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

    void equation(Schema& s, const Expr& st) {
        auto lhs = path(s, st.args[0]);
        auto rhs = path(s, st.args[1]);
        if (!lhs || !rhs) {
            return;
        }
        std::string lend = path_end(s, *lhs), rend = path_end(s, *rhs);
        if (lhs->dom != rhs->dom || lhs->attr.has_value() != rhs->attr.has_value() ||
            lend != rend) {
            sink_.error(st.range,
                        fmt::format("the sides of the equation have different ends: {} : {} → {} "
                                    "but {} : {} → {}",
                                    s.path_to_string(*lhs), s.ob(lhs->dom).name, lend,
                                    s.path_to_string(*rhs), s.ob(rhs->dom).name, rend));
            return;
        }
        s.add_equation({"", std::move(*lhs), std::move(*rhs), st.range});
    }

    // ---- instances: headers and kinds
    // ------------------------------------------------------------

    bool resolve_instance_header(const MacroCall& form, std::string& name, SourceRange& range,
                                 std::shared_ptr<Schema>& schema) {
        const Expr* schema_name = nullptr;
        if (!form.assigned.empty()) {
            name = form.assigned;
            range = form.assigned_range;
            if (form.header.size() == 1 && form.header[0].kind == Expr::Kind::Name) {
                schema_name = &form.header[0];
            }
        } else if (form.header.size() == 1 && form.header[0].kind == Expr::Kind::Call &&
                   form.header[0].args.size() == 1 &&
                   form.header[0].args[0].kind == Expr::Kind::Name) {
            name = form.header[0].text;
            range = form.header[0].name_range;
            schema_name = &form.header[0].args[0];
        }
        if (schema_name == nullptr || !form.has_body) {
            sink_.error(form.range, fmt::format("expected '@{0} Name(Schema) begin ... end' or "
                                                "'Name = @{0} Schema begin ... end'",
                                                form.name));
            return false;
        }
        schema = lookup_schema(*schema_name, true);
        return schema != nullptr;
    }

    struct Inferred {
        ValueKind kind;
        SourceRange range;
        bool local;
    };

    void infer(const Schema& s, AttrTypeId t, const Expr& lit) {
        if (s.attr_type(t).kind != ValueKind::Unknown) {
            return;
        }
        auto& table = inferred_[const_cast<Schema*>(&s)];
        auto it = table.find(t.index());
        ValueKind k = literal_kind(lit);
        if (it == table.end()) {
            table.emplace(t.index(), Inferred{k, lit.range, local_schemas_.count(&s) > 0});
        } else if (it->second.kind == ValueKind::Int && k == ValueKind::Float) {
            it->second.kind = ValueKind::Float; // an Int literal is also a Float
        }
    }

    // Records the kind each literal suggests for its attribute type (the first one wins, except
    // that a later Float widens an Int).
    void infer_kinds(const MacroCall& form, const Schema& s) {
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
        std::unordered_map<std::string, AttrTypeId> var_types;
        for (const auto& st : form.body) {
            if (st.is_binary("::") && st.args[1].kind == Expr::Kind::Name) {
                if (auto t = s.find_attr_type(st.args[1].text)) {
                    DiagnosticSink quiet(sources_);
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
        for (const auto& st : form.body) {
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

    // The literal as a value of type t, or a located error naming both kinds.
    std::optional<Value> literal_value(const Schema& s, AttrTypeId t, const Expr& lit) {
        const auto& info = s.attr_type(t);
        ValueKind k = literal_kind(lit);
        if (info.kind == ValueKind::Unknown) {
            sink_.error(lit.range, fmt::format("attribute type '{}' has no value kind; declare "
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
        auto& d = sink_.error(lit.range, fmt::format("expected a {} value for '{}', found {} "
                                                     "literal {}",
                                                     schema::to_string(info.kind), info.name,
                                                     schema::to_string(k), to_string(lit)));
        auto sit = inferred_.find(const_cast<Schema*>(&s));
        if (sit != inferred_.end()) {
            auto it = sit->second.find(t.index());
            if (it != sit->second.end()) {
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

    // ---- instances: presentations (@acset_colim) ------------------------------------------------

    struct PartNode {
        ObId ob;
        std::vector<std::uint32_t> homs;  // by position in homs_from(ob); kNone if undefined
        std::vector<std::uint32_t> attrs; // value nodes, by position in attrs_from(ob)
    };

    struct ValueNode {
        AttrTypeId type;
        std::optional<Value> literal;
        SourceRange literal_range;
    };

    static constexpr std::uint32_t kNone = UINT32_MAX;

    struct Term {
        enum class Kind { Part, Value, Literal } kind;
        std::uint32_t node = 0;
        const Expr* expr = nullptr;
    };

    class Colimit {
    public:
        Colimit(Loader& loader, const Schema& s) : l_(loader), s_(s) {
            for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
                auto homs = s.homs_from(ObId(o));
                for (std::uint32_t i = 0; i < homs.size(); ++i) {
                    hom_slot_[homs[i].index()] = i;
                }
                auto attrs = s.attrs_from(ObId(o));
                for (std::uint32_t i = 0; i < attrs.size(); ++i) {
                    attr_slot_[attrs[i].index()] = i;
                }
            }
        }

        std::uint32_t new_part(ObId x, std::string name) {
            PartNode n{x, std::vector<std::uint32_t>(s_.homs_from(x).size(), kNone),
                       std::vector<std::uint32_t>(s_.attrs_from(x).size(), kNone)};
            parts_.push_back(std::move(n));
            part_names_.push_back(std::move(name));
            return parts_uf_.make_set();
        }

        std::uint32_t new_value(AttrTypeId t, std::string name) {
            values_.push_back({t, std::nullopt, {}});
            value_names_.push_back(std::move(name));
            return values_uf_.make_set();
        }

        void declare(const Expr& st) {
            const Expr& type = st.args[1];
            auto names = declared_names(st.args[0], l_.sink_);
            std::optional<ObId> ob;
            std::optional<AttrTypeId> t;
            if (type.kind == Expr::Kind::Name) {
                ob = s_.find_ob(type.text);
                t = s_.find_attr_type(type.text);
            }
            if (!ob && !t) {
                l_.sink_.error(type.range,
                               fmt::format("unknown object or attribute type '{}' in schema '{}'",
                                           to_string(type), s_.name()));
                return;
            }
            for (const Expr* n : names) {
                auto it = gens_.find(n->text);
                if (it != gens_.end()) {
                    auto& d =
                        l_.sink_.error(n->range, fmt::format("duplicate generator '{}'", n->text));
                    d.notes.emplace_back(it->second.range, "first declared here");
                    continue;
                }
                Term term = ob ? Term{Term::Kind::Part, new_part(*ob, n->text), nullptr}
                               : Term{Term::Kind::Value, new_value(*t, n->text), nullptr};
                gens_.emplace(n->text, Gen{term, n->range});
            }
        }

        std::string describe(const Term& t) {
            switch (t.kind) {
            case Term::Kind::Part:
                return fmt::format("a part of {}", s_.ob(parts_[t.node].ob).name);
            case Term::Kind::Value:
                return fmt::format("a value of {}", s_.attr_type(values_[t.node].type).name);
            case Term::Kind::Literal:
                return "a literal";
            }
            return "?";
        }

        std::optional<Term> eval(const Expr& e) {
            if (is_literal(e)) {
                return Term{Term::Kind::Literal, 0, &e};
            }
            if (e.kind == Expr::Kind::Name) {
                auto it = gens_.find(e.text);
                if (it == gens_.end()) {
                    l_.sink_.error(e.range, fmt::format("unknown generator '{}'", e.text));
                    return std::nullopt;
                }
                Term t = it->second.term;
                t.node =
                    t.kind == Term::Kind::Part ? parts_uf_.find(t.node) : values_uf_.find(t.node);
                return t;
            }
            if (e.kind != Expr::Kind::Call) {
                l_.sink_.error(e.range, fmt::format("expected a generator, a hom or attribute "
                                                    "applied to a term, or a literal; found '{}'",
                                                    to_string(e)));
                return std::nullopt;
            }
            auto hom = s_.find_hom(e.text);
            auto attr = s_.find_attr(e.text);
            if (!hom && !attr) {
                auto g = s_.find(e.text);
                l_.sink_.error(e.name_range,
                               g ? fmt::format("'{}' is {}, not a hom or attribute", e.text,
                                               kind_noun(g->kind))
                                 : fmt::format("unknown hom or attribute '{}' in schema '{}'",
                                               e.text, s_.name()));
                return std::nullopt;
            }
            if (!l_.check_arity(e, 1)) {
                return std::nullopt;
            }
            auto arg = eval(e.args[0]);
            if (!arg) {
                return std::nullopt;
            }
            ObId dom = hom ? s_.hom(*hom).dom : s_.attr(*attr).dom;
            if (arg->kind != Term::Kind::Part || parts_[arg->node].ob != dom) {
                l_.sink_.error(e.args[0].range,
                               fmt::format("'{}' expects a part of {}, but '{}' is {}", e.text,
                                           s_.ob(dom).name, to_string(e.args[0]), describe(*arg)));
                return std::nullopt;
            }
            std::uint32_t p = arg->node;
            if (hom) {
                std::uint32_t slot = hom_slot_[hom->index()];
                if (parts_[p].homs[slot] == kNone) {
                    std::uint32_t q = new_part(s_.hom(*hom).codom, "");
                    parts_[p].homs[slot] = q;
                }
                return Term{Term::Kind::Part, parts_uf_.find(parts_[p].homs[slot]), nullptr};
            }
            std::uint32_t slot = attr_slot_[attr->index()];
            if (parts_[p].attrs[slot] == kNone) {
                std::uint32_t v = new_value(s_.attr(*attr).codom, "");
                parts_[p].attrs[slot] = v;
            }
            return Term{Term::Kind::Value, values_uf_.find(parts_[p].attrs[slot]), nullptr};
        }

        void equation(const Expr& st) {
            auto lhs = eval(st.args[0]);
            auto rhs = eval(st.args[1]);
            if (!lhs || !rhs) {
                return;
            }
            if (lhs->kind == Term::Kind::Literal) {
                std::swap(lhs, rhs);
            }
            if (lhs->kind == Term::Kind::Literal) {
                l_.sink_.error(st.range, "an equation between two literals says nothing about "
                                         "the instance");
                return;
            }
            if (rhs->kind == Term::Kind::Literal) {
                if (lhs->kind != Term::Kind::Value) {
                    l_.sink_.error(st.range, fmt::format("cannot equate {} with literal {}",
                                                         describe(*lhs), to_string(*rhs->expr)));
                    return;
                }
                auto v = l_.literal_value(s_, values_[lhs->node].type, *rhs->expr);
                if (v) {
                    set_literal(lhs->node, *v, rhs->expr->range, st.range);
                }
                return;
            }
            bool same = lhs->kind == rhs->kind &&
                        (lhs->kind == Term::Kind::Part
                             ? parts_[lhs->node].ob == parts_[rhs->node].ob
                             : values_[lhs->node].type == values_[rhs->node].type);
            if (!same) {
                l_.sink_.error(st.range, fmt::format("cannot equate {} ('{}') with {} ('{}')",
                                                     describe(*lhs), to_string(st.args[0]),
                                                     describe(*rhs), to_string(st.args[1])));
                return;
            }
            if (lhs->kind == Term::Kind::Part) {
                pending_parts_.emplace_back(lhs->node, rhs->node);
            } else {
                pending_values_.emplace_back(lhs->node, rhs->node);
            }
            close(st.range);
        }

        void set_literal(std::uint32_t v, Value value, SourceRange lit, SourceRange at) {
            auto& node = values_[values_uf_.find(v)];
            if (node.literal) {
                if (!(*node.literal == value)) {
                    auto& d = l_.sink_.error(at, fmt::format("conflicting values {} and {} for "
                                                             "one cell",
                                                             node.literal->to_string(),
                                                             value.to_string()));
                    d.notes.emplace_back(node.literal_range, "the first value is given here");
                }
                return;
            }
            node.literal = value;
            node.literal_range = lit;
        }

        // Congruence closure: merging parts merges their images under every hom and attribute.
        void close(SourceRange at) {
            while (!pending_parts_.empty() || !pending_values_.empty()) {
                if (!pending_values_.empty()) {
                    auto [a, b] = pending_values_.back();
                    pending_values_.pop_back();
                    a = values_uf_.find(a);
                    b = values_uf_.find(b);
                    if (a == b) {
                        continue;
                    }
                    values_uf_.union_sets(a, b);
                    std::uint32_t r = std::min(a, b), o = std::max(a, b);
                    if (values_[o].literal) {
                        set_literal(r, *values_[o].literal, values_[o].literal_range, at);
                    }
                    continue;
                }
                auto [a, b] = pending_parts_.back();
                pending_parts_.pop_back();
                a = parts_uf_.find(a);
                b = parts_uf_.find(b);
                if (a == b) {
                    continue;
                }
                parts_uf_.union_sets(a, b);
                std::uint32_t r = std::min(a, b), o = std::max(a, b);
                for (std::size_t i = 0; i < parts_[r].homs.size(); ++i) {
                    if (parts_[o].homs[i] == kNone) {
                        continue;
                    }
                    if (parts_[r].homs[i] == kNone) {
                        parts_[r].homs[i] = parts_[o].homs[i];
                    } else {
                        pending_parts_.emplace_back(parts_[r].homs[i], parts_[o].homs[i]);
                    }
                }
                for (std::size_t i = 0; i < parts_[r].attrs.size(); ++i) {
                    if (parts_[o].attrs[i] == kNone) {
                        continue;
                    }
                    if (parts_[r].attrs[i] == kNone) {
                        parts_[r].attrs[i] = parts_[o].attrs[i];
                    } else {
                        pending_values_.emplace_back(parts_[r].attrs[i], parts_[o].attrs[i]);
                    }
                }
            }
        }

        // Gives every undefined hom a new part and every undefined attribute a new variable.
        bool complete(SourceRange at, std::size_t max_fresh) {
            std::size_t fresh = 0;
            for (std::uint32_t p = 0; p < parts_.size(); ++p) {
                if (parts_uf_.find(p) != p) {
                    continue;
                }
                ObId ob = parts_[p].ob;
                auto homs = s_.homs_from(ob);
                for (std::size_t i = 0; i < homs.size(); ++i) {
                    if (parts_[p].homs[i] != kNone) {
                        continue;
                    }
                    if (++fresh > max_fresh) {
                        const auto& h = s_.hom(homs[i]);
                        auto& d = l_.sink_.error(
                            at, fmt::format("the free instance is infinite or too large: hom "
                                            "'{}' keeps generating new parts of {} (stopped "
                                            "after {} new parts)",
                                            h.name, s_.ob(h.codom).name, max_fresh));
                        if (h.range.valid()) {
                            d.notes.emplace_back(h.range, fmt::format("'{}' is declared here; "
                                                                      "give its values with "
                                                                      "equations",
                                                                      h.name));
                        }
                        return false;
                    }
                    std::uint32_t q = new_part(s_.hom(homs[i]).codom, "");
                    parts_[p].homs[i] = q;
                }
                auto attrs = s_.attrs_from(ob);
                for (std::size_t i = 0; i < attrs.size(); ++i) {
                    if (parts_[p].attrs[i] == kNone) {
                        std::uint32_t v = new_value(s_.attr(attrs[i]).codom, "");
                        parts_[p].attrs[i] = v;
                    }
                }
            }
            return true;
        }

        ACSet build(std::shared_ptr<Schema> schema) {
            ACSet x(schema);
            std::vector<Part> part_of(parts_.size(), kNoPart);
            for (std::uint32_t p = 0; p < parts_.size(); ++p) {
                if (parts_uf_.find(p) == p) {
                    part_of[p] = x.add_part(parts_[p].ob, part_names_[p]);
                }
            }
            std::vector<Value> value_of(values_.size());
            for (std::uint32_t v = 0; v < values_.size(); ++v) {
                if (values_uf_.find(v) == v) {
                    value_of[v] = values_[v].literal ? *values_[v].literal
                                                     : x.add_var(values_[v].type, value_names_[v]);
                }
            }
            for (std::uint32_t p = 0; p < parts_.size(); ++p) {
                if (parts_uf_.find(p) != p) {
                    continue;
                }
                ObId ob = parts_[p].ob;
                auto homs = s_.homs_from(ob);
                for (std::size_t i = 0; i < homs.size(); ++i) {
                    x.set_subpart(homs[i], part_of[p], part_of[parts_uf_.find(parts_[p].homs[i])]);
                }
                auto attrs = s_.attrs_from(ob);
                for (std::size_t i = 0; i < attrs.size(); ++i) {
                    x.set_subpart(attrs[i], part_of[p],
                                  value_of[values_uf_.find(parts_[p].attrs[i])]);
                }
            }
            return x;
        }

    private:
        struct Gen {
            Term term;
            SourceRange range;
        };

        Loader& l_;
        const Schema& s_;
        std::unordered_map<std::uint32_t, std::uint32_t> hom_slot_, attr_slot_;
        std::vector<PartNode> parts_;
        std::vector<std::string> part_names_;
        std::vector<ValueNode> values_;
        std::vector<std::string> value_names_;
        UnionFind parts_uf_, values_uf_;
        std::unordered_map<std::string, Gen> gens_;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> pending_parts_, pending_values_;
    };

    std::optional<ACSet> build_colimit(const MacroCall& form, const std::shared_ptr<Schema>& s,
                                       SourceRange name_range) {
        std::size_t errors = sink_.num_errors();
        Colimit c(*this, *s);
        // Generators first, wherever they are written, so that they come first in part order.
        for (const auto& st : form.body) {
            if (st.is_binary("::")) {
                c.declare(st);
            }
        }
        for (const auto& st : form.body) {
            if (st.is_binary("::")) {
                continue;
            }
            if (st.is_binary("==")) {
                c.equation(st);
            } else {
                sink_.error(st.range, fmt::format("expected a generator (x::Block) or an "
                                                  "equation (f(x) == y), found '{}'",
                                                  to_string(st)));
            }
        }
        if (sink_.num_errors() != errors || !c.complete(name_range, options_.max_fresh_parts)) {
            return std::nullopt;
        }
        return c.build(s);
    }

    // ---- instances: literal tables (@acset)
    // ------------------------------------------------------

    std::optional<ACSet> build_literal(const MacroCall& form, const std::shared_ptr<Schema>& s) {
        std::size_t errors = sink_.num_errors();
        ACSet x(s);
        std::map<std::string, SourceRange> seen;
        std::vector<const Expr*> columns;
        for (const auto& st : form.body) {
            if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Name) {
                sink_.error(st.range, fmt::format("expected 'Name = value' (an object count, a "
                                                  "column, or a number of variables), found '{}'",
                                                  to_string(st)));
                continue;
            }
            const Expr& lhs = st.args[0];
            const Expr& rhs = st.args[1];
            auto [it, fresh] = seen.emplace(lhs.text, lhs.range);
            if (!fresh) {
                auto& d = sink_.error(lhs.range, fmt::format("'{}' is given twice", lhs.text));
                d.notes.emplace_back(it->second, "first given here");
                continue;
            }
            auto g = s->find(lhs.text);
            if (!g) {
                sink_.error(lhs.range,
                            fmt::format("unknown name '{}' in schema '{}'", lhs.text, s->name()));
                continue;
            }
            if (g->kind == GeneratorKind::Ob || g->kind == GeneratorKind::AttrType) {
                if (rhs.kind != Expr::Kind::Int || rhs.int_value < 0) {
                    sink_.error(rhs.range, fmt::format("expected a count (an integer ≥ 0) for "
                                                       "'{}', found '{}'",
                                                       lhs.text, to_string(rhs)));
                    continue;
                }
                if (g->kind == GeneratorKind::Ob) {
                    x.add_parts(ObId(g->index), static_cast<std::size_t>(rhs.int_value));
                } else {
                    for (std::int64_t i = 0; i < rhs.int_value; ++i) {
                        x.add_var(AttrTypeId(g->index));
                    }
                }
            } else {
                columns.push_back(&st);
            }
        }
        for (const Expr* st : columns) {
            const Expr& lhs = st->args[0];
            const Expr& rhs = st->args[1];
            auto hom = s->find_hom(lhs.text);
            auto attr = s->find_attr(lhs.text);
            ObId dom = hom ? s->hom(*hom).dom : s->attr(*attr).dom;
            std::size_t n = x.num_parts(dom);
            std::vector<const Expr*> items;
            if (rhs.kind == Expr::Kind::Vector) {
                for (const auto& item : rhs.args) {
                    items.push_back(&item);
                }
                if (items.size() != n) {
                    sink_.error(rhs.range,
                                fmt::format("column '{}' has {} value{} but {} has {} "
                                            "part{}",
                                            lhs.text, items.size(), items.size() == 1 ? "" : "s",
                                            s->ob(dom).name, n, n == 1 ? "" : "s"));
                    continue;
                }
            } else {
                items.assign(n, &rhs); // a scalar is broadcast to the whole column
            }
            for (Part p = 0; p < n; ++p) {
                const Expr& item = *items[p];
                if (hom) {
                    ObId codom = s->hom(*hom).codom;
                    std::size_t m = x.num_parts(codom);
                    if (item.kind != Expr::Kind::Int || item.int_value < 0 ||
                        static_cast<std::uint64_t>(item.int_value) > m) {
                        sink_.error(item.range,
                                    fmt::format("'{}' must be a part of {} (1 to {}, or 0 for "
                                                "unset), found '{}'",
                                                lhs.text, s->ob(codom).name, m, to_string(item)));
                        if (&item == &rhs) {
                            break;
                        }
                        continue;
                    }
                    x.set_subpart(*hom, p,
                                  item.int_value == 0 ? kNoPart
                                                      : static_cast<Part>(item.int_value - 1));
                    continue;
                }
                AttrTypeId t = s->attr(*attr).codom;
                if (item.kind == Expr::Kind::Call && item.text == "AttrVar") {
                    std::size_t k = x.num_vars(t);
                    if (item.args.size() != 1 || item.args[0].kind != Expr::Kind::Int ||
                        item.args[0].int_value < 1 ||
                        static_cast<std::uint64_t>(item.args[0].int_value) > k) {
                        sink_.error(item.range,
                                    fmt::format("AttrVar needs one index from 1 to {} (the "
                                                "number of variables of {}), found '{}'",
                                                k, s->attr_type(t).name, to_string(item)));
                        if (&item == &rhs) {
                            break;
                        }
                        continue;
                    }
                    x.set_subpart(
                        *attr, p,
                        Value::var(static_cast<std::uint32_t>(item.args[0].int_value - 1)));
                    continue;
                }
                if (!is_literal(item)) {
                    sink_.error(item.range, fmt::format("expected a literal or AttrVar(n) for "
                                                        "'{}', found '{}'",
                                                        lhs.text, to_string(item)));
                    continue;
                }
                auto v = literal_value(*s, t, item);
                if (!v) {
                    if (&item == &rhs) {
                        break;
                    }
                    continue;
                }
                x.set_subpart(*attr, p, *v);
            }
        }
        if (sink_.num_errors() != errors) {
            return std::nullopt;
        }
        return x;
    }

    SourceManager& sources_;
    DiagnosticSink& sink_;
    LoadOptions options_;
    Module module_;
    std::vector<std::string> stack_;
    std::set<std::string> loaded_;
    std::unordered_map<std::string, SourceRange> names_;
    std::unordered_map<std::string, std::shared_ptr<Schema>> schemas_;
    std::set<const Schema*> local_schemas_;
    std::set<const Schema*> broken_;
    std::set<std::string> file_instances_;
    std::map<Schema*, std::map<std::uint32_t, Inferred>> inferred_;
};

} // namespace

Module load_file(const std::string& path, SourceManager& sources, DiagnosticSink& sink,
                 const LoadOptions& options) {
    Loader loader(sources, sink, options);
    loader.load_root_file(path);
    return loader.take();
}

Module load_source(std::string name, std::string text, SourceManager& sources, DiagnosticSink& sink,
                   const LoadOptions& options) {
    Loader loader(sources, sink, options);
    loader.load_root_source(sources.add_buffer(std::move(name), std::move(text)));
    return loader.take();
}

} // namespace catplan::lang
