// Migration benchmarks: Δ along a delta map against memcpy of the columns it touches, and the
// colour-filter split of the paper's case study against SQLite. Figures: RESULTS.md.

#include "catplan/migrate/migration.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sqlite3.h>

namespace {

using namespace catplan;
using namespace catplan::migrate;
using schema::Schema;
using schema::ValueKind;

constexpr std::size_t kParts = 1'000'000;

// ---- Δ along a delta map ----------------------------------------------------------------------

struct GraphFixture {
    SchemaPtr s;
    ObId v, e;
    HomId src, tgt;
    std::optional<ACSet> x;
    std::optional<SchemaMap> reverse;
};

const GraphFixture& graph_fixture() {
    static GraphFixture f = [] {
        GraphFixture g;
        auto s = std::make_shared<Schema>("Graph");
        g.v = s->add_ob("V");
        g.e = s->add_ob("E");
        g.src = s->add_hom("src", g.e, g.v);
        g.tgt = s->add_hom("tgt", g.e, g.v);
        g.s = s;
        ACSet x(s);
        x.add_parts(g.v, kParts);
        x.add_parts(g.e, kParts);
        std::mt19937_64 rng(7);
        for (Part p = 0; p < kParts; ++p) {
            x.set_subpart(g.src, p, static_cast<Part>(rng() % kParts));
            x.set_subpart(g.tgt, p, static_cast<Part>(rng() % kParts));
        }
        g.x.emplace(std::move(x));
        SchemaMap m(s, s);
        m.map_ob(g.v, g.v);
        m.map_ob(g.e, g.e);
        m.map_hom_path(g.src, {g.tgt});
        m.map_hom_path(g.tgt, {g.src});
        (void)m.finish();
        if (!m.ok() || !m.is_delta()) {
            std::abort();
        }
        g.reverse.emplace(std::move(m));
        return g;
    }();
    return f;
}

// Bytes a delta migration of the fixture touches in hom columns: two columns read, two written.
constexpr std::int64_t kDeltaBytes = 4 * static_cast<std::int64_t>(kParts * sizeof(Part));

// Whether y is the fixture's graph with its edges reversed, checked cell by cell.
bool is_reversed(const GraphFixture& g, const ACSet& y) {
    const ACSet& x = *g.x;
    if (y.num_parts(g.v) != kParts || y.num_parts(g.e) != kParts) {
        return false;
    }
    for (Part p = 0; p < kParts; ++p) {
        if (y.subpart(g.src, p) != x.subpart(g.tgt, p) ||
            y.subpart(g.tgt, p) != x.subpart(g.src, p) || !y.part_name(g.e, p).empty()) {
            return false;
        }
    }
    // The preimage index, rebuilt from the bulk-written column (x's is left unbuilt).
    Part v = x.subpart(g.tgt, 17);
    std::size_t into_v = 0;
    for (Part p = 0; p < kParts; ++p) {
        into_v += x.subpart(g.tgt, p) == v ? 1 : 0;
    }
    return y.incident(g.src, v).size() == into_v;
}

void BM_DeltaMigrate(benchmark::State& state) {
    const GraphFixture& g = graph_fixture();
    if (!is_reversed(g, catplan::migrate::migrate(*g.reverse, *g.x))) {
        std::abort();
    }
    for (auto _ : state) {
        ACSet y = catplan::migrate::migrate(*g.reverse, *g.x);
        // Spot checks in the loop (the full check above runs once, untimed).
        for (Part p = 0; p < kParts; p += 9973) {
            if (y.subpart(g.src, p) != g.x->subpart(g.tgt, p) ||
                y.subpart(g.tgt, p) != g.x->subpart(g.src, p)) {
                std::abort();
            }
        }
        if (y.num_parts(g.v) != kParts || y.num_parts(g.e) != kParts) {
            std::abort();
        }
        benchmark::DoNotOptimize(y);
    }
    state.SetBytesProcessed(state.iterations() * kDeltaBytes);
}

void BM_DeltaMemcpy(benchmark::State& state) {
    const GraphFixture& g = graph_fixture();
    for (auto _ : state) {
        // The same columns copied into fresh buffers (allocation included, as for migrate).
        std::vector<Part> a(kParts), b(kParts);
        std::memcpy(a.data(), g.x->column(g.tgt).data(), kParts * sizeof(Part));
        std::memcpy(b.data(), g.x->column(g.src).data(), kParts * sizeof(Part));
        benchmark::DoNotOptimize(a.data());
        benchmark::DoNotOptimize(b.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(state.iterations() * kDeltaBytes);
}

// ---- the colour-filter split ------------------------------------------------------------------

const char* const kColors[] = {"purple", "green", "red", "yellow", "blue"};
const char* const kFoods[] = {"BreadSliced", "LettuceSliced", "TomatoSliced", "Plate", "Knife"};

struct SplitFixture {
    SchemaPtr blocks, kitchen;
    ObId block;
    AttrId has_color;
    std::optional<ACSet> x;
    std::optional<SchemaMap> map;
    std::vector<int> colors; // per block
    std::size_t expected[5] = {};
};

const SplitFixture& split_fixture() {
    static SplitFixture f = [] {
        SplitFixture sf;
        auto b = std::make_shared<Schema>("ColorBlocksworld");
        sf.block = b->add_ob("Block");
        AttrTypeId color = b->add_attr_type("Color", ValueKind::String);
        sf.has_color = b->add_attr("hasColor", sf.block, color);
        auto k = std::make_shared<Schema>("Kitchen");
        for (const char* food : kFoods) {
            k->add_ob(food);
        }
        sf.blocks = b;
        sf.kitchen = k;
        ACSet x(b);
        x.add_parts(sf.block, kParts);
        std::mt19937_64 rng(11);
        for (Part p = 0; p < kParts; ++p) {
            int c = static_cast<int>(rng() % 5);
            sf.colors.push_back(c);
            ++sf.expected[c];
            x.set_subpart(sf.has_color, p, Value::string(kColors[c]));
        }
        sf.x.emplace(std::move(x));
        SchemaMap m(k, b);
        for (std::uint32_t i = 0; i < 5; ++i) {
            Query q(b);
            q.add_variable("block", sf.block);
            q.add_equation(Term::path("block", {}, sf.has_color),
                           Term::constant(Value::string(kColors[i])));
            m.map_ob(ObId(i), std::move(q));
        }
        (void)m.finish();
        if (!m.ok()) {
            std::abort();
        }
        sf.map.emplace(std::move(m));
        return sf;
    }();
    return f;
}

void BM_ColorSplitCatplan(benchmark::State& state) {
    const SplitFixture& f = split_fixture();
    for (auto _ : state) {
        ACSet y = catplan::migrate::migrate(*f.map, *f.x);
        for (std::uint32_t i = 0; i < 5; ++i) {
            if (y.num_parts(ObId(i)) != f.expected[i]) {
                std::abort();
            }
        }
        benchmark::DoNotOptimize(y);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kParts));
}

void check(int rc, sqlite3* db, const char* what) {
    if (rc != SQLITE_OK && rc != SQLITE_DONE && rc != SQLITE_ROW) {
        std::fprintf(stderr, "sqlite %s: %s\n", what, sqlite3_errmsg(db));
        std::abort();
    }
}

void BM_ColorSplitSqlite(benchmark::State& state) {
    const SplitFixture& f = split_fixture();
    sqlite3* db = nullptr;
    check(sqlite3_open(":memory:", &db), db, "open");
    check(sqlite3_exec(db, "CREATE TABLE block(id INTEGER PRIMARY KEY, color TEXT NOT NULL);",
                       nullptr, nullptr, nullptr),
          db, "create");
    for (const char* food : kFoods) {
        std::string sql = "CREATE TABLE " + std::string(food) + "(id INTEGER PRIMARY KEY);";
        check(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), db, "create");
    }
    sqlite3_stmt* ins = nullptr;
    check(sqlite3_exec(db, "BEGIN", nullptr, nullptr, nullptr), db, "begin");
    check(sqlite3_prepare_v2(db, "INSERT INTO block VALUES (?, ?)", -1, &ins, nullptr), db,
          "prepare");
    for (Part p = 0; p < kParts; ++p) {
        sqlite3_bind_int64(ins, 1, p);
        sqlite3_bind_text(ins, 2, kColors[f.colors[p]], -1, SQLITE_STATIC);
        check(sqlite3_step(ins), db, "insert");
        sqlite3_reset(ins);
    }
    sqlite3_finalize(ins);
    check(sqlite3_exec(db, "COMMIT", nullptr, nullptr, nullptr), db, "commit");
    std::string run = "BEGIN;";
    for (int i = 0; i < 5; ++i) {
        run += "DELETE FROM " + std::string(kFoods[i]) + ";";
        run += "INSERT INTO " + std::string(kFoods[i]) + " SELECT id FROM block WHERE color = '" +
               kColors[i] + "';";
    }
    run += "COMMIT;";
    sqlite3_stmt* count = nullptr;
    check(sqlite3_prepare_v2(db, "SELECT count(*) FROM Plate", -1, &count, nullptr), db, "prepare");
    for (auto _ : state) {
        check(sqlite3_exec(db, run.c_str(), nullptr, nullptr, nullptr), db, "split");
        state.PauseTiming();
        check(sqlite3_step(count), db, "count");
        if (static_cast<std::size_t>(sqlite3_column_int64(count, 0)) != f.expected[3]) {
            std::abort();
        }
        sqlite3_reset(count);
        state.ResumeTiming();
    }
    sqlite3_finalize(count);
    sqlite3_close(db);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kParts));
}

BENCHMARK(BM_DeltaMigrate)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeltaMemcpy)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColorSplitCatplan)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColorSplitSqlite)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
