// The presentation engine of the language (detail/colimit.hpp): generators and equations closed
// under congruence into a free or partial state.

#include "catplan/lang/detail/colimit.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::lang::detail {

using acset::ACSet;
using acset::Value;
using schema::Schema;

Colimit::Colimit(const Schema& s, const InferredKinds* inferred) : s_(s), inferred_(inferred) {
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        auto homs = s.homs_from(ObId(o));
        for (std::uint32_t i = 0; i < homs.size(); ++i) {
            hom_slot_[homs[i].index()] = i;
        }
        auto attrs = s.attrs_from(ObId(o));
        for (std::uint32_t i = 0; i < attrs.size(); ++i) {
            attr_slot_[attrs[i].index()] = i;
        }
    }
}

std::uint32_t Colimit::new_part(ObId x, std::string name) {
    PartNode n{x, std::vector<std::uint32_t>(s_.homs_from(x).size(), kNone),
               std::vector<std::uint32_t>(s_.attrs_from(x).size(), kNone)};
    parts_.push_back(std::move(n));
    part_names_.push_back(std::move(name));
    return parts_uf_.make_set();
}

std::uint32_t Colimit::new_value(AttrTypeId t, std::string name) {
    values_.push_back({t, std::nullopt, {}});
    value_names_.push_back(std::move(name));
    return values_uf_.make_set();
}

void Colimit::declare(const Expr& st, DiagnosticSink& sink) {
    const Expr& type = st.args[1];
    auto names = declared_names(st.args[0], sink);
    std::optional<ObId> ob;
    std::optional<AttrTypeId> t;
    if (type.kind == Expr::Kind::Name) {
        ob = s_.find_ob(type.text);
        t = s_.find_attr_type(type.text);
    }
    if (!ob && !t) {
        sink.error(type.range, fmt::format("unknown object or attribute type '{}' in schema '{}'",
                                           to_string(type), s_.name()));
        return;
    }
    for (const Expr* n : names) {
        auto it = gens_.find(n->text);
        if (it != gens_.end() && allow_redeclare_) {
            // Rules: Keep's generators are declared again in Eff; same type, same part.
            const Term& old = it->second.term;
            bool same = ob ? old.kind == Term::Kind::Part && parts_[old.node].ob == *ob
                           : old.kind == Term::Kind::Value && values_[old.node].type == *t;
            if (same) {
                continue;
            }
        }
        if (it != gens_.end()) {
            auto& d = sink.error(n->range, fmt::format("duplicate generator '{}'", n->text));
            d.notes.emplace_back(it->second.range, "first declared here");
            continue;
        }
        Term term = ob ? Term{Term::Kind::Part, new_part(*ob, n->text), nullptr}
                       : Term{Term::Kind::Value, new_value(*t, n->text), nullptr};
        gens_.emplace(n->text, Gen{term, n->range});
        gen_order_.push_back(n->text);
    }
}

std::string Colimit::describe(const Term& t) {
    switch (t.kind) {
    case Term::Kind::Part:
        return fmt::format("a part of {}", s_.ob(parts_[t.node].ob).name);
    case Term::Kind::Value:
        return fmt::format("a value of {}", s_.attr_type(values_[t.node].type).name);
    case Term::Kind::Literal:
        return "a literal";
    }
    return "?";
}

std::optional<Term> Colimit::eval(const Expr& e, DiagnosticSink& sink) {
    if (is_literal(e)) {
        return Term{Term::Kind::Literal, 0, &e};
    }
    if (e.kind == Expr::Kind::Name) {
        auto it = gens_.find(e.text);
        if (it == gens_.end()) {
            sink.error(e.range, fmt::format("unknown generator '{}'", e.text));
            return std::nullopt;
        }
        Term t = it->second.term;
        t.node = t.kind == Term::Kind::Part ? parts_uf_.find(t.node) : values_uf_.find(t.node);
        return t;
    }
    if (e.kind != Expr::Kind::Call) {
        sink.error(e.range, fmt::format("expected a generator, a hom or attribute "
                                        "applied to a term, or a literal; found '{}'",
                                        to_string(e)));
        return std::nullopt;
    }
    auto hom = s_.find_hom(e.text);
    auto attr = s_.find_attr(e.text);
    if (!hom && !attr) {
        auto g = s_.find(e.text);
        sink.error(
            e.name_range,
            g ? fmt::format("'{}' is {}, not a hom or attribute", e.text, kind_noun(g->kind))
              : fmt::format("unknown hom or attribute '{}' in schema '{}'", e.text, s_.name()));
        return std::nullopt;
    }
    if (!check_arity(e, 1, sink)) {
        return std::nullopt;
    }
    auto arg = eval(e.args[0], sink);
    if (!arg) {
        return std::nullopt;
    }
    ObId dom = hom ? s_.hom(*hom).dom : s_.attr(*attr).dom;
    if (arg->kind != Term::Kind::Part || parts_[arg->node].ob != dom) {
        sink.error(e.args[0].range,
                   fmt::format("'{}' expects a part of {}, but '{}' is {}", e.text, s_.ob(dom).name,
                               to_string(e.args[0]), describe(*arg)));
        return std::nullopt;
    }
    std::uint32_t p = arg->node;
    if (hom) {
        std::uint32_t slot = hom_slot_[hom->index()];
        if (parts_[p].homs[slot] == kNone) {
            std::uint32_t q = new_part(s_.hom(*hom).codom, "");
            parts_[p].homs[slot] = q;
        }
        return Term{Term::Kind::Part, parts_uf_.find(parts_[p].homs[slot]), nullptr};
    }
    std::uint32_t slot = attr_slot_[attr->index()];
    if (parts_[p].attrs[slot] == kNone) {
        std::uint32_t v = new_value(s_.attr(*attr).codom, "");
        parts_[p].attrs[slot] = v;
    }
    return Term{Term::Kind::Value, values_uf_.find(parts_[p].attrs[slot]), nullptr};
}

void Colimit::equation(const Expr& st, DiagnosticSink& sink) {
    auto lhs = eval(st.args[0], sink);
    auto rhs = eval(st.args[1], sink);
    if (!lhs || !rhs) {
        return;
    }
    if (lhs->kind == Term::Kind::Literal) {
        std::swap(lhs, rhs);
    }
    if (lhs->kind == Term::Kind::Literal) {
        sink.error(st.range, "an equation between two literals says nothing about "
                             "the instance");
        return;
    }
    if (rhs->kind == Term::Kind::Literal) {
        if (lhs->kind != Term::Kind::Value) {
            sink.error(st.range, fmt::format("cannot equate {} with literal {}", describe(*lhs),
                                             to_string(*rhs->expr)));
            return;
        }
        auto v = literal_value(s_, values_[lhs->node].type, *rhs->expr, inferred_, sink);
        if (v) {
            set_literal(lhs->node, *v, rhs->expr->range, st.range, sink);
        }
        return;
    }
    bool same =
        lhs->kind == rhs->kind &&
        (lhs->kind == Term::Kind::Part ? parts_[lhs->node].ob == parts_[rhs->node].ob
                                       : values_[lhs->node].type == values_[rhs->node].type);
    if (!same) {
        sink.error(st.range,
                   fmt::format("cannot equate {} ('{}') with {} ('{}')", describe(*lhs),
                               to_string(st.args[0]), describe(*rhs), to_string(st.args[1])));
        return;
    }
    if (lhs->kind == Term::Kind::Part) {
        pending_parts_.emplace_back(lhs->node, rhs->node);
    } else {
        pending_values_.emplace_back(lhs->node, rhs->node);
    }
    close(st.range, sink);
}

void Colimit::set_literal(std::uint32_t v, Value value, SourceRange lit, SourceRange at,
                          DiagnosticSink& sink) {
    auto& node = values_[values_uf_.find(v)];
    if (node.literal) {
        if (!(*node.literal == value)) {
            auto& d = sink.error(at, fmt::format("conflicting values {} and {} for "
                                                 "one cell",
                                                 node.literal->to_string(), value.to_string()));
            d.notes.emplace_back(node.literal_range, "the first value is given here");
        }
        return;
    }
    node.literal = value;
    node.literal_range = lit;
}

// Congruence closure: merging parts merges their images under every hom and attribute.
void Colimit::close(SourceRange at, DiagnosticSink& sink) {
    while (!pending_parts_.empty() || !pending_values_.empty()) {
        if (!pending_values_.empty()) {
            auto [a, b] = pending_values_.back();
            pending_values_.pop_back();
            a = values_uf_.find(a);
            b = values_uf_.find(b);
            if (a == b) {
                continue;
            }
            values_uf_.union_sets(a, b);
            std::uint32_t r = std::min(a, b), o = std::max(a, b);
            if (values_[o].literal) {
                set_literal(r, *values_[o].literal, values_[o].literal_range, at, sink);
            }
            continue;
        }
        auto [a, b] = pending_parts_.back();
        pending_parts_.pop_back();
        a = parts_uf_.find(a);
        b = parts_uf_.find(b);
        if (a == b) {
            continue;
        }
        parts_uf_.union_sets(a, b);
        std::uint32_t r = std::min(a, b), o = std::max(a, b);
        for (std::size_t i = 0; i < parts_[r].homs.size(); ++i) {
            if (parts_[o].homs[i] == kNone) {
                continue;
            }
            if (parts_[r].homs[i] == kNone) {
                parts_[r].homs[i] = parts_[o].homs[i];
            } else {
                pending_parts_.emplace_back(parts_[r].homs[i], parts_[o].homs[i]);
            }
        }
        for (std::size_t i = 0; i < parts_[r].attrs.size(); ++i) {
            if (parts_[o].attrs[i] == kNone) {
                continue;
            }
            if (parts_[r].attrs[i] == kNone) {
                parts_[r].attrs[i] = parts_[o].attrs[i];
            } else {
                pending_values_.emplace_back(parts_[r].attrs[i], parts_[o].attrs[i]);
            }
        }
    }
}

bool Colimit::complete(SourceRange at, std::size_t max_fresh, DiagnosticSink& sink) {
    std::size_t fresh = 0;
    for (std::uint32_t p = 0; p < parts_.size(); ++p) {
        if (parts_uf_.find(p) != p) {
            continue;
        }
        ObId ob = parts_[p].ob;
        auto homs = s_.homs_from(ob);
        for (std::size_t i = 0; i < homs.size(); ++i) {
            if (parts_[p].homs[i] != kNone) {
                continue;
            }
            if (++fresh > max_fresh) {
                const auto& h = s_.hom(homs[i]);
                auto& d =
                    sink.error(at, fmt::format("the free instance is infinite or too large: hom "
                                               "'{}' keeps generating new parts of {} (stopped "
                                               "after {} new parts)",
                                               h.name, s_.ob(h.codom).name, max_fresh));
                if (h.range.valid()) {
                    d.notes.emplace_back(h.range, fmt::format("'{}' is declared here; "
                                                              "give its values with "
                                                              "equations",
                                                              h.name));
                }
                return false;
            }
            std::uint32_t q = new_part(s_.hom(homs[i]).codom, "");
            parts_[p].homs[i] = q;
        }
        auto attrs = s_.attrs_from(ob);
        for (std::size_t i = 0; i < attrs.size(); ++i) {
            if (parts_[p].attrs[i] == kNone) {
                std::uint32_t v = new_value(s_.attr(attrs[i]).codom, "");
                parts_[p].attrs[i] = v;
            }
        }
    }
    return true;
}

void Colimit::declare_value(const std::string& name, AttrTypeId t, SourceRange range) {
    Term term{Term::Kind::Value, new_value(t, name), nullptr};
    gens_.emplace(name, Gen{term, range});
    gen_order_.push_back(name);
}

std::optional<std::pair<Term, SourceRange>> Colimit::generator(const std::string& name) {
    auto it = gens_.find(name);
    if (it == gens_.end()) {
        return std::nullopt;
    }
    Term t = it->second.term;
    t.node = t.kind == Term::Kind::Part ? parts_uf_.find(t.node) : values_uf_.find(t.node);
    return std::make_pair(t, it->second.range);
}

ACSet Colimit::build_partial(std::shared_ptr<Schema> schema) {
    ACSet x(schema);
    std::vector<Part> part_of(parts_.size(), kNoPart);
    for (std::uint32_t p = 0; p < parts_.size(); ++p) {
        if (parts_uf_.find(p) == p) {
            part_of[p] = x.add_part(parts_[p].ob, part_names_[p]);
        }
    }
    std::vector<Value> value_of(values_.size());
    for (std::uint32_t v = 0; v < values_.size(); ++v) {
        if (values_uf_.find(v) == v) {
            value_of[v] = values_[v].literal ? *values_[v].literal
                                             : x.add_var(values_[v].type, value_names_[v]);
        }
    }
    for (std::uint32_t p = 0; p < parts_.size(); ++p) {
        if (parts_uf_.find(p) != p) {
            continue;
        }
        ObId ob = parts_[p].ob;
        auto homs = s_.homs_from(ob);
        for (std::size_t i = 0; i < homs.size(); ++i) {
            if (parts_[p].homs[i] != kNone) {
                x.set_subpart(homs[i], part_of[p], part_of[parts_uf_.find(parts_[p].homs[i])]);
            }
        }
        auto attrs = s_.attrs_from(ob);
        for (std::size_t i = 0; i < attrs.size(); ++i) {
            if (parts_[p].attrs[i] != kNone) {
                x.set_subpart(attrs[i], part_of[p], value_of[values_uf_.find(parts_[p].attrs[i])]);
            }
        }
    }
    built_parts_ = std::move(part_of);
    built_values_ = std::move(value_of);
    return x;
}

} // namespace catplan::lang::detail
