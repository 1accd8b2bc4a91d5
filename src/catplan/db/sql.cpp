#include "catplan/db/detail/sql.hpp"

namespace catplan::db::detail {

std::string col(const std::string& alias, std::string_view column) {
    return alias + "." + quote(column);
}

SqlPath path_sql(const Layout& layout, ObId dom, SqlStart start, const std::vector<HomId>& homs,
                 std::optional<AttrId> attr, const std::string& prefix, int& counter) {
    const Schema& s = layout.schema();
    SqlPath out;
    ObId ob = dom;
    // A row to read the next column from: the current part's row, joined when there is none.
    auto row = [&]() {
        if (start.alias.empty()) {
            start.alias = prefix + std::to_string(counter++);
            out.joins += " LEFT JOIN " + layout.table(ob) + " AS " + start.alias + " ON " +
                         col(start.alias, kIdColumn) + " = " + start.id;
        }
        return start.alias;
    };
    for (HomId h : homs) {
        start.id = col(row(), s.hom(h).name);
        start.alias.clear();
        ob = s.hom(h).codom;
    }
    if (attr) {
        std::string a = row();
        out.value = col(a, s.attr(*attr).name);
        out.var = col(a, Layout::var_column(s.attr(*attr)));
    }
    out.id = start.id;
    return out;
}

} // namespace catplan::db::detail
