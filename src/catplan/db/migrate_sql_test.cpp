#include "catplan/db/detail/test_databases.hpp"
#include "catplan/db/detail/test_states.hpp"
#include "catplan/db/migrate_sql.hpp"
#include "catplan/db/tables.hpp"
#include "catplan/migrate/migration.hpp"

#include <gtest/gtest.h>

namespace catplan::db {
namespace {

using migrate::SchemaMap;
using testing::FreshDatabase;
using testing::random_state;
using testing::same_state;

class MigrateSqlTest : public ::testing::TestWithParam<Engine> {};

const SchemaMap& find_map(const lang::Module& m, const std::string& name) {
    const auto* d = m.find(name);
    CATPLAN_ASSERT(d != nullptr && d->map != nullptr, "no such map");
    return *d->map;
}

// The parts of X each tuple of the origin table of c starts at (its first object variable).
std::vector<Part> origins_in_database(const std::string& url, const SchemaMap& f, ObId c,
                                      const std::string& ns) {
    const migrate::Query& q = f.query(c);
    std::string first;
    for (const auto& n : q.nodes()) {
        if (!n.is_value) {
            first = n.name;
            break;
        }
    }
    auto conn = connect(url);
    std::vector<Part> parts;
    auto st =
        (*conn)->query("SELECT " + quote(first) + " FROM " +
                           table_name((*conn)->engine(), ns, origin_table(f.target()->ob(c).name)) +
                           " ORDER BY " + quote(kIdColumn),
                       [&](const Row& r) {
                           parts.push_back(static_cast<Part>(*r.integer(0) - 1));
                           return true;
                       });
    EXPECT_TRUE(st) << st.error();
    return parts;
}

// Migrates x along f inside the database and in memory and expects the same state, names,
// variables and tuple origins.
void expect_same_migration(const std::string& url, const SchemaMap& f, const ACSet& x,
                           const std::string& tag) {
    std::string from = "x" + tag, to = "y" + tag;
    auto st = export_state(url, x, from);
    ASSERT_TRUE(st) << st.error();
    st = migrate_in_database(url, f, from, to);
    ASSERT_TRUE(st) << st.error();
    ReadState y = import_state(url, f.target(), to);
    ASSERT_TRUE(y.state) << y.errors.front();
    migrate::MigratedState m = migrate::migrate_state(f, x);
    std::string why;
    ASSERT_TRUE(same_state(m.state, *y.state, &why)) << tag << ": " << why;
    for (std::uint32_t c = 0; c < f.target()->num_obs(); ++c) {
        const migrate::Query& q = f.query(ObId(c));
        if (q.is_plain() || q.is_empty()) {
            continue;
        }
        auto origins = migrate::tuple_origins(f, m, ObId(c));
        if (origins) {
            EXPECT_EQ(origins->parts, origins_in_database(url, f, ObId(c), to))
                << tag << ": " << f.target()->ob(ObId(c)).name;
        }
    }
}

TEST_P(MigrateSqlTest, EqualsMigrateOnSeededRandomStates) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    SourceManager sources;
    lang::Module m = testing::load_example("tests/db/maps.cp", sources);
    std::mt19937_64 rng(18);
    int n = 0;
    for (const char* name : {"Reverse", "TwoPaths", "SameLabel", "RedPart", "Discrete"}) {
        const SchemaMap& f = find_map(m, name);
        for (int i = 0; i < 6; ++i) {
            ACSet x = random_state(f.source(), rng, i == 0 ? 0 : 7);
            expect_same_migration(db.url(), f, x, std::to_string(n++));
        }
    }
}

TEST_P(MigrateSqlTest, EqualsMigrateOnTheCaseStudy) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    SourceManager sources;
    lang::Module m =
        testing::load_example("examples/colorblocks_to_kitchen/appendix_map.cp", sources);
    const SchemaMap& f = find_map(m, "ColorToKitchen");
    expect_same_migration(db.url(), f, *m.find("Initial")->instance, "initial");
    std::mt19937_64 rng(1);
    for (int i = 0; i < 4; ++i) {
        expect_same_migration(db.url(), f, random_state(f.source(), rng, 8, /*partial=*/false),
                              std::to_string(i));
    }
}

TEST_P(MigrateSqlTest, ADanglingForeignKeyStopsTheMigrationAndWritesNothing) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    SourceManager sources;
    lang::Module m = testing::load_example("tests/db/maps.cp", sources);
    const SchemaMap& f = find_map(m, "TwoPaths");
    ACSet x(f.source());
    x.add_parts(ObId(0), 2);
    x.add_parts(ObId(1), 1);
    ASSERT_TRUE(export_state(db.url(), x, "G"));
    auto c = connect(db.url());
    ASSERT_TRUE(c);
    std::string edges = table_name(GetParam(), "G", "E");
    std::string sql = GetParam() == Engine::PostgreSQL
                          ? "ALTER TABLE " + edges + " DROP CONSTRAINT \"E_tgt_fkey\"; "
                          : "";
    ASSERT_TRUE((*c)->exec(sql + "UPDATE " + edges + " SET \"tgt\" = 7"));
    auto st = migrate_in_database(db.url(), f, "G", "H");
    ASSERT_FALSE(st);
    EXPECT_EQ(st.error(), "table " + edges + ", row 1, column \"tgt\": 7 points to no row of " +
                              table_name(GetParam(), "G", "V"));
    auto tables = tables_in(**c, "H");
    ASSERT_TRUE(tables);
    EXPECT_TRUE(tables->empty());
}

TEST(MigrateSql, SqliteCellsOfTheWrongTypeStopTheMigration) {
    FreshDatabase db(Engine::SQLite);
    SourceManager sources;
    lang::Module m = testing::load_example("tests/db/maps.cp", sources);
    const SchemaMap& f = find_map(m, "Reverse");
    ACSet x(f.source());
    x.add_parts(ObId(0), 2);
    x.add_parts(ObId(1), 1);
    ASSERT_TRUE(export_state(db.url(), x, "G"));
    auto c = connect(db.url());
    ASSERT_TRUE(c);
    ASSERT_TRUE((*c)->exec("UPDATE \"G.E\" SET \"src\" = 'one', \"weight\" = 'heavy'"));
    auto st = migrate_in_database(db.url(), f, "G", "H");
    ASSERT_FALSE(st);
    EXPECT_EQ(st.error(), "table \"G.E\", row 1, column \"src\": 'one' is not an id\n"
                          "table \"G.E\", row 1, column \"weight\": 'heavy' is not a Float");
}

TEST(MigrateSql, ThePrintedSqlReadsAsSql) {
    SourceManager sources;
    lang::Module m = testing::load_example("tests/db/maps.cp", sources);
    std::string sql = migration_sql(find_map(m, "RedPart"), Engine::SQLite, "G", "R").text();
    EXPECT_NE(sql.find("CREATE TABLE \"R.V__origin\" AS SELECT ROW_NUMBER() OVER (ORDER BY "
                       "s0.\"_id\") AS \"_id\", s0.\"_id\" AS \"v\""),
              std::string::npos)
        << sql;
    EXPECT_NE(sql.find("s0.\"label\" = CAST('red' AS TEXT)"), std::string::npos) << sql;
}

INSTANTIATE_TEST_SUITE_P(Engines, MigrateSqlTest,
                         ::testing::Values(Engine::SQLite, Engine::PostgreSQL),
                         testing::engine_name);

} // namespace
} // namespace catplan::db
