#include "catplan/pddl/import.hpp"

#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/actions.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/schema/schema.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <unordered_map>
#include <unordered_set>

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

/// The types an object of all of `types` is of: each of them and every ancestor, in the domain's
/// order (parents first).
std::vector<std::string> ancestors(const Domain& d, const std::vector<std::string>& types) {
    std::vector<std::string> out;
    for (const auto& t : d.types) {
        if (std::any_of(types.begin(), types.end(),
                        [&](const std::string& u) { return d.is_subtype(u, t.name); })) {
            out.push_back(t.name);
        }
    }
    return out;
}

/// The name of a type's schema object: the type's, or `either_a_b` for `(either a b)`.
std::string ob_name(const std::string& type) {
    if (type.empty() || type[0] != '(') {
        return type;
    }
    std::string out = type.substr(1, type.size() - 2);
    std::replace(out.begin(), out.end(), ' ', '_');
    return out;
}

/// The schema of im.pddl_domain, with the ids the importer needs in im.
void make_vocabulary(Import& im) {
    const Domain& d = im.pddl_domain;
    auto schema = std::make_shared<Schema>(d.name);
    Schema& s = *schema;
    for (const auto& t : d.types) {
        im.type_ob[t.name] = s.add_ob(fresh_name(s, ob_name(t.name)), t.range);
    }
    im.name_type = s.add_attr_type(fresh_name(s, "Name"), schema::ValueKind::String);
    for (const auto& t : d.types) {
        for (const auto& parent : t.parents) {
            im.is_a[t.name].push_back(
                s.add_hom(fresh_name(s, ob_name(t.name) + "_is_" + ob_name(parent)),
                          im.type_ob[t.name], im.type_ob[parent], t.range));
        }
    }
    for (const auto& t : d.types) {
        im.name_attr[t.name] = s.add_attr(fresh_name(s, ob_name(t.name) + "_name"),
                                          im.type_ob[t.name], im.name_type, t.range);
    }
    for (const auto& p : d.predicates) {
        ObId ob = s.add_ob(fresh_name(s, p.name), p.range);
        im.predicate_ob[p.name] = ob;
        auto& homs = im.predicate_homs[p.name];
        for (std::size_t i = 0; i < p.params.size(); ++i) {
            homs.push_back(s.add_hom(fresh_name(s, fmt::format("{}_{}", p.name, i + 1)), ob,
                                     im.type_ob.at(p.params[i].type), p.params[i].range));
        }
    }
    auto domain = std::make_shared<plan::Domain>();
    domain->name = d.name;
    domain->schema = std::move(schema);
    domain->range = d.range;
    im.domain = std::move(domain);
}

/// The parts of one PDDL object (or rule term) in a state: one per type it is of.
using EntityParts = std::map<std::string, Part>;

/// Adds the parts of an object of the types `kinds` (every type it is of, parents first:
/// ancestors()) named `name`, linked by the is-a homs; `pinned` sets the name attribute.
EntityParts add_entity(const Import& im, ACSet& x, const std::vector<std::string>& kinds,
                       const std::string& name, bool pinned) {
    const Domain& d = im.pddl_domain;
    EntityParts parts;
    for (const auto& t : kinds) {
        Part p = x.add_part(im.type_ob.at(t), name);
        if (pinned) {
            x.set_subpart(im.name_attr.at(t), p, Value::string(name));
        }
        parts[t] = p;
        // Parents come first, so each is-a hom's target is there.
        const Type* info = d.find_type(t);
        for (std::size_t k = 0; k < info->parents.size(); ++k) {
            x.set_subpart(im.is_a.at(t)[k], p, parts.at(info->parents[k]));
        }
    }
    return parts;
}

/// A ground fact over entity indices (objects of a state, or blocks of a rule).
using Fact = BlockFact;

Part add_fact(const Import& im, ACSet& x, const Fact& f, const std::vector<EntityParts>& ents,
              std::string_view name) {
    Part p = x.add_part(im.predicate_ob.at(f.predicate), name);
    const Predicate* pred = im.pddl_domain.find_predicate(f.predicate);
    for (std::size_t i = 0; i < f.args.size(); ++i) {
        x.set_subpart(im.predicate_homs.at(f.predicate)[i], p,
                      ents[f.args[i]].at(pred->params[i].type));
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

/// The morphism sending each part of a (a prefix of b's parts, object by object) to itself.
hom::ACSetMorphism inclusion(const ACSet& a, const ACSet& b) {
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

// ---- the variants of an action ----------------------------------------------------------------

class VariantBuilder {
public:
    VariantBuilder(const Import& im, const Action& a, std::vector<Identification> ids,
                   DiagnosticSink& sink, const ImportOptions& options)
        : im_(im),
          a_(a),
          ids_(std::move(ids)),
          sink_(sink),
          options_(options),
          terms_(action_terms(im.pddl_domain, a)) {}

    /// Every variant, or nullopt (with an error) when there are too many.
    std::optional<ActionVariants> build() {
        ActionVariants out;
        out.action = a_.name;
        for (const auto& id : ids_) {
            if (!variants_of(id, out)) {
                return std::nullopt;
            }
        }
        return out;
    }

private:
    /// The rules of one identification: one per present/absent choice of its open deletes.
    bool variants_of(const Identification& id, ActionVariants& out) {
        std::vector<Fact> open;
        for (const auto& f : id.del) {
            if (std::find(id.pos.begin(), id.pos.end(), f) == id.pos.end() &&
                std::find(id.neg.begin(), id.neg.end(), f) == id.neg.end()) {
                open.push_back(f);
            }
        }
        if (open.size() > 20 ||
            out.variants.size() + (std::size_t{1} << open.size()) > options_.max_variants) {
            sink_.error(a_.range, fmt::format("the action '{}' needs more than {} rules (one per "
                                              "identification of parameters and per open "
                                              "delete)",
                                              a_.name, options_.max_variants));
            return false;
        }
        for (std::size_t mask = 0; mask < (std::size_t{1} << open.size()); ++mask) {
            std::set<Fact> present(id.pos.begin(), id.pos.end());
            std::set<Fact> absent(id.neg.begin(), id.neg.end());
            for (std::size_t k = 0; k < open.size(); ++k) {
                ((mask >> k) & 1 ? absent : present).insert(open[k]);
            }
            out.variants.push_back(make_variant(id, present, absent, out.variants.size()));
        }
        return true;
    }

    /// One entity per block: its names joined by '=', its type the most specific, pinned when
    /// it holds a constant.
    std::vector<ActionTerm> representatives(const Identification& id) const {
        std::vector<ActionTerm> reps(id.blocks);
        std::vector<bool> seen(id.blocks, false);
        for (std::size_t i = 0; i < terms_.size(); ++i) {
            auto& r = reps[id.block[i]];
            const auto& t = terms_[i];
            if (!seen[id.block[i]]) {
                r = t;
                seen[id.block[i]] = true;
                continue;
            }
            if (t.constant) {
                r = t;
            } else if (!r.constant) {
                r.name += "=" + t.name;
                if (im_.pddl_domain.is_subtype(t.type, r.type)) {
                    r.type = t.type;
                }
            }
        }
        return reps;
    }

    /// Per block: the types of its terms (its entity is of each of them; they need not be on
    /// one chain when unions or a type with two parents let an object be of both).
    std::vector<std::vector<std::string>> block_types(const Identification& id) const {
        std::vector<std::vector<std::string>> out(id.blocks);
        for (std::size_t i = 0; i < terms_.size(); ++i) {
            out[id.block[i]].push_back(terms_[i].type);
        }
        return out;
    }

    Variant make_variant(const Identification& id, const std::set<Fact>& present,
                         const std::set<Fact>& absent, std::size_t index) const {
        std::vector<ActionTerm> reps = representatives(id);
        auto types = block_types(id);
        auto rule = std::make_shared<rewrite::Rule>(im_.domain->schema);
        rule->name = index == 0 ? a_.name : fmt::format("{}~{}", a_.name, index + 1);
        rule->range = a_.range;
        for (const auto& [name, ob] : im_.predicate_ob) {
            rule->relations.push_back(ob);
        }
        std::sort(rule->relations.begin(), rule->relations.end());
        std::vector<EntityParts> ents;
        std::vector<std::string> names;
        for (std::size_t b = 0; b < reps.size(); ++b) {
            ents.push_back(add_entity(im_, rule->K, ancestors(im_.pddl_domain, types[b]),
                                      reps[b].name, reps[b].constant));
            names.push_back(reps[b].name);
        }
        // K: the entities and the present facts that stay true; L adds the deleted ones, R the
        // added ones (merged into an equal fact where there is one). Parts are appended to copies
        // of K, so l and r are inclusions.
        std::set<Fact> del(id.del.begin(), id.del.end());
        std::vector<Fact> deleted, created;
        for (const auto& f : present) {
            if (del.count(f) == 0) {
                add_fact(im_, rule->K, f, ents, fact_label(f, names));
            } else {
                deleted.push_back(f);
            }
        }
        for (const auto& f : id.add) {
            if (present.count(f) == 0) {
                created.push_back(f);
            }
        }
        rule->L = rule->K;
        rule->R = rule->K;
        for (const auto& f : deleted) {
            add_fact(im_, rule->L, f, ents, fact_label(f, names));
        }
        for (const auto& f : created) {
            add_fact(im_, rule->R, f, ents, fact_label(f, names));
        }
        rule->l = inclusion(rule->K, rule->L);
        rule->r = inclusion(rule->K, rule->R);
        for (const auto& f : absent) {
            rewrite::ApplicationCondition nac{"not " + fact_label(f, names), true, rule->L, {}, {}};
            add_fact(im_, nac.n_state, f, ents, fact_label(f, names));
            nac.n = inclusion(rule->L, nac.n_state);
            nac.range = a_.range;
            rule->conditions.push_back(std::move(nac));
        }
        rule->exprs.resize(im_.domain->schema->num_attr_types());
        rewrite::ActionOf action{a_.name, {}};
        std::vector<int> param_index(id.blocks, -1);
        for (std::size_t i = 0; i < a_.params.size(); ++i) {
            std::size_t b = id.block[i];
            if (reps[b].constant) {
                action.arguments.push_back({-1, reps[b].name});
                continue;
            }
            if (param_index[b] < 0) {
                param_index[b] = static_cast<int>(rule->parameters.size());
                ObId ob = im_.type_ob.at(reps[b].type);
                rule->parameters.push_back({reps[b].name, ob, ents[b].at(reps[b].type)});
            }
            action.arguments.push_back({param_index[b], {}});
        }
        rule->action = std::move(action);
        if (im_.pddl_domain.has_costs()) {
            rule->cost = cost(rule->action->arguments);
        }
        return Variant{std::move(rule)};
    }

    /// The action's cost as a rule's: its numbers summed, and a term per function read, each
    /// argument the action's argument (a parameter of the rule or a constant) or a constant.
    rewrite::Cost cost(const std::vector<rewrite::ActionOf::Argument>& args) const {
        rewrite::Cost out;
        for (const auto& c : a_.cost) {
            out.constant += c.number;
            if (!c.fluent) {
                continue;
            }
            rewrite::Cost::Term term{c.fluent->predicate, {}};
            for (const auto& t : c.fluent->args) {
                auto p = std::find_if(a_.params.begin(), a_.params.end(),
                                      [&](const TypedName& q) { return q.name == t.name; });
                term.arguments.push_back(t.variable && p != a_.params.end()
                                             ? args[static_cast<std::size_t>(p - a_.params.begin())]
                                             : rewrite::ActionOf::Argument{-1, t.name});
            }
            out.terms.push_back(std::move(term));
        }
        return out;
    }

    const Import& im_;
    const Action& a_;
    std::vector<Identification> ids_;
    DiagnosticSink& sink_;
    const ImportOptions& options_;
    std::vector<ActionTerm> terms_;
};

/// The rules of im's domain under im.assumptions, replacing im.domain's (same schema and name).
bool build_rules(Import& im, DiagnosticSink& sink, const ImportOptions& options) {
    auto domain = std::make_shared<plan::Domain>(*im.domain);
    domain->rules.clear();
    im.actions.clear();
    im.domain = domain; // the builder reads the schema through it
    auto ids = applicable_identifications(im.pddl_domain, im.assumptions);
    for (std::size_t k = 0; k < im.pddl_domain.actions.size(); ++k) {
        const Action& a = im.pddl_domain.actions[k];
        auto variants = VariantBuilder(im, a, std::move(ids[k]), sink, options).build();
        if (!variants) {
            return false;
        }
        for (const auto& var : variants->variants) {
            domain->rules.push_back(var.rule);
        }
        im.actions.push_back(std::move(*variants));
    }
    return true;
}

// ---- problems ---------------------------------------------------------------------------------

/// A state holding every object of `objects` and the given facts (each once).
std::shared_ptr<ACSet> make_state(const Import& im, const std::vector<TypedName>& objects,
                                  const std::vector<Atom>& atoms) {
    auto x = std::make_shared<ACSet>(im.domain->schema);
    std::vector<EntityParts> ents;
    std::unordered_map<std::string, std::size_t> index;
    std::unordered_map<std::string, std::vector<std::string>> kinds; // per type: ancestors()
    for (const auto& o : objects) {
        index[o.name] = ents.size();
        auto [k, fresh] = kinds.try_emplace(o.type);
        if (fresh) {
            k->second = ancestors(im.pddl_domain, {o.type});
        }
        ents.push_back(add_entity(im, *x, k->second, o.name, true));
    }
    std::set<Fact> facts;
    for (const auto& a : atoms) {
        Fact f{a.predicate, {}};
        for (const auto& t : a.args) {
            f.args.push_back(index.at(t.name));
        }
        if (facts.insert(f).second) {
            add_fact(im, *x, f, ents, "");
        }
    }
    return x;
}

/// The objects an atom list mentions, in order of first mention, with their types.
std::vector<TypedName> mentioned(const Domain& d, const Problem& p,
                                 const std::vector<Atom>& atoms) {
    std::vector<TypedName> out;
    ObjectIndex objects(d, p);
    std::unordered_set<std::string_view> known; // views of the atoms' names
    for (const auto& a : atoms) {
        for (const auto& t : a.args) {
            if (known.insert(t.name).second) {
                out.push_back(*objects.find(t.name));
            }
        }
    }
    return out;
}

/// im with the problem's states (on im's domain): the goal of its positive literals, and one
/// goal condition per negative literal (the goal with that fact, which must not extend).
void add_problem(Import& im, const Problem& problem) {
    im.pddl_problem = problem;
    std::vector<TypedName> objects = im.pddl_domain.constants;
    objects.insert(objects.end(), problem.objects.begin(), problem.objects.end());
    std::vector<Atom> goal_atoms;
    for (const auto& l : problem.goal) {
        if (l.positive) {
            goal_atoms.push_back(l.atom);
        }
    }
    auto p = std::make_shared<plan::Problem>();
    p->name = problem.name;
    p->domain = im.domain;
    p->initial = make_state(im, objects, problem.init);
    auto goal_objects = mentioned(im.pddl_domain, problem, goal_atoms);
    p->goal = make_state(im, goal_objects, goal_atoms);
    for (const auto& l : problem.goal) {
        if (l.positive) {
            continue;
        }
        // G's objects and facts first, so that G is a prefix of N.
        auto n_atoms = goal_atoms;
        n_atoms.push_back(l.atom);
        auto n_objects = goal_objects;
        for (const auto& o : mentioned(im.pddl_domain, problem, {l.atom})) {
            if (std::none_of(n_objects.begin(), n_objects.end(),
                             [&](const TypedName& x) { return x.name == o.name; })) {
                n_objects.push_back(o);
            }
        }
        auto n = make_state(im, n_objects, n_atoms);
        rewrite::ApplicationCondition c{l.to_string(), true, *n, inclusion(*p->goal, *n), l.range};
        p->goal_conditions.push_back(std::move(c));
    }
    p->range = problem.range;
    p->values = function_values(problem.values);
    p->counts_steps = !problem.metric && im.pddl_domain.has_costs();
    plan::set_step_cost(*p);
    im.problem = p;
}

} // namespace

std::vector<plan::FunctionValue> function_values(const std::vector<FunctionValue>& values) {
    std::vector<plan::FunctionValue> out;
    for (const auto& v : values) {
        if (v.term.predicate == "total-cost") {
            continue; // what the plan has cost so far, 0 at the start
        }
        plan::FunctionValue f{v.term.predicate, {}, v.value, v.range};
        for (const auto& t : v.term.args) {
            f.args.push_back(t.name);
        }
        out.push_back(std::move(f));
    }
    return out;
}

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

std::string Import::action_of(std::string_view rule_name) const {
    auto found = find_rule(rule_name);
    return found ? found->first->action : std::string(rule_name);
}

const std::string* Import::type_of(ObId ob) const {
    for (const auto& [name, o] : type_ob) {
        if (o == ob) {
            return &name;
        }
    }
    return nullptr;
}

const std::string* Import::predicate_of(ObId ob) const {
    for (const auto& [name, o] : predicate_ob) {
        if (o == ob) {
            return &name;
        }
    }
    return nullptr;
}

std::vector<Atom> Import::facts(const acset::ACSet& x) const {
    std::vector<Atom> out;
    for (const auto& pred : pddl_domain.predicates) {
        ObId ob = predicate_ob.at(pred.name);
        const auto& homs = predicate_homs.at(pred.name);
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            Atom a{pred.name, {}, {}};
            for (std::size_t i = 0; i < homs.size(); ++i) {
                ObId type = x.schema().hom(homs[i]).codom;
                Part q = x.subpart(homs[i], p);
                std::string name = q == kNoPart ? "?" : std::string(x.part_name(type, q));
                a.args.push_back({name.empty() ? x.part_label(type, q) : name, false, {}});
            }
            out.push_back(std::move(a));
        }
    }
    return out;
}

std::optional<Import> import_pddl(const Domain& domain, const Problem* problem,
                                  DiagnosticSink& sink, const ImportOptions& options) {
    Import out;
    out.pddl_domain = domain;
    make_vocabulary(out);
    out.assumptions = domain_assumptions(domain);
    if (problem != nullptr) {
        out.assumptions = assumptions_for(domain, out.assumptions, problem->init);
    }
    if (!build_rules(out, sink, options)) {
        return std::nullopt;
    }
    if (problem != nullptr) {
        add_problem(out, *problem);
    }
    return out;
}

std::optional<Import> for_initial_facts(const Import& domain, const std::vector<Atom>& facts,
                                        DiagnosticSink& sink, const ImportOptions& options) {
    Import out = domain;
    out.problem = nullptr;
    out.pddl_problem.reset();
    // Rules made for another problem's assumptions are rebuilt from the domain's own.
    bool own = domain.assumptions.broken.empty() && domain.assumptions.patterns.empty();
    auto a =
        assumptions_for(domain.pddl_domain,
                        own ? domain.assumptions : domain_assumptions(domain.pddl_domain), facts);
    if (own && a.broken.empty()) {
        return out;
    }
    out.assumptions = std::move(a);
    if (!build_rules(out, sink, options)) {
        return std::nullopt;
    }
    return out;
}

std::optional<Import> import_problem(const Import& domain, const Problem& problem,
                                     DiagnosticSink& sink, const ImportOptions& options) {
    auto out = for_initial_facts(domain, problem.init, sink, options);
    if (out) {
        add_problem(*out, problem);
    }
    return out;
}

} // namespace catplan::pddl
