#pragma once
// A connection to a relational database: SQLite (embedded, Debian's libsqlite3) or PostgreSQL
// (Debian's libpq), chosen by the URL:
//
//   sqlite:path/to/file.db           sqlite::memory:
//   postgresql://user@host:port/db   postgresql:///db?host=/tmp/socketdir   (libpq's URI form)
//
// Only what catplan's state tables, migrations and plan library need: statements run as text,
// rows read one at a time (PostgreSQL in single-row mode, so a result never has to fit in
// memory), bulk insertion (a prepared statement in SQLite, COPY in PostgreSQL) and transactions.
// Every failure is data: a Failure whose reason is the database's own message, prefixed with
// what catplan was doing.
//
//   auto c = connect("sqlite:states.db");
//   Transaction t(**c);
//   (*c)->exec("CREATE TABLE t(x INTEGER)");
//   t.commit();

#include "catplan/base/result.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace catplan::db {

/// The database engines catplan speaks to.
enum class Engine : std::uint8_t { SQLite, PostgreSQL };

/// "SQLite" or "PostgreSQL".
std::string_view to_string(Engine engine);

/// The success of an operation that yields nothing (its failure carries the reason).
struct Done {};

using Status = Result<Done>;

/// A database URL taken apart.
struct Url {
    Engine engine = Engine::SQLite;
    /// The file (SQLite; ":memory:" for a private in-memory database) or libpq's connection
    /// string (PostgreSQL, the URL itself).
    std::string target;
    /// The URL as written.
    std::string text;
};

/// Parses `sqlite:PATH` or `postgresql://...` (also `postgres://`); the reason names the forms
/// accepted.
Result<Url> parse_url(std::string_view text);

/// A value to store in a cell: NULL, an integer, a float, a Boolean or a text.
using SqlValue = std::variant<std::monostate, std::int64_t, double, bool, std::string_view>;

/// One row of a query's result, read cell by cell; a typed read gives nullopt when the cell does
/// not hold a value of that type (or is NULL).
class Row {
public:
    virtual ~Row() = default;
    virtual std::size_t size() const = 0;
    virtual bool is_null(std::size_t i) const = 0;
    virtual std::optional<std::int64_t> integer(std::size_t i) const = 0;
    virtual std::optional<double> real(std::size_t i) const = 0;
    virtual std::optional<bool> boolean(std::size_t i) const = 0;
    virtual std::optional<std::string> text(std::size_t i) const = 0;
    /// The cell as text whatever its type ("NULL" for NULL), for messages.
    virtual std::string display(std::size_t i) const = 0;
};

/// Called once per row; return false to stop reading.
using RowFn = std::function<bool(const Row&)>;
/// Fills the cells of row i (one per column) for a bulk insertion.
using FillFn = std::function<void(std::size_t i, std::vector<SqlValue>& cells)>;

class Connection {
public:
    virtual ~Connection() = default;

    virtual Engine engine() const = 0;

    /// Runs one or more statements that return no rows.
    virtual Status exec(const std::string& sql) = 0;
    /// Runs one statement and calls fn on each row, in order. The column names are in `names`
    /// when it is not null.
    virtual Status query(const std::string& sql, const RowFn& fn,
                         std::vector<std::string>* names = nullptr) = 0;
    /// Inserts `rows` rows into `table` (a quoted, qualified name) with one cell per column.
    virtual Status insert(const std::string& table, const std::vector<std::string>& columns,
                          std::size_t rows, const FillFn& fill) = 0;

    /// The single integer a query returns (a count), or a failure.
    Result<std::int64_t> query_integer(const std::string& sql);
};

/// Opens a connection; the reason says why it cannot (a database that is not reachable, a file
/// that cannot be opened). With create false, a SQLite file that does not exist is an error
/// rather than a new empty database (for commands that only read).
Result<std::unique_ptr<Connection>> connect(const Url& url, bool create = true);

/// Opens a connection to a URL given as text.
Result<std::unique_ptr<Connection>> connect(std::string_view url, bool create = true);

/// A transaction: BEGIN when made, ROLLBACK when destroyed unless commit() succeeded, so a
/// command that fails half-way leaves the database as it was.
class Transaction {
public:
    explicit Transaction(Connection& c);
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    ~Transaction();

    /// Whether BEGIN succeeded (else why not, in status()).
    const Status& status() const { return begun_; }

    Status commit();

private:
    Connection& c_;
    Status begun_;
    bool open_ = false;
};

/// A quoted SQL identifier: "name", with inner quotes doubled.
std::string quote(std::string_view identifier);
/// A quoted SQL string literal: 'text', with inner quotes doubled.
std::string quote_literal(std::string_view text);

/// The (quoted) table `name` of namespace `ns`: "ns"."name" in PostgreSQL (a schema per
/// namespace), "ns.name" in SQLite.
std::string table_name(Engine engine, std::string_view ns, std::string_view name);

/// The names of the tables of namespace `ns` (without the namespace), sorted.
Result<std::vector<std::string>> tables_in(Connection& c, std::string_view ns);

/// Drops every table of namespace `ns` (in PostgreSQL the schema itself).
Status drop_namespace(Connection& c, std::string_view ns);

} // namespace catplan::db
