#include "catplan/migrate/query.hpp"

#include "catplan/base/assert.hpp"

#include <algorithm>
#include <map>
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

Query::Query(SchemaPtr source) : source_(std::move(source)) {}

Query Query::representable(SchemaPtr source, ObId ob, std::string name) {
    Query q(std::move(source));
    q.add_variable(std::move(name), ob);
    return q;
}

std::optional<std::size_t> Query::find_node(std::string_view name) const {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        if (nodes_[i].name == name) {
            return i;
        }
    }
    return std::nullopt;
}

std::uint32_t Query::new_elem(Elem e) {
    auto id = uf_.make_set();
    literal_.push_back(e.literal);
    elems_.push_back(std::move(e));
    built_ = false;
    return id;
}

bool Query::add_variable(std::string name, ObId ob, SourceRange range) {
    if (find_node(name)) {
        problems_.push_back({"variable '" + name + "' declared twice", range});
        return false;
    }
    auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({std::move(name), false, ob, AttrTypeId{}, range});
    node_elems_.push_back(new_elem({false, ob.index(), node, {}, std::nullopt, std::nullopt}));
    return true;
}

bool Query::add_value_variable(std::string name, AttrTypeId type, SourceRange range) {
    if (find_node(name)) {
        problems_.push_back({"variable '" + name + "' declared twice", range});
        return false;
    }
    auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({std::move(name), true, ObId{}, type, range});
    node_elems_.push_back(new_elem({true, type.index(), node, {}, std::nullopt, std::nullopt}));
    return true;
}

std::uint32_t Query::follow(std::uint32_t from, std::uint32_t label, bool is_attr, Elem proto) {
    std::uint32_t root = uf_.find(from);
    for (const Edge& e : edges_) {
        if (e.label == label && e.is_attr == is_attr && uf_.find(e.src) == root) {
            return e.tgt;
        }
    }
    std::uint32_t t = new_elem(std::move(proto));
    edges_.push_back({from, label, is_attr, t});
    return t;
}

std::optional<std::uint32_t> Query::resolve(const Term& t, SourceRange where) {
    SourceRange at = t.range.valid() ? t.range : where;
    if (t.is_literal()) {
        if (!t.literal.is_concrete()) {
            problems_.push_back({"a literal must be a concrete value", at});
            return std::nullopt;
        }
        return new_elem({true, UINT32_MAX, UINT32_MAX, {}, std::nullopt, t.literal});
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
        return node_elems_[*node];
    }
    std::uint32_t cur = node_elems_[*node];
    ObId ob = n.ob;
    std::vector<HomId> prefix;
    for (HomId h : t.homs) {
        if (s.hom(h).dom != ob) {
            problems_.push_back({"hom '" + s.hom(h).name + "' does not start at '" + s.ob(ob).name +
                                     "' (it goes from '" + s.ob(s.hom(h).dom).name + "')",
                                 at});
            return std::nullopt;
        }
        prefix.push_back(h);
        ob = s.hom(h).codom;
        cur = follow(cur, h.index(), false,
                     {false, ob.index(), static_cast<std::uint32_t>(*node), prefix, std::nullopt,
                      std::nullopt});
    }
    if (t.attr) {
        if (s.attr(*t.attr).dom != ob) {
            problems_.push_back({"attribute '" + s.attr(*t.attr).name + "' does not start at '" +
                                     s.ob(ob).name + "'",
                                 at});
            return std::nullopt;
        }
        cur = follow(cur, t.attr->index(), true,
                     {true, s.attr(*t.attr).codom.index(), static_cast<std::uint32_t>(*node),
                      prefix, t.attr, std::nullopt});
    }
    return cur;
}

std::optional<std::uint32_t> Query::add_term(const Term& term) {
    auto r = resolve(term, term.range);
    if (r) {
        if (elems_[*r].sort == UINT32_MAX) {
            problems_.push_back({"a bare literal has no place in the query", term.range});
            return std::nullopt;
        }
        close(term.range);
    }
    return r;
}

bool Query::merge(std::uint32_t a, std::uint32_t b, SourceRange where) {
    a = uf_.find(a);
    b = uf_.find(b);
    if (a == b) {
        return true;
    }
    auto& la = literal_[a];
    auto& lb = literal_[b];
    bool ok = true;
    std::optional<Value> lit = la ? la : lb;
    if (la && lb && !(*la == *lb)) {
        problems_.push_back(
            {"two different literals for one value: " + la->to_string() + " and " + lb->to_string(),
             where});
        ok = false;
    }
    uf_.union_sets(a, b);
    literal_[uf_.find(a)] = lit;
    built_ = false;
    return ok;
}

void Query::close(SourceRange where) {
    // Congruence closure: two edges with the same label out of one class reach one class.
    bool changed = true;
    while (changed) {
        changed = false;
        std::map<std::tuple<std::uint32_t, std::uint32_t, bool>, std::uint32_t> seen;
        for (const Edge& e : edges_) {
            auto key = std::make_tuple(uf_.find(e.src), e.label, e.is_attr);
            auto [it, fresh] = seen.emplace(key, e.tgt);
            if (!fresh && uf_.find(it->second) != uf_.find(e.tgt)) {
                merge(it->second, e.tgt, where);
                changed = true;
            }
        }
    }
}

bool Query::add_equation(const Term& lhs, const Term& rhs, SourceRange range) {
    std::size_t before = problems_.size();
    auto a = resolve(lhs, range);
    auto b = resolve(rhs, range);
    if (!a || !b) {
        return false;
    }
    const Elem& ea = elems_[*a];
    const Elem& eb = elems_[*b];
    auto sort_name = [&](const Elem& e) -> std::string {
        if (e.sort == UINT32_MAX) {
            return "a literal";
        }
        return e.is_value ? "'" + source_->attr_type(AttrTypeId(e.sort)).name + "'"
                          : "'" + source_->ob(ObId(e.sort)).name + "'";
    };
    bool compatible = ea.is_value == eb.is_value &&
                      (ea.sort == eb.sort || ea.sort == UINT32_MAX || eb.sort == UINT32_MAX);
    if (ea.sort == UINT32_MAX && eb.sort == UINT32_MAX) {
        compatible = false;
    }
    if (compatible && (ea.sort == UINT32_MAX || eb.sort == UINT32_MAX)) {
        // A literal must have the kind of the value it fixes, when that kind is known.
        const Elem& typed = ea.sort == UINT32_MAX ? eb : ea;
        const Value& lit = ea.sort == UINT32_MAX ? *ea.literal : *eb.literal;
        auto kind = source_->attr_type(AttrTypeId(typed.sort)).kind;
        if (kind != schema::ValueKind::Unknown && lit.kind() != kind) {
            problems_.push_back(
                {"literal " + lit.to_string() + " is not a " + std::string(schema::to_string(kind)),
                 rhs.range.valid() ? rhs.range : range});
            return false;
        }
    }
    if (!compatible) {
        problems_.push_back(
            {"the two sides have different types: " + sort_name(ea) + " and " + sort_name(eb),
             range});
        return false;
    }
    ++num_equations_;
    merge(*a, *b, range);
    close(range);
    return problems_.size() == before;
}

void Query::build() const {
    if (built_) {
        return;
    }
    const schema::Schema& s = *source_;
    ACSet st(source_);
    elem_slot_.assign(elems_.size(), UINT32_MAX);
    reps_.assign(s.num_obs(), {});
    vreps_.assign(s.num_attr_types(), {});
    // Classes in order of their smallest element (the root): nodes come first, in order.
    for (std::uint32_t e = 0; e < elems_.size(); ++e) {
        if (uf_.find(e) != e) {
            continue;
        }
        // A class's sort: a literal element alone has none; take any typed member.
        std::uint32_t sort = UINT32_MAX;
        bool is_value = elems_[e].is_value;
        for (std::uint32_t m = e; m < elems_.size(); ++m) {
            if (uf_.find(m) == e && elems_[m].sort != UINT32_MAX) {
                sort = elems_[m].sort;
                is_value = elems_[m].is_value;
                break;
            }
        }
        if (sort == UINT32_MAX) {
            continue; // a literal that nothing else refers to
        }
        if (!is_value) {
            elem_slot_[e] = st.add_part(ObId(sort));
            reps_[sort].push_back(e);
        } else if (!literal_[e]) {
            elem_slot_[e] = st.add_var(AttrTypeId(sort)).var_index();
            vreps_[sort].push_back(e);
        }
    }
    for (const Edge& ed : edges_) {
        std::uint32_t src = uf_.find(ed.src), tgt = uf_.find(ed.tgt);
        Part p = elem_slot_[src];
        if (ed.is_attr) {
            Value v = literal_[tgt] ? *literal_[tgt] : Value::var(elem_slot_[tgt]);
            st.set_subpart(AttrId(ed.label), p, v);
        } else {
            st.set_subpart(HomId(ed.label), p, elem_slot_[tgt]);
        }
    }
    state_.emplace(std::move(st));
    built_ = true;
}

const ACSet& Query::state() const {
    build();
    return *state_;
}

QueryElement Query::locate(std::uint32_t handle) const {
    build();
    std::uint32_t r = uf_.find(handle);
    QueryElement out;
    // The class's sort may come from a member other than the handle (a literal joined a value).
    std::uint32_t sort = elems_[handle].sort;
    bool is_value = elems_[handle].is_value;
    if (sort == UINT32_MAX) {
        for (std::uint32_t m = 0; m < elems_.size(); ++m) {
            if (uf_.find(m) == r && elems_[m].sort != UINT32_MAX) {
                sort = elems_[m].sort;
                is_value = elems_[m].is_value;
                break;
            }
        }
    }
    out.is_value = is_value;
    if (!is_value) {
        out.ob = ObId(sort);
        out.part = elem_slot_[r];
    } else {
        out.type = AttrTypeId(sort);
        out.value = literal_[r] ? *literal_[r] : Value::var(elem_slot_[r]);
    }
    return out;
}

Term Query::witness(ObId ob, Part p) const {
    build();
    std::uint32_t r = reps_[ob.index()][p];
    // The smallest member reached from a node (the root itself unless it is a literal).
    for (std::uint32_t m = r; m < elems_.size(); ++m) {
        if (uf_.find(m) == r && elems_[m].node != UINT32_MAX) {
            return Term::path(nodes_[elems_[m].node].name, elems_[m].homs);
        }
    }
    CATPLAN_UNREACHABLE("a part of a query is reached from no node");
}

Term Query::witness_value(AttrTypeId t, const Value& v) const {
    build();
    if (!v.is_var()) {
        return Term::constant(v);
    }
    std::uint32_t r = vreps_[t.index()][v.var_index()];
    for (std::uint32_t m = r; m < elems_.size(); ++m) {
        if (uf_.find(m) == r && elems_[m].node != UINT32_MAX) {
            return Term::path(nodes_[elems_[m].node].name, elems_[m].homs, elems_[m].attr);
        }
    }
    CATPLAN_UNREACHABLE("a value of a query is reached from no node");
}

bool Query::is_plain() const {
    return !empty_ && nodes_.size() == 1 && !nodes_[0].is_value && elems_.size() == 1 &&
           num_equations_ == 0;
}

} // namespace catplan::migrate
