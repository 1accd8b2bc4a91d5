#include "catplan/db/detail/test_databases.hpp"
#include "catplan/db/detail/test_states.hpp"
#include "catplan/db/tables.hpp"

#include <gtest/gtest.h>

namespace catplan::db {
namespace {

using testing::FreshDatabase;
using testing::random_state;
using testing::same_state;

class TablesTest : public ::testing::TestWithParam<Engine> {};

// Exports x, imports it back and expects the same state, names and variables included.
void round_trip(const std::string& url, const ACSet& x, const std::string& ns) {
    auto st = export_state(url, x, ns);
    ASSERT_TRUE(st) << st.error();
    ReadState back = import_state(url, x.schema_ptr(), ns);
    ASSERT_TRUE(back.errors.empty()) << back.errors.front();
    std::string why;
    EXPECT_TRUE(same_state(x, *back.state, &why)) << why;
}

schema::SchemaPtr test_schema() {
    auto s = std::make_shared<schema::Schema>("S");
    ObId v = s->add_ob("V"), e = s->add_ob("E"), f = s->add_ob("Face");
    s->add_hom("src", e, v);
    s->add_hom("tgt", e, v);
    s->add_hom("next", e, e); // a cycle
    s->add_hom("edge", f, e);
    auto label = s->add_attr_type("Label", schema::ValueKind::String);
    auto weight = s->add_attr_type("Weight", schema::ValueKind::Float);
    auto count = s->add_attr_type("Count", schema::ValueKind::Int);
    auto flag = s->add_attr_type("Flag", schema::ValueKind::Bool);
    s->add_attr("label", v, label);
    s->add_attr("other_label", e, label);
    s->add_attr("weight", e, weight);
    s->add_attr("count", f, count);
    s->add_attr("flag", v, flag);
    return s;
}

TEST_P(TablesTest, SeededRandomStatesRoundTrip) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    auto s = test_schema();
    std::mt19937_64 rng(2024);
    for (int i = 0; i < 12; ++i) {
        ACSet x = random_state(s, rng, i < 2 ? 0 : 9);
        round_trip(db.url(), x, "state" + std::to_string(i));
    }
}

TEST_P(TablesTest, TheExamplesRoundTrip) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    SourceManager sources;
    int n = 0;
    for (const auto& file : testing::example_files()) {
        lang::Module m = testing::load_example(file, sources);
        for (const auto& d : m.declarations()) {
            if (d.kind == lang::DeclKind::Instance && !d.imported) {
                round_trip(db.url(), *d.instance, d.name + std::to_string(n++));
            }
        }
    }
    EXPECT_GT(n, 5);
}

TEST_P(TablesTest, ExportRefusesToOverwriteAndReplaceReplaces) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    std::mt19937_64 rng(5);
    ACSet x = random_state(test_schema(), rng, 4);
    ACSet y = random_state(test_schema(), rng, 6);
    ASSERT_TRUE(export_state(db.url(), x, "S"));
    auto again = export_state(db.url(), y, "S");
    ASSERT_FALSE(again);
    EXPECT_NE(again.error().find("already holds tables of 'S'"), std::string::npos)
        << again.error();
    ReadState back = import_state(db.url(), x.schema_ptr(), "S");
    ASSERT_TRUE(back.state);
    EXPECT_TRUE(same_state(x, *back.state)); // the refused export wrote nothing
    ASSERT_TRUE(export_state(db.url(), y, "S", /*replace=*/true));
    back = import_state(db.url(), x.schema_ptr(), "S");
    ASSERT_TRUE(back.state);
    EXPECT_TRUE(same_state(y, *back.state));
}

TEST_P(TablesTest, AFailedTransactionLeavesNothing) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    std::mt19937_64 rng(6);
    ACSet x = random_state(test_schema(), rng, 4);
    auto c = connect(db.url());
    ASSERT_TRUE(c) << c.error();
    {
        Transaction t(**c);
        ASSERT_TRUE(write_state(**c, x, "S"));
        auto tables = tables_in(**c, "S");
        ASSERT_TRUE(tables);
        EXPECT_EQ(tables->size(), 7U);
        // No commit: the transaction is rolled back.
    }
    auto tables = tables_in(**c, "S");
    ASSERT_TRUE(tables);
    EXPECT_TRUE(tables->empty());
}

// Runs SQL on the database (with "T." standing for the namespace's table prefix).
void run(const std::string& url, Engine e, const std::string& sql) {
    auto c = connect(url);
    ASSERT_TRUE(c) << c.error();
    auto st = (*c)->exec(sql);
    ASSERT_TRUE(st) << st.error() << "\n" << sql;
    (void)e;
}

// Every error of reading namespace S, joined by newlines.
std::string import_errors(const std::string& url, const schema::SchemaPtr& s) {
    ReadState r = import_state(url, s, "S");
    EXPECT_FALSE(r.state);
    std::string all;
    for (const auto& e : r.errors) {
        all += e + "\n";
    }
    return all;
}

TEST_P(TablesTest, BadTablesAreReportedByTableRowAndColumn) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    Engine e = GetParam();
    std::mt19937_64 rng(7);
    auto s = test_schema();
    ACSet x = random_state(s, rng, 5, /*partial=*/false);
    while (x.num_parts(ObId(0)) < 3 || x.num_parts(ObId(1)) < 2) {
        x = random_state(s, rng, 5, false);
    }
    ASSERT_TRUE(export_state(db.url(), x, "S"));
    std::string edge = table_name(e, "S", "E"), vertex = table_name(e, "S", "V");
    std::string drop_fk =
        e == Engine::PostgreSQL ? "ALTER TABLE " + edge + " DROP CONSTRAINT \"E_src_fkey\";" : "";
    run(db.url(), e, drop_fk + "UPDATE " + edge + " SET \"src\" = 99 WHERE \"_id\" = 2");
    std::string errors = import_errors(db.url(), s);
    EXPECT_NE(
        errors.find("table " + edge + ", row 2, column \"src\": 99 points to no row of " + vertex),
        std::string::npos)
        << errors;

    run(db.url(), e, "ALTER TABLE " + vertex + " DROP COLUMN \"label\"");
    errors = import_errors(db.url(), s);
    EXPECT_NE(errors.find("table " + vertex +
                          " has no column \"label\" (attribute label::Attr(V, Label))"),
              std::string::npos)
        << errors;

    run(db.url(), e, "DROP TABLE " + table_name(e, "S", "Face"));
    errors = import_errors(db.url(), s);
    EXPECT_NE(errors.find("the database has no table " + table_name(e, "S", "Face") +
                          " (object Face of schema S)"),
              std::string::npos)
        << errors;
}

TEST_P(TablesTest, ACellOfTheWrongTypeIsReported) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    Engine e = GetParam();
    auto s = test_schema();
    ACSet x(s);
    x.add_parts(ObId(0), 2);
    ASSERT_TRUE(export_state(db.url(), x, "S"));
    std::string vertex = table_name(e, "S", "V");
    if (e == Engine::SQLite) {
        // SQLite keeps whatever is stored; PostgreSQL's types refuse it in the first place.
        run(db.url(), e, "UPDATE " + vertex + " SET \"flag\" = 'yes' WHERE \"_id\" = 2");
    } else {
        run(db.url(), e,
            "ALTER TABLE " + vertex + " ALTER COLUMN \"flag\" TYPE TEXT; UPDATE " + vertex +
                " SET \"flag\" = 'yes' WHERE \"_id\" = 2");
    }
    std::string errors = import_errors(db.url(), s);
    EXPECT_NE(errors.find("table " + vertex + ", row 2, column \"flag\": 'yes' is not a Bool"),
              std::string::npos)
        << errors;
}

TEST_P(TablesTest, PathEquationsAreChecked) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    // A reflexive graph: refl ⋅ src == id(V).
    auto s = std::make_shared<schema::Schema>("R");
    ObId v = s->add_ob("V"), ed = s->add_ob("E");
    HomId src = s->add_hom("src", ed, v);
    HomId refl = s->add_hom("refl", v, ed);
    s->add_equation({"", {v, {refl, src}, std::nullopt}, {v, {}, std::nullopt}, {}});
    ACSet x(s);
    x.add_parts(v, 2);
    x.add_parts(ed, 2);
    x.set_subpart(refl, 0, 0);
    x.set_subpart(refl, 1, 1);
    x.set_subpart(src, 0, 0);
    x.set_subpart(src, 1, 0); // refl(2) has source 1, not 2
    ASSERT_TRUE(export_state(db.url(), x, "R"));
    ReadState r = import_state(db.url(), s, "R");
    ASSERT_EQ(r.errors.size(), 1U);
    EXPECT_EQ(r.errors[0], "table " + table_name(GetParam(), "R", "V") +
                               ", row 2: the path equation refl ⋅ src == id(V) does not hold");
    x.set_subpart(src, 1, 1);
    ASSERT_TRUE(export_state(db.url(), x, "R", true));
    EXPECT_TRUE(import_state(db.url(), s, "R").state);
}

TEST(Tables, AnUnreachableDatabaseIsAnError) {
    auto c = connect("postgresql:///nothere?host=/nonexistent-catplan-dir&connect_timeout=2");
    ASSERT_FALSE(c);
    EXPECT_NE(c.error().find("cannot connect to PostgreSQL"), std::string::npos) << c.error();
    ReadState r = import_state("sqlite:/nonexistent-catplan-dir/x.db", test_schema(), "S");
    ASSERT_EQ(r.errors.size(), 1U);
    EXPECT_NE(r.errors[0].find("cannot open SQLite database"), std::string::npos) << r.errors[0];
    EXPECT_FALSE(parse_url("mysql://x"));
}

INSTANTIATE_TEST_SUITE_P(Engines, TablesTest, ::testing::Values(Engine::SQLite, Engine::PostgreSQL),
                         testing::engine_name);

} // namespace
} // namespace catplan::db
