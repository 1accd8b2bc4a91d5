#include "catplan/db/detail/libpq.hpp"

#include "catplan/base/dynamic_library.hpp"

namespace catplan::db::detail {
namespace {

void bind(SymbolBinder& b, LibPq& f) {
    b.function(f.connectdb, "PQconnectdb");
    b.function(f.status, "PQstatus");
    b.function(f.errorMessage, "PQerrorMessage");
    b.function(f.finish, "PQfinish");
    b.function(f.exec, "PQexec");
    b.function(f.sendQuery, "PQsendQuery");
    b.function(f.setSingleRowMode, "PQsetSingleRowMode");
    b.function(f.getResult, "PQgetResult");
    b.function(f.resultStatus, "PQresultStatus");
    b.function(f.resultErrorMessage, "PQresultErrorMessage");
    b.function(f.clear, "PQclear");
    b.function(f.nfields, "PQnfields");
    b.function(f.fname, "PQfname");
    b.function(f.ftype, "PQftype");
    b.function(f.getisnull, "PQgetisnull");
    b.function(f.getvalue, "PQgetvalue");
    b.function(f.getlength, "PQgetlength");
    b.function(f.putCopyData, "PQputCopyData");
    b.function(f.putCopyEnd, "PQputCopyEnd");
}

LazyLibrary<LibPq>& library() {
    // The soname Debian's libpq5 installs (the one libpq-dev links against).
    static LazyLibrary<LibPq> lib("libpq.so.5", "libpq (Debian's libpq5)", bind);
    return lib;
}

} // namespace

const LibPq* load_libpq(std::string& why) {
    return library().load(why);
}

const LibPq& libpq() {
    return library().get();
}

} // namespace catplan::db::detail
