#include "catplan/lang/detail/printing.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/lang/syntax.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <set>

namespace catplan::lang {

using acset::ACSet;
using acset::Value;
using schema::Path;
using schema::Schema;
using schema::ValueKind;

namespace {

std::string plural(std::size_t n, std::string_view noun) {
    return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s");
}

std::string path_term(const Schema& s, const Path& p) {
    std::vector<std::string> names;
    for (HomId f : p.homs) {
        names.push_back(quoted_name(s.hom(f).name));
    }
    if (p.attr) {
        names.push_back(quoted_name(s.attr(*p.attr).name));
    }
    if (names.empty()) {
        return fmt::format("id({})", quoted_name(s.ob(p.dom).name));
    }
    if (names.size() == 1) {
        return names[0];
    }
    return fmt::format("compose({})", fmt::join(names, ", "));
}

} // namespace

std::string generated_name(std::string_view wanted, std::string_view kind, std::uint32_t index) {
    if (wanted.empty() || wanted.find_first_of("\n\r") != std::string_view::npos) {
        return fmt::format("_{}{}", kind, index + 1);
    }
    return fmt::format("{}_{}", wanted, kind);
}

std::string summarize_rule(const rewrite::Rule& rule) {
    // Each name once: a migrated rule carries a parameter to every target object that has it
    // (unstack(block, underblock), not unstack(block, block, underblock, underblock)).
    std::vector<std::string> params;
    for (const auto& p : rule.parameters) {
        if (std::find(params.begin(), params.end(), p.name) == params.end()) {
            params.push_back(p.name);
        }
    }
    std::size_t deleted = 0, created = 0;
    for (std::uint32_t o = 0; o < rule.L.schema().num_obs(); ++o) {
        deleted += rule.deleted_parts(ObId(o)).size();
        created += rule.created_parts(ObId(o)).size();
    }
    std::string out = fmt::format("rule {}({}) on {}: L {}, K {}, R {}, deletes {}, creates {}",
                                  rule.name, fmt::join(params, ", "), rule.L.schema().name(),
                                  plural(rule.L.total_parts(), "part"), rule.K.total_parts(),
                                  rule.R.total_parts(), deleted, created);
    std::size_t nacs = 0, pacs = 0, exprs = 0;
    for (const auto& c : rule.conditions) {
        ++(c.negative ? nacs : pacs);
    }
    for (const auto& per_type : rule.exprs) {
        for (const auto& e : per_type) {
            exprs += e ? 1 : 0;
        }
    }
    if (nacs > 0) {
        out += fmt::format(", {} NAC{}", nacs, nacs == 1 ? "" : "s");
    }
    if (pacs > 0) {
        out += fmt::format(", {} PAC{}", pacs, pacs == 1 ? "" : "s");
    }
    if (exprs > 0) {
        out += ", " + plural(exprs, "expression");
    }
    return out;
}

std::string summarize(const Declaration& d) {
    if (d.kind == DeclKind::Rule) {
        return summarize_rule(*d.rule);
    }
    if (d.kind == DeclKind::Domain && d.pddl != nullptr) {
        // A PDDL domain by its actions, as its plans name them (a rule per variant: import.hpp).
        std::vector<std::string> names;
        for (const auto& a : d.pddl->actions) {
            std::size_t n = a.variants.size();
            names.push_back(n == 1 ? a.action
                                   : fmt::format("{} ({})", a.action, plural(n, "rule")));
        }
        return fmt::format("domain {} ({}): {} ({}){}{}", d.name, d.schema->name(),
                           plural(names.size(), "action"), plural(d.domain->rules.size(), "rule"),
                           names.empty() ? "" : ": ", fmt::join(names, ", "));
    }
    if (d.kind == DeclKind::Domain) {
        std::vector<std::string> names;
        for (const auto& r : d.domain->rules) {
            names.push_back(r->name);
        }
        return fmt::format("domain {} ({}): {}{}{}", d.name, d.schema->name(),
                           plural(names.size(), "rule"), names.empty() ? "" : ": ",
                           fmt::join(names, ", "));
    }
    if (d.kind == DeclKind::Problem) {
        return fmt::format("problem {} ({}): initial {}, goal {}", d.name, d.problem->domain->name,
                           d.initial_name, d.goal_name);
    }
    if (d.kind == DeclKind::Map) {
        const auto& m = *d.map;
        const Schema& t = *m.target();
        std::size_t queries = 0;
        for (std::uint32_t o = 0; o < t.num_obs(); ++o) {
            queries += m.query(ObId(o)).is_plain() ? 0 : 1;
        }
        return fmt::format("map {} : {} -> {} ({}, {}, {} by query, {}, {}, {})", d.name, t.name(),
                           m.source()->name(), m.is_delta() ? "delta" : "conjunctive",
                           plural(t.num_obs(), "object"), queries, plural(t.num_homs(), "hom"),
                           plural(t.num_attr_types(), "attribute type"),
                           plural(t.num_attrs(), "attribute"));
    }
    if (d.kind == DeclKind::Schema) {
        const Schema& s = *d.schema;
        std::string out =
            fmt::format("schema {}: {}, {}, {}, {}", d.name, plural(s.num_obs(), "object"),
                        plural(s.num_homs(), "hom"), plural(s.num_attr_types(), "attribute type"),
                        plural(s.num_attrs(), "attribute"));
        if (!s.equations().empty()) {
            out += ", " + plural(s.equations().size(), "equation");
        }
        return out;
    }
    const ACSet& x = *d.instance;
    const Schema& s = x.schema();
    std::vector<std::string> counts;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (auto n = x.num_parts(ObId(o))) {
            counts.push_back(fmt::format("{} {}", s.ob(ObId(o)).name, n));
        }
    }
    std::size_t vars = 0;
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        vars += x.num_vars(AttrTypeId(t));
    }
    std::string out =
        fmt::format("instance {} ({}): {}", d.name, s.name(), plural(x.total_parts(), "part"));
    if (!counts.empty()) {
        out += fmt::format(" ({})", fmt::join(counts, ", "));
    }
    return out + ", " + plural(vars, "variable");
}

std::string print_schema(const Schema& s) {
    std::string out = fmt::format("@present {}(FreeSchema) begin\n", quoted_name(s.name()));
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        out += fmt::format("  {}::Ob\n", quoted_name(s.ob(ObId(i)).name));
    }
    for (std::uint32_t i = 0; i < s.num_homs(); ++i) {
        const auto& h = s.hom(HomId(i));
        out += fmt::format("  {}::Hom({}, {})\n", quoted_name(h.name),
                           quoted_name(s.ob(h.dom).name), quoted_name(s.ob(h.codom).name));
    }
    for (std::uint32_t i = 0; i < s.num_attr_types(); ++i) {
        const auto& t = s.attr_type(AttrTypeId(i));
        if (t.kind == ValueKind::Unknown) {
            out += fmt::format("  {}::AttrType\n", quoted_name(t.name));
        } else {
            out +=
                fmt::format("  {}::AttrType({})\n", quoted_name(t.name), schema::to_string(t.kind));
        }
    }
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        const auto& a = s.attr(AttrId(i));
        out += fmt::format("  {}::Attr({}, {})\n", quoted_name(a.name),
                           quoted_name(s.ob(a.dom).name), quoted_name(s.attr_type(a.codom).name));
    }
    for (const auto& eq : s.equations()) {
        std::string named = eq.name.empty() ? "" : quoted_name(eq.name) + " := ";
        out += fmt::format("  {}{} == {}\n", named, path_term(s, eq.lhs), path_term(s, eq.rhs));
    }
    return out + "end\n";
}

namespace detail {

std::string NamePool::take(std::string_view wanted, std::string_view kind, std::uint32_t index) {
    std::string n(wanted);
    // A name that is not an identifier is written quoted (var"on-table"); one with a line break
    // in it could not be.
    if (n.empty() || n.find_first_of("\n\r") != std::string::npos || used(n)) {
        n = generated_name(wanted, kind, index);
        while (used(n)) {
            n += "_";
        }
    }
    add(n);
    return n;
}

StateNames state_names(const ACSet& x, std::span<const ObId> name_first) {
    const Schema& s = x.schema();
    // Every part and variable becomes a generator; the names must be distinct identifiers that
    // do not shadow each other, so others get generated names.
    NamePool pool;
    auto pick = [&](std::string_view wanted, std::string_view kind, std::uint32_t index) {
        return pool.take(wanted, kind, index);
    };
    std::vector<ObId> order(name_first.begin(), name_first.end());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (std::find(order.begin(), order.end(), ObId(o)) == order.end()) {
            order.push_back(ObId(o));
        }
    }
    StateNames names;
    names.parts.resize(s.num_obs());
    for (ObId ob : order) {
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            names.parts[ob.index()].push_back(pick(x.part_name(ob, p), s.ob(ob).name, p));
        }
    }
    names.vars.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < x.num_vars(AttrTypeId(t)); ++j) {
            names.vars[t].push_back(
                pick(x.var_name(AttrTypeId(t), j), s.attr_type(AttrTypeId(t)).name, j));
        }
    }
    return names;
}

} // namespace detail

std::string print_instance(const ACSet& x, std::string_view name,
                           std::span<const ObId> name_first) {
    const Schema& s = x.schema();
    auto [part_names, var_names] = detail::state_names(x, name_first);
    for (auto* names : {&part_names, &var_names}) {
        for (auto& row : *names) {
            for (auto& n : row) {
                n = quoted_name(n);
            }
        }
    }
    std::string out =
        fmt::format("@acset_colim {}({}) begin\n", quoted_name(name), quoted_name(s.name()));
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!part_names[o].empty()) {
            out += fmt::format("  ({})::{}\n", fmt::join(part_names[o], ", "),
                               quoted_name(s.ob(ObId(o)).name));
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        if (!var_names[t].empty()) {
            out += fmt::format("  ({})::{}\n", fmt::join(var_names[t], ", "),
                               quoted_name(s.attr_type(AttrTypeId(t)).name));
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            const std::string& pn = part_names[o][p];
            for (HomId f : s.homs_from(ob)) {
                Part q = x.subpart(f, p);
                if (q == kNoPart) {
                    out += fmt::format("  # {}({}) is unset\n", quoted_name(s.hom(f).name), pn);
                } else {
                    out += fmt::format("  {}({}) == {}\n", quoted_name(s.hom(f).name), pn,
                                       part_names[s.hom(f).codom.index()][q]);
                }
            }
            for (AttrId a : s.attrs_from(ob)) {
                const Value& v = x.subpart(a, p);
                if (v.is_unset()) {
                    out += fmt::format("  # {}({}) is unset\n", quoted_name(s.attr(a).name), pn);
                } else if (v.is_var()) {
                    out += fmt::format("  {}({}) == {}\n", quoted_name(s.attr(a).name), pn,
                                       var_names[s.attr(a).codom.index()][v.var_index()]);
                } else {
                    out += fmt::format("  {}({}) == {}\n", quoted_name(s.attr(a).name), pn,
                                       v.to_string());
                }
            }
        }
    }
    return out + "end\n";
}

} // namespace catplan::lang
