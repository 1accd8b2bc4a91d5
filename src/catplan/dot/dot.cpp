#include "catplan/dot/dot.hpp"

#include "catplan/base/ascii.hpp"
#include "catplan/base/assert.hpp"
#include "catplan/base/escape.hpp"
#include "catplan/dot/detail/panel.hpp"
#include "catplan/migrate/describe.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <optional>
#include <vector>

namespace catplan::dot {

using acset::ACSet;
using acset::Value;
using schema::Schema;

std::string dot_id(std::string_view s) {
    static constexpr std::array<std::string_view, 6> kKeywords = {"node",    "edge",     "graph",
                                                                  "digraph", "subgraph", "strict"};
    auto is_letter = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    };
    auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
    bool bare = !s.empty() && is_letter(s.front()) && std::all_of(s.begin(), s.end(), [&](char c) {
        return is_letter(c) || is_digit(c);
    });
    if (bare) {
        bare = std::find(kKeywords.begin(), kKeywords.end(), ascii_lowercase(s)) == kKeywords.end();
    }
    return bare ? std::string(s) : "\"" + escape_quoted(s) + "\"";
}

std::string escape_quoted(std::string_view s) {
    return escape_chars(s, [](char c) -> std::optional<std::string_view> {
        switch (c) {
        case '"':
            return "\\\"";
        case '\\':
            // Graphviz reads \N, \G, \l ... in labels as escapes; "\\" is a plain backslash.
            return "\\\\";
        case '\n':
            return "\\n";
        case '\r':
            return "";
        default:
            return std::nullopt;
        }
    });
}

std::string escape_html(std::string_view s) {
    return escape_chars(s, [](char c) -> std::optional<std::string_view> {
        switch (c) {
        case '&':
            return "&amp;";
        case '<':
            return "&lt;";
        case '>':
            return "&gt;";
        case '"':
            return "&quot;";
        case '\'':
            return "&#39;";
        case '\n':
            return "<BR/>";
        case '\r':
            return "";
        default:
            return std::nullopt;
        }
    });
}

namespace {

using detail::endpoint;
using detail::fill;
using detail::Folding;
using detail::header;
using detail::Panel;
using detail::Writer;

/// Writes a panel as a cluster titled `title` (a placeholder node keeps an empty one visible).
void write_panel_cluster(Writer& w, const Panel& panel, std::string_view id, std::string_view title,
                         std::string_view color) {
    w.open(fmt::format("subgraph {} {{", dot_id(std::string("cluster_") + std::string(id))));
    w.line(fmt::format("graph [label=<<B>{}</B>>, style=\"rounded,bold\", color=\"{}\", "
                       "fontsize=13];",
                       escape_html(title), color));
    if (panel.has_nodes()) {
        panel.write(w);
    } else {
        w.line(fmt::format("{} [shape=plaintext, label=\"(empty)\", fontcolor=\"#888888\"];",
                           dot_id(std::string(id) + "__empty")));
    }
    w.close();
}

/// The anchor node of a panel: its first node, or the placeholder of an empty one.
std::string anchor(const Panel& panel, std::string_view id) {
    auto first = panel.first_node();
    return first ? *first : std::string(id) + "__empty";
}

/// Puts the panel of anchor `a` left of the panel of anchor `b` when no map edge does: an
/// invisible edge within one rank (an edge across ranks would fight the maps' rank constraints).
void order_panels(Writer& w, const std::string& a, const std::string& b) {
    w.line(fmt::format("{} -> {} [style=invis];", dot_id(a), dot_id(b)));
    w.line(fmt::format("{{rank=same; {}; {};}}", dot_id(a), dot_id(b)));
}

/// Writes the dashed edges of a map between two panels. With `reversed`, the edge is written
/// from the codomain to the domain with dir=back (the arrow still points at the image) so that
/// the codomain is laid out to the left: Pre ← Keep. With `same_rank`, each part is put in the
/// rank of its image, which lays the two panels out side by side. Returns the number of edges.
std::size_t write_map(Writer& w, const hom::ACSetMorphism& f, const ACSet& dom, const Panel& from,
                      const Panel& to, std::string_view style, bool reversed, bool same_rank) {
    const Schema& s = dom.schema();
    std::size_t count = 0;
    std::string_view east = same_rank ? "e" : "", west = same_rank ? "w" : "";
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        ObId ob(i);
        CATPLAN_ASSERT(f.components.size() == s.num_obs() &&
                           f.components[i].size() == dom.num_parts(ob),
                       "a morphism component does not match its domain");
        for (Part p = 0; p < dom.num_parts(ob); ++p) {
            auto a = from.place(ob, p);
            auto b = to.place(ob, f(ob, p));
            if (!a || !b) {
                continue;
            }
            if (reversed) {
                w.line(fmt::format("{} -> {} [{}, dir=back, arrowtail=vee];", endpoint(*b, east),
                                   endpoint(*a, west), style));
            } else {
                w.line(
                    fmt::format("{} -> {} [{}];", endpoint(*a, east), endpoint(*b, west), style));
            }
            if (same_rank) {
                w.line(fmt::format("{{rank=same; {}; {};}}", dot_id(a->first), dot_id(b->first)));
            }
            ++count;
        }
    }
    return count;
}

void check_images(const hom::ACSetMorphism& f, const ACSet& dom, const ACSet& codom) {
    const Schema& s = dom.schema();
    CATPLAN_ASSERT(f.components.size() == s.num_obs(), "a morphism has one component per object");
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        CATPLAN_ASSERT(f.components[i].size() == dom.num_parts(ObId(i)),
                       "a morphism component has one image per domain part");
        for (Part q : f.components[i]) {
            CATPLAN_ASSERT(q < codom.num_parts(ObId(i)), "a morphism image is not a codomain part");
        }
    }
}

constexpr std::string_view kMapStyle = "style=dashed, color=\"#888888\", arrowhead=vee";
// An ontology map's edges from each target object (and attribute type) to its image: blue and
// heavier, so that they do not read as the schemas' own dashed gray attribute edges.
constexpr std::string_view kImageStyle =
    "style=dashed, color=\"#1f5fbf\", penwidth=1.6, arrowhead=vee";

/// Writes a schema's objects, attribute types, homs and attributes, with node ids prefixed by
/// `prefix` (schema pictures use none; a map picture draws two schemas that may share names).
void write_schema_body(Writer& w, const Schema& s, std::string_view prefix) {
    auto id = [&](std::string_view name) {
        return dot_id(std::string(prefix) + std::string(name));
    };
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        const std::string& name = s.ob(ObId(i)).name;
        std::string label =
            prefix.empty() ? std::string() : fmt::format(", label=\"{}\"", escape_quoted(name));
        w.line(fmt::format("{} [shape=box, style=\"rounded,filled\", fillcolor=\"{}\"{}];",
                           id(name), fill(ObId(i)), label));
    }
    for (std::uint32_t i = 0; i < s.num_attr_types(); ++i) {
        const auto& t = s.attr_type(AttrTypeId(i));
        std::string label = escape_html(t.name);
        if (t.kind != schema::ValueKind::Unknown) {
            label += fmt::format("<BR/><FONT POINT-SIZE=\"9\" COLOR=\"#555555\">{}</FONT>",
                                 schema::to_string(t.kind));
        }
        w.line(fmt::format("{} [shape=ellipse, style=\"filled,dashed\", fillcolor=\"#f4f4f4\", "
                           "color=\"#777777\", label=<{}>];",
                           id(t.name), label));
    }
    for (std::uint32_t i = 0; i < s.num_homs(); ++i) {
        const auto& h = s.hom(HomId(i));
        w.line(fmt::format("{} -> {} [label=\"{}\"];", id(s.ob(h.dom).name), id(s.ob(h.codom).name),
                           escape_quoted(h.name)));
    }
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        const auto& a = s.attr(AttrId(i));
        w.line(fmt::format("{} -> {} [label=\"{}\", style=dashed, color=\"#777777\", "
                           "fontcolor=\"#555555\"];",
                           id(s.ob(a.dom).name), id(s.attr_type(a.codom).name),
                           escape_quoted(a.name)));
    }
}

} // namespace

std::string schema_to_dot(const Schema& s, const DotOptions& o) {
    Writer w;
    header(w, s.name(), s.name(), o, o.left_to_right, false);
    write_schema_body(w, s, "");
    if (!s.equations().empty()) {
        // A name no generator has, so the note cannot collide with an object's node.
        std::string id = "equations";
        while (s.find(id)) {
            id.insert(0, "_");
        }
        std::string label;
        for (const auto& eq : s.equations()) {
            std::string text =
                fmt::format("{} = {}", s.path_to_string(eq.lhs), s.path_to_string(eq.rhs));
            if (!eq.name.empty()) {
                text = fmt::format("{}: {}", eq.name, text);
            }
            label += escape_quoted(text) + "\\l"; // \l: left-justified lines
        }
        w.line(fmt::format("{} [shape=note, fontsize=10, label=\"{}\"];", dot_id(id), label));
    }
    w.close();
    return w.take();
}

std::string state_to_dot(const ACSet& x, std::string_view name, const DotOptions& o,
                         const std::vector<PartClass>& classes,
                         const std::vector<PartLabel>& labels) {
    Writer w;
    header(w, name, name, o, o.left_to_right, false);
    Folding folding = detail::decide_folding(x.schema(), o, {});
    Panel panel(x, "", folding, o);
    panel.set_marks(&classes, &labels);
    if (panel.has_nodes()) {
        panel.write(w);
    } else {
        w.line("empty [shape=plaintext, label=\"(empty)\", fontcolor=\"#888888\"];");
    }
    w.close();
    return w.take();
}

std::string rule_to_dot(const rewrite::Rule& r, const DotOptions& o) {
    check_images(r.l, r.K, r.L);
    check_images(r.r, r.K, r.R);
    std::vector<const ACSet*> sources = {&r.K};
    if (!r.conditions.empty()) {
        sources.push_back(&r.L);
    }
    Folding folding = detail::decide_folding(r.L.schema(), o, sources);
    Panel pre(r.L, "Pre_", folding, o), keep(r.K, "Keep_", folding, o),
        eff(r.R, "Eff_", folding, o);

    Writer w;
    header(w, r.name.empty() ? "rule" : r.name,
           (r.name.empty() ? std::string() : r.name + ": ") + "Pre ← Keep → Eff", o, false, true);
    write_panel_cluster(w, pre, "Pre", "Pre", "#555555");
    write_panel_cluster(w, keep, "Keep", "Keep", "#555555");
    write_panel_cluster(w, eff, "Eff", "Eff", "#555555");
    std::vector<Panel> conditions;
    conditions.reserve(r.conditions.size());
    for (std::size_t i = 0; i < r.conditions.size(); ++i) {
        const auto& c = r.conditions[i];
        check_images(c.n, r.L, c.n_state);
        conditions.emplace_back(c.n_state, fmt::format("N{}_", i + 1), folding, o);
        std::string title = fmt::format("{} {}", c.negative ? "forbidden" : "required",
                                        c.name.empty() ? fmt::format("N{}", i + 1) : c.name);
        write_panel_cluster(w, conditions.back(), fmt::format("N{}", i + 1), title,
                            c.negative ? "#b03030" : "#307030");
    }
    // l : Keep -> Pre is written Pre -> Keep with dir=back so that Pre is drawn on the left.
    if (write_map(w, r.l, r.K, keep, pre, kMapStyle, /*reversed=*/true, /*same_rank=*/true) == 0) {
        order_panels(w, anchor(pre, "Pre"), anchor(keep, "Keep"));
    }
    if (write_map(w, r.r, r.K, keep, eff, kMapStyle, /*reversed=*/false, /*same_rank=*/true) == 0) {
        order_panels(w, anchor(keep, "Keep"), anchor(eff, "Eff"));
    }
    for (std::size_t i = 0; i < r.conditions.size(); ++i) {
        // Conditions go right of Eff; their maps from Pre do not constrain the layout.
        order_panels(w,
                     i == 0 ? anchor(eff, "Eff") : anchor(conditions[i - 1], fmt::format("N{}", i)),
                     anchor(conditions[i], fmt::format("N{}", i + 1)));
        std::string style = fmt::format("style=dashed, color=\"{}\", arrowhead=vee, "
                                        "constraint=false",
                                        r.conditions[i].negative ? "#c07070" : "#70a070");
        write_map(w, r.conditions[i].n, r.L, pre, conditions[i], style, false, false);
    }
    w.close();
    return w.take();
}

std::string morphism_to_dot(const hom::ACSetMorphism& f, const ACSet& dom, const ACSet& codom,
                            std::string_view name, const DotOptions& o) {
    check_images(f, dom, codom);
    Folding folding = detail::decide_folding(dom.schema(), o, {&dom});
    Panel from(dom, "dom_", folding, o), to(codom, "codom_", folding, o);
    Writer w;
    header(w, name, name, o, false, true);
    write_panel_cluster(w, from, "dom", "domain", "#555555");
    write_panel_cluster(w, to, "codom", "codomain", "#555555");
    if (write_map(w, f, dom, from, to, kMapStyle, false, true) == 0) {
        order_panels(w, anchor(from, "dom"), anchor(to, "codom"));
    }
    // Where the domain's attribute variables go: a note under the picture.
    std::string vars;
    const Schema& s = dom.schema();
    for (std::uint32_t t = 0; t < s.num_attr_types() && t < f.var_components.size(); ++t) {
        AttrTypeId type(t);
        for (std::uint32_t j = 0; j < dom.num_vars(type) && j < f.var_components[t].size(); ++j) {
            vars += escape_quoted(fmt::format("{} ↦ {}", dom.value_label(type, Value::var(j)),
                                              codom.value_label(type, f.var(type, j)))) +
                    "\\l";
        }
    }
    if (!vars.empty()) {
        w.line(fmt::format("variables [shape=note, fontsize=10, label=\"{}\"];", vars));
    }
    w.close();
    return w.take();
}

namespace {

// ---- ontology maps ------------------------------------------------------------------------------

std::string html_row(std::string_view text, std::string_view port = {}) {
    std::string attrs = "ALIGN=\"LEFT\"";
    if (!port.empty()) {
        attrs += fmt::format(" PORT=\"{}\"", port);
    }
    return fmt::format("<TR><TD {}>{}</TD></TR>", attrs, escape_html(text));
}

/// Writes the query box of target object `c` (node id `id`) and dotted edges from each of its
/// variables to the source object or attribute type it ranges over.
void write_query_box(Writer& w, const migrate::SchemaMap& f, ObId c, const std::string& id) {
    const migrate::Query& q = f.query(c);
    const Schema& s = *f.source();
    const ACSet& shape = q.state();
    migrate::ShapeNames names(q);
    std::string html = fmt::format("<TABLE BORDER=\"1\" CELLBORDER=\"0\" CELLSPACING=\"0\" "
                                   "CELLPADDING=\"3\" STYLE=\"rounded\" BGCOLOR=\"#fffbe6\">"
                                   "<TR><TD><B>{}</B> <FONT COLOR=\"#666666\">query</FONT></TD>"
                                   "</TR><HR/>",
                                   escape_html(f.target()->ob(c).name));
    std::vector<std::string> edges;
    std::size_t row = 0;
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        for (Part p = 0; p < shape.num_parts(ObId(i)); ++p) {
            std::string port = fmt::format("v{}", ++row);
            html +=
                html_row(fmt::format("{}::{}", names.part(ObId(i), p), s.ob(ObId(i)).name), port);
            edges.push_back(fmt::format("{}:{}:e -> {} [style=dotted, color=\"#b08000\", "
                                        "arrowhead=vee];",
                                        dot_id(id), port, dot_id("S_" + s.ob(ObId(i)).name)));
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId type(t);
        for (std::uint32_t j = 0; j < shape.num_vars(type); ++j) {
            std::string port = fmt::format("v{}", ++row);
            html += html_row(
                fmt::format("{}::{}", names.value(type, Value::var(j)), s.attr_type(type).name),
                port);
            edges.push_back(fmt::format("{}:{}:e -> {} [style=dotted, color=\"#b08000\", "
                                        "arrowhead=vee];",
                                        dot_id(id), port, dot_id("S_" + s.attr_type(type).name)));
        }
    }
    if (q.is_empty()) {
        html += html_row("@empty (no elements)");
    } else if (row == 0) {
        html += html_row("@unit (one element)");
    }
    auto facts = migrate::query_facts(q, names);
    for (std::size_t i = 0; i < facts.size(); ++i) {
        html += (i == 0 ? "<HR/>" : "") + html_row(facts[i]);
    }
    html += "</TABLE>";
    w.line(fmt::format("{} [shape=plain, label=<{}>];", dot_id(id), html));
    for (const auto& e : edges) {
        w.line(e);
    }
}

/// The table of hom and attribute images, one row per target generator; "" when there are none.
std::string images_table(const migrate::SchemaMap& f) {
    std::string rows;
    std::string_view section;
    for (const auto& line : migrate::describe_map(f)) {
        using schema::GeneratorKind;
        std::string_view kind = line.target.kind == GeneratorKind::Hom    ? "homs"
                                : line.target.kind == GeneratorKind::Attr ? "attributes"
                                                                          : "";
        if (kind.empty()) {
            continue; // objects and attribute types are drawn as edges
        }
        if (kind != section) {
            section = kind;
            rows += fmt::format("<TR><TD COLSPAN=\"2\" ALIGN=\"LEFT\"><B>{}</B></TD></TR>", kind);
        }
        rows += fmt::format("<TR><TD ALIGN=\"LEFT\">{}</TD><TD ALIGN=\"LEFT\">⇒ {}</TD></TR>",
                            escape_html(line.name), escape_html(line.image));
    }
    if (rows.empty()) {
        return {};
    }
    return "<TABLE BORDER=\"1\" CELLBORDER=\"0\" CELLSPACING=\"0\" CELLPADDING=\"2\" "
           "COLOR=\"#999999\">" +
           rows + "</TABLE>";
}

void write_schema_cluster(Writer& w, const Schema& s, std::string_view id, std::string_view role,
                          std::string_view prefix) {
    w.open(fmt::format("subgraph {} {{", dot_id("cluster_" + std::string(id))));
    w.line(fmt::format("graph [label=<<B>{}</B> <FONT COLOR=\"#666666\">({})</FONT>>, "
                       "style=\"rounded,bold\", color=\"#555555\", fontsize=13];",
                       escape_html(s.name()), role));
    write_schema_body(w, s, prefix);
    w.close();
}

} // namespace

std::string map_to_dot(const migrate::SchemaMap& f, std::string_view name, const DotOptions& o) {
    CATPLAN_ASSERT(f.ok(), "map_to_dot needs a finished map without errors");
    const Schema& t = *f.target();
    const Schema& s = *f.source();
    Writer w;
    header(w, name,
           fmt::format("{}: {} → {}{}", name, t.name(), s.name(),
                       f.is_delta() ? " (delta)" : " (conjunctive)"),
           o, /*left_to_right=*/true, /*newrank=*/true);
    write_schema_cluster(w, t, "target", "target", "T_");
    write_schema_cluster(w, s, "source", "source", "S_");
    w.line(fmt::format("edge [{}];", kImageStyle));
    for (std::uint32_t i = 0; i < t.num_obs(); ++i) {
        ObId c(i);
        std::string from = dot_id("T_" + t.ob(c).name);
        if (f.query(c).is_plain()) {
            w.line(fmt::format("{} -> {};", from, dot_id("S_" + s.ob(f.plain_ob(c)).name)));
            continue;
        }
        std::string box = "Q_" + t.ob(c).name;
        write_query_box(w, f, c, box);
        w.line(fmt::format("{} -> {};", from, dot_id(box)));
    }
    std::vector<std::string> kinds; // value kinds drawn so far
    for (std::uint32_t i = 0; i < t.num_attr_types(); ++i) {
        AttrTypeId a(i);
        std::string from = dot_id("T_" + t.attr_type(a).name);
        if (auto image = f.attr_type_image(a)) {
            w.line(fmt::format("{} -> {};", from, dot_id("S_" + s.attr_type(*image).name)));
            continue;
        }
        std::string kind(schema::to_string(f.attr_type_kind(a)));
        if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
            kinds.push_back(kind);
            w.line(fmt::format("{} [shape=ellipse, style=dotted, label=<{}<BR/><FONT "
                               "POINT-SIZE=\"9\" COLOR=\"#555555\">value kind</FONT>>];",
                               dot_id("K_" + kind), escape_html(kind)));
        }
        w.line(fmt::format("{} -> {};", from, dot_id("K_" + kind)));
    }
    std::string table = images_table(f);
    if (!table.empty()) {
        w.line(fmt::format("images [shape=plain, fontsize=10, label=<{}>];", table));
    }
    w.close();
    return w.take();
}

} // namespace catplan::dot
