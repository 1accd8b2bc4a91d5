// The PostgreSQL engine (Debian's libpq, loaded at the first connection: detail/libpq.hpp):
// statements as text, rows read in single-row mode (so a result never has to fit in memory) and
// bulk insertion through COPY FROM STDIN in text format.

#include "catplan/base/escape.hpp"
#include "catplan/db/detail/engines.hpp"
#include "catplan/db/detail/libpq.hpp"

#include <charconv>
#include <cstdlib>
#include <fmt/format.h>

namespace catplan::db::detail {
namespace {

class PgRow final : public Row {
public:
    explicit PgRow(const PGresult* r) : r_(r) {}

    std::size_t size() const override { return static_cast<std::size_t>(libpq().nfields(r_)); }

    bool is_null(std::size_t i) const override { return libpq().getisnull(r_, 0, col(i)) == 1; }

    std::optional<std::int64_t> integer(std::size_t i) const override {
        if (is_null(i) || !numeric(i, /*integral=*/true)) {
            return std::nullopt;
        }
        std::string_view s = raw(i);
        std::int64_t v = 0;
        auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec != std::errc() || p != s.data() + s.size()) {
            return std::nullopt;
        }
        return v;
    }

    std::optional<double> real(std::size_t i) const override {
        if (is_null(i) || !numeric(i, /*integral=*/false)) {
            return std::nullopt;
        }
        std::string s(raw(i));
        char* end = nullptr;
        double v = std::strtod(s.c_str(), &end);
        if (end != s.c_str() + s.size()) {
            return std::nullopt;
        }
        return v;
    }

    std::optional<bool> boolean(std::size_t i) const override {
        if (is_null(i) || libpq().ftype(r_, col(i)) != kBool) {
            return std::nullopt;
        }
        return raw(i) == "t";
    }

    std::optional<std::string> text(std::size_t i) const override {
        Oid t = libpq().ftype(r_, col(i));
        if (is_null(i) || (t != kText && t != kVarchar && t != kName && t != kBpchar)) {
            return std::nullopt;
        }
        return std::string(raw(i));
    }

    std::string display(std::size_t i) const override {
        if (is_null(i)) {
            return "NULL";
        }
        return text(i) ? quote_literal(raw(i)) : std::string(raw(i));
    }

private:
    // Type oids of pg_type (stable across versions).
    static constexpr Oid kBool = 16, kName = 19, kInt8 = 20, kInt2 = 21, kInt4 = 23, kText = 25,
                         kOid = 26, kFloat4 = 700, kFloat8 = 701, kBpchar = 1042, kVarchar = 1043,
                         kNumeric = 1700;

    int col(std::size_t i) const { return static_cast<int>(i); }

    bool numeric(std::size_t i, bool integral) const {
        Oid t = libpq().ftype(r_, col(i));
        bool whole = t == kInt8 || t == kInt2 || t == kInt4 || t == kOid;
        return integral ? whole : whole || t == kFloat4 || t == kFloat8 || t == kNumeric;
    }

    std::string_view raw(std::size_t i) const {
        return {libpq().getvalue(r_, 0, col(i)),
                static_cast<std::size_t>(libpq().getlength(r_, 0, col(i)))};
    }

    const PGresult* r_;
};

// A result, cleared when it goes out of scope.
struct Res {
    PGresult* r = nullptr;

    explicit Res(PGresult* p) : r(p) {}

    Res(const Res&) = delete;
    Res& operator=(const Res&) = delete;

    ~Res() { libpq().clear(r); }
};

// Appends a cell in COPY's text format: \N for NULL, backslash escapes in text.
void copy_cell(std::string& out, const SqlValue& v) {
    if (const auto* x = std::get_if<std::int64_t>(&v)) {
        out += std::to_string(*x);
    } else if (const auto* d = std::get_if<double>(&v)) {
        out += fmt::format("{}", *d); // shortest form that reads back to the same double
    } else if (const auto* b = std::get_if<bool>(&v)) {
        out += *b ? 't' : 'f';
    } else if (const auto* t = std::get_if<std::string_view>(&v)) {
        out += escape_chars(*t, [](char c) -> std::optional<std::string_view> {
            switch (c) {
            case '\\':
                return "\\\\";
            case '\n':
                return "\\n";
            case '\r':
                return "\\r";
            case '\t':
                return "\\t";
            default:
                return std::nullopt;
            }
        });
    } else {
        out += "\\N";
    }
}

class PgConnection final : public Connection {
public:
    explicit PgConnection(PGconn* c) : c_(c) {}

    ~PgConnection() override { libpq().finish(c_); }

    Engine engine() const override { return Engine::PostgreSQL; }

    Status exec(const std::string& sql) override {
        Res r(libpq().exec(c_, sql.c_str()));
        auto s = libpq().resultStatus(r.r);
        if (s != PGRES_COMMAND_OK && s != PGRES_TUPLES_OK) {
            return error(r.r);
        }
        return Done{};
    }

    Status query(const std::string& sql, const RowFn& fn,
                 std::vector<std::string>* names) override {
        if (libpq().sendQuery(c_, sql.c_str()) != 1) {
            return error(nullptr);
        }
        libpq().setSingleRowMode(c_);
        std::optional<Failure> failure;
        bool reading = true;
        bool named = names == nullptr;
        while (PGresult* p = libpq().getResult(c_)) {
            Res r(p);
            auto s = libpq().resultStatus(r.r);
            if (!named && (s == PGRES_SINGLE_TUPLE || s == PGRES_TUPLES_OK)) {
                for (int i = 0; i < libpq().nfields(r.r); ++i) {
                    names->emplace_back(libpq().fname(r.r, i));
                }
                named = true;
            }
            if (s == PGRES_SINGLE_TUPLE) {
                if (reading && !fn(PgRow(r.r))) {
                    reading = false;
                    // The rest is drained (libpq has no cheaper way to stop a query).
                }
            } else if (s != PGRES_TUPLES_OK && s != PGRES_COMMAND_OK && !failure) {
                failure = error(r.r);
            }
        }
        if (failure) {
            return *failure;
        }
        return Done{};
    }

    Status insert(const std::string& table, const std::vector<std::string>& columns,
                  std::size_t rows, const FillFn& fill) override {
        std::string sql = "COPY " + table + " (";
        for (std::size_t i = 0; i < columns.size(); ++i) {
            sql += (i == 0 ? "" : ", ") + quote(columns[i]);
        }
        sql += ") FROM STDIN";
        {
            Res r(libpq().exec(c_, sql.c_str()));
            if (libpq().resultStatus(r.r) != PGRES_COPY_IN) {
                return error(r.r);
            }
        }
        std::string buf;
        std::vector<SqlValue> cells(columns.size());
        bool ok = true;
        for (std::size_t i = 0; i < rows && ok; ++i) {
            std::fill(cells.begin(), cells.end(), SqlValue{});
            fill(i, cells);
            for (std::size_t k = 0; k < cells.size(); ++k) {
                if (k > 0) {
                    buf += '\t';
                }
                copy_cell(buf, cells[k]);
            }
            buf += '\n';
            if (buf.size() >= (1U << 20)) {
                ok = libpq().putCopyData(c_, buf.data(), static_cast<int>(buf.size())) == 1;
                buf.clear();
            }
        }
        if (ok && !buf.empty()) {
            ok = libpq().putCopyData(c_, buf.data(), static_cast<int>(buf.size())) == 1;
        }
        libpq().putCopyEnd(c_, ok ? nullptr : "catplan stopped the copy");
        std::optional<Failure> failure;
        while (PGresult* p = libpq().getResult(c_)) {
            Res r(p);
            if (libpq().resultStatus(r.r) != PGRES_COMMAND_OK && !failure) {
                failure = error(r.r);
            }
        }
        if (failure) {
            return *failure;
        }
        return Done{};
    }

private:
    Failure error(const PGresult* r) const {
        std::string why = r != nullptr ? libpq().resultErrorMessage(r) : "";
        if (why.empty()) {
            why = libpq().errorMessage(c_);
        }
        while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) {
            why.pop_back();
        }
        return fail("PostgreSQL: " + why);
    }

    PGconn* c_;
};

} // namespace

Result<std::unique_ptr<Connection>> connect_postgresql(const std::string& conninfo) {
    std::string missing;
    const LibPq* pq = load_libpq(missing);
    if (pq == nullptr) {
        return fail("cannot connect to PostgreSQL at '" + conninfo + "': " + missing);
    }
    PGconn* c = pq->connectdb(conninfo.c_str());
    if (c == nullptr || pq->status(c) != CONNECTION_OK) {
        std::string why = c != nullptr ? pq->errorMessage(c) : "out of memory";
        while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) {
            why.pop_back();
        }
        pq->finish(c);
        return fail("cannot connect to PostgreSQL at '" + conninfo + "': " + why);
    }
    auto conn = std::make_unique<PgConnection>(c);
    // Quiet notices (DROP ... IF EXISTS), and floats printed exactly.
    if (auto st = conn->exec("SET client_min_messages = warning; SET extra_float_digits = 3");
        !st) {
        return fail(st.error());
    }
    return std::unique_ptr<Connection>(std::move(conn));
}

} // namespace catplan::db::detail
