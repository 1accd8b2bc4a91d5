#include "catplan/db/connection.hpp"

#include "catplan/db/detail/engines.hpp"

namespace catplan::db {

std::string_view to_string(Engine engine) {
    return engine == Engine::SQLite ? "SQLite" : "PostgreSQL";
}

Result<Url> parse_url(std::string_view text) {
    Url url;
    url.text = std::string(text);
    auto starts = [&](std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; };
    if (starts("sqlite:")) {
        url.engine = Engine::SQLite;
        url.target = std::string(text.substr(7));
        if (url.target.empty()) {
            return fail("'" + url.text + "' names no file (write sqlite:PATH)");
        }
        return url;
    }
    if (starts("postgresql://") || starts("postgres://")) {
        url.engine = Engine::PostgreSQL;
        url.target = url.text;
        return url;
    }
    return fail("'" + url.text +
                "' is not a database URL: write sqlite:PATH or postgresql://[user@]host[:port]/db");
}

Result<std::int64_t> Connection::query_integer(const std::string& sql) {
    std::optional<std::int64_t> value;
    auto st = query(sql, [&](const Row& r) {
        value = r.size() > 0 ? r.integer(0) : std::nullopt;
        return false;
    });
    if (!st) {
        return fail(st.error());
    }
    if (!value) {
        return fail("the query returned no integer: " + sql);
    }
    return *value;
}

Result<std::unique_ptr<Connection>> connect(const Url& url, bool create) {
    if (url.engine == Engine::SQLite) {
        return detail::connect_sqlite(url.target, create);
    }
    return detail::connect_postgresql(url.target);
}

Result<std::unique_ptr<Connection>> connect(std::string_view text, bool create) {
    auto url = parse_url(text);
    if (!url) {
        return fail(url.error());
    }
    return connect(*url, create);
}

Transaction::Transaction(Connection& c) : c_(c), begun_(c.exec("BEGIN")) {
    open_ = begun_.has_value();
}

Transaction::~Transaction() {
    if (open_) {
        (void)c_.exec("ROLLBACK");
    }
}

Status Transaction::commit() {
    CATPLAN_ASSERT(open_, "commit of a transaction that is not open");
    open_ = false;
    auto st = c_.exec("COMMIT");
    if (!st) {
        (void)c_.exec("ROLLBACK");
    }
    return st;
}

std::string quote(std::string_view identifier) {
    std::string out = "\"";
    for (char ch : identifier) {
        out += ch;
        if (ch == '"') {
            out += '"';
        }
    }
    return out + "\"";
}

std::string quote_literal(std::string_view text) {
    std::string out = "'";
    for (char ch : text) {
        out += ch;
        if (ch == '\'') {
            out += '\'';
        }
    }
    return out + "'";
}

std::string table_name(Engine engine, std::string_view ns, std::string_view name) {
    if (engine == Engine::PostgreSQL) {
        return quote(ns) + "." + quote(name);
    }
    return quote(std::string(ns) + "." + std::string(name));
}

Result<std::vector<std::string>> tables_in(Connection& c, std::string_view ns) {
    std::string sql =
        c.engine() == Engine::SQLite
            ? "SELECT substr(name, " + std::to_string(ns.size() + 2) +
                  ") FROM sqlite_master WHERE type = 'table' AND substr(name, 1, " +
                  std::to_string(ns.size() + 1) + ") = " + quote_literal(std::string(ns) + ".") +
                  " ORDER BY 1"
            : "SELECT table_name::text FROM information_schema.tables WHERE table_schema = " +
                  quote_literal(ns) + " ORDER BY 1";
    std::vector<std::string> names;
    auto st = c.query(sql, [&](const Row& r) {
        names.push_back(r.text(0).value_or(""));
        return true;
    });
    if (!st) {
        return fail(st.error());
    }
    return names;
}

Status drop_namespace(Connection& c, std::string_view ns) {
    if (c.engine() == Engine::PostgreSQL) {
        return c.exec("DROP SCHEMA IF EXISTS " + quote(ns) + " CASCADE");
    }
    auto names = tables_in(c, ns);
    if (!names) {
        return fail(names.error());
    }
    for (const auto& n : *names) {
        if (auto st = c.exec("DROP TABLE " + table_name(c.engine(), ns, n)); !st) {
            return st;
        }
    }
    return Done{};
}

} // namespace catplan::db
