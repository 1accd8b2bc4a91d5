#include "catplan/dot/dot.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/base/escape.hpp"
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
        std::string lower(s);
        std::transform(lower.begin(), lower.end(), lower.begin(),
                       [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; });
        bare = std::find(kKeywords.begin(), kKeywords.end(), lower) == kKeywords.end();
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

// Soft fills, one per object (by declaration index), so an object has the same colour in the
// schema, in every state and in every panel of a rule.
constexpr std::array<std::string_view, 8> kFills = {"#dbe9f6", "#fde2c8", "#d9f0d3", "#f3d9ec",
                                                    "#fff2b3", "#e0dcf5", "#cdeeee", "#f6d5d5"};

std::string_view fill(ObId x) {
    return kFills[x.index() % kFills.size()];
}

/// Accumulates indented lines.
class Writer {
public:
    void line(std::string_view text) {
        out_.append(2 * indent_, ' ');
        out_ += text;
        out_ += '\n';
    }

    void open(std::string_view text) {
        line(text);
        ++indent_;
    }

    void close() {
        CATPLAN_ASSERT(indent_ > 0, "unbalanced braces");
        --indent_;
        line("}");
    }

    std::string take() { return std::move(out_); }

private:
    std::string out_;
    std::size_t indent_ = 0;
};

void header(Writer& w, std::string_view name, std::string_view label, const DotOptions& o,
            bool left_to_right, bool newrank) {
    w.open(fmt::format("digraph {} {{", dot_id(name)));
    std::string graph = fmt::format("graph [fontname=\"{}\", fontsize=14, labelloc=t, label=\"{}\"",
                                    escape_quoted(o.font), escape_quoted(label));
    if (left_to_right) {
        graph += ", rankdir=LR";
    }
    if (newrank) {
        graph += ", newrank=true";
    }
    w.line(graph + "];");
    w.line(fmt::format("node [fontname=\"{}\", fontsize=11];", escape_quoted(o.font)));
    w.line(fmt::format("edge [fontname=\"{}\", fontsize=10];", escape_quoted(o.font)));
}

// ---- which objects are drawn as edges or rows ---------------------------------------------------

struct Folding {
    std::vector<bool> relation;  // by object: parts drawn as one edge
    std::vector<bool> predicate; // by object: parts drawn as rows of their hom's target
};

/// Decides the folding of each object. `sources` are the states whose parts start map edges: a
/// relation object with parts there stays drawn as nodes so the edges have somewhere to start.
Folding decide_folding(const Schema& s, const DotOptions& o,
                       const std::vector<const ACSet*>& sources) {
    Folding f{std::vector<bool>(s.num_obs(), false), std::vector<bool>(s.num_obs(), false)};
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        ObId x(i);
        if (!s.homs_into(x).empty()) {
            continue; // something points at these parts: they must be nodes
        }
        auto homs = s.homs_from(x);
        auto attrs = s.attrs_from(x);
        if (o.relation_edges && homs.size() == 2 && attrs.empty()) {
            f.relation[i] = std::none_of(sources.begin(), sources.end(),
                                         [&](const ACSet* a) { return a->num_parts(x) > 0; });
        } else if (o.predicate_rows && homs.size() == 1 && !attrs.empty()) {
            f.predicate[i] = true;
        }
    }
    return f;
}

// ---- panels: one state drawn inside a picture -------------------------------------------------

struct Row {
    std::string port; // empty for an attribute of the part itself
    std::string html; // the row's text, already escaped
    std::string_view bg;
};

/// A state drawn with node ids prefixed by `prefix` ("" for a picture of one state).
class Panel {
public:
    Panel(const ACSet& x, std::string prefix, const Folding& folding, const DotOptions& o)
        : x_(x), s_(x.schema()), prefix_(std::move(prefix)), folding_(folding), o_(o) {
        rows_.resize(s_.num_obs());
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            rows_[i].resize(x_.num_parts(ObId(i)));
        }
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            ObId ob(i);
            // One row per attribute of the part itself: long values stay readable.
            for (Part p = 0; p < x_.num_parts(ob); ++p) {
                for (AttrId a : s_.attrs_from(ob)) {
                    std::string text = attr_text(p, a);
                    if (!text.empty()) {
                        rows_[i][p].push_back({"", std::move(text), ""});
                    }
                }
            }
        }
        // Predicate rows go after the part's own attributes, by object then part.
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            ObId ob(i);
            if (!folding_.predicate[i]) {
                continue;
            }
            HomId h = s_.homs_from(ob)[0];
            ObId target = s_.hom(h).codom;
            for (Part q = 0; q < x_.num_parts(ob); ++q) {
                Part t = x_.subpart(h, q);
                if (t == kNoPart) {
                    continue; // drawn as a node of its own
                }
                std::string text = attr_text(ob, q);
                if (text.empty()) {
                    text = escape_html(s_.ob(ob).name);
                }
                if (o_.predicate_part_names && !x_.part_name(ob, q).empty()) {
                    text = fmt::format("<FONT COLOR=\"#666666\">{}:</FONT> {}",
                                       escape_html(x_.part_name(ob, q)), text);
                }
                rows_[target.index()][t].push_back({port_name(ob, q), std::move(text), fill(ob)});
            }
        }
    }

    /// Marks parts with CSS classes (state pictures only: the parts are this panel's).
    void set_classes(const std::vector<PartClass>* classes) { classes_ = classes; }

    /// The node id of a part drawn as a node.
    std::string node_id(ObId ob, Part p) const {
        return prefix_ + s_.ob(ob).name + "_" + std::to_string(p + 1);
    }

    /// Where a part is drawn, as a node id and a port ("" for the whole node); nullopt for a
    /// relation part drawn as an edge.
    std::optional<std::pair<std::string, std::string>> place(ObId ob, Part p) const {
        if (is_node(ob, p)) {
            return std::pair{node_id(ob, p), std::string()};
        }
        if (folding_.predicate[ob.index()]) {
            HomId h = s_.homs_from(ob)[0];
            return std::pair{node_id(s_.hom(h).codom, x_.subpart(h, p)), port_name(ob, p)};
        }
        return std::nullopt;
    }

    /// Writes the clusters of this panel's nodes and the edges of its homs.
    void write(Writer& w) const {
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            write_cluster(w, ObId(i));
        }
        for (std::uint32_t i = 0; i < s_.num_homs(); ++i) {
            HomId h(i);
            ObId dom = s_.hom(h).dom;
            for (Part p = 0; p < x_.num_parts(dom); ++p) {
                Part t = x_.subpart(h, p);
                if (t != kNoPart && is_node(dom, p)) {
                    w.line(fmt::format("{} -> {} [label=\"{}\"];", dot_id(node_id(dom, p)),
                                       dot_id(node_id(s_.hom(h).codom, t)),
                                       escape_quoted(s_.hom(h).name)));
                }
            }
        }
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            if (folding_.relation[i]) {
                write_relation_edges(w, ObId(i));
            }
        }
    }

    /// Whether the panel draws any node (an empty state draws a placeholder instead).
    bool has_nodes() const {
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            for (Part p = 0; p < x_.num_parts(ObId(i)); ++p) {
                if (is_node(ObId(i), p)) {
                    return true;
                }
            }
        }
        return false;
    }

    /// The first node of the panel, if any (anchors the side-by-side layout of panels).
    std::optional<std::string> first_node() const {
        for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
            for (Part p = 0; p < x_.num_parts(ObId(i)); ++p) {
                if (is_node(ObId(i), p)) {
                    return node_id(ObId(i), p);
                }
            }
        }
        return std::nullopt;
    }

private:
    std::string port_name(ObId ob, Part p) const {
        return s_.ob(ob).name + "_" + std::to_string(p + 1);
    }

    /// "a = v" for one attribute of a part, escaped for HTML; "" when the cell is unset.
    std::string attr_text(Part p, AttrId a) const {
        const Value& v = x_.subpart(a, p);
        if (v.is_unset()) {
            return {};
        }
        return escape_html(
            fmt::format("{} = {}", s_.attr(a).name, x_.value_label(s_.attr(a).codom, v)));
    }

    /// "a = v, b = w" for the set attributes of a part, escaped for HTML; "" when none is set.
    std::string attr_text(ObId ob, Part p) const {
        std::string text;
        for (AttrId a : s_.attrs_from(ob)) {
            std::string one = attr_text(p, a);
            if (!one.empty()) {
                text += (text.empty() ? "" : ", ") + one;
            }
        }
        return text;
    }

    /// `, class="..."` for a marked part, else "".
    std::string class_attr(ObId ob, Part p) const {
        if (classes_ == nullptr) {
            return {};
        }
        std::string out;
        for (const auto& c : *classes_) {
            if (c.ob == ob && c.part == p) {
                out += (out.empty() ? "" : " ") + c.css_class;
            }
        }
        return out.empty() ? out : fmt::format(", class=\"{}\"", escape_quoted(out));
    }

    bool is_node(ObId ob, Part p) const {
        if (folding_.relation[ob.index()]) {
            auto homs = s_.homs_from(ob);
            return x_.subpart(homs[0], p) == kNoPart || x_.subpart(homs[1], p) == kNoPart;
        }
        if (folding_.predicate[ob.index()]) {
            return x_.subpart(s_.homs_from(ob)[0], p) == kNoPart;
        }
        return true;
    }

    void write_cluster(Writer& w, ObId ob) const {
        std::vector<Part> parts;
        for (Part p = 0; p < x_.num_parts(ob); ++p) {
            if (is_node(ob, p)) {
                parts.push_back(p);
            }
        }
        if (parts.empty()) {
            return;
        }
        const std::string& name = s_.ob(ob).name;
        w.open(fmt::format("subgraph {} {{", dot_id("cluster_" + prefix_ + name)));
        w.line(fmt::format("graph [label=\"{}\", style=rounded, color=\"#999999\", "
                           "fontcolor=\"#444444\", fontsize=11];",
                           escape_quoted(name)));
        w.line(
            fmt::format("node [shape=box, style=\"rounded,filled\", fillcolor=\"{}\"];", fill(ob)));
        for (Part p : parts) {
            write_node(w, ob, p);
        }
        w.close();
    }

    void write_node(Writer& w, ObId ob, Part p) const {
        std::string label = x_.part_label(ob, p);
        const auto& rows = rows_[ob.index()][p];
        if (rows.empty()) {
            w.line(fmt::format("{} [label=\"{}\"{}];", dot_id(node_id(ob, p)), escape_quoted(label),
                               class_attr(ob, p)));
            return;
        }
        std::string html = fmt::format("<TABLE BORDER=\"1\" CELLBORDER=\"0\" CELLSPACING=\"0\" "
                                       "CELLPADDING=\"3\" STYLE=\"rounded\" BGCOLOR=\"{}\">"
                                       "<TR><TD><B>{}</B></TD></TR>",
                                       fill(ob), escape_html(label));
        for (const Row& row : rows) {
            std::string attrs = "ALIGN=\"LEFT\"";
            if (!row.port.empty()) {
                attrs += fmt::format(" PORT=\"{}\"", escape_html(row.port));
            }
            if (!row.bg.empty()) {
                attrs += fmt::format(" BGCOLOR=\"{}\"", row.bg);
            }
            html += fmt::format("<HR/><TR><TD {}>{}</TD></TR>", attrs, row.html);
        }
        html += "</TABLE>";
        w.line(fmt::format("{} [shape=plain, label=<{}>{}];", dot_id(node_id(ob, p)), html,
                           class_attr(ob, p)));
    }

    void write_relation_edges(Writer& w, ObId ob) const {
        auto homs = s_.homs_from(ob);
        const std::string& name = s_.ob(ob).name;
        for (Part p = 0; p < x_.num_parts(ob); ++p) {
            if (is_node(ob, p)) {
                continue;
            }
            auto part = x_.part_name(ob, p);
            std::string label = part.empty() ? name : fmt::format("{} {}", name, part);
            w.line(fmt::format("{} -> {} [label=\"{}\", penwidth=1.6, color=\"#555555\"{}];",
                               dot_id(node_id(s_.hom(homs[0]).codom, x_.subpart(homs[0], p))),
                               dot_id(node_id(s_.hom(homs[1]).codom, x_.subpart(homs[1], p))),
                               escape_quoted(label), class_attr(ob, p)));
        }
    }

    const ACSet& x_;
    const Schema& s_;
    std::string prefix_;
    const Folding& folding_;
    const DotOptions& o_;
    std::vector<std::vector<std::vector<Row>>> rows_; // by object, by part
    const std::vector<PartClass>* classes_ = nullptr;
};

/// An edge end: a node, or a row of a node with an optional compass point ("e", "w") so that an
/// edge between side-by-side panels leaves and enters the row from the side facing the other.
std::string endpoint(const std::pair<std::string, std::string>& place, std::string_view compass) {
    if (place.second.empty()) {
        return dot_id(place.first);
    }
    std::string out = dot_id(place.first) + ":" + dot_id(place.second);
    if (!compass.empty()) {
        out += ":" + std::string(compass);
    }
    return out;
}

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
                         const std::vector<PartClass>& classes) {
    Writer w;
    header(w, name, name, o, o.left_to_right, false);
    Folding folding = decide_folding(x.schema(), o, {});
    Panel panel(x, "", folding, o);
    panel.set_classes(&classes);
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
    Folding folding = decide_folding(r.L.schema(), o, sources);
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
    Folding folding = decide_folding(dom.schema(), o, {&dom});
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
    w.line(fmt::format("edge [{}];", kMapStyle));
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
