// The database layer against catplan in memory, in one run (figures: RESULTS.md):
//   - Δ_F (a graph's edges reversed) and the colour-split conjunctive migration of states of
//     10^6 and 10^7 parts: catplan in memory, then the same map compiled to SQL and run inside
//     SQLite (a file) and PostgreSQL (a private server started for the run);
//   - the batch transfer of 10^4 stored plans (the case study's plan) along ColorToKitchen, with
//     one and with two workers: plans per second per core, and the peak resident memory after
//     10^3 and after 10^4 plans (bounded by a batch, not by the library's size).
//
//   db_bench [--parts 1000000,10000000] [--plans 10000] [--repetitions 3] [--no-postgresql]
//            [--only migration|library]
//
// Run the library part on its own (--only library) for its peak memory to mean anything: the
// process's peak includes the migrations' states of 10^7 parts otherwise.
//
// Every database run is checked: the number of rows it made equals the in-memory migration's.

#include "catplan/base/process.hpp"
#include "catplan/db/library.hpp"
#include "catplan/db/migrate_sql.hpp"
#include "catplan/db/tables.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/transfer/transfer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <random>
#include <sstream>
#include <unistd.h>

namespace {

using namespace catplan;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

[[noreturn]] void die(const std::string& why) {
    std::fprintf(stderr, "db_bench: %s\n", why.c_str());
    std::exit(1);
}

template <class T>
T check(Result<T> r, const char* what) {
    if (!r) {
        die(std::string(what) + ": " + r.error());
    }
    return std::move(*r);
}

void check(const db::Status& s, const char* what) {
    if (!s) {
        die(std::string(what) + ": " + s.error());
    }
}

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// A private PostgreSQL server for the run (tools/pg-test-server.sh), stopped at the end.
struct Server {
    fs::path dir;
    std::string url;
    std::string script = std::string(CATPLAN_SOURCE_DIR) + "/tools/pg-test-server.sh";

    Server() {
        dir = fs::temp_directory_path() / ("catplan-bench-pg-" + std::to_string(::getpid()));
        std::string cmd = script + " start " + dir.string() + " >/dev/null";
        (void)std::system(cmd.c_str());
        std::ifstream in(dir / "url");
        std::getline(in, url);
    }

    ~Server() {
        std::string cmd = script + " stop " + dir.string();
        (void)std::system(cmd.c_str());
    }
};

lang::Module load(const std::string& file, SourceManager& sources) {
    DiagnosticSink sink(sources);
    auto m = lang::load_file(std::string(CATPLAN_SOURCE_DIR) + "/" + file, sources, sink);
    if (sink.has_errors()) {
        die(sink.render());
    }
    return m;
}

const migrate::SchemaMap& map_of(const lang::Module& m, const char* name) {
    const auto* d = m.find(name);
    if (d == nullptr || d->map == nullptr) {
        die(std::string("no map ") + name);
    }
    return *d->map;
}

// A graph with parts/2 vertices and parts/2 random edges.
acset::ACSet random_graph(const schema::SchemaPtr& s, std::size_t parts) {
    acset::ACSet x(s);
    std::size_t n = parts / 2;
    x.add_parts(ObId(0), n);
    x.add_parts(ObId(1), n);
    std::mt19937_64 rng(7);
    std::vector<Part> src(n), tgt(n);
    for (std::size_t i = 0; i < n; ++i) {
        src[i] = static_cast<Part>(rng() % n);
        tgt[i] = static_cast<Part>(rng() % n);
    }
    x.set_column(HomId(0), src);
    x.set_column(HomId(1), tgt);
    return x;
}

// parts blocks of five colours at random.
acset::ACSet random_blocks(const schema::SchemaPtr& s, std::size_t parts) {
    static const char* const kColors[] = {"purple", "red", "green", "yellow", "blue"};
    acset::ACSet x(s);
    x.add_parts(ObId(0), parts);
    std::mt19937_64 rng(11);
    std::vector<acset::Value> colors(parts);
    for (auto& c : colors) {
        c = acset::Value::string(kColors[rng() % 5]);
    }
    x.set_column(AttrId(0), colors);
    return x;
}

std::size_t total_rows(db::Connection& c, const schema::Schema& s, const std::string& ns) {
    std::size_t n = 0;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        n += static_cast<std::size_t>(
            check(c.query_integer("SELECT count(*) FROM " +
                                  db::table_name(c.engine(), ns, s.ob(ObId(o)).name)),
                  "count"));
    }
    return n;
}

// One migration workload at one size: in memory, then in each database.
void migration_rows(const char* workload, const migrate::SchemaMap& f, const acset::ACSet& x,
                    const std::vector<std::string>& urls, int reps) {
    std::vector<double> mem;
    std::size_t parts = 0;
    for (int r = 0; r < reps; ++r) {
        auto t = Clock::now();
        acset::ACSet y = migrate::migrate(f, x);
        mem.push_back(seconds_since(t));
        parts = y.total_parts();
    }
    double m = median(mem);
    fmt::print("| {} | {} | catplan in memory | {:.2f} ms | 1 | — |\n", workload, x.total_parts(),
               m * 1e3);
    std::fflush(stdout);
    for (const auto& url : urls) {
        auto c = check(db::connect(url), "connect");
        auto t0 = Clock::now();
        {
            db::Transaction tx(*c);
            check(db::write_state(*c, x, "bench_x", /*replace=*/true), "export");
            check(tx.commit(), "commit");
        }
        double load = seconds_since(t0);
        auto sql = db::migration_sql(f, c->engine(), "bench_x", "bench_y");
        std::vector<double> times;
        for (int r = 0; r < reps; ++r) {
            check(db::drop_namespace(*c, "bench_y"), "drop");
            auto t = Clock::now();
            db::Transaction tx(*c);
            for (const auto& s : sql.statements) {
                check(c->exec(s), "migration");
            }
            check(tx.commit(), "commit");
            times.push_back(seconds_since(t));
        }
        std::size_t rows = total_rows(*c, *f.target(), "bench_y");
        if (rows != parts) {
            die(fmt::format("{} made {} rows, catplan {} parts", url, rows, parts));
        }
        double d = median(times);
        fmt::print("| {} | {} | {} | {:.1f} ms | {:.0f} | {:.1f} s |\n", workload, x.total_parts(),
                   to_string(c->engine()), d * 1e3, d / m, load);
        std::fflush(stdout);
        check(db::drop_namespace(*c, "bench_y"), "drop");
        check(db::drop_namespace(*c, "bench_x"), "drop");
    }
}

long peak_rss_kib() {
    return catplan::peak_rss_kib();
}

// Stores `plans` copies of the case study's plan in a fresh library at url.
void fill_library(const std::string& url, std::size_t plans) {
    SourceManager sources;
    lang::Module m = load("examples/colorblocksworld/colorblocksworld.cp", sources);
    const auto* p = m.find("CaseStudy");
    std::ifstream in(std::string(CATPLAN_SOURCE_DIR) + "/examples/colorblocksworld/paper.plan");
    std::stringstream text;
    text << in.rdbuf();
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer("paper.plan", text.str());
    auto plan = plan::parse_plan(file, sources, sink);
    if (!plan) {
        die("paper.plan");
    }
    std::vector<std::pair<std::string, plan::Plan>> list;
    for (std::size_t i = 0; i < plans; ++i) {
        list.emplace_back("paper.plan#" + std::to_string(i + 1), *plan);
    }
    auto c = check(db::connect(url), "connect");
    db::Transaction tx(*c);
    check(db::open_library(*c), "library");
    (void)check(db::add_plans(*c, *p->problem->domain, "", *p->problem, list), "add");
    check(tx.commit(), "commit");
}

void library_rows(const std::string& url, std::size_t plans, std::size_t jobs) {
    fill_library(url, plans);
    auto c = check(db::connect(url), "connect");
    std::string map =
        std::string(CATPLAN_SOURCE_DIR) + "/examples/colorblocks_to_kitchen/appendix_map.cp";
    std::size_t valid = 0;
    long rss_tenth = 0;
    db::LibraryTransferOptions options{jobs, 64, 0};
    std::size_t seen = 0;
    auto summary = check(db::transfer_library(*c, map, "ColorToKitchen", options,
                                              [&](const db::StoredTransfer& t) {
                                                  valid += t.valid ? 1 : 0;
                                                  if (++seen == plans / 10) {
                                                      rss_tenth = peak_rss_kib();
                                                  }
                                              }),
                         "transfer");
    if (summary.transferred != plans || valid != plans) {
        die(fmt::format("{} of {} plans transferred, {} valid", summary.transferred, plans, valid));
    }
    double per_s = static_cast<double>(plans) / summary.seconds;
    fmt::print("| {} | {} | {} | {:.1f} s | {:.0f} | {:.0f} | {} / {} MiB |\n",
               to_string(c->engine()), plans, jobs, summary.seconds, per_s,
               per_s / static_cast<double>(jobs), rss_tenth / 1024, peak_rss_kib() / 1024);
    std::fflush(stdout);
}

std::vector<std::size_t> parse_sizes(const std::string& s) {
    std::vector<std::size_t> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) {
        out.push_back(std::stoul(item));
    }
    return out;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::size_t> sizes{1'000'000, 10'000'000};
    std::size_t plans = 10'000;
    int reps = 3;
    bool postgresql = true;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--parts" && i + 1 < argc) {
            sizes = parse_sizes(argv[++i]);
        } else if (a == "--plans" && i + 1 < argc) {
            plans = std::stoul(argv[++i]);
        } else if (a == "--repetitions" && i + 1 < argc) {
            reps = std::stoi(argv[++i]);
        } else if (a == "--only" && i + 1 < argc) {
            only = argv[++i];
        } else if (a == "--no-postgresql") {
            postgresql = false;
        } else {
            die("unknown argument " + a);
        }
    }
    std::optional<Server> server;
    if (postgresql) {
        server.emplace();
        if (server->url.empty()) {
            die("the private PostgreSQL server did not start (see tools/pg-test-server.sh)");
        }
    }
    fs::path dir = fs::temp_directory_path() / ("catplan-bench-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::vector<std::string> urls{"sqlite:" + (dir / "bench.db").string()};
    if (server) {
        urls.push_back(server->url);
    }

    SourceManager sources;
    lang::Module m = load("bench/db_maps.cp", sources);
    const auto& reverse = map_of(m, "Reverse");
    const auto& split = map_of(m, "ColorSplit");
    if (only != "library") {
        fmt::print(
            "| workload | parts | engine | median migration | / in memory | load (export) |\n");
        fmt::print("|---|---|---|---|---|---|\n");
        for (std::size_t n : sizes) {
            migration_rows("Δ_F reverse edges", reverse, random_graph(reverse.source(), n), urls,
                           reps);
            migration_rows("colour split", split, random_blocks(split.source(), n), urls, reps);
        }
    }
    if (only == "migration") {
        fs::remove_all(dir);
        return 0;
    }

    fmt::print("\n| engine | plans | workers | time | plans/s | plans/s per worker | peak RSS "
               "after 1/10 / all |\n");
    fmt::print("|---|---|---|---|---|---|---|\n");
    for (const auto& url : urls) {
        for (std::size_t jobs : {1, 2}) {
            std::string lib = url;
            if (url.rfind("sqlite:", 0) == 0) {
                lib = "sqlite:" + (dir / ("library" + std::to_string(jobs) + ".db")).string();
            } else {
                auto c = check(db::connect(url), "connect");
                check(c->exec("DROP SCHEMA IF EXISTS \"catplan\" CASCADE"), "drop");
            }
            library_rows(lib, plans, jobs);
        }
    }
    fs::remove_all(dir);
    return 0;
}
