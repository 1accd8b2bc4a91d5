#include "catplan/migrate/query.hpp"

#include "catplan/base/assert.hpp"

#include <utility>

namespace catplan::migrate {

Term Term::path(std::string var, std::vector<HomId> homs, std::optional<AttrId> attr,
                SourceRange range) {
    Term t;
    t.var = std::move(var);
    t.homs = std::move(homs);
    t.attr = attr;
    t.range = range;
    return t;
}

Term Term::constant(Value value, SourceRange range) {
    Term t;
    t.literal = value;
    t.range = range;
    return t;
}

Query::Query(SchemaPtr source) : source_(source), shape_(std::move(source)) {}

Query Query::representable(SchemaPtr source, ObId ob, std::string name) {
    Query q(std::move(source));
    q.add_variable(std::move(name), ob);
    return q;
}

std::optional<std::size_t> Query::first_object_node() const {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        if (!nodes_[i].is_value) {
            return i;
        }
    }
    return std::nullopt;
}

Part follow(const ACSet& x, Part p, const std::vector<HomId>& homs) {
    for (HomId h : homs) {
        if (p == kNoPart) {
            return kNoPart;
        }
        p = x.subpart(h, p);
    }
    return p;
}

std::optional<std::size_t> Query::find_node(std::string_view name) const {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        if (nodes_[i].name == name) {
            return i;
        }
    }
    return std::nullopt;
}

bool Query::add_variable(std::string name, ObId ob, SourceRange range) {
    if (find_node(name)) {
        problems_.push_back({"variable '" + name + "' declared twice", range});
        return false;
    }
    auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({std::move(name), false, ob, AttrTypeId{}, range});
    node_handles_.push_back({false, shape_.add_part(ob)});
    part_origin_.push_back({node, {}, std::nullopt});
    built_.reset();
    return true;
}

bool Query::add_value_variable(std::string name, AttrTypeId type, SourceRange range) {
    if (find_node(name)) {
        problems_.push_back({"variable '" + name + "' declared twice", range});
        return false;
    }
    auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({std::move(name), true, ObId{}, type, range});
    node_handles_.push_back({true, shape_.add_value(type)});
    value_origin_.push_back({node, {}, std::nullopt});
    built_.reset();
    return true;
}

// The last step of `origin` (its attribute, else its last hom) from `from`; a node it makes
// remembers `origin`.
colimit::Node Query::follow(colimit::Node from, Origin origin) {
    bool is_attr = origin.attr.has_value();
    colimit::Node to =
        is_attr ? shape_.attr(from, *origin.attr) : shape_.hom(from, origin.homs.back());
    auto& origins = is_attr ? value_origin_ : part_origin_;
    if ((is_attr ? shape_.num_value_nodes() : shape_.num_part_nodes()) > origins.size()) {
        origins.push_back(std::move(origin));
        built_.reset();
    }
    return to;
}

std::optional<Query::Resolved> Query::resolve(const Term& t, SourceRange where) {
    SourceRange at = t.range.valid() ? t.range : where;
    if (t.is_literal()) {
        if (!t.literal.is_concrete()) {
            problems_.push_back({"a literal must be a concrete value", at});
            return std::nullopt;
        }
        return Resolved{std::nullopt, t.literal};
    }
    auto node = find_node(t.var);
    if (!node) {
        problems_.push_back({"unknown variable '" + t.var + "'", at});
        return std::nullopt;
    }
    const QueryNode& n = nodes_[*node];
    const schema::Schema& s = *source_;
    if (n.is_value) {
        if (!t.homs.empty() || t.attr) {
            problems_.push_back(
                {"'" + t.var + "' is a value: no hom or attribute applies to it", at});
            return std::nullopt;
        }
        return Resolved{node_handles_[*node], Value()};
    }
    colimit::Node cur = node_handles_[*node].node;
    ObId ob = n.ob;
    std::vector<HomId> prefix;
    auto var = static_cast<std::uint32_t>(*node);
    for (HomId h : t.homs) {
        if (s.hom(h).dom != ob) {
            problems_.push_back({"hom '" + s.hom(h).name + "' does not start at '" + s.ob(ob).name +
                                     "' (it goes from '" + s.ob(s.hom(h).dom).name + "')",
                                 at});
            return std::nullopt;
        }
        prefix.push_back(h);
        ob = s.hom(h).codom;
        cur = follow(cur, {var, prefix, std::nullopt});
    }
    if (t.attr) {
        if (s.attr(*t.attr).dom != ob) {
            problems_.push_back({"attribute '" + s.attr(*t.attr).name + "' does not start at '" +
                                     s.ob(ob).name + "'",
                                 at});
            return std::nullopt;
        }
        return Resolved{Handle{true, follow(cur, {var, prefix, t.attr})}, Value()};
    }
    return Resolved{Handle{false, cur}, Value()};
}

std::optional<std::uint32_t> Query::add_term(const Term& term) {
    auto r = resolve(term, term.range);
    if (!r) {
        return std::nullopt;
    }
    if (!r->handle) {
        problems_.push_back({"a bare literal has no place in the query", term.range});
        return std::nullopt;
    }
    handles_.push_back(*r->handle);
    return static_cast<std::uint32_t>(handles_.size() - 1);
}

// The presentation's new problems (two literals that met), in the query's words.
void Query::take_problems() {
    const auto& found = shape_.problems();
    for (; problems_taken_ < found.size(); ++problems_taken_) {
        const auto& p = found[problems_taken_];
        problems_.push_back({"two different literals for one value: " + p.first.to_string() +
                                 " and " + p.second.to_string(),
                             p.where});
    }
}

bool Query::add_equation(const Term& lhs, const Term& rhs, SourceRange range) {
    std::size_t before = problems_.size();
    auto a = resolve(lhs, range);
    auto b = resolve(rhs, range);
    if (!a || !b) {
        return false;
    }
    // A side's sort: an object or attribute type, or none for a literal.
    auto sort_name = [&](const Resolved& r) -> std::string {
        if (!r.handle) {
            return "a literal";
        }
        return r.handle->is_value
                   ? "'" + source_->attr_type(shape_.value_type(r.handle->node)).name + "'"
                   : "'" + source_->ob(shape_.part_ob(r.handle->node)).name + "'";
    };
    bool compatible = a->handle || b->handle;
    if (a->handle && b->handle) {
        const Handle &ha = *a->handle, &hb = *b->handle;
        compatible = ha.is_value == hb.is_value &&
                     (ha.is_value ? shape_.value_type(ha.node) == shape_.value_type(hb.node)
                                  : shape_.part_ob(ha.node) == shape_.part_ob(hb.node));
    } else if (compatible) {
        // A literal must fix a value, of its kind when that kind is known.
        const Handle& typed = a->handle ? *a->handle : *b->handle;
        const Value& lit = a->handle ? b->literal : a->literal;
        compatible = typed.is_value;
        auto kind = compatible ? source_->attr_type(shape_.value_type(typed.node)).kind
                               : schema::ValueKind::Unknown;
        if (compatible && kind != schema::ValueKind::Unknown && lit.kind() != kind) {
            problems_.push_back(
                {"literal " + lit.to_string() + " is not a " + std::string(schema::to_string(kind)),
                 rhs.range.valid() ? rhs.range : range});
            return false;
        }
    }
    if (!compatible) {
        problems_.push_back(
            {"the two sides have different types: " + sort_name(*a) + " and " + sort_name(*b),
             range});
        return false;
    }
    ++num_equations_;
    if (!a->handle || !b->handle) {
        const Handle& typed = a->handle ? *a->handle : *b->handle;
        shape_.set_literal(typed.node, a->handle ? b->literal : a->literal, {}, range);
    } else if (a->handle->is_value) {
        shape_.equate_values(a->handle->node, b->handle->node, range);
    } else {
        shape_.equate_parts(a->handle->node, b->handle->node, range);
    }
    built_.reset();
    take_problems();
    return problems_.size() == before;
}

void Query::build() const {
    if (built_) {
        return;
    }
    const schema::Schema& s = *source_;
    built_ = shape_.build();
    reps_.assign(s.num_obs(), {});
    vreps_.assign(s.num_attr_types(), {});
    for (colimit::Node n = 0; n < shape_.num_part_nodes(); ++n) {
        if (shape_.find_part(n) == n) {
            reps_[shape_.part_ob(n).index()].push_back(n);
        }
    }
    for (colimit::Node v = 0; v < shape_.num_value_nodes(); ++v) {
        if (shape_.find_value(v) == v && !shape_.literal(v)) {
            vreps_[shape_.value_type(v).index()].push_back(v);
        }
    }
}

const ACSet& Query::state() const {
    build();
    return built_->state;
}

QueryElement Query::locate(const Handle& h) const {
    build();
    QueryElement out;
    out.is_value = h.is_value;
    if (h.is_value) {
        out.type = shape_.value_type(h.node);
        out.value = built_->value_of[h.node];
    } else {
        out.ob = shape_.part_ob(h.node);
        out.part = built_->part_of[h.node];
    }
    return out;
}

QueryElement Query::locate(std::uint32_t handle) const {
    return locate(handles_[handle]);
}

QueryElement Query::locate_node(std::size_t i) const {
    return locate(node_handles_[i]);
}

Term Query::witness(ObId ob, Part p) const {
    build();
    // The first node of a class is the one first reached, so its origin is the shortest path.
    const Origin& o = part_origin_[reps_[ob.index()][p]];
    return Term::path(nodes_[o.node].name, o.homs);
}

Term Query::witness_value(AttrTypeId t, const Value& v) const {
    build();
    if (!v.is_var()) {
        return Term::constant(v);
    }
    const Origin& o = value_origin_[vreps_[t.index()][v.var_index()]];
    return Term::path(nodes_[o.node].name, o.homs, o.attr);
}

bool Query::is_plain() const {
    return !empty_ && nodes_.size() == 1 && !nodes_[0].is_value &&
           shape_.num_part_nodes() + shape_.num_value_nodes() == 1 && num_equations_ == 0;
}

} // namespace catplan::migrate
