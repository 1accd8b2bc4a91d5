#include "catplan/transfer/transfer.hpp"

#include "catplan/base/ascii.hpp"
#include "catplan/base/process.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"
#include "catplan/transfer/correspond.hpp"
#include "catplan/transfer/divergence.hpp"
#include "catplan/transfer/named_state.hpp"
#include "catplan/transfer/rename.hpp"
#include "catplan/transfer/repair.hpp"
#include "catplan/transfer/terms.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <string>
#include <unordered_map>

namespace catplan::transfer {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Names every unnamed part after its label (#7), so that names can follow every part.
ACSet named(const ACSet& x) {
    ACSet out = x;
    for (std::uint32_t o = 0; o < x.schema().num_obs(); ++o) {
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            if (x.part_name(ObId(o), p).empty()) {
                out.set_part_name(ObId(o), p, x.part_label(ObId(o), p));
            }
        }
    }
    return out;
}

// A source action with its migration and the origins of the migrated L's and R's tuples.
struct ActionPair {
    const rewrite::Rule* source = nullptr;
    const rewrite::Rule* target = nullptr;
    std::vector<std::optional<migrate::TupleOrigins>> l_origins, r_origins; // by target object
};

/// Δ_F of a goal's conditions: each Δ_F(n) : Δ_F(G) -> Δ_F(N).
std::vector<rewrite::ApplicationCondition>
migrate_conditions(const SchemaMap& f, const ACSet& goal,
                   const std::vector<rewrite::ApplicationCondition>& conditions) {
    std::vector<rewrite::ApplicationCondition> out;
    if (conditions.empty()) {
        return out;
    }
    migrate::MigratedState g = migrate::migrate_state(f, goal);
    for (const auto& c : conditions) {
        migrate::MigratedState n = migrate::migrate_state(f, c.n_state);
        auto m = migrate::migrate(f, c.n, g, n);
        CATPLAN_ASSERT(m.has_value(), "Δ_F of a monic goal -> N is a morphism");
        out.push_back({c.name, c.negative, std::move(n.state), std::move(*m), c.range});
    }
    return out;
}

std::vector<std::optional<migrate::TupleOrigins>> origins_of(const SchemaMap& f, const ACSet& x) {
    auto ms = migrate::migrate_state(f, x);
    std::vector<std::optional<migrate::TupleOrigins>> out;
    for (std::uint32_t c = 0; c < f.target()->num_obs(); ++c) {
        out.push_back(migrate::tuple_origins(f, ms, ObId(c)));
    }
    return out;
}

// The target match's parts fixed by carrying the source match m through part names: each part
// of Δ_F(L) starts at a part q of L, m(q) is a named part of X, and the part of Y with that
// name (when it is the only one) is where the target match sends it.
std::vector<hom::PartBinding> carried_bindings(const ActionPair& a, const ACSetMorphism& m,
                                               const NamedState& x, const NamedState& y,
                                               const Renaming& renaming) {
    std::vector<hom::PartBinding> out;
    const ACSet& fl = a.target->L;
    for (std::uint32_t c = 0; c < fl.schema().num_obs(); ++c) {
        const auto& origin = a.l_origins[c];
        if (!origin) {
            continue;
        }
        for (Part p = 0; p < fl.num_parts(ObId(c)) && p < origin->parts.size(); ++p) {
            Part in_x = m.components[origin->ob.index()][origin->parts[p]];
            std::string_view name = x.state().part_name(origin->ob, in_x);
            Part in_y = name.empty() ? kNoPart : y.find(ObId(c), renamed(renaming, name));
            if (in_y != kNoPart) {
                out.push_back({ObId(c), p, in_y});
            }
        }
    }
    return out;
}

// One argument per distinct parameter name, from labels[i] for parameter i: the distinct labels
// a name binds, joined with '|' when they differ (a migrated action has a parameter per target
// object its source parameter goes to, and a replanned step may bind them to different parts).
std::vector<std::string> collapse(const std::vector<rewrite::Parameter>& parameters,
                                  const std::vector<std::string>& labels) {
    std::vector<std::string_view> names;
    std::vector<std::vector<std::string>> bound;
    for (std::size_t i = 0; i < parameters.size() && i < labels.size(); ++i) {
        auto it = std::find(names.begin(), names.end(), parameters[i].name);
        std::size_t k = static_cast<std::size_t>(it - names.begin());
        if (it == names.end()) {
            names.push_back(parameters[i].name);
            bound.emplace_back();
        }
        if (std::find(bound[k].begin(), bound[k].end(), labels[i]) == bound[k].end()) {
            bound[k].push_back(labels[i]);
        }
    }
    std::vector<std::string> out;
    for (const auto& b : bound) {
        out.push_back(fmt::format("{}", fmt::join(b, "|")));
    }
    return out;
}

// The step `rule(args)` of a match, arguments collapsed by parameter name.
plan::Step step_of(const rewrite::Rule& rule, const ACSetMorphism& m, const ACSet& y) {
    plan::Step step;
    step.action = rule.name;
    std::vector<std::string> labels;
    for (const auto& p : rule.parameters) {
        labels.push_back(y.part_label(p.ob, m.components[p.ob.index()][p.part]));
    }
    step.args = collapse(rule.parameters, labels);
    return step;
}

// The parameter names of rule that target_rule does not have.
std::vector<std::string> lost_parameters(const rewrite::Rule& rule,
                                         const rewrite::Rule& target_rule) {
    std::vector<std::string> out;
    for (const auto& p : rule.parameters) {
        bool kept = std::any_of(target_rule.parameters.begin(), target_rule.parameters.end(),
                                [&](const auto& q) { return q.name == p.name; });
        if (!kept) {
            out.push_back(p.name);
        }
    }
    return out;
}

// Why rule has no match in y extending the bindings.
std::string explain_no_match(const rewrite::Rule& rule, const ACSet& y,
                             const std::vector<hom::PartBinding>& bindings) {
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    opt.initial = bindings;
    opt.max_results = 1;
    auto embedding = hom::find_homomorphism(rule.L, y, opt);
    if (embedding) {
        auto why = rewrite::match_problem(rule, y, *embedding);
        return fmt::format("no valid match in the target: {}",
                           why ? *why : std::string("the match is rejected"));
    }
    auto missing = plan::explain_no_embedding(rule.L, y, bindings);
    return fmt::format("no match in the target: {}",
                       missing ? *missing : std::string("the precondition does not embed"));
}

class Transfer {
public:
    Transfer(const SchemaMap& f, const plan::Problem& problem, const plan::Plan& plan,
             const TransferOptions& options, TransferResult& out)
        : f_(f), problem_(problem), plan_(plan), options_(options), out_(out) {}

    /// Replays the plan; returns the source plan's own fault when the replay did not stop in
    /// the source (it comes after the target goal's in the verdict).
    std::optional<Fault> run() {
        auto t0 = Clock::now();
        ACSet x0 = named(*problem_.initial);
        out_.target_domain = options_.migrated_domain ? *options_.migrated_domain
                                                      : migrate_domain(f_, *problem_.domain);
        ACSet y0 = migrate::migrate(f_, x0);
        if (options_.rename_by_type) {
            renaming_ = names_by_type(y0);
            rename_parts(y0, renaming_);
        }
        out_.carried_values = problem_.values;
        for (auto& v : out_.carried_values) {
            for (auto& a : v.args) {
                a = renamed(renaming_, a);
            }
        }
        out_.counts_steps = problem_.counts_steps;
        out_.target_initial = std::make_shared<const ACSet>(y0);
        out_.target_goal = std::make_shared<const ACSet>(migrate::migrate(f_, *problem_.goal));
        out_.target_goal_conditions =
            migrate_conditions(f_, *problem_.goal, problem_.goal_conditions);
        out_.timings.migrate_ms = ms_since(t0);
        x_.emplace(std::move(x0));
        y_.emplace(std::move(y0));
        if (options_.check_divergence || options_.follow_source) {
            check_.emplace(f_, renaming_);
        }
        keep_states();
        t0 = Clock::now();
        out_.steps.reserve(plan_.steps.size());
        for (std::size_t i = 0; i < plan_.steps.size(); ++i) {
            if (!step(i)) {
                break;
            }
            keep_states();
        }
        out_.timings.apply_ms = ms_since(t0);
        auto source = finish_source();
        out_.whole_comparisons = check_ ? check_->whole_comparisons() : 0;
        out_.final_state = std::move(*y_).release();
        y_.reset();
        return source;
    }

private:
    void keep_states() {
        if (options_.keep_states) {
            out_.source_states.push_back(x_->state());
            out_.target_states.push_back(y_->state());
        }
    }

    const ActionPair* action(const std::string& name) {
        auto it = actions_.find(name);
        if (it != actions_.end()) {
            return &it->second;
        }
        ActionPair a;
        a.source = problem_.domain->find_rule(name);
        a.target = out_.target_domain.domain->find_rule(name);
        if (a.source && a.target) {
            a.l_origins = origins_of(f_, a.source->L);
            a.r_origins = origins_of(f_, a.source->R);
        }
        return &actions_.emplace(name, std::move(a)).first->second;
    }

    // "step 3 unstack(a, b)": the step as users name its action (a PDDL action, not one of its
    // rules' variants).
    std::string where(std::size_t i) const {
        plan::Step step = plan_.steps[i];
        const auto* own = options_.target_actions.get();
        if (own != nullptr && own->source_action_name) {
            step.action = own->source_action_name(step.action);
        }
        return fmt::format("step {} {}", i + 1, step.to_string());
    }

    bool fail_at(std::size_t i, const std::string& why) {
        out_.verdict.faults.push_back({Fault::Kind::Step, i, where(i), why});
        return false;
    }

    // Replays step i in the source and applies its migration in the target.
    bool step(std::size_t i) {
        const plan::Step& s = plan_.steps[i];
        const ActionPair* a = action(s.action);
        if (a->source == nullptr) {
            source_failure(
                i, fmt::format("no action '{}' in domain {}", s.action, problem_.domain->name));
            return false;
        }
        auto m = match_by_names(*a->source, *x_, s);
        if (!m) {
            source_failure(i, m.error());
            return false;
        }
        // A step whose cost has no value cannot be taken, as validate_plan (and VAL) say.
        if (auto cost = plan::step_cost(problem_, *a->source, s.args); !cost) {
            source_failure(i, cost.error());
            return false;
        }
        if (options_.target_actions) {
            return own_action_step(i, *a, std::move(*m));
        }
        if (a->target == nullptr) {
            return fail_at(i, "the action does not migrate: " + migration_failure(s.action));
        }
        auto bindings = carried_bindings(*a, *m, *x_, *y_, renaming_);
        rewrite::MatchOptions opt;
        opt.initial = bindings;
        opt.max_results = 1;
        auto matches = rewrite::find_matches(*a->target, y_->state(), opt);
        if (matches.empty()) {
            return fail_at(i, explain_no_match(*a->target, y_->state(), bindings));
        }
        StepTransfer st;
        st.source = s;
        st.target = step_of(*a->target, matches[0], y_->state());
        if (options_.describe_bindings) {
            st.source_bindings = describe_bindings(*m, a->source->L, x_->state());
            st.target_bindings =
                describe_bindings(matches[0], a->target->L, y_->state(), &a->l_origins);
        }
        st.lost_parameters = lost_parameters(*a->source, *a->target);
        if (comparing()) {
            check_->before(*m, *x_, matches[0], *y_);
        }
        auto r_to_x = apply_source(i, *a->source, *m);
        CATPLAN_ASSERT(r_to_x, "a valid source match failed to apply");
        // A part created in the target is named after the source part its tuple starts at.
        auto applied = y_->apply(
            *a->target, matches[0],
            [&](ObId c, Part q) {
                const auto& origin = a->r_origins[c.index()];
                if (!origin || q >= origin->parts.size()) {
                    return created_name(c, i);
                }
                Part in_x = r_to_x->components[origin->ob.index()][origin->parts[q]];
                return renamed(renaming_, x_->state().part_name(origin->ob, in_x));
            },
            rewrite::CheckMatch::No);
        if (!applied) {
            return fail_at(i, applied.error());
        }
        if (comparing()) {
            if (auto d = check_->after(i, *r_to_x, *x_, *applied, *y_)) {
                d->where = where(i);
                out_.verdict.divergences.push_back(std::move(*d));
            }
        }
        st.source_comatch = *r_to_x;
        if (options_.follow_source) {
            follow_source();
        } else {
            st.target_comatch = *applied;
        }
        st.source_match = std::move(*m);
        st.target_match = std::move(matches[0]);
        st.target_steps = {st.target};
        out_.steps.push_back(std::move(st));
        return true;
    }

    // The name of a part of ob that target step i creates and no source part names: after its
    // object and the step (clear@2), a name no person writes (terms.hpp).
    std::string created_name(ObId ob, std::size_t i) { return created_name(*y_, ob, i); }

    // The same name in a target state z (one a repair reaches from Y_{i-1}).
    std::string created_name(NamedState& z, ObId ob, std::size_t i) {
        return z.fresh_name(ob, step_name(target_prefixes_, *f_.target(), ob, i));
    }

    // Applies the source step at m (match_by_names found it for x_ as it is), naming a created
    // part after its generator in the rule, or after its object and the step that created it
    // (block@2).
    Result<ACSetMorphism> apply_source(std::size_t i, const rewrite::Rule& rule,
                                       const ACSetMorphism& m) {
        return x_->apply(
            rule, m,
            [&](ObId ob, Part q) {
                std::string base(rule.R.part_name(ob, q));
                if (base.empty()) {
                    base = step_name(source_prefixes_, *problem_.domain->schema, ob, i);
                }
                return x_->fresh_name(ob, base);
            },
            rewrite::CheckMatch::No);
    }

    // ob's name in lower case, '@' and step i's number (clear@2); `prefixes` keeps the part
    // before the number, per object, for the next step (names are made at every step).
    static std::string step_name(std::vector<std::string>& prefixes, const schema::Schema& s,
                                 ObId ob, std::size_t i) {
        prefixes.resize(s.num_obs());
        std::string& prefix = prefixes[ob.index()];
        if (prefix.empty()) {
            prefix = ascii_lowercase(s.ob(ob).name) + "@";
        }
        return prefix + std::to_string(i + 1);
    }

    // Step i with the target's own actions (correspond.hpp): the corresponding target action at
    // the generated action's match, else a repair from Y_{i-1} to Δ_F(X_i) (repair.hpp).
    bool own_action_step(std::size_t i, const ActionPair& a, ACSetMorphism m) {
        const auto& own = *options_.target_actions;
        const Correspondence* c = a.target ? own.find(a.target->name) : nullptr;
        std::vector<ACSetMorphism> matches;
        if (c != nullptr) {
            rewrite::MatchOptions opt;
            opt.initial = carried_bindings(a, m, *x_, *y_, renaming_);
            opt.max_results = 1;
            matches = rewrite::find_matches(*a.target, y_->state(), opt);
        }
        StepTransfer st;
        st.source = plan_.steps[i];
        if (options_.describe_bindings) {
            st.source_bindings = describe_bindings(m, a.source->L, x_->state());
        }
        if (!matches.empty() && comparing()) {
            check_->before(m, *x_, matches[0], *y_);
        }
        // Where nothing corresponds, the generated action bound as the source step binds it
        // (read before the source step changes X), where a repair would start from its sides.
        std::optional<GeneratedStep> generated;
        if (matches.empty() && a.target != nullptr &&
            repairer().searches_generated(plan_.steps[i].action)) {
            generated.emplace();
            generated->rule = a.target;
            generated->bindings = carried_bindings(a, m, *x_, *y_, renaming_);
        }
        auto r_to_x = apply_source(i, *a.source, m);
        CATPLAN_ASSERT(r_to_x, "a valid source match failed to apply");
        if (!matches.empty()) {
            corresponding_step(i, a, *c, matches[0], *r_to_x, st);
        } else if (!repaired_step(i, c, st, generated ? &*generated : nullptr)) {
            return false;
        }
        st.source_comatch = *r_to_x;
        if (options_.follow_source) {
            follow_source();
        }
        st.source_match = std::move(m);
        out_.steps.push_back(std::move(st));
        return true;
    }

    // The target action c corresponds to, at the generated action's match mg; a part it creates
    // is named as the generated action would name it.
    void corresponding_step(std::size_t i, const ActionPair& a, const Correspondence& c,
                            const ACSetMorphism& mg, const ACSetMorphism& r_to_x,
                            StepTransfer& st) {
        ACSetMorphism mt = transport(mg, c);
        st.kind = StepTransfer::Kind::Corresponds;
        st.target = step_of(*c.target, mt, y_->state());
        if (options_.describe_bindings) {
            st.target_bindings = describe_bindings(mt, c.target->L, y_->state());
        }
        auto applied = y_->apply(*c.target, mt, [&](ObId ob, Part q) {
            const auto& origin = a.r_origins[ob.index()];
            Part qg = generated_part(c, ob, q);
            if (!origin || qg >= origin->parts.size()) {
                return created_name(ob, i);
            }
            Part in_x = r_to_x.components[origin->ob.index()][origin->parts[qg]];
            return renamed(renaming_, x_->state().part_name(origin->ob, in_x));
        });
        CATPLAN_ASSERT(applied, "a corresponding action applies where its generated one does");
        if (comparing()) {
            // The generated action's comatch is the target action's after φ_R.
            if (auto d = check_->after(i, r_to_x, *x_, hom::compose(c.r_iso, *applied), *y_)) {
                d->where = where(i);
                out_.verdict.divergences.push_back(std::move(*d));
            }
        }
        st.target_steps = {st.target};
        st.target_match = std::move(mt);
    }

    // A repair: the target's own actions from Y_{i-1} to a state that holds Δ_F(X_i).
    bool repaired_step(std::size_t i, const Correspondence* c, StepTransfer& st,
                       const GeneratedStep* generated) {
        ACSet subgoal = migrate::migrate(f_, x_->state());
        rename_parts(subgoal, renaming_);
        auto repair = repairer().repair(
            *y_, subgoal, i, [&](NamedState& z, ObId ob) { return created_name(z, ob, i); },
            &plan_.steps[i], generated);
        if (!repair.found) {
            return fail_at(i, fmt::format("{}; repair: {}",
                                          c == nullptr ? "no target action corresponds"
                                                       : "the corresponding action has no "
                                                         "match in the target",
                                          repair.why));
        }
        if (repair.reached) {
            // The steps replayed from Y_{i-1}, checked there; Y_{i-1}'s memory serves the next.
            std::swap(*y_, *repair.reached);
            repairer_->recycle(std::move(*repair.reached));
        }
        if (comparing()) {
            // The repair reaches a state that holds Δ_F(X_i); whether it is Δ_F(X_i) is checked.
            if (auto d = check_->compare_repaired(i, subgoal, *y_, repair.by_names)) {
                d->where = where(i);
                out_.verdict.divergences.push_back(std::move(*d));
            }
        }
        st.kind = StepTransfer::Kind::Repaired;
        st.target_steps = std::move(repair.steps);
        st.repair_stats = repair.stats;
        st.repair_focus = repair.focus_parts;
        st.repair_from_action = repair.from_action;
        st.repair_reused_from = repair.reused_from;
        st.repair_cost = repair.cost;
        st.repair_least_cost = repair.least_cost;
        return true;
    }

    // Whether this step's target state is compared with Δ_F of the source state: every step
    // when following the source, else until the first divergence (the later target states are
    // not comparable with the source's).
    bool comparing() const {
        return check_ && (options_.follow_source || out_.verdict.divergences.empty());
    }

    // The repairer of this transfer, made at the first repair.
    Repairer& repairer() {
        if (!repairer_) {
            const auto& own = *options_.target_actions;
            repairer_.emplace(own.domain, options_.repair, options_.target_values);
        }
        return *repairer_;
    }

    // Y_i := Δ_F(X_i), named as Y_0 was.
    void follow_source() {
        ACSet z = migrate::migrate(f_, x_->state());
        rename_parts(z, renaming_);
        y_.emplace(std::move(z));
        check_->reset();
    }

    std::string migration_failure(const std::string& action) const {
        for (const auto& [name, why] : out_.target_domain.failures) {
            if (name == action) {
                return why;
            }
        }
        return "unknown reason";
    }

    void source_failure(std::size_t i, const std::string& why) {
        out_.verdict.faults.push_back(worded({Fault::Kind::SourcePlan, i, where(i), why}));
    }

    // A source-plan fault in the words of the user's own validator (TransferOptions::source_fault)
    // where it finds the same step at fault, else as the rule steps word it.
    Fault worded(Fault f) const {
        if (options_.source_fault) {
            if (auto own = options_.source_fault(); own && own->step == f.step) {
                own->kind = Fault::Kind::SourcePlan;
                return *own;
            }
        }
        return f;
    }

    // The source plan's fault when the replay did not stop in the source: its goal not reached,
    // or, when the target stopped first, whatever validating the source plan on its own finds.
    std::optional<Fault> finish_source() const {
        const auto& faults = out_.verdict.faults;
        if (!faults.empty()) {
            if (faults.front().kind == Fault::Kind::SourcePlan) {
                return std::nullopt;
            }
            auto v = plan::validate_plan(problem_, plan_);
            if (v.valid) {
                return std::nullopt;
            }
            // validate_plan words a step's reason as "step 3 pickup(B): why".
            return worded(Fault::from_reason(Fault::Kind::SourcePlan, v.failed_step,
                                             v.failed_step ? where(*v.failed_step) : "", v.reason));
        }
        auto g = plan::embed_goal(*problem_.goal, problem_.goal_conditions, x_->state());
        if (g) {
            return std::nullopt;
        }
        return worded(
            Fault{Fault::Kind::SourcePlan, std::nullopt, {}, "goal not reached: " + g.error()});
    }

    const SchemaMap& f_;
    const plan::Problem& problem_;
    const plan::Plan& plan_;
    const TransferOptions& options_;
    TransferResult& out_;
    Renaming renaming_;
    std::optional<NamedState> x_, y_;
    std::optional<DivergenceCheck> check_;
    std::optional<Repairer> repairer_;
    std::map<std::string, ActionPair, std::less<>> actions_;
    std::vector<std::string> source_prefixes_, target_prefixes_; // step_name's
};

// What makes f conjunctive, named: the first target object sent to a query, hom sent to a
// query's variable or attribute sent to a value.
std::string not_delta(const SchemaMap& f) {
    const auto& t = *f.target();
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        if (!f.query(ObId(c)).is_plain()) {
            return fmt::format("it sends {} to a query", t.ob(ObId(c)).name);
        }
    }
    for (std::uint32_t h = 0; h < t.num_homs(); ++h) {
        if (!f.hom_image(HomId(h)).path) {
            return fmt::format("it sends {} to a variable of a query", t.hom(HomId(h)).name);
        }
    }
    for (std::uint32_t a = 0; a < t.num_attrs(); ++a) {
        if (f.attr_image(AttrId(a)).kind == migrate::AttrImage::Kind::Value) {
            return fmt::format("it sends {} to a computed value", t.attr(AttrId(a)).name);
        }
    }
    return "it is not a delta map";
}

// Why a rule that holds each fact of its relations once (a DPO step followed by merging an
// added fact into an equal one) does not commute with Δ_F: a target object on one of its
// relations that is not a relation of the target (it forgets an argument); "" when none.
std::string facts_kept(const SchemaMap& f, const rewrite::Rule& rule) {
    if (rule.relations.empty()) {
        return "";
    }
    auto kept = migrate::migrate_relations(f, rule.relations);
    const auto& t = *f.target();
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        const auto& q = f.query(ObId(c));
        if (!q.is_plain() || std::find(rule.relations.begin(), rule.relations.end(),
                                       q.nodes()[0].ob) == rule.relations.end()) {
            continue;
        }
        if (std::find(kept.begin(), kept.end(), ObId(c)) == kept.end()) {
            return fmt::format("rule {} holds each {} fact once and the target's {} does not "
                               "see all of its arguments: Δ_F may hold one fact twice",
                               rule.name, f.source()->ob(q.nodes()[0].ob).name, t.ob(ObId(c)).name);
        }
    }
    return "";
}

// The claim of Appendix A and its hypotheses: Δ_F preserves pushouts for a delta map, so each
// migrated DPO step at a monic match applies and Y_i = Δ_F(X_i), and the goal of a valid source
// plan embeds. An application condition is not preserved (Δ_F is not full: the migrated NAC may
// see less than the source NAC), nor is SPO's deletion of dangling parts.
Claim valid_by_construction(const SchemaMap& f, const TransferResult& out,
                            const plan::Problem& problem, const plan::Plan& plan) {
    Claim c;
    c.kind = Claim::Kind::ValidByConstruction;
    bool delta = out.migration == MigrationKind::Delta;
    c.hypotheses.push_back(
        {"F is a delta map (Δ_F preserves pushouts)", delta, delta ? "" : not_delta(f)});
    std::string conditions, spo, facts;
    for (const auto& step : plan.steps) {
        const auto* rule = problem.domain->find_rule(step.action);
        if (rule == nullptr) {
            continue;
        }
        if (facts.empty()) {
            facts = facts_kept(f, *rule);
        }
        if (conditions.empty() && !rule->conditions.empty()) {
            conditions = fmt::format("rule {} has a {} application condition", rule->name,
                                     rule->conditions.front().negative ? "negative" : "positive");
        }
        if (spo.empty() && rule->semantics == rewrite::Semantics::SPO) {
            spo = fmt::format("rule {} deletes dangling parts (SPO)", rule->name);
        }
    }
    c.hypotheses.push_back({"no rule the plan uses has an application condition (Δ_F does not "
                            "preserve them)",
                            conditions.empty(), conditions});
    c.hypotheses.push_back({"every rule the plan uses is a DPO rule", spo.empty(), spo});
    c.hypotheses.push_back({"each object whose facts a rule the plan uses holds once is sent to "
                            "facts held once in the target (Δ_F keeps each fact once)",
                            facts.empty(), facts});
    std::string not_monic;
    for (std::size_t i = 0; i < out.steps.size() && not_monic.empty(); ++i) {
        for (auto component : out.steps[i].source_match.components) {
            std::sort(component.begin(), component.end());
            if (std::adjacent_find(component.begin(), component.end()) != component.end()) {
                not_monic = fmt::format("the match of step {} identifies parts", i + 1);
            }
        }
    }
    c.hypotheses.push_back({"every match is monic", not_monic.empty(), not_monic});
    // A target action with the same span as the migrated one is the same step; a repair is not.
    std::string repaired;
    for (std::size_t i = 0; i < out.steps.size() && repaired.empty(); ++i) {
        if (out.steps[i].kind == StepTransfer::Kind::Repaired) {
            repaired = fmt::format("step {} is repaired with the target's own actions", i + 1);
        }
    }
    c.hypotheses.push_back({"every step is carried out by its migrated action or one with the "
                            "same span (none is repaired)",
                            repaired.empty(), repaired});
    const Fault* source = out.verdict.find(Fault::Kind::SourcePlan);
    c.hypotheses.push_back({"the source plan is valid", source == nullptr,
                            source ? headline(*source) : std::string()});
    return c;
}

// The goal checks and the verdict: Δ_F(G) embedded monically in y, then the source plan's own
// fault, then the intended goal, if the options give one.
void judge(TransferResult& out, const ACSet& y, std::optional<Fault> source,
           const TransferOptions& options) {
    auto t0 = Clock::now();
    Verdict& v = out.verdict;
    v.trajectory = options.follow_source ? Trajectory::FollowSource : Trajectory::Own;
    if (options.strict) {
        for (const auto& d : v.divergences) {
            v.faults.push_back(
                {Fault::Kind::Divergence, d.step, d.where,
                 fmt::format("the target state is not Δ_F(X{}): {}", d.step + 1, d.difference())});
        }
    }
    auto embedding = plan::embed_goal(*out.target_goal, out.target_goal_conditions, y);
    if (!embedding) {
        v.faults.push_back(
            {Fault::Kind::Goal, std::nullopt, {}, "goal not reached: " + embedding.error()});
    }
    if (source) {
        v.faults.push_back(std::move(*source));
    }
    // A goal condition is one more statement: met when some embedding of the goal avoids it.
    auto count_conditions = [&](const ACSet& goal, const auto& conditions) {
        for (const auto& c : conditions) {
            ++v.goal.total;
            if (plan::embed_goal(goal, {c}, y)) {
                ++v.goal.satisfied;
            } else {
                v.goal.unsatisfied.push_back(c.name);
            }
        }
    };
    if (options.goal) {
        CATPLAN_ASSERT(&options.goal->schema() == &y.schema(),
                       "the intended goal must be on the map's target schema");
        v.goal = goal_satisfaction(*options.goal, y);
        count_conditions(*options.goal, options.goal_conditions);
        v.goal_name = options.goal_name;
        if (v.goal.satisfied != v.goal.total) {
            v.faults.push_back({Fault::Kind::IntendedGoal,
                                std::nullopt,
                                {},
                                fmt::format("the intended goal {} is not satisfied", v.goal_name)});
        } else if (auto m = plan::embed_goal(*options.goal, options.goal_conditions, y); !m) {
            v.faults.push_back(
                {Fault::Kind::IntendedGoal,
                 std::nullopt,
                 {},
                 fmt::format("the intended goal {} is not satisfied: {}", v.goal_name, m.error())});
        }
    } else if (embedding) {
        v.goal.total = count_goal_statements(*out.target_goal) + out.target_goal_conditions.size();
        v.goal.satisfied = v.goal.total;
    } else {
        v.goal = goal_satisfaction(*out.target_goal, y);
        count_conditions(*out.target_goal, out.target_goal_conditions);
    }
    v.status = v.faults.empty() ? Verdict::Status::Valid : Verdict::Status::Invalid;
    out.timings.validate_ms = ms_since(t0);
}

} // namespace

std::string_view to_string(MigrationKind kind) {
    return kind == MigrationKind::Delta ? "delta" : "conjunctive";
}

std::string_view to_string(StepTransfer::Kind kind) {
    switch (kind) {
    case StepTransfer::Kind::Corresponds:
        return "corresponds";
    case StepTransfer::Kind::Repaired:
        return "repaired";
    case StepTransfer::Kind::Generated:
        break;
    }
    return "generated";
}

MigratedDomain migrate_domain(const SchemaMap& f, const plan::Domain& d, const std::string& name) {
    auto domain = std::make_shared<plan::Domain>();
    domain->name = name.empty() ? fmt::format("{}_{}", d.name, f.target()->name()) : name;
    domain->schema = f.target();
    domain->range = d.range;
    MigratedDomain out;
    for (const auto& rule : d.rules) {
        auto migrated = migrate::migrate(f, *rule);
        if (migrated) {
            domain->rules.push_back(std::make_shared<rewrite::Rule>(std::move(*migrated)));
        } else {
            out.failures.emplace_back(rule->name, migrated.error());
        }
    }
    out.domain = std::move(domain);
    return out;
}

TransferResult transfer_plan(const SchemaMap& f, const plan::Problem& problem,
                             const plan::Plan& plan, const TransferOptions& options) {
    CATPLAN_ASSERT(f.ok(), "transfer along an unfinished or invalid map");
    auto t0 = Clock::now();
    TransferResult out;
    out.migration = f.is_delta() ? MigrationKind::Delta : MigrationKind::Conjunctive;
    auto source = Transfer(f, problem, plan, options, out).run();
    judge(out, *out.final_state, std::move(source), options);
    out.verdict.claims = {valid_by_construction(f, out, problem, plan)};
    out.timings.total_ms = ms_since(t0);
    return out;
}

std::vector<plan::Step> target_plan(const std::vector<StepTransfer>& steps) {
    std::vector<plan::Step> out;
    for (const auto& s : steps) {
        out.insert(out.end(), s.target_steps.begin(), s.target_steps.end());
    }
    return out;
}

plan::Step collapse_arguments(const rewrite::Rule& rule, const plan::Step& step) {
    plan::Step out;
    out.action = step.action;
    out.range = step.range;
    out.args = collapse(rule.parameters, step.args);
    return out;
}

std::size_t edit_distance(const std::vector<plan::Step>& a, const std::vector<plan::Step>& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            bool same = a[i - 1].action == b[j - 1].action && a[i - 1].args == b[j - 1].args;
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

plan::Problem target_problem(const TransferResult& t) {
    CATPLAN_ASSERT(t.target_domain.domain && t.target_initial && t.target_goal,
                   "a transfer's target problem");
    plan::Problem p;
    p.name = "target";
    p.domain = t.target_domain.domain;
    p.initial = t.target_initial;
    p.goal = t.target_goal;
    p.goal_conditions = t.target_goal_conditions;
    p.values = t.carried_values;
    p.counts_steps = t.counts_steps;
    plan::set_step_cost(p);
    return p;
}

std::optional<PlanCosts> plan_costs(const TransferResult& t, const plan::Problem& problem,
                                    const plan::Plan& plan) {
    bool generated = std::all_of(t.steps.begin(), t.steps.end(), [](const StepTransfer& s) {
        return s.kind == StepTransfer::Kind::Generated;
    });
    if (!problem.step_cost || !t.verdict.source_valid() || t.verdict.failed_step() != nullptr ||
        !generated || !t.target_domain.domain) {
        return std::nullopt;
    }
    plan::Problem target = target_problem(t);
    auto steps = target_plan(t.steps);
    // No generated action says a cost when only rules without one migrated: each costs 1.
    Result<std::int64_t> target_cost = target.step_cost
                                           ? plan::plan_cost(target, steps)
                                           : Result<std::int64_t>(std::int64_t(steps.size()));
    return PlanCosts{plan::plan_cost(problem, plan.steps), std::move(target_cost)};
}

Replan replan(const TransferResult& t, const plan::SearchOptions& options) {
    plan::Problem problem = target_problem(t);
    problem.name = "replan";
    Replan out;
    auto t0 = Clock::now();
    out.search = plan::find_plan(problem, options);
    out.ms = ms_since(t0);
    out.peak_rss_kib = peak_rss_kib();
    if (out.search.plan && problem.step_cost) {
        // None when the C-set search, which reads no costs, took a step without one.
        auto cost = plan::plan_cost(problem, out.search.plan->steps);
        out.cost = cost ? std::optional(*cost) : std::nullopt;
    }
    if (out.search.plan) {
        for (const auto& s : out.search.plan->steps) {
            const auto* rule = problem.domain->find_rule(s.action);
            out.steps.push_back(rule ? collapse_arguments(*rule, s) : s);
        }
    }
    out.edit_distance = edit_distance(target_plan(t.steps), out.steps);
    return out;
}

bool hit_limit(const Replan& r) {
    auto st = r.search.status;
    return st == plan::SearchStatus::NodeLimit || st == plan::SearchStatus::TimeLimit ||
           st == plan::SearchStatus::MemoryLimit;
}

std::string speedup_text(const Replan& r, double transfer_ms) {
    double ratio = r.ms / std::max(transfer_ms, 1e-6);
    if (hit_limit(r)) {
        return fmt::format("> {:.0f}x (replanning hit its {})", ratio,
                           plan::to_string(r.search.status));
    }
    return fmt::format("{:.0f}x", ratio);
}

} // namespace catplan::transfer
