// The SQLite engine (Debian's libsqlite3): one database file, statements prepared one at a time.

#include "catplan/db/detail/engines.hpp"

#include <algorithm>
#include <sqlite3.h>

namespace catplan::db::detail {
namespace {

class SqliteRow final : public Row {
public:
    explicit SqliteRow(sqlite3_stmt* st) : st_(st) {}

    std::size_t size() const override {
        return static_cast<std::size_t>(sqlite3_column_count(st_));
    }

    bool is_null(std::size_t i) const override { return type(i) == SQLITE_NULL; }

    std::optional<std::int64_t> integer(std::size_t i) const override {
        if (type(i) != SQLITE_INTEGER) {
            return std::nullopt;
        }
        return sqlite3_column_int64(st_, col(i));
    }

    std::optional<double> real(std::size_t i) const override {
        int t = type(i);
        if (t != SQLITE_FLOAT && t != SQLITE_INTEGER) {
            return std::nullopt;
        }
        return sqlite3_column_double(st_, col(i));
    }

    std::optional<bool> boolean(std::size_t i) const override {
        auto v = integer(i);
        if (!v || (*v != 0 && *v != 1)) {
            return std::nullopt;
        }
        return *v == 1;
    }

    std::optional<std::string> text(std::size_t i) const override {
        if (type(i) != SQLITE_TEXT) {
            return std::nullopt;
        }
        return raw(i);
    }

    std::string display(std::size_t i) const override {
        switch (type(i)) {
        case SQLITE_NULL:
            return "NULL";
        case SQLITE_TEXT:
            return quote_literal(raw(i));
        case SQLITE_BLOB:
            return "a blob";
        default:
            return raw(i);
        }
    }

private:
    int col(std::size_t i) const { return static_cast<int>(i); }

    int type(std::size_t i) const { return sqlite3_column_type(st_, col(i)); }

    std::string raw(std::size_t i) const {
        const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(st_, col(i)));
        return p == nullptr
                   ? std::string()
                   : std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(st_, col(i))));
    }

    sqlite3_stmt* st_;
};

// A prepared statement, finalized when it goes out of scope.
struct Statement {
    sqlite3_stmt* st = nullptr;
    Statement() = default;
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;

    ~Statement() { sqlite3_finalize(st); }
};

class SqliteConnection final : public Connection {
public:
    explicit SqliteConnection(sqlite3* db) : db_(db) {}

    ~SqliteConnection() override { sqlite3_close(db_); }

    Engine engine() const override { return Engine::SQLite; }

    Status exec(const std::string& sql) override {
        char* msg = nullptr;
        if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &msg) != SQLITE_OK) {
            std::string why = msg != nullptr ? msg : sqlite3_errmsg(db_);
            sqlite3_free(msg);
            return fail("SQLite: " + why);
        }
        return Done{};
    }

    Status query(const std::string& sql, const RowFn& fn,
                 std::vector<std::string>* names) override {
        Statement s;
        if (sqlite3_prepare_v2(db_, sql.c_str(), static_cast<int>(sql.size()), &s.st, nullptr) !=
            SQLITE_OK) {
            return error();
        }
        if (names != nullptr) {
            names->clear();
            for (int i = 0; i < sqlite3_column_count(s.st); ++i) {
                names->emplace_back(sqlite3_column_name(s.st, i));
            }
        }
        SqliteRow row(s.st);
        for (;;) {
            int rc = sqlite3_step(s.st);
            if (rc == SQLITE_DONE) {
                return Done{};
            }
            if (rc != SQLITE_ROW) {
                return error();
            }
            if (!fn(row)) {
                return Done{};
            }
        }
    }

    Status insert(const std::string& table, const std::vector<std::string>& columns,
                  std::size_t rows, const FillFn& fill) override {
        std::string sql = "INSERT INTO " + table + " (";
        std::string marks;
        for (std::size_t i = 0; i < columns.size(); ++i) {
            sql += (i == 0 ? "" : ", ") + quote(columns[i]);
            marks += i == 0 ? "?" : ", ?";
        }
        sql += ") VALUES (" + marks + ")";
        Statement s;
        if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &s.st, nullptr) != SQLITE_OK) {
            return error();
        }
        std::vector<SqlValue> cells(columns.size());
        for (std::size_t r = 0; r < rows; ++r) {
            std::fill(cells.begin(), cells.end(), SqlValue{});
            fill(r, cells);
            for (std::size_t i = 0; i < cells.size(); ++i) {
                bind(s.st, static_cast<int>(i) + 1, cells[i]);
            }
            if (sqlite3_step(s.st) != SQLITE_DONE) {
                return error();
            }
            sqlite3_reset(s.st);
        }
        return Done{};
    }

private:
    static void bind(sqlite3_stmt* st, int i, const SqlValue& v) {
        if (const auto* x = std::get_if<std::int64_t>(&v)) {
            sqlite3_bind_int64(st, i, *x);
        } else if (const auto* d = std::get_if<double>(&v)) {
            sqlite3_bind_double(st, i, *d);
        } else if (const auto* b = std::get_if<bool>(&v)) {
            sqlite3_bind_int(st, i, *b ? 1 : 0);
        } else if (const auto* t = std::get_if<std::string_view>(&v)) {
            // An empty view may have no data pointer, which SQLite would take for NULL.
            sqlite3_bind_text(st, i, t->empty() ? "" : t->data(), static_cast<int>(t->size()),
                              SQLITE_TRANSIENT);
        } else {
            sqlite3_bind_null(st, i);
        }
    }

    Failure error() const { return fail(std::string("SQLite: ") + sqlite3_errmsg(db_)); }

    sqlite3* db_;
};

} // namespace

Result<std::unique_ptr<Connection>> connect_sqlite(const std::string& path, bool create) {
    sqlite3* db = nullptr;
    int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0);
    int rc = sqlite3_open_v2(path.c_str(), &db, flags, nullptr);
    if (rc != SQLITE_OK) {
        std::string why = db != nullptr ? sqlite3_errmsg(db) : "out of memory";
        sqlite3_close(db);
        return fail("cannot open SQLite database '" + path + "': " + why);
    }
    sqlite3_busy_timeout(db, 10000);
    auto c = std::make_unique<SqliteConnection>(db);
    // A file that is not a database is found by the first statement.
    if (auto st = c->exec("PRAGMA schema_version"); !st) {
        return fail("cannot open SQLite database '" + path + "': " + st.error());
    }
    return std::unique_ptr<Connection>(std::move(c));
}

} // namespace catplan::db::detail
