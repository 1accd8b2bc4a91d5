#include "catplan/db/detail/libpq.hpp"

#include "catplan/base/assert.hpp"

#include <dlfcn.h>

namespace catplan::db::detail {
namespace {

struct Loaded {
    LibPq functions;
    std::string why; // empty when every function was found
};

template <class F>
void bind(void* handle, const char* name, F& f, std::string& why) {
    f = reinterpret_cast<F>(dlsym(handle, name));
    if (f == nullptr && why.empty()) {
        why = std::string("libpq has no function ") + name;
    }
}

Loaded load() {
    Loaded l;
    // The soname Debian's libpq5 installs (the one libpq-dev links against).
    void* h = dlopen("libpq.so.5", RTLD_NOW | RTLD_LOCAL);
    if (h == nullptr) {
        const char* e = dlerror();
        l.why = std::string("cannot load libpq (Debian's libpq5): ") + (e ? e : "not found");
        return l;
    }
    auto& f = l.functions;
    bind(h, "PQconnectdb", f.connectdb, l.why);
    bind(h, "PQstatus", f.status, l.why);
    bind(h, "PQerrorMessage", f.errorMessage, l.why);
    bind(h, "PQfinish", f.finish, l.why);
    bind(h, "PQexec", f.exec, l.why);
    bind(h, "PQsendQuery", f.sendQuery, l.why);
    bind(h, "PQsetSingleRowMode", f.setSingleRowMode, l.why);
    bind(h, "PQgetResult", f.getResult, l.why);
    bind(h, "PQresultStatus", f.resultStatus, l.why);
    bind(h, "PQresultErrorMessage", f.resultErrorMessage, l.why);
    bind(h, "PQclear", f.clear, l.why);
    bind(h, "PQnfields", f.nfields, l.why);
    bind(h, "PQfname", f.fname, l.why);
    bind(h, "PQftype", f.ftype, l.why);
    bind(h, "PQgetisnull", f.getisnull, l.why);
    bind(h, "PQgetvalue", f.getvalue, l.why);
    bind(h, "PQgetlength", f.getlength, l.why);
    bind(h, "PQputCopyData", f.putCopyData, l.why);
    bind(h, "PQputCopyEnd", f.putCopyEnd, l.why);
    return l; // the library stays loaded for the process's life
}

const Loaded& loaded() {
    static const Loaded l = load(); // thread-safe once
    return l;
}

} // namespace

const LibPq* load_libpq(std::string& why) {
    const Loaded& l = loaded();
    if (!l.why.empty()) {
        why = l.why;
        return nullptr;
    }
    return &l.functions;
}

const LibPq& libpq() {
    const Loaded& l = loaded();
    CATPLAN_ASSERT(l.why.empty(), "libpq used before a PostgreSQL connection loaded it");
    return l.functions;
}

} // namespace catplan::db::detail
