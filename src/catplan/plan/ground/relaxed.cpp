#include "catplan/plan/ground/relaxed.hpp"

#include <algorithm>
#include <map>

namespace catplan::plan::ground {

RelaxedTask::RelaxedTask(const Task& task, CostType costs) {
    offset_.resize(task.vars.size());
    for (VarId v = 0; v < task.vars.size(); ++v) {
        offset_[v] = num_props_;
        num_props_ += task.vars[v].size();
    }
    var_props_ = num_props_;
    relaxed_of_.assign(task.actions.size(), kNone);
    // Absence is free in the relaxation (no action adds it): in preconditions, effects and goals.
    auto absent = [&](const Fact& f) {
        auto kind = task.vars[f.var].kind;
        return f.value == 0 && (kind == Variable::Kind::Presence || kind == Variable::Kind::Atom);
    };
    for (ActionId a = 0; a < task.actions.size(); ++a) {
        const Action& act = task.actions[a];
        if (!act.exit.empty()) {
            continue;
        }
        RelaxedAction r;
        r.action = a;
        r.cost = costs == CostType::One ? 1 : act.cost + (costs == CostType::PlusOne ? 1 : 0);
        for (const Fact& f : act.pre) {
            if (!absent(f)) {
                r.pre.push_back(prop(f));
            }
        }
        for (const Fact& f : act.eff) {
            if (!absent(f)) {
                r.add.push_back(prop(f));
            }
        }
        std::sort(r.pre.begin(), r.pre.end());
        std::sort(r.add.begin(), r.add.end());
        actions_.push_back(std::move(r));
    }
    drop_dominated(task);
    for (std::uint32_t i = 0; i < actions_.size(); ++i) {
        relaxed_of_[actions_[i].action] = i;
        for (ActionId b : actions_[i].also) {
            relaxed_of_[b] = i;
        }
    }
    if (task.goal.size() == 1) {
        for (const Fact& f : task.goal[0]) {
            if (!absent(f)) {
                goal_.push_back(prop(f));
            }
        }
    } else {
        Prop g = num_props_++;
        goal_.push_back(g);
        for (const auto& term : task.goal) {
            RelaxedAction r;
            r.cost = 0;
            for (const Fact& f : term) {
                if (!absent(f)) {
                    r.pre.push_back(prop(f));
                }
            }
            r.add.push_back(g);
            actions_.push_back(std::move(r));
        }
    }
    pre_of_.assign(num_props_, {});
    for (std::uint32_t i = 0; i < actions_.size(); ++i) {
        auto& pre = actions_[i].pre;
        std::sort(pre.begin(), pre.end());
        pre.erase(std::unique(pre.begin(), pre.end()), pre.end());
        if (pre.empty()) {
            unconditional_.push_back(i);
        }
        for (Prop p : pre) {
            pre_of_[p].push_back(i);
        }
    }
    index_achievers();
}

void RelaxedTask::index_achievers() {
    achievers_begin_.assign(num_props_ + 1, 0);
    for (const auto& a : actions_) {
        for (Prop p : a.add) {
            ++achievers_begin_[p + 1];
        }
    }
    for (Prop p = 0; p < num_props_; ++p) {
        achievers_begin_[p + 1] += achievers_begin_[p];
    }
    achievers_.resize(achievers_begin_[num_props_]);
    std::vector<std::uint32_t> next(achievers_begin_.begin(), achievers_begin_.end() - 1);
    for (std::uint32_t i = 0; i < actions_.size(); ++i) {
        for (Prop p : actions_[i].add) {
            achievers_[next[p]++] = i;
        }
    }
}

void RelaxedTask::drop_dominated(const Task& task) {
    // Candidates share the objects their matches send L's parts to (the variants of one PDDL
    // action at one binding do).
    std::map<std::vector<ObjectId>, std::vector<std::uint32_t>> groups;
    for (std::uint32_t i = 0; i < actions_.size(); ++i) {
        std::vector<ObjectId> key;
        for (const auto& per_ob : task.actions[actions_[i].action].match) {
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
    std::vector<char> gone(actions_.size(), 0);
    auto dominates = [&](const RelaxedAction& a, const RelaxedAction& b) {
        return a.cost <= b.cost &&
               std::includes(b.pre.begin(), b.pre.end(), a.pre.begin(), a.pre.end()) &&
               std::includes(a.add.begin(), a.add.end(), b.add.begin(), b.add.end());
    };
    for (const auto& [key, members] : groups) {
        for (std::uint32_t i : members) {
            for (std::uint32_t j : members) {
                if (i == j || gone[i] || gone[j] || !dominates(actions_[i], actions_[j])) {
                    continue;
                }
                gone[j] = 1;
                auto& also = actions_[i].also;
                also.push_back(actions_[j].action);
                also.insert(also.end(), actions_[j].also.begin(), actions_[j].also.end());
            }
        }
    }
    std::size_t kept = 0;
    for (std::uint32_t i = 0; i < actions_.size(); ++i) {
        if (!gone[i]) {
            if (kept != i) {
                actions_[kept] = std::move(actions_[i]);
            }
            ++kept;
        }
    }
    actions_.resize(kept);
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

FlatRelaxation::FlatRelaxation(const RelaxedTask& r) {
    const auto& actions = r.actions();
    pre_begin.reserve(actions.size() + 1);
    add_begin.reserve(actions.size() + 1);
    for (const auto& a : actions) {
        pre_begin.push_back(static_cast<std::uint32_t>(pres.size()));
        pres.insert(pres.end(), a.pre.begin(), a.pre.end());
        add_begin.push_back(static_cast<std::uint32_t>(adds.size()));
        adds.insert(adds.end(), a.add.begin(), a.add.end());
        cost.push_back(a.cost);
        num_pre.push_back(static_cast<std::uint32_t>(a.pre.size()));
    }
    pre_begin.push_back(static_cast<std::uint32_t>(pres.size()));
    add_begin.push_back(static_cast<std::uint32_t>(adds.size()));
    pre_of_begin.reserve(r.num_props() + 1);
    for (Prop p = 0; p < r.num_props(); ++p) {
        pre_of_begin.push_back(static_cast<std::uint32_t>(pre_ofs.size()));
        pre_ofs.insert(pre_ofs.end(), r.pre_of(p).begin(), r.pre_of(p).end());
    }
    pre_of_begin.push_back(static_cast<std::uint32_t>(pre_ofs.size()));
    is_goal.assign(r.num_props(), 0);
    for (Prop g : r.goal()) {
        is_goal[g] = 1;
    }
    needed.assign(r.num_props(), 0);
    for (Prop p = 0; p < r.num_props(); ++p) {
        needed[p] = is_goal[p] != 0 || pre_of_begin[p] != pre_of_begin[p + 1] ? 1 : 0;
    }
}

} // namespace catplan::plan::ground
