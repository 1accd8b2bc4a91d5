#include "catplan/plan/ground/heuristics.hpp"

#include "catplan/plan/ground/landmarks.hpp"

#include <algorithm>
#include <limits>

namespace catplan::plan::ground {

namespace {

constexpr int kInf = std::numeric_limits<int>::max();

class Blind final : public Evaluator {
public:
    explicit Blind(const Task& task) : task_(task) {}

    int evaluate(StateId, const std::vector<std::uint32_t>& state, const std::vector<ActionId>*,
                 std::vector<ActionId>*) override {
        for (const auto& term : task_.goal) {
            if (std::all_of(term.begin(), term.end(),
                            [&](const Fact& f) { return state[f.var] == f.value; })) {
                return 0;
            }
        }
        return 1;
    }

    bool admissible() const override { return true; }

private:
    const Task& task_;
};

class GoalCount final : public Evaluator {
public:
    explicit GoalCount(const Task& task) : task_(task) {}

    int evaluate(StateId, const std::vector<std::uint32_t>& state, const std::vector<ActionId>*,
                 std::vector<ActionId>*) override {
        int best = task_.goal.empty() ? kDeadEnd : kInf;
        for (const auto& term : task_.goal) {
            int h = 0;
            for (const Fact& f : term) {
                h += state[f.var] == f.value ? 0 : 1;
            }
            best = std::min(best, h);
        }
        return best;
    }

private:
    const Task& task_;
};

// h_add, h_max and h_FF: a generalised Dijkstra over the propositions from the state's, stopped
// when every goal proposition has its final cost (as Fast Downward's relaxation heuristics).
class Relaxation final : public Evaluator {
public:
    enum class Mode { Add, Max, FF };

    Relaxation(const RelaxedTask& r, Mode mode, Budget& budget)
        : r_(r), mode_(mode), budget_(budget) {
        goals_.assign(r.goal().begin(), r.goal().end());
        std::sort(goals_.begin(), goals_.end());
        goals_.erase(std::unique(goals_.begin(), goals_.end()), goals_.end());
    }

    int evaluate(StateId, const std::vector<std::uint32_t>& state, const std::vector<ActionId>*,
                 std::vector<ActionId>* preferred) override {
        explore(state);
        int h = 0;
        for (Prop g : goals_) {
            if (cost_[g] == kInf) {
                return kDeadEnd;
            }
            h = mode_ == Mode::Max ? std::max(h, cost_[g]) : h + cost_[g];
        }
        if (mode_ != Mode::FF) {
            return std::min(h, kDeadEnd - 1);
        }
        return relaxed_plan(preferred);
    }

    bool admissible() const override { return mode_ == Mode::Max; }

private:
    void explore(const std::vector<std::uint32_t>& state) {
        cost_.assign(r_.num_props(), kInf);
        supporter_.assign(r_.num_props(), kNone);
        unsat_.assign(r_.num_pres().begin(), r_.num_pres().end());
        acc_.assign(r_.num_actions(), 0);
        queue_.clear();
        r_.props_of(state, init_);
        for (Prop p : init_) {
            cost_[p] = 0;
            if (r_.needed(p)) {
                queue_.push(0, p); // popping it would fire nothing
            }
        }
        for (std::uint32_t a : r_.unconditional()) {
            fire(a);
        }
        if (mode_ == Mode::Max) {
            dijkstra<true>();
        } else {
            dijkstra<false>();
        }
    }

    // Pops propositions until every goal has its cost; an action fires when its last
    // precondition pops, at its cost plus the max (h_max) or sum (h_add) of theirs.
    template <bool Max>
    void dijkstra() {
        std::size_t open_goals = goals_.size();
        std::uint32_t pops = 0;
        while (!queue_.empty() && open_goals > 0) {
            auto [c, p] = queue_.pop();
            if (c > cost_[p]) {
                continue;
            }
            if ((++pops & 1023) == 0) {
                budget_.poll(); // the clock is read every 64th poll: per 65,536 propositions
            }
            if (r_.is_goal(p)) {
                --open_goals; // the goals are distinct and each pops once at its final cost
            }
            for (std::uint32_t a : r_.pre_of(p)) {
                acc_[a] = Max ? std::max(acc_[a], c) : std::min(acc_[a] + c, kDeadEnd);
                if (--unsat_[a] == 0) {
                    fire(a);
                }
            }
        }
    }

    void fire(std::uint32_t a) {
        int c = r_.cost(a) + acc_[a];
        for (Prop q : r_.add(a)) {
            if (c < cost_[q]) {
                cost_[q] = c;
                supporter_[q] = a;
                queue_.push(c, q);
            }
        }
    }

    // The relaxed plan of the best supporters (achiever() breaks their ties); its actions
    // applicable now are preferred. Every proposition it visits costs at most the goal's, so its
    // cost and supporter are final.
    int relaxed_plan(std::vector<ActionId>* preferred) {
        in_plan_.assign(r_.num_actions(), 0);
        marked_.assign(r_.num_props(), 0);
        mark_goal_side_effects();
        stack_.assign(goals_.begin(), goals_.end());
        int h = 0;
        while (!stack_.empty()) {
            Prop p = stack_.back();
            stack_.pop_back();
            if (marked_[p] || cost_[p] == 0) {
                continue;
            }
            marked_[p] = 1;
            std::uint32_t a = achiever(p);
            if (in_plan_[a]) {
                continue;
            }
            in_plan_[a] = 1;
            h += r_.cost(a);
            bool applicable = true;
            for (Prop q : r_.pre(a)) {
                stack_.push_back(q);
                applicable = applicable && cost_[q] == 0;
            }
            if (preferred != nullptr && applicable && r_.action(a) != kNone) {
                preferred->push_back(r_.action(a));
                preferred->insert(preferred->end(), r_.also(a).begin(), r_.also(a).end());
            }
        }
        return std::min(h, kDeadEnd - 1);
    }

    // Whether action b adds p at p's cost (p's supporter does; others may tie with it).
    bool least_achiever(std::uint32_t b, Prop p) const {
        return unsat_[b] == 0 && r_.cost(b) != 0 && r_.cost(b) + acc_[b] == cost_[p];
    }

    // The propositions that the supporters of the goal's propositions add at their own cost:
    // every relaxed plan that takes those supporters has them for free.
    void mark_goal_side_effects() {
        by_goal_.assign(r_.num_props(), 0);
        for (Prop g : goals_) {
            std::uint32_t a = supporter_[g];
            if (cost_[g] == 0 || r_.cost(a) == 0) {
                continue;
            }
            for (Prop q : r_.add(a)) {
                by_goal_[q] = by_goal_[q] != 0 || least_achiever(a, q) ? 1 : 0;
            }
        }
    }

    // The preconditions of action a that the state lacks and no goal supporter adds.
    int new_needs(std::uint32_t a) const {
        int n = 0;
        for (Prop q : r_.pre(a)) {
            n += cost_[q] != 0 && by_goal_[q] == 0 ? 1 : 0;
        }
        return n;
    }

    // p's supporter, unless another achiever of the same cost needs fewer propositions that
    // neither the state nor a goal's supporter gives. The supporter is the achiever found first,
    // so it depends on the order of the actions: on a grid of cells to visit, it may reach a cell
    // from one visited already (one more step in the relaxed plan) where another comes from a
    // cell that a goal's supporter enters anyway (Fast Downward gets that one by the order of
    // its operators; greedy search on hff stalls on visitall without it).
    std::uint32_t achiever(Prop p) const {
        std::uint32_t best = supporter_[p];
        int best_needs = new_needs(best);
        for (std::uint32_t b : r_.achievers(p)) {
            if (best_needs == 0) {
                break;
            }
            if (b == best || !least_achiever(b, p)) {
                continue; // not fired, free (a goal action), or costlier
            }
            int needs = new_needs(b);
            if (needs < best_needs) {
                best = b;
                best_needs = needs;
            }
        }
        return best;
    }

    const RelaxedTask& r_;
    Mode mode_;
    Budget& budget_;
    std::vector<Prop> goals_;
    std::vector<int> cost_, acc_;
    std::vector<std::uint32_t> supporter_, unsat_;
    std::vector<Prop> init_, stack_;
    std::vector<char> in_plan_, marked_, by_goal_;
    AdaptiveQueue queue_;
};

} // namespace

std::unique_ptr<Evaluator> make_evaluator(HeuristicKind kind, const Task& task,
                                          const RelaxedTask& relaxed, Budget& budget) {
    switch (kind) {
    case HeuristicKind::Blind:
        return std::make_unique<Blind>(task);
    case HeuristicKind::GoalCount:
        return std::make_unique<GoalCount>(task);
    case HeuristicKind::HAdd:
        return std::make_unique<Relaxation>(relaxed, Relaxation::Mode::Add, budget);
    case HeuristicKind::HMax:
        return std::make_unique<Relaxation>(relaxed, Relaxation::Mode::Max, budget);
    case HeuristicKind::Default:
    case HeuristicKind::HFF:
        return std::make_unique<Relaxation>(relaxed, Relaxation::Mode::FF, budget);
    case HeuristicKind::LmCut:
        return make_lm_cut(relaxed, budget);
    case HeuristicKind::LmCount:
        return make_landmark_count(task, relaxed, budget);
    }
    CATPLAN_UNREACHABLE("heuristic kind");
}

} // namespace catplan::plan::ground
