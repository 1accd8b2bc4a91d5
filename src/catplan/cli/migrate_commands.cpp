// `catplan migrate`: a state carried along an ontology map (Δ_F), and `catplan migrate-domain`:
// the actions of a domain carried along one.

#include "catplan/acset/printer.hpp"
#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/cli/json_output.hpp"
#include "catplan/json/json.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/migrate/sigma.hpp"
#include "catplan/transfer/transfer.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

namespace catplan::cli {
namespace {

struct MigrateArgs {
    std::string file, map, state, output, format = "text";
    bool sigma = false;
};

// The state as the command prints it: a heading and tables, or Catlab's ACSet JSON.
std::string state_text(const MigrateArgs& a, const std::string& heading, const acset::ACSet& y) {
    if (a.format == "json") {
        return json::write_acset(y, /*pretty=*/true) + "\n";
    }
    return heading + acset::to_tables(y);
}

// The map `name` of a loaded module; nullptr with an error on err.
const migrate::SchemaMap* find_map(const lang::Module& m, const std::string& file,
                                   const std::string& name, std::ostream& err) {
    const auto* d = find_declaration(m, file, name, lang::DeclKind::Map, err);
    return d == nullptr ? nullptr : d->map.get();
}

// `--sigma`: the state, on the map's target, pushed to its source (Σ_F, the left adjoint of Δ_F).
int push_forward(const MigrateArgs& a, const migrate::SchemaMap& f, const lang::Declaration& x,
                 std::ostream& out, std::ostream& err) {
    if (x.schema != f.target()) {
        error(err, fmt::format("'{}' is on schema {}, but Σ along map '{}' takes states on {}",
                               a.state, x.schema->name(), a.map, f.target()->name()));
        return kBadInput;
    }
    auto y = migrate::sigma(f, *x.instance);
    if (!y) {
        error(err, fmt::format("cannot push '{}' along '{}': {}", a.state, a.map, y.error()));
        return kUnsupported;
    }
    std::string text = state_text(
        a,
        fmt::format("instance {} pushed along {} (Σ), on {}\n", a.state, a.map, f.source()->name()),
        *y);
    return emit(text, a.output, out, err);
}

int cmd_migrate(const MigrateArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto m = load(s, a.file, err);
    if (!m) {
        return kBadInput;
    }
    if (a.state.empty()) {
        error(err, "migrate needs STATE, or --db URL to migrate the state stored in a database");
        return kBadInput;
    }
    const auto* f = find_map(*m, a.file, a.map, err);
    const auto* x = find_declaration(*m, a.file, a.state, lang::DeclKind::Instance, err);
    if (f == nullptr || x == nullptr) {
        return kBadInput;
    }
    if (a.sigma) {
        return push_forward(a, *f, *x, out, err);
    }
    if (x->schema != f->source()) {
        error(err, fmt::format("'{}' is on schema {}, but map '{}' migrates states on {}", a.state,
                               x->schema->name(), a.map, f->source()->name()));
        return kBadInput;
    }
    acset::ACSet y = migrate::migrate(*f, *x->instance);
    std::string text = state_text(
        a,
        fmt::format("instance {} migrated along {}, on {}\n", a.state, a.map, f->target()->name()),
        y);
    return emit(text, a.output, out, err);
}

struct MigrateDomainArgs {
    std::string file, map, domain, output, format = "text";
};

// --format cp: the target schema and the migrated domain as a file of the language, loadable
// again (the rules that did not migrate named in comments); exit 3 when one did not migrate, and
// nothing written when the language cannot write one of them.
int migrated_domain_file(const MigrateDomainArgs& a, const migrate::SchemaMap& f,
                         const plan::Domain& d, std::ostream& out, std::ostream& err) {
    auto md = transfer::migrate_domain(f, d);
    for (const auto& rule : md.domain->rules) {
        // A conjunctive map may send one parameter to parts of several target objects, which the
        // language's parameter list cannot say (one generator per parameter).
        const auto& ps = rule->parameters;
        for (std::size_t i = 1; i < ps.size(); ++i) {
            if (ps[i].name == ps[i - 1].name) {
                error(err, fmt::format("the domain {} migrated along {} cannot be written as a .cp "
                                       "file: the migrated rule '{}' binds its parameter '{}' to "
                                       "a part of {} and one of {}, and a parameter of the "
                                       "language names one part",
                                       a.domain, a.map, rule->name, ps[i].name,
                                       f.target()->ob(ps[i - 1].ob).name,
                                       f.target()->ob(ps[i].ob).name));
                return kUnsupported;
            }
        }
    }
    auto domain = lang::print_domain(*md.domain);
    if (!domain) {
        error(err, fmt::format("the domain {} migrated along {} cannot be written as a .cp file: "
                               "{}",
                               a.domain, a.map, domain.error()));
        return kUnsupported;
    }
    std::string text = fmt::format("# The domain {} of {} migrated along {} (catplan "
                                   "migrate-domain): Δ_F of each rule, on {}.\n",
                                   a.domain, a.file, a.map, f.target()->name());
    for (const auto& [rule, why] : md.failures) {
        text += fmt::format("# not migrated: {}: {}\n", rule, why);
    }
    text += "\n" + lang::print_schema(*f.target()) + "\n" + *domain;
    int rc = emit(text, a.output, out, err);
    return rc != kOk ? rc : md.failures.empty() ? kOk : kUnsupported;
}

int cmd_migrate_domain(const MigrateDomainArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto m = load(s, a.file, err);
    if (!m) {
        return kBadInput;
    }
    const auto* f = find_map(*m, a.file, a.map, err);
    const auto* d = find_declaration(*m, a.file, a.domain, lang::DeclKind::Domain, err);
    if (f == nullptr || d == nullptr) {
        return kBadInput;
    }
    if (d->schema != f->source()) {
        error(err, fmt::format("domain '{}' is on schema {}, but map '{}' migrates {}", a.domain,
                               d->schema->name(), a.map, f->source()->name()));
        return kBadInput;
    }
    if (a.format == "cp") {
        return migrated_domain_file(a, *f, *d->domain, out, err);
    }
    bool json = a.format == "json";
    nlohmann::ordered_json doc = {
        {"domain", a.domain}, {"map", a.map}, {"schema", f->target()->name()}};
    doc["rules"] = nlohmann::ordered_json::array();
    if (!json) {
        out << fmt::format("domain {} migrated along {}, on {}\n", a.domain, a.map,
                           f->target()->name());
    }
    int rc = kOk;
    for (const auto& rule : d->domain->rules) {
        auto migrated = migrate::migrate(*f, *rule);
        if (!migrated) {
            doc["rules"].push_back({{"name", rule->name}, {"error", migrated.error()}});
            out << (json ? ""
                         : fmt::format("  {}: not migrated: {}\n", rule->name, migrated.error()));
            rc = kUnsupported;
            continue;
        }
        doc["rules"].push_back({{"name", migrated->name},
                                {"summary", lang::summarize_rule(*migrated)},
                                {"Pre", acset_value(migrated->L)},
                                {"Keep", acset_value(migrated->K)},
                                {"Eff", acset_value(migrated->R)}});
        if (json) {
            continue;
        }
        out << rule_tables(*migrated, 2);
    }
    out << (json ? json_text(doc) : "");
    return rc;
}

} // namespace

void add_migrate_commands(CLI::App& app, CommandTable& table) {
    // The arguments live as long as the table's functions that read them.
    auto migrate_args = std::make_shared<MigrateArgs>();
    auto* migrate_cmd = app.add_subcommand(
        "migrate", "Carry a state along an ontology map (Δ_F) and print it as tables");
    migrate_cmd->add_option("FILE", migrate_args->file, "language file (.cp)")->required();
    migrate_cmd->add_option("--map", migrate_args->map, "a map declared in FILE")->required();
    migrate_cmd->add_option("STATE", migrate_args->state,
                            "an instance on the map's source schema (not with --db)");
    migrate_cmd->add_option("-o,--output", migrate_args->output,
                            "write to this file instead of stdout");
    migrate_cmd
        ->add_option("--format", migrate_args->format,
                     "text (tables) or json (Catlab's ACSet JSON)")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
    migrate_cmd->add_flag(
        "--sigma", migrate_args->sigma,
        "push STATE, on the map's target schema, to its source instead (Σ_F, "
        "the left adjoint of Δ_F; delta maps only; exit 3 when it cannot be done)");
    auto in_database = add_migrate_db_options(*migrate_cmd, migrate_args->file, migrate_args->map,
                                              migrate_args->state);
    table.add(migrate_cmd, [migrate_args, in_database](std::ostream& o, std::ostream& e) {
        if (auto rc = in_database(o, e)) {
            return *rc;
        }
        return cmd_migrate(*migrate_args, o, e);
    });

    auto domain_args = std::make_shared<MigrateDomainArgs>();
    auto* domain_cmd = app.add_subcommand(
        "migrate-domain", "Carry the actions of a domain along an ontology map and summarize them "
                          "(exit 3 when one cannot be migrated)");
    domain_cmd->add_option("FILE", domain_args->file, "language file (.cp)")->required();
    domain_cmd->add_option("--map", domain_args->map, "a map declared in FILE")->required();
    domain_cmd->add_option("--domain", domain_args->domain, "a domain on the map's source schema")
        ->required();
    domain_cmd
        ->add_option("--format", domain_args->format,
                     "text (tables), json (each rule's Pre, Keep and Eff as Catlab's ACSet JSON) "
                     "or cp (the target schema and the migrated domain, a file catplan loads)")
        ->check(CLI::IsMember({"text", "json", "cp"}))
        ->capture_default_str();
    domain_cmd->add_option("-o,--output", domain_args->output,
                           "write to this file instead of stdout (atomically)");
    table.add(domain_cmd, [domain_args](std::ostream& o, std::ostream& e) {
        return cmd_migrate_domain(*domain_args, o, e);
    });
}

} // namespace catplan::cli
