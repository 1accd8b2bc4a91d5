#include "catplan/lang/module.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/base/union_find.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/lang/detail/map_elaboration.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/rewrite/rule.hpp"

#include <algorithm>
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
        : sources_(sources), sink_(&sink), options_(options) {}

    void load_root_file(const std::string& path) {
        auto file = sources_.add_file(path);
        if (!file) {
            sink_->error(fmt::format("cannot read file '{}'", path));
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
        ParsedFile parsed = parse(sources_, file, *sink_);
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
            sink_->error(form.range, "expected @import \"path/to/file.cp\"");
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
                sink_->error(arg.range,
                             fmt::format("import cycle: {}{}", chain,
                                         std::filesystem::path(key).filename().string()));
                return;
            }
        }
        if (loaded_.count(key)) {
            return; // already loaded through another import
        }
        auto imported = sources_.add_file(path);
        if (!imported) {
            sink_->error(arg.range, fmt::format("cannot read imported file '{}'", path));
            return;
        }
        load_buffer(*imported, key, true);
    }

    // A name must be new in the whole module (all files); reports and returns false otherwise.
    bool claim_name(const std::string& name, SourceRange range) {
        auto it = names_.find(name);
        if (it != names_.end()) {
            auto& d = sink_->error(range, fmt::format("'{}' is already declared", name));
            d.notes.emplace_back(it->second, "first declared here");
            return false;
        }
        names_.emplace(name, range);
        return true;
    }

    void elaborate_file(const ParsedFile& parsed, bool imported) {
        // Schemas first, then kinds are inferred from every literal of the file, then instances:
        // so the order of declarations in a file does not change the meaning.
        std::vector<const MacroCall*> instances, rules, domains, problems, maps, composites,
            migrations;
        for (const auto& form : parsed.forms) {
            if (form.name == "import") {
                continue;
            }
            if (form.name == "present") {
                elaborate_schema(form, imported);
            } else if (form.name == "acset_colim" || form.name == "acset") {
                instances.push_back(&form);
            } else if (form.name == "migration" && is_map_form(form)) {
                maps.push_back(&form);
            } else if (form.name == "rule" || form.name == "migration") {
                rules.push_back(&form);
            } else if (form.name == "compose") {
                composites.push_back(&form);
            } else if (form.name == "migrate") {
                migrations.push_back(&form);
            } else if (form.name == "domain") {
                domains.push_back(&form);
            } else if (form.name == "problem") {
                problems.push_back(&form);
            } else {
                sink_->error(form.name_range,
                             fmt::format("unknown macro '@{}' (expected @present, @acset_colim, "
                                         "@acset, @rule, @migration, @compose, @migrate, "
                                         "@domain, @problem or @import)",
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
        for (const auto* form : rules) {
            infer_rule_kinds(*form, nullptr);
        }
        for (const auto* form : domains) {
            infer_domain_kinds(*form);
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
        // Rules, domains and problems refer to schemas, instances and rules declared above.
        for (const auto* form : rules) {
            elaborate_top_rule(*form, imported);
        }
        for (const auto* form : domains) {
            elaborate_domain(*form, imported);
        }
        for (const auto* form : problems) {
            elaborate_problem(*form, imported);
        }
        // Maps refer to schemas only; composites to maps.
        for (const auto* form : maps) {
            elaborate_map(*form, imported);
        }
        for (const auto* form : composites) {
            elaborate_compose(*form, imported);
        }
        // Migrated instances refer to instances above and make instances.
        for (const auto* form : migrations) {
            elaborate_migrate(*form, imported);
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
            sink_->error(name_expr.range, fmt::format("'{}' is an instance, not a schema", name));
        } else {
            sink_->error(name_expr.range, fmt::format("unknown schema '{}'", name));
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
                    sink_->error(
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
            sink_->error(form.range, "expected '@present Name(FreeSchema) begin ... end' or "
                                     "'@present Name <: Base begin ... end'");
            return;
        }
        SourceRange name_range = name->kind == Expr::Kind::Call ? name->name_range : name->range;
        auto s = std::make_shared<Schema>(name->text);
        for (const Expr* b : bases) {
            if (b->kind != Expr::Kind::Name) {
                sink_->error(b->range, "expected a schema name");
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
        std::size_t errors = sink_->num_errors();
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
        if (sink_->num_errors() != errors) {
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
                sink_->error(at, fmt::format("'{}' is declared by two base schemas", n));
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
            auto& d = sink_->error(name.range, fmt::format("duplicate generator '{}'", name.text));
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
                sink_->error(e.range,
                             fmt::format("'{}' is {}, not an object", e.text, kind_noun(g->kind)));
                return std::nullopt;
            }
        }
        sink_->error(e.range, fmt::format("unknown object '{}'", to_string(e)));
        return std::nullopt;
    }

    std::optional<AttrTypeId> attr_type_arg(const Schema& s, const Expr& e) {
        if (e.kind == Expr::Kind::Name) {
            if (auto t = s.find_attr_type(e.text)) {
                return t;
            }
            if (auto g = s.find(e.text)) {
                sink_->error(e.range, fmt::format("'{}' is {}, not an attribute type", e.text,
                                                  kind_noun(g->kind)));
                return std::nullopt;
            }
        }
        sink_->error(e.range, fmt::format("unknown attribute type '{}'", to_string(e)));
        return std::nullopt;
    }

    bool check_arity(const Expr& call, std::size_t n) {
        if (call.args.size() != n) {
            sink_->error(call.range, fmt::format("'{}' takes {} argument{}, found {}", call.text, n,
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
            sink_->error(st.range, fmt::format("expected a generator (X::Ob, f::Hom(A, B), "
                                               "T::AttrType, a::Attr(A, T)) or an equation, "
                                               "found '{}'",
                                               to_string(st)));
            return;
        }
        const Expr& type = st.args[1];
        auto names = declared_names(st.args[0], *sink_);
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
                    sink_->error(type.args[0].range,
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
            sink_->error(type.range, fmt::format("unknown generator type '{}' (expected Ob, "
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
                sink_->error(e.range, fmt::format("'{}' is {}, not a hom or attribute", e.text,
                                                  kind_noun(g->kind)));
            } else {
                sink_->error(e.range, fmt::format("unknown hom or attribute '{}'", e.text));
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
            sink_->error(e.range, fmt::format("expected a path (f, compose(f, g), f ⋅ g or id(X)), "
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
                sink_->error(part->range,
                             fmt::format("cannot compose after attribute '{}': an attribute ends "
                                         "a path",
                                         s.attr(*acc->attr).name));
                return std::nullopt;
            }
            ObId end = s.path_codom_ob(*acc);
            if (end != p->dom) {
                sink_->error(part->range,
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
            sink_->error(st.range,
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
            sink_->error(form.range, fmt::format("expected '@{0} Name(Schema) begin ... end' or "
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
        infer_kinds_body(form.body, s);
    }

    // Kinds from the literals of `@acset_colim`-style statements (instances and rule blocks).
    void infer_kinds_body(const std::vector<Expr>& body, const Schema& s) {
        std::unordered_map<std::string, AttrTypeId> var_types;
        for (const auto& st : body) {
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

    // The literal as a value of type t, or a located error naming both kinds.
    std::optional<Value> literal_value(const Schema& s, AttrTypeId t, const Expr& lit) {
        const auto& info = s.attr_type(t);
        ValueKind k = literal_kind(lit);
        if (info.kind == ValueKind::Unknown) {
            sink_->error(lit.range, fmt::format("attribute type '{}' has no value kind; declare "
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
        auto& d = sink_->error(lit.range, fmt::format("expected a {} value for '{}', found {} "
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
            auto names = declared_names(st.args[0], *l_.sink_);
            std::optional<ObId> ob;
            std::optional<AttrTypeId> t;
            if (type.kind == Expr::Kind::Name) {
                ob = s_.find_ob(type.text);
                t = s_.find_attr_type(type.text);
            }
            if (!ob && !t) {
                l_.sink_->error(type.range,
                                fmt::format("unknown object or attribute type '{}' in schema '{}'",
                                            to_string(type), s_.name()));
                return;
            }
            for (const Expr* n : names) {
                auto it = gens_.find(n->text);
                if (it != gens_.end() && allow_redeclare_) {
                    // Rules: Keep's generators are declared again in Eff; same type, same part.
                    const Term& old = it->second.term;
                    bool same = ob ? old.kind == Term::Kind::Part && parts_[old.node].ob == *ob
                                   : old.kind == Term::Kind::Value && values_[old.node].type == *t;
                    if (same) {
                        continue;
                    }
                }
                if (it != gens_.end()) {
                    auto& d =
                        l_.sink_->error(n->range, fmt::format("duplicate generator '{}'", n->text));
                    d.notes.emplace_back(it->second.range, "first declared here");
                    continue;
                }
                Term term = ob ? Term{Term::Kind::Part, new_part(*ob, n->text), nullptr}
                               : Term{Term::Kind::Value, new_value(*t, n->text), nullptr};
                gens_.emplace(n->text, Gen{term, n->range});
                gen_order_.push_back(n->text);
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
                    l_.sink_->error(e.range, fmt::format("unknown generator '{}'", e.text));
                    return std::nullopt;
                }
                Term t = it->second.term;
                t.node =
                    t.kind == Term::Kind::Part ? parts_uf_.find(t.node) : values_uf_.find(t.node);
                return t;
            }
            if (e.kind != Expr::Kind::Call) {
                l_.sink_->error(e.range, fmt::format("expected a generator, a hom or attribute "
                                                     "applied to a term, or a literal; found '{}'",
                                                     to_string(e)));
                return std::nullopt;
            }
            auto hom = s_.find_hom(e.text);
            auto attr = s_.find_attr(e.text);
            if (!hom && !attr) {
                auto g = s_.find(e.text);
                l_.sink_->error(e.name_range,
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
                l_.sink_->error(e.args[0].range,
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
                l_.sink_->error(st.range, "an equation between two literals says nothing about "
                                          "the instance");
                return;
            }
            if (rhs->kind == Term::Kind::Literal) {
                if (lhs->kind != Term::Kind::Value) {
                    l_.sink_->error(st.range, fmt::format("cannot equate {} with literal {}",
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
                l_.sink_->error(st.range, fmt::format("cannot equate {} ('{}') with {} ('{}')",
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
                    auto& d = l_.sink_->error(at, fmt::format("conflicting values {} and {} for "
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
                        auto& d = l_.sink_->error(
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

        // Rules: a named variable K takes over from Pre (so values flow by name to Eff).
        void declare_value(const std::string& name, AttrTypeId t, SourceRange range) {
            Term term{Term::Kind::Value, new_value(t, name), nullptr};
            gens_.emplace(name, Gen{term, range});
            gen_order_.push_back(name);
        }

        // Rules: a generator declared again with the same type is the same generator.
        void allow_redeclare() { allow_redeclare_ = true; }

        // The generator with this name: its term (node resolved) and declaration range.
        std::optional<std::pair<Term, SourceRange>> generator(const std::string& name) {
            auto it = gens_.find(name);
            if (it == gens_.end()) {
                return std::nullopt;
            }
            Term t = it->second.term;
            t.node = t.kind == Term::Kind::Part ? parts_uf_.find(t.node) : values_uf_.find(t.node);
            return std::make_pair(t, it->second.range);
        }

        const std::vector<std::string>& generator_names() const { return gen_order_; }

        ObId part_ob(std::uint32_t node) const { return parts_[node].ob; }

        AttrTypeId value_type(std::uint32_t node) const { return values_[node].type; }

        // After build: the part or value a node became.
        Part built_part(std::uint32_t node) { return built_parts_[parts_uf_.find(node)]; }

        Value built_value(std::uint32_t node) { return built_values_[values_uf_.find(node)]; }

        // A partial presentation (rules): undefined homs and attributes stay unset.
        ACSet build_partial(std::shared_ptr<Schema> schema) {
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
                    if (parts_[p].homs[i] != kNone) {
                        x.set_subpart(homs[i], part_of[p],
                                      part_of[parts_uf_.find(parts_[p].homs[i])]);
                    }
                }
                auto attrs = s_.attrs_from(ob);
                for (std::size_t i = 0; i < attrs.size(); ++i) {
                    if (parts_[p].attrs[i] != kNone) {
                        x.set_subpart(attrs[i], part_of[p],
                                      value_of[values_uf_.find(parts_[p].attrs[i])]);
                    }
                }
            }
            built_parts_ = std::move(part_of);
            built_values_ = std::move(value_of);
            return x;
        }

        // A free presentation (instances): after completion every hom and attribute is defined,
        // so building it partially gives the whole state.
        ACSet build(std::shared_ptr<Schema> schema) { return build_partial(std::move(schema)); }

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
        std::vector<std::string> gen_order_;
        bool allow_redeclare_ = false;
        std::vector<Part> built_parts_;
        std::vector<Value> built_values_;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> pending_parts_, pending_values_;
    };

    std::optional<ACSet> build_colimit(const MacroCall& form, const std::shared_ptr<Schema>& s,
                                       SourceRange name_range) {
        std::size_t errors = sink_->num_errors();
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
                sink_->error(st.range, fmt::format("expected a generator (x::Block) or an "
                                                   "equation (f(x) == y), found '{}'",
                                                   to_string(st)));
            }
        }
        if (sink_->num_errors() != errors || !c.complete(name_range, options_.max_fresh_parts)) {
            return std::nullopt;
        }
        return c.build(s);
    }

    // ---- instances: literal tables (@acset)
    // ------------------------------------------------------

    std::optional<ACSet> build_literal(const MacroCall& form, const std::shared_ptr<Schema>& s) {
        std::size_t errors = sink_->num_errors();
        ACSet x(s);
        std::map<std::string, SourceRange> seen;
        std::vector<const Expr*> columns;
        for (const auto& st : form.body) {
            if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Name) {
                sink_->error(st.range, fmt::format("expected 'Name = value' (an object count, a "
                                                   "column, or a number of variables), found '{}'",
                                                   to_string(st)));
                continue;
            }
            const Expr& lhs = st.args[0];
            const Expr& rhs = st.args[1];
            auto [it, fresh] = seen.emplace(lhs.text, lhs.range);
            if (!fresh) {
                auto& d = sink_->error(lhs.range, fmt::format("'{}' is given twice", lhs.text));
                d.notes.emplace_back(it->second, "first given here");
                continue;
            }
            auto g = s->find(lhs.text);
            if (!g) {
                sink_->error(lhs.range,
                             fmt::format("unknown name '{}' in schema '{}'", lhs.text, s->name()));
                continue;
            }
            if (g->kind == GeneratorKind::Ob || g->kind == GeneratorKind::AttrType) {
                if (rhs.kind != Expr::Kind::Int || rhs.int_value < 0) {
                    sink_->error(rhs.range, fmt::format("expected a count (an integer ≥ 0) for "
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
                    sink_->error(rhs.range,
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
                        sink_->error(item.range,
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
                        sink_->error(item.range,
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
                    sink_->error(item.range, fmt::format("expected a literal or AttrVar(n) for "
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
        if (sink_->num_errors() != errors) {
            return std::nullopt;
        }
        return x;
    }

    // ---- rules (@rule, @migration), domains (@domain), problems (@problem) ----------------------

    struct RuleBlock {
        std::string name;
        SourceRange range;
        const std::vector<Expr>* body = nullptr;
    };

    // A rule as written, before elaboration.
    struct RuleSource {
        std::string name;
        SourceRange name_range;
        SourceRange range;
        std::shared_ptr<Schema> schema;
        bool span_form = false; // the authors' slide form: L, K, R, l, r
        bool has_params = false;
        std::vector<const Expr*> params;
        std::vector<RuleBlock> blocks;
    };

    static bool is_operator_expr(const Expr& e) {
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

    // `a(x) == <expression>`: an attribute computed from values the match bound.
    static bool is_expression_statement(const Expr& st) {
        return st.is_binary("==") && (is_operator_expr(st.args[0]) || is_operator_expr(st.args[1]));
    }

    // The statements of `Pre => @join begin ... end` / `Pre => begin ... end` into src.blocks.
    void rule_blocks(const std::vector<Expr>& body, RuleSource& src) {
        static const std::vector<std::string> ours = {"Pre", "Keep", "Eff", "NAC", "PAC"};
        static const std::vector<std::string> span = {"L", "K", "R", "l", "r"};
        const auto& allowed = src.span_form ? span : ours;
        std::map<std::string, SourceRange> seen;
        for (const auto& st : body) {
            const std::vector<Expr>* stmts = nullptr;
            if (st.is_binary("=>") && st.args[0].kind == Expr::Kind::Name) {
                const Expr& rhs = st.args[1];
                if (rhs.kind == Expr::Kind::Block) {
                    stmts = &rhs.args;
                } else if (rhs.kind == Expr::Kind::Macro && rhs.macro->name == "join" &&
                           rhs.macro->has_body && rhs.macro->header.empty()) {
                    stmts = &rhs.macro->body;
                }
            }
            if (stmts == nullptr) {
                sink_->error(st.range,
                             fmt::format("expected a block of the rule, '{} => @join begin ... "
                                         "end' or '{} => begin ... end', found '{}'",
                                         allowed[0], allowed[0], to_string(st)));
                continue;
            }
            const Expr& name = st.args[0];
            if (std::find(allowed.begin(), allowed.end(), name.text) == allowed.end()) {
                std::string list;
                for (std::size_t i = 0; i < allowed.size(); ++i) {
                    list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + allowed[i];
                }
                sink_->error(name.range, fmt::format("unknown block '{}' in rule '{}' (expected "
                                                     "{})",
                                                     name.text, src.name, list));
                continue;
            }
            if (name.text != "NAC" && name.text != "PAC") {
                auto [it, fresh] = seen.emplace(name.text, name.range);
                if (!fresh) {
                    auto& d = sink_->error(name.range,
                                           fmt::format("block '{}' is given twice", name.text));
                    d.notes.emplace_back(it->second, "first given here");
                    continue;
                }
            }
            src.blocks.push_back({name.text, st.range, stmts});
        }
    }

    // The rule form `form` named `name` (from an assignment or a domain's `:name =>`), with
    // `default_schema` when the form names none (inside a domain). False after an error.
    bool rule_source(const MacroCall& form, const std::string& assigned, SourceRange assigned_range,
                     const std::shared_ptr<Schema>& default_schema, RuleSource& src) {
        src.range = form.range;
        const Expr* schema_name = nullptr;
        bool ok = form.has_body;
        if (form.name == "rule") {
            // @rule name(params...) [on Schema] begin ... end
            const auto& h = form.header;
            if (!h.empty() && (h[0].kind == Expr::Kind::Name || h[0].kind == Expr::Kind::Call)) {
                src.name = h[0].text;
                src.name_range = h[0].kind == Expr::Kind::Call ? h[0].name_range : h[0].range;
                if (h[0].kind == Expr::Kind::Call) {
                    src.has_params = true;
                    for (const auto& a : h[0].args) {
                        src.params.push_back(&a);
                    }
                }
            } else {
                ok = false;
            }
            if (h.size() == 3 && h[1].kind == Expr::Kind::Name && h[1].text == "on" &&
                h[2].kind == Expr::Kind::Name) {
                schema_name = &h[2];
            } else if (h.size() != 1 || !default_schema) {
                ok = false;
            }
            if (!ok) {
                sink_->error(form.range, "expected '@rule name(parameters...) on Schema begin "
                                         "... end' (inside a domain, 'on Schema' may be left "
                                         "out)");
                return false;
            }
        } else {
            // name = @migration SchRule Schema begin L => ... end (the authors' slides), or
            // :name => @migration(Schema, begin Pre => ... end) (the paper's listing).
            src.name = assigned;
            src.name_range = assigned_range;
            const auto& h = form.header;
            if (h.size() == 2 && h[0].kind == Expr::Kind::Name && h[0].text == "SchRule" &&
                h[1].kind == Expr::Kind::Name) {
                src.span_form = true;
                schema_name = &h[1];
            } else if (h.size() == 1 && h[0].kind == Expr::Kind::Name) {
                schema_name = &h[0];
            } else {
                ok = false;
            }
            if (!ok || assigned.empty()) {
                sink_->error(form.range, "expected 'name = @migration SchRule Schema begin L => "
                                         "... end' or ':name => @migration(Schema, begin Pre "
                                         "=> ... end)' in a domain");
                return false;
            }
        }
        if (schema_name != nullptr) {
            src.schema = lookup_schema(*schema_name, true);
        } else {
            src.schema = default_schema;
        }
        if (!src.schema) {
            return false;
        }
        rule_blocks(form.body, src);
        return true;
    }

    // Runs fn with diagnostics going nowhere unless `loud`: rule blocks are elaborated into
    // several states (Pre into L and into each NAC), and each error should be reported once.
    template <class Fn>
    void with_sink(bool loud, Fn&& fn) {
        DiagnosticSink quiet(sources_);
        DiagnosticSink* saved = sink_;
        if (!loud) {
            sink_ = &quiet;
        }
        fn();
        sink_ = saved;
    }

    void declare_all(Colimit& c, const RuleBlock* b, bool loud) {
        if (b == nullptr) {
            return;
        }
        with_sink(loud, [&] {
            for (const auto& st : *b->body) {
                if (st.is_binary("::")) {
                    c.declare(st);
                }
            }
        });
    }

    // The equations of a block; expression statements are left to the caller (`exprs`), and
    // rejected where none is allowed.
    void equations_all(Colimit& c, const RuleBlock* b, bool loud, std::vector<const Expr*>* exprs) {
        if (b == nullptr) {
            return;
        }
        with_sink(loud, [&] {
            for (const auto& st : *b->body) {
                if (st.is_binary("::")) {
                    continue;
                }
                if (is_expression_statement(st)) {
                    if (exprs != nullptr) {
                        exprs->push_back(&st);
                    } else {
                        sink_->error(st.range,
                                     fmt::format("an attribute computed by an expression may "
                                                 "only be given in the effect block, found '{}' "
                                                 "in '{}'",
                                                 to_string(st), b->name));
                    }
                    continue;
                }
                if (st.is_binary("==")) {
                    c.equation(st);
                } else {
                    sink_->error(st.range, fmt::format("expected a generator (x::Block) or an "
                                                       "equation (f(x) == y), found '{}'",
                                                       to_string(st)));
                }
            }
        });
    }

    static bool numeric(ValueKind k) { return k == ValueKind::Int || k == ValueKind::Float; }

    // "an Int value", "a Bool value".
    static std::string kind_phrase(ValueKind k) {
        std::string name(schema::to_string(k));
        bool vowel = !name.empty() && std::string_view("AEIOU").find(name[0]) != std::string::npos;
        return fmt::format("{} {} value", vowel ? "an" : "a", name);
    }

    // An expression of Eff over values of L's cells, typed; Input nodes hold L's *value node*
    // until L is built (fix_inputs). nullopt after an error.
    std::optional<rewrite::AttrExpr> translate(Colimit& lc, const Expr& e, ValueKind& kind) {
        using Op = rewrite::AttrExpr::Op;
        rewrite::AttrExpr out;
        out.range = e.range;
        if (is_literal(e)) {
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
        if (e.kind == Expr::Kind::Name || e.kind == Expr::Kind::Call) {
            auto t = lc.eval(e);
            if (!t) {
                return std::nullopt;
            }
            if (t->kind != Term::Kind::Value) {
                sink_->error(e.range, fmt::format("expected a value in the expression, but '{}' "
                                                  "is {}",
                                                  to_string(e), lc.describe(*t)));
                return std::nullopt;
            }
            out.op = Op::Input;
            out.input_type = lc.value_type(t->node);
            out.input_var = t->node;
            kind = src_schema_->attr_type(out.input_type).kind;
            if (kind == ValueKind::Unknown) {
                sink_->error(e.range,
                             fmt::format("attribute type '{}' has no value kind; declare one",
                                         src_schema_->attr_type(out.input_type).name));
                return std::nullopt;
            }
            return out;
        }
        if (e.kind == Expr::Kind::Unary) {
            ValueKind k = ValueKind::Unknown;
            auto arg = translate(lc, e.args[0], k);
            if (!arg) {
                return std::nullopt;
            }
            bool neg = e.text == "-";
            if (neg ? !numeric(k) : k != ValueKind::Bool) {
                sink_->error(e.range, fmt::format("type error: '{}' needs {}, found {}", e.text,
                                                  neg ? "a number" : "a Bool", kind_phrase(k)));
                return std::nullopt;
            }
            out.op = neg ? Op::Neg : Op::Not;
            out.args.push_back(std::move(*arg));
            kind = k;
            return out;
        }
        if (e.kind == Expr::Kind::Binary && is_operator_expr(e)) {
            ValueKind a = ValueKind::Unknown, b = ValueKind::Unknown;
            auto x = translate(lc, e.args[0], a);
            auto y = translate(lc, e.args[1], b);
            if (!x || !y) {
                return std::nullopt;
            }
            const std::string& op = e.text;
            bool ok = false;
            if (op == "+" || op == "-" || op == "/" || op == "*") {
                if (numeric(a) && numeric(b)) {
                    ok = true;
                    kind = a == ValueKind::Int && b == ValueKind::Int ? ValueKind::Int
                                                                      : ValueKind::Float;
                    out.op = op == "+"   ? Op::Add
                             : op == "-" ? Op::Sub
                             : op == "*" ? Op::Mul
                                         : Op::Div;
                } else if (op == "*" && a == ValueKind::String && b == ValueKind::String) {
                    ok = true; // Julia's string concatenation
                    kind = ValueKind::String;
                    out.op = Op::Concat;
                }
            } else if (op == "&&" || op == "||") {
                ok = a == ValueKind::Bool && b == ValueKind::Bool;
                kind = ValueKind::Bool;
                out.op = op == "&&" ? Op::And : Op::Or;
            } else {
                bool comparable = a == b || (numeric(a) && numeric(b));
                if (op != "==" && op != "!=") {
                    comparable = comparable && a != ValueKind::Bool;
                }
                ok = comparable;
                kind = ValueKind::Bool;
                out.op = op == "=="   ? Op::Eq
                         : op == "!=" ? Op::Ne
                         : op == "<"  ? Op::Lt
                         : op == "<=" ? Op::Le
                         : op == ">"  ? Op::Gt
                                      : Op::Ge;
            }
            if (!ok) {
                sink_->error(e.range, fmt::format("type error: cannot apply '{}' to {} and {}", op,
                                                  kind_phrase(a), kind_phrase(b)));
                return std::nullopt;
            }
            out.args.push_back(std::move(*x));
            out.args.push_back(std::move(*y));
            return out;
        }
        sink_->error(e.range, fmt::format("expected an expression over attributes of the "
                                          "precondition's parts, found '{}'",
                                          to_string(e)));
        return std::nullopt;
    }

    // Replaces L's value nodes in Input nodes by L's variables (or by the constant Pre gives).
    static void fix_inputs(Colimit& lc, rewrite::AttrExpr& e) {
        if (e.op == rewrite::AttrExpr::Op::Input) {
            Value v = lc.built_value(e.input_var);
            if (v.is_var()) {
                e.input_var = v.var_index();
            } else {
                e.op = rewrite::AttrExpr::Op::Const;
                e.constant = v;
                e.input_var = 0;
            }
        }
        for (auto& a : e.args) {
            fix_inputs(lc, a);
        }
    }

    // Initial bindings from `from`'s generators to `to`'s: by equal names, or by the statements
    // `k => l` of an explicit map block (the slide form's l and r). False after an error.
    bool bind_names(Colimit& from, Colimit& to, const RuleBlock* map, const std::string& from_name,
                    const std::string& to_name, hom::HomSearchOptions& opt) {
        bool ok = true;
        auto bind = [&](const std::string& a, SourceRange a_range, const std::string& b,
                        SourceRange b_range) {
            auto ga = from.generator(a);
            auto gb = to.generator(b);
            if (!ga) {
                sink_->error(a_range, fmt::format("'{}' is not a generator of {}", a, from_name));
                ok = false;
                return;
            }
            if (!gb) {
                sink_->error(b_range,
                             fmt::format("{} {} '{}' is not in {}", from_name,
                                         ga->first.kind == Term::Kind::Part ? "part" : "variable",
                                         b, to_name));
                ok = false;
                return;
            }
            const Term& ta = ga->first;
            const Term& tb = gb->first;
            if (ta.kind != tb.kind || (ta.kind == Term::Kind::Part
                                           ? from.part_ob(ta.node) != to.part_ob(tb.node)
                                           : from.value_type(ta.node) != to.value_type(tb.node))) {
                sink_->error(b_range,
                             fmt::format("'{}' of {} is {} but '{}' of {} is {}", a, from_name,
                                         from.describe(ta), b, to_name, to.describe(tb)));
                ok = false;
                return;
            }
            if (ta.kind == Term::Kind::Part) {
                opt.bind(from.part_ob(ta.node), from.built_part(ta.node), to.built_part(tb.node));
            } else {
                Value va = from.built_value(ta.node);
                if (va.is_var()) {
                    opt.bind_var(from.value_type(ta.node), va.var_index(), to.built_value(tb.node));
                }
            }
        };
        if (map == nullptr) {
            for (const auto& name : from.generator_names()) {
                auto g = from.generator(name);
                bind(name, g->second, name, g->second);
            }
            return ok;
        }
        for (const auto& st : *map->body) {
            if (!st.is_binary("=>") || st.args[0].kind != Expr::Kind::Name ||
                st.args[1].kind != Expr::Kind::Name) {
                sink_->error(st.range, fmt::format("expected 'name => name' (a generator of {} "
                                                   "and its image in {}), found '{}'",
                                                   from_name, to_name, to_string(st)));
                ok = false;
                continue;
            }
            bind(st.args[0].text, st.args[0].range, st.args[1].text, st.args[1].range);
        }
        return ok;
    }

    // The unique morphism from -> to with the given initial bindings, or a located error.
    std::optional<hom::ACSetMorphism> unique_morphism(const ACSet& from, const ACSet& to,
                                                      hom::HomSearchOptions opt,
                                                      const std::string& what, SourceRange at) {
        opt.max_results = 2;
        auto res = hom::find_homomorphisms(from, to, opt);
        if (!res.error.empty()) {
            sink_->error(at, fmt::format("{} cannot be found: {}", what, res.error));
            return std::nullopt;
        }
        if (res.morphisms.empty()) {
            std::string why = "it says something about its parts that the other block does "
                              "not";
            // When the names fix every part, the failure of the name-given map is the reason.
            hom::ACSetMorphism m;
            const Schema& s = from.schema();
            bool complete = true;
            m.components.resize(s.num_obs());
            for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
                m.components[o].assign(from.num_parts(ObId(o)), kNoPart);
            }
            m.var_components.resize(s.num_attr_types());
            for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
                m.var_components[t].assign(from.num_vars(AttrTypeId(t)), Value());
            }
            for (const auto& b : opt.initial) {
                m.components[b.ob.index()][b.dom] = b.codom;
            }
            for (const auto& b : opt.initial_vars) {
                m.var_components[b.type.index()][b.var] = b.value;
            }
            for (const auto& c : m.components) {
                for (Part p : c) {
                    complete = complete && p != kNoPart;
                }
            }
            if (complete) {
                auto failures = hom::naturality_failures(m, from, to);
                for (const auto& f : failures) {
                    if (f.kind != hom::NaturalityFailureKind::VarImageInvalid) {
                        why = hom::describe(f, from, to);
                        break;
                    }
                }
            }
            sink_->error(at, fmt::format("{} does not exist: {}", what, why));
            return std::nullopt;
        }
        if (res.morphisms.size() > 1) {
            sink_->error(at, fmt::format("{} is not unique: the names leave a choice; name the "
                                         "parts of the smaller block so that each has one image",
                                         what));
            return std::nullopt;
        }
        return std::move(res.morphisms[0]);
    }

    // Gives the parts R creates (outside r's image) a value for every attribute and a part for
    // every hom they leave unset, as in a free instance: a fresh unknown, a fresh part.
    bool complete_created(ACSet& r_state, const hom::ACSetMorphism& r, SourceRange at) {
        const Schema& s = r_state.schema();
        std::vector<std::pair<ObId, Part>> work;
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            std::vector<bool> kept(r_state.num_parts(ObId(o)), false);
            for (Part p : r.components[o]) {
                kept[p] = true;
            }
            for (Part p = 0; p < kept.size(); ++p) {
                if (!kept[p]) {
                    work.emplace_back(ObId(o), p);
                }
            }
        }
        std::size_t fresh = 0;
        while (!work.empty()) {
            auto [ob, p] = work.back();
            work.pop_back();
            for (AttrId a : s.attrs_from(ob)) {
                if (r_state.subpart(a, p).is_unset()) {
                    r_state.set_subpart(a, p, r_state.add_var(s.attr(a).codom));
                }
            }
            for (HomId f : s.homs_from(ob)) {
                if (r_state.subpart(f, p) == kNoPart) {
                    if (++fresh > options_.max_fresh_parts) {
                        sink_->error(at, fmt::format("the effect creates infinitely many parts "
                                                     "(hom '{}' keeps needing new parts)",
                                                     s.hom(f).name));
                        return false;
                    }
                    ObId c = s.hom(f).codom;
                    Part q = r_state.add_part(c);
                    r_state.set_subpart(f, p, q);
                    work.emplace_back(c, q);
                }
            }
        }
        return true;
    }

    rewrite::RulePtr elaborate_rule(const RuleSource& src) {
        std::size_t errors = sink_->num_errors();
        const std::shared_ptr<Schema>& schema = src.schema;
        src_schema_ = schema.get();
        const RuleBlock *pre = nullptr, *keep = nullptr, *eff = nullptr, *lmap = nullptr,
                        *rmap = nullptr;
        std::vector<const RuleBlock*> conds;
        for (const auto& b : src.blocks) {
            if (b.name == "Pre" || b.name == "L") {
                pre = &b;
            } else if (b.name == "Keep" || b.name == "K") {
                keep = &b;
            } else if (b.name == "Eff" || b.name == "R") {
                eff = &b;
            } else if (b.name == "l") {
                lmap = &b;
            } else if (b.name == "r") {
                rmap = &b;
            } else {
                conds.push_back(&b);
            }
        }
        const std::string pre_name = src.span_form ? "L" : "Pre";
        const std::string keep_name = src.span_form ? "K" : "Keep";
        const std::string eff_name = src.span_form ? "R" : "Eff";

        // L: the precondition, plus a variable for every cell an expression of Eff reads.
        Colimit lc(*this, *schema);
        declare_all(lc, pre, true);
        equations_all(lc, pre, true, nullptr);
        std::vector<const Expr*> expr_stmts;
        {
            // Collect Eff's expression statements first (R's elaboration reports the rest).
            Colimit scratch(*this, *schema);
            with_sink(false, [&] { equations_all(scratch, eff, false, &expr_stmts); });
        }
        std::vector<std::pair<const Expr*, rewrite::AttrExpr>> translated;
        std::vector<ValueKind> kinds; // the kind each translated expression gives
        for (const Expr* st : expr_stmts) {
            // The computed side is the operator expression; the other names the cell.
            bool rhs_is_expr = is_operator_expr(st->args[1]);
            const Expr& value_side = rhs_is_expr ? st->args[1] : st->args[0];
            ValueKind k = ValueKind::Unknown;
            auto e = translate(lc, value_side, k);
            if (e) {
                e->range = st->range;
                translated.emplace_back(st, std::move(*e));
                kinds.push_back(k);
            }
        }

        // R: Keep's statements hold in Eff too, so Eff need only say what changes.
        Colimit rc(*this, *schema);
        rc.allow_redeclare();
        if (!src.span_form) {
            declare_all(rc, keep, false);
        }
        declare_all(rc, eff, true);
        if (!src.span_form) {
            equations_all(rc, keep, false, nullptr);
        }
        std::vector<const Expr*> unused;
        equations_all(rc, eff, true, &unused);
        std::vector<std::pair<std::uint32_t, std::size_t>> expr_cells; // R value node, index
        for (std::size_t i = 0; i < translated.size(); ++i) {
            const Expr* st = translated[i].first;
            const Expr& cell = is_operator_expr(st->args[1]) ? st->args[0] : st->args[1];
            auto t = rc.eval(cell);
            if (!t) {
                continue;
            }
            if (t->kind != Term::Kind::Value || cell.kind != Expr::Kind::Call) {
                sink_->error(cell.range, fmt::format("the left side of a computed attribute must "
                                                     "be an attribute of a part, found '{}'",
                                                     to_string(cell)));
                continue;
            }
            ValueKind want = schema->attr_type(rc.value_type(t->node)).kind;
            ValueKind got = kinds[i];
            if (want != got) {
                sink_->error(st->range, fmt::format("type error: the expression gives {} but '{}' "
                                                    "holds {} values",
                                                    kind_phrase(got), to_string(cell),
                                                    schema::to_string(want)));
                continue;
            }
            expr_cells.emplace_back(t->node, i);
        }
        if (sink_->num_errors() != errors) {
            return nullptr;
        }
        ACSet L = lc.build_partial(schema);
        for (auto& [st, e] : translated) {
            fix_inputs(lc, e);
        }
        ACSet R = rc.build_partial(schema);

        // K: Keep, plus every named variable of Pre that Eff uses too (values flow by name).
        Colimit kc(*this, *schema);
        declare_all(kc, keep, true);
        if (!src.span_form) {
            for (const auto& name : lc.generator_names()) {
                auto g = lc.generator(name);
                auto h = rc.generator(name);
                if (g->first.kind == Term::Kind::Value && h && h->first.kind == Term::Kind::Value &&
                    !kc.generator(name)) {
                    kc.declare_value(name, lc.value_type(g->first.node), g->second);
                }
            }
        }
        equations_all(kc, keep, true, nullptr);
        if (sink_->num_errors() != errors) {
            return nullptr;
        }
        ACSet K = kc.build_partial(schema);

        auto rule = std::make_shared<rewrite::Rule>(schema);
        rule->name = src.name;
        rule->range = src.name_range;
        hom::HomSearchOptions lopt, ropt;
        bool names_ok = bind_names(kc, lc, lmap, keep_name, pre_name, lopt);
        names_ok = bind_names(kc, rc, rmap, keep_name, eff_name, ropt) && names_ok;
        if (!names_ok) {
            return nullptr;
        }
        auto l = unique_morphism(K, L, lopt, fmt::format("l : {} -> {}", keep_name, pre_name),
                                 src.name_range);
        auto r = unique_morphism(K, R, ropt, fmt::format("r : {} -> {}", keep_name, eff_name),
                                 src.name_range);
        if (!l || !r) {
            return nullptr;
        }
        bool monic = true;
        for (std::uint32_t o = 0; o < schema->num_obs() && monic; ++o) {
            const auto& c = l->components[o];
            for (Part a = 0; a < c.size() && monic; ++a) {
                for (Part b = a + 1; b < c.size(); ++b) {
                    if (c[a] == c[b]) {
                        sink_->error(src.name_range,
                                     fmt::format("l is not monic: {} parts '{}' and '{}' both "
                                                 "go to part '{}' of {}",
                                                 keep_name, K.part_label(ObId(o), a),
                                                 K.part_label(ObId(o), b),
                                                 L.part_label(ObId(o), c[a]), pre_name));
                        monic = false;
                        break;
                    }
                }
            }
        }
        if (!monic) {
            return nullptr;
        }
        if (!complete_created(R, *r, src.name_range)) {
            return nullptr;
        }

        // Application conditions: N = Pre ∪ the condition's statements; n : L -> N by names.
        for (const RuleBlock* b : conds) {
            Colimit nc(*this, *schema);
            nc.allow_redeclare();
            declare_all(nc, pre, false);
            declare_all(nc, b, true);
            equations_all(nc, pre, false, nullptr);
            equations_all(nc, b, true, nullptr);
            with_sink(false, [&] {
                for (auto& [st, e] : translated) {
                    ValueKind k = ValueKind::Unknown;
                    translate(nc, is_operator_expr(st->args[1]) ? st->args[1] : st->args[0], k);
                }
            });
            if (sink_->num_errors() != errors) {
                return nullptr;
            }
            ACSet N = nc.build_partial(schema);
            hom::HomSearchOptions nopt;
            if (!bind_names(lc, nc, nullptr, pre_name, b->name, nopt)) {
                return nullptr;
            }
            auto n = unique_morphism(L, N, nopt, fmt::format("n : {} -> {}", pre_name, b->name),
                                     b->range);
            if (!n) {
                return nullptr;
            }
            rule->conditions.push_back(rewrite::ApplicationCondition{
                fmt::format("{} {}", b->name, rule->conditions.size() + 1), b->name == "NAC",
                std::move(N), std::move(*n), b->range});
        }

        // Parameters: the header's list, else L's named entities (objects without homs out).
        if (src.has_params) {
            for (const Expr* p : src.params) {
                auto g = p->kind == Expr::Kind::Name ? lc.generator(p->text) : std::nullopt;
                if (!g || g->first.kind != Term::Kind::Part) {
                    sink_->error(p->range, fmt::format("parameter '{}' is not a part generator of "
                                                       "{}",
                                                       to_string(*p), pre_name));
                    continue;
                }
                rule->parameters.push_back(
                    {p->text, lc.part_ob(g->first.node), lc.built_part(g->first.node)});
            }
        } else {
            for (const auto& name : lc.generator_names()) {
                auto g = lc.generator(name);
                if (g->first.kind == Term::Kind::Part &&
                    schema->homs_from(lc.part_ob(g->first.node)).empty()) {
                    rule->parameters.push_back(
                        {name, lc.part_ob(g->first.node), lc.built_part(g->first.node)});
                }
            }
        }

        rule->exprs.resize(schema->num_attr_types());
        for (std::uint32_t t = 0; t < schema->num_attr_types(); ++t) {
            rule->exprs[t].resize(R.num_vars(AttrTypeId(t)));
        }
        for (auto [node, i] : expr_cells) {
            Value v = rc.built_value(node);
            const Expr* st = translated[i].first;
            if (!v.is_var()) {
                sink_->error(st->range, fmt::format("'{}' is also given the constant {}; an "
                                                    "attribute is computed or constant, not "
                                                    "both",
                                                    to_string(st->args[0]), v.to_string()));
                continue;
            }
            rule->exprs[rc.value_type(node).index()][v.var_index()] =
                std::move(translated[i].second);
        }
        rule->L = std::move(L);
        rule->K = std::move(K);
        rule->R = std::move(R);
        rule->l = std::move(*l);
        rule->r = std::move(*r);
        if (sink_->num_errors() != errors) {
            return nullptr;
        }
        for (const auto& problem : rewrite::check_rule(*rule)) {
            SourceRange at = src.name_range;
            if (problem.kind == rewrite::RuleProblemKind::UnboundVariable ||
                problem.kind == rewrite::RuleProblemKind::ExprOnBoundVariable) {
                std::string vname(rule->R.var_name(problem.type, problem.var));
                if (auto g = rc.generator(vname)) {
                    at = g->second;
                }
            }
            sink_->error(at, fmt::format("in rule '{}': {}", src.name, problem.message));
        }
        if (sink_->num_errors() != errors) {
            return nullptr;
        }
        return rule;
    }

    // The kinds attribute types take from the literals in a rule's blocks.
    void infer_rule_kinds(const MacroCall& form, const std::shared_ptr<Schema>& default_schema) {
        std::shared_ptr<Schema> s = default_schema;
        const Expr* schema_name = nullptr;
        const auto& h = form.header;
        if (form.name == "rule" && h.size() == 3 && h[2].kind == Expr::Kind::Name) {
            schema_name = &h[2];
        } else if (form.name == "migration" && !h.empty() && h.back().kind == Expr::Kind::Name) {
            schema_name = &h.back();
        }
        if (schema_name != nullptr) {
            auto it = schemas_.find(schema_name->text);
            s = it == schemas_.end() ? nullptr : it->second;
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
                infer_kinds_body(rhs.args, *s);
            } else if (rhs.kind == Expr::Kind::Macro && rhs.macro->has_body) {
                infer_kinds_body(rhs.macro->body, *s);
            }
        }
    }

    void infer_domain_kinds(const MacroCall& form) {
        std::shared_ptr<Schema> s;
        if (form.header.size() == 1 && form.header[0].kind == Expr::Kind::Call &&
            form.header[0].args.size() == 1) {
            auto it = schemas_.find(form.header[0].args[0].text);
            if (it != schemas_.end()) {
                s = it->second;
            }
        }
        for (const auto& st : form.body) {
            if (st.kind == Expr::Kind::Macro) {
                infer_rule_kinds(*st.macro, s);
            } else if (st.is_binary("=>") && st.args[1].kind == Expr::Kind::Macro) {
                infer_rule_kinds(*st.args[1].macro, s);
            }
        }
    }

    void elaborate_top_rule(const MacroCall& form, bool imported) {
        RuleSource src;
        if (!rule_source(form, form.assigned, form.assigned_range, nullptr, src)) {
            return;
        }
        auto rule = elaborate_rule(src);
        if (!rule || !claim_name(src.name, src.name_range)) {
            return;
        }
        Declaration d;
        d.kind = DeclKind::Rule;
        d.name = src.name;
        d.range = src.name_range;
        d.imported = imported;
        d.schema = src.schema;
        d.rule = rule;
        module_.add(std::move(d));
    }

    // A rule named in a domain, `unstack` or with parameters `unstack(block, underblock)`.
    rewrite::RulePtr named_rule(const Expr& st) {
        const Declaration* d = module_.find(st.text);
        SourceRange at = st.kind == Expr::Kind::Call ? st.name_range : st.range;
        if (d == nullptr || d->kind != DeclKind::Rule) {
            sink_->error(at, d == nullptr ? fmt::format("unknown rule '{}'", st.text)
                                          : fmt::format("'{}' is not a rule", st.text));
            return nullptr;
        }
        if (st.kind == Expr::Kind::Name) {
            return d->rule;
        }
        auto copy = std::make_shared<rewrite::Rule>(*d->rule);
        copy->parameters.clear();
        bool ok = true;
        for (const auto& a : st.args) {
            bool found = false;
            for (std::uint32_t o = 0; o < copy->L.schema().num_obs() && !found; ++o) {
                if (a.kind != Expr::Kind::Name) {
                    break;
                }
                if (auto p = copy->L.find_part(ObId(o), a.text)) {
                    copy->parameters.push_back({a.text, ObId(o), *p});
                    found = true;
                }
            }
            if (!found) {
                sink_->error(a.range, fmt::format("parameter '{}' is not a part generator of the "
                                                  "precondition of '{}'",
                                                  to_string(a), st.text));
                ok = false;
            }
        }
        return ok ? copy : nullptr;
    }

    void elaborate_domain(const MacroCall& form, bool imported) {
        const auto& h = form.header;
        if (h.size() != 1 || h[0].kind != Expr::Kind::Call || h[0].args.size() != 1 ||
            h[0].args[0].kind != Expr::Kind::Name || !form.has_body || !form.assigned.empty()) {
            sink_->error(form.range, "expected '@domain Name(Schema) begin ... end'");
            return;
        }
        std::size_t errors = sink_->num_errors();
        auto schema = lookup_schema(h[0].args[0], true);
        if (!schema) {
            return;
        }
        auto domain = std::make_shared<plan::Domain>();
        domain->name = h[0].text;
        domain->schema = schema;
        domain->range = h[0].name_range;
        std::map<std::string, SourceRange> seen;
        for (const auto& st : form.body) {
            rewrite::RulePtr rule;
            SourceRange at = st.range;
            if (st.kind == Expr::Kind::Macro && st.macro->name == "rule") {
                RuleSource src;
                if (rule_source(*st.macro, "", {}, schema, src)) {
                    rule = elaborate_rule(src);
                    at = src.name_range;
                }
            } else if (st.is_binary("=>") &&
                       (st.args[0].kind == Expr::Kind::Symbol ||
                        st.args[0].kind == Expr::Kind::Name) &&
                       st.args[1].kind == Expr::Kind::Macro &&
                       st.args[1].macro->name == "migration") {
                RuleSource src;
                if (rule_source(*st.args[1].macro, st.args[0].text, st.args[0].range, schema,
                                src)) {
                    rule = elaborate_rule(src);
                    at = src.name_range;
                }
            } else if (st.kind == Expr::Kind::Name || st.kind == Expr::Kind::Call) {
                rule = named_rule(st);
                at = st.kind == Expr::Kind::Call ? st.name_range : st.range;
            } else {
                sink_->error(st.range, fmt::format("expected a rule in the domain: '@rule ...', "
                                                   "':name => @migration(...)' or the name of a "
                                                   "rule, found '{}'",
                                                   to_string(st)));
                continue;
            }
            if (!rule) {
                continue;
            }
            if (rule->L.schema_ptr().get() != schema.get()) {
                sink_->error(at, fmt::format("rule '{}' is on schema '{}' but domain '{}' is on "
                                             "'{}'",
                                             rule->name, rule->L.schema().name(), domain->name,
                                             schema->name()));
                continue;
            }
            auto [it, fresh] = seen.emplace(rule->name, at);
            if (!fresh) {
                auto& d = sink_->error(at, fmt::format("rule '{}' is already in domain '{}'",
                                                       rule->name, domain->name));
                d.notes.emplace_back(it->second, "first given here");
                continue;
            }
            domain->rules.push_back(std::move(rule));
        }
        if (sink_->num_errors() != errors || !claim_name(domain->name, domain->range)) {
            return;
        }
        Declaration d;
        d.kind = DeclKind::Domain;
        d.name = domain->name;
        d.range = domain->range;
        d.imported = imported;
        d.schema = schema;
        d.domain = std::move(domain);
        module_.add(std::move(d));
    }

    void elaborate_problem(const MacroCall& form, bool imported) {
        const auto& h = form.header;
        if (h.size() != 1 || h[0].kind != Expr::Kind::Call || h[0].args.size() != 1 ||
            h[0].args[0].kind != Expr::Kind::Name || !form.has_body || !form.assigned.empty()) {
            sink_->error(form.range, "expected '@problem Name(Domain) begin initial = I; goal = "
                                     "G end'");
            return;
        }
        std::size_t errors = sink_->num_errors();
        const Expr& dname = h[0].args[0];
        const Declaration* dd = module_.find(dname.text);
        if (dd == nullptr || dd->kind != DeclKind::Domain) {
            sink_->error(dname.range, dd == nullptr
                                          ? fmt::format("unknown domain '{}'", dname.text)
                                          : fmt::format("'{}' is not a domain", dname.text));
            return;
        }
        auto problem = std::make_shared<plan::Problem>();
        problem->name = h[0].text;
        problem->domain = dd->domain;
        problem->range = h[0].name_range;
        std::string names[2];
        std::shared_ptr<const ACSet>* slots[2] = {&problem->initial, &problem->goal};
        for (const auto& st : form.body) {
            if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Name ||
                (st.args[0].text != "initial" && st.args[0].text != "goal") ||
                st.args[1].kind != Expr::Kind::Name) {
                sink_->error(st.range, fmt::format("expected 'initial = Instance' or 'goal = "
                                                   "Instance', found '{}'",
                                                   to_string(st)));
                continue;
            }
            int i = st.args[0].text == "initial" ? 0 : 1;
            const Expr& iname = st.args[1];
            if (slots[i]->get() != nullptr) {
                sink_->error(st.range, fmt::format("'{}' is given twice", st.args[0].text));
                continue;
            }
            const Declaration* id = module_.find(iname.text);
            if (id == nullptr || id->kind != DeclKind::Instance) {
                sink_->error(iname.range, id == nullptr
                                              ? fmt::format("unknown instance '{}'", iname.text)
                                              : fmt::format("'{}' is not an instance", iname.text));
                continue;
            }
            if (id->schema.get() != dd->schema.get()) {
                sink_->error(iname.range, fmt::format("instance '{}' is on schema '{}' but domain "
                                                      "'{}' is on '{}'",
                                                      iname.text, id->schema->name(), dname.text,
                                                      dd->schema->name()));
                continue;
            }
            *slots[i] = id->instance;
            names[i] = iname.text;
        }
        for (int i = 0; i < 2; ++i) {
            if (slots[i]->get() == nullptr && sink_->num_errors() == errors) {
                sink_->error(form.range, fmt::format("problem '{}' needs '{} = Instance'",
                                                     problem->name, i == 0 ? "initial" : "goal"));
            }
        }
        if (sink_->num_errors() != errors || !claim_name(problem->name, problem->range)) {
            return;
        }
        Declaration d;
        d.kind = DeclKind::Problem;
        d.name = problem->name;
        d.range = problem->range;
        d.imported = imported;
        d.schema = dd->schema;
        d.initial_name = names[0];
        d.goal_name = names[1];
        d.problem = std::move(problem);
        module_.add(std::move(d));
    }

    // ---- ontology maps (@migration Name(Target, Source), @compose) -----------------------------

    // An ontology map rather than a rule: `@migration Name(Target, Source) begin ... end` or
    // `Name = @migration Target Source begin ... end` (a rule names SchRule or one schema).
    static bool is_map_form(const MacroCall& form) {
        const auto& h = form.header;
        if (form.assigned.empty()) {
            return h.size() == 1 && h[0].kind == Expr::Kind::Call && h[0].args.size() == 2;
        }
        return h.size() == 2 && h[0].kind == Expr::Kind::Name && h[0].text != "SchRule";
    }

    // The name and the two arguments of `@macro Name(A, B)` or `Name = @macro A B`; false after
    // reporting a malformed header.
    bool binary_header(const MacroCall& form, std::string_view usage, std::string& name,
                       SourceRange& name_range, const Expr*& first, const Expr*& second) {
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
            sink_->error(form.range, fmt::format("expected {}", usage));
            return false;
        }
        for (const Expr* e : {first, second}) {
            if (e->kind != Expr::Kind::Name) {
                sink_->error(e->range, fmt::format("expected a name, found '{}'", to_string(*e)));
                return false;
            }
        }
        return true;
    }

    void elaborate_map(const MacroCall& form, bool imported) {
        detail::MapForm mf;
        const Expr *target = nullptr, *source = nullptr;
        if (!binary_header(form, "'@migration Name(Target, Source) begin ... end'", mf.name,
                           mf.name_range, target, source)) {
            return;
        }
        if (!form.has_body) {
            sink_->error(form.range, fmt::format("map '{}' needs its entries: '@migration "
                                                 "{}({}, {}) begin ... end'",
                                                 mf.name, mf.name, target->text, source->text));
            return;
        }
        auto t = lookup_schema(*target, false);
        auto s = lookup_schema(*source, false);
        if (!t || !s || broken_.count(t.get()) || broken_.count(s.get())) {
            return;
        }
        mf.target = t;
        mf.source = s;
        mf.body = &form.body;
        auto map = detail::elaborate_map(mf, *sink_);
        if (map && claim_name(mf.name, mf.name_range)) {
            add_map(mf.name, mf.name_range, imported, std::move(map));
        }
    }

    void add_map(const std::string& name, SourceRange range, bool imported,
                 std::shared_ptr<const migrate::SchemaMap> map) {
        Declaration d;
        d.kind = DeclKind::Map;
        d.name = name;
        d.range = range;
        d.imported = imported;
        d.schema = map->target();
        d.map = std::move(map);
        module_.add(std::move(d));
    }

    const Declaration* find_map(const Expr& name) {
        const Declaration* d = module_.find(name.text);
        if (d == nullptr || d->kind != DeclKind::Map) {
            sink_->error(name.range, d == nullptr ? fmt::format("unknown map '{}'", name.text)
                                                  : fmt::format("'{}' is not a map", name.text));
            return nullptr;
        }
        return d;
    }

    // `Name = @migrate Target X begin ... end` (or `@migrate Name(Target, X) begin ... end`):
    // the instance X migrated along the map the body gives, as DataMigrations' @migrate builds
    // a map and runs it at once.
    void elaborate_migrate(const MacroCall& form, bool imported) {
        detail::MapForm mf;
        const Expr *target = nullptr, *source = nullptr;
        if (!binary_header(form, "'Name = @migrate Target Instance begin ... end'", mf.name,
                           mf.name_range, target, source)) {
            return;
        }
        const Declaration* x = module_.find(source->text);
        if (x == nullptr || x->kind != DeclKind::Instance) {
            sink_->error(source->range, x == nullptr
                                            ? fmt::format("unknown instance '{}'", source->text)
                                            : fmt::format("'{}' is not an instance", source->text));
            return;
        }
        if (!form.has_body) {
            sink_->error(form.range, fmt::format("'{}' needs the map's entries: '{} = @migrate "
                                                 "{} {} begin ... end'",
                                                 mf.name, mf.name, target->text, source->text));
            return;
        }
        auto t = lookup_schema(*target, false);
        if (!t || broken_.count(t.get())) {
            return;
        }
        mf.target = t;
        mf.source = x->schema;
        mf.body = &form.body;
        auto map = detail::elaborate_map(mf, *sink_);
        if (!map || !claim_name(mf.name, mf.name_range)) {
            return;
        }
        Declaration d;
        d.kind = DeclKind::Instance;
        d.name = mf.name;
        d.range = mf.name_range;
        d.imported = imported;
        d.schema = t;
        d.instance = std::make_shared<const ACSet>(migrate::migrate(*map, *x->instance));
        module_.add(std::move(d));
    }

    // `@compose H(F, G)`: H = F ∘ G as functors, so Δ_H migrates along F, then along G.
    void elaborate_compose(const MacroCall& form, bool imported) {
        std::string name;
        SourceRange name_range;
        const Expr *first = nullptr, *second = nullptr;
        if (!binary_header(form, "'@compose Name(F, G)' (the map F ∘ G: migrate along F, then G)",
                           name, name_range, first, second)) {
            return;
        }
        const Declaration* f = find_map(*first);
        const Declaration* g = find_map(*second);
        if (f == nullptr || g == nullptr) {
            return;
        }
        if (g->map->source() != f->map->target()) {
            sink_->error(second->range,
                         fmt::format("cannot compose: '{}' is a map from {}, so '{}' must be a "
                                     "map into {}, but it maps into {}",
                                     first->text, f->map->target()->name(), second->text,
                                     f->map->target()->name(), g->map->source()->name()));
            return;
        }
        auto h = migrate::compose(*f->map, *g->map);
        if (!h) {
            sink_->error(form.range, fmt::format("cannot compose '{}' and '{}': {}", first->text,
                                                 second->text, h.error()));
            return;
        }
        if (claim_name(name, name_range)) {
            add_map(name, name_range, imported,
                    std::make_shared<const migrate::SchemaMap>(std::move(*h)));
        }
    }

    SourceManager& sources_;
    DiagnosticSink* sink_;
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
    // The schema of the rule being elaborated (for the kinds of expression inputs).
    const Schema* src_schema_ = nullptr;
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
