#pragma once
// The two engines behind db::connect (sqlite.cpp, postgresql.cpp).

#include "catplan/db/connection.hpp"

namespace catplan::db::detail {

/// Opens the SQLite database file at path (creating it when `create`).
Result<std::unique_ptr<Connection>> connect_sqlite(const std::string& path, bool create);
/// Connects to PostgreSQL with libpq's connection string or URI.
Result<std::unique_ptr<Connection>> connect_postgresql(const std::string& conninfo);

} // namespace catplan::db::detail
