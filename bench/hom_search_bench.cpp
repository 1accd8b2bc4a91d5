// Homomorphism search benchmarks: triangle counting against SQLite, and Catlab's workloads
// (benchmark/HomSearch.jl: DDS and triangles in an Erdős–Rényi graph). Figures: RESULTS.md.

#include "catplan/hom/detail/test_instances.hpp"
#include "catplan/hom/hom_search.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <sqlite3.h>

namespace {

using namespace catplan;
using namespace catplan::hom;
using namespace catplan::hom::testing;

constexpr std::size_t kTriangleN = 300;
constexpr double kTriangleP = 0.5;
constexpr std::uint64_t kTriangleSeed = 42;

const ACSet& triangle_target() {
    static ACSet g = random_graph(kTriangleN, kTriangleP, kTriangleSeed);
    return g;
}

std::uint64_t catplan_triangles() {
    HomSearchOptions opt;
    opt.monic_all = true;
    return count_homomorphisms(cycle_graph(3), triangle_target(), opt).count;
}

void check(int rc, sqlite3* db, const char* what) {
    if (rc != SQLITE_OK && rc != SQLITE_DONE && rc != SQLITE_ROW) {
        std::fprintf(stderr, "sqlite %s: %s\n", what, sqlite3_errmsg(db));
        std::abort();
    }
}

// An in-memory database holding the same edge table, indexed as a DBA would for this join:
// the primary key (src, tgt) serves e2 (by src) and e3 (by src and tgt), (tgt, src) the rest.
struct Sqlite {
    sqlite3* db = nullptr;
    sqlite3_stmt* query = nullptr;

    Sqlite() {
        check(sqlite3_open(":memory:", &db), db, "open");
        check(sqlite3_exec(db,
                           "CREATE TABLE e(src INTEGER NOT NULL, tgt INTEGER NOT NULL, "
                           "PRIMARY KEY (src, tgt)) WITHOUT ROWID;",
                           nullptr, nullptr, nullptr),
              db, "create");
        sqlite3_stmt* ins = nullptr;
        check(sqlite3_exec(db, "BEGIN", nullptr, nullptr, nullptr), db, "begin");
        check(sqlite3_prepare_v2(db, "INSERT INTO e VALUES (?, ?)", -1, &ins, nullptr), db,
              "prepare insert");
        const ACSet& g = triangle_target();
        for (Part e = 0; e < g.num_parts(kE); ++e) {
            sqlite3_bind_int(ins, 1, static_cast<int>(g.subpart(kSrc, e)));
            sqlite3_bind_int(ins, 2, static_cast<int>(g.subpart(kTgt, e)));
            check(sqlite3_step(ins), db, "insert");
            sqlite3_reset(ins);
        }
        sqlite3_finalize(ins);
        check(sqlite3_exec(db, "COMMIT; CREATE INDEX e_tgt ON e(tgt, src); ANALYZE;", nullptr,
                           nullptr, nullptr),
              db, "index");
        check(sqlite3_prepare_v2(
                  db,
                  "SELECT count(*) FROM e e1 JOIN e e2 ON e1.tgt=e2.src JOIN e e3 ON "
                  "e2.tgt=e3.src AND e3.tgt=e1.src WHERE e1.src<>e2.src AND e2.src<>e3.src "
                  "AND e1.src<>e3.src",
                  -1, &query, nullptr),
              db, "prepare query");
    }

    ~Sqlite() {
        sqlite3_finalize(query);
        sqlite3_close(db);
    }

    std::uint64_t triangles() {
        check(sqlite3_step(query), db, "query");
        auto n = static_cast<std::uint64_t>(sqlite3_column_int64(query, 0));
        sqlite3_reset(query);
        return n;
    }
};

Sqlite& sqlite() {
    static Sqlite s;
    return s;
}

// Both engines must agree before either is timed.
std::uint64_t agreed_triangle_count() {
    static std::uint64_t n = [] {
        std::uint64_t a = catplan_triangles(), b = sqlite().triangles();
        if (a != b) {
            std::fprintf(stderr, "triangle counts differ: catplan %llu, sqlite %llu\n",
                         static_cast<unsigned long long>(a), static_cast<unsigned long long>(b));
            std::abort();
        }
        return a;
    }();
    return n;
}

void BM_TrianglesCatplan(benchmark::State& state) {
    std::uint64_t expected = agreed_triangle_count();
    for (auto _ : state) {
        std::uint64_t n = catplan_triangles();
        if (n != expected) {
            state.SkipWithError("wrong triangle count");
        }
        benchmark::DoNotOptimize(n);
    }
    state.counters["triangles"] = static_cast<double>(expected);
    state.counters["edges"] = static_cast<double>(triangle_target().num_parts(kE));
}

BENCHMARK(BM_TrianglesCatplan)->Unit(benchmark::kMillisecond);

void BM_TrianglesSqlite(benchmark::State& state) {
    std::uint64_t expected = agreed_triangle_count();
    for (auto _ : state) {
        std::uint64_t n = sqlite().triangles();
        if (n != expected) {
            state.SkipWithError("wrong triangle count");
        }
        benchmark::DoNotOptimize(n);
    }
    state.counters["triangles"] = static_cast<double>(expected);
}

BENCHMARK(BM_TrianglesSqlite)->Unit(benchmark::kMillisecond);

// Catlab's DDS workload: all homomorphisms from a random DDS(5) into a random DDS(200).
void BM_DdsHoms(benchmark::State& state) {
    ACSet x = random_dds(5, 1);
    ACSet y = random_dds(200, 2);
    std::uint64_t n = 0;
    for (auto _ : state) {
        n = count_homomorphisms(x, y).count;
        benchmark::DoNotOptimize(n);
    }
    state.counters["homs"] = static_cast<double>(n);
}

BENCHMARK(BM_DdsHoms)->Unit(benchmark::kMicrosecond);

// Same workload, collecting every morphism (the cost of building results).
void BM_DdsHomsCollect(benchmark::State& state) {
    ACSet x = random_dds(5, 1);
    ACSet y = random_dds(200, 2);
    std::uint64_t n = 0;
    for (auto _ : state) {
        auto r = find_homomorphisms(x, y);
        n = r.count;
        benchmark::DoNotOptimize(r.morphisms.data());
    }
    state.counters["homs"] = static_cast<double>(n);
}

BENCHMARK(BM_DdsHomsCollect)->Unit(benchmark::kMicrosecond);

// Catlab's triangle workload: all homomorphisms from a directed 3-cycle into ER(150, 0.05).
void BM_TriangleErdosRenyi(benchmark::State& state) {
    ACSet y = random_graph(150, 0.05, 3);
    ACSet x = cycle_graph(3);
    std::uint64_t n = 0;
    for (auto _ : state) {
        n = count_homomorphisms(x, y).count;
        benchmark::DoNotOptimize(n);
    }
    state.counters["homs"] = static_cast<double>(n);
    state.counters["edges"] = static_cast<double>(y.num_parts(kE));
}

BENCHMARK(BM_TriangleErdosRenyi)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
