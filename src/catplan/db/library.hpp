#pragma once
// A plan library in a database (docs/database.md): the paper's case-based architecture (§VI.B),
// where plans are stored, retrieved, transferred and adapted. Four tables in namespace "catplan":
//
//   domains    _id, name (unique), schema_name, schema (Catlab schema JSON), source (the text
//              of the file it was added from, for people)
//   problems   _id, domain, name (unique per domain), initial, goal (states as Catlab ACSet
//              JSON with the names of parts and variables beside it)
//   plans      _id, problem, label (where the plan came from), steps (one step a line)
//   transfers  plan, map (together the key), migration, source_valid, valid, reason,
//              goal_satisfied, goal_total, unsatisfied (JSON array), target_plan, failed_step,
//              ms: one row per plan transferred along a map, with its verdict
//
// `transfer_library` transfers every stored plan of the map's source domains that has no row
// for the map yet, in batches: a batch is read, transferred on every core (each worker with its
// own copy of the map and domains, loaded from the map's file), and its results written in one
// transaction before the next batch is read. So memory is bounded by a batch, an interrupted run
// loses at most the batch in progress, and running it again goes on where it stopped.

#include "catplan/db/connection.hpp"
#include "catplan/plan/domain.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace catplan::db {

/// A state as the library stores it: Catlab's ACSet JSON with the names beside it.
std::string state_to_text(const acset::ACSet& x);
/// Reads a state stored by state_to_text on `schema`, or the reason it cannot.
Result<acset::ACSet> state_from_text(const schema::SchemaPtr& schema, std::string_view text);

/// Creates the library's tables when they are missing.
Status open_library(Connection& c);

/// A plan stored in the library.
struct StoredPlan {
    std::int64_t id = 0;
    std::string domain, problem, label;
    std::size_t steps = 0;
};

/// Stores a problem of domain d (added from a file whose text is `source`) and its plans, each
/// with a label; the domain and problem are stored once (a second add finds them, and fails
/// when the stored schema or states differ). Runs in the caller's transaction.
Result<std::vector<StoredPlan>>
add_plans(Connection& c, const plan::Domain& d, std::string_view source, const plan::Problem& p,
          const std::vector<std::pair<std::string, plan::Plan>>& plans);

/// The outcome of one stored plan's transfer, as stored.
struct StoredTransfer {
    std::int64_t plan = 0;
    std::string domain, problem, label, map;
    std::string migration; ///< "delta" or "conjunctive"
    bool source_valid = false, valid = false;
    std::string reason;
    std::size_t goal_satisfied = 0, goal_total = 0;
    std::vector<std::string> unsatisfied;
    std::vector<std::string> target_plan;
    std::optional<std::size_t> failed_step; ///< 1-based
    double ms = 0;
};

/// One JSON object on one line (JSON Lines).
std::string to_json_line(const StoredTransfer& t);
std::string to_json_line(const StoredPlan& p);

struct LibraryTransferOptions {
    /// Worker threads (0: one per core).
    std::size_t jobs = 0;
    /// Plans read, transferred and written together.
    std::size_t batch = 64;
    /// Stop after this many plans (0: all).
    std::size_t limit = 0;
};

/// What a library transfer did.
struct LibraryTransferSummary {
    std::size_t transferred = 0, valid = 0, already_done = 0;
    double seconds = 0;
};

/// Transfers the stored plans of the source domains of map `map_name` declared in `map_file`
/// (which must load without errors and declare those domains by name) that have no result for
/// the map yet; calls `each` on every result as its batch is committed.
Result<LibraryTransferSummary>
transfer_library(Connection& c, const std::string& map_file, const std::string& map_name,
                 const LibraryTransferOptions& options,
                 const std::function<void(const StoredTransfer&)>& each);

/// Which stored results a query returns.
struct LibraryQuery {
    std::string map;           ///< only transfers along this map ("" for all)
    std::string domain;        ///< only plans of this domain
    std::string problem;       ///< only plans of this problem
    std::optional<bool> valid; ///< only valid (true) or failed (false) transfers
};

/// The stored transfers that match q, by plan then map.
Status query_transfers(Connection& c, const LibraryQuery& q,
                       const std::function<void(const StoredTransfer&)>& each);
/// The stored plans that match q (map and valid are ignored), by id.
Status query_plans(Connection& c, const LibraryQuery& q,
                   const std::function<void(const StoredPlan&)>& each);

} // namespace catplan::db
