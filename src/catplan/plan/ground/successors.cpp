#include "catplan/plan/ground/successors.hpp"

#include <algorithm>
#include <cstring>

namespace catplan::plan::ground {

bool holds(const StatePacker& packer, const Word* s, const std::vector<Fact>& facts) {
    return std::all_of(facts.begin(), facts.end(),
                       [&](const Fact& f) { return packer.get(s, f.var) == f.value; });
}

bool is_goal(const Task& task, const StatePacker& packer, const Word* s) {
    return std::any_of(task.goal.begin(), task.goal.end(),
                       [&](const std::vector<Fact>& term) { return holds(packer, s, term); });
}

bool apply(const Task& task, const StatePacker& packer, const Word* s, ActionId id, Word* out) {
    const Action& a = task.actions[id];
    if (!a.exit.empty()) {
        return false;
    }
    for (VarId v : a.creates) {
        if (packer.get(s, v) == 1) {
            return false; // present already (an action that removes it first needs it, so it
                          // is not in `creates`): the result would hold two equal parts
        }
    }
    std::memcpy(out, s, packer.bytes());
    for (const Fact& f : a.eff) {
        packer.set(out, f.var, f.value);
    }
    return true;
}

SuccessorGenerator::SuccessorGenerator(const Task& task, const StatePacker& packer)
    : task_(task), packer_(packer) {
    std::vector<std::pair<ActionId, std::uint32_t>> items;
    for (ActionId a = 0; a < task.actions.size(); ++a) {
        items.emplace_back(a, 0);
    }
    build(std::move(items));
}

// Builds the subtree of `items` (action, index of its next precondition); returns its node.
std::uint32_t SuccessorGenerator::build(std::vector<std::pair<ActionId, std::uint32_t>> items) {
    auto id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Node node;
    VarId var = kNone;
    for (auto [a, i] : items) {
        const auto& pre = task_.actions[a].pre;
        if (i == pre.size()) {
            node.actions.push_back(a);
        } else {
            var = std::min(var, pre[i].var);
        }
    }
    if (var != kNone) {
        node.var = var;
        std::vector<std::pair<ActionId, std::uint32_t>> any;
        std::vector<std::pair<std::uint32_t, std::vector<std::pair<ActionId, std::uint32_t>>>> by;
        for (auto [a, i] : items) {
            const auto& pre = task_.actions[a].pre;
            if (i == pre.size()) {
                continue;
            }
            if (pre[i].var != var) {
                any.emplace_back(a, i);
                continue;
            }
            std::uint32_t value = pre[i].value;
            auto it =
                std::find_if(by.begin(), by.end(), [&](const auto& e) { return e.first == value; });
            if (it == by.end()) {
                by.emplace_back(value, std::vector<std::pair<ActionId, std::uint32_t>>{});
                it = by.end() - 1;
            }
            it->second.emplace_back(a, i + 1);
        }
        std::sort(by.begin(), by.end(),
                  [](const auto& x, const auto& y) { return x.first < y.first; });
        for (auto& [value, sub] : by) {
            std::uint32_t child = build(std::move(sub));
            node.children.emplace_back(value, child);
        }
        if (!any.empty()) {
            node.any = build(std::move(any));
        }
    }
    nodes_[id] = std::move(node);
    return id;
}

bool SuccessorGenerator::rest_holds(const Word* s, const Action& a) const {
    for (const Fact& f : a.forbidden) {
        if (packer_.get(s, f.var) == f.value) {
            return false;
        }
    }
    for (const auto& clause : a.nacs) {
        if (holds(packer_, s, clause)) {
            return false;
        }
    }
    return true;
}

void SuccessorGenerator::applicable(const Word* s, std::vector<ActionId>& out) const {
    out.clear();
    if (nodes_.empty()) {
        return;
    }
    stack_.clear();
    stack_.push_back(0);
    while (!stack_.empty()) {
        const Node& n = nodes_[stack_.back()];
        stack_.pop_back();
        for (ActionId a : n.actions) {
            if (rest_holds(s, task_.actions[a])) {
                out.push_back(a);
            }
        }
        if (n.var == kNone) {
            continue;
        }
        if (n.any != kNone) {
            stack_.push_back(n.any);
        }
        std::uint32_t value = packer_.get(s, n.var);
        auto it = std::lower_bound(n.children.begin(), n.children.end(),
                                   std::pair<std::uint32_t, std::uint32_t>{value, 0});
        if (it != n.children.end() && it->first == value) {
            stack_.push_back(it->second);
        }
    }
    std::sort(out.begin(), out.end());
}

bool SuccessorGenerator::applies(const Word* s, ActionId a) const {
    const Action& act = task_.actions[a];
    return holds(packer_, s, act.pre) && rest_holds(s, act);
}

} // namespace catplan::plan::ground
