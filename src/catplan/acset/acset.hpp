#pragma once
// States: attributed C-sets (the paper's X : D -> Set), stored by columns.
//
// For each object a count of parts 0..n-1; for each hom a column of part ids (kNoPart when unset);
// for each attribute a column of Values (a constant, an attribute variable, or unset); for each
// attribute type a count of variables 0..k-1 (Catlab's AttrVar parts). A preimage index per hom
// makes incident(f, y) cost O(result); it is built on first use and then kept in step with
// set_subpart, add_part(s) and remove_part. A whole column can be written at once by set_column
// (for building a state in bulk, as data migration does); that drops the column's index, which
// is rebuilt on its next use.
//
// Deletion is pop-and-swap, as in Catlab's rem_part!: removing part p of X moves the last part of
// X into slot p (its columns and name come along and every reference to it is redirected to p),
// and every hom value that pointed at the removed part becomes unset. Removal does not cascade.
//
// Parts and variables may carry names (labels for people: equality and morphisms ignore them).
// An object none of whose parts is named stores no names, so unnamed parts cost nothing.
//
//   ACSet g(graph_schema);
//   Part v0 = g.add_part(V), v1 = g.add_part(V);
//   Part e = g.add_part(E);
//   g.set_subpart(src, e, v0);  g.set_subpart(tgt, e, v1);
//   g.incident(src, v0);   // {e}

#include "catplan/acset/value.hpp"
#include "catplan/base/id.hpp"
#include "catplan/base/symbol.hpp"
#include "catplan/schema/schema.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::acset {

using schema::Schema;
using schema::SchemaPtr;

class ACSet {
public:
    explicit ACSet(SchemaPtr schema);

    const Schema& schema() const { return *schema_; }

    const SchemaPtr& schema_ptr() const { return schema_; }

    // ---- parts -------------------------------------------------------------------------------
    std::size_t num_parts(ObId x) const { return nparts_[x.index()]; }

    /// Adds a part with unset homs and attributes, optionally named; returns its id.
    Part add_part(ObId x, std::string_view name = {});
    /// Adds a part named by an interned name (Symbol() for none); returns its id.
    Part add_part(ObId x, Symbol name);
    /// Adds n unnamed parts; returns the id of the first.
    Part add_parts(ObId x, std::size_t n);
    /// Removes a part by pop-and-swap; returns the former id of the part now at p, or kNoPart
    /// when p was the last part.
    Part remove_part(ObId x, Part p);
    /// Reserves room for n parts of x.
    void reserve(ObId x, std::size_t n);

    // ---- homs --------------------------------------------------------------------------------
    Part subpart(HomId f, Part p) const { return homs_[f.index()][p]; }

    /// Sets f(p) = q (q may be kNoPart to unset it).
    void set_subpart(HomId f, Part p, Part q);

    std::span<const Part> column(HomId f) const { return homs_[f.index()]; }

    /// Sets f(p) = values[p] for every part p of f's domain (one value each, a part of f's
    /// codomain or kNoPart; asserted) in one pass, dropping f's preimage index until its next use.
    void set_column(HomId f, std::span<const Part> values);

    /// The parts p with f(p) == q, in no particular (but deterministic) order.
    std::span<const Part> incident(HomId f, Part q) const;
    /// Builds every preimage index now (otherwise each is built on its first incident call).
    void build_indexes() const;

    // ---- attributes --------------------------------------------------------------------------
    const Value& subpart(AttrId a, Part p) const { return attrs_[a.index()][p]; }

    /// Sets a(p) = v; a variable must exist in this state (asserted).
    void set_subpart(AttrId a, Part p, Value v);

    std::span<const Value> column(AttrId a) const { return attrs_[a.index()]; }

    /// Sets a(p) = values[p] for every part p of a's domain (one value each, any variable one of
    /// this state's; asserted) in one pass, dropping the variable index of a's type until its next
    /// use.
    void set_column(AttrId a, std::span<const Value> values);

    // ---- attribute variables -----------------------------------------------------------------
    std::size_t num_vars(AttrTypeId t) const { return nvars_[t.index()]; }

    /// Adds a variable of t, optionally named; returns it as a Value.
    Value add_var(AttrTypeId t, std::string_view name = {});
    /// Removes variable j by pop-and-swap: cells holding it become unset, cells holding the last
    /// variable are renumbered to j. Returns the former index of the variable now at j, or
    /// UINT32_MAX when j was the last. Costs O(cells holding either variable).
    std::uint32_t remove_var(AttrTypeId t, std::uint32_t j);

    /// A cell of an attribute column.
    struct Cell {
        AttrId attr;
        Part part;
        friend bool operator==(const Cell&, const Cell&) = default;
    };

    /// The cells holding variable j of t, in no particular (but deterministic) order; the index
    /// is built on first use and then kept in step like the hom preimage indexes.
    std::span<const Cell> var_incident(AttrTypeId t, std::uint32_t j) const;

    // ---- names -------------------------------------------------------------------------------
    /// The name of a part, or "" when it has none.
    std::string_view part_name(ObId x, Part p) const {
        const auto& names = names_[x.index()];
        return names.empty() ? std::string_view() : names[p].str();
    }

    void set_part_name(ObId x, Part p, std::string_view name);

    /// The name symbols of the parts of x, one per part (Symbol() for an unnamed part), or an
    /// empty span when x stores none, which means that no part of x is named.
    std::span<const Symbol> part_names(ObId x) const { return names_[x.index()]; }

    /// Replaces the names of the parts of x by `names`: one per part (Symbol() for none), or
    /// none at all to unname every part (asserted).
    void set_part_names(ObId x, std::vector<Symbol> names);

    /// The first part of x with this name.
    std::optional<Part> find_part(ObId x, std::string_view name) const;

    std::string_view var_name(AttrTypeId t, std::uint32_t j) const {
        return var_names_[t.index()][j].str();
    }

    void set_var_name(AttrTypeId t, std::uint32_t j, std::string_view name);
    /// "A" for a named part, "#3" (1-based) for an unnamed one.
    std::string part_label(ObId x, Part p) const;
    /// The display form of a value, using variable names where they exist.
    std::string value_label(AttrTypeId t, const Value& v) const;

    /// Total number of parts over all objects.
    std::size_t total_parts() const;

    /// Exact equality of parts, columns and variable counts (names are ignored).
    friend bool operator==(const ACSet& a, const ACSet& b);

private:
    struct Preimage {
        std::vector<std::vector<Part>> lists; // by target part
        std::vector<std::uint32_t> pos;       // position of each source part in its list
    };

    struct VarIndex {
        std::vector<std::vector<Cell>> lists;        // by variable
        std::vector<std::vector<std::uint32_t>> pos; // per attribute of the type: by part
    };

    VarIndex* var_index_if_built(AttrTypeId t) const {
        return var_index_[t.index()] ? &*var_index_[t.index()] : nullptr;
    }

    const VarIndex& var_index(AttrTypeId t) const;

    /// The position of attribute a among the attributes into its type.
    std::size_t attr_slot(AttrId a) const { return attr_slot_[a.index()]; }

    void var_index_insert(AttrId a, Part p, std::uint32_t var);
    void var_index_erase(AttrId a, Part p, std::uint32_t var);
    void index_insert(HomId f, Part p, Part q);
    void index_erase(HomId f, Part p, Part q);
    const Preimage& index(HomId f) const;

    SchemaPtr schema_;
    std::vector<std::size_t> nparts_;
    std::vector<std::vector<Part>> homs_;
    std::vector<std::vector<Value>> attrs_;
    std::vector<std::uint32_t> nvars_;
    std::vector<std::vector<Symbol>> names_; // per object: empty, or one per part
    std::vector<std::vector<Symbol>> var_names_;
    mutable std::vector<std::optional<Preimage>> index_;
    mutable std::vector<std::optional<VarIndex>> var_index_;
    std::vector<std::size_t> attr_slot_;
};

} // namespace catplan::acset
