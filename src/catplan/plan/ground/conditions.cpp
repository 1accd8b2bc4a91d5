// Step 4 and 5 of the ground compiler (compile.hpp): the conditions of each action that need the
// whole universe, and the goal.

#include "catplan/plan/ground/grounding.hpp"
#include "catplan/plan/ground/matcher.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <set>

namespace catplan::plan::ground {

namespace {

class Conditions {
public:
    explicit Conditions(Universe& u) : u_(u), s_(u.s), task_(u.task) {}

    // Whether the action can still apply; adds its dangling and negative conditions.
    bool complete(Action& a) {
        const Rule& rule = *task_.problem->domain->rules[a.rule];
        pre_.clear();
        for (const Fact& f : a.pre) {
            pre_[f.var] = f.value;
        }
        if (!dangling(rule, a)) {
            return false;
        }
        for (const auto& c : rule.conditions) {
            if (!negative(rule, c, a)) {
                return false;
            }
        }
        a.pre.clear();
        for (auto [v, x] : pre_) {
            a.pre.push_back({v, x});
        }
        std::sort(a.forbidden.begin(), a.forbidden.end());
        a.forbidden.erase(std::unique(a.forbidden.begin(), a.forbidden.end()), a.forbidden.end());
        return true;
    }

private:
    bool require(VarId v, std::uint32_t value) {
        auto [it, fresh] = pre_.emplace(v, value);
        return fresh || it->second == value;
    }

    // var must not have value: a precondition for a two-valued variable, else a forbidden fact.
    bool forbid(Action& a, VarId v, std::uint32_t value) {
        if (task_.vars[v].size() == 2) {
            return require(v, 1 - value);
        }
        auto it = pre_.find(v);
        if (it != pre_.end()) {
            return it->second != value;
        }
        a.forbidden.push_back({v, value});
        return true;
    }

    // The dangling condition: every object or atom that may point to a deleted slot must be
    // deleted too, or kept with that hom redirected by the rule, or not point there.
    bool dangling(const Rule& rule, Action& a) {
        const auto& k_parts = rule.K;
        std::set<std::pair<std::uint64_t, std::uint32_t>> covered; // (image, hom)
        auto key = [](Image c) { return (std::uint64_t{c.atom} << 32) | c.id; };
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            for (Part k = 0; k < k_parts.num_parts(ob); ++k) {
                Part l = rule.l(ob, k);
                for (HomId f : s_.homs_from(ob)) {
                    if (k_parts.subpart(f, k) == kNoPart &&
                        rule.R.subpart(f, rule.r(ob, k)) != kNoPart) {
                        covered.insert({key(a.match[o][l]), f.index()});
                    }
                }
            }
            for (Part l : rule.deleted_parts(ob)) {
                for (HomId f : s_.homs_from(ob)) {
                    covered.insert({key(a.match[o][l]), f.index()});
                }
            }
        }
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            for (Part l : rule.deleted_parts(ob)) {
                Image d = a.match[o][l];
                if (d.atom) {
                    continue; // nothing points into an atom
                }
                for (HomId f : s_.homs_into(ob)) {
                    for (Image c : u_.pointing(f, d.id)) {
                        if (covered.contains({key(c), f.index()}) || !refers(c, f, d.id)) {
                            continue;
                        }
                        if (!may_not_refer(a, c, f, d.id)) {
                            return false;
                        }
                    }
                }
            }
        }
        return true;
    }

    std::uint32_t pos(HomId f) const { return u_.position[f.index()]; }

    // Whether c may point to target through f at all (its cell has that value somewhere).
    bool refers(Image c, HomId f, ObjectId target) const {
        if (c.atom) {
            return task_.atoms[c.id].homs[pos(f)] == target;
        }
        const Cell& cell = task_.homs[c.id][pos(f)];
        return cell.var == kNone ? cell.target == target
                                 : u_.find_hom_value(cell.var, target) != kNone;
    }

    // Adds the condition that c does not point to target; false when c always does.
    bool may_not_refer(Action& a, Image c, HomId f, ObjectId target) {
        if (c.atom) {
            return forbid(a, task_.atoms[c.id].var, 1);
        }
        const Cell& cell = task_.homs[c.id][pos(f)];
        if (cell.var == kNone) {
            return false;
        }
        // (An absent slot's cells are unset, so this holds for it too.)
        return forbid(a, cell.var, u_.find_hom_value(cell.var, target));
    }

    // A negative application condition: each extension of the match along L -> N gives the
    // facts under which N embeds; the action needs at least one of them false in each.
    bool negative(const Rule& rule, const rewrite::ApplicationCondition& c, Action& a) {
        Pattern pat;
        pat.p = &c.n_state;
        pat.unread = unread_variables(c.n_state, nullptr);
        pat.fixed.resize(s_.num_obs());
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            pat.fixed[o].assign(c.n_state.num_parts(ObId(o)), Image{});
            for (Part l = 0; l < rule.L.num_parts(ObId(o)); ++l) {
                pat.fixed[o][c.n(ObId(o), l)] = a.match[o][l];
            }
        }
        pat.bound.resize(s_.num_attr_types());
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            AttrTypeId ty(t);
            pat.bound[t].assign(c.n_state.num_vars(ty), Value());
            for (std::uint32_t v = 0; v < rule.L.num_vars(ty); ++v) {
                const Value& nv = c.n.var(ty, v);
                if (nv.is_var()) {
                    pat.bound[t][nv.var_index()] = a.bindings[t][v];
                }
            }
        }
        bool always = false;
        for_each_match(u_, pat, [&](const Match& m) {
            std::vector<Fact> clause;
            for (const Fact& f : m.facts) {
                auto it = pre_.find(f.var);
                if (it != pre_.end()) {
                    if (it->second != f.value) {
                        return true; // contradicts the action's own preconditions
                    }
                    continue;
                }
                clause.push_back(f);
            }
            if (clause.empty()) {
                always = true;
                return false;
            }
            std::sort(clause.begin(), clause.end());
            if (clause.size() == 1 && task_.vars[clause[0].var].size() == 2) {
                // One two-valued fact: a precondition on its other value.
                if (!require(clause[0].var, 1 - clause[0].value)) {
                    always = true;
                    return false;
                }
                return true;
            }
            a.nacs.push_back(std::move(clause));
            return true;
        });
        return !always;
    }

    Universe& u_;
    const schema::Schema& s_;
    Task& task_;
    std::map<VarId, std::uint32_t> pre_;
};

} // namespace

void finish_actions(Universe& u) {
    Conditions c(u);
    auto& actions = u.task.actions;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < actions.size(); ++i) {
        u.budget.poll();
        if (c.complete(actions[i])) {
            if (kept != i) {
                actions[kept] = std::move(actions[i]);
            }
            ++kept;
        }
    }
    actions.resize(kept);
}

namespace {

// The facts under which each extension of a goal match along a goal condition's n holds, less
// those the term already asks for; nullopt when one holds whenever the term does (or the
// condition is positive: the ground goal has no form for it).
std::optional<std::vector<std::vector<Fact>>>
condition_clauses(const Universe& u, const rewrite::ApplicationCondition& c, const Match& m,
                  const std::vector<Fact>& term) {
    if (!c.negative) {
        return std::nullopt;
    }
    const auto& s = *u.task.problem->domain->schema;
    const ACSet& goal = *u.task.problem->goal;
    Pattern pat;
    pat.p = &c.n_state;
    pat.fixed.resize(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        pat.fixed[o].assign(c.n_state.num_parts(ObId(o)), Image{});
        for (Part g = 0; g < goal.num_parts(ObId(o)); ++g) {
            pat.fixed[o][c.n(ObId(o), g)] = m.images[o][g];
        }
    }
    pat.bound.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        pat.bound[t].assign(c.n_state.num_vars(ty), Value());
        for (std::uint32_t v = 0; v < goal.num_vars(ty); ++v) {
            const Value& nv = c.n.var(ty, v);
            if (nv.is_var()) {
                pat.bound[t][nv.var_index()] = m.bindings[t][v];
            }
        }
    }
    std::vector<std::vector<Fact>> clauses;
    bool always = false;
    for_each_match(u, pat, [&](const Match& n) {
        std::vector<Fact> clause;
        for (const Fact& f : n.facts) {
            auto it = std::find_if(term.begin(), term.end(),
                                   [&](const Fact& t) { return t.var == f.var; });
            if (it != term.end() && it->value != f.value) {
                return true; // cannot hold together with the term
            }
            if (it == term.end()) {
                clause.push_back(f);
            }
        }
        always = clause.empty();
        clauses.push_back(std::move(clause));
        return !always;
    });
    if (always) {
        return std::nullopt;
    }
    return clauses;
}

// The terms that ask, besides `term`, that no clause hold entirely: one fact of each clause takes
// another value (the disjunction multiplied out); false when there are more than `limit`.
bool refine(const Task& task, const std::vector<Fact>& term,
            const std::vector<std::vector<Fact>>& clauses, std::size_t limit,
            std::set<std::vector<Fact>>& out) {
    std::vector<std::vector<Fact>> partial{term};
    for (const auto& clause : clauses) {
        std::vector<std::vector<Fact>> next;
        for (const auto& t : partial) {
            for (const Fact& f : clause) {
                for (std::uint32_t w = 0; w < task.vars[f.var].size(); ++w) {
                    auto it = std::find_if(t.begin(), t.end(),
                                           [&](const Fact& g) { return g.var == f.var; });
                    if (w == f.value || (it != t.end() && it->value != w)) {
                        continue;
                    }
                    auto grown = t;
                    if (it == t.end()) {
                        grown.push_back({f.var, w});
                    }
                    std::sort(grown.begin(), grown.end());
                    next.push_back(std::move(grown));
                }
            }
            if (next.size() > limit) {
                return false;
            }
        }
        std::sort(next.begin(), next.end());
        next.erase(std::unique(next.begin(), next.end()), next.end());
        partial = std::move(next);
    }
    out.insert(partial.begin(), partial.end());
    return out.size() <= limit;
}

} // namespace

std::optional<std::string> ground_goal(Universe& u, const CompileOptions& options) {
    auto& task = u.task;
    const auto& goal = task.problem->goal;
    const auto& conditions = task.problem->goal_conditions;
    task.goal.clear();
    if (goal == nullptr) {
        task.goal.push_back({});
        return std::nullopt;
    }
    Pattern pat;
    pat.p = goal.get();
    if (conditions.empty()) {
        pat.unread = unread_variables(*goal, nullptr); // else the conditions may read them
    }
    std::set<std::vector<Fact>> terms;
    bool too_many = false;
    bool positive = std::any_of(conditions.begin(), conditions.end(),
                                [](const auto& c) { return !c.negative; });
    if (positive) {
        return std::string("the goal has a positive condition");
    }
    for_each_match(u, pat, [&](const Match& m) {
        std::vector<Fact> term = m.facts;
        std::sort(term.begin(), term.end());
        // Each negative condition: no extension of m along it may hold.
        std::vector<std::vector<Fact>> clauses;
        for (const auto& c : conditions) {
            auto more = condition_clauses(u, c, m, term);
            if (!more) {
                return true; // this match always breaks the condition
            }
            clauses.insert(clauses.end(), more->begin(), more->end());
        }
        too_many = !refine(task, term, clauses, options.max_goal_terms, terms);
        return !too_many;
    });
    if (too_many) {
        return fmt::format("the goal holds in more than {} ways", options.max_goal_terms);
    }
    task.goal.assign(terms.begin(), terms.end());
    return std::nullopt;
}

} // namespace catplan::plan::ground
