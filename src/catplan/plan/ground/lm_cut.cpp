// LM-cut (Helmert & Domshlak 2009): repeatedly compute h_max, find a cut of actions between the
// state and the goal zone (the propositions that reach the goal through zero-cost actions along
// h_max supporters), add the cut's least cost, and lower the cut's costs by it.

#include "catplan/plan/ground/heuristics.hpp"
#include "catplan/plan/ground/landmarks.hpp"

#include <algorithm>
#include <limits>
#include <tuple>

namespace catplan::plan::ground {

namespace {

constexpr int kInf = std::numeric_limits<int>::max();

class LmCut final : public Evaluator {
public:
    LmCut(const RelaxedTask& r, Budget& budget) : r_(r), budget_(budget) {}

    int evaluate(StateId, const std::vector<std::uint32_t>& state, const std::vector<ActionId>*,
                 std::vector<ActionId>*) override {
        cost_.assign(r_.costs().begin(), r_.costs().end());
        r_.props_of(state, init_);
        hmax();
        int h = 0;
        for (;;) {
            budget_.poll();
            int g = 0;
            for (Prop p : r_.goal()) {
                if (value_[p] == kInf) {
                    return kDeadEnd; // lowering costs reaches nothing new: only the first time
                }
                g = std::max(g, value_[p]);
            }
            if (g == 0) {
                return h;
            }
            mark_goal_zone();
            int m = cut();
            CATPLAN_ASSERT(m > 0 && m < kInf, "an LM-cut cut without a positive cost");
            h += m;
            for (std::uint32_t a : cut_) {
                cost_[a] -= m;
            }
            hmax_after_cut();
        }
    }

    bool admissible() const override { return true; }

private:
    // h_max under the current costs, with each action's supporter (its precondition of largest
    // value; kNone for an action with none).
    void hmax() {
        const std::size_t num_actions = r_.num_actions();
        value_.assign(r_.num_props(), kInf);
        queue_.clear();
        unsat_.assign(r_.num_pres().begin(), r_.num_pres().end());
        acc_.assign(num_actions, 0);
        supporter_.assign(num_actions, kNone);
        for (Prop p : init_) {
            value_[p] = 0;
            queue_.push(0, p);
        }
        for (std::uint32_t a : r_.unconditional()) {
            lower_effects(a, cost_[a]);
        }
        int c = 0;
        Prop p = 0;
        while (pop(c, p)) {
            for (std::uint32_t a : r_.pre_of(p)) {
                if (c >= acc_[a]) {
                    acc_[a] = c;
                    supporter_[a] = p; // the last precondition reached has the largest value
                }
                if (--unsat_[a] == 0) {
                    lower_effects(a, acc_[a] + cost_[a]);
                }
            }
        }
    }

    // h_max again after the cut's costs were lowered. Lower costs only lower values, so only
    // what the cut's actions reach can change: their effects are lowered and the change is
    // propagated, each action whose supporter got cheaper taking the largest of its
    // preconditions again (it may now be another one). Much cheaper than hmax() from scratch,
    // since a cut is small; the values are the same, a supporter among equals may differ.
    void hmax_after_cut() {
        for (std::uint32_t a : cut_) {
            lower_effects(a, acc_[a] + cost_[a]);
        }
        int c = 0;
        Prop p = 0;
        while (pop(c, p)) {
            for (std::uint32_t a : r_.pre_of(p)) {
                if (supporter_[a] != p || unsat_[a] != 0 || acc_[a] <= c) {
                    continue;
                }
                Prop best = p;
                for (Prop q : r_.pre(a)) {
                    best = value_[q] > value_[best] ? q : best;
                }
                supporter_[a] = best;
                if (value_[best] < acc_[a]) {
                    acc_[a] = value_[best];
                    lower_effects(a, acc_[a] + cost_[a]);
                }
            }
        }
    }

    // The next proposition of the queue whose value is still the one it was queued with.
    bool pop(int& c, Prop& p) {
        while (!queue_.empty()) {
            std::tie(c, p) = queue_.pop();
            if (c == value_[p]) {
                return true;
            }
        }
        return false;
    }

    // Lowers the values of a's effects to c where c is less, queueing them.
    void lower_effects(std::uint32_t a, int c) {
        for (Prop q : r_.add(a)) {
            if (c < value_[q]) {
                value_[q] = c;
                queue_.push(c, q);
            }
        }
    }

    // The goal zone: the goal fact of largest h_max (the supporter of the goal's artificial
    // zero-cost action), and the supporters of zero-cost actions adding a zone member.
    void mark_goal_zone() {
        zone_.assign(r_.num_props(), 0);
        Prop seed = r_.goal().front();
        for (Prop g : r_.goal()) {
            if (value_[g] > value_[seed]) {
                seed = g;
            }
        }
        auto& stack = stack_;
        stack.assign(1, seed);
        zone_[seed] = 1;
        while (!stack.empty()) {
            Prop p = stack.back();
            stack.pop_back();
            for (std::uint32_t a : r_.achievers(p)) {
                Prop s = supporter_[a];
                if (cost_[a] == 0 && s != kNone && value_[s] != kInf && !zone_[s]) {
                    zone_[s] = 1;
                    stack.push_back(s);
                }
            }
        }
    }

    // The actions that cross from the part reachable from the state (along supporters, outside
    // the goal zone) into the goal zone; returns their least cost. An action is reached once at
    // most, from its supporter: into the cut if an effect is in the goal zone, and its other
    // effects are reached (they may lead to more of the cut).
    int cut() {
        cut_.clear();
        seen_.assign(r_.num_props(), 0);
        auto& stack = stack_;
        stack.clear();
        auto through = [&](std::uint32_t a) {
            bool crosses = false;
            for (Prop q : r_.add(a)) {
                if (zone_[q]) {
                    crosses = true;
                } else if (!seen_[q]) {
                    seen_[q] = 1;
                    stack.push_back(q);
                }
            }
            if (crosses) {
                cut_.push_back(a);
            }
        };
        for (Prop p : init_) {
            if (!zone_[p] && !seen_[p]) {
                seen_[p] = 1;
                stack.push_back(p);
            }
        }
        for (std::uint32_t a : r_.unconditional()) {
            through(a);
        }
        while (!stack.empty()) {
            Prop p = stack.back();
            stack.pop_back();
            for (std::uint32_t a : r_.pre_of(p)) {
                if (supporter_[a] == p && unsat_[a] == 0) {
                    through(a);
                }
            }
        }
        int m = kInf;
        for (std::uint32_t a : cut_) {
            m = std::min(m, cost_[a]);
        }
        return m;
    }

    const RelaxedTask& r_;
    Budget& budget_;
    std::vector<int> cost_, value_, acc_;
    std::vector<std::uint32_t> unsat_, cut_;
    std::vector<Prop> supporter_, init_;
    std::vector<Prop> stack_;
    std::vector<char> zone_, seen_;
    AdaptiveQueue queue_{AdaptiveQueue::Ties::LeastProposition};
};

} // namespace

std::unique_ptr<Evaluator> make_lm_cut(const RelaxedTask& relaxed, Budget& budget) {
    return std::make_unique<LmCut>(relaxed, budget);
}

} // namespace catplan::plan::ground
