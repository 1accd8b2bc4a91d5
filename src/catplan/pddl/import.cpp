#include "catplan/pddl/import.hpp"

#include "catplan/schema/schema.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <set>
#include <unordered_map>

namespace catplan::pddl {

namespace {

using acset::ACSet;
using acset::Value;
using schema::Schema;

/// `base`, or `base_` ... when a generator already has that name.
std::string fresh_name(const Schema& s, std::string base) {
    while (s.find(base)) {
        base += "_";
    }
    return base;
}

/// The schema and the ids the importer needs to build states on it.
struct Vocabulary {
    std::shared_ptr<Schema> schema;
    std::unordered_map<std::string, ObId> type_ob;
    std::unordered_map<std::string, AttrId> type_name_attr;
    std::unordered_map<std::string, HomId> is_a; // child type -> hom to its parent
    std::unordered_map<std::string, ObId> pred_ob;
    std::unordered_map<std::string, std::vector<HomId>> pred_homs;
    const Domain* domain = nullptr;

    /// The type's ancestors, itself first, "object" last.
    std::vector<std::string> chain(const std::string& type) const {
        std::vector<std::string> out;
        for (const Type* t = domain->find_type(type); t != nullptr;
             t = t->parent.empty() ? nullptr : domain->find_type(t->parent)) {
            out.push_back(t->name);
        }
        return out;
    }
};

Vocabulary make_vocabulary(const Domain& d) {
    Vocabulary v;
    v.domain = &d;
    v.schema = std::make_shared<Schema>(d.name);
    Schema& s = *v.schema;
    for (const auto& t : d.types) {
        v.type_ob[t.name] = s.add_ob(t.name, t.range);
    }
    auto name_type = s.add_attr_type(fresh_name(s, "Name"), schema::ValueKind::String);
    for (const auto& t : d.types) {
        if (!t.parent.empty()) {
            v.is_a[t.name] = s.add_hom(fresh_name(s, t.name + "_is_" + t.parent), v.type_ob[t.name],
                                       v.type_ob[t.parent], t.range);
        }
    }
    for (const auto& t : d.types) {
        v.type_name_attr[t.name] =
            s.add_attr(fresh_name(s, t.name + "_name"), v.type_ob[t.name], name_type, t.range);
    }
    for (const auto& p : d.predicates) {
        ObId ob = s.add_ob(fresh_name(s, p.name), p.range);
        v.pred_ob[p.name] = ob;
        auto& homs = v.pred_homs[p.name];
        for (std::size_t i = 0; i < p.params.size(); ++i) {
            homs.push_back(s.add_hom(fresh_name(s, fmt::format("{}_{}", p.name, i + 1)), ob,
                                     v.type_ob.at(p.params[i].type), p.params[i].range));
        }
    }
    return v;
}

/// The parts of one PDDL object (or rule term) in a state: one per type of its chain.
using EntityParts = std::map<std::string, Part>;

/// Adds the parts of an object of `type` named `name`; `pinned` sets the name attribute.
EntityParts add_entity(const Vocabulary& v, ACSet& x, const std::string& type,
                       const std::string& name, bool pinned) {
    EntityParts parts;
    Part below = kNoPart;
    std::string below_type;
    for (const auto& t : v.chain(type)) {
        Part p = x.add_part(v.type_ob.at(t), name);
        if (pinned) {
            x.set_subpart(v.type_name_attr.at(t), p, Value::string(name));
        }
        if (below != kNoPart) {
            x.set_subpart(v.is_a.at(below_type), below, p);
        }
        parts[t] = p;
        below = p;
        below_type = t;
    }
    return parts;
}

/// A ground fact over entity indices (objects of a state, or terms of a rule).
struct Fact {
    std::string predicate;
    std::vector<std::size_t> args;
    auto operator<=>(const Fact&) const = default;
};

Part add_fact(const Vocabulary& v, ACSet& x, const Fact& f, const std::vector<EntityParts>& ents,
              std::string_view name) {
    Part p = x.add_part(v.pred_ob.at(f.predicate), name);
    const Predicate* pred = v.domain->find_predicate(f.predicate);
    for (std::size_t i = 0; i < f.args.size(); ++i) {
        x.set_subpart(v.pred_homs.at(f.predicate)[i], p, ents[f.args[i]].at(pred->params[i].type));
    }
    return p;
}

std::string fact_label(const Fact& f, const std::vector<std::string>& names) {
    std::string s = "(" + f.predicate;
    for (auto a : f.args) {
        s += " " + names[a];
    }
    return s + ")";
}

// ---- the variants of an action ----------------------------------------------------------------

/// A term of an action: a parameter or a constant it mentions.
struct ActionTerm {
    std::string name; // without `?`
    std::string type;
    bool constant = false;
};

class VariantBuilder {
public:
    VariantBuilder(const Vocabulary& v, const Action& a, DiagnosticSink& sink,
                   const ImportOptions& options)
        : v_(v), a_(a), sink_(sink), options_(options) {
        for (const auto& p : a.params) {
            terms_.push_back({p.name, p.type, false});
        }
        auto note_constant = [&](const Atom& atom) {
            for (const auto& t : atom.args) {
                if (!t.variable && index_of(t) == terms_.size()) {
                    for (const auto& c : v.domain->constants) {
                        if (c.name == t.name) {
                            terms_.push_back({c.name, c.type, true});
                        }
                    }
                }
            }
        };
        for (const auto& l : a.precondition) {
            note_constant(l.atom);
        }
        for (const auto& l : a.add) {
            note_constant(l);
        }
        for (const auto& l : a.del) {
            note_constant(l);
        }
    }

    /// Every variant, or nullopt (with an error) when there are too many.
    std::optional<ActionVariants> build() {
        ActionVariants out;
        out.action = a_.name;
        std::vector<std::size_t> block(terms_.size(), 0);
        if (!partitions(0, 0, block, out)) {
            return std::nullopt;
        }
        return out;
    }

private:
    std::size_t index_of(const Term& t) const {
        for (std::size_t i = 0; i < terms_.size(); ++i) {
            if (terms_[i].name == t.name && terms_[i].constant == !t.variable) {
                return i;
            }
        }
        return terms_.size();
    }

    /// Set partitions as restricted growth strings: block[i] <= max(block[0..i-1]) + 1.
    bool partitions(std::size_t i, std::size_t nblocks, std::vector<std::size_t>& block,
                    ActionVariants& out) {
        if (i == terms_.size()) {
            return variants_of(block, nblocks, out);
        }
        for (std::size_t b = 0; b <= nblocks; ++b) {
            block[i] = b;
            if (fits(i, block) && !partitions(i + 1, std::max(nblocks, b + 1), block, out)) {
                return false;
            }
        }
        return true;
    }

    /// Whether term i may join its block: types on a chain, at most one constant, a constant's
    /// type below every parameter's type, and the equality literals so far respected.
    bool fits(std::size_t i, const std::vector<std::size_t>& block) const {
        const Domain& d = *v_.domain;
        for (std::size_t j = 0; j < i; ++j) {
            if (block[j] != block[i]) {
                continue;
            }
            const auto &s = terms_[i], &t = terms_[j];
            if (s.constant && t.constant) {
                return false;
            }
            if ((s.constant && !d.is_subtype(s.type, t.type)) ||
                (t.constant && !d.is_subtype(t.type, s.type))) {
                return false;
            }
            if (!d.is_subtype(s.type, t.type) && !d.is_subtype(t.type, s.type)) {
                return false;
            }
        }
        for (const auto& l : a_.precondition) {
            if (l.atom.predicate != "=") {
                continue;
            }
            std::size_t x = index_of(l.atom.args[0]), y = index_of(l.atom.args[1]);
            if (x <= i && y <= i && (block[x] == block[y]) != l.positive) {
                return false;
            }
        }
        return true;
    }

    Fact fact(const Atom& atom, const std::vector<std::size_t>& block) const {
        Fact f{atom.predicate, {}};
        for (const auto& t : atom.args) {
            f.args.push_back(block[index_of(t)]);
        }
        return f;
    }

    /// The rules of one partition: one per present/absent choice of the open facts.
    bool variants_of(const std::vector<std::size_t>& block, std::size_t nblocks,
                     ActionVariants& out) {
        std::set<Fact> pos, neg, add, del;
        for (const auto& l : a_.precondition) {
            if (l.atom.predicate != "=") {
                (l.positive ? pos : neg).insert(fact(l.atom, block));
            }
        }
        for (const auto& f : pos) {
            if (neg.count(f) != 0) {
                return true; // contradictory precondition under this identification
            }
        }
        for (const auto& at : a_.add) {
            add.insert(fact(at, block));
        }
        for (const auto& at : a_.del) {
            del.insert(fact(at, block));
        }
        std::vector<Fact> open;
        for (const auto* s : {&add, &del}) {
            for (const auto& f : *s) {
                if (pos.count(f) == 0 && neg.count(f) == 0 &&
                    std::find(open.begin(), open.end(), f) == open.end()) {
                    open.push_back(f);
                }
            }
        }
        if (open.size() > 20 ||
            out.variants.size() + (std::size_t{1} << open.size()) > options_.max_variants) {
            sink_.error(a_.range, fmt::format("the action '{}' needs more than {} rules (one per "
                                              "identification of parameters and per open fact)",
                                              a_.name, options_.max_variants));
            return false;
        }
        for (std::size_t mask = 0; mask < (std::size_t{1} << open.size()); ++mask) {
            std::set<Fact> present = pos, absent = neg;
            for (std::size_t k = 0; k < open.size(); ++k) {
                ((mask >> k) & 1 ? absent : present).insert(open[k]);
            }
            out.variants.push_back(
                make_variant(block, nblocks, present, absent, add, del, out.variants.size()));
        }
        return true;
    }

    Variant make_variant(const std::vector<std::size_t>& block, std::size_t nblocks,
                         const std::set<Fact>& present, const std::set<Fact>& absent,
                         const std::set<Fact>& add, const std::set<Fact>& del,
                         std::size_t index) const {
        // One entity per block: its names joined by '=', its type the most specific, pinned
        // when it holds a constant.
        std::vector<ActionTerm> reps(nblocks);
        std::vector<bool> seen(nblocks, false);
        for (std::size_t i = 0; i < terms_.size(); ++i) {
            auto& r = reps[block[i]];
            const auto& t = terms_[i];
            if (!seen[block[i]]) {
                r = t;
                seen[block[i]] = true;
                continue;
            }
            if (t.constant) {
                r.constant = true;
                r.name = t.name;
                r.type = t.type;
            } else if (!r.constant) {
                r.name += "=" + t.name;
                if (v_.domain->is_subtype(t.type, r.type)) {
                    r.type = t.type;
                }
            }
        }
        auto rule = std::make_shared<rewrite::Rule>(v_.schema);
        rule->name = index == 0 ? a_.name : fmt::format("{}~{}", a_.name, index + 1);
        rule->range = a_.range;
        std::vector<EntityParts> ents;
        std::vector<std::string> names;
        for (const auto& r : reps) {
            ents.push_back(add_entity(v_, rule->K, r.type, r.name, r.constant));
            names.push_back(r.name);
        }
        // K: the entities and the present facts that stay true; L adds the deleted ones, R the
        // created ones. Parts are appended to copies of K, so l and r are inclusions.
        std::vector<Fact> deleted, created;
        for (const auto& f : present) {
            bool stays = add.count(f) != 0 || del.count(f) == 0;
            if (stays) {
                add_fact(v_, rule->K, f, ents, fact_label(f, names));
            } else {
                deleted.push_back(f);
            }
        }
        for (const auto& f : absent) {
            if (add.count(f) != 0) {
                created.push_back(f);
            }
        }
        rule->L = rule->K;
        rule->R = rule->K;
        for (const auto& f : deleted) {
            add_fact(v_, rule->L, f, ents, fact_label(f, names));
        }
        for (const auto& f : created) {
            add_fact(v_, rule->R, f, ents, fact_label(f, names));
        }
        rule->l = inclusion(rule->K, rule->L);
        rule->r = inclusion(rule->K, rule->R);
        for (const auto& f : absent) {
            rewrite::ApplicationCondition nac{"not " + fact_label(f, names), true, rule->L, {}, {}};
            add_fact(v_, nac.n_state, f, ents, fact_label(f, names));
            nac.n = inclusion(rule->L, nac.n_state);
            nac.range = a_.range;
            rule->conditions.push_back(std::move(nac));
        }
        rule->exprs.resize(v_.schema->num_attr_types());
        Variant out;
        std::vector<int> param_index(nblocks, -1);
        for (std::size_t i = 0; i < a_.params.size(); ++i) {
            std::size_t b = block[i];
            if (reps[b].constant) {
                out.param_of.push_back(-1);
                out.constant_of.push_back(reps[b].name);
                continue;
            }
            if (param_index[b] < 0) {
                param_index[b] = static_cast<int>(rule->parameters.size());
                ObId ob = v_.type_ob.at(reps[b].type);
                rule->parameters.push_back({reps[b].name, ob, ents[b].at(reps[b].type)});
            }
            out.param_of.push_back(param_index[b]);
            out.constant_of.emplace_back();
        }
        out.rule = std::move(rule);
        return out;
    }

    /// The morphism sending each part of a (a prefix of b's parts, object by object) to itself.
    static hom::ACSetMorphism inclusion(const ACSet& a, const ACSet& b) {
        hom::ACSetMorphism m;
        const Schema& s = a.schema();
        m.components.resize(s.num_obs());
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Part p = 0; p < a.num_parts(ObId(o)); ++p) {
                m.components[o].push_back(p);
            }
            CATPLAN_ASSERT(a.num_parts(ObId(o)) <= b.num_parts(ObId(o)), "not a prefix");
        }
        m.var_components.resize(s.num_attr_types());
        return m;
    }

    const Vocabulary& v_;
    const Action& a_;
    DiagnosticSink& sink_;
    const ImportOptions& options_;
    std::vector<ActionTerm> terms_;
};

// ---- problems ---------------------------------------------------------------------------------

/// A state holding every object of `objects` and the given facts (each once).
std::shared_ptr<ACSet> make_state(const Vocabulary& v, const std::vector<TypedName>& objects,
                                  const std::vector<Atom>& atoms) {
    auto x = std::make_shared<ACSet>(v.schema);
    std::vector<EntityParts> ents;
    std::vector<std::string> names;
    std::unordered_map<std::string, std::size_t> index;
    for (const auto& o : objects) {
        index[o.name] = ents.size();
        ents.push_back(add_entity(v, *x, o.type, o.name, true));
        names.push_back(o.name);
    }
    std::set<Fact> facts;
    for (const auto& a : atoms) {
        Fact f{a.predicate, {}};
        for (const auto& t : a.args) {
            f.args.push_back(index.at(t.name));
        }
        if (facts.insert(f).second) {
            add_fact(v, *x, f, ents, "");
        }
    }
    return x;
}

/// The objects an atom list mentions, in order of first mention, with their types.
std::vector<TypedName> mentioned(const Domain& d, const Problem& p,
                                 const std::vector<Atom>& atoms) {
    std::vector<TypedName> out;
    for (const auto& a : atoms) {
        for (const auto& t : a.args) {
            bool known = std::any_of(out.begin(), out.end(),
                                     [&](const TypedName& o) { return o.name == t.name; });
            if (!known) {
                out.push_back(*find_object(d, p, t.name));
            }
        }
    }
    return out;
}

} // namespace

const ActionVariants* Import::find_action(std::string_view name) const {
    for (const auto& a : actions) {
        if (a.action == name) {
            return &a;
        }
    }
    return nullptr;
}

std::optional<std::pair<const ActionVariants*, const Variant*>>
Import::find_rule(std::string_view rule_name) const {
    for (const auto& a : actions) {
        for (const auto& v : a.variants) {
            if (v.rule->name == rule_name) {
                return std::pair{&a, &v};
            }
        }
    }
    return std::nullopt;
}

std::optional<Import> import_pddl(const Domain& domain, const Problem* problem,
                                  DiagnosticSink& sink, const ImportOptions& options) {
    Import out;
    out.pddl_domain = domain;
    Vocabulary v = make_vocabulary(out.pddl_domain);
    auto d = std::make_shared<plan::Domain>();
    d->name = domain.name;
    d->schema = v.schema;
    d->range = domain.range;
    for (const auto& a : out.pddl_domain.actions) {
        auto variants = VariantBuilder(v, a, sink, options).build();
        if (!variants) {
            return std::nullopt;
        }
        for (const auto& var : variants->variants) {
            d->rules.push_back(var.rule);
        }
        out.actions.push_back(std::move(*variants));
    }
    out.domain = d;
    out.type_ob = v.type_ob;
    out.predicate_ob = v.pred_ob;
    out.predicate_homs = v.pred_homs;
    if (problem == nullptr) {
        return out;
    }
    out.pddl_problem = *problem;
    std::vector<TypedName> objects = domain.constants;
    objects.insert(objects.end(), problem->objects.begin(), problem->objects.end());
    std::vector<Atom> goal_atoms;
    for (const auto& l : problem->goal) {
        goal_atoms.push_back(l.atom);
    }
    auto p = std::make_shared<plan::Problem>();
    p->name = problem->name;
    p->domain = d;
    p->initial = make_state(v, objects, problem->init);
    p->goal = make_state(v, mentioned(domain, *problem, goal_atoms), goal_atoms);
    p->range = problem->range;
    out.problem = p;
    return out;
}

} // namespace catplan::pddl
