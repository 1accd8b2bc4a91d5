#include "catplan/dot/detail/panel.hpp"

#include "catplan/base/assert.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>

namespace catplan::dot::detail {

using acset::ACSet;
using schema::Schema;

void Writer::line(std::string_view text) {
    out_.append(2 * indent_, ' ');
    out_ += text;
    out_ += '\n';
}

void Writer::open(std::string_view text) {
    line(text);
    ++indent_;
}

void Writer::close() {
    CATPLAN_ASSERT(indent_ > 0, "unbalanced braces");
    --indent_;
    line("}");
}

std::string_view fill(ObId x) {
    static constexpr std::array<std::string_view, 8> kFills = {
        "#dbe9f6", "#fde2c8", "#d9f0d3", "#f3d9ec", "#fff2b3", "#e0dcf5", "#cdeeee", "#f6d5d5"};
    return kFills[x.index() % kFills.size()];
}

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

namespace {

// Objects whose parts are nothing but an aspect of another part: no homs out, no attributes.
bool may_be_facet(const Schema& s, ObId x) {
    return s.homs_from(x).empty() && s.attrs_from(x).empty() && !s.homs_into(x).empty();
}

// The homs of x into objects that may be facets.
std::vector<HomId> facet_homs(const Schema& s, ObId x) {
    std::vector<HomId> out;
    for (HomId h : s.homs_from(x)) {
        if (may_be_facet(s, s.hom(h).codom)) {
            out.push_back(h);
        }
    }
    return out;
}

// Entities and their facets. An object with two or more homs into objects that may be facets
// (BreadSliced is an Object and a Receptacle) makes them facets; then an object with
// attributes and a hom into a facet (Knife is an Object) is an entity too, not a predicate
// row, and its homs into facets are is-a homs. Without the first kind nothing is a facet, so
// the slides' IsClear stays a row of its Block.
void decide_facets(const Schema& s, Folding& f) {
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        auto homs = facet_homs(s, ObId(i));
        if (!f.relation[i] && homs.size() >= 2) {
            for (HomId h : homs) {
                f.facet[s.hom(h).codom.index()] = true;
            }
        }
    }
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        ObId x(i);
        auto homs = facet_homs(s, x);
        bool entity = !f.relation[i] && (homs.size() >= 2 || !s.attrs_from(x).empty());
        for (HomId h : homs) {
            if (entity && f.facet[s.hom(h).codom.index()]) {
                f.is_a[h.index()] = true;
                f.predicate[i] = false;
            }
        }
    }
    // A predicate row needs a node to sit in: an object a folded predicate points at is no facet.
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        if (f.predicate[i]) {
            f.facet[s.hom(s.homs_from(ObId(i))[0]).codom.index()] = false;
        }
    }
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        f.is_a[h] = f.is_a[h] && f.facet[s.hom(HomId(h)).codom.index()];
    }
}

} // namespace

Folding decide_folding(const Schema& s, const DotOptions& o,
                       const std::vector<const ACSet*>& sources) {
    Folding f{std::vector<bool>(s.num_obs(), false), std::vector<bool>(s.num_obs(), false),
              std::vector<bool>(s.num_obs(), false), std::vector<bool>(s.num_homs(), false)};
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
    if (o.facet_rows && sources.empty()) {
        decide_facets(s, f);
    }
    return f;
}

Panel::Panel(const ACSet& x, std::string prefix, const Folding& folding, const DotOptions& o)
    : x_(x), s_(x.schema()), prefix_(std::move(prefix)), folding_(folding), o_(o) {
    rows_.resize(s_.num_obs());
    owner_.resize(s_.num_obs());
    for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
        rows_[i].resize(x_.num_parts(ObId(i)));
    }
    add_facet_rows();
    add_attribute_rows();
    add_predicate_rows();
}

void Panel::set_marks(const std::vector<PartClass>* classes, const std::vector<PartLabel>* labels) {
    classes_ = classes;
    labels_ = labels;
}

// A facet part is folded into the one entity part an is-a hom sends to it; one that no entity
// part or several are (the hand-empty block's Object, made from no sliced thing) stays a node.
void Panel::add_facet_rows() {
    std::vector<std::vector<int>> count(s_.num_obs());
    for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
        if (folding_.facet[i]) {
            count[i].assign(x_.num_parts(ObId(i)), 0);
            owner_[i].assign(x_.num_parts(ObId(i)), std::nullopt);
        }
    }
    for (std::uint32_t h = 0; h < s_.num_homs(); ++h) {
        if (!folding_.is_a[h]) {
            continue;
        }
        const auto& hom = s_.hom(HomId(h));
        for (Part p = 0; p < x_.num_parts(hom.dom); ++p) {
            Part q = x_.subpart(HomId(h), p);
            if (q != kNoPart && ++count[hom.codom.index()][q] == 1) {
                owner_[hom.codom.index()][q] = std::pair{hom.dom, p};
            }
        }
    }
    for (std::uint32_t h = 0; h < s_.num_homs(); ++h) {
        if (!folding_.is_a[h]) {
            continue;
        }
        const auto& hom = s_.hom(HomId(h));
        std::uint32_t f = hom.codom.index();
        for (Part p = 0; p < x_.num_parts(hom.dom); ++p) {
            Part q = x_.subpart(HomId(h), p);
            if (q == kNoPart || count[f][q] != 1) {
                if (q != kNoPart) {
                    owner_[f][q] = std::nullopt;
                }
                continue;
            }
            rows_[hom.dom.index()][p].push_back({port_name(hom.codom, q),
                                                 fmt::format("<FONT COLOR=\"#555555\">is {}</FONT>",
                                                             escape_html(s_.ob(hom.codom).name)),
                                                 fill(hom.codom)});
        }
    }
}

// One row per attribute of the part itself: long values stay readable.
void Panel::add_attribute_rows() {
    for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
        ObId ob(i);
        const auto& hidden = o_.attributes_hidden;
        if (std::find(hidden.begin(), hidden.end(), s_.ob(ob).name) != hidden.end()) {
            continue;
        }
        for (Part p = 0; p < x_.num_parts(ob); ++p) {
            for (AttrId a : s_.attrs_from(ob)) {
                std::string text = attr_text(p, a);
                if (!text.empty()) {
                    rows_[i][p].push_back({"", std::move(text), ""});
                }
            }
        }
    }
}

// Predicate rows go after the part's own attributes, by object then part.
void Panel::add_predicate_rows() {
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

std::string Panel::node_id(ObId ob, Part p) const {
    return prefix_ + s_.ob(ob).name + "_" + std::to_string(p + 1);
}

std::optional<std::pair<std::string, std::string>> Panel::place(ObId ob, Part p) const {
    if (is_node(ob, p)) {
        return std::pair{node_id(ob, p), std::string()};
    }
    if (folding_.predicate[ob.index()]) {
        HomId h = s_.homs_from(ob)[0];
        return std::pair{node_id(s_.hom(h).codom, x_.subpart(h, p)), port_name(ob, p)};
    }
    if (folding_.facet[ob.index()]) {
        auto [entity, part] = *owner_[ob.index()][p];
        return std::pair{node_id(entity, part), port_name(ob, p)};
    }
    return std::nullopt;
}

void Panel::write(Writer& w) const {
    for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
        write_cluster(w, ObId(i));
    }
    for (std::uint32_t i = 0; i < s_.num_homs(); ++i) {
        write_hom_edges(w, HomId(i));
    }
    for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
        if (folding_.relation[i]) {
            write_relation_edges(w, ObId(i));
        }
    }
}

bool Panel::has_nodes() const {
    return first_node().has_value();
}

std::optional<std::string> Panel::first_node() const {
    for (std::uint32_t i = 0; i < s_.num_obs(); ++i) {
        for (Part p = 0; p < x_.num_parts(ObId(i)); ++p) {
            if (is_node(ObId(i), p)) {
                return node_id(ObId(i), p);
            }
        }
    }
    return std::nullopt;
}

std::string Panel::port_name(ObId ob, Part p) const {
    return s_.ob(ob).name + "_" + std::to_string(p + 1);
}

std::string Panel::attr_text(Part p, AttrId a) const {
    const acset::Value& v = x_.subpart(a, p);
    if (v.is_unset()) {
        return {};
    }
    return escape_html(
        fmt::format("{} = {}", s_.attr(a).name, x_.value_label(s_.attr(a).codom, v)));
}

std::string Panel::attr_text(ObId ob, Part p) const {
    std::string text;
    for (AttrId a : s_.attrs_from(ob)) {
        std::string one = attr_text(p, a);
        if (!one.empty()) {
            text += (text.empty() ? "" : ", ") + one;
        }
    }
    return text;
}

// The part's label, or the one the caller gave it (a term for a name catplan made up).
std::string Panel::label(ObId ob, Part p) const {
    if (labels_ != nullptr) {
        for (const auto& l : *labels_) {
            if (l.ob == ob && l.part == p) {
                return l.label;
            }
        }
    }
    return x_.part_label(ob, p);
}

// `, class="..."` for a marked part (or a marked facet folded into it), else "".
std::string Panel::class_attr(ObId ob, Part p) const {
    if (classes_ == nullptr) {
        return {};
    }
    std::string out;
    for (const auto& c : *classes_) {
        bool here = c.ob == ob && c.part == p;
        if (!here && folding_.facet[c.ob.index()] && c.part < owner_[c.ob.index()].size()) {
            here = owner_[c.ob.index()][c.part] == std::pair{ob, p};
        }
        if (here && out.find(c.css_class) == std::string::npos) {
            out += (out.empty() ? "" : " ") + c.css_class;
        }
    }
    return out.empty() ? out : fmt::format(", class=\"{}\"", escape_quoted(out));
}

bool Panel::is_node(ObId ob, Part p) const {
    if (folding_.relation[ob.index()]) {
        auto homs = s_.homs_from(ob);
        return x_.subpart(homs[0], p) == kNoPart || x_.subpart(homs[1], p) == kNoPart;
    }
    if (folding_.predicate[ob.index()]) {
        return x_.subpart(s_.homs_from(ob)[0], p) == kNoPart;
    }
    if (folding_.facet[ob.index()]) {
        return !owner_[ob.index()][p].has_value();
    }
    return true;
}

// Whether ob's parts carry facets: they are drawn outside clusters, their object named in each
// node, so that things of several kinds can stand in one tower.
bool Panel::is_entity(ObId ob) const {
    const auto homs = s_.homs_from(ob);
    return std::any_of(homs.begin(), homs.end(), [&](HomId h) { return folding_.is_a[h.index()]; });
}

void Panel::write_cluster(Writer& w, ObId ob) const {
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
    bool cluster = !is_entity(ob);
    if (cluster) {
        w.open(fmt::format("subgraph {} {{", dot_id("cluster_" + prefix_ + name)));
        w.line(fmt::format("graph [label=\"{}\", style=rounded, color=\"#999999\", "
                           "fontcolor=\"#444444\", fontsize=11];",
                           escape_quoted(name)));
        w.line(
            fmt::format("node [shape=box, style=\"rounded,filled\", fillcolor=\"{}\"];", fill(ob)));
    }
    for (Part p : parts) {
        write_node(w, ob, p);
    }
    if (cluster) {
        w.close();
    }
}

void Panel::write_node(Writer& w, ObId ob, Part p) const {
    std::string text = label(ob, p);
    const auto& rows = rows_[ob.index()][p];
    if (rows.empty()) {
        // In a cluster the node's shape and fill are the cluster's defaults.
        std::string style = is_entity(ob) ? fmt::format("shape=box, style=\"rounded,filled\", "
                                                        "fillcolor=\"{}\", ",
                                                        fill(ob))
                                          : std::string();
        w.line(fmt::format("{} [{}label=\"{}\"{}];", dot_id(node_id(ob, p)), style,
                           escape_quoted(text), class_attr(ob, p)));
        return;
    }
    std::string title = fmt::format("<B>{}</B>", escape_html(text));
    if (is_entity(ob)) {
        title += fmt::format(" <FONT COLOR=\"#555555\">{}</FONT>", escape_html(s_.ob(ob).name));
    }
    std::string html = fmt::format("<TABLE BORDER=\"1\" CELLBORDER=\"0\" CELLSPACING=\"0\" "
                                   "CELLPADDING=\"3\" STYLE=\"rounded\" BGCOLOR=\"{}\">"
                                   "<TR><TD>{}</TD></TR>",
                                   fill(ob), title);
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

// The edges of hom h from parts drawn as nodes, but for an is-a hom to the facet folded into
// the part itself.
void Panel::write_hom_edges(Writer& w, HomId h) const {
    ObId dom = s_.hom(h).dom, codom = s_.hom(h).codom;
    for (Part p = 0; p < x_.num_parts(dom); ++p) {
        Part t = x_.subpart(h, p);
        if (t == kNoPart || !is_node(dom, p)) {
            continue;
        }
        if (folding_.is_a[h.index()] && owner_[codom.index()][t] == std::pair{dom, p}) {
            continue;
        }
        w.line(fmt::format("{} -> {} [label=\"{}\"];", dot_id(node_id(dom, p)),
                           endpoint(*place(codom, t), ""), escape_quoted(s_.hom(h).name)));
    }
}

void Panel::write_relation_edges(Writer& w, ObId ob) const {
    auto homs = s_.homs_from(ob);
    const std::string& name = s_.ob(ob).name;
    for (Part p = 0; p < x_.num_parts(ob); ++p) {
        if (is_node(ob, p)) {
            continue;
        }
        auto part = x_.part_name(ob, p);
        std::string label = part.empty() ? name : fmt::format("{} {}", name, part);
        auto from = place(s_.hom(homs[0]).codom, x_.subpart(homs[0], p));
        auto to = place(s_.hom(homs[1]).codom, x_.subpart(homs[1], p));
        w.line(fmt::format("{} -> {} [label=\"{}\", penwidth=1.6, color=\"#555555\"{}];",
                           endpoint(*from, ""), endpoint(*to, ""), escape_quoted(label),
                           class_attr(ob, p)));
    }
}

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

} // namespace catplan::dot::detail
