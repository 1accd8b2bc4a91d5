// libpq (Debian's libpq5), loaded when the first PostgreSQL connection is opened rather than
// linked: its dependencies (Kerberos, LDAP, TLS: some twenty libraries) cost every catplan
// command about 7 ms of start-up, and only `postgresql://` URLs need it (base/dynamic_library.hpp
// loads it). The header is libpq's own, so the functions keep their types.
#pragma once

#include <libpq-fe.h>
#include <string>

namespace catplan::db::detail {

/// The libpq functions the PostgreSQL engine calls (libpq's names without the PQ prefix).
struct LibPq {
    decltype(&::PQconnectdb) connectdb = nullptr;
    decltype(&::PQstatus) status = nullptr;
    decltype(&::PQerrorMessage) errorMessage = nullptr;
    decltype(&::PQfinish) finish = nullptr;
    decltype(&::PQexec) exec = nullptr;
    decltype(&::PQsendQuery) sendQuery = nullptr;
    decltype(&::PQsetSingleRowMode) setSingleRowMode = nullptr;
    decltype(&::PQgetResult) getResult = nullptr;
    decltype(&::PQresultStatus) resultStatus = nullptr;
    decltype(&::PQresultErrorMessage) resultErrorMessage = nullptr;
    decltype(&::PQclear) clear = nullptr;
    decltype(&::PQnfields) nfields = nullptr;
    decltype(&::PQfname) fname = nullptr;
    decltype(&::PQftype) ftype = nullptr;
    decltype(&::PQgetisnull) getisnull = nullptr;
    decltype(&::PQgetvalue) getvalue = nullptr;
    decltype(&::PQgetlength) getlength = nullptr;
    decltype(&::PQputCopyData) putCopyData = nullptr;
    decltype(&::PQputCopyEnd) putCopyEnd = nullptr;
};

/// libpq's functions, loaded on the first call; nullptr, with the reason in `why`, when the
/// library or one of its functions cannot be found.
const LibPq* load_libpq(std::string& why);

/// libpq's functions, once load_libpq has succeeded (asserted).
const LibPq& libpq();

} // namespace catplan::db::detail
