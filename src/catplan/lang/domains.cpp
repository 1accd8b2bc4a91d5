// Domains and problems (docs/language.md, "Domains and problems"): `@domain Name(Schema)` gathers
// rules (written inside or named), `@problem Name(Domain)` names an initial and a goal instance.

#include "catplan/lang/detail/colimit.hpp"
#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/detail/rule_elaboration.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/plan/domain.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace catplan::lang::detail {
namespace {

using acset::ACSet;

// The action's arguments (rewrite::ActionOf) of a rule whose parameters a domain replaced: each
// the same part as before, and every new parameter among them; false after an error.
bool action_parameters(const rewrite::Rule& before, rewrite::Rule& after, SourceRange at,
                       DiagnosticSink& sink) {
    if (!after.action) {
        return true;
    }
    std::vector<bool> given(after.parameters.size(), false);
    for (auto& a : after.action->arguments) {
        if (a.parameter < 0) {
            continue;
        }
        const auto& old = before.parameters[static_cast<std::size_t>(a.parameter)];
        auto p = std::find_if(after.parameters.begin(), after.parameters.end(),
                              [&](const auto& q) { return q.ob == old.ob && q.part == old.part; });
        if (p == after.parameters.end()) {
            sink.error(at, fmt::format("the parameters leave out '{}', an argument of the action "
                                       "'{}' of rule '{}'",
                                       old.name, after.action->name, after.name));
            return false;
        }
        a.parameter = static_cast<int>(p - after.parameters.begin());
        given[static_cast<std::size_t>(a.parameter)] = true;
    }
    for (std::size_t i = 0; i < given.size(); ++i) {
        if (!given[i]) {
            sink.error(at, fmt::format("parameter '{}' is not an argument of the action '{}' of "
                                       "rule '{}'",
                                       after.parameters[i].name, after.action->name, after.name));
            return false;
        }
    }
    return true;
}

// A rule named in a domain, `unstack` or with parameters `unstack(block, underblock)`.
rewrite::RulePtr named_rule(Elaborator& ctx, const Expr& st) {
    DiagnosticSink& sink = ctx.sink;
    const Declaration* d = ctx.module.find(st.text);
    SourceRange at = st.kind == Expr::Kind::Call ? st.name_range : st.range;
    if (d == nullptr || d->kind != DeclKind::Rule) {
        sink.error(at, d == nullptr ? fmt::format("unknown rule '{}'", st.text)
                                    : fmt::format("'{}' is not a rule", st.text));
        return nullptr;
    }
    if (st.kind == Expr::Kind::Name) {
        return d->rule;
    }
    auto copy = std::make_shared<rewrite::Rule>(*d->rule);
    copy->parameters.clear();
    bool ok = true;
    std::map<std::string, SourceRange> seen;
    for (const auto& a : st.args) {
        if (a.kind == Expr::Kind::Name && !new_parameter(seen, a, sink)) {
            ok = false;
            continue;
        }
        bool found = false;
        for (std::uint32_t o = 0; o < copy->L.schema().num_obs() && !found; ++o) {
            if (a.kind != Expr::Kind::Name) {
                break;
            }
            if (auto p = copy->L.find_part(ObId(o), a.text)) {
                copy->parameters.push_back({a.text, ObId(o), *p});
                found = true;
            }
        }
        if (!found) {
            sink.error(a.range, fmt::format("parameter '{}' is not a part generator of the "
                                            "precondition of '{}'",
                                            to_string(a), st.text));
            ok = false;
        }
    }
    return ok && action_parameters(*d->rule, *copy, at, sink) ? copy : nullptr;
}

// One statement of a domain's body as a rule (`@rule ...`, `:name => @migration(...)` or a rule's
// name), with the place to report it at; nullptr after an error.
rewrite::RulePtr domain_rule(Elaborator& ctx, const Expr& st,
                             const std::shared_ptr<schema::Schema>& schema, SourceRange& at) {
    at = st.range;
    if (st.kind == Expr::Kind::Macro && st.macro->name == "rule") {
        RuleSource src;
        if (!rule_source(ctx, *st.macro, "", {}, schema, src)) {
            return nullptr;
        }
        at = src.name_range;
        return elaborate_rule(ctx, src);
    }
    if (st.is_binary("=>") &&
        (st.args[0].kind == Expr::Kind::Symbol || st.args[0].kind == Expr::Kind::Name) &&
        st.args[1].kind == Expr::Kind::Macro && st.args[1].macro->name == "migration") {
        RuleSource src;
        if (!rule_source(ctx, *st.args[1].macro, st.args[0].text, st.args[0].range, schema, src)) {
            return nullptr;
        }
        at = src.name_range;
        return elaborate_rule(ctx, src);
    }
    if (st.kind == Expr::Kind::Name || st.kind == Expr::Kind::Call) {
        at = st.kind == Expr::Kind::Call ? st.name_range : st.range;
        return named_rule(ctx, st);
    }
    ctx.sink.error(st.range, fmt::format("expected a rule in the domain: '@rule ...', "
                                         "':name => @migration(...)' or the name of a "
                                         "rule, found '{}'",
                                         to_string(st)));
    return nullptr;
}

// `facts = (on, clear)`: objects of the schema whose parts are facts, each held at most once
// (rewrite::Rule::relations), in every rule of the domain. False after an error.
bool domain_facts(Elaborator& ctx, const Expr& st, const schema::Schema& s,
                  std::vector<ObId>& facts) {
    DiagnosticSink& sink = ctx.sink;
    const Expr& v = st.args[1];
    std::vector<const Expr*> names;
    if (v.kind == Expr::Kind::Tuple) {
        for (const auto& a : v.args) {
            names.push_back(&a);
        }
    } else {
        names.push_back(&v);
    }
    bool ok = true;
    for (const Expr* n : names) {
        auto ob = n->kind == Expr::Kind::Name ? s.find_ob(n->text) : std::nullopt;
        if (!ob) {
            sink.error(n->range, fmt::format("expected an object of schema '{}' as a fact, found "
                                             "'{}'",
                                             s.name(), to_string(*n)));
            ok = false;
        } else if (std::find(facts.begin(), facts.end(), *ob) != facts.end()) {
            sink.error(n->range, fmt::format("'{}' is given twice", n->text));
            ok = false;
        } else {
            facts.push_back(*ob);
        }
    }
    std::sort(facts.begin(), facts.end());
    return ok;
}

// The rules of one action (rewrite::ActionOf) take as many arguments, so that a step of the
// action reads the same whichever rule carries it out.
void check_action(const rewrite::Rule& rule, SourceRange at, const plan::Domain& domain,
                  DiagnosticSink& sink) {
    for (const auto& other : domain.rules) {
        if (other->action_name() == rule.action_name() &&
            other->action_arity() != rule.action_arity()) {
            auto& d = sink.error(
                at, fmt::format(
                        "rule '{}' carries out the action '{}' with {} argument{}, but rule "
                        "'{}' does with {}",
                        rule.name, rule.action_name(), rule.action_arity(),
                        rule.action_arity() == 1 ? "" : "s", other->name, other->action_arity()));
            d.notes.emplace_back(other->range, "that rule is here");
            return;
        }
    }
}

// `initial = I` or `goal = G` of a problem on domain dd into its slot; false after an error.
bool problem_instance(Elaborator& ctx, const Expr& st, const Declaration& dd,
                      const std::string& dname, std::shared_ptr<const ACSet>* slots[2],
                      std::string names[2]) {
    DiagnosticSink& sink = ctx.sink;
    if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Name ||
        (st.args[0].text != "initial" && st.args[0].text != "goal") ||
        st.args[1].kind != Expr::Kind::Name) {
        sink.error(st.range, fmt::format("expected 'initial = Instance', 'goal = Instance', a "
                                         "goal condition 'NAC => begin ... end', a function "
                                         "value 'f(a, b) = 3' or 'metric = steps', found '{}'",
                                         to_string(st)));
        return false;
    }
    int i = st.args[0].text == "initial" ? 0 : 1;
    const Expr& iname = st.args[1];
    if (slots[i]->get() != nullptr) {
        sink.error(st.range, fmt::format("'{}' is given twice", st.args[0].text));
        return false;
    }
    const Declaration* id = ctx.module.find(iname.text);
    if (id == nullptr || id->kind != DeclKind::Instance) {
        sink.error(iname.range, id == nullptr ? fmt::format("unknown instance '{}'", iname.text)
                                              : fmt::format("'{}' is not an instance", iname.text));
        return false;
    }
    if (id->schema.get() != dd.schema.get()) {
        sink.error(iname.range,
                   fmt::format("instance '{}' is on schema '{}' but domain "
                               "'{}' is on '{}'",
                               iname.text, id->schema->name(), dname, dd.schema->name()));
        return false;
    }
    *slots[i] = id->instance;
    names[i] = iname.text;
    return true;
}

// `metric = steps` (plans are measured by their steps although the rules say costs) or
// `metric = cost` (the default); false when st says neither.
bool problem_metric(const Expr& st, plan::Problem& p, DiagnosticSink& sink) {
    if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Name || st.args[0].text != "metric") {
        return false;
    }
    const Expr& v = st.args[1];
    if (v.kind != Expr::Kind::Name || (v.text != "steps" && v.text != "cost")) {
        sink.error(v.range, fmt::format("expected 'metric = cost' or 'metric = steps', found '{}'",
                                        to_string(st)));
    } else {
        p.counts_steps = v.text == "steps";
    }
    return true;
}

// `road_length(a, d) = 20`, a value of a function rules' costs read (plan/costs.hpp): the
// arguments parts of the initial state, the value a non-negative integer. False when st is no
// such statement.
bool function_value(const Expr& st, plan::Problem& p, DiagnosticSink& sink) {
    if (!st.is_binary("=") || st.args[0].kind != Expr::Kind::Call) {
        return false;
    }
    const Expr& f = st.args[0];
    const Expr& v = st.args[1];
    plan::FunctionValue value{f.text, {}, v.int_value, st.range};
    bool ok = true;
    for (const auto& a : f.args) {
        if (a.kind != Expr::Kind::Name && a.kind != Expr::Kind::String) {
            sink.error(a.range, fmt::format("expected a part name, found '{}'", to_string(a)));
            ok = false;
        }
        value.args.push_back(a.text);
    }
    if (v.kind != Expr::Kind::Int || v.int_value < 0) {
        sink.error(v.range, fmt::format("expected the value of {} as a non-negative integer, "
                                        "found '{}'",
                                        f.text, to_string(v)));
        ok = false;
    }
    if (ok) {
        p.values.push_back(std::move(value));
    }
    return true;
}

// The function values against the initial state and the rules: each argument a part, each
// function given once per arguments and with as many as the rules' costs read it with.
void check_values(const plan::Problem& p, const std::vector<const Expr*>& at,
                  DiagnosticSink& sink) {
    std::map<std::pair<std::string, std::vector<std::string>>, SourceRange> seen;
    const ACSet& x = *p.initial;
    for (std::size_t i = 0; i < p.values.size(); ++i) {
        const auto& v = p.values[i];
        const Expr& call = at[i]->args[0];
        for (std::size_t k = 0; k < v.args.size(); ++k) {
            bool part = false;
            for (std::uint32_t o = 0; o < x.schema().num_obs() && !part; ++o) {
                part = x.find_part(ObId(o), v.args[k]).has_value();
            }
            if (!part) {
                sink.error(call.args[k].range,
                           fmt::format("'{}' is no part of the initial state", v.args[k]));
            }
        }
        auto [it, fresh] = seen.emplace(std::pair(v.function, v.args), v.range);
        if (!fresh) {
            auto& d = sink.error(v.range, fmt::format("{} is given twice", to_string(call)));
            d.notes.emplace_back(it->second, "first given here");
        }
        const rewrite::Cost::Term* read = nullptr;
        std::string rule;
        for (const auto& r : p.domain->rules) {
            for (std::size_t t = 0; r->cost && t < r->cost->terms.size() && !read; ++t) {
                if (r->cost->terms[t].function == v.function) {
                    read = &r->cost->terms[t];
                    rule = r->name;
                }
            }
        }
        if (read == nullptr) {
            sink.warning(call.name_range, fmt::format("no rule's cost reads '{}'", v.function));
        } else if (read->arguments.size() != v.args.size()) {
            sink.error(call.range,
                       fmt::format("rule '{}' reads {} with {} argument{}, not {}", rule,
                                   v.function, read->arguments.size(),
                                   read->arguments.size() == 1 ? "" : "s", v.args.size()));
        }
    }
}

// The statements of `NAC => begin ... end` (or `@join begin ... end`), or nullptr.
const std::vector<Expr>* condition_block(const Expr& st) {
    if (!st.is_binary("=>") || st.args[0].kind != Expr::Kind::Name ||
        (st.args[0].text != "NAC" && st.args[0].text != "PAC")) {
        return nullptr;
    }
    return block_body(st.args[1]);
}

// A goal condition `NAC => begin ... end`: N is the goal together with the block, whose names
// refer to the goal's generators; n : goal -> N is the inclusion. nullopt after an error.
std::optional<rewrite::ApplicationCondition> goal_condition(Elaborator& ctx, const Expr& st,
                                                            const std::vector<Expr>& body,
                                                            const ACSet& goal, std::size_t index) {
    DiagnosticSink& sink = ctx.sink;
    std::size_t errors = sink.num_errors();
    Colimit c(goal.schema_ptr(), ctx.inferred_kinds(goal.schema()));
    auto nodes = c.add_state(goal, st.range);
    for (const auto& b : body) {
        if (b.is_binary("::")) {
            c.declare(b, sink);
        }
    }
    for (const auto& b : body) {
        if (b.is_binary("==")) {
            c.equation(b, sink);
        } else if (!b.is_binary("::")) {
            sink.error(b.range, fmt::format("expected a generator (x::Block) or an equation (f(x) "
                                            "== y), found '{}'",
                                            to_string(b)));
        }
    }
    if (sink.num_errors() != errors) {
        return std::nullopt;
    }
    ACSet N = c.build_partial();
    hom::ACSetMorphism n;
    n.components.resize(nodes.parts.size());
    for (std::size_t o = 0; o < nodes.parts.size(); ++o) {
        for (auto node : nodes.parts[o]) {
            n.components[o].push_back(c.built_part(node));
        }
    }
    n.var_components.resize(nodes.vars.size());
    for (std::size_t t = 0; t < nodes.vars.size(); ++t) {
        for (auto node : nodes.vars[t]) {
            n.var_components[t].push_back(c.built_value(node));
        }
    }
    const std::string& kind = st.args[0].text;
    return rewrite::ApplicationCondition{fmt::format("{} {}", kind, index + 1), kind == "NAC",
                                         std::move(N), std::move(n), st.range};
}

} // namespace

void elaborate_domain(Elaborator& ctx, const MacroCall& form, bool imported) {
    DiagnosticSink& sink = ctx.sink;
    const auto& h = form.header;
    if (h.size() != 1 || h[0].kind != Expr::Kind::Call || h[0].args.size() != 1 ||
        h[0].args[0].kind != Expr::Kind::Name || !form.has_body || !form.assigned.empty()) {
        sink.error(form.range, "expected '@domain Name(Schema) begin ... end'");
        return;
    }
    std::size_t errors = sink.num_errors();
    auto schema = ctx.lookup_schema(h[0].args[0], true);
    if (!schema) {
        return;
    }
    auto domain = std::make_shared<plan::Domain>();
    domain->name = h[0].text;
    domain->schema = schema;
    domain->range = h[0].name_range;
    std::map<std::string, SourceRange> seen;
    std::optional<std::vector<ObId>> facts;
    for (const auto& st : form.body) {
        if (st.is_binary("=") && st.args[0].kind == Expr::Kind::Name &&
            st.args[0].text == "facts") {
            if (facts) {
                sink.error(st.range, "the facts are given twice");
            } else {
                facts.emplace();
                domain_facts(ctx, st, *schema, *facts);
            }
            continue;
        }
        SourceRange at;
        rewrite::RulePtr rule = domain_rule(ctx, st, schema, at);
        if (!rule) {
            continue;
        }
        if (rule->L.schema_ptr().get() != schema.get()) {
            sink.error(at, fmt::format("rule '{}' is on schema '{}' but domain '{}' is on "
                                       "'{}'",
                                       rule->name, rule->L.schema().name(), domain->name,
                                       schema->name()));
            continue;
        }
        auto [it, fresh] = seen.emplace(rule->name, at);
        if (!fresh) {
            auto& d = sink.error(
                at, fmt::format("rule '{}' is already in domain '{}'", rule->name, domain->name));
            d.notes.emplace_back(it->second, "first given here");
            continue;
        }
        check_action(*rule, at, *domain, sink);
        domain->rules.push_back(std::move(rule));
    }
    if (sink.num_errors() != errors || !ctx.claim_name(domain->name, domain->range)) {
        return;
    }
    if (facts) {
        for (auto& rule : domain->rules) {
            auto copy = std::make_shared<rewrite::Rule>(*rule);
            copy->relations = *facts;
            rule = std::move(copy);
        }
    }
    Declaration d =
        new_declaration(DeclKind::Domain, domain->name, domain->range, imported, schema);
    d.domain = std::move(domain);
    ctx.module.add(std::move(d));
}

void elaborate_problem(Elaborator& ctx, const MacroCall& form, bool imported) {
    DiagnosticSink& sink = ctx.sink;
    const auto& h = form.header;
    if (h.size() != 1 || h[0].kind != Expr::Kind::Call || h[0].args.size() != 1 ||
        h[0].args[0].kind != Expr::Kind::Name || !form.has_body || !form.assigned.empty()) {
        sink.error(form.range, "expected '@problem Name(Domain) begin initial = I; goal = "
                               "G end'");
        return;
    }
    std::size_t errors = sink.num_errors();
    const Expr& dname = h[0].args[0];
    const Declaration* dd = ctx.module.find(dname.text);
    if (dd == nullptr || dd->kind != DeclKind::Domain) {
        sink.error(dname.range, dd == nullptr ? fmt::format("unknown domain '{}'", dname.text)
                                              : fmt::format("'{}' is not a domain", dname.text));
        return;
    }
    auto problem = std::make_shared<plan::Problem>();
    problem->name = h[0].text;
    problem->domain = dd->domain;
    problem->range = h[0].name_range;
    std::string names[2];
    std::shared_ptr<const ACSet>* slots[2] = {&problem->initial, &problem->goal};
    std::vector<std::pair<const Expr*, const std::vector<Expr>*>> conditions;
    std::vector<const Expr*> value_statements;
    for (const auto& st : form.body) {
        if (const auto* body = condition_block(st)) {
            conditions.emplace_back(&st, body);
        } else if (function_value(st, *problem, sink)) {
            value_statements.resize(problem->values.size(), &st);
        } else if (!problem_metric(st, *problem, sink)) {
            problem_instance(ctx, st, *dd, dname.text, slots, names);
        }
    }
    for (int i = 0; i < 2; ++i) {
        if (slots[i]->get() == nullptr && sink.num_errors() == errors) {
            sink.error(form.range, fmt::format("problem '{}' needs '{} = Instance'", problem->name,
                                               i == 0 ? "initial" : "goal"));
        }
    }
    if (problem->initial != nullptr) {
        check_values(*problem, value_statements, sink);
    }
    if (sink.num_errors() == errors) {
        plan::set_step_cost(*problem);
        // Negative goals (PDDL's `(not (on a b))`): conditions on the goal's embedding.
        for (const auto& [st, body] : conditions) {
            auto c =
                goal_condition(ctx, *st, *body, *problem->goal, problem->goal_conditions.size());
            if (c) {
                problem->goal_conditions.push_back(std::move(*c));
            }
        }
    }
    if (sink.num_errors() != errors || !ctx.claim_name(problem->name, problem->range)) {
        return;
    }
    Declaration d =
        new_declaration(DeclKind::Problem, problem->name, problem->range, imported, dd->schema);
    d.initial_name = names[0];
    d.goal_name = names[1];
    d.problem = std::move(problem);
    ctx.module.add(std::move(d));
}

} // namespace catplan::lang::detail
