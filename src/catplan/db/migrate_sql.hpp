#pragma once
// Data migration inside the database (docs/database.md): a schema map F : D' -> D compiled to
// SQL that reads the tables of a state X on D (namespace `from`) and writes the tables of the
// migrated state on D' (namespace `to`), equal to migrate::migrate(F, X) part for part, names
// and variables included.
//
//   plain object  c' => c       INSERT INTO c' SELECT the rows of c, in _id order (Δ_F keeps
//                               X's numbering); a hom path is a chain of LEFT JOINs, so an unset
//                               hom on the way gives NULL
//   conjunctive   c' => @join   first the table c'__origin: one row per assignment of the query
//                               (a join of one alias per part of the query's shape, with its
//                               equations and filters in WHERE), numbered by ROW_NUMBER() in
//                               the order of migrate (lexicographic in the query's variables; a
//                               single filtered part keeps X's order), one column per part and
//                               per value of the shape, named by the term that reaches it
//                               (block, gripper.isHolding). Then c' from its origin table: the
//                               name of the first variable's part, each hom by a join with the
//                               codomain's origin table on the variables the query morphism
//                               fixes, each attribute along its path.
//   attribute variables         copied from D's variable tables to those of each type sent there
//   constants                   literals
//
// The origin tables stay beside the target tables: they are the tuple origins (which parts of X
// each tuple of Δ_F(X) is made of) that the transfer reads to carry matches through a map.
// Equality of attribute values in a query is that of catplan: a variable equals only itself and
// never a constant, which is what `a = b OR a__var = b__var` says in SQL (NULL is not true).

#include "catplan/db/connection.hpp"
#include "catplan/migrate/schema_map.hpp"

#include <string>
#include <vector>

namespace catplan::db {

/// The statements of one migration, in the order they run.
struct MigrationSql {
    std::vector<std::string> statements;

    /// Every statement followed by ";" and a newline.
    std::string text() const;
};

/// The name of the origin table of a target object ("BreadSliced__origin").
std::string origin_table(std::string_view object);

/// The SQL that migrates the state in namespace `from` along f into namespace `to` (which it
/// creates). f must be finished and ok.
MigrationSql migration_sql(const migrate::SchemaMap& f, Engine engine, const std::string& from,
                           const std::string& to);

/// Checks the source tables (layout, foreign keys, path equations, in SQL), then runs the
/// migration in one transaction; every problem found is in the failure, one per line. The
/// target namespace must hold no tables unless `replace`.
Status migrate_in_database(std::string_view url, const migrate::SchemaMap& f,
                           const std::string& from, const std::string& to, bool replace = false);

} // namespace catplan::db
