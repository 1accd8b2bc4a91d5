#include "catplan/plan/cset_search.hpp"

#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"
#include "catplan/plan/state_registry.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <deque>
#include <map>
#include <utility>

namespace catplan::plan {

namespace {

// What the search knows about a stored state: how it was best reached.
struct NodeInfo {
    StateId parent = UINT32_MAX;
    std::uint32_t rule = 0;
    std::uint32_t match = 0; // the index in find_matches(rule, parent)
    int g = 0;
    int h = 0;
    bool closed = false;
};

// An open-list entry: a state and the g it was pushed with (stale entries are skipped).
struct Entry {
    StateId state;
    int g;
};

// Open nodes by (key1, key2), first in first out within a key. Buckets grow in small blocks
// (std::deque), so the open list never doubles a large array at once (limits.hpp).
class OpenList {
public:
    void push(int key1, int key2, Entry e) {
        buckets_[{key1, key2}].push_back(e);
        ++size_;
    }

    bool empty() const { return size_ == 0; }

    std::size_t size() const { return size_; }

    /// The first entry of the smallest key, and that key's first component.
    std::pair<Entry, int> pop() {
        auto it = buckets_.begin();
        Entry e = it->second.front();
        int key = it->first.first;
        it->second.pop_front();
        if (it->second.empty()) {
            buckets_.erase(it);
        }
        --size_;
        return {e, key};
    }

private:
    std::map<std::pair<int, int>, std::deque<Entry>> buckets_;
    std::size_t size_ = 0;
};

bool satisfies(const Problem& problem, const ACSet& x) {
    const ACSet* goal = problem.goal.get();
    if (goal == nullptr) {
        return true;
    }
    if (!problem.goal_conditions.empty()) {
        return embed_goal(*goal, problem.goal_conditions, x).has_value();
    }
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    opt.max_results = 1;
    return hom::is_homomorphic(*goal, x, opt);
}

class Search {
public:
    Search(const Problem& problem, const SearchOptions& options, Budget& budget)
        : problem_(problem), options_(options), budget_(budget), last_report_(Clock::now()) {}

    SearchResult run() {
        try {
            return search();
        } catch (const LimitReached& stop) {
            return finish(stop.status, std::nullopt); // in the set-up or a heuristic evaluation
        }
    }

private:
    SearchResult search() {
        heuristic_ = make_heuristic(
            options_.search == SearchKind::BreadthFirst ? HeuristicKind::Blind : options_.heuristic,
            problem_, &budget_);
        stats_.end_setup(budget_);
        auto root = registry_.insert(*problem_.initial).id;
        info_.push_back({});
        info_[root].h = evaluate(root);
        if (options_.search != SearchKind::BreadthFirst) {
            int h = info_[root].h;
            stats_.initial_h.push_back(
                {options_.heuristic, h == kDeadEnd ? std::nullopt : std::optional(h)});
        }
        if (satisfies(problem_, registry_.state(root))) {
            return finish(SearchStatus::Solved, root);
        }
        push(root, 0);
        while (!open_.empty()) {
            if (auto stop = limit_reached()) {
                return finish(*stop, std::nullopt);
            }
            auto [e, key] = open_.pop();
            auto& node = info_[e.state];
            if (e.g > node.g || (node.closed && options_.search != SearchKind::AStar)) {
                continue; // stale: a cheaper entry was pushed, or already expanded
            }
            if (node.closed && e.g >= node.g) {
                continue;
            }
            node.closed = true;
            stats_.f = key;
            if (options_.search == SearchKind::AStar &&
                satisfies(problem_, registry_.state(e.state))) {
                return finish(SearchStatus::Solved, e.state);
            }
            ++stats_.expanded;
            if (auto goal = expand(e.state)) {
                return finish(SearchStatus::Solved, *goal);
            }
            report();
        }
        return finish(SearchStatus::Unsolvable, std::nullopt);
    }

    int evaluate(StateId id) {
        if (options_.search == SearchKind::BreadthFirst) {
            return 0;
        }
        ++stats_.evaluated;
        return heuristic_->evaluate(registry_.state(id));
    }

    void push(StateId id, int g) {
        const auto& n = info_[id];
        switch (options_.search) {
        case SearchKind::BreadthFirst:
            open_.push(g, 0, {id, g}); // g never decreases in FIFO order: first in, first out
            break;
        case SearchKind::AStar:
            open_.push(g + n.h, n.h, {id, g});
            break;
        case SearchKind::GreedyBestFirst:
        case SearchKind::LazyGreedy: // find_plan gives the C-set search eager greedy for these
        case SearchKind::Lama:
            open_.push(n.h, 0, {id, g});
            break;
        }
    }

    // Generates the successors of a state; returns a goal state found on generation (BFS, GBFS).
    std::optional<StateId> expand(StateId id) {
        const auto& rules = problem_.domain->rules;
        int g = info_[id].g + 1;
        for (std::uint32_t ri = 0; ri < rules.size(); ++ri) {
            auto matches = rewrite::find_matches(*rules[ri], registry_.state(id));
            for (std::uint32_t mi = 0; mi < matches.size(); ++mi) {
                ACSet next = registry_.state(id);
                auto applied = rewrite::rewrite_in_place(*rules[ri], next, matches[mi],
                                                         rewrite::CheckMatch::No);
                if (!applied) {
                    continue; // an expression of R failed, or the step is not supported
                }
                ++stats_.generated;
                auto ins = registry_.insert(std::move(next));
                if (!ins.is_new) {
                    ++stats_.duplicates;
                    auto& old = info_[ins.id];
                    if (options_.search == SearchKind::AStar && g < old.g) {
                        old = NodeInfo{id, ri, mi, g, old.h, false};
                        push(ins.id, g);
                    }
                    continue;
                }
                info_.push_back(NodeInfo{id, ri, mi, g, 0, false});
                info_[ins.id].h = evaluate(ins.id);
                if (options_.search != SearchKind::AStar &&
                    satisfies(problem_, registry_.state(ins.id))) {
                    return ins.id;
                }
                push(ins.id, g);
            }
        }
        return std::nullopt;
    }

    std::optional<SearchStatus> limit_reached() {
        if (options_.max_nodes > 0 && stats_.expanded >= options_.max_nodes) {
            return SearchStatus::NodeLimit;
        }
        return budget_.check();
    }

    void fill_stats() {
        stats_.states = registry_.size();
        stats_.frontier = open_.size();
        stats_.seconds = budget_.elapsed();
        budget_.check();
        stats_.memory = budget_.resident();
        stats_.peak_memory = budget_.peak_bytes();
        stats_.cpu_seconds = Budget::cpu_seconds();
    }

    void report() {
        if (!options_.progress) {
            return;
        }
        auto now = Clock::now();
        if (std::chrono::duration<double>(now - last_report_).count() >=
            options_.progress_interval) {
            last_report_ = now;
            fill_stats();
            options_.progress(stats_);
        }
    }

    SearchResult finish(SearchStatus status, std::optional<StateId> goal) {
        SearchResult r;
        r.status = status;
        if (goal) {
            r.plan = extract_plan(*goal);
        }
        if (stats_.setup_seconds == 0) {
            stats_.end_setup(budget_); // stopped during the set-up
        }
        fill_stats();
        r.stats = stats_;
        return r;
    }

    // Replays the path to `goal` from the initial state (see search.hpp): each stored match is
    // carried to the replayed state through an isomorphism, so the arguments are its names.
    Plan extract_plan(StateId goal) {
        std::vector<StateId> path;
        for (StateId s = goal; s != 0; s = info_[s].parent) {
            path.push_back(s);
        }
        Plan plan;
        ACSet actual = *problem_.initial;
        for (auto it = path.rbegin(); it != path.rend(); ++it) {
            const auto& n = info_[*it];
            const Rule& rule = *problem_.domain->rules[n.rule];
            const ACSet& stored = registry_.state(n.parent);
            auto matches = rewrite::find_matches(rule, stored);
            CATPLAN_ASSERT(n.match < matches.size(), "a stored match disappeared");
            hom::ACSetMorphism m = matches[n.match];
            if (!(stored == actual)) {
                auto iso = hom::find_isomorphism(stored, actual);
                CATPLAN_ASSERT(iso.has_value(), "a stored state is not isomorphic to its replay");
                m = hom::compose(m, *iso);
            }
            Step step;
            step.action = rule.name;
            for (const auto& p : rule.parameters) {
                step.args.push_back(actual.part_label(p.ob, m(p.ob, p.part)));
            }
            auto applied = rewrite::rewrite_in_place(rule, actual, m);
            CATPLAN_ASSERT(applied.has_value(), "a found step does not apply on replay");
            plan.steps.push_back(std::move(step));
        }
        return plan;
    }

    const Problem& problem_;
    const SearchOptions& options_;
    Budget& budget_;
    std::unique_ptr<Heuristic> heuristic_;
    StateRegistry registry_;
    std::deque<NodeInfo> info_;
    OpenList open_;
    SearchStats stats_;
    Clock::time_point last_report_;
};

} // namespace

SearchResult cset_search(const Problem& problem, const SearchOptions& options, Budget& budget) {
    return Search(problem, options, budget).run();
}

} // namespace catplan::plan
