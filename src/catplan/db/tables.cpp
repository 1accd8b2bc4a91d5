#include "catplan/db/tables.hpp"

#include "catplan/db/detail/sql.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <unordered_map>

namespace catplan::db {

using acset::Value;
using detail::col;

Layout::Layout(Engine engine, std::string ns, const Schema& schema)
    : engine_(engine), ns_(std::move(ns)), schema_(schema) {}

std::string Layout::table(ObId x) const {
    return table_name(engine_, ns_, schema_.ob(x).name);
}

std::string Layout::table(AttrTypeId t) const {
    return table_name(engine_, ns_, schema_.attr_type(t).name);
}

std::string Layout::sql_type(AttrTypeId t) const {
    switch (schema_.attr_type(t).kind) {
    case schema::ValueKind::Bool:
        return "BOOLEAN";
    case schema::ValueKind::Int:
        return "BIGINT";
    case schema::ValueKind::Float:
        return "DOUBLE PRECISION";
    default:
        return "TEXT";
    }
}

std::string Layout::create_sql() const {
    const Schema& s = schema_;
    bool pg = engine_ == Engine::PostgreSQL;
    // SQLite takes foreign keys inline (it has no ALTER TABLE ... ADD CONSTRAINT, and does not
    // enforce them unless asked); PostgreSQL gets them after the rows (foreign_key_sql).
    auto fk = [&](const std::string& to) {
        return pg ? std::string() : " REFERENCES " + to + "(" + quote(kIdColumn) + ")";
    };
    std::string sql = pg ? "CREATE SCHEMA IF NOT EXISTS " + quote(ns_) + ";\n" : "";
    std::string key =
        std::string(quote(kIdColumn)) + " BIGINT PRIMARY KEY, " + quote(kNameColumn) + " TEXT";
    if (!pg) {
        key =
            std::string(quote(kIdColumn)) + " INTEGER PRIMARY KEY, " + quote(kNameColumn) + " TEXT";
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        sql += "CREATE TABLE " + table(AttrTypeId(t)) + " (" + key + ");\n";
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        sql += "CREATE TABLE " + table(ObId(o)) + " (" + key;
        for (HomId h : s.homs_from(ObId(o))) {
            sql += ", " + quote(s.hom(h).name) + " BIGINT" + fk(table(s.hom(h).codom));
        }
        for (AttrId a : s.attrs_from(ObId(o))) {
            const auto& info = s.attr(a);
            sql += ", " + quote(info.name) + " " + sql_type(info.codom) + ", " +
                   quote(var_column(info)) + " BIGINT" + fk(table(info.codom));
        }
        sql += ");\n";
    }
    return sql;
}

std::string Layout::foreign_key_sql() const {
    if (engine_ != Engine::PostgreSQL) {
        return {};
    }
    const Schema& s = schema_;
    std::string sql;
    auto add = [&](ObId from, const std::string& column, const std::string& to) {
        sql += "ALTER TABLE " + table(from) + " ADD FOREIGN KEY (" + quote(column) +
               ") REFERENCES " + to + " (" + quote(kIdColumn) + ");\n";
    };
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        add(s.hom(HomId(h)).dom, s.hom(HomId(h)).name, table(s.hom(HomId(h)).codom));
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        const auto& info = s.attr(AttrId(a));
        add(info.dom, var_column(info), table(info.codom));
    }
    return sql;
}

std::vector<std::string> Layout::problems() const {
    std::vector<std::string> out;
    const Schema& s = schema_;
    auto reserved = [](const std::string& n) {
        return n == kIdColumn || n == kNameColumn ||
               (n.size() > 5 && n.compare(n.size() - 5, 5, "__var") == 0);
    };
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        if (reserved(s.hom(HomId(h)).name)) {
            out.push_back("hom '" + s.hom(HomId(h)).name + "' is named like a column catplan adds");
        }
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        if (reserved(s.attr(AttrId(a)).name)) {
            out.push_back("attribute '" + s.attr(AttrId(a)).name +
                          "' is named like a column catplan adds");
        }
    }
    return out;
}

namespace {

// A cell of an attribute column as SQL: the value, or NULL (then the variable goes beside it).
SqlValue sql_value(const Value& v) {
    return v.visit_concrete([](auto x) { return SqlValue(x); }, SqlValue{});
}

SqlValue name_value(std::string_view name) {
    return name.empty() ? SqlValue{} : SqlValue{name};
}

SqlValue id_value(Part p) {
    return p == kNoPart ? SqlValue{} : SqlValue{static_cast<std::int64_t>(p) + 1};
}

Status write_rows(Connection& c, const Layout& l, const ACSet& x) {
    const Schema& s = x.schema();
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        auto st = c.insert(l.table(ty), {kIdColumn, kNameColumn}, x.num_vars(ty),
                           [&](std::size_t j, std::vector<SqlValue>& cells) {
                               cells[0] = static_cast<std::int64_t>(j) + 1;
                               cells[1] = name_value(x.var_name(ty, static_cast<std::uint32_t>(j)));
                           });
        if (!st) {
            return st;
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        std::vector<std::string> columns{kIdColumn, kNameColumn};
        for (HomId h : s.homs_from(ob)) {
            columns.push_back(s.hom(h).name);
        }
        for (AttrId a : s.attrs_from(ob)) {
            columns.push_back(s.attr(a).name);
            columns.push_back(Layout::var_column(s.attr(a)));
        }
        auto homs = s.homs_from(ob);
        auto attrs = s.attrs_from(ob);
        auto st = c.insert(l.table(ob), columns, x.num_parts(ob),
                           [&](std::size_t i, std::vector<SqlValue>& cells) {
                               auto p = static_cast<Part>(i);
                               cells[0] = static_cast<std::int64_t>(i) + 1;
                               cells[1] = name_value(x.part_name(ob, p));
                               std::size_t k = 2;
                               for (HomId h : homs) {
                                   cells[k++] = id_value(x.subpart(h, p));
                               }
                               for (AttrId a : attrs) {
                                   const Value& v = x.subpart(a, p);
                                   cells[k++] = sql_value(v);
                                   cells[k++] = v.is_var() ? id_value(v.var_index()) : SqlValue{};
                               }
                           });
        if (!st) {
            return st;
        }
    }
    return Done{};
}

} // namespace

Status write_state(Connection& c, const ACSet& x, const std::string& ns, bool replace) {
    Layout l(c.engine(), ns, x.schema());
    if (auto problems = l.problems(); !problems.empty()) {
        return fail("schema " + x.schema().name() + " cannot be stored as tables: " + problems[0]);
    }
    auto existing = tables_in(c, ns);
    if (!existing) {
        return fail(existing.error());
    }
    if (!existing->empty() && !replace) {
        std::string list;
        for (std::size_t i = 0; i < existing->size() && i < 4; ++i) {
            list += (i == 0 ? "" : ", ") + (*existing)[i];
        }
        return fail(fmt::format("the database already holds tables of '{}' ({}{}); pass "
                                "--replace to overwrite them",
                                ns, list, existing->size() > 4 ? ", ..." : ""));
    }
    if (!existing->empty()) {
        if (auto st = drop_namespace(c, ns); !st) {
            return st;
        }
    }
    if (auto st = c.exec(l.create_sql()); !st) {
        return st;
    }
    if (auto st = write_rows(c, l, x); !st) {
        return st;
    }
    if (std::string fks = l.foreign_key_sql(); !fks.empty()) {
        return c.exec(fks);
    }
    return Done{};
}

namespace {

// Errors of one read, at most kMaxErrors of them spelled out.
struct Errors {
    static constexpr std::size_t kMax = 20;
    std::vector<std::string> list;
    std::size_t more = 0;

    void add(std::string e) {
        if (list.size() < kMax) {
            list.push_back(std::move(e));
        } else {
            ++more;
        }
    }

    /// Each message of `r`, or its error.
    void add_all(Result<std::vector<std::string>> r) {
        if (!r) {
            add(r.error());
            return;
        }
        for (auto& e : *r) {
            add(std::move(e));
        }
    }

    std::vector<std::string> done() {
        if (more > 0) {
            list.push_back(fmt::format("... and {} more", more));
        }
        return std::move(list);
    }
};

// The ids of a table's rows, in order, and the part (0-based) of each id.
struct Ids {
    std::vector<std::int64_t> ids; // sorted

    std::optional<Part> part(std::int64_t id) const {
        if (!ids.empty() && ids.front() == 1 &&
            ids.back() == static_cast<std::int64_t>(ids.size())) {
            if (id >= 1 && id <= static_cast<std::int64_t>(ids.size())) {
                return static_cast<Part>(id - 1);
            }
            return std::nullopt;
        }
        auto it = std::lower_bound(ids.begin(), ids.end(), id);
        if (it == ids.end() || *it != id) {
            return std::nullopt;
        }
        return static_cast<Part>(it - ids.begin());
    }
};

// Every table and column the layout needs is present.
bool check_tables(Connection& c, const Layout& l, Errors& errors) {
    const Schema& s = l.schema();
    auto present = tables_in(c, l.ns());
    if (!present) {
        errors.add(present.error());
        return false;
    }
    auto has = [&](const std::string& name) {
        return std::binary_search(present->begin(), present->end(), name);
    };
    auto check_columns = [&](const std::string& table, const std::vector<std::string>& need,
                             const std::string& what) {
        std::vector<std::string> names;
        auto st = c.query(
            "SELECT * FROM " + table + " LIMIT 0", [](const Row&) { return true; }, &names);
        if (!st) {
            errors.add(st.error());
            return;
        }
        for (const auto& n : need) {
            if (std::find(names.begin(), names.end(), n) == names.end()) {
                errors.add(fmt::format("table {} has no column {} ({})", table, quote(n), what));
            }
        }
    };
    std::size_t before = errors.list.size() + errors.more;
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        const auto& name = s.attr_type(AttrTypeId(t)).name;
        if (!has(name)) {
            errors.add(fmt::format("the database has no table {} (the variables of attribute "
                                   "type {} of schema {})",
                                   l.table(AttrTypeId(t)), name, s.name()));
            continue;
        }
        check_columns(l.table(AttrTypeId(t)), {kIdColumn, kNameColumn},
                      "every table has an id and a name");
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        if (!has(s.ob(ob).name)) {
            errors.add(fmt::format("the database has no table {} (object {} of schema {})",
                                   l.table(ob), s.ob(ob).name, s.name()));
            continue;
        }
        check_columns(l.table(ob), {kIdColumn, kNameColumn}, "every table has an id and a name");
        for (HomId h : s.homs_from(ob)) {
            const auto& info = s.hom(h);
            check_columns(l.table(ob), {info.name},
                          fmt::format("hom {}::Hom({}, {})", info.name, s.ob(info.dom).name,
                                      s.ob(info.codom).name));
        }
        for (AttrId a : s.attrs_from(ob)) {
            const auto& info = s.attr(a);
            check_columns(l.table(ob), {info.name, Layout::var_column(info)},
                          fmt::format("attribute {}::Attr({}, {})", info.name, s.ob(info.dom).name,
                                      s.attr_type(info.codom).name));
        }
    }
    return errors.list.size() + errors.more == before;
}

// A cell read as `T`, made into a value, or nullopt (the cell has another type).
template <class T, class Make>
std::optional<Value> cell_value(const std::optional<T>& cell, Make make) {
    return cell ? std::optional<Value>(make(*cell)) : std::nullopt;
}

// A value of kind `kind` read from column i, or nullopt (the cell has another type).
std::optional<Value> read_value(const Row& r, std::size_t i, schema::ValueKind kind) {
    switch (kind) {
    case schema::ValueKind::Bool:
        return cell_value(r.boolean(i), Value::boolean);
    case schema::ValueKind::Int:
        return cell_value(r.integer(i), Value::integer);
    case schema::ValueKind::Float:
        return cell_value(r.real(i), Value::real);
    case schema::ValueKind::String:
        return cell_value(r.text(i), [](const std::string& t) { return Value::string(t); });
    default:
        return std::nullopt;
    }
}

// The raw cells of one object's table: ids, names, hom ids and attribute values as read.
struct RawTable {
    Ids ids;
    std::vector<std::string> names;
    bool named = false;
    std::vector<std::vector<std::int64_t>> homs; // 0 for NULL
    std::vector<std::vector<Value>> values;
    std::vector<std::vector<std::int64_t>> vars; // 0 for NULL
};

std::string select_sql(const Layout& l, ObId ob) {
    const Schema& s = l.schema();
    std::string sql = std::string("SELECT ") + quote(kIdColumn) + ", " + quote(kNameColumn);
    for (HomId h : s.homs_from(ob)) {
        sql += ", " + quote(s.hom(h).name);
    }
    for (AttrId a : s.attrs_from(ob)) {
        sql += ", " + quote(s.attr(a).name) + ", " + quote(Layout::var_column(s.attr(a)));
    }
    return sql + " FROM " + l.table(ob) + " ORDER BY " + quote(kIdColumn);
}

std::string kind_word(schema::ValueKind k) {
    return k == schema::ValueKind::Unknown ? "NULL (its type has no kind)"
                                           : "a " + std::string(schema::to_string(k));
}

void read_table(Connection& c, const Layout& l, ObId ob, RawTable& t, Errors& errors) {
    const Schema& s = l.schema();
    auto homs = s.homs_from(ob);
    auto attrs = s.attrs_from(ob);
    t.homs.resize(homs.size());
    t.values.resize(attrs.size());
    t.vars.resize(attrs.size());
    std::string table = l.table(ob);
    auto st = c.query(select_sql(l, ob), [&](const Row& r) {
        auto id = r.integer(0);
        if (!id) {
            errors.add(
                fmt::format("table {}: a row has the id {}, not an integer", table, r.display(0)));
            return true;
        }
        t.ids.ids.push_back(*id);
        auto name = r.text(1);
        t.named = t.named || name.has_value();
        if (!name && !r.is_null(1)) {
            errors.add(fmt::format("table {}, row {}, column {}: {} is not a text", table, *id,
                                   quote(kNameColumn), r.display(1)));
        }
        t.names.push_back(name.value_or(""));
        std::size_t k = 2;
        for (std::size_t i = 0; i < homs.size(); ++i, ++k) {
            auto v = r.integer(k);
            if (!v && !r.is_null(k)) {
                errors.add(fmt::format("table {}, row {}, column {}: {} is not an id", table, *id,
                                       quote(s.hom(homs[i]).name), r.display(k)));
            }
            t.homs[i].push_back(v.value_or(0));
        }
        for (std::size_t i = 0; i < attrs.size(); ++i, k += 2) {
            const auto& info = s.attr(attrs[i]);
            schema::ValueKind kind = s.attr_type(info.codom).kind;
            Value v;
            if (!r.is_null(k)) {
                auto read = read_value(r, k, kind);
                if (!read) {
                    errors.add(fmt::format("table {}, row {}, column {}: {} is not {}", table, *id,
                                           quote(info.name), r.display(k), kind_word(kind)));
                }
                v = read.value_or(Value());
            }
            auto var = r.integer(k + 1);
            if (!var && !r.is_null(k + 1)) {
                errors.add(fmt::format("table {}, row {}, column {}: {} is not an id", table, *id,
                                       quote(Layout::var_column(info)), r.display(k + 1)));
            }
            if (var && !r.is_null(k)) {
                errors.add(fmt::format("table {}, row {}: column {} holds a value and column {} "
                                       "a variable; a cell holds one or the other",
                                       table, *id, quote(info.name),
                                       quote(Layout::var_column(info))));
            }
            t.values[i].push_back(v);
            t.vars[i].push_back(var.value_or(0));
        }
        return true;
    });
    if (!st) {
        errors.add(st.error());
    }
}

// Reads the variables of every attribute type: their ids and names.
void read_vars(Connection& c, const Layout& l, std::vector<Ids>& ids,
               std::vector<std::vector<std::string>>& names, Errors& errors) {
    const Schema& s = l.schema();
    ids.resize(s.num_attr_types());
    names.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        std::string table = l.table(AttrTypeId(t));
        auto st = c.query(std::string("SELECT ") + quote(kIdColumn) + ", " + quote(kNameColumn) +
                              " FROM " + table + " ORDER BY " + quote(kIdColumn),
                          [&](const Row& r) {
                              auto id = r.integer(0);
                              if (!id) {
                                  errors.add(fmt::format("table {}: a row has the id {}, not an "
                                                         "integer",
                                                         table, r.display(0)));
                                  return true;
                              }
                              ids[t].ids.push_back(*id);
                              names[t].push_back(r.text(1).value_or(""));
                              return true;
                          });
        if (!st) {
            errors.add(st.error());
        }
    }
}

// Builds the state from the raw tables, mapping ids to parts; every dangling id is an error.
void assemble(const Layout& l, std::vector<RawTable>& raw, const std::vector<Ids>& var_ids,
              const std::vector<std::vector<std::string>>& var_names, ACSet& x, Errors& errors) {
    const Schema& s = l.schema();
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (const auto& n : var_names[t]) {
            x.add_var(AttrTypeId(t), n);
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        x.add_parts(ObId(o), raw[o].ids.ids.size());
        if (raw[o].named) {
            std::vector<Symbol> names;
            names.reserve(raw[o].names.size());
            for (const auto& n : raw[o].names) {
                names.push_back(n.empty() ? Symbol() : Symbol::intern(n));
            }
            x.set_part_names(ObId(o), std::move(names));
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        const RawTable& t = raw[o];
        auto homs = s.homs_from(ob);
        for (std::size_t i = 0; i < homs.size(); ++i) {
            const auto& info = s.hom(homs[i]);
            const Ids& to = raw[info.codom.index()].ids;
            std::vector<Part> column(t.homs[i].size(), kNoPart);
            for (std::size_t p = 0; p < column.size(); ++p) {
                if (std::int64_t id = t.homs[i][p]; id != 0) {
                    auto q = to.part(id);
                    if (!q) {
                        errors.add(fmt::format("table {}, row {}, column {}: {} points to no row "
                                               "of {}",
                                               l.table(ob), t.ids.ids[p], quote(info.name), id,
                                               l.table(info.codom)));
                    }
                    column[p] = q.value_or(kNoPart);
                }
            }
            x.set_column(homs[i], column);
        }
        auto attrs = s.attrs_from(ob);
        for (std::size_t i = 0; i < attrs.size(); ++i) {
            const auto& info = s.attr(attrs[i]);
            std::vector<Value> column = t.values[i];
            for (std::size_t p = 0; p < column.size(); ++p) {
                if (std::int64_t id = t.vars[i][p]; id != 0) {
                    auto j = var_ids[info.codom.index()].part(id);
                    if (!j) {
                        errors.add(fmt::format("table {}, row {}, column {}: {} points to no row "
                                               "of {}",
                                               l.table(ob), t.ids.ids[p],
                                               quote(Layout::var_column(info)), id,
                                               l.table(info.codom)));
                    } else {
                        column[p] = Value::var(*j);
                    }
                }
            }
            x.set_column(attrs[i], column);
        }
    }
}

} // namespace

namespace {

// Every foreign key of the layout that points to no row, in SQL (a few rows per column).
void dangling_keys(Connection& c, const Layout& l, Errors& errors) {
    const Schema& s = l.schema();
    auto check = [&](ObId from, const std::string& column, const std::string& to) {
        std::string sql = "SELECT x." + quote(kIdColumn) + ", x." + quote(column) + " FROM " +
                          l.table(from) + " AS x LEFT JOIN " + to + " AS y ON y." +
                          quote(kIdColumn) + " = x." + quote(column) + " WHERE x." + quote(column) +
                          " IS NOT NULL AND y." + quote(kIdColumn) + " IS NULL ORDER BY 1 LIMIT 5";
        auto st = c.query(sql, [&](const Row& r) {
            errors.add(fmt::format("table {}, row {}, column {}: {} points to no row of {}",
                                   l.table(from), r.display(0), quote(column), r.display(1), to));
            return true;
        });
        if (!st) {
            errors.add(st.error());
        }
    };
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        const auto& info = s.hom(HomId(h));
        check(info.dom, info.name, l.table(info.codom));
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        const auto& info = s.attr(AttrId(a));
        check(info.dom, Layout::var_column(info), l.table(info.codom));
    }
}

// SQLite stores whatever a cell is given: every cell whose type is not its column's, in SQL (a
// few rows per column). PostgreSQL's column types already refuse them.
void wrong_types(Connection& c, const Layout& l, Errors& errors) {
    if (c.engine() != Engine::SQLite) {
        return;
    }
    const Schema& s = l.schema();
    auto check = [&](ObId from, const std::string& column, const std::string& allowed,
                     const std::string& word, bool boolean = false) {
        std::string sql =
            "SELECT " + quote(kIdColumn) + ", quote(" + quote(column) + ") FROM " + l.table(from) +
            " WHERE typeof(" + quote(column) + ") NOT IN ('null', " + allowed + ")" +
            (boolean ? " OR " + quote(column) + " NOT IN (0, 1)" : "") + " ORDER BY 1 LIMIT 5";
        auto st = c.query(sql, [&](const Row& r) {
            errors.add(fmt::format("table {}, row {}, column {}: {} is not {}", l.table(from),
                                   r.display(0), quote(column), r.text(1).value_or("?"), word));
            return true;
        });
        if (!st) {
            errors.add(st.error());
        }
    };
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        check(s.hom(HomId(h)).dom, s.hom(HomId(h)).name, "'integer'", "an id");
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        const auto& info = s.attr(AttrId(a));
        check(info.dom, Layout::var_column(info), "'integer'", "an id");
        schema::ValueKind kind = s.attr_type(info.codom).kind;
        std::string allowed = kind == schema::ValueKind::String    ? "'text'"
                              : kind == schema::ValueKind::Float   ? "'real', 'integer'"
                              : kind == schema::ValueKind::Unknown ? "'none'"
                                                                   : "'integer'";
        check(info.dom, info.name, allowed, kind_word(kind), kind == schema::ValueKind::Bool);
    }
}

} // namespace

std::vector<std::string> verify_tables(Connection& c, const Layout& l) {
    Errors errors;
    // Each check needs the one before it to pass (a text is no key, a dangling key no path).
    if (!check_tables(c, l, errors)) {
        return errors.done();
    }
    wrong_types(c, l, errors);
    if (errors.list.empty()) {
        dangling_keys(c, l, errors);
    }
    if (errors.list.empty()) {
        errors.add_all(equation_violations(c, l));
    }
    return errors.done();
}

Result<std::vector<std::string>> equation_violations(Connection& c, const Layout& l,
                                                     std::size_t limit) {
    const Schema& s = l.schema();
    std::vector<std::string> out;
    for (const auto& eq : s.equations()) {
        int counter = 0;
        detail::SqlStart start{"x", col("x", kIdColumn)};
        auto lhs = detail::path_sql(l, eq.lhs.dom, start, eq.lhs.homs, eq.lhs.attr, "l", counter);
        auto rhs = detail::path_sql(l, eq.rhs.dom, start, eq.rhs.homs, eq.rhs.attr, "r", counter);
        std::string differ = eq.lhs.attr
                                 ? "NOT (" + lhs.value + " IS NOT DISTINCT FROM " + rhs.value +
                                       " AND " + lhs.var + " IS NOT DISTINCT FROM " + rhs.var + ")"
                                 : "NOT (" + lhs.id + " IS NOT DISTINCT FROM " + rhs.id + ")";
        std::string sql = "SELECT " + col("x", kIdColumn) + " FROM " + l.table(eq.lhs.dom) +
                          " AS x" + lhs.joins + rhs.joins + " WHERE " + differ + " ORDER BY 1" +
                          " LIMIT " + std::to_string(limit);
        std::string words = s.path_to_string(eq.lhs) + " == " + s.path_to_string(eq.rhs);
        auto st = c.query(sql, [&](const Row& r) {
            out.push_back(fmt::format("table {}, row {}: the path equation {} does not hold",
                                      l.table(eq.lhs.dom), r.display(0), words));
            return true;
        });
        if (!st) {
            return fail(st.error());
        }
    }
    return out;
}

ReadState read_state(Connection& c, const SchemaPtr& schema, const std::string& ns) {
    Layout l(c.engine(), ns, *schema);
    Errors errors;
    ReadState out;
    if (!check_tables(c, l, errors)) {
        out.errors = errors.done();
        return out;
    }
    std::vector<Ids> var_ids;
    std::vector<std::vector<std::string>> var_names;
    read_vars(c, l, var_ids, var_names, errors);
    std::vector<RawTable> raw(schema->num_obs());
    for (std::uint32_t o = 0; o < schema->num_obs(); ++o) {
        read_table(c, l, ObId(o), raw[o], errors);
    }
    ACSet x(schema);
    assemble(l, raw, var_ids, var_names, x, errors);
    errors.add_all(equation_violations(c, l));
    out.errors = errors.done();
    if (out.errors.empty()) {
        out.state = std::move(x);
    }
    return out;
}

Status export_state(std::string_view url, const ACSet& x, const std::string& ns, bool replace) {
    auto c = connect(url);
    if (!c) {
        return fail(c.error());
    }
    Transaction t(**c);
    if (!t.status()) {
        return t.status();
    }
    if (auto st = write_state(**c, x, ns, replace); !st) {
        return st;
    }
    return t.commit();
}

ReadState import_state(std::string_view url, const SchemaPtr& schema, const std::string& ns) {
    ReadState out;
    auto c = connect(url, /*create=*/false);
    if (!c) {
        out.errors.push_back(c.error());
        return out;
    }
    // One snapshot: a writer cannot change the tables between two reads.
    Transaction t(**c);
    return read_state(**c, schema, ns);
}

} // namespace catplan::db
