// Presentations by generators and equations (presentation.hpp): congruence closure with a
// union-find per sort of node, the images of a class kept at its first node.

#include "catplan/colimit/presentation.hpp"

#include "catplan/base/assert.hpp"

#include <fmt/format.h>
#include <utility>

namespace catplan::colimit {

Presentation::Presentation(schema::SchemaPtr schema) : schema_(std::move(schema)) {
    const auto& s = *schema_;
    slot_.assign(s.num_homs() + s.num_attrs(), 0);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        auto homs = s.homs_from(ObId(o));
        for (std::size_t i = 0; i < homs.size(); ++i) {
            slot_[homs[i].index()] = static_cast<std::uint32_t>(i);
        }
        auto attrs = s.attrs_from(ObId(o));
        for (std::size_t i = 0; i < attrs.size(); ++i) {
            slot_[s.num_homs() + attrs[i].index()] = static_cast<std::uint32_t>(i);
        }
    }
}

Node Presentation::new_part(ObId ob, std::string_view name, HomId needed_by) {
    if (limit_reached_) {
        return kNoNode;
    }
    if (parts_.size() >= max_parts_) {
        limit_reached_ = true;
        PresentationProblem p;
        p.kind = PresentationProblemKind::TooManyParts;
        p.hom = needed_by;
        p.message = fmt::format("the presented state has more than {} parts", max_parts_);
        problems_.push_back(std::move(p));
        return kNoNode;
    }
    const auto& s = *schema_;
    parts_.push_back({ob, std::vector<Node>(s.homs_from(ob).size(), kUnset),
                      std::vector<Node>(s.attrs_from(ob).size(), kUnset)});
    part_names_.emplace_back(name);
    return parts_uf_.make_set();
}

Node Presentation::add_part(ObId ob, std::string_view name) {
    return new_part(ob, name, HomId());
}

Node Presentation::add_value(AttrTypeId t, std::string_view name) {
    values_.push_back({t, std::nullopt, {}});
    value_names_.emplace_back(name);
    return values_uf_.make_set();
}

Node Presentation::hom(Node n, HomId h) {
    Node r = find_part(n);
    CATPLAN_ASSERT(parts_[r].ob == schema_->hom(h).dom, "hom: the node is not in its domain");
    Node& image = parts_[r].homs[slot_[h.index()]];
    if (image == kUnset) {
        Node q = new_part(schema_->hom(h).codom, {}, h);
        if (q == kNoNode) {
            return kNoNode;
        }
        parts_[r].homs[slot_[h.index()]] = q; // `image` may dangle: new_part grew parts_
        return q;
    }
    return find_part(image);
}

Node Presentation::attr(Node n, AttrId a) {
    Node r = find_part(n);
    CATPLAN_ASSERT(parts_[r].ob == schema_->attr(a).dom, "attr: the node is not in its domain");
    Node& image = parts_[r].attrs[slot_[schema_->num_homs() + a.index()]];
    if (image == kUnset) {
        image = add_value(schema_->attr(a).codom);
    }
    return find_value(image);
}

void Presentation::set_hom(Node n, HomId h, Node target, SourceRange where) {
    Node& image = parts_[find_part(n)].homs[slot_[h.index()]];
    if (image == kUnset) {
        image = target;
        return;
    }
    equate_parts(image, target, where);
}

void Presentation::set_attr(Node n, AttrId a, Node value, SourceRange where) {
    Node& image = parts_[find_part(n)].attrs[slot_[schema_->num_homs() + a.index()]];
    if (image == kUnset) {
        image = value;
        return;
    }
    pending_values_.push_back({image, value, a});
    close(where);
}

void Presentation::equate_parts(Node a, Node b, SourceRange where) {
    if (a == kNoNode || b == kNoNode) {
        return;
    }
    pending_parts_.emplace_back(a, b);
    close(where);
}

void Presentation::equate_values(Node a, Node b, SourceRange where) {
    pending_values_.push_back({a, b, AttrId()});
    close(where);
}

void Presentation::set_literal(Node v, Value literal, SourceRange range, SourceRange where) {
    give_literal(v, literal, range, where, AttrId());
}

void Presentation::give_literal(Node v, Value literal, SourceRange range, SourceRange where,
                                AttrId attr) {
    ValueNode& node = values_[find_value(v)];
    if (!node.literal) {
        node.literal = literal;
        node.literal_range = range;
        return;
    }
    if (*node.literal == literal) {
        return;
    }
    PresentationProblem p;
    p.first = *node.literal;
    p.second = literal;
    p.first_range = node.literal_range;
    p.where = where;
    p.attr = attr;
    p.message = fmt::format("two different literals {} and {} for one value",
                            node.literal->to_string(), literal.to_string());
    problems_.push_back(std::move(p));
}

// Identifies two classes of parts: the class of the larger first node joins the other, and
// their images under each hom and attribute are identified in turn (queued).
void Presentation::merge_parts(Node a, Node b) {
    a = find_part(a);
    b = find_part(b);
    if (a == b) {
        return;
    }
    parts_uf_.union_sets(a, b);
    Node r = std::min(a, b), o = std::max(a, b);
    for (std::size_t i = 0; i < parts_[r].homs.size(); ++i) {
        Node image = parts_[o].homs[i];
        if (image == kUnset) {
            continue;
        }
        if (parts_[r].homs[i] == kUnset) {
            parts_[r].homs[i] = image;
        } else {
            pending_parts_.emplace_back(parts_[r].homs[i], image);
        }
    }
    auto attrs = schema_->attrs_from(parts_[r].ob);
    for (std::size_t i = 0; i < parts_[r].attrs.size(); ++i) {
        Node image = parts_[o].attrs[i];
        if (image == kUnset) {
            continue;
        }
        if (parts_[r].attrs[i] == kUnset) {
            parts_[r].attrs[i] = image;
        } else {
            pending_values_.push_back({parts_[r].attrs[i], image, attrs[i]});
        }
    }
}

// Congruence closure of the queued identifications, values first.
void Presentation::close(SourceRange where) {
    while (!pending_parts_.empty() || !pending_values_.empty()) {
        if (!pending_values_.empty()) {
            auto [a, b, attr] = pending_values_.back();
            pending_values_.pop_back();
            a = find_value(a);
            b = find_value(b);
            if (a == b) {
                continue;
            }
            CATPLAN_ASSERT(values_[a].type == values_[b].type, "equated values of two types");
            values_uf_.union_sets(a, b);
            Node r = std::min(a, b), o = std::max(a, b);
            if (values_[o].literal) {
                give_literal(r, *values_[o].literal, values_[o].literal_range, where, attr);
            }
            continue;
        }
        auto [a, b] = pending_parts_.back();
        pending_parts_.pop_back();
        CATPLAN_ASSERT(parts_[a].ob == parts_[b].ob, "equated parts of two objects");
        merge_parts(a, b);
    }
}

Node Presentation::path(Node n, const std::vector<HomId>& homs) {
    for (HomId h : homs) {
        if (n == kNoNode) {
            return kNoNode;
        }
        n = hom(n, h);
    }
    return n;
}

// The schema's path equations at the class of n (an equation of attributes identifies values).
void Presentation::impose_equations(Node n) {
    for (const schema::Equation& eq : schema_->equations()) {
        if (eq.lhs.dom != parts_[n].ob) {
            continue;
        }
        Node l = path(n, eq.lhs.homs), r = path(n, eq.rhs.homs);
        if (limit_reached_) {
            return;
        }
        if (eq.lhs.attr && eq.rhs.attr) {
            equate_values(attr(l, *eq.lhs.attr), attr(r, *eq.rhs.attr));
        } else {
            equate_parts(l, r);
        }
    }
}

void Presentation::complete(bool equations) {
    // Classes made along the way are completed in their turn; identifying a new node with an old
    // one before its turn is what keeps the chase finite along cycles an equation cuts.
    for (Node n = 0; n < parts_.size() && !limit_reached_; ++n) {
        if (find_part(n) != n) {
            continue;
        }
        for (HomId h : schema_->homs_from(parts_[n].ob)) {
            if (hom(n, h) == kNoNode) {
                return;
            }
        }
        if (equations) {
            impose_equations(n);
        }
        if (find_part(n) != n || limit_reached_) {
            continue;
        }
        for (AttrId a : schema_->attrs_from(parts_[n].ob)) {
            (void)attr(n, a);
        }
    }
}

// Per node: the name of its class (the first named node's), at the class's first node.
std::vector<std::string_view> Presentation::class_names(bool values) const {
    const auto& names = values ? value_names_ : part_names_;
    std::vector<std::string_view> out(names.size());
    for (Node n = 0; n < names.size(); ++n) {
        Node r = values ? find_value(n) : find_part(n);
        if (out[r].empty() && !names[n].empty()) {
            out[r] = names[n];
        }
    }
    return out;
}

Presentation::Instance Presentation::build(VariableOrder order) const {
    const auto& s = *schema_;
    Instance out{ACSet(schema_), std::vector<Part>(parts_.size(), kNoPart),
                 std::vector<Value>(values_.size())};
    ACSet& x = out.state;
    auto part_names = class_names(false), value_names = class_names(true);
    for (Node n = 0; n < parts_.size(); ++n) {
        if (find_part(n) == n) {
            out.part_of[n] = x.add_part(parts_[n].ob, part_names[n]);
        }
    }
    auto value_of = [&](Node v) -> Value& {
        Node r = find_value(v);
        Value& slot = out.value_of[r];
        if (slot.is_unset()) {
            slot = values_[r].literal ? *values_[r].literal
                                      : x.add_var(values_[r].type, value_names[r]);
        }
        return slot;
    };
    if (order == VariableOrder::Nodes) {
        for (Node v = 0; v < values_.size(); ++v) {
            (void)value_of(v);
        }
    }
    for (Node n = 0; n < parts_.size(); ++n) {
        if (find_part(n) != n) {
            continue;
        }
        auto homs = s.homs_from(parts_[n].ob);
        for (std::size_t i = 0; i < homs.size(); ++i) {
            if (parts_[n].homs[i] != kUnset) {
                x.set_subpart(homs[i], out.part_of[n], out.part_of[find_part(parts_[n].homs[i])]);
            }
        }
        auto attrs = s.attrs_from(parts_[n].ob);
        for (std::size_t i = 0; i < attrs.size(); ++i) {
            if (parts_[n].attrs[i] != kUnset) {
                x.set_subpart(attrs[i], out.part_of[n], value_of(parts_[n].attrs[i]));
            }
        }
    }
    for (Node v = 0; v < values_.size(); ++v) {
        out.value_of[v] = value_of(v); // the values no cell holds, then every node's value
    }
    for (Node n = 0; n < parts_.size(); ++n) {
        out.part_of[n] = out.part_of[find_part(n)];
    }
    return out;
}

Result<Presentation::Instance> Presentation::instance(VariableOrder order) const {
    if (!problems_.empty()) {
        return fail(problems_.front().message);
    }
    return build(order);
}

} // namespace catplan::colimit
