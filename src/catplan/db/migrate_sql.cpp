#include "catplan/db/migrate_sql.hpp"

#include "catplan/db/detail/sql.hpp"
#include "catplan/db/tables.hpp"

#include <fmt/format.h>
#include <set>

namespace catplan::db {

using acset::Value;
using detail::col;
using migrate::Query;
using migrate::QueryElement;
using migrate::SchemaMap;

std::string MigrationSql::text() const {
    std::string out;
    for (const auto& s : statements) {
        out += s + ";\n";
    }
    return out;
}

std::string origin_table(std::string_view object) {
    return std::string(object) + "__origin";
}

namespace {

// A literal of SQL for a concrete value, typed so that PostgreSQL needs no guess.
std::string literal(Engine e, const Value& v) {
    switch (v.tag()) {
    case Value::Tag::Bool:
        return e == Engine::PostgreSQL ? (v.as_bool() ? "TRUE" : "FALSE")
                                       : (v.as_bool() ? "1" : "0");
    case Value::Tag::Int:
        return "CAST(" + std::to_string(v.as_int()) + " AS BIGINT)";
    case Value::Tag::Float:
        return "CAST(" + fmt::format("{}", v.as_float()) + " AS DOUBLE PRECISION)";
    case Value::Tag::String:
        return "CAST(" + quote_literal(v.as_string()) + " AS TEXT)";
    default:
        return "NULL";
    }
}

std::string typed_null(const std::string& type) {
    return "CAST(NULL AS " + type + ")";
}

// "block", "gripper.isHolding", "block.hasColor": a term as a column name.
std::string term_name(const schema::Schema& s, const migrate::Term& t) {
    if (t.is_literal()) {
        return t.literal.to_string();
    }
    std::string name = t.var;
    for (HomId h : t.homs) {
        name += "." + s.hom(h).name;
    }
    if (t.attr) {
        name += "." + s.attr(*t.attr).name;
    }
    return name;
}

// A cell of a query's shape: attribute a of part p.
struct Cell {
    AttrId attr;
    Part part;
};

// How the tuples of one target object are read: from the source object (a plain query), from
// its origin table, or nowhere (@empty).
struct Tuples {
    enum class Mode : std::uint8_t { Empty, Plain, Origin };
    Mode mode = Mode::Empty;
    ObId ob;                                           // Plain: the source object
    std::string origin;                                // Origin: the quoted origin table
    std::vector<std::vector<std::string>> part_col;    // Origin: [ob][part] of the shape
    std::vector<std::vector<std::string>> var_col;     // Origin: [type][var] of the shape
    std::vector<std::vector<std::vector<Cell>>> cells; // [type][var]: cells holding it
};

Tuples tuples_of(const Query& q, const schema::Schema& src, Engine e, const std::string& to,
                 std::string_view name) {
    Tuples t;
    if (q.is_empty()) {
        return t;
    }
    if (q.is_plain()) {
        t.mode = Tuples::Mode::Plain;
        t.ob = q.nodes()[0].ob;
        return t;
    }
    t.mode = Tuples::Mode::Origin;
    t.origin = table_name(e, to, origin_table(name));
    const ACSet& shape = q.state();
    std::set<std::string> used{kIdColumn};
    auto unique = [&](std::string n) {
        std::string base = n;
        for (int k = 2; !used.insert(n).second; ++k) {
            n = base + "#" + std::to_string(k);
        }
        return n;
    };
    t.part_col.resize(src.num_obs());
    for (std::uint32_t o = 0; o < src.num_obs(); ++o) {
        for (Part p = 0; p < shape.num_parts(ObId(o)); ++p) {
            t.part_col[o].push_back(unique(term_name(src, q.witness(ObId(o), p))));
        }
    }
    t.var_col.resize(src.num_attr_types());
    t.cells.resize(src.num_attr_types());
    for (std::uint32_t ty = 0; ty < src.num_attr_types(); ++ty) {
        auto n = static_cast<std::uint32_t>(shape.num_vars(AttrTypeId(ty)));
        t.cells[ty].resize(n);
        for (std::uint32_t j = 0; j < n; ++j) {
            t.var_col[ty].push_back(
                unique(term_name(src, q.witness_value(AttrTypeId(ty), Value::var(j)))));
        }
    }
    for (std::uint32_t a = 0; a < src.num_attrs(); ++a) {
        const auto& info = src.attr(AttrId(a));
        for (Part p = 0; p < shape.num_parts(info.dom); ++p) {
            const Value& v = shape.subpart(AttrId(a), p);
            if (v.is_var()) {
                t.cells[info.codom.index()][v.var_index()].push_back({AttrId(a), p});
            }
        }
    }
    return t;
}

// The alias of each part of a query's shape in the query's join: s0, s1, ...
std::vector<std::vector<std::string>> shape_aliases(const ACSet& shape) {
    std::vector<std::vector<std::string>> aliases(shape.schema().num_obs());
    int k = 0;
    for (std::uint32_t o = 0; o < shape.schema().num_obs(); ++o) {
        for (Part p = 0; p < shape.num_parts(ObId(o)); ++p) {
            aliases[o].push_back("s" + std::to_string(k++));
        }
    }
    return aliases;
}

// A single part with only attribute filters: migrate scans it and keeps X's order.
bool is_scan(const ACSet& shape) {
    if (shape.total_parts() != 1) {
        return false;
    }
    for (std::uint32_t o = 0; o < shape.schema().num_obs(); ++o) {
        if (shape.num_parts(ObId(o)) == 1) {
            for (HomId h : shape.schema().homs_from(ObId(o))) {
                if (shape.subpart(h, 0) != kNoPart) {
                    return false;
                }
            }
        }
    }
    return true;
}

// CREATE TABLE c'__origin AS the assignments of q, numbered as migrate numbers them.
std::string origin_sql(const Query& q, const Tuples& t, const Layout& src) {
    const ACSet& shape = q.state();
    const schema::Schema& s = src.schema();
    Engine e = src.engine();
    auto alias = shape_aliases(shape);
    std::vector<std::string> select, from, where, order;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < shape.num_parts(ObId(o)); ++p) {
            const std::string& a = alias[o][p];
            from.push_back(src.table(ObId(o)) + " AS " + a);
            select.push_back(col(a, kIdColumn) + " AS " + quote(t.part_col[o][p]));
            for (HomId h : s.homs_from(ObId(o))) {
                if (Part q2 = shape.subpart(h, p); q2 != kNoPart) {
                    where.push_back(col(a, s.hom(h).name) + " = " +
                                    col(alias[s.hom(h).codom.index()][q2], kIdColumn));
                }
            }
            for (AttrId at : s.attrs_from(ObId(o))) {
                const Value& v = shape.subpart(at, p);
                const auto& info = s.attr(at);
                if (v.is_concrete()) {
                    where.push_back(col(a, info.name) + " = " + literal(e, v));
                } else if (v.is_var()) {
                    const Cell& first = t.cells[info.codom.index()][v.var_index()].front();
                    const auto& finfo = s.attr(first.attr);
                    const std::string& fa = alias[finfo.dom.index()][first.part];
                    if (first.attr == at && first.part == p) {
                        where.push_back("(" + col(a, info.name) + " IS NOT NULL OR " +
                                        col(a, Layout::var_column(info)) + " IS NOT NULL)");
                    } else {
                        where.push_back("(" + col(a, info.name) + " = " + col(fa, finfo.name) +
                                        " OR " + col(a, Layout::var_column(info)) + " = " +
                                        col(fa, Layout::var_column(finfo)) + ")");
                    }
                }
            }
        }
    }
    // The value of each variable of the shape, read from its first cell.
    for (std::uint32_t ty = 0; ty < s.num_attr_types(); ++ty) {
        for (std::size_t j = 0; j < t.var_col[ty].size(); ++j) {
            const Cell& c = t.cells[ty][j].front();
            const auto& info = s.attr(c.attr);
            const std::string& a = alias[info.dom.index()][c.part];
            select.push_back(col(a, info.name) + " AS " + quote(t.var_col[ty][j]));
            select.push_back(col(a, Layout::var_column(info)) + " AS " +
                             quote(t.var_col[ty][j] + "__var"));
        }
    }
    if (is_scan(shape)) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            if (shape.num_parts(ObId(o)) == 1) {
                order.push_back(col(alias[o][0], kIdColumn));
            }
        }
    } else {
        for (std::size_t i = 0; i < q.nodes().size(); ++i) {
            QueryElement el = q.locate_node(i);
            if (!el.is_value) {
                order.push_back(col(alias[el.ob.index()][el.part], kIdColumn));
            } else if (el.value.is_var()) {
                // Variables before constants (catplan's order of values), then by value.
                const Cell& c = t.cells[el.type.index()][el.value.var_index()].front();
                const auto& info = s.attr(c.attr);
                const std::string& a = alias[info.dom.index()][c.part];
                std::string var = col(a, Layout::var_column(info));
                bool text = s.attr_type(el.type).kind == schema::ValueKind::String;
                order.push_back("CASE WHEN " + var + " IS NULL THEN 1 ELSE 0 END");
                order.push_back(var);
                order.push_back(col(a, info.name) +
                                (text && e == Engine::PostgreSQL ? " COLLATE \"C\"" : ""));
            }
        }
    }
    std::string sql = "CREATE TABLE " + t.origin + " AS SELECT ROW_NUMBER() OVER (";
    for (std::size_t i = 0; i < order.size(); ++i) {
        sql += (i == 0 ? "ORDER BY " : ", ") + order[i];
    }
    sql += ") AS " + quote(kIdColumn);
    for (const auto& c : select) {
        sql += ", " + c;
    }
    for (std::size_t i = 0; i < from.size(); ++i) {
        sql += (i == 0 ? " FROM " : ", ") + from[i];
    }
    for (std::size_t i = 0; i < where.size(); ++i) {
        sql += (i == 0 ? " WHERE " : " AND ") + where[i];
    }
    return sql;
}

// An index on an origin table's object columns, for the joins of homs into it.
std::string origin_index_sql(const Query& q, const Tuples& t, Engine e, const std::string& to,
                             std::string_view name) {
    std::string cols;
    for (std::size_t i = 0; i < q.nodes().size(); ++i) {
        QueryElement el = q.locate_node(i);
        if (!el.is_value) {
            cols += (cols.empty() ? "" : ", ") + quote(t.part_col[el.ob.index()][el.part]);
        }
    }
    if (cols.empty()) {
        return {};
    }
    std::string index = e == Engine::PostgreSQL ? quote(origin_table(name) + "_key")
                                                : quote(to + "." + origin_table(name) + "_key");
    return "CREATE INDEX " + index + " ON " + t.origin + " (" + cols + ")";
}

// Reads the tuples of one target object in the SELECT that fills its table.
struct TupleRow {
    const Tuples& t;
    std::string joins;
    int counter = 0;

    // The part of the shape (the query's element) in the current tuple.
    detail::SqlStart part(ObId ob, Part p) const {
        if (t.mode == Tuples::Mode::Plain) {
            return {"x", col("x", kIdColumn)};
        }
        return {"", col("o", t.part_col[ob.index()][p])};
    }

    // The value (and variable) of a variable of the shape in the current tuple.
    std::pair<std::string, std::string> value(AttrTypeId ty, std::uint32_t j) const {
        const std::string& c = t.var_col[ty.index()][j];
        return {col("o", c), col("o", c + "__var")};
    }
};

// The expression of target hom h's column, with the joins it needs added to row.
std::string hom_expr(const SchemaMap& f, HomId h, const std::vector<Tuples>& all, const Layout& src,
                     TupleRow& row) {
    const auto& info = f.target()->hom(h);
    const migrate::HomImage& im = f.hom_image(h);
    if (im.path) {
        auto p = detail::path_sql(src, row.t.ob, row.part(row.t.ob, 0), *im.path, std::nullopt, "j",
                                  row.counter);
        row.joins += p.joins;
        return p.id;
    }
    const hom::ACSetMorphism& qf = *im.morphism;
    const Tuples& d = all[info.codom.index()];
    const Query& qd = f.query(info.codom);
    if (d.mode == Tuples::Mode::Empty) {
        return typed_null("BIGINT");
    }
    if (d.mode == Tuples::Mode::Plain) {
        QueryElement el = qd.locate_node(0);
        return row.part(el.ob, qf(el.ob, el.part)).id;
    }
    std::string a = "h" + std::to_string(row.counter++);
    std::string on;
    auto add = [&](const std::string& c) { on += (on.empty() ? "" : " AND ") + c; };
    for (std::size_t i = 0; i < qd.nodes().size(); ++i) {
        QueryElement el = qd.locate_node(i);
        if (!el.is_value) {
            add(col(a, d.part_col[el.ob.index()][el.part]) + " = " +
                row.part(el.ob, qf(el.ob, el.part)).id);
        } else if (el.value.is_var()) {
            const std::string& dc = d.var_col[el.type.index()][el.value.var_index()];
            const Value& v = qf.var(el.type, el.value.var_index());
            if (v.is_var()) {
                auto [cv, cvar] = row.value(el.type, v.var_index());
                add("(" + col(a, dc) + " = " + cv + " OR " + col(a, dc + "__var") + " = " + cvar +
                    ")");
            } else {
                add(col(a, dc) + " = " + literal(src.engine(), v));
            }
        }
    }
    row.joins += " LEFT JOIN " + d.origin + " AS " + a + " ON " + (on.empty() ? "TRUE" : on);
    return col(a, kIdColumn);
}

// The expressions of target attribute a's value and variable columns.
std::pair<std::string, std::string> attr_expr(const SchemaMap& f, AttrId a, const Layout& src,
                                              const Layout& dst, TupleRow& row) {
    const auto& info = f.target()->attr(a);
    const migrate::AttrImage& im = f.attr_image(a);
    std::string type = dst.sql_type(info.codom);
    std::string no_var = typed_null("BIGINT");
    switch (im.kind) {
    case migrate::AttrImage::Kind::Constant:
        return {literal(src.engine(), im.constant), no_var};
    case migrate::AttrImage::Kind::Value:
        if (im.value.is_var()) {
            return row.value(im.type, im.value.var_index());
        }
        return {literal(src.engine(), im.value), no_var};
    case migrate::AttrImage::Kind::Path: {
        auto p = detail::path_sql(src, im.start_ob, row.part(im.start_ob, im.start), im.homs,
                                  im.attr, "j", row.counter);
        row.joins += p.joins;
        return {p.value, p.var};
    }
    default:
        return {typed_null(type), no_var};
    }
}

// INSERT INTO the target table of c from its tuples.
std::string fill_sql(const SchemaMap& f, ObId c, const std::vector<Tuples>& all, const Layout& src,
                     const Layout& dst) {
    const schema::Schema& t = *f.target();
    const Tuples& tu = all[c.index()];
    TupleRow row{tu, {}, 0};
    std::vector<std::string> columns{kIdColumn, kNameColumn}, exprs;
    std::string base;
    if (tu.mode == Tuples::Mode::Plain) {
        exprs = {col("x", kIdColumn), col("x", kNameColumn)};
        base = src.table(tu.ob) + " AS x";
    } else {
        const Query& q = f.query(c);
        std::string name = typed_null("TEXT");
        for (std::size_t i = 0; i < q.nodes().size(); ++i) {
            QueryElement el = q.locate_node(i);
            if (!el.is_value) {
                row.joins += " LEFT JOIN " + src.table(el.ob) + " AS n ON " + col("n", kIdColumn) +
                             " = " + row.part(el.ob, el.part).id;
                name = col("n", kNameColumn);
                break;
            }
        }
        exprs = {col("o", kIdColumn), name};
        base = tu.origin + " AS o";
    }
    for (HomId h : t.homs_from(c)) {
        columns.push_back(t.hom(h).name);
        exprs.push_back(hom_expr(f, h, all, src, row));
    }
    for (AttrId a : t.attrs_from(c)) {
        columns.push_back(t.attr(a).name);
        columns.push_back(Layout::var_column(t.attr(a)));
        auto [v, var] = attr_expr(f, a, src, dst, row);
        exprs.push_back(v);
        exprs.push_back(var);
    }
    std::string sql = "INSERT INTO " + dst.table(c) + " (";
    for (std::size_t i = 0; i < columns.size(); ++i) {
        sql += (i == 0 ? "" : ", ") + quote(columns[i]);
    }
    sql += ") SELECT ";
    for (std::size_t i = 0; i < exprs.size(); ++i) {
        sql += (i == 0 ? "" : ", ") + exprs[i];
    }
    return sql + " FROM " + base + row.joins;
}

} // namespace

MigrationSql migration_sql(const SchemaMap& f, Engine engine, const std::string& from,
                           const std::string& to) {
    CATPLAN_ASSERT(f.ok(), "migration_sql: the schema map is not finished without errors");
    const schema::Schema& t = *f.target();
    Layout src(engine, from, *f.source());
    Layout dst(engine, to, t);
    MigrationSql out;
    std::string create = dst.create_sql();
    for (std::size_t start = 0; start < create.size();) {
        std::size_t end = create.find(";\n", start);
        out.statements.push_back(create.substr(start, end - start));
        start = end + 2;
    }
    std::vector<Tuples> all;
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        all.push_back(tuples_of(f.query(ObId(c)), *f.source(), engine, to, t.ob(ObId(c)).name));
    }
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        if (all[c].mode == Tuples::Mode::Origin) {
            const Query& q = f.query(ObId(c));
            out.statements.push_back(origin_sql(q, all[c], src));
            if (auto index = origin_index_sql(q, all[c], engine, to, t.ob(ObId(c)).name);
                !index.empty()) {
                out.statements.push_back(index);
            }
        }
    }
    for (std::uint32_t i = 0; i < t.num_attr_types(); ++i) {
        if (auto s = f.attr_type_image(AttrTypeId(i))) {
            out.statements.push_back("INSERT INTO " + dst.table(AttrTypeId(i)) + " (" +
                                     quote(kIdColumn) + ", " + quote(kNameColumn) + ") SELECT " +
                                     quote(kIdColumn) + ", " + quote(kNameColumn) + " FROM " +
                                     src.table(*s));
        }
    }
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        if (all[c].mode != Tuples::Mode::Empty) {
            out.statements.push_back(fill_sql(f, ObId(c), all, src, dst));
        }
    }
    std::string fks = dst.foreign_key_sql();
    for (std::size_t start = 0; start < fks.size();) {
        std::size_t end = fks.find(";\n", start);
        out.statements.push_back(fks.substr(start, end - start));
        start = end + 2;
    }
    return out;
}

Status migrate_in_database(std::string_view url, const SchemaMap& f, const std::string& from,
                           const std::string& to, bool replace) {
    if (from == to) {
        return fail("the state and its migration cannot share the namespace '" + from +
                    "': name another one for the migrated state");
    }
    auto c = connect(url, /*create=*/false);
    if (!c) {
        return fail(c.error());
    }
    Transaction tx(**c);
    if (!tx.status()) {
        return tx.status();
    }
    Layout src((*c)->engine(), from, *f.source());
    if (auto errors = verify_tables(**c, src); !errors.empty()) {
        std::string all;
        for (const auto& e : errors) {
            all += (all.empty() ? "" : "\n") + e;
        }
        return fail(all);
    }
    if (auto problems = Layout((*c)->engine(), to, *f.target()).problems(); !problems.empty()) {
        return fail("schema " + f.target()->name() + " cannot be stored as tables: " + problems[0]);
    }
    auto existing = tables_in(**c, to);
    if (!existing) {
        return fail(existing.error());
    }
    if (!existing->empty()) {
        if (!replace) {
            return fail(fmt::format("the database already holds tables of '{}'; pass --replace "
                                    "to overwrite them",
                                    to));
        }
        if (auto st = drop_namespace(**c, to); !st) {
            return st;
        }
    }
    for (const auto& s : migration_sql(f, (*c)->engine(), from, to).statements) {
        if (auto st = (*c)->exec(s); !st) {
            return fail(st.error() + "\nin: " + s);
        }
    }
    return tx.commit();
}

} // namespace catplan::db
