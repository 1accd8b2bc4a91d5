// Reading and writing schemas in Catlab's schema JSON (ACSets.jl generate_json_acset_schema).

#include "catplan/json/detail/located_json.hpp"
#include "catplan/json/json.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace catplan::json {

using detail::Node;
using schema::GeneratorKind;
using schema::Schema;
using OrderedJson = nlohmann::ordered_json;

namespace {

// The version Catlab writes (ACSets' own, as our reference documents it).
constexpr const char* kSchemaFormatVersion = "0.0.1";
constexpr const char* kACSetsVersion = "0.2.27";

OrderedJson path_to_json(const Schema& s, const schema::Path& p) {
    OrderedJson out = OrderedJson::array();
    for (HomId f : p.homs) {
        out.push_back(s.hom(f).name);
    }
    if (p.attr) {
        out.push_back(s.attr(*p.attr).name);
    }
    return out;
}

std::string path_codom_name(const Schema& s, const schema::Path& p) {
    if (p.attr) {
        return s.attr_type(s.attr(*p.attr).codom).name;
    }
    return s.ob(s.path_codom_ob(p)).name;
}

} // namespace

std::string write_schema(const Schema& s, bool pretty) {
    OrderedJson out = OrderedJson::object();
    out["version"] = {{"ACSetSchema", kSchemaFormatVersion}, {"ACSets", kACSetsVersion}};
    OrderedJson obs = OrderedJson::array();
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        obs.push_back({{"name", s.ob(ObId(i)).name}});
    }
    OrderedJson homs = OrderedJson::array();
    for (std::uint32_t i = 0; i < s.num_homs(); ++i) {
        const auto& f = s.hom(HomId(i));
        homs.push_back(
            {{"name", f.name}, {"dom", s.ob(f.dom).name}, {"codom", s.ob(f.codom).name}});
    }
    OrderedJson attr_types = OrderedJson::array();
    for (std::uint32_t i = 0; i < s.num_attr_types(); ++i) {
        const auto& t = s.attr_type(AttrTypeId(i));
        OrderedJson entry = {{"name", t.name}};
        if (t.kind != schema::ValueKind::Unknown) {
            entry["kind"] = std::string(schema::to_string(t.kind)); // ACSets.jl reads only "name"
        }
        attr_types.push_back(std::move(entry));
    }
    OrderedJson attrs = OrderedJson::array();
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        const auto& a = s.attr(AttrId(i));
        attrs.push_back(
            {{"name", a.name}, {"dom", s.ob(a.dom).name}, {"codom", s.attr_type(a.codom).name}});
    }
    OrderedJson eqs = OrderedJson::array();
    for (const auto& eq : s.equations()) {
        OrderedJson e = OrderedJson::object();
        e["dom"] = s.ob(eq.lhs.dom).name;
        e["codom"] = path_codom_name(s, eq.lhs);
        e["name"] = eq.name.empty() ? OrderedJson(nullptr) : OrderedJson(eq.name);
        e["paths"] = OrderedJson::array({path_to_json(s, eq.lhs), path_to_json(s, eq.rhs)});
        eqs.push_back(std::move(e));
    }
    out["Ob"] = std::move(obs);
    out["Hom"] = std::move(homs);
    out["AttrType"] = std::move(attr_types);
    out["Attr"] = std::move(attrs);
    out["equations"] = std::move(eqs);
    return dump(out, pretty ? 2 : -1);
}

namespace {

class SchemaReader {
public:
    SchemaReader(std::string name, DiagnosticSink& sink)
        : s_(std::make_shared<Schema>(std::move(name))), sink_(sink) {}

    std::shared_ptr<Schema> read(const Node& root) {
        if (!root.is_object()) {
            sink_.error(root.head(), fmt::format("expected a JSON object describing a schema "
                                                 "(with \"Ob\" and \"Hom\"), found {}",
                                                 root.describe()));
            return nullptr;
        }
        // Generators are read kind by kind, whatever the key order, so references resolve.
        for_each_entry(root, "Ob", true, [&](const Node& e) { read_ob(e); });
        for_each_entry(root, "AttrType", false, [&](const Node& e) { read_attr_type(e); });
        for_each_entry(root, "Hom", true, [&](const Node& e) { read_hom(e); });
        for_each_entry(root, "Attr", false, [&](const Node& e) { read_attr(e); });
        for_each_entry(root, "equations", false, [&](const Node& e) { read_equation(e); });
        return s_;
    }

private:
    template <class F>
    void for_each_entry(const Node& root, const char* key, bool required, F&& read_entry) {
        const Node* list = root.find(key);
        if (list == nullptr) {
            if (required) {
                sink_.error(root.head(), fmt::format("schema has no \"{}\" array", key));
            }
            return;
        }
        if (!list->is_array()) {
            sink_.error(list->head(),
                        fmt::format("\"{}\" must be an array, found {}", key, list->describe()));
            return;
        }
        for (const Node& entry : list->items) {
            if (!entry.is_object()) {
                sink_.error(entry.head(), fmt::format("an entry of \"{}\" must be an object, "
                                                      "found {}",
                                                      key, entry.describe()));
                continue;
            }
            read_entry(entry);
        }
    }

    // A string member; the older Catlab spelling is tried when the current one is absent.
    const Node* string_field(const Node& entry, const char* key, const char* old_key,
                             const char* what) {
        const Node* n = entry.find(key);
        if (n == nullptr && old_key != nullptr) {
            n = entry.find(old_key);
        }
        if (n == nullptr) {
            sink_.error(entry.head(), fmt::format("{} has no \"{}\"", what, key));
            return nullptr;
        }
        if (n->kind != Node::Kind::String) {
            sink_.error(n->head(), fmt::format("\"{}\" of {} must be a string, found {}", key, what,
                                               n->describe()));
            return nullptr;
        }
        return n;
    }

    // Whether a name is still free; reports a duplicate with a note at the first declaration.
    bool check_new_name(const Node& name) {
        auto gen = s_->find(name.string);
        if (!gen) {
            return true;
        }
        SourceRange first;
        switch (gen->kind) {
        case GeneratorKind::Ob:
            first = s_->ob(ObId(gen->index)).range;
            break;
        case GeneratorKind::Hom:
            first = s_->hom(HomId(gen->index)).range;
            break;
        case GeneratorKind::AttrType:
            first = s_->attr_type(AttrTypeId(gen->index)).range;
            break;
        case GeneratorKind::Attr:
            first = s_->attr(AttrId(gen->index)).range;
            break;
        }
        sink_.error(name.range, fmt::format("duplicate name '{}'", name.string))
            .notes.emplace_back(first, "first declared here");
        return false;
    }

    std::optional<ObId> resolve_ob(const Node& n, const std::string& owner, const char* role) {
        auto gen = s_->find(n.string);
        if (gen && gen->kind == GeneratorKind::Ob) {
            return ObId(gen->index);
        }
        sink_.error(n.range, fmt::format("{} of '{}' must be an object, but '{}' is {}", role,
                                         owner, n.string, describe(gen)));
        return std::nullopt;
    }

    static const char* describe(const std::optional<schema::Generator>& gen) {
        if (!gen) {
            return "not declared";
        }
        return schema::kind_noun(gen->kind);
    }

    void read_ob(const Node& e) {
        const Node* name = string_field(e, "name", nullptr, "an object");
        if (name != nullptr && check_new_name(*name)) {
            s_->add_ob(name->string, name->range);
        }
    }

    void read_attr_type(const Node& e) {
        const Node* name = string_field(e, "name", nullptr, "an attribute type");
        auto kind = schema::ValueKind::Unknown;
        if (const Node* k = e.find("kind")) {
            auto parsed =
                k->kind == Node::Kind::String ? schema::parse_value_kind(k->string) : std::nullopt;
            if (parsed) {
                kind = *parsed;
            } else {
                sink_.error(k->head(), fmt::format("\"kind\" of an attribute type must be one of "
                                                   "\"Bool\", \"Int\", \"Float\", \"String\", "
                                                   "found {}",
                                                   k->describe()));
            }
        }
        if (name != nullptr && check_new_name(*name)) {
            s_->add_attr_type(name->string, kind, name->range);
        }
    }

    void read_hom(const Node& e) {
        const Node* name = string_field(e, "name", nullptr, "a hom");
        std::string owner = name != nullptr ? name->string : "?";
        const Node* dom = string_field(e, "dom", "domain", "a hom");
        const Node* codom = string_field(e, "codom", "codomain", "a hom");
        auto d = dom != nullptr ? resolve_ob(*dom, owner, "the domain") : std::nullopt;
        auto c = codom != nullptr ? resolve_ob(*codom, owner, "the codomain") : std::nullopt;
        if (name != nullptr && check_new_name(*name) && d && c) {
            s_->add_hom(name->string, *d, *c, name->range);
        }
    }

    void read_attr(const Node& e) {
        const Node* name = string_field(e, "name", nullptr, "an attribute");
        std::string owner = name != nullptr ? name->string : "?";
        const Node* dom = string_field(e, "dom", "domain", "an attribute");
        const Node* codom = string_field(e, "codom", "codomain", "an attribute");
        auto d = dom != nullptr ? resolve_ob(*dom, owner, "the domain") : std::nullopt;
        std::optional<AttrTypeId> c;
        if (codom != nullptr) {
            auto gen = s_->find(codom->string);
            if (gen && gen->kind == GeneratorKind::AttrType) {
                c = AttrTypeId(gen->index);
            } else {
                sink_.error(codom->range,
                            fmt::format("the codomain of '{}' must be an attribute type, but "
                                        "'{}' is {}",
                                        owner, codom->string, describe(gen)));
            }
        }
        if (name != nullptr && check_new_name(*name) && d && c) {
            s_->add_attr(name->string, *d, *c, name->range);
        }
    }

    // A path is a list of hom names, optionally ending in an attribute, composable from `dom`.
    std::optional<schema::Path> read_path(const Node& list, ObId dom) {
        if (!list.is_array()) {
            sink_.error(list.head(), fmt::format("a path must be an array of hom and attribute "
                                                 "names, found {}",
                                                 list.describe()));
            return std::nullopt;
        }
        schema::Path path{dom, {}, std::nullopt};
        ObId at = dom;
        for (const Node& step : list.items) {
            if (step.kind != Node::Kind::String) {
                sink_.error(step.head(), fmt::format("a path step must be a hom or attribute "
                                                     "name, found {}",
                                                     step.describe()));
                return std::nullopt;
            }
            auto gen = s_->find(step.string);
            bool is_hom = gen && gen->kind == GeneratorKind::Hom;
            bool is_attr = gen && gen->kind == GeneratorKind::Attr;
            if (!is_hom && !is_attr) {
                sink_.error(step.range, fmt::format("a path step must be a hom or attribute, but "
                                                    "'{}' is {}",
                                                    step.string, describe(gen)));
                return std::nullopt;
            }
            ObId from = is_hom ? s_->hom(HomId(gen->index)).dom : s_->attr(AttrId(gen->index)).dom;
            if (path.attr || from != at) {
                sink_.error(step.range,
                            path.attr
                                ? fmt::format("'{}' follows an attribute; an attribute can "
                                              "only end a path",
                                              step.string)
                                : fmt::format("'{}' starts at '{}', but the path is at '{}' "
                                              "here",
                                              step.string, s_->ob(from).name, s_->ob(at).name));
                return std::nullopt;
            }
            if (is_hom) {
                path.homs.push_back(HomId(gen->index));
                at = s_->hom(HomId(gen->index)).codom;
            } else {
                path.attr = AttrId(gen->index);
            }
        }
        return path;
    }

    void read_equation(const Node& e) {
        const Node* dom = string_field(e, "dom", "domain", "an equation");
        const Node* codom = string_field(e, "codom", "codomain", "an equation");
        const Node* paths = e.find("paths");
        std::string name;
        if (const Node* n = e.find("name"); n != nullptr && n->kind == Node::Kind::String) {
            name = n->string;
        } else if (n != nullptr && n->kind != Node::Kind::Null) {
            sink_.error(n->head(), fmt::format("the name of an equation must be a string or "
                                               "null, found {}",
                                               n->describe()));
        }
        std::string owner = name.empty() ? "an equation" : name;
        auto d = dom != nullptr ? resolve_ob(*dom, owner, "the domain") : std::nullopt;
        if (paths == nullptr) {
            sink_.error(e.head(), "an equation has no \"paths\"");
            return;
        }
        if (!paths->is_array() || paths->items.size() != 2) {
            sink_.error(paths->head(),
                        fmt::format("\"paths\" of an equation must be an array of "
                                    "two paths, found {}",
                                    paths->is_array()
                                        ? std::to_string(paths->items.size()) + " paths"
                                        : paths->describe()));
            return;
        }
        if (!d || codom == nullptr) {
            return;
        }
        auto lhs = read_path(paths->items[0], *d);
        auto rhs = read_path(paths->items[1], *d);
        if (!lhs || !rhs) {
            return;
        }
        bool ok = true;
        for (const auto* p : {&*lhs, &*rhs}) {
            std::string end = path_codom_name(*s_, *p);
            if (end != codom->string) {
                const Node& where = paths->items[p == &*lhs ? 0 : 1];
                sink_.error(where.head(), fmt::format("this path ends at '{}', but the equation's "
                                                      "codomain is '{}'",
                                                      end, codom->string));
                ok = false;
            }
        }
        if (ok) {
            s_->add_equation({name, std::move(*lhs), std::move(*rhs), e.head()});
        }
    }

    std::shared_ptr<Schema> s_;
    DiagnosticSink& sink_;
};

} // namespace

schema::SchemaPtr read_schema(std::string name, std::uint32_t file, const SourceManager& sources,
                              DiagnosticSink& sink) {
    std::size_t errors_before = sink.num_errors();
    auto root = detail::parse_located(file, sources, sink);
    if (!root) {
        return nullptr;
    }
    auto s = SchemaReader(std::move(name), sink).read(*root);
    if (sink.num_errors() > errors_before) {
        return nullptr;
    }
    return s;
}

} // namespace catplan::json
