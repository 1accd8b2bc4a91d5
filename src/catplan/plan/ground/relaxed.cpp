#include "catplan/plan/ground/relaxed.hpp"

#include <algorithm>
#include <map>

namespace catplan::plan::ground {

// A relaxed action while the task is built, before it is flattened.
struct RelaxedTask::Draft {
    std::vector<Prop> pre, add;
    int cost = 1;
    ActionId action = kNone;    // the ground action, or kNone for a goal action
    std::vector<ActionId> also; // the ground actions it stands for besides `action`
};

namespace {

// Absence is free in the relaxation (no action adds it): in preconditions, effects and goals.
bool absent(const Task& task, const Fact& f) {
    auto kind = task.vars[f.var].kind;
    return f.value == 0 && (kind == Variable::Kind::Presence || kind == Variable::Kind::Atom);
}

} // namespace

RelaxedTask::RelaxedTask(const Task& task, CostType costs) {
    offset_.resize(task.vars.size());
    for (VarId v = 0; v < task.vars.size(); ++v) {
        offset_[v] = num_props_;
        num_props_ += task.vars[v].size();
    }
    var_props_ = num_props_;
    std::vector<Draft> actions = drafts(task, costs);
    drop_dominated(task, actions);
    relaxed_of_.assign(task.actions.size(), kNone);
    for (std::uint32_t i = 0; i < actions.size(); ++i) {
        relaxed_of_[actions[i].action] = i;
        for (ActionId b : actions[i].also) {
            relaxed_of_[b] = i;
        }
    }
    add_goal_actions(task, actions);
    flatten(actions);
    index_by_proposition();
}

std::vector<RelaxedTask::Draft> RelaxedTask::drafts(const Task& task, CostType costs) const {
    std::vector<Draft> out;
    for (ActionId a = 0; a < task.actions.size(); ++a) {
        const Action& act = task.actions[a];
        if (!act.exit.empty()) {
            continue;
        }
        Draft r;
        r.action = a;
        r.cost = costs == CostType::One ? 1 : act.cost + (costs == CostType::PlusOne ? 1 : 0);
        for (const Fact& f : act.pre) {
            if (!absent(task, f)) {
                r.pre.push_back(prop(f));
            }
        }
        for (const Fact& f : act.eff) {
            if (!absent(task, f)) {
                r.add.push_back(prop(f));
            }
        }
        std::sort(r.pre.begin(), r.pre.end());
        r.pre.erase(std::unique(r.pre.begin(), r.pre.end()), r.pre.end());
        std::sort(r.add.begin(), r.add.end());
        out.push_back(std::move(r));
    }
    return out;
}

// A goal with one term is a set of propositions; one with several gets one more proposition,
// the goal, and a zero-cost action per term that adds it.
void RelaxedTask::add_goal_actions(const Task& task, std::vector<Draft>& actions) {
    if (task.goal.size() == 1) {
        for (const Fact& f : task.goal[0]) {
            if (!absent(task, f)) {
                goal_.push_back(prop(f));
            }
        }
        return;
    }
    Prop g = num_props_++;
    goal_.push_back(g);
    for (const auto& term : task.goal) {
        Draft r;
        r.cost = 0;
        for (const Fact& f : term) {
            if (!absent(task, f)) {
                r.pre.push_back(prop(f));
            }
        }
        std::sort(r.pre.begin(), r.pre.end());
        r.pre.erase(std::unique(r.pre.begin(), r.pre.end()), r.pre.end());
        r.add.push_back(g);
        actions.push_back(std::move(r));
    }
}

void RelaxedTask::flatten(const std::vector<Draft>& actions) {
    for (const Draft& a : actions) {
        pre_begin_.push_back(static_cast<std::uint32_t>(pres_.size()));
        pres_.insert(pres_.end(), a.pre.begin(), a.pre.end());
        add_begin_.push_back(static_cast<std::uint32_t>(adds_.size()));
        adds_.insert(adds_.end(), a.add.begin(), a.add.end());
        also_begin_.push_back(static_cast<std::uint32_t>(alsos_.size()));
        alsos_.insert(alsos_.end(), a.also.begin(), a.also.end());
        num_pre_.push_back(static_cast<std::uint32_t>(a.pre.size()));
        cost_.push_back(a.cost);
        action_.push_back(a.action);
    }
    pre_begin_.push_back(static_cast<std::uint32_t>(pres_.size()));
    add_begin_.push_back(static_cast<std::uint32_t>(adds_.size()));
    also_begin_.push_back(static_cast<std::uint32_t>(alsos_.size()));
}

namespace {

// Per proposition, the actions whose `props_of(a)` hold it, in one array with offsets.
template <class PropsOf>
void index(std::uint32_t num_props, std::uint32_t num_actions, PropsOf props_of,
           std::vector<std::uint32_t>& begin, std::vector<std::uint32_t>& out) {
    begin.assign(num_props + 1, 0);
    for (std::uint32_t a = 0; a < num_actions; ++a) {
        for (Prop p : props_of(a)) {
            ++begin[p + 1];
        }
    }
    for (Prop p = 0; p < num_props; ++p) {
        begin[p + 1] += begin[p];
    }
    out.resize(begin[num_props]);
    std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
    for (std::uint32_t a = 0; a < num_actions; ++a) {
        for (Prop p : props_of(a)) {
            out[next[p]++] = a;
        }
    }
}

} // namespace

void RelaxedTask::index_by_proposition() {
    index(
        num_props_, num_actions(), [this](std::uint32_t a) { return pre(a); }, pre_of_begin_,
        pre_ofs_);
    index(
        num_props_, num_actions(), [this](std::uint32_t a) { return add(a); }, achievers_begin_,
        achievers_);
    for (std::uint32_t a = 0; a < num_actions(); ++a) {
        if (num_pre_[a] == 0) {
            unconditional_.push_back(a);
        }
    }
    is_goal_.assign(num_props_, 0);
    for (Prop g : goal_) {
        is_goal_[g] = 1;
    }
    needed_.assign(num_props_, 0);
    for (Prop p = 0; p < num_props_; ++p) {
        needed_[p] = is_goal_[p] != 0 || !pre_of(p).empty() ? 1 : 0;
    }
}

void RelaxedTask::drop_dominated(const Task& task, std::vector<Draft>& actions) {
    // Candidates share the objects their matches send L's parts to (the variants of one PDDL
    // action at one binding do).
    std::map<std::vector<ObjectId>, std::vector<std::uint32_t>> groups;
    for (std::uint32_t i = 0; i < actions.size(); ++i) {
        std::vector<ObjectId> key;
        for (const auto& per_ob : task.actions[actions[i].action].match) {
            for (Image c : per_ob) {
                if (!c.atom) {
                    key.push_back(c.id);
                }
            }
        }
        std::sort(key.begin(), key.end());
        key.erase(std::unique(key.begin(), key.end()), key.end());
        groups[std::move(key)].push_back(i);
    }
    std::vector<char> gone(actions.size(), 0);
    auto dominates = [&](const Draft& a, const Draft& b) {
        return a.cost <= b.cost &&
               std::includes(b.pre.begin(), b.pre.end(), a.pre.begin(), a.pre.end()) &&
               std::includes(a.add.begin(), a.add.end(), b.add.begin(), b.add.end());
    };
    for (const auto& [key, members] : groups) {
        for (std::uint32_t i : members) {
            for (std::uint32_t j : members) {
                if (i == j || gone[i] || gone[j] || !dominates(actions[i], actions[j])) {
                    continue;
                }
                gone[j] = 1;
                auto& also = actions[i].also;
                also.push_back(actions[j].action);
                also.insert(also.end(), actions[j].also.begin(), actions[j].also.end());
            }
        }
    }
    std::size_t kept = 0;
    for (std::uint32_t i = 0; i < actions.size(); ++i) {
        if (!gone[i]) {
            if (kept != i) {
                actions[kept] = std::move(actions[i]);
            }
            ++kept;
        }
    }
    actions.resize(kept);
}

Fact RelaxedTask::fact(Prop p) const {
    if (p >= var_props_) {
        return {kNone, 0}; // the goal proposition
    }
    auto it = std::upper_bound(offset_.begin(), offset_.end(), p);
    auto var = static_cast<VarId>(std::distance(offset_.begin(), it) - 1);
    return {var, p - offset_[var]};
}

void RelaxedTask::props_of(const std::vector<std::uint32_t>& state, std::vector<Prop>& out) const {
    out.resize(state.size());
    for (VarId v = 0; v < state.size(); ++v) {
        out[v] = offset_[v] + state[v];
    }
}

} // namespace catplan::plan::ground
