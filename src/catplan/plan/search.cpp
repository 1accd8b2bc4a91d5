#include "catplan/plan/search.hpp"

#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"
#include "catplan/plan/state_registry.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <chrono>
#include <deque>
#include <queue>
#include <tuple>

namespace catplan::plan {

std::optional<SearchKind> parse_search(std::string_view name) {
    if (name == "bfs") {
        return SearchKind::BreadthFirst;
    }
    if (name == "astar") {
        return SearchKind::AStar;
    }
    if (name == "gbfs") {
        return SearchKind::GreedyBestFirst;
    }
    return std::nullopt;
}

std::string_view to_string(SearchKind kind) {
    switch (kind) {
    case SearchKind::BreadthFirst:
        return "bfs";
    case SearchKind::AStar:
        return "astar";
    case SearchKind::GreedyBestFirst:
        return "gbfs";
    }
    CATPLAN_UNREACHABLE("search kind");
}

std::string_view to_string(SearchStatus status) {
    switch (status) {
    case SearchStatus::Solved:
        return "solved";
    case SearchStatus::Unsolvable:
        return "unsolvable";
    case SearchStatus::NodeLimit:
        return "node limit";
    case SearchStatus::TimeLimit:
        return "time limit";
    case SearchStatus::MemoryLimit:
        return "memory limit";
    }
    CATPLAN_UNREACHABLE("search status");
}

namespace {

using Clock = std::chrono::steady_clock;

// What the search knows about a stored state: how it was best reached.
struct NodeInfo {
    StateId parent = UINT32_MAX;
    std::uint32_t rule = 0;
    std::uint32_t match = 0; // the index in find_matches(rule, parent)
    int g = 0;
    int h = 0;
    bool closed = false;
};

// An open-list entry; smaller (key1, key2, seq) first. Stale entries are skipped when popped.
struct Entry {
    int key1, key2;
    std::uint64_t seq;
    StateId state;
    int g;

    friend bool operator>(const Entry& a, const Entry& b) {
        return std::tie(a.key1, a.key2, a.seq) > std::tie(b.key1, b.key2, b.seq);
    }
};

bool satisfies(const ACSet* goal, const ACSet& x) {
    if (goal == nullptr) {
        return true;
    }
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    opt.max_results = 1;
    return hom::is_homomorphic(*goal, x, opt);
}

class Search {
public:
    Search(const Problem& problem, const SearchOptions& options)
        : problem_(problem),
          options_(options),
          heuristic_(make_heuristic(
              options.search == SearchKind::BreadthFirst ? HeuristicKind::Blind : options.heuristic,
              problem)),
          start_(Clock::now()),
          last_report_(start_) {}

    SearchResult run() {
        SearchResult result;
        auto root = registry_.insert(*problem_.initial).id;
        info_.push_back({});
        info_[root].h = evaluate(root);
        if (satisfies(problem_.goal.get(), registry_.state(root))) {
            return finish(SearchStatus::Solved, root);
        }
        push(root, 0);
        while (!open_empty()) {
            if (auto stop = limit_reached()) {
                return finish(*stop, std::nullopt);
            }
            auto e = pop();
            auto& node = info_[e.state];
            if (e.g > node.g || (node.closed && options_.search != SearchKind::AStar)) {
                continue; // stale: a cheaper entry was pushed, or already expanded
            }
            if (node.closed && e.g >= node.g) {
                continue;
            }
            node.closed = true;
            stats_.f = e.key1;
            if (options_.search == SearchKind::AStar &&
                satisfies(problem_.goal.get(), registry_.state(e.state))) {
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

private:
    int evaluate(StateId id) {
        return options_.search == SearchKind::BreadthFirst
                   ? 0
                   : heuristic_->evaluate(registry_.state(id));
    }

    void push(StateId id, int g) {
        const auto& n = info_[id];
        switch (options_.search) {
        case SearchKind::BreadthFirst:
            fifo_.push_back(id);
            break;
        case SearchKind::AStar:
            heap_.push({g + n.h, n.h, seq_++, id, g});
            break;
        case SearchKind::GreedyBestFirst:
            heap_.push({n.h, 0, seq_++, id, g});
            break;
        }
    }

    bool open_empty() const { return fifo_.empty() && heap_.empty(); }

    Entry pop() {
        if (options_.search == SearchKind::BreadthFirst) {
            StateId id = fifo_.front();
            fifo_.pop_front();
            return {info_[id].g, 0, 0, id, info_[id].g};
        }
        Entry e = heap_.top();
        heap_.pop();
        return e;
    }

    // Generates the successors of a state; returns a goal state found on generation (BFS, GBFS).
    std::optional<StateId> expand(StateId id) {
        const auto& rules = problem_.domain->rules;
        int g = info_[id].g + 1;
        for (std::uint32_t ri = 0; ri < rules.size(); ++ri) {
            // Copy the matches' source: the registry may reallocate while successors are stored.
            auto matches = rewrite::find_matches(*rules[ri], registry_.state(id));
            for (std::uint32_t mi = 0; mi < matches.size(); ++mi) {
                ACSet next = registry_.state(id);
                if (!rewrite::rewrite_in_place(*rules[ri], next, matches[mi])) {
                    continue; // find_matches returns valid matches only; kept for robustness
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
                    satisfies(problem_.goal.get(), registry_.state(ins.id))) {
                    return ins.id;
                }
                push(ins.id, g);
            }
        }
        return std::nullopt;
    }

    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    std::optional<SearchStatus> limit_reached() const {
        if (options_.max_nodes > 0 && stats_.expanded >= options_.max_nodes) {
            return SearchStatus::NodeLimit;
        }
        if (options_.max_seconds > 0 && elapsed() >= options_.max_seconds) {
            return SearchStatus::TimeLimit;
        }
        if (options_.max_bytes > 0 && registry_.bytes() >= options_.max_bytes) {
            return SearchStatus::MemoryLimit;
        }
        return std::nullopt;
    }

    void fill_stats() {
        stats_.states = registry_.size();
        stats_.frontier = fifo_.size() + heap_.size();
        stats_.bytes = registry_.bytes();
        stats_.seconds = elapsed();
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
    std::unique_ptr<Heuristic> heuristic_;
    StateRegistry registry_;
    std::vector<NodeInfo> info_;
    std::deque<StateId> fifo_;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap_;
    std::uint64_t seq_ = 0;
    SearchStats stats_;
    Clock::time_point start_, last_report_;
};

} // namespace

SearchResult find_plan(const Problem& problem, const SearchOptions& options) {
    CATPLAN_ASSERT(problem.initial != nullptr && problem.domain != nullptr,
                   "a problem needs an initial state and a domain");
    return Search(problem, options).run();
}

} // namespace catplan::plan
