#include "catplan/transfer/repair.hpp"

#include "catplan/hom/hom_search.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"
#include "catplan/transfer/focus.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using hom::ACSetMorphism;

void add_stats(plan::SearchStats& into, const plan::SearchStats& s) {
    into.expanded += s.expanded;
    into.evaluated += s.evaluated;
    into.generated += s.generated;
    into.duplicates += s.duplicates;
    into.states += s.states;
    into.seconds += s.seconds;
    into.setup_seconds += s.setup_seconds;
    into.ground_seconds += s.ground_seconds;
    into.plans += s.plans;
}

// Whether goal embeds monically in x (any morphism; no reason is looked for when none does).
bool embeds(const ACSet& goal, const ACSet& x) {
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    opt.max_results = 1;
    return hom::is_homomorphic(goal, x, opt);
}

// The steps replayed as DPO steps on z (a copy of y), each match bound by names (through the index
// of names), created parts named by `name`, and the subgoal checked to embed in the result, by
// names, or (unless `by_names`) by any monic morphism: whether it embeds by names; or why the steps
// do not reach the subgoal.
Result<bool> replay(const plan::Domain& target, NamedState& z, const std::vector<plan::Step>& steps,
                    const ACSet& subgoal, bool by_names, const CreatedName& name) {
    for (const auto& step : steps) {
        const auto* rule = target.find_rule(step.action);
        if (rule == nullptr) {
            return fail(fmt::format("no action {} in the target", step.action));
        }
        auto m = match_by_names(*rule, z, step);
        if (!m) {
            return fail(m.error());
        }
        auto applied = z.apply(
            *rule, *m, [&](ObId ob, Part) { return name(z, ob); }, rewrite::CheckMatch::No);
        if (!applied) {
            return fail(applied.error());
        }
    }
    bool named = embeds_by_names(z, subgoal);
    if (!named && (by_names || !embeds(subgoal, z.state()))) {
        return fail("the subgoal does not embed in the state the steps reach");
    }
    return named;
}

// Whether every argument of the steps names a part of `initial`: a step of a focused plan that
// binds a part the plan created names it by its place in the focus, which the whole state does
// not share.
bool binds_initial_parts(const plan::Domain& target, const ACSet& initial,
                         const std::vector<plan::Step>& steps) {
    for (const auto& step : steps) {
        const auto* rule = target.find_rule(step.action);
        if (rule == nullptr || step.args.size() != rule->parameters.size()) {
            return false;
        }
        for (std::size_t i = 0; i < step.args.size(); ++i) {
            if (!initial.find_part(rule->parameters[i].ob, step.args[i])) {
                return false;
            }
        }
    }
    return true;
}

// The generated action's left side, each bound part named and valued as its part of y, and its
// right side, each part it keeps named and valued as on the left (a value the rule computes
// stays so): the problem of carrying out the generated action alone. The values make the goal's
// kept parts their namesakes (a block's name is an attribute), not any parts alike.
std::pair<ACSet, ACSet> generated_sides(const GeneratedStep& g, const NamedState& y) {
    const rewrite::Rule& rule = *g.rule;
    const auto& s = rule.K.schema();
    ACSet left = rule.L, right = rule.R;
    for (const auto& b : g.bindings) {
        left.set_part_name(b.ob, b.dom, y.state().part_name(b.ob, b.codom));
        for (AttrId a : s.attrs_from(b.ob)) {
            const auto& v = y.state().subpart(a, b.codom);
            if (v.is_concrete() && !left.subpart(a, b.dom).is_concrete()) {
                left.set_subpart(a, b.dom, v);
            }
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
            Part l = rule.l.components[o][k], r = rule.r.components[o][k];
            right.set_part_name(ob, r, left.part_name(ob, l));
            for (AttrId a : s.attrs_from(ob)) {
                const auto& v = right.subpart(a, r);
                std::uint32_t t = s.attr(a).codom.index();
                bool computed = v.is_var() && t < rule.exprs.size() &&
                                v.var_index() < rule.exprs[t].size() &&
                                rule.exprs[t][v.var_index()].has_value();
                if (!v.is_concrete() && !computed && left.subpart(a, l).is_concrete()) {
                    right.set_subpart(a, r, left.subpart(a, l));
                }
            }
        }
    }
    return {std::move(left), std::move(right)};
}

} // namespace

Repairer::Repairer(plan::DomainPtr target, RepairOptions options,
                   const std::optional<std::vector<plan::FunctionValue>>& values)
    : target_(std::move(target)), options_(std::move(options)) {
    costs_.domain = target_;
    if (values) {
        costs_.values = *values;
        plan::set_step_cost(costs_);
    }
    by_cost_ = costs_.step_cost && options_.least_cost;
    if (by_cost_) {
        greedy_ = options_.search;
        options_.search.search = plan::SearchKind::AStar;
        options_.search.heuristic = plan::HeuristicKind::Default; // LM-cut: admissible
        options_.search.anytime = false;
        values_.emplace(costs_.values, *target_);
    }
}

plan::ProblemPtr Repairer::problem(ACSet initial, ACSet goal) const {
    auto p = std::make_shared<plan::Problem>();
    p->name = "repair";
    p->domain = target_;
    p->initial = std::make_shared<const ACSet>(std::move(initial));
    p->goal = std::make_shared<const ACSet>(std::move(goal));
    p->step_cost = costs_.step_cost;
    return p;
}

bool Repairer::costed(const std::vector<plan::Step>& steps) const {
    return !costs_.step_cost || cost(steps).has_value();
}

std::optional<std::int64_t> Repairer::cost(const std::vector<plan::Step>& steps) const {
    if (!costs_.step_cost) {
        return std::nullopt;
    }
    auto c = plan::plan_cost(costs_, steps);
    return c ? std::optional(*c) : std::nullopt;
}

bool Repairer::least(const plan::SearchResult& r) const {
    return by_cost_ && r.costs && r.optimal;
}

void Repairer::take(Repair& out, std::vector<plan::Step> steps, NamedState&& reached, bool by_names,
                    bool least_cost) const {
    out.found = true;
    out.cost = cost(steps);
    out.least_cost = least_cost;
    out.steps = std::move(steps);
    out.reached.emplace(std::move(reached));
    out.by_names = by_names;
}

NamedState& Repairer::scratch_copy(const NamedState& y) {
    if (scratch_) {
        *scratch_ = y; // into the containers of a state the transfer is done with
    } else {
        scratch_.emplace(y);
    }
    return *scratch_;
}

void Repairer::recycle(NamedState&& old) {
    scratch_.emplace(std::move(old));
}

Repair Repairer::repair(const NamedState& y, const ACSet& subgoal, std::size_t step,
                        const CreatedName& name, const plan::Step* source,
                        const GeneratedStep* generated) {
    Request q{y, subgoal, step, name, source, generated};
    Repair out;
    if (embeds_by_names(y, subgoal)) {
        out.found = true;
        out.by_names = true;
        return out;
    }
    if (use_action_repair(q, out)) {
        return out;
    }
    if (generated_repair(q, out)) {
        remember_action_repair(q, out);
        return out;
    }
    // Every seed, for the focused problems (the check above stopped at the first difference).
    auto focus = Focus::of(y, subgoal);
    if (!(focus && focus_repair(q, *focus, out))) {
        if (embeds(subgoal, y.state())) {
            out.found = true; // by another morphism than the names'
            return out;
        }
        whole_repair(q, out);
    }
    remember_action_repair(q, out);
    return out;
}

// A focused problem's goal is reached by names (a focus may be too small to tell its parts apart
// otherwise): its ground task, compiled for it, is searched with the goal written by names; where
// the grounded search does not apply, the planner's own search (any monic morphism), which the
// replay on the whole state then checks by names.
plan::SearchResult Repairer::search_by_names(const plan::ProblemPtr& p,
                                             const plan::SearchOptions& options) const {
    if (options.ground) {
        plan::ground::CompileOptions small; // a focus: a few blocks, a few expansions
        small.mutexes = false;
        auto task = plan::ground::ReusableTask::compile(p, options, small);
        if (task) {
            auto r = task->search(p->initial, p->goal, options);
            if (r) {
                r->stats.ground_seconds += task->compile_seconds();
                return std::move(*r);
            }
        }
    }
    return plan::find_plan(*p, options);
}

// The plan that `memo` holds for a focus of this shape, renamed and replayed on y;
// `searched_before` says whether the shape was searched at all (a failed search need not be run
// again).
bool Repairer::use_memo(const Request& q, const RepairMemo& memo, const RepairShape& shape,
                        Repair& out, bool& searched_before) {
    const auto* e = memo.find(shape);
    searched_before = e != nullptr;
    if (e == nullptr || !e->solved) {
        return false;
    }
    auto steps = RepairMemo::renamed(*e, shape);
    if (!costed(steps)) {
        return false; // a step whose cost the target problem gives here no value
    }
    auto replayed = replay(*target_, scratch_copy(q.y), steps, q.subgoal, true, q.name);
    if (!replayed) {
        return false; // something outside the focus differs
    }
    // The same problem, values and all, up to names: the least here if it was where searched.
    take(out, std::move(steps), std::move(*scratch_), *replayed, e->least_cost);
    out.reused_from = e->origin;
    return true;
}

// The plans that repaired earlier steps of this source action, on this step's arguments, in the
// order they were found: the first that replays on the whole state. Not where repairs sum costs
// (a least-cost claim needs the shape with its values).
bool Repairer::use_action_repair(const Request& q, Repair& out) {
    if (by_cost_ || q.source == nullptr) {
        return false;
    }
    auto it = by_action_.find(q.source->action);
    if (it == by_action_.end()) {
        return false;
    }
    for (const auto& a : it->second) {
        std::vector<plan::Step> steps(a.actions.size());
        bool fits = true;
        for (std::size_t k = 0; k < steps.size() && fits; ++k) {
            steps[k].action = a.actions[k];
            for (std::uint32_t i : a.args[k]) {
                fits = fits && i < q.source->args.size();
                steps[k].args.push_back(fits ? q.source->args[i] : std::string());
            }
        }
        if (!fits || !costed(steps)) {
            continue;
        }
        auto replayed = replay(*target_, scratch_copy(q.y), steps, q.subgoal, true, q.name);
        if (!replayed) {
            continue; // another context: a block to clear first, a different place
        }
        take(out, std::move(steps), std::move(*scratch_), *replayed, false);
        out.reused_from = a.origin; // no focus was built: focus_parts stays 0
        return true;
    }
    return false;
}

// Remembers r's plan for q's source action when every argument of its steps is an argument of
// the source step (a plan that moves another part depends on where that part is).
void Repairer::remember_action_repair(const Request& q, const Repair& r) {
    if (by_cost_ || q.source == nullptr || !r.found || r.steps.empty()) {
        return;
    }
    auto& known = by_action_[q.source->action];
    if (known.size() >= kActionRepairs) {
        return;
    }
    ActionRepair a;
    a.origin = r.reused_from.value_or(q.step);
    const auto& source_args = q.source->args;
    for (const auto& step : r.steps) {
        a.actions.push_back(step.action);
        auto& args = a.args.emplace_back();
        for (const auto& arg : step.args) {
            auto at = std::find(source_args.begin(), source_args.end(), arg);
            if (at == source_args.end()) {
                return;
            }
            args.push_back(static_cast<std::uint32_t>(at - source_args.begin()));
        }
    }
    bool seen = std::any_of(known.begin(), known.end(), [&](const ActionRepair& b) {
        return b.actions == a.actions && b.args == a.args;
    });
    if (!seen) {
        known.push_back(std::move(a));
    }
}

// Once per source action, for its first step that no earlier repair of the action serves: a
// plan of target actions from the generated action's left side to its right side (no other part
// of y), found by a breadth-first search of those few parts, then replayed on y and checked
// there as a focused plan is. The plan is remembered for the action's later steps.
bool Repairer::generated_repair(const Request& q, Repair& out) {
    if (by_cost_ || q.source == nullptr || q.generated == nullptr ||
        !generated_searched_.insert(q.source->action).second) {
        return false;
    }
    auto [left, right] = generated_sides(*q.generated, q.y);
    auto p = problem(std::move(left), std::move(right));
    plan::SearchOptions options = options_.search;
    options.search = plan::SearchKind::BreadthFirst;
    options.ground = false;
    if (options.max_nodes == 0 || options.max_nodes > options_.generated_max_nodes) {
        options.max_nodes = options_.generated_max_nodes;
    }
    auto r = plan::find_plan(*p, options);
    add_stats(out.stats, r.stats);
    if (r.status != plan::SearchStatus::Solved || r.plan->steps.empty() ||
        !binds_initial_parts(*target_, *p->initial, r.plan->steps) || !costed(r.plan->steps)) {
        return false;
    }
    auto replayed = replay(*target_, scratch_copy(q.y), r.plan->steps, q.subgoal, true, q.name);
    if (!replayed) {
        return false;
    }
    take(out, std::move(r.plan->steps), std::move(*scratch_), *replayed, false);
    out.from_action = true;
    return true;
}

bool Repairer::focus_repair(const Request& q, const Focus& focus, Repair& out) {
    if (focus.seeds() == 0) {
        return false;
    }
    std::size_t searched = 0; // the parts of the last focus searched (a larger radius adds some)
    plan::SearchOptions options = options_.search;
    if (options.max_nodes == 0 || options.max_nodes > options_.focus_max_nodes) {
        options.max_nodes = options_.focus_max_nodes;
    }
    options.validate = false; // a focused plan is replayed by names on the whole state below
    for (std::size_t radius : options_.radii) {
        auto fp = focus.problem(radius);
        if (fp.whole) {
            return false; // the whole state is searched next
        }
        if (fp.parts == searched) {
            continue;
        }
        searched = fp.parts;
        auto p = problem(std::move(fp.initial), std::move(fp.goal));
        // When costs are summed, the shape holds the values (a place of the same shape costs
        // the same) and the change's shape is not used (its frame may cost otherwise).
        auto shape = repair_shape(*p->initial, *p->goal, values_ ? &*values_ : nullptr);
        bool searched_before = false;
        if (shape && use_memo(q, memo_, *shape, out, searched_before)) {
            out.focus_parts = fp.parts;
            return true;
        }
        if (searched_before) {
            continue; // the same search, renamed, found nothing or nothing that replays here
        }
        // The same change in another frame: its plan, if it replays here, needs no search.
        auto change = by_cost_ ? std::nullopt : change_shape(*p->initial, *p->goal);
        bool changed_before = false;
        if (change && use_memo(q, changes_, *change, out, changed_before)) {
            if (shape) {
                memo_.remember(*shape, out.steps, *out.reused_from);
            }
            out.focus_parts = fp.parts;
            return true;
        }
        auto r = search_by_names(p, options);
        add_stats(out.stats, r.stats);
        if (r.status != plan::SearchStatus::Solved ||
            !binds_initial_parts(*target_, *p->initial, r.plan->steps) || !costed(r.plan->steps)) {
            if (shape && r.status != plan::SearchStatus::TimeLimit &&
                r.status != plan::SearchStatus::MemoryLimit) {
                memo_.remember_failure(*shape, q.step);
            }
            continue;
        }
        if (shape) {
            memo_.remember(*shape, r.plan->steps, q.step, least(r));
        }
        if (change) {
            changes_.remember(*change, r.plan->steps, q.step);
        }
        auto replayed = replay(*target_, scratch_copy(q.y), r.plan->steps, q.subgoal, true, q.name);
        if (!replayed) {
            continue;
        }
        take(out, std::move(r.plan->steps), std::move(*scratch_), *replayed, least(r));
        out.focus_parts = fp.parts;
        return true;
    }
    return false;
}

// One search of the whole state's problem: the target's ground task compiled at the first (within
// the repair's limits), else the problem's own search.
plan::SearchResult Repairer::search_whole(const plan::ProblemPtr& whole,
                                          const plan::SearchOptions& options) {
    if (options.ground && !task_ && why_no_task_.empty()) {
        auto task = plan::ground::ReusableTask::compile(whole, options_.search);
        if (task) {
            task_.emplace(std::move(*task));
        } else {
            why_no_task_ = task.error();
        }
    }
    if (task_) {
        auto reused = task_->search(whole->initial, whole->goal, options);
        // Unsolvable by names is not unsolvable: the repair's own problem is searched then.
        if (reused && !(reused->status == plan::SearchStatus::Unsolvable)) {
            return std::move(*reused);
        }
    }
    return plan::find_plan(*whole, options);
}

// The whole state: the target's ground task compiled once per transfer and searched from each
// state (plan/ground/reuse.hpp), else a search of the repair's own problem.
void Repairer::whole_repair(const Request& q, Repair& out) {
    auto whole = problem(q.y.state(), q.subgoal);
    plan::SearchResult r = search_whole(whole, options_.search);
    add_stats(out.stats, r.stats);
    if (greedy_ &&
        (r.status == plan::SearchStatus::NodeLimit || r.status == plan::SearchStatus::TimeLimit)) {
        // A* stopped where a greedy search may still find a repair, of no known least cost.
        r = search_whole(whole, *greedy_);
        add_stats(out.stats, r.stats);
    }
    if (r.status != plan::SearchStatus::Solved) {
        out.why = r.status == plan::SearchStatus::Unsolvable
                      ? std::string("no target plan reaches the migrated source state")
                      : fmt::format("the local search stopped at its {} ({} states expanded)",
                                    plan::to_string(r.status), out.stats.expanded);
        return;
    }
    if (!costed(r.plan->steps)) {
        out.why = "the plan found takes a step whose cost the target problem gives no value (the "
                  "C-set search reads no costs)";
        return;
    }
    auto replayed = replay(*target_, scratch_copy(q.y), r.plan->steps, q.subgoal, false, q.name);
    CATPLAN_ASSERT(replayed, "a plan the planner validated replays on its initial state");
    take(out, std::move(r.plan->steps), std::move(*scratch_), *replayed, least(r));
}

} // namespace catplan::transfer
