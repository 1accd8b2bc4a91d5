// Reading and writing states in Catlab's ACSet JSON (see json.hpp for the format).

#include "catplan/base/assert.hpp"
#include "catplan/json/detail/located_json.hpp"
#include "catplan/json/json.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace catplan::json {

using acset::ACSet;
using acset::Value;
using detail::Node;
using schema::ValueKind;
using OrderedJson = nlohmann::ordered_json;

namespace {

// The key of a row that carries the name of its part or variable (catplan's own; see json.hpp).
constexpr const char* kNameKey = "_name";

// Catlab writes 1-based ids and 0 for "unset".
std::int64_t to_json_id(Part p) {
    return p == kNoPart ? 0 : static_cast<std::int64_t>(p) + 1;
}

OrderedJson value_to_json(const Value& v) {
    if (v.is_var()) {
        OrderedJson var = OrderedJson::object();
        var["_var"] = static_cast<std::int64_t>(v.var_index()) + 1;
        return var;
    }
    return v.visit_concrete(
        [](auto x) {
            if constexpr (std::is_same_v<decltype(x), std::string_view>) {
                return OrderedJson(std::string(x));
            } else {
                return OrderedJson(x);
            }
        },
        OrderedJson(nullptr));
}

} // namespace

std::string dump(const nlohmann::json& doc, int indent) {
    return doc.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string dump(const nlohmann::ordered_json& doc, int indent) {
    return doc.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string write_acset(const ACSet& x, bool pretty, bool names) {
    const auto& s = x.schema();
    OrderedJson out = OrderedJson::object();
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        ObId ob(i);
        OrderedJson rows = OrderedJson::array();
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            OrderedJson row = OrderedJson::object();
            row["_id"] = static_cast<std::int64_t>(p) + 1;
            if (names && !x.part_name(ob, p).empty()) {
                row[kNameKey] = std::string(x.part_name(ob, p));
            }
            for (HomId f : s.homs_from(ob)) {
                row[s.hom(f).name] = to_json_id(x.subpart(f, p));
            }
            for (AttrId a : s.attrs_from(ob)) {
                row[s.attr(a).name] = value_to_json(x.subpart(a, p));
            }
            rows.push_back(std::move(row));
        }
        out[s.ob(ob).name] = std::move(rows);
    }
    for (std::uint32_t i = 0; i < s.num_attr_types(); ++i) {
        AttrTypeId t(i);
        OrderedJson rows = OrderedJson::array();
        for (std::uint32_t j = 0; j < x.num_vars(t); ++j) {
            OrderedJson row = OrderedJson::object();
            row["_id"] = static_cast<std::int64_t>(j) + 1;
            if (names && !x.var_name(t, j).empty()) {
                row[kNameKey] = std::string(x.var_name(t, j));
            }
            rows.push_back(std::move(row));
        }
        out[s.attr_type(t).name] = std::move(rows);
    }
    return dump(out, pretty ? 2 : -1);
}

namespace {

// One attribute cell waiting for its kind to be known.
struct Cell {
    AttrId attr;
    Part part;
    const Node* node;
};

// The state being read, checked in two passes: structure first (counts, ids, homs), then values,
// once the kinds of Unknown attribute types have been inferred from all the cells.
class AcsetReader {
public:
    AcsetReader(const schema::SchemaPtr& schema, DiagnosticSink& sink)
        : schema_(schema),
          s_(*schema),
          sink_(sink),
          nparts_(s_.num_obs(), 0),
          nvars_(s_.num_attr_types(), 0),
          kinds_(s_.num_attr_types()),
          kind_sources_(s_.num_attr_types(), nullptr),
          part_names_(s_.num_obs()),
          var_names_(s_.num_attr_types()) {
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            kinds_[t] = s_.attr_type(AttrTypeId(t)).kind;
        }
    }

    std::optional<ACSet> read(const Node& root) {
        std::size_t errors_before = sink_.num_errors();
        if (!root.is_object()) {
            sink_.error(root.head(),
                        fmt::format("expected a JSON object with one array per object and "
                                    "attribute type of schema '{}', found {}",
                                    s_.name(), root.describe()));
            return std::nullopt;
        }
        // Values are checked even when the structure has errors, so that one run reports all.
        read_tables(root);
        infer_kinds();
        std::vector<Value> values;
        values.reserve(cells_.size());
        for (const Cell& cell : cells_) {
            values.push_back(convert(cell));
        }
        if (sink_.num_errors() > errors_before) {
            return std::nullopt;
        }
        ACSet x = build(values);
        check_equations(x);
        if (sink_.num_errors() > errors_before) {
            return std::nullopt;
        }
        return x;
    }

private:
    void read_tables(const Node& root) {
        std::vector<const Node*> ob_tables(s_.num_obs(), nullptr);
        std::vector<const Node*> var_tables(s_.num_attr_types(), nullptr);
        for (std::size_t i = 0; i < root.keys.size(); ++i) {
            const std::string& key = root.keys[i];
            const Node& table = root.items[i];
            auto gen = s_.find(key);
            const Node** slot = nullptr;
            if (gen && gen->kind == schema::GeneratorKind::Ob) {
                slot = &ob_tables[gen->index];
            } else if (gen && gen->kind == schema::GeneratorKind::AttrType) {
                slot = &var_tables[gen->index];
            } else {
                sink_.error(root.key_ranges[i],
                            gen ? fmt::format("'{}' is a {} of schema '{}', not an object or "
                                              "attribute type",
                                              key, kind_name(gen->kind), s_.name())
                                : fmt::format("unknown object or attribute type '{}' in schema "
                                              "'{}'",
                                              key, s_.name()));
                continue;
            }
            if (!table.is_array()) {
                sink_.error(table.head(),
                            fmt::format("expected an array of rows for '{}', found {}", key,
                                        table.describe()));
                continue;
            }
            if (*slot == nullptr) { // a duplicate key is reported by the parser
                *slot = &table;
            }
        }
        // A missing table has no rows, as ACSets.jl reads it (it adds parts per key present).
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            if (ob_tables[i] != nullptr) {
                nparts_[i] = ob_tables[i]->items.size();
            }
        }
        for (std::uint32_t i = 0; i < s_.num_attr_types(); ++i) {
            if (var_tables[i] != nullptr) {
                nvars_[i] = var_tables[i]->items.size();
            }
        }
        // Counts are known now, so hom targets and variable numbers can be checked.
        for (std::uint32_t i = 0; i < s_.num_attr_types(); ++i) {
            if (var_tables[i] != nullptr) {
                read_var_rows(AttrTypeId(i), *var_tables[i]);
            }
        }
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            if (ob_tables[i] != nullptr) {
                read_rows(ObId(i), *ob_tables[i]);
            }
        }
        ob_tables_ = std::move(ob_tables);
    }

    static const char* kind_name(schema::GeneratorKind kind) {
        switch (kind) {
        case schema::GeneratorKind::Ob:
            return "object";
        case schema::GeneratorKind::Hom:
            return "hom";
        case schema::GeneratorKind::AttrType:
            return "attribute type";
        case schema::GeneratorKind::Attr:
            return "attribute";
        }
        return "name";
    }

    // Checks a row is an object whose "_id", if any, is its 1-based position (Catlab before 2023
    // wrote none, and `{}` for a variable); false if not an object.
    bool check_row(const Node& row, std::size_t index, const std::string& table) {
        if (!row.is_object()) {
            sink_.error(row.head(), fmt::format("row {} of '{}' must be an object, found {}",
                                                index + 1, table, row.describe()));
            return false;
        }
        const Node* id = row.find("_id");
        if (id != nullptr &&
            (id->kind != Node::Kind::Int || id->integer != static_cast<std::int64_t>(index) + 1)) {
            sink_.error(id->range, fmt::format("\"_id\" of row {} of '{}' must be {} (ids are the "
                                               "1-based row numbers), found {}",
                                               index + 1, table, index + 1, id->describe()));
        }
        return true;
    }

    void read_var_rows(AttrTypeId t, const Node& table) {
        const std::string& name = s_.attr_type(t).name;
        for (std::size_t j = 0; j < table.items.size(); ++j) {
            const Node& row = table.items[j];
            if (!check_row(row, j, name)) {
                continue;
            }
            for (std::size_t k = 0; k < row.keys.size(); ++k) {
                if (row.keys[k] == kNameKey) {
                    read_name(row.items[k], var_names_[t.index()], j);
                } else if (row.keys[k] != "_id") {
                    sink_.error(row.key_ranges[k],
                                fmt::format("unexpected key '{}' in a variable of attribute type "
                                            "'{}' (only \"_id\" and \"_name\" are allowed)",
                                            row.keys[k], name));
                }
            }
        }
    }

    void read_rows(ObId ob, const Node& table) {
        const std::string& ob_name = s_.ob(ob).name;
        homs_.resize(s_.num_homs());
        for (std::size_t p = 0; p < table.items.size(); ++p) {
            const Node& row = table.items[p];
            if (!check_row(row, p, ob_name)) {
                continue;
            }
            for (std::size_t k = 0; k < row.keys.size(); ++k) {
                const std::string& key = row.keys[k];
                const Node& cell = row.items[k];
                if (key == "_id") {
                    continue;
                }
                if (key == kNameKey) {
                    read_name(cell, part_names_[ob.index()], p);
                    continue;
                }
                auto gen = s_.find(key);
                if (gen && gen->kind == schema::GeneratorKind::Hom &&
                    s_.hom(HomId(gen->index)).dom == ob) {
                    read_hom(HomId(gen->index), static_cast<Part>(p), cell);
                } else if (gen && gen->kind == schema::GeneratorKind::Attr &&
                           s_.attr(AttrId(gen->index)).dom == ob) {
                    cells_.push_back({AttrId(gen->index), static_cast<Part>(p), &cell});
                } else {
                    sink_.error(row.key_ranges[k],
                                fmt::format("'{}' is not a hom or attribute out of object '{}'",
                                            key, ob_name));
                }
            }
        }
    }

    // A "_name" must be a string; names are labels, so two rows may share one.
    void read_name(const Node& cell, std::vector<std::string>& names, std::size_t row) {
        if (cell.kind != Node::Kind::String) {
            sink_.error(cell.head(),
                        fmt::format("\"_name\" must be a string, found {}", cell.describe()));
            return;
        }
        names.resize(std::max(names.size(), row + 1));
        names[row] = cell.string;
    }

    void read_hom(HomId f, Part p, const Node& cell) {
        const auto& hom = s_.hom(f);
        std::size_t n = nparts_[hom.codom.index()];
        if (cell.kind != Node::Kind::Int) {
            sink_.error(cell.head(), fmt::format("hom '{}' needs a part id of '{}' (an integer, 0 "
                                                 "for unset), found {}",
                                                 hom.name, s_.ob(hom.codom).name, cell.describe()));
            return;
        }
        if (cell.integer < 0 || static_cast<std::uint64_t>(cell.integer) > n) {
            sink_.error(cell.range,
                        fmt::format("hom '{}' of {} #{} points to {} #{}, but '{}' has "
                                    "{} part{}",
                                    hom.name, s_.ob(hom.dom).name, p + 1, s_.ob(hom.codom).name,
                                    cell.integer, s_.ob(hom.codom).name, n, n == 1 ? "" : "s"));
            return;
        }
        if (cell.integer > 0) {
            homs_[f.index()].emplace_back(p, static_cast<Part>(cell.integer - 1));
        }
    }

    static std::optional<ValueKind> json_kind(const Node& n) {
        switch (n.kind) {
        case Node::Kind::Bool:
            return ValueKind::Bool;
        case Node::Kind::Int:
        case Node::Kind::BigInt:
            return ValueKind::Int;
        case Node::Kind::Float:
            return ValueKind::Float;
        case Node::Kind::String:
            return ValueKind::String;
        default:
            return std::nullopt;
        }
    }

    // Catlab's file has no kinds, so an Unknown attribute type takes the kind of the first
    // concrete value met; Int widens to Float when a float appears too (JSON writers drop ".0").
    void infer_kinds() {
        for (const Cell& cell : cells_) {
            auto t = s_.attr(cell.attr).codom.index();
            if (s_.attr_type(AttrTypeId(t)).kind != ValueKind::Unknown) {
                continue;
            }
            auto k = json_kind(*cell.node);
            if (!k) {
                continue;
            }
            if (kinds_[t] == ValueKind::Unknown) {
                kinds_[t] = *k;
                kind_sources_[t] = cell.node;
            } else if (kinds_[t] == ValueKind::Int && *k == ValueKind::Float) {
                kinds_[t] = ValueKind::Float;
                kind_sources_[t] = cell.node;
            }
        }
    }

    Value convert(const Cell& cell) {
        const Node& n = *cell.node;
        const auto& attr = s_.attr(cell.attr);
        auto t = attr.codom;
        ValueKind want = kinds_[t.index()];
        if (n.kind == Node::Kind::Null) {
            return Value();
        }
        if (n.is_object()) {
            return convert_var(cell, attr);
        }
        auto got = json_kind(n);
        if (!got) {
            sink_.error(n.head(), fmt::format("attribute '{}' needs a value, {{\"_var\": j}} or "
                                              "null, found {}",
                                              attr.name, n.describe()));
            return Value();
        }
        if (n.kind == Node::Kind::BigInt && want != ValueKind::Float) {
            sink_.error(n.range, fmt::format("integer out of range for attribute '{}'", attr.name));
            return Value();
        }
        if (*got == want || (*got == ValueKind::Int && want == ValueKind::Float)) {
            switch (n.kind) {
            case Node::Kind::Bool:
                return Value::boolean(n.boolean);
            case Node::Kind::Int:
                return want == ValueKind::Float ? Value::real(static_cast<double>(n.integer))
                                                : Value::integer(n.integer);
            case Node::Kind::BigInt:
            case Node::Kind::Float:
                return Value::real(n.real);
            case Node::Kind::String:
                return Value::string(n.string);
            default:
                break;
            }
        }
        auto& d = sink_.error(n.range, fmt::format("attribute '{}' has type '{}' of kind {}, but "
                                                   "found {}",
                                                   attr.name, s_.attr_type(t).name,
                                                   schema::to_string(want), n.describe()));
        if (const Node* source = kind_sources_[t.index()]) {
            d.notes.emplace_back(
                source->range,
                fmt::format("the kind of '{}' was inferred from this value", s_.attr_type(t).name));
        }
        return Value();
    }

    // {"_var": j}, or the older {"val": j}, names variable j (1-based) of the attribute type.
    Value convert_var(const Cell& cell, const schema::AttrInfo& attr) {
        const Node& n = *cell.node;
        std::size_t nvars = nvars_[attr.codom.index()];
        const std::string& type_name = s_.attr_type(attr.codom).name;
        if (n.keys.size() != 1 || (n.keys[0] != "_var" && n.keys[0] != "val")) {
            sink_.error(n.head(), fmt::format("attribute '{}': an object value must be "
                                              "{{\"_var\": j}}, naming variable j of '{}'",
                                              attr.name, type_name));
            return Value();
        }
        const Node& j = n.items[0];
        if (j.kind != Node::Kind::Int || j.integer < 1 ||
            static_cast<std::uint64_t>(j.integer) > nvars) {
            sink_.error(j.range, fmt::format("attribute '{}' of {} #{} names variable {} of '{}', "
                                             "but '{}' has {} variable{}",
                                             attr.name, s_.ob(attr.dom).name, cell.part + 1,
                                             j.kind == Node::Kind::Int ? std::to_string(j.integer)
                                                                       : j.describe(),
                                             type_name, type_name, nvars, nvars == 1 ? "" : "s"));
            return Value();
        }
        return Value::var(static_cast<std::uint32_t>(j.integer - 1));
    }

    // Where a path leads from part p: a part (as an integer Value) or an attribute value; nullopt
    // when a hom on the way is unset, which no equation can be checked against.
    static std::optional<Value> follow(const ACSet& x, const schema::Path& path, Part p) {
        for (HomId f : path.homs) {
            p = x.subpart(f, p);
            if (p == kNoPart) {
                return std::nullopt;
            }
        }
        if (!path.attr) {
            return Value::integer(static_cast<std::int64_t>(p));
        }
        const Value& v = x.subpart(*path.attr, p);
        return v.is_unset() ? std::nullopt : std::optional<Value>(v);
    }

    std::string describe_end(const schema::Path& path, const Value& v) const {
        if (path.attr) {
            return v.is_var() ? fmt::format("variable {} of '{}'", v.var_index() + 1,
                                            s_.attr_type(s_.attr(*path.attr).codom).name)
                              : v.to_string();
        }
        ObId end = s_.path_codom_ob(path);
        return fmt::format("{} #{}", s_.ob(end).name, v.as_int() + 1);
    }

    // The schema's path equations must hold in the state (Catlab's reader does not check them;
    // a state that breaks them is not an instance of the schema). Each violation is reported at
    // its row, up to kMaxViolations per equation.
    void check_equations(const ACSet& x) {
        static constexpr std::size_t kMaxViolations = 10;
        for (const auto& eq : s_.equations()) {
            std::size_t found = 0;
            ObId dom = eq.lhs.dom;
            const Node* table = ob_tables_[dom.index()];
            std::string words = eq.name.empty() ? std::string() : eq.name + ": ";
            words += s_.path_to_string(eq.lhs);
            words += " == ";
            words += s_.path_to_string(eq.rhs);
            for (Part p = 0; p < x.num_parts(dom); ++p) {
                auto l = follow(x, eq.lhs, p), r = follow(x, eq.rhs, p);
                if (!l || !r || *l == *r) {
                    continue;
                }
                if (++found > kMaxViolations) {
                    continue;
                }
                auto& d = sink_.error(
                    table->items[p].head(),
                    fmt::format(
                        "row {} of '{}' breaks the equation {} of schema '{}': {} gives {}, "
                        "{} gives {}",
                        p + 1, s_.ob(dom).name, words, s_.name(), s_.path_to_string(eq.lhs),
                        describe_end(eq.lhs, *l), s_.path_to_string(eq.rhs),
                        describe_end(eq.rhs, *r)));
                if (eq.range.valid()) {
                    d.notes.emplace_back(eq.range, "the equation is declared here");
                }
            }
            if (found > kMaxViolations) {
                sink_.error(table->head(),
                            fmt::format("{} more rows of '{}' break the equation {}",
                                        found - kMaxViolations, s_.ob(dom).name, words));
            }
        }
    }

    ACSet build(const std::vector<Value>& values) {
        schema::SchemaPtr target = schema_;
        bool adjusted = false;
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            adjusted = adjusted || kinds_[t] != s_.attr_type(AttrTypeId(t)).kind;
        }
        if (adjusted) {
            auto copy = std::make_shared<schema::Schema>(s_);
            for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
                copy->set_kind(AttrTypeId(t), kinds_[t]);
            }
            target = std::move(copy);
        }
        ACSet x(target);
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            const auto& names = part_names_[i];
            if (names.empty() && nparts_[i] > 0) {
                x.add_parts(ObId(i), nparts_[i]);
            }
            for (std::size_t p = 0; !names.empty() && p < nparts_[i]; ++p) {
                x.add_part(ObId(i), p < names.size() ? names[p] : std::string_view());
            }
        }
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            const auto& names = var_names_[t];
            for (std::size_t j = 0; j < nvars_[t]; ++j) {
                x.add_var(AttrTypeId(t), j < names.size() ? names[j] : std::string_view());
            }
        }
        for (std::uint32_t f = 0; f < homs_.size(); ++f) {
            for (auto [p, q] : homs_[f]) {
                x.set_subpart(HomId(f), p, q);
            }
        }
        for (std::size_t i = 0; i < cells_.size(); ++i) {
            if (!values[i].is_unset()) {
                x.set_subpart(cells_[i].attr, cells_[i].part, values[i]);
            }
        }
        return x;
    }

    schema::SchemaPtr schema_;
    const schema::Schema& s_;
    DiagnosticSink& sink_;
    std::vector<std::size_t> nparts_;
    std::vector<std::size_t> nvars_;
    std::vector<ValueKind> kinds_;
    std::vector<const Node*> kind_sources_;
    std::vector<std::vector<std::pair<Part, Part>>> homs_; // by hom: (part, target)
    std::vector<Cell> cells_;
    std::vector<const Node*> ob_tables_;               // by object; nullptr when missing
    std::vector<std::vector<std::string>> part_names_; // by object; "" for unnamed
    std::vector<std::vector<std::string>> var_names_;  // by attribute type
};

} // namespace

std::optional<ACSet> read_acset(const schema::SchemaPtr& schema, std::uint32_t file,
                                const SourceManager& sources, DiagnosticSink& sink) {
    CATPLAN_ASSERT(schema != nullptr, "read_acset needs a schema");
    std::size_t errors_before = sink.num_errors();
    auto root = detail::parse_located(file, sources, sink);
    if (!root) {
        return std::nullopt;
    }
    auto x = AcsetReader(schema, sink).read(*root);
    // Duplicate keys are reported by the parser, which still yields a tree so that the semantic
    // errors come in the same run.
    if (sink.num_errors() > errors_before) {
        return std::nullopt;
    }
    return x;
}

bool looks_like_schema(std::string_view text) {
    auto doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) {
        return false;
    }
    auto ob = doc.find("Ob");
    auto hom = doc.find("Hom");
    if (ob == doc.end() || hom == doc.end() || !ob->is_array() || !hom->is_array()) {
        return false;
    }
    // An instance of a schema with objects named Ob and Hom has rows with "_id", not "name".
    return ob->empty() || (ob->front().is_object() && ob->front().contains("name"));
}

} // namespace catplan::json
