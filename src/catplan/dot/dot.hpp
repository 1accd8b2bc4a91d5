#pragma once
// Graphviz DOT pictures of schemas, states, rules and morphisms, for people to look at
// (`dot -Tsvg picture.dot > picture.svg`).
//
//   schema     objects as boxes, homs as solid labelled edges, attribute types as ellipses and
//              attributes as dashed labelled edges (the paper's schema figures)
//   state      one cluster per object that has parts; a part is a node labelled by its name (or
//              #k, 1-based) with one row per attribute value; homs are labelled edges
//   rule       Pre ← Keep → Eff side by side, each drawn like a state, with l and r as dashed
//              gray edges from each Keep part to its images
//   morphism   domain and codomain side by side, a dashed edge from each part to its image
//   map        an ontology map F : D' -> D: the target schema D' (left) and the source schema D
//              (right) as clusters drawn like schema pictures; a dashed blue edge from each target
//              object to its image, a source object or a query box listing the query's variables
//              (`block::Block`) and facts (`hasColor(block) == "purple"`), with dotted edges
//              from each variable to the source object or attribute type it ranges over; dashed
//              blue edges from each target attribute type to its source type or value kind; the
//              images of homs and attributes listed in a table under the picture
//
// Three readability heuristics for blocks-like domains, all on by default (DotOptions):
//   relation edges   an object with exactly two homs, no attributes and no homs into it (a binary
//                    relation such as On(on_l, on_r)) is drawn as one edge from a part's first
//                    target to its second, labelled "On x1", instead of a node with two edges.
//                    In rule and morphism pictures this applies only to objects of which the
//                    source of the maps (Keep, the domain) has no parts, so that every map edge
//                    has a node at each end. A part with an unset hom is drawn as a node.
//   predicate rows   an object with exactly one hom, at least one attribute and no homs into it
//                    (a predicate object such as IsClear(isClearDom, isClear) in the slides'
//                    form) whose hom points at a part drawn as a node is drawn as a row
//                    "isClear = true" of that node. Map edges attach to the row.
//   facet rows       in a picture of one state, an object with attributes or with two or more
//                    homs into objects that have no homs and no attributes of their own is an
//                    entity, and those objects are its facets (Kitchenworld's BreadSliced is an
//                    Object and a Receptacle): a facet part that exactly one entity part is, is
//                    drawn as a row "is Object" of that part's node, and edges to the facet part
//                    (a relation's, InReceptacle) attach to the row, so that one thing is one
//                    node and a tower reads as one. Entity nodes are drawn outside clusters,
//                    their object named after the part's name.
//
// Output is deterministic: objects, homs and attributes in declaration order, parts in part
// order. Node ids are stable and readable: `Block_3` is part 3 (1-based) of Block; in rule and
// morphism pictures they carry the panel's name (`Pre_Block_3`, `dom_Block_3`). Unset attribute
// cells are not shown; attribute variables are shown as ?name or ?k.

#include "catplan/acset/acset.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/schema/schema.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace catplan::dot {

struct DotOptions {
    /// Lay states and schemas out left to right (rankdir=LR) instead of top to bottom. Rule and
    /// morphism pictures always put their panels side by side.
    bool left_to_right = false;
    /// Draw binary relation objects as one edge per part (see the header comment).
    bool relation_edges = true;
    /// Draw predicate objects as rows of the node they point at (see the header comment).
    bool predicate_rows = true;
    /// Fold facet parts into the node of the entity part that is them (see the header comment).
    bool facet_rows = true;
    /// Objects (by name) whose parts' attribute rows are not drawn: a report says their values
    /// once beside the picture when every part has the same ones.
    std::vector<std::string> attributes_hidden;
    /// Prefix each folded predicate row with the predicate part's name, when it has one.
    bool predicate_part_names = false;
    /// The font of every label.
    std::string font = "Helvetica";
};

/// A DOT digraph of a schema: objects, homs, attribute types and attributes, plus a note listing
/// the equations when there are any.
std::string schema_to_dot(const schema::Schema& s, const DotOptions& options = {});

/// A CSS class given to one part of a state's picture (Graphviz's `class` attribute, which SVG
/// output puts on the part's element): how a report marks what a step deletes or creates.
struct PartClass {
    ObId ob;
    Part part = kNoPart;
    std::string css_class;
};

/// A label given to one part of a state's picture in place of its name: how a report calls a
/// part whose name catplan made up by a term a person can read (`isEmpty(empty)`).
struct PartLabel {
    ObId ob;
    Part part = kNoPart;
    std::string label;
};

/// A DOT digraph of a state, titled `name`, with one cluster per object that has parts; a part
/// in `classes` carries its class on its node (a facet folded into a row, on its entity's node),
/// or on its edge for a relation part drawn as one (a predicate folded into a row has no element
/// of its own and is not marked); a part in `labels` is shown with that label.
std::string state_to_dot(const acset::ACSet& x, std::string_view name,
                         const DotOptions& options = {}, const std::vector<PartClass>& classes = {},
                         const std::vector<PartLabel>& labels = {});

/// A DOT digraph of a rule: clusters Pre, Keep and Eff (and one per application condition) with
/// the maps between them as dashed edges.
std::string rule_to_dot(const rewrite::Rule& r, const DotOptions& options = {});

/// A DOT digraph of a morphism f : dom -> codom, titled `name`. f's components must have one
/// entry per part of dom and images in codom (asserted); naturality is not required.
std::string morphism_to_dot(const hom::ACSetMorphism& f, const acset::ACSet& dom,
                            const acset::ACSet& codom, std::string_view name,
                            const DotOptions& options = {});

/// A DOT digraph of a finished ontology map F : D' -> D, titled `name`: both schemas side by
/// side, the images of objects and attribute types as dashed edges (through query boxes for
/// conjunctive images), and the images of homs and attributes as a table.
std::string map_to_dot(const migrate::SchemaMap& f, std::string_view name,
                       const DotOptions& options = {});

/// `s` as a DOT ID: bare when it is a plain identifier (letters, digits, '_', not starting with
/// a digit, not a keyword), otherwise a quoted string with '"' and '\' escaped.
std::string dot_id(std::string_view s);

/// `s` as the text of a quoted DOT string: '"' and '\' escaped, a newline as "\n".
std::string escape_quoted(std::string_view s);

/// `s` as HTML text, in an HTML-like DOT label or an HTML page: & < > " ' escaped as entities, a
/// newline as <BR/>, carriage returns dropped.
std::string escape_html(std::string_view s);

} // namespace catplan::dot
