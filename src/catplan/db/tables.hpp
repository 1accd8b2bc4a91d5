#pragma once
// A state as tables (docs/database.md). A state on schema S lives in a namespace (by default S's
// name; PostgreSQL's schema, a name prefix "S." in SQLite):
//
//   object X         table X(_id INTEGER PRIMARY KEY, _name TEXT, one column per hom out of X
//                    (the _id of the part it points to, NULL when unset, a foreign key), one
//                    column per attribute a of X with a's value kind, and a__var (the _id of the
//                    attribute variable the cell holds, NULL otherwise, a foreign key))
//   attribute type T table T(_id INTEGER PRIMARY KEY, _name TEXT): T's attribute variables
//
// Parts are numbered from 1 in _id order (catplan's part p is _id p + 1), so an exported state
// reads back with the same numbering; names of parts and variables are kept in _name. A cell
// holds a value, or NULL with the variable in a__var, or NULL twice when unset. Booleans are
// BOOLEAN (0/1 in SQLite), integers BIGINT, floats DOUBLE PRECISION, strings TEXT.
//
// Reading checks what the database cannot: every table and column the schema needs is there,
// every cell has the right type, every foreign key points to a row, and every path equation of
// the schema holds (NULL-safe, so an unset path equals only an unset path). Every problem is
// reported, naming the table, the row (_id) and the column.

#include "catplan/acset/acset.hpp"
#include "catplan/db/connection.hpp"

#include <optional>
#include <string>
#include <vector>

namespace catplan::db {

using acset::ACSet;
using schema::Schema;
using schema::SchemaPtr;

/// The names catplan gives the tables and columns of a state on a schema.
class Layout {
public:
    Layout(Engine engine, std::string ns, const Schema& schema);

    Engine engine() const { return engine_; }

    const std::string& ns() const { return ns_; }

    const Schema& schema() const { return schema_; }

    /// The quoted table of an object.
    std::string table(ObId x) const;
    /// The quoted table of an attribute type (its variables).
    std::string table(AttrTypeId t) const;

    /// The column of the variable an attribute's cell holds ("hasColor__var").
    static std::string var_column(const schema::AttrInfo& a) { return a.name + "__var"; }

    /// The SQL type of an attribute type's values.
    std::string sql_type(AttrTypeId t) const;

    /// The statements that create the namespace and every table (in SQLite with their foreign
    /// keys).
    std::string create_sql() const;
    /// PostgreSQL's foreign keys, added once the rows are in (one validating scan per key);
    /// empty for SQLite.
    std::string foreign_key_sql() const;

    /// Why the schema cannot be laid out (a generator named like a column catplan adds), empty
    /// when it can.
    std::vector<std::string> problems() const;

private:
    Engine engine_;
    std::string ns_;
    const Schema& schema_;
};

/// The id column and the name column of every table.
inline constexpr const char* kIdColumn = "_id";
inline constexpr const char* kNameColumn = "_name";

/// Writes x as the tables of namespace ns, creating them; the namespace must hold no tables,
/// unless `replace`, which drops them first. Runs inside the caller's transaction.
Status write_state(Connection& c, const ACSet& x, const std::string& ns, bool replace = false);

/// A state read back from tables, or every problem found.
struct ReadState {
    std::optional<ACSet> state;
    std::vector<std::string> errors;
};

/// Reads the state on `schema` stored in namespace ns, checking it as described above.
ReadState read_state(Connection& c, const SchemaPtr& schema, const std::string& ns);

/// Checks the tables of a state without reading it into memory: every table and column is
/// there, every foreign key points to a row, every path equation holds (at most a few rows named
/// per check). Empty when the tables are a state on the layout's schema.
std::vector<std::string> verify_tables(Connection& c, const Layout& layout);

/// Every row (at most `limit` per equation) that violates a path equation of the schema, in
/// words; empty when they all hold.
Result<std::vector<std::string>> equation_violations(Connection& c, const Layout& layout,
                                                     std::size_t limit = 5);

/// Exports x to the database at url in one transaction (nothing is written on failure).
Status export_state(std::string_view url, const ACSet& x, const std::string& ns,
                    bool replace = false);

/// Imports the state on `schema` from namespace ns of the database at url.
ReadState import_state(std::string_view url, const SchemaPtr& schema, const std::string& ns);

} // namespace catplan::db
