// `catplan check`, `show` and `homs`: what files declare, one declaration, the homomorphisms
// between two instances; as text or, with --format json, as docs/json-output.md describes.

#include "catplan/acset/printer.hpp"
#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/cli/json_output.hpp"
#include "catplan/cli/options.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/describe.hpp"
#include "catplan/schema/printer.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

namespace catplan::cli {

namespace {

// ---- check ----------------------------------------------------------------------------------

int cmd_check(const std::vector<std::string>& files, bool json, std::ostream& out,
              std::ostream& err) {
    Session s;
    std::vector<lang::Module> modules;
    for (const auto& f : files) {
        modules.push_back(lang::load_file(f, s.sources, s.sink));
    }
    if (report(s, err)) {
        return input_error(s);
    }
    nlohmann::ordered_json doc = {{"files", nlohmann::ordered_json::array()}};
    for (std::size_t i = 0; i < files.size(); ++i) {
        nlohmann::ordered_json decls = nlohmann::ordered_json::array();
        for (const auto& d : modules[i].declarations()) {
            if (d.imported) {
                continue;
            }
            if (json) {
                decls.push_back(declaration_json(d));
            } else {
                out << lang::summarize(d) << "\n";
            }
        }
        doc["files"].push_back({{"file", files[i]}, {"declarations", std::move(decls)}});
    }
    if (json) {
        out << json_text(doc);
    }
    return kOk;
}

// ---- show -----------------------------------------------------------------------------------

// Application conditions (of a rule) or goal conditions (of a problem): name, whether negative,
// and the state N.
nlohmann::ordered_json conditions_json(const std::vector<rewrite::ApplicationCondition>& cs) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& c : cs) {
        out.push_back({{"name", c.name}, {"negative", c.negative}, {"N", acset_value(c.n_state)}});
    }
    return out;
}

// A map's actions and functions sections (between PDDL domains), as written: each action
// `source ⇒ target`, each function `target ⇒ source`.
std::string map_sections_text(const lang::Declaration& d) {
    std::string out;
    if (!d.actions.empty()) {
        out += "  actions (source action ⇒ target action):\n";
        for (const auto& c : d.actions) {
            out += fmt::format("    {} ⇒ {}\n", c.source, c.target);
        }
    }
    if (!d.functions.empty()) {
        out += "  functions (target function ⇒ source function):\n";
        for (const auto& c : d.functions) {
            out += fmt::format("    {} ⇒ {}\n", c.target, c.source);
        }
    }
    return out;
}

// The declaration as JSON: its kind, name and summary, and what it holds (docs/json-output.md).
nlohmann::ordered_json show_json(const lang::Declaration& d) {
    nlohmann::ordered_json j = declaration_json(d);
    switch (d.kind) {
    case lang::DeclKind::Schema:
        j["schema"] = schema_value(*d.schema);
        break;
    case lang::DeclKind::Instance:
        j["schema"] = d.schema->name();
        j["acset"] = acset_value(*d.instance);
        break;
    case lang::DeclKind::Rule:
        j["schema"] = d.schema->name();
        j["Pre"] = acset_value(d.rule->L);
        j["Keep"] = acset_value(d.rule->K);
        j["Eff"] = acset_value(d.rule->R);
        j["conditions"] = conditions_json(d.rule->conditions);
        break;
    case lang::DeclKind::Domain:
        j["schema"] = d.schema->name();
        j["rules"] = nlohmann::ordered_json::array();
        for (const auto& r : d.domain->rules) {
            j["rules"].push_back({{"name", r->name}, {"summary", lang::summarize_rule(*r)}});
        }
        break;
    case lang::DeclKind::Problem:
        j["domain"] = d.problem->domain->name;
        j["initial"] = acset_value(*d.problem->initial);
        j["goal"] = acset_value(*d.problem->goal);
        j["goal_conditions"] = conditions_json(d.problem->goal_conditions);
        break;
    case lang::DeclKind::Map:
        j["target"] = d.map->target()->name();
        j["source"] = d.map->source()->name();
        j["entries"] = nlohmann::ordered_json::array();
        for (const auto& line : migrate::describe_map(*d.map)) {
            j["entries"].push_back({{"name", line.name}, {"image", line.image}});
        }
        j["actions"] = nlohmann::ordered_json::array();
        for (const auto& c : d.actions) {
            j["actions"].push_back({{"source", c.source}, {"target", c.target}});
        }
        j["functions"] = nlohmann::ordered_json::array();
        for (const auto& c : d.functions) {
            j["functions"].push_back({{"target", c.target}, {"source", c.source}});
        }
        break;
    }
    return j;
}

int cmd_show(const std::string& file, const std::string& name, bool json, std::ostream& out,
             std::ostream& err) {
    Session s;
    std::optional<lang::Module> m;
    const auto* d = load_declaration(s, file, name, std::nullopt, m, err);
    if (d == nullptr) {
        return kBadInput;
    }
    if (json) {
        out << json_text(show_json(*d));
    } else if (d->kind == lang::DeclKind::Schema) {
        out << schema::describe(*d->schema);
    } else if (d->kind == lang::DeclKind::Map) {
        out << lang::summarize(*d) << "\n"
            << migrate::map_text(migrate::describe_map(*d->map)) << map_sections_text(*d);
    } else if (d->kind == lang::DeclKind::Rule) {
        out << rule_tables(*d->rule, 0);
    } else if (d->kind == lang::DeclKind::Domain) {
        out << lang::summarize(*d) << "\n";
        for (const auto& r : d->domain->rules) {
            out << rule_tables(*r, 2);
        }
    } else if (d->kind == lang::DeclKind::Problem) {
        out << lang::summarize(*d) << "\n";
        out << "  initial:\n" << indent(acset::to_tables(*d->problem->initial), 4);
        out << "  goal:\n" << indent(acset::to_tables(*d->problem->goal), 4);
        for (const auto& c : d->problem->goal_conditions) {
            out << fmt::format("  goal condition {} (the goal holds where it {}):\n", c.name,
                               c.negative ? "does not extend to" : "extends to")
                << indent(acset::to_tables(c.n_state), 4);
        }
    } else if (d->kind != lang::DeclKind::Instance) {
        out << lang::summarize(*d) << "\n";
    } else {
        out << fmt::format("instance {} of {}\n", d->name, d->schema->name());
        out << acset::to_tables(*d->instance);
    }
    return kOk;
}

// ---- homs -----------------------------------------------------------------------------------

// The morphism as text: a line per object (and attribute type) with parts, in schema order.
std::string format_morphism(const hom::ACSetMorphism& f, const acset::ACSet& x,
                            const acset::ACSet& y) {
    const auto& s = x.schema();
    std::string text;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        if (x.num_parts(ob) == 0) {
            continue;
        }
        std::string line;
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            line += fmt::format("{}{} ↦ {}", p ? ", " : "", x.part_label(ob, p),
                                y.part_label(ob, f.components[o][p]));
        }
        text += fmt::format("  {}: {}\n", s.ob(ob).name, line);
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        if (x.num_vars(ty) == 0) {
            continue;
        }
        std::string line;
        for (std::uint32_t j = 0; j < x.num_vars(ty); ++j) {
            line += fmt::format("{}{} ↦ {}", j ? ", " : "", x.value_label(ty, acset::Value::var(j)),
                                y.value_label(ty, f.var_components[t][j]));
        }
        text += fmt::format("  {}: {}\n", s.attr_type(ty).name, line);
    }
    return text;
}

struct HomsArgs {
    std::string file, from, to, format = "text";
    bool monic = false, iso = false, count = false, all = false;
    std::size_t max = 0;
};

int cmd_homs(const HomsArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto m = load(s, a.file, err);
    if (!m) {
        return kBadInput;
    }
    const auto* dx = find_declaration(*m, a.file, a.from, lang::DeclKind::Instance, err);
    const auto* dy = find_declaration(*m, a.file, a.to, lang::DeclKind::Instance, err);
    if (dx == nullptr || dy == nullptr) {
        return kBadInput;
    }
    if (dx->schema != dy->schema) {
        error(err, fmt::format("'{}' is on schema {} but '{}' is on schema {}", a.from,
                               dx->schema->name(), a.to, dy->schema->name()));
        return kBadInput;
    }
    const auto& x = *dx->instance;
    const auto& y = *dy->instance;
    bool json = a.format == "json";
    nlohmann::ordered_json doc = {
        {"from", a.from}, {"to", a.to}, {"monic", a.monic}, {"iso", a.iso}};
    hom::HomSearchOptions options;
    options.monic_all = a.monic;
    options.iso = a.iso;
    if (a.count) {
        auto result = hom::count_homomorphisms(x, y, options);
        if (!result.error.empty()) {
            error(err, result.error);
            return kBadInput;
        }
        doc["count"] = result.count;
        out << (json ? json_text(doc) : fmt::format("{}\n", result.count));
        return result.count > 0 ? kOk : kNo;
    }
    options.max_results = a.all ? a.max : 1; // 0 = no limit
    auto result = hom::find_homomorphisms(x, y, options);
    if (!result.error.empty()) {
        error(err, result.error);
        return kBadInput;
    }
    if (json) {
        doc["homomorphisms"] = nlohmann::ordered_json::array();
        for (const auto& f : result.morphisms) {
            doc["homomorphisms"].push_back(morphism_json(f, x, y));
        }
        out << json_text(doc);
    } else if (result.morphisms.empty()) {
        out << fmt::format("no {}homomorphism from {} to {}\n", a.monic ? "monic " : "", a.from,
                           a.to);
    }
    for (std::size_t i = 0; i < result.morphisms.size() && !json; ++i) {
        out << fmt::format("homomorphism {}:\n", i + 1);
        out << format_morphism(result.morphisms[i], x, y);
    }
    return result.morphisms.empty() ? kNo : kOk;
}

// --format text|json on cmd, into `format`.
void add_format_option(CLI::App* cmd, std::string& format) {
    cmd->add_option("--format", format, "text or json (docs/json-output.md)")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
}

} // namespace

void add_inspect_commands(CLI::App& app, CommandTable& table) {
    // The arguments live as long as the table's functions that read them.
    struct Args {
        std::vector<std::string> check_files;
        std::string check_format = "text", show_file, show_name, show_format = "text";
        HomsArgs homs_args;
    };

    auto args = std::make_shared<Args>();
    auto* check = app.add_subcommand("check", "Parse and validate files; one summary line per "
                                              "declaration");
    check->add_option("FILE", args->check_files, "language files (.cp)")->required();
    add_format_option(check, args->check_format);

    auto* show = app.add_subcommand("show", "Print a declaration: a schema as lists, a state or "
                                            "the states of a rule, domain or problem as tables");
    show->add_option("FILE", args->show_file)->required();
    show->add_option("NAME", args->show_name,
                     "a declaration of FILE: schema, instance, rule, domain, problem or map")
        ->required();
    add_format_option(show, args->show_format);

    auto* homs = app.add_subcommand("homs", "Find homomorphisms between two instances "
                                            "(exit 1 when there are none)");
    homs->add_option("FILE", args->homs_args.file)->required();
    homs->add_option("A", args->homs_args.from, "domain instance")->required();
    homs->add_option("B", args->homs_args.to, "codomain instance")->required();
    homs->add_flag("--monic", args->homs_args.monic, "injective on every object");
    homs->add_flag("--iso", args->homs_args.iso, "isomorphisms only");
    auto* count_flag = homs->add_flag("--count", args->homs_args.count, "print how many there are");
    homs->add_flag("--all", args->homs_args.all, "print all of them (default: the first)")
        ->excludes(count_flag);
    homs->add_option("--max", args->homs_args.max, "with --all, stop after this many")
        ->check(positive_count());
    add_format_option(homs, args->homs_args.format);

    using O = std::ostream;
    table.add(check, [args](O& o, O& e) {
        return cmd_check(args->check_files, args->check_format == "json", o, e);
    });
    table.add(show, [args](O& o, O& e) {
        return cmd_show(args->show_file, args->show_name, args->show_format == "json", o, e);
    });
    table.add(homs, [args](O& o, O& e) { return cmd_homs(args->homs_args, o, e); });
}

} // namespace catplan::cli
