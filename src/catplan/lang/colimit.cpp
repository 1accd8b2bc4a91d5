// The presentation engine of the language (detail/colimit.hpp): generators and equations closed
// under congruence into a free or partial state.

#include "catplan/lang/detail/colimit.hpp"

#include <fmt/format.h>
#include <map>

namespace catplan::lang::detail {

using acset::ACSet;
using acset::Value;
using schema::Schema;

Colimit::Colimit(std::shared_ptr<const Schema> s, const InferredKinds* inferred)
    : inferred_(inferred), p_(std::move(s)) {}

// A term with its node resolved to its class.
Term Colimit::resolved(Term t) const {
    if (t.kind != Term::Kind::Literal) {
        t.node = t.kind == Term::Kind::Part ? p_.find_part(t.node) : p_.find_value(t.node);
    }
    return t;
}

// Reports the literals that met since the last report (the presentation's problems).
void Colimit::report_problems(DiagnosticSink& sink) {
    const auto& problems = p_.problems();
    for (; problems_reported_ < problems.size(); ++problems_reported_) {
        const auto& p = problems[problems_reported_];
        if (p.kind != colimit::PresentationProblemKind::ConflictingLiterals) {
            continue;
        }
        auto& d = sink.error(p.where, fmt::format("conflicting values {} and {} for one cell",
                                                  p.first.to_string(), p.second.to_string()));
        d.notes.emplace_back(p.first_range, "the first value is given here");
    }
}

void Colimit::declare(const Expr& st, DiagnosticSink& sink) {
    const Schema& s = schema();
    const Expr& type = st.args[1];
    auto names = declared_names(st.args[0], sink);
    std::optional<ObId> ob;
    std::optional<AttrTypeId> t;
    if (type.kind == Expr::Kind::Name) {
        ob = s.find_ob(type.text);
        t = s.find_attr_type(type.text);
    }
    if (!ob && !t) {
        sink.error(type.range, fmt::format("unknown object or attribute type '{}' in schema '{}'",
                                           to_string(type), s.name()));
        return;
    }
    for (const Expr* n : names) {
        auto it = gens_.find(n->text);
        if (it != gens_.end() && allow_redeclare_) {
            // Rules: Keep's generators are declared again in Eff; same type, same part.
            const Term& old = it->second.term;
            bool same = ob ? old.kind == Term::Kind::Part && p_.part_ob(old.node) == *ob
                           : old.kind == Term::Kind::Value && p_.value_type(old.node) == *t;
            if (same) {
                continue;
            }
        }
        if (it != gens_.end()) {
            auto& d = sink.error(n->range, fmt::format("duplicate generator '{}'", n->text));
            d.notes.emplace_back(it->second.range, "first declared here");
            continue;
        }
        Term term = ob ? Term{Term::Kind::Part, p_.add_part(*ob, n->text), nullptr}
                       : Term{Term::Kind::Value, p_.add_value(*t, n->text), nullptr};
        gens_.emplace(n->text, Gen{term, n->range});
        gen_order_.push_back(n->text);
    }
}

std::string Colimit::describe(const Term& t) {
    switch (t.kind) {
    case Term::Kind::Part:
        return fmt::format("a part of {}", schema().ob(p_.part_ob(t.node)).name);
    case Term::Kind::Value:
        return fmt::format("a value of {}", schema().attr_type(p_.value_type(t.node)).name);
    case Term::Kind::Literal:
        return "a literal";
    }
    return "?";
}

std::optional<Term> Colimit::eval(const Expr& e, DiagnosticSink& sink) {
    const Schema& s = schema();
    if (is_literal(e)) {
        return Term{Term::Kind::Literal, 0, &e};
    }
    if (e.kind == Expr::Kind::Name) {
        auto it = gens_.find(e.text);
        if (it == gens_.end()) {
            sink.error(e.range, fmt::format("unknown generator '{}'", e.text));
            return std::nullopt;
        }
        return resolved(it->second.term);
    }
    if (e.kind != Expr::Kind::Call) {
        sink.error(e.range, fmt::format("expected a generator, a hom or attribute "
                                        "applied to a term, or a literal; found '{}'",
                                        to_string(e)));
        return std::nullopt;
    }
    auto hom = s.find_hom(e.text);
    auto attr = s.find_attr(e.text);
    if (!hom && !attr) {
        auto g = s.find(e.text);
        sink.error(
            e.name_range,
            g ? fmt::format("'{}' is {}, not a hom or attribute", e.text, kind_noun(g->kind))
              : fmt::format("unknown hom or attribute '{}' in schema '{}'", e.text, s.name()));
        return std::nullopt;
    }
    if (!check_arity(e, 1, sink)) {
        return std::nullopt;
    }
    auto arg = eval(e.args[0], sink);
    if (!arg) {
        return std::nullopt;
    }
    ObId dom = hom ? s.hom(*hom).dom : s.attr(*attr).dom;
    if (arg->kind != Term::Kind::Part || p_.part_ob(arg->node) != dom) {
        sink.error(e.args[0].range,
                   fmt::format("'{}' expects a part of {}, but '{}' is {}", e.text, s.ob(dom).name,
                               to_string(e.args[0]), describe(*arg)));
        return std::nullopt;
    }
    if (hom) {
        return Term{Term::Kind::Part, p_.hom(arg->node, *hom), nullptr};
    }
    return Term{Term::Kind::Value, p_.attr(arg->node, *attr), nullptr};
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
        auto v = literal_value(schema(), p_.value_type(lhs->node), *rhs->expr, inferred_, sink);
        if (v) {
            p_.set_literal(lhs->node, *v, rhs->expr->range, st.range);
            report_problems(sink);
        }
        return;
    }
    bool same =
        lhs->kind == rhs->kind &&
        (lhs->kind == Term::Kind::Part ? p_.part_ob(lhs->node) == p_.part_ob(rhs->node)
                                       : p_.value_type(lhs->node) == p_.value_type(rhs->node));
    if (!same) {
        sink.error(st.range,
                   fmt::format("cannot equate {} ('{}') with {} ('{}')", describe(*lhs),
                               to_string(st.args[0]), describe(*rhs), to_string(st.args[1])));
        return;
    }
    if (lhs->kind == Term::Kind::Part) {
        p_.equate_parts(lhs->node, rhs->node, st.range);
    } else {
        p_.equate_values(lhs->node, rhs->node, st.range);
    }
    report_problems(sink);
}

bool Colimit::complete(SourceRange at, std::size_t max_fresh, DiagnosticSink& sink) {
    p_.set_max_parts(p_.num_part_nodes() + max_fresh);
    p_.complete(/*equations=*/false);
    if (!p_.limit_reached()) {
        return true;
    }
    const auto& h = schema().hom(p_.problems().back().hom);
    auto& d = sink.error(at, fmt::format("the free instance is infinite or too large: hom '{}' "
                                         "keeps generating new parts of {} (stopped after {} new "
                                         "parts)",
                                         h.name, schema().ob(h.codom).name, max_fresh));
    if (h.range.valid()) {
        d.notes.emplace_back(h.range, fmt::format("'{}' is declared here; give its values with "
                                                  "equations",
                                                  h.name));
    }
    problems_reported_ = p_.problems().size();
    return false;
}

void Colimit::declare_value(const std::string& name, AttrTypeId t, SourceRange range) {
    Term term{Term::Kind::Value, p_.add_value(t, name), nullptr};
    gens_.emplace(name, Gen{term, range});
    gen_order_.push_back(name);
}

std::optional<std::pair<Term, SourceRange>> Colimit::generator(const std::string& name) {
    auto it = gens_.find(name);
    if (it == gens_.end()) {
        return std::nullopt;
    }
    return std::make_pair(resolved(it->second.term), it->second.range);
}

Colimit::StateNodes Colimit::add_state(const ACSet& x, SourceRange range) {
    const Schema& s = schema();
    StateNodes nodes;
    nodes.parts.resize(s.num_obs());
    nodes.vars.resize(s.num_attr_types());
    // A name that two parts or variables share names neither (print_instance would write one
    // of them under a generated name).
    std::map<std::string, int> uses;
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < x.num_vars(AttrTypeId(t)); ++j) {
            ++uses[std::string(x.var_name(AttrTypeId(t), j))];
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            ++uses[std::string(x.part_name(ObId(o), p))];
        }
    }
    auto named = [&](std::string_view name, Term term) {
        std::string n(name);
        if (!n.empty() && uses[n] == 1 && gens_.emplace(n, Gen{term, range}).second) {
            gen_order_.push_back(n);
        }
    };
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < x.num_vars(AttrTypeId(t)); ++j) {
            auto v = p_.add_value(AttrTypeId(t), x.var_name(AttrTypeId(t), j));
            nodes.vars[t].push_back(v);
            named(x.var_name(AttrTypeId(t), j), Term{Term::Kind::Value, v, nullptr});
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            auto node = p_.add_part(ObId(o), x.part_name(ObId(o), p));
            nodes.parts[o].push_back(node);
            named(x.part_name(ObId(o), p), Term{Term::Kind::Part, node, nullptr});
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            std::uint32_t node = nodes.parts[o][p];
            for (HomId f : s.homs_from(ObId(o))) {
                if (Part q = x.subpart(f, p); q != kNoPart) {
                    p_.set_hom(node, f, nodes.parts[s.hom(f).codom.index()][q]);
                }
            }
            for (AttrId a : s.attrs_from(ObId(o))) {
                const Value& v = x.subpart(a, p);
                if (v.is_var()) {
                    p_.set_attr(node, a, nodes.vars[s.attr(a).codom.index()][v.var_index()]);
                } else if (!v.is_unset()) {
                    auto value = p_.add_value(s.attr(a).codom);
                    p_.set_literal(value, v);
                    p_.set_attr(node, a, value);
                }
            }
        }
    }
    return nodes;
}

ACSet Colimit::build_partial() {
    built_ = p_.build();
    return built_->state;
}

} // namespace catplan::lang::detail
