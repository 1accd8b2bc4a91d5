#include "catplan/acset/printer.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::acset {
namespace {

std::size_t display_width(std::string_view s) {
    std::size_t w = 0;
    for (char c : s) {
        if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
            ++w;
        }
    }
    return w;
}

void append_table(std::string& out, const std::vector<std::vector<std::string>>& rows) {
    std::vector<std::size_t> widths;
    for (const auto& row : rows) {
        widths.resize(std::max(widths.size(), row.size()), 0);
        for (std::size_t c = 0; c < row.size(); ++c) {
            widths[c] = std::max(widths[c], display_width(row[c]));
        }
    }
    for (const auto& row : rows) {
        std::string line = " ";
        for (std::size_t c = 0; c < row.size(); ++c) {
            line += ' ';
            line += row[c];
            if (c + 1 < row.size()) {
                line.append(widths[c] - display_width(row[c]) + 1, ' ');
            }
        }
        while (!line.empty() && line.back() == ' ') {
            line.pop_back();
        }
        out += line;
        out += '\n';
    }
}

} // namespace

std::string to_tables(const ACSet& x) {
    const auto& s = x.schema();
    std::string out;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        auto n = x.num_parts(ob);
        out += fmt::format("{} ({} part{})\n", s.ob(ob).name, n, n == 1 ? "" : "s");
        if (n == 0) {
            continue;
        }
        std::vector<std::vector<std::string>> rows;
        std::vector<std::string> header{"id", "name"};
        for (HomId f : s.homs_from(ob)) {
            header.push_back(s.hom(f).name);
        }
        for (AttrId a : s.attrs_from(ob)) {
            header.push_back(s.attr(a).name);
        }
        rows.push_back(std::move(header));
        for (Part p = 0; p < n; ++p) {
            std::vector<std::string> row{fmt::format("{}", p + 1), std::string(x.part_name(ob, p))};
            for (HomId f : s.homs_from(ob)) {
                row.push_back(x.part_label(s.hom(f).codom, x.subpart(f, p)));
            }
            for (AttrId a : s.attrs_from(ob)) {
                row.push_back(x.value_label(s.attr(a).codom, x.subpart(a, p)));
            }
            rows.push_back(std::move(row));
        }
        append_table(out, rows);
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        auto k = x.num_vars(ty);
        if (k == 0) {
            continue;
        }
        std::string vars;
        for (std::uint32_t j = 0; j < k; ++j) {
            vars += (j ? ", " : "") + x.value_label(ty, Value::var(j));
        }
        out += fmt::format("{} ({} variable{}): {}\n", s.attr_type(ty).name, k, k == 1 ? "" : "s",
                           vars);
    }
    return out;
}

} // namespace catplan::acset
