#include "catplan/plan/ground/relaxed.hpp"

#include <algorithm>

namespace catplan::plan::ground {

RelaxedTask::RelaxedTask(const Task& task) {
    offset_.resize(task.vars.size());
    for (VarId v = 0; v < task.vars.size(); ++v) {
        offset_[v] = num_props_;
        num_props_ += task.vars[v].size();
    }
    var_props_ = num_props_;
    relaxed_of_.assign(task.actions.size(), kNone);
    for (ActionId a = 0; a < task.actions.size(); ++a) {
        const Action& act = task.actions[a];
        if (!act.exit.empty()) {
            continue;
        }
        RelaxedAction r;
        r.action = a;
        for (const Fact& f : act.pre) {
            r.pre.push_back(prop(f));
        }
        for (const Fact& f : act.eff) {
            r.add.push_back(prop(f));
        }
        relaxed_of_[a] = static_cast<std::uint32_t>(actions_.size());
        actions_.push_back(std::move(r));
    }
    if (task.goal.size() == 1) {
        for (const Fact& f : task.goal[0]) {
            goal_.push_back(prop(f));
        }
    } else {
        Prop g = num_props_++;
        goal_.push_back(g);
        for (const auto& term : task.goal) {
            RelaxedAction r;
            r.cost = 0;
            for (const Fact& f : term) {
                r.pre.push_back(prop(f));
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
