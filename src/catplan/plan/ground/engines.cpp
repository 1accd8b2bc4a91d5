// The search engines on ground tasks (space.hpp).

#include "catplan/plan/ground/space.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <queue>
#include <tuple>

namespace catplan::plan::ground {

namespace {

// Entries by integer key, first in first out within a key. Keys below kDense have a bucket each
// (a vector indexed by key, so most pushes and pops take constant time); larger keys, which sums
// of action costs give, are kept in a map, so a key of a million does not allocate a million
// buckets.
template <class T>
class BucketList {
public:
    void push(int key, const T& item) {
        auto k = static_cast<std::size_t>(std::max(key, 0));
        ++size_;
        if (k >= kDense) {
            sparse_[k].push_back(item);
            return;
        }
        if (k >= buckets_.size()) {
            buckets_.resize(k + 1);
        }
        buckets_[k].push_back(item);
        min_ = std::min(min_, k);
        ++dense_size_;
    }

    bool empty() const { return size_ == 0; }

    std::size_t size() const { return size_; }

    /// The first item of the smallest key, and the key.
    std::pair<T, int> pop() {
        --size_;
        if (dense_size_ == 0) {
            auto first = sparse_.begin();
            std::pair<T, int> out{first->second.front(), static_cast<int>(first->first)};
            first->second.pop_front();
            if (first->second.empty()) {
                sparse_.erase(first);
            }
            return out;
        }
        while (buckets_[min_].empty()) {
            ++min_;
        }
        T item = buckets_[min_].front();
        buckets_[min_].pop_front();
        --dense_size_;
        return {item, static_cast<int>(min_)};
    }

private:
    static constexpr std::size_t kDense = 4096;
    std::vector<std::deque<T>> buckets_;
    std::map<std::size_t, std::deque<T>> sparse_;
    std::size_t min_ = SIZE_MAX;
    std::size_t size_ = 0, dense_size_ = 0;
};

// Evaluates a state with one evaluator, telling a path-dependent one how it was reached.
int evaluate(Space& space, Evaluator& h, StateId parent, ActionId a, StateId s, bool is_new,
             const std::vector<ActionId>* applicable, std::vector<ActionId>* preferred) {
    const auto& values = space.values(s);
    if (h.path_dependent()) {
        h.reach(parent, a, s, values, is_new);
    }
    return h.evaluate(s, values, applicable, preferred);
}

} // namespace

EngineResult breadth_first(Space& space) {
    StateId root = space.initial();
    if (space.is_goal(root)) {
        return {SearchStatus::Solved, {}};
    }
    std::deque<StateId> open{root};
    std::vector<ActionId> ops;
    while (!open.empty()) {
        if (auto stop = space.limit_reached()) {
            return {*stop, {}};
        }
        StateId s = open.front();
        open.pop_front();
        ++space.stats.expanded;
        space.stats.f = space.node(s).g;
        space.applicable(s, ops);
        for (ActionId a : ops) {
            auto succ = space.successor(s, a);
            if (!succ || !succ->is_new) {
                continue;
            }
            Node& n = space.node(succ->id);
            n = {s, a, space.node(s).g + 1, false, false};
            if (space.is_goal(succ->id)) {
                return {SearchStatus::Solved, space.path_to(succ->id)};
            }
            open.push_back(succ->id);
        }
        space.stats.frontier = open.size();
    }
    return {SearchStatus::Unsolvable, {}};
}

EngineResult eager_best_first(Space& space, Evaluator& h, bool astar) {
    struct Entry {
        int f, h;          // A*: f = g + h; greedy: f = 0
        std::uint64_t seq; // first in, first out among equal keys
        StateId state;
        int g;
    };

    // A heap rather than buckets by f and h: with action costs the keys are sparse and large.
    auto later = [](const Entry& a, const Entry& b) {
        return std::tie(a.f, a.h, a.seq) > std::tie(b.f, b.h, b.seq);
    };
    std::priority_queue<Entry, std::vector<Entry>, decltype(later)> open(later);
    std::uint64_t seq = 0;
    auto push = [&](StateId s, int g, int hv) { open.push({astar ? g + hv : 0, hv, seq++, s, g}); };
    std::vector<int> hval;
    auto set_h = [&](StateId s, int v) {
        if (hval.size() <= s) {
            hval.resize(s + 1, 0);
        }
        hval[s] = v;
    };
    StateId root = space.initial();
    int h0 = evaluate(space, h, kNone, kNone, root, true, nullptr, nullptr);
    ++space.stats.evaluated;
    space.initial_values = {h0};
    if (h0 == kDeadEnd) {
        return {SearchStatus::Unsolvable, {}};
    }
    if (space.is_goal(root)) {
        return {SearchStatus::Solved, {}};
    }
    set_h(root, h0);
    push(root, 0, h0);
    std::vector<ActionId> ops;
    while (!open.empty()) {
        if (auto stop = space.limit_reached()) {
            return {*stop, {}};
        }
        const Entry e = open.top();
        open.pop();
        const int hv = e.h;
        Node& node = space.node(e.state);
        if (node.closed && (!astar || e.g >= node.g)) {
            continue;
        }
        if (e.g > node.g) {
            continue; // a cheaper path was found after this entry
        }
        node.closed = true;
        space.stats.f = astar ? e.g + hv : hv;
        if (astar && space.is_goal(e.state)) {
            return {SearchStatus::Solved, space.path_to(e.state)};
        }
        ++space.stats.expanded;
        space.applicable(e.state, ops);
        for (ActionId a : ops) {
            auto succ = space.successor(e.state, a);
            if (!succ) {
                continue;
            }
            int g = e.g + space.cost(a);
            Node& n = space.node(succ->id);
            if (!succ->is_new) {
                if (h.path_dependent()) {
                    (void)evaluate(space, h, e.state, a, succ->id, false, nullptr, nullptr);
                }
                if (astar && !n.dead && g < n.g) {
                    n.parent = e.state;
                    n.action = a;
                    n.g = g;
                    n.closed = false;
                    push(succ->id, g, hval[succ->id]);
                }
                continue;
            }
            n = {e.state, a, g, false, false};
            int hs = evaluate(space, h, e.state, a, succ->id, true, nullptr, nullptr);
            ++space.stats.evaluated;
            if (hs == kDeadEnd) {
                n.dead = true;
                continue;
            }
            set_h(succ->id, hs);
            if (!astar && space.is_goal(succ->id)) {
                return {SearchStatus::Solved, space.path_to(succ->id)};
            }
            push(succ->id, g, hs);
        }
        space.stats.frontier = open.size();
    }
    return {SearchStatus::Unsolvable, {}};
}

namespace {

// The open lists of lazy search: per evaluator one of every successor and, with preferred
// operators, one of the preferred successors only; taken in turn by the lowest priority (Fast
// Downward's alternation open list), a preferred list boosted when an evaluator makes progress.
class LazyOpen {
public:
    struct Entry {
        StateId parent;
        ActionId action;
    };

    LazyOpen(Space& space, const std::vector<Evaluator*>& hs,
             const std::vector<Evaluator*>& preferred, int weight, int bound)
        : space_(space),
          hs_(hs),
          preferred_(!preferred.empty()),
          weight_(weight),
          bound_(bound),
          per_h_(preferred_ ? 2 : 1),
          best_(hs.size(), kDeadEnd),
          values_(hs.size(), 0) {
        for (Evaluator* h : hs) {
            gives_preferred_.push_back(std::find(preferred.begin(), preferred.end(), h) !=
                                       preferred.end());
            subs_.push_back({});
            if (preferred_) {
                subs_.push_back({{}, 0, true});
            }
        }
    }

    /// Evaluates s, then puts its successors into the open lists; false for a dead end.
    bool expand(StateId parent, ActionId a, StateId s, bool is_new) {
        space_.applicable(s, ops_);
        pref_.clear();
        for (std::size_t i = 0; i < hs_.size(); ++i) {
            values_[i] = evaluate(space_, *hs_[i], parent, a, s, is_new, &ops_,
                                  gives_preferred_[i] ? &pref_ : nullptr);
            if (parent == kNone) {
                space_.initial_values.push_back(values_[i]);
            }
            if (values_[i] == kDeadEnd) {
                space_.node(s).dead = true;
                ++space_.stats.evaluated;
                return false;
            }
        }
        ++space_.stats.evaluated;
        ++space_.stats.expanded;
        bool progress = false;
        for (std::size_t i = 0; i < hs_.size(); ++i) {
            if (values_[i] < best_[i]) {
                best_[i] = values_[i];
                progress = true;
            }
        }
        if (progress && preferred_) {
            for (auto& sub : subs_) {
                if (sub.preferred_only) {
                    sub.priority -= 1000;
                }
            }
        }
        int g = space_.node(s).g;
        space_.stats.f = values_[0];
        std::sort(pref_.begin(), pref_.end());
        for (ActionId op : ops_) {
            int g_op = g + space_.cost(op);
            if (bound_ > 0 && g_op >= bound_) {
                continue;
            }
            bool p = preferred_ && std::binary_search(pref_.begin(), pref_.end(), op);
            for (std::size_t i = 0; i < hs_.size(); ++i) {
                int key = weight_ == 0 ? values_[i] : g_op + weight_ * values_[i];
                subs_[i * per_h_].list.push(key, {s, op});
                if (p) {
                    subs_[i * per_h_ + 1].list.push(key, {s, op});
                }
            }
        }
        return true;
    }

    /// The next entry of the list whose turn it is; nullopt when every list is empty.
    std::optional<Entry> pop() {
        Sub* pick = nullptr;
        for (auto& sub : subs_) {
            if (!sub.list.empty() && (pick == nullptr || sub.priority < pick->priority)) {
                pick = &sub;
            }
        }
        if (pick == nullptr) {
            return std::nullopt;
        }
        ++pick->priority;
        return pick->list.pop().first;
    }

    /// The entries waiting in every list.
    std::size_t size() const {
        std::size_t n = 0;
        for (const auto& sub : subs_) {
            n += sub.list.size();
        }
        return n;
    }

private:
    struct Sub {
        BucketList<Entry> list;
        int priority = 0;
        bool preferred_only = false;
    };

    Space& space_;
    const std::vector<Evaluator*>& hs_;
    bool preferred_;
    int weight_, bound_;
    std::size_t per_h_;
    std::vector<Sub> subs_;
    std::vector<bool> gives_preferred_; // per evaluator: its preferred operators count
    std::vector<int> best_, values_;
    std::vector<ActionId> ops_, pref_;
};

} // namespace

EngineResult lazy_best_first(Space& space, const std::vector<Evaluator*>& hs,
                             const std::vector<Evaluator*>& preferred, int weight, int bound) {
    LazyOpen open(space, hs, preferred, weight, bound);
    bool path_dependent =
        std::any_of(hs.begin(), hs.end(), [](const Evaluator* h) { return h->path_dependent(); });
    StateId root = space.initial();
    if (!open.expand(kNone, kNone, root, true)) {
        return {SearchStatus::Unsolvable, {}};
    }
    if (space.is_goal(root)) {
        return {SearchStatus::Solved, {}};
    }
    for (;;) {
        if (auto stop = space.limit_reached()) {
            return {*stop, {}};
        }
        auto next = open.pop();
        if (!next) {
            return {SearchStatus::Unsolvable, {}};
        }
        const LazyOpen::Entry e = *next;
        const Node parent = space.node(e.parent);
        if (parent.dead) {
            continue;
        }
        auto succ = space.successor(e.parent, e.action);
        if (!succ) {
            continue;
        }
        int g = parent.g + space.cost(e.action);
        Node& n = space.node(succ->id);
        if (!succ->is_new) {
            if (path_dependent) {
                const auto& values_now = space.values(succ->id);
                for (Evaluator* h : hs) {
                    if (h->path_dependent()) {
                        h->reach(e.parent, e.action, succ->id, values_now, false);
                    }
                }
            }
            if (weight == 0 || n.dead || g >= n.g) {
                continue; // greedy search does not reopen
            }
        }
        n.parent = e.parent;
        n.action = e.action;
        n.g = g;
        if (space.is_goal(succ->id)) {
            return {SearchStatus::Solved, space.path_to(succ->id)};
        }
        if (!open.expand(e.parent, e.action, succ->id, succ->is_new)) {
            continue;
        }
        space.stats.frontier = open.size();
    }
}

} // namespace catplan::plan::ground
