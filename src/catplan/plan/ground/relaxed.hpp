#pragma once
// The delete relaxation of a ground task, shared by its heuristics: one proposition per variable
// value; per ground action its preconditions and its effects as adds, with forbidden facts and
// negative conditions dropped and exits left out; unit costs, or the task's for a search that sums
// them (CostType). Facts that a two-valued variable (presence of an atom or a slot) is absent are
// dropped from preconditions and effects, as STRIPS relaxations drop deletes and negative
// preconditions. Then an action is dropped when another needs no more, adds no less and costs no
// more (PDDL's rule variants, import.hpp, collapse to one): each relaxed action lists the ground
// actions it stands for, so preferred operators name them all. A goal with several terms gets one
// more proposition, the goal, and a zero-cost action per term that adds it, so every heuristic
// sees one conjunction.

#include "catplan/plan/ground/task.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

namespace catplan::plan::ground {

using Prop = std::uint32_t;

/// What an action costs in the relaxation: 1 (Fast Downward's cost_type=one), the task's cost
/// (normal), or the task's cost plus 1 (plusone: LAMA's later iterations, where zero-cost actions
/// still lengthen a relaxed plan).
enum class CostType : std::uint8_t { One, Normal, PlusOne };

/// A relaxed task in flat arrays (offsets into one array per kind): the explorations touch every
/// reachable action per state (h_add, h_max, h_FF, LM-cut) and read memory in order. Relaxed
/// actions are numbered from 0; the goal actions come last.
class RelaxedTask {
public:
    /// The relaxation of task, its actions costing as `costs` says.
    explicit RelaxedTask(const Task& task, CostType costs = CostType::One);

    std::uint32_t num_props() const { return num_props_; }

    std::uint32_t num_actions() const { return static_cast<std::uint32_t>(cost_.size()); }

    Prop prop(Fact f) const { return offset_[f.var] + f.value; }

    Prop prop(VarId var, std::uint32_t value) const { return offset_[var] + value; }

    /// The fact a proposition stands for (the goal proposition has var kNone).
    Fact fact(Prop p) const;

    /// Relaxed action a's preconditions, sorted and distinct.
    std::span<const Prop> pre(std::uint32_t a) const { return slice(pres_, pre_begin_, a); }

    /// Relaxed action a's adds, sorted.
    std::span<const Prop> add(std::uint32_t a) const { return slice(adds_, add_begin_, a); }

    int cost(std::uint32_t a) const { return cost_[a]; }

    /// Every relaxed action's cost, by action.
    const std::vector<int>& costs() const { return cost_; }

    /// Every relaxed action's number of preconditions, by action.
    const std::vector<std::uint32_t>& num_pres() const { return num_pre_; }

    /// The ground action relaxed action a stands for, or kNone for a goal action.
    ActionId action(std::uint32_t a) const { return action_[a]; }

    /// The ground actions relaxed action a stands for besides action(a) (dominated variants).
    std::span<const ActionId> also(std::uint32_t a) const { return slice(alsos_, also_begin_, a); }

    /// The relaxed actions with proposition p as a precondition.
    std::span<const std::uint32_t> pre_of(Prop p) const {
        return slice(pre_ofs_, pre_of_begin_, p);
    }

    /// The relaxed actions that add proposition p, in the order of their numbers.
    std::span<const std::uint32_t> achievers(Prop p) const {
        return slice(achievers_, achievers_begin_, p);
    }

    /// The relaxed actions with no precondition.
    const std::vector<std::uint32_t>& unconditional() const { return unconditional_; }

    const std::vector<Prop>& goal() const { return goal_; }

    bool is_goal(Prop p) const { return is_goal_[p] != 0; }

    /// Whether p is a goal or a precondition (an absent atom is neither).
    bool needed(Prop p) const { return needed_[p] != 0; }

    /// The propositions true in a state (a value per variable), sorted.
    void props_of(const std::vector<std::uint32_t>& state, std::vector<Prop>& out) const;

    /// The relaxed action of each ground action (kNone for an exit).
    std::uint32_t relaxed_of(ActionId a) const { return relaxed_of_[a]; }

private:
    struct Draft;

    template <class T>
    static std::span<const T> slice(const std::vector<T>& all,
                                    const std::vector<std::uint32_t>& begin, std::uint32_t i) {
        return {all.data() + begin[i], all.data() + begin[i + 1]};
    }

    std::vector<Draft> drafts(const Task& task, CostType costs) const;
    static void drop_dominated(const Task& task, std::vector<Draft>& drafts);
    void add_goal_actions(const Task& task, std::vector<Draft>& drafts);
    void flatten(const std::vector<Draft>& drafts);
    void index_by_proposition();

    std::vector<std::uint32_t> offset_;
    std::uint32_t num_props_ = 0, var_props_ = 0;
    std::vector<std::uint32_t> pre_begin_, add_begin_, also_begin_, num_pre_;
    std::vector<Prop> pres_, adds_;
    std::vector<ActionId> alsos_, action_;
    std::vector<int> cost_;
    std::vector<std::uint32_t> pre_of_begin_, pre_ofs_;      // per proposition, in one array
    std::vector<std::uint32_t> achievers_begin_, achievers_; // per proposition, in one array
    std::vector<std::uint32_t> unconditional_;
    std::vector<Prop> goal_;
    std::vector<char> is_goal_, needed_;
    std::vector<std::uint32_t> relaxed_of_;
};

/// Propositions by cost, least first, for the explorations' Dijkstras: buckets for small costs
/// (Dial's algorithm), a binary heap for the rare large ones (h_add's sums). Of equal costs, the
/// proposition pushed last pops first (Fast Downward's order), or with Ties::LeastProposition the
/// least proposition (each bucket a heap), which decides LM-cut's supporters among equals.
class AdaptiveQueue {
public:
    enum class Ties : std::uint8_t { LastPushed, LeastProposition };

    explicit AdaptiveQueue(Ties ties = Ties::LastPushed) : ties_(ties) {}

    void clear() {
        for (std::size_t i = 0; i < used_; ++i) {
            buckets_[i].clear();
        }
        heap_.clear();
        current_ = used_ = size_ = 0;
    }

    void push(int cost, Prop p) {
        auto c = static_cast<std::size_t>(cost);
        if (c < buckets_.size()) [[likely]] {
            buckets_[c].push_back(p);
            if (ties_ == Ties::LeastProposition) {
                std::push_heap(buckets_[c].begin(), buckets_[c].end(), std::greater<>());
            }
            used_ = std::max(used_, c + 1);
            current_ = std::min(current_, c);
            ++size_;
        } else {
            push_slow(cost, p);
        }
    }

    bool empty() const { return size_ == 0; }

    std::pair<int, Prop> pop() {
        --size_;
        while (current_ < used_ && buckets_[current_].empty()) {
            ++current_;
        }
        if (current_ < used_) {
            auto& bucket = buckets_[current_];
            if (ties_ == Ties::LeastProposition) {
                std::pop_heap(bucket.begin(), bucket.end(), std::greater<>());
            }
            Prop p = bucket.back();
            bucket.pop_back();
            return {static_cast<int>(current_), p};
        }
        std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
        auto top = heap_.back();
        heap_.pop_back();
        return top;
    }

private:
    [[gnu::noinline]] void push_slow(int cost, Prop p) {
        auto c = static_cast<std::size_t>(cost);
        if (c < kBuckets) {
            buckets_.resize(std::min(kBuckets, 2 * c + 16));
            push(cost, p);
            return;
        }
        heap_.push_back({cost, p});
        std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
        ++size_;
    }

    static constexpr std::size_t kBuckets = 1 << 14;
    Ties ties_;
    std::vector<std::vector<Prop>> buckets_;
    std::vector<std::pair<int, Prop>> heap_;
    std::size_t current_ = 0, used_ = 0, size_ = 0;
};

} // namespace catplan::plan::ground
