#pragma once
// The drawing of one state inside a DOT picture (a "panel"), shared by the state, rule and
// morphism pictures of dot.cpp: which objects are folded into edges or rows, and the nodes,
// rows and edges of the state's parts. Private to the dot layer.

#include "catplan/dot/dot.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace catplan::dot::detail {

/// Accumulates indented lines.
class Writer {
public:
    void line(std::string_view text);
    void open(std::string_view text);
    void close();

    std::string take() { return std::move(out_); }

private:
    std::string out_;
    std::size_t indent_ = 0;
};

/// A soft fill per object (by declaration index), so an object has the same colour in the
/// schema, in every state and in every panel of a rule.
std::string_view fill(ObId x);

/// Opens a digraph named `name` with a title and the fonts of `o`.
void header(Writer& w, std::string_view name, std::string_view label, const DotOptions& o,
            bool left_to_right, bool newrank);

/// How each object is drawn besides as nodes (dot.hpp's readability heuristics).
struct Folding {
    std::vector<bool> relation;  // by object: parts drawn as one edge
    std::vector<bool> predicate; // by object: parts drawn as rows of their hom's target
    std::vector<bool> facet;     // by object: parts drawn as rows of the entity part that is them
    std::vector<bool> is_a;      // by hom: from an entity object to a facet object
};

/// Decides the folding of each object. `sources` are the states whose parts start map edges: a
/// relation object with parts there stays drawn as nodes so the edges have somewhere to start,
/// and facets are folded only in pictures of one state (no sources).
Folding decide_folding(const schema::Schema& s, const DotOptions& o,
                       const std::vector<const acset::ACSet*>& sources);

/// One row of a node's table.
struct Row {
    std::string port; // empty for an attribute of the part itself
    std::string html; // the row's text, already escaped
    std::string_view bg;
};

/// A state drawn with node ids prefixed by `prefix` ("" for a picture of one state).
class Panel {
public:
    Panel(const acset::ACSet& x, std::string prefix, const Folding& folding, const DotOptions& o);

    /// Marks parts with CSS classes and relabels parts (state pictures only: the parts are this
    /// panel's); either may be null.
    void set_marks(const std::vector<PartClass>* classes, const std::vector<PartLabel>* labels);

    /// The node id of a part drawn as a node.
    std::string node_id(ObId ob, Part p) const;

    /// Where a part is drawn, as a node id and a port ("" for the whole node); nullopt for a
    /// relation part drawn as an edge.
    std::optional<std::pair<std::string, std::string>> place(ObId ob, Part p) const;

    /// Writes the clusters of this panel's nodes and the edges of its homs.
    void write(Writer& w) const;

    /// Whether the panel draws any node (an empty state draws a placeholder instead).
    bool has_nodes() const;

    /// The first node of the panel, if any (anchors the side-by-side layout of panels).
    std::optional<std::string> first_node() const;

private:
    using Owner = std::optional<std::pair<ObId, Part>>;

    void add_attribute_rows();
    void add_predicate_rows();
    void add_facet_rows();
    std::string port_name(ObId ob, Part p) const;
    std::string attr_text(Part p, AttrId a) const;
    std::string attr_text(ObId ob, Part p) const;
    std::string label(ObId ob, Part p) const;
    std::string class_attr(ObId ob, Part p) const;
    bool is_node(ObId ob, Part p) const;
    bool is_entity(ObId ob) const;
    void write_cluster(Writer& w, ObId ob) const;
    void write_node(Writer& w, ObId ob, Part p) const;
    void write_hom_edges(Writer& w, HomId h) const;
    void write_relation_edges(Writer& w, ObId ob) const;

    const acset::ACSet& x_;
    const schema::Schema& s_;
    std::string prefix_;
    const Folding& folding_;
    const DotOptions& o_;
    std::vector<std::vector<std::vector<Row>>> rows_; // by object, by part
    std::vector<std::vector<Owner>> owner_;           // by facet object, by part
    const std::vector<PartClass>* classes_ = nullptr;
    const std::vector<PartLabel>* labels_ = nullptr;
};

/// An edge end: a node, or a row of a node with an optional compass point ("e", "w") so that an
/// edge between side-by-side panels leaves and enters the row from the side facing the other.
std::string endpoint(const std::pair<std::string, std::string>& place, std::string_view compass);

} // namespace catplan::dot::detail
