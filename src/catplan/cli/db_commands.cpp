// `catplan db export|import`: a state as tables of a SQLite file or a PostgreSQL database
// (docs/database.md).

#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/db/library.hpp"
#include "catplan/db/migrate_sql.hpp"
#include "catplan/db/tables.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <ostream>
#include <sstream>

namespace catplan::cli {
namespace {

struct DbArgs {
    std::string file, name, db, ns, output, as_name = "Imported";
    bool replace = false;
};

// Prints every error of a database command; returns kBadInput.
int db_errors(const std::vector<std::string>& errors, std::ostream& err) {
    for (const auto& e : errors) {
        error(err, e);
    }
    return kBadInput;
}

int cmd_db_export(const DbArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto m = load(s, a.file, err);
    if (!m) {
        return kBadInput;
    }
    const auto* x = find_declaration(*m, a.file, a.name, lang::DeclKind::Instance, err);
    if (x == nullptr) {
        return kBadInput;
    }
    std::string ns = a.ns.empty() ? x->schema->name() : a.ns;
    if (auto st = db::export_state(a.db, *x->instance, ns, a.replace); !st) {
        return db_errors({st.error()}, err);
    }
    out << fmt::format("exported {} ({} parts) to {} as the tables of {}\n", a.name,
                       x->instance->total_parts(), a.db, ns);
    return kOk;
}

int cmd_db_import(const DbArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto m = load(s, a.file, err);
    if (!m) {
        return kBadInput;
    }
    const auto* d = find_declaration(*m, a.file, a.name, lang::DeclKind::Schema, err);
    if (d == nullptr) {
        return kBadInput;
    }
    db::ReadState r = db::import_state(a.db, d->schema, a.ns.empty() ? d->schema->name() : a.ns);
    if (!r.state) {
        return db_errors(r.errors, err);
    }
    return emit(lang::print_instance(*r.state, a.as_name), a.output, out, err);
}

// The options every db subcommand shares.
void add_db_option(CLI::App* cmd, DbArgs& a) {
    cmd->add_option("--db", a.db, "the database: sqlite:PATH or postgresql://...")->required();
    cmd->add_option("--as", a.ns,
                    "the namespace of the tables (default: the schema's name; a PostgreSQL "
                    "schema, a table-name prefix NS. in SQLite)");
}

struct MigrateDbArgs {
    std::string db, from, to;
    bool replace = false, print_sql = false;
};

// `catplan migrate FILE --map M --db URL`: the migration compiled to SQL and run in the database.
int cmd_migrate_db(const MigrateDbArgs& a, const std::string& file, const std::string& map,
                   const std::string& state, std::ostream& out, std::ostream& err) {
    if (!state.empty()) {
        error(err, fmt::format("with --db the state is the one stored in the database, so STATE "
                               "('{}') is not used: store it first with `catplan db export`",
                               state));
        return kBadInput;
    }
    auto url = db::parse_url(a.db);
    if (!url) {
        return db_errors({url.error()}, err);
    }
    Session s;
    std::optional<lang::Module> m;
    const auto* d = load_declaration(s, file, map, lang::DeclKind::Map, m, err);
    if (d == nullptr) {
        return kBadInput;
    }
    const migrate::SchemaMap& f = *d->map;
    std::string from = a.from.empty() ? f.source()->name() : a.from;
    std::string to = a.to.empty() ? f.target()->name() : a.to;
    if (a.print_sql) {
        out << db::migration_sql(f, url->engine, from, to).text();
        return kOk;
    }
    if (auto st = db::migrate_in_database(a.db, f, from, to, a.replace); !st) {
        error(err, fmt::format("cannot migrate the tables of '{}' along {}:", from, map));
        std::string_view why = st.error();
        while (!why.empty()) {
            std::size_t nl = why.find('\n');
            err << "  " << why.substr(0, nl) << "\n";
            why = nl == std::string_view::npos ? std::string_view() : why.substr(nl + 1);
        }
        return kBadInput;
    }
    out << fmt::format("migrated the tables of {} along {} into the tables of {}\n", from, map, to);
    return kOk;
}

struct LibraryArgs {
    std::string file, db, domain, problem, map;
    std::vector<std::string> plans;
    std::size_t jobs = 0, batch = 64, limit = 0;
    bool failed = false, valid = false, list_plans = false;
};

// A connection to the library's database; nullptr with the error printed.
std::unique_ptr<db::Connection> open_database(const std::string& url, bool create,
                                              std::ostream& err) {
    auto c = db::connect(url, create);
    if (!c) {
        db_errors({c.error()}, err);
        return nullptr;
    }
    return std::move(*c);
}

int cmd_library_add(const LibraryArgs& a, std::ostream& out, std::ostream& err) {
    Session s;
    auto m = load(s, a.file, err);
    if (!m) {
        return kBadInput;
    }
    auto problem = find_problem(*m, a.file, a.domain, a.problem, err);
    if (!problem) {
        return kBadInput;
    }
    std::vector<std::pair<std::string, plan::Plan>> plans;
    for (const auto& path : a.plans) {
        auto f = read_input(s, path, err);
        if (!f) {
            return kBadInput;
        }
        auto p = plan::parse_plan(*f, s.sources, s.sink);
        if (report(s, err) || !p) {
            return kBadInput;
        }
        plans.emplace_back(path, std::move(*p));
    }
    std::ifstream in(a.file);
    std::stringstream source;
    source << in.rdbuf();
    auto c = open_database(a.db, /*create=*/true, err);
    if (!c) {
        return kBadInput;
    }
    db::Transaction t(*c);
    if (!t.status()) {
        return db_errors({t.status().error()}, err);
    }
    auto opened = db::open_library(*c);
    if (!opened) {
        return db_errors({opened.error()}, err);
    }
    auto stored = db::add_plans(*c, *problem->domain, source.str(), *problem, plans);
    if (!stored) {
        return db_errors({stored.error()}, err);
    }
    if (auto st = t.commit(); !st) {
        return db_errors({st.error()}, err);
    }
    for (const auto& p : *stored) {
        out << db::to_json_line(p) << "\n";
    }
    return kOk;
}

int cmd_library_transfer(const LibraryArgs& a, std::ostream& out, std::ostream& err) {
    {
        // The map's file is loaded here once so that its errors are printed located.
        Session s;
        auto m = load(s, a.file, err);
        if (!m || find_declaration(*m, a.file, a.map, lang::DeclKind::Map, err) == nullptr) {
            return kBadInput;
        }
    }
    auto c = open_database(a.db, /*create=*/false, err);
    if (!c) {
        return kBadInput;
    }
    db::LibraryTransferOptions options{a.jobs, a.batch, a.limit};
    auto summary = db::transfer_library(*c, a.file, a.map, options, [&](const auto& t) {
        out << db::to_json_line(t) << "\n" << std::flush;
    });
    if (!summary) {
        return db_errors({summary.error()}, err);
    }
    err << fmt::format("catplan: transferred {} plan(s) along {} ({} valid) in {:.2f} s; {} "
                       "transferred before\n",
                       summary->transferred, a.map, summary->valid, summary->seconds,
                       summary->already_done);
    return kOk;
}

int cmd_library_query(const LibraryArgs& a, std::ostream& out, std::ostream& err) {
    if (a.failed && a.valid) {
        error(err, "--failed and --valid exclude each other");
        return kBadInput;
    }
    auto c = open_database(a.db, /*create=*/false, err);
    if (!c) {
        return kBadInput;
    }
    if (auto st = db::open_library(*c); !st) {
        return db_errors({st.error()}, err);
    }
    db::LibraryQuery q{a.map, a.domain, a.problem, std::nullopt};
    if (a.failed || a.valid) {
        q.valid = a.valid;
    }
    auto st =
        a.list_plans
            ? db::query_plans(*c, q, [&](const auto& p) { out << db::to_json_line(p) << "\n"; })
            : db::query_transfers(*c, q,
                                  [&](const auto& t) { out << db::to_json_line(t) << "\n"; });
    if (!st) {
        return db_errors({st.error()}, err);
    }
    return kOk;
}

void add_library_commands(CLI::App& app, CommandTable& table) {
    auto* lib = app.add_subcommand(
        "library", "A plan library in SQLite or PostgreSQL: add plans, transfer them, query");
    lib->require_subcommand(1);

    auto add = std::make_shared<LibraryArgs>();
    auto* add_cmd = lib->add_subcommand("add", "Store a problem and plans of it (JSON Lines out)");
    add_cmd->add_option("FILE", add->file, "language file (.cp) declaring the problem")->required();
    add_cmd->add_option("PLAN", add->plans, "plan files of the problem")->required();
    add_cmd->add_option("--db", add->db, "the library: sqlite:PATH or postgresql://...")
        ->required();
    add_cmd->add_option("--problem", add->problem, "a problem declared in FILE")->required();
    add_cmd->add_option("--domain", add->domain, "the problem's domain (checked)");
    table.add(add_cmd,
              [add](std::ostream& o, std::ostream& e) { return cmd_library_add(*add, o, e); });

    auto tr = std::make_shared<LibraryArgs>();
    auto* tr_cmd = lib->add_subcommand(
        "transfer", "Transfer every stored plan of the map's source domains not yet transferred "
                    "along it, on every core, resumable; results stored and printed as JSON Lines");
    tr_cmd->add_option("FILE", tr->file, "language file (.cp) declaring the map and its domains")
        ->required();
    tr_cmd->add_option("--map", tr->map, "a map declared in FILE")->required();
    tr_cmd->add_option("--db", tr->db, "the library: sqlite:PATH or postgresql://...")->required();
    tr_cmd->add_option("--jobs", tr->jobs, "worker threads (default: one per core)");
    tr_cmd->add_option("--batch", tr->batch, "plans read, transferred and stored together")
        ->capture_default_str();
    tr_cmd->add_option("--limit", tr->limit, "stop after this many plans");
    table.add(tr_cmd,
              [tr](std::ostream& o, std::ostream& e) { return cmd_library_transfer(*tr, o, e); });

    auto q = std::make_shared<LibraryArgs>();
    auto* q_cmd = lib->add_subcommand(
        "query", "Print stored transfers (or plans) as JSON Lines, e.g. the failed ones and why");
    q_cmd->add_option("--db", q->db, "the library: sqlite:PATH or postgresql://...")->required();
    q_cmd->add_option("--map", q->map, "only transfers along this map");
    q_cmd->add_option("--domain", q->domain, "only plans of this domain");
    q_cmd->add_option("--problem", q->problem, "only plans of this problem");
    q_cmd->add_flag("--failed", q->failed, "only transfers that are not valid");
    q_cmd->add_flag("--valid", q->valid, "only valid transfers");
    q_cmd->add_flag("--plans", q->list_plans, "the stored plans instead of transfers");
    table.add(q_cmd, [q](std::ostream& o, std::ostream& e) { return cmd_library_query(*q, o, e); });
}

} // namespace

std::function<std::optional<int>(std::ostream&, std::ostream&)>
add_migrate_db_options(CLI::App& migrate, const std::string& file, const std::string& map,
                       const std::string& state) {
    auto a = std::make_shared<MigrateDbArgs>();
    migrate.add_option("--db", a->db,
                       "migrate inside this database (sqlite:PATH or postgresql://...): read the "
                       "source schema's tables, write the target schema's, in one transaction");
    migrate.add_option("--from", a->from,
                       "with --db: the namespace of the state (default: the source schema's name)");
    migrate.add_option("--to", a->to,
                       "with --db: the namespace written (default: the target schema's name)");
    migrate.add_flag("--replace", a->replace,
                     "with --db: replace the tables of the namespace --to");
    migrate.add_flag("--print-sql", a->print_sql,
                     "with --db: print the SQL of the migration for that engine, run nothing");
    return [a, &migrate, &file, &map, &state](std::ostream& out,
                                              std::ostream& err) -> std::optional<int> {
        if (a->db.empty()) {
            if (a->print_sql || a->replace || !a->from.empty() || !a->to.empty()) {
                error(err, "--print-sql, --replace, --from and --to go with --db URL");
                return kBadInput;
            }
            return std::nullopt;
        }
        for (const char* name : {"--sigma", "--output", "--format"}) {
            if (migrate.get_option(name)->count() > 0) {
                error(err, fmt::format("{} does not go with --db (the result is the tables "
                                       "written in the database)",
                                       name));
                return kBadInput;
            }
        }
        return cmd_migrate_db(*a, file, map, state, out, err);
    };
}

void add_db_commands(CLI::App& app, CommandTable& table) {
    auto* db_cmd = app.add_subcommand("db", "States as tables of SQLite or PostgreSQL");
    db_cmd->require_subcommand(1);

    auto ex = std::make_shared<DbArgs>();
    auto* export_cmd = db_cmd->add_subcommand(
        "export", "Write a state as tables, in one transaction (nothing is written on error)");
    export_cmd->add_option("FILE", ex->file, "language file (.cp)")->required();
    export_cmd->add_option("STATE", ex->name, "an instance declared in FILE")->required();
    add_db_option(export_cmd, *ex);
    export_cmd->add_flag("--replace", ex->replace, "replace the tables the namespace holds");
    table.add(export_cmd,
              [ex](std::ostream& o, std::ostream& e) { return cmd_db_export(*ex, o, e); });

    auto im = std::make_shared<DbArgs>();
    auto* import_cmd = db_cmd->add_subcommand(
        "import", "Read a state on SCHEMA from tables (checked: columns, types, foreign keys, "
                  "path equations) and print it in the language");
    import_cmd->add_option("FILE", im->file, "language file (.cp) declaring SCHEMA")->required();
    import_cmd->add_option("SCHEMA", im->name, "a schema declared in FILE")->required();
    add_db_option(import_cmd, *im);
    import_cmd->add_option("--name", im->as_name, "name of the instance printed")
        ->capture_default_str();
    import_cmd->add_option("-o,--output", im->output, "write to this file instead of stdout");
    table.add(import_cmd,
              [im](std::ostream& o, std::ostream& e) { return cmd_db_import(*im, o, e); });
    add_library_commands(app, table);
}

} // namespace catplan::cli
