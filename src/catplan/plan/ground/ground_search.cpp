#include "catplan/plan/ground/ground_search.hpp"

#include "catplan/plan/ground/compile.hpp"
#include "catplan/plan/ground/plan_back.hpp"
#include "catplan/plan/ground/space.hpp"
#include "catplan/plan/validate.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <fmt/format.h>
#include <optional>
#include <utility>

namespace catplan::plan::ground {

namespace {

HeuristicKind resolve(HeuristicKind h, SearchKind search) {
    if (h != HeuristicKind::Default) {
        return h;
    }
    switch (search) {
    case SearchKind::AStar:
        return HeuristicKind::LmCut;
    case SearchKind::BreadthFirst:
        return HeuristicKind::Blind;
    default:
        return HeuristicKind::HFF;
    }
}

bool prefers(HeuristicKind h) {
    return h == HeuristicKind::HFF || h == HeuristicKind::LmCount;
}

// The evaluators whose preferred operators a configuration uses. LAMA takes them from h_FF only:
// the landmark count's (every applicable action achieving a needed landmark) are so many that the
// preferred lists stop telling the search anything (Fast Downward's lama-first: pref=false).
bool gives_preferred(HeuristicKind h, SearchKind search) {
    return search == SearchKind::Lama ? h == HeuristicKind::HFF : prefers(h);
}

// The evaluators of a configuration, made anew (a path-dependent one belongs to one search).
class Evaluators {
public:
    Evaluators(const Task& task, const RelaxedTask& relaxed, Budget& budget,
               const SearchOptions& o) {
        if (o.search == SearchKind::Lama) {
            kinds_ = {HeuristicKind::HFF, HeuristicKind::LmCount};
        } else {
            kinds_ = {resolve(o.heuristic, o.search)};
        }
        for (auto k : kinds_) {
            owned_.push_back(make_evaluator(k, task, relaxed, budget));
            raw_.push_back(owned_.back().get());
            if (gives_preferred(k, o.search)) {
                preferred_.push_back(raw_.back());
            }
        }
    }

    const std::vector<Evaluator*>& all() const { return raw_; }

    /// The evaluators whose preferred operators the lazy search uses.
    const std::vector<Evaluator*>& preferred() const { return preferred_; }

    Evaluator& first() { return *raw_.front(); }

    /// The kinds of the evaluators, in the order all() gives them.
    const std::vector<HeuristicKind>& kinds() const { return kinds_; }

    std::string names() const {
        std::string out;
        for (auto k : kinds_) {
            out += (out.empty() ? "" : " and ") + std::string(to_string(k));
        }
        return out;
    }

    /// ", preferred operators" and, when not every evaluator gives them, whose.
    std::string preferred_names() const {
        if (preferred_.empty() || preferred_.size() == raw_.size()) {
            return preferred_.empty() ? "" : ", preferred operators";
        }
        std::string whose;
        for (std::size_t i = 0; i < raw_.size(); ++i) {
            if (std::find(preferred_.begin(), preferred_.end(), raw_[i]) != preferred_.end()) {
                whose += (whose.empty() ? "" : " and ") + std::string(to_string(kinds_[i]));
            }
        }
        return ", preferred operators of " + whose;
    }

private:
    std::vector<HeuristicKind> kinds_;
    std::vector<std::unique_ptr<Evaluator>> owned_;
    std::vector<Evaluator*> raw_, preferred_;
};

std::string describe_config(const SearchOptions& o, const Evaluators& e) {
    switch (o.search) {
    case SearchKind::BreadthFirst:
        return "breadth-first";
    case SearchKind::AStar:
        return fmt::format("A*, {}", e.names());
    case SearchKind::GreedyBestFirst:
        return fmt::format("eager greedy best-first, {}", e.names());
    case SearchKind::LazyGreedy:
    case SearchKind::Lama:
        return fmt::format("lazy greedy best-first, {}{}", e.names(), e.preferred_names());
    }
    CATPLAN_UNREACHABLE("search kind");
}

class Runner {
public:
    Runner(const Task& task, const SearchOptions& options, Budget& budget, SearchResult& result)
        : task_(task),
          options_(options),
          budget_(budget),
          r_(result),
          costs_(!task.unit_cost && options.search == SearchKind::AStar),
          relaxed_(task, costs_ ? CostType::Normal : CostType::One) {}

    // The first search, then with anytime the weighted ones; the best plan in best_.
    SearchStatus run() {
        Evaluators e(task_, relaxed_, budget_, options_);
        r_.config = describe_config(options_, e) + (costs_ ? ", summing action costs" : "");
        r_.costs = costs_;
        r_.stats.end_setup(budget_);
        EngineResult first = search(e, 0, 0, costs_);
        if (first.status != SearchStatus::Solved) {
            return first.status;
        }
        keep(first.plan);
        // Breadth-first search finds a shortest plan, which is a cheapest one only at unit costs.
        bool optimal_search = (options_.search == SearchKind::BreadthFirst && task_.unit_cost) ||
                              (options_.search == SearchKind::AStar && e.first().admissible());
        r_.optimal = optimal_search;
        if (!options_.anytime || optimal_search) {
            return SearchStatus::Solved;
        }
        r_.config += "; anytime: lazy weighted A* with weights 5, 3, 2, 1";
        // As LAMA: with general costs the later searches sum them (g and the bound), and their
        // heuristics count each action's cost plus 1, so that zero-cost steps still count.
        std::optional<RelaxedTask> plus_one;
        if (!task_.unit_cost) {
            plus_one.emplace(task_, CostType::PlusOne);
            r_.config += ", summing action costs";
            r_.costs = true;
        }
        const RelaxedTask& later = plus_one ? *plus_one : relaxed_;
        // As LAMA: each weight once, the last one again for as long as it finds a better plan;
        // a plan that costs nothing cannot be bettered.
        for (int w : {5, 3, 2, 1, 1}) {
            for (bool again = true; again && cost(best_) > 0;) {
                Evaluators ew(task_, later, budget_, options_);
                EngineResult better = search(ew, w, cost(best_), !task_.unit_cost);
                if (better.status == SearchStatus::Solved) {
                    keep(better.plan);
                } else if (better.status != SearchStatus::Unsolvable) {
                    return SearchStatus::Solved; // a limit: the best plan so far stands
                }
                again = w == 1 && better.status == SearchStatus::Solved;
            }
        }
        return SearchStatus::Solved;
    }

    const std::vector<ActionId>& best() const { return best_; }

    std::uint64_t exits() const { return exits_; }

    const std::string& exit_example() const { return exit_example_; }

private:
    // One search; `costs`: g sums the actions' costs (else it counts steps).
    EngineResult search(Evaluators& e, int weight, int bound, bool costs) {
        Space space(task_, budget_, options_, r_.stats, costs);
        EngineResult out;
        switch (options_.search) {
        case SearchKind::BreadthFirst:
            out = weight == 0 ? breadth_first(space)
                              : lazy_best_first(space, e.all(), {}, weight, bound);
            break;
        case SearchKind::AStar:
            out = eager_best_first(space, e.first(), true);
            break;
        case SearchKind::GreedyBestFirst:
            out = weight == 0 ? eager_best_first(space, e.first(), false)
                              : lazy_best_first(space, e.all(), {}, weight, bound);
            break;
        case SearchKind::LazyGreedy:
        case SearchKind::Lama:
            out = lazy_best_first(space, e.all(), e.preferred(), weight, bound);
            break;
        }
        if (weight == 0) { // the first search's, as Fast Downward reports them
            for (std::size_t i = 0; i < space.initial_values.size(); ++i) {
                int v = space.initial_values[i];
                r_.stats.initial_h.push_back(
                    {e.kinds()[i], v == kDeadEnd ? std::nullopt : std::optional(v)});
            }
        }
        exits_ += space.exits;
        if (exit_example_.empty()) {
            exit_example_ = space.exit_example;
        }
        return out;
    }

    // What a plan costs: the sum of its actions' costs (its length where every action costs 1),
    // at most INT_MAX (a search bound cannot exceed it).
    int cost(const std::vector<ActionId>& plan) const {
        std::int64_t sum = 0;
        for (ActionId a : plan) {
            sum = std::min<std::int64_t>(sum + task_.actions[a].cost, INT_MAX);
        }
        return static_cast<int>(sum);
    }

    // Keeps the cheaper plan, and of two as cheap the shorter.
    void keep(const std::vector<ActionId>& plan) {
        ++r_.stats.plans;
        auto key = [&](const std::vector<ActionId>& p) { return std::pair(cost(p), p.size()); };
        if (r_.stats.plans == 1 || key(plan) < key(best_)) {
            best_ = plan;
        }
    }

    const Task& task_;
    const SearchOptions& options_;
    Budget& budget_;
    SearchResult& r_;
    bool costs_; // the search sums the actions' costs
    RelaxedTask relaxed_;
    std::vector<ActionId> best_;
    std::uint64_t exits_ = 0;
    std::string exit_example_;
};

void fill_stats(SearchResult& r, Budget& budget) {
    r.stats.seconds = budget.elapsed();
    (void)budget.check();
    r.stats.memory = budget.resident();
    r.stats.peak_memory = budget.peak_bytes();
    r.stats.cpu_seconds = Budget::cpu_seconds();
    if (r.stats.setup_seconds == 0) {
        r.stats.end_setup(budget); // stopped during the set-up
    }
}

} // namespace

GroundOutcome ground_search(const ProblemPtr& problem, const SearchOptions& options,
                            Budget& budget) {
    GroundOutcome out;
    out.result.path = "grounded";
    std::optional<Task> task;
    try {
        auto compiled = compile(problem, budget);
        out.result.stats.ground_seconds = budget.elapsed();
        if (!compiled) {
            out.why_not = compiled.error();
            return out;
        }
        task.emplace(std::move(*compiled));
    } catch (const LimitReached& stop) {
        out.compiled = true; // the limit stops the whole run: no fall-back
        out.result.status = stop.status;
        out.result.config = "compiling the ground task";
        fill_stats(out.result, budget);
        return out;
    }
    search_task(*task, options, budget, out);
    return out;
}

void search_task(const Task& task, const SearchOptions& options, Budget& budget,
                 GroundOutcome& out) {
    out.compiled = true;
    auto& r = out.result;
    r.stats.variables = task.vars.size();
    r.stats.actions = task.actions.size();
    r.uncosted = task.uncosted;
    r.costs_ignored = task.costs_ignored;
    Runner runner(task, options, budget, r);
    try {
        r.status = runner.run();
    } catch (const LimitReached& stop) {
        r.status = stop.status;
    }
    if (r.stats.plans > 0) {
        r.status = SearchStatus::Solved;
    }
    r.exits = runner.exits();
    r.exit_example = runner.exit_example();
    if (r.exits > 0) {
        r.optimal = false;
    }
    if (r.status == SearchStatus::Solved) {
        std::optional<ACSet> last;
        auto plan = to_dpo_plan(task, runner.best(), &last);
        const Problem& problem = *task.problem;
        // Each step was checked at the match the search chose; a caller that replays the steps
        // itself need not have the plan's text replayed here too (SearchOptions::validate).
        auto check = [&] {
            Validation unchecked;
            unchecked.valid = true;
            return options.validate ? validate_plan(problem, *plan) : unchecked;
        };
        if (!plan) {
            out.rejected = plan.error();
        } else if (auto v = check(); v.valid) {
            r.plan = std::move(*plan);
        } else if (v.ambiguous && (!problem.goal || embed_goal(*problem.goal, *last))) {
            // The replay applied each step with the match the search chose (each checked by
            // match_problem) and reached the goal; only the plan's text leaves a choice.
            r.caveat = fmt::format("the steps' arguments do not say which match the search "
                                   "applied, so `catplan validate` rejects this plan: {}",
                                   v.reason);
            r.plan = std::move(*plan);
        } else {
            out.rejected = v.reason;
        }
    }
    fill_stats(r, budget);
}

} // namespace catplan::plan::ground
