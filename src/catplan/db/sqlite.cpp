// The SQLite engine (Debian's libsqlite3): one database file, statements prepared one at a time.

#include "catplan/base/dynamic_library.hpp"
#include "catplan/db/detail/engines.hpp"

#include <algorithm>
#include <sqlite3.h>

namespace catplan::db::detail {
namespace {

// SQLite's functions, loaded at the first `sqlite:` connection rather than linked, as libpq is
// (libpq.hpp): linked, it cost every catplan command a few hundred microseconds of start-up, and
// only the database commands use it. The types are those of SQLite's header (libsqlite3-dev).
struct Sqlite {
    decltype(&::sqlite3_bind_double) bind_double = nullptr;
    decltype(&::sqlite3_bind_int) bind_int = nullptr;
    decltype(&::sqlite3_bind_int64) bind_int64 = nullptr;
    decltype(&::sqlite3_bind_null) bind_null = nullptr;
    decltype(&::sqlite3_bind_text) bind_text = nullptr;
    decltype(&::sqlite3_busy_timeout) busy_timeout = nullptr;
    decltype(&::sqlite3_close) close = nullptr;
    decltype(&::sqlite3_column_bytes) column_bytes = nullptr;
    decltype(&::sqlite3_column_count) column_count = nullptr;
    decltype(&::sqlite3_column_double) column_double = nullptr;
    decltype(&::sqlite3_column_int64) column_int64 = nullptr;
    decltype(&::sqlite3_column_name) column_name = nullptr;
    decltype(&::sqlite3_column_text) column_text = nullptr;
    decltype(&::sqlite3_column_type) column_type = nullptr;
    decltype(&::sqlite3_errmsg) errmsg = nullptr;
    decltype(&::sqlite3_exec) exec = nullptr;
    decltype(&::sqlite3_finalize) finalize = nullptr;
    decltype(&::sqlite3_free) free = nullptr;
    decltype(&::sqlite3_open_v2) open_v2 = nullptr;
    decltype(&::sqlite3_prepare_v2) prepare_v2 = nullptr;
    decltype(&::sqlite3_reset) reset = nullptr;
    decltype(&::sqlite3_step) step = nullptr;
};

void bind_sqlite(SymbolBinder& b, Sqlite& f) {
    b.function(f.bind_double, "sqlite3_bind_double");
    b.function(f.bind_int, "sqlite3_bind_int");
    b.function(f.bind_int64, "sqlite3_bind_int64");
    b.function(f.bind_null, "sqlite3_bind_null");
    b.function(f.bind_text, "sqlite3_bind_text");
    b.function(f.busy_timeout, "sqlite3_busy_timeout");
    b.function(f.close, "sqlite3_close");
    b.function(f.column_bytes, "sqlite3_column_bytes");
    b.function(f.column_count, "sqlite3_column_count");
    b.function(f.column_double, "sqlite3_column_double");
    b.function(f.column_int64, "sqlite3_column_int64");
    b.function(f.column_name, "sqlite3_column_name");
    b.function(f.column_text, "sqlite3_column_text");
    b.function(f.column_type, "sqlite3_column_type");
    b.function(f.errmsg, "sqlite3_errmsg");
    b.function(f.exec, "sqlite3_exec");
    b.function(f.finalize, "sqlite3_finalize");
    b.function(f.free, "sqlite3_free");
    b.function(f.open_v2, "sqlite3_open_v2");
    b.function(f.prepare_v2, "sqlite3_prepare_v2");
    b.function(f.reset, "sqlite3_reset");
    b.function(f.step, "sqlite3_step");
}

LazyLibrary<Sqlite>& sqlite() {
    // The soname of Debian's libsqlite3-0 (the one libsqlite3-dev links against).
    static LazyLibrary<Sqlite> lib("libsqlite3.so.0", "SQLite (Debian's libsqlite3-0)",
                                   bind_sqlite);
    return lib;
}

// SQLite's functions, once a connection has loaded them.
const Sqlite& lib() {
    return sqlite().get();
}

class SqliteRow final : public Row {
public:
    explicit SqliteRow(sqlite3_stmt* st) : st_(st) {}

    std::size_t size() const override { return static_cast<std::size_t>(lib().column_count(st_)); }

    bool is_null(std::size_t i) const override { return type(i) == SQLITE_NULL; }

    std::optional<std::int64_t> integer(std::size_t i) const override {
        if (type(i) != SQLITE_INTEGER) {
            return std::nullopt;
        }
        return lib().column_int64(st_, col(i));
    }

    std::optional<double> real(std::size_t i) const override {
        int t = type(i);
        if (t != SQLITE_FLOAT && t != SQLITE_INTEGER) {
            return std::nullopt;
        }
        return lib().column_double(st_, col(i));
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

    int type(std::size_t i) const { return lib().column_type(st_, col(i)); }

    std::string raw(std::size_t i) const {
        const auto* p = reinterpret_cast<const char*>(lib().column_text(st_, col(i)));
        return p == nullptr
                   ? std::string()
                   : std::string(p, static_cast<std::size_t>(lib().column_bytes(st_, col(i))));
    }

    sqlite3_stmt* st_;
};

// A prepared statement, finalized when it goes out of scope.
struct Statement {
    sqlite3_stmt* st = nullptr;
    Statement() = default;
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;

    ~Statement() { lib().finalize(st); }
};

class SqliteConnection final : public Connection {
public:
    explicit SqliteConnection(sqlite3* db) : db_(db) {}

    ~SqliteConnection() override { lib().close(db_); }

    Engine engine() const override { return Engine::SQLite; }

    Status exec(const std::string& sql) override {
        char* msg = nullptr;
        if (lib().exec(db_, sql.c_str(), nullptr, nullptr, &msg) != SQLITE_OK) {
            std::string why = msg != nullptr ? msg : lib().errmsg(db_);
            lib().free(msg);
            return fail("SQLite: " + why);
        }
        return Done{};
    }

    Status query(const std::string& sql, const RowFn& fn,
                 std::vector<std::string>* names) override {
        Statement s;
        if (lib().prepare_v2(db_, sql.c_str(), static_cast<int>(sql.size()), &s.st, nullptr) !=
            SQLITE_OK) {
            return error();
        }
        if (names != nullptr) {
            names->clear();
            for (int i = 0; i < lib().column_count(s.st); ++i) {
                names->emplace_back(lib().column_name(s.st, i));
            }
        }
        SqliteRow row(s.st);
        for (;;) {
            int rc = lib().step(s.st);
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
        if (lib().prepare_v2(db_, sql.c_str(), -1, &s.st, nullptr) != SQLITE_OK) {
            return error();
        }
        std::vector<SqlValue> cells(columns.size());
        for (std::size_t r = 0; r < rows; ++r) {
            std::fill(cells.begin(), cells.end(), SqlValue{});
            fill(r, cells);
            for (std::size_t i = 0; i < cells.size(); ++i) {
                bind(s.st, static_cast<int>(i) + 1, cells[i]);
            }
            if (lib().step(s.st) != SQLITE_DONE) {
                return error();
            }
            lib().reset(s.st);
        }
        return Done{};
    }

private:
    static void bind(sqlite3_stmt* st, int i, const SqlValue& v) {
        if (const auto* x = std::get_if<std::int64_t>(&v)) {
            lib().bind_int64(st, i, *x);
        } else if (const auto* d = std::get_if<double>(&v)) {
            lib().bind_double(st, i, *d);
        } else if (const auto* b = std::get_if<bool>(&v)) {
            lib().bind_int(st, i, *b ? 1 : 0);
        } else if (const auto* t = std::get_if<std::string_view>(&v)) {
            // An empty view may have no data pointer, which SQLite would take for NULL.
            lib().bind_text(st, i, t->empty() ? "" : t->data(), static_cast<int>(t->size()),
                            SQLITE_TRANSIENT);
        } else {
            lib().bind_null(st, i);
        }
    }

    Failure error() const { return fail(std::string("SQLite: ") + lib().errmsg(db_)); }

    sqlite3* db_;
};

} // namespace

Result<std::unique_ptr<Connection>> connect_sqlite(const std::string& path, bool create) {
    if (std::string missing; sqlite().load(missing) == nullptr) {
        return fail("cannot open SQLite database '" + path + "': " + missing);
    }
    sqlite3* db = nullptr;
    int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0);
    int rc = lib().open_v2(path.c_str(), &db, flags, nullptr);
    if (rc != SQLITE_OK) {
        std::string why = db != nullptr ? lib().errmsg(db) : "out of memory";
        lib().close(db);
        return fail("cannot open SQLite database '" + path + "': " + why);
    }
    lib().busy_timeout(db, 10000);
    auto c = std::make_unique<SqliteConnection>(db);
    // A file that is not a database is found by the first statement.
    if (auto st = c->exec("PRAGMA schema_version"); !st) {
        return fail("cannot open SQLite database '" + path + "': " + st.error());
    }
    return std::unique_ptr<Connection>(std::move(c));
}

} // namespace catplan::db::detail
