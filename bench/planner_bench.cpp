// The planner (plan::find_plan) on seeded blocksworld problems of 4..20 blocks: random initial
// towers and random goal towers (plan/detail/test_domains.hpp, labelled blocks so that states tell
// blocks apart), per size and per search/heuristic.
//
// Each benchmark solves the same kSeeds instances of its size per iteration, each with a node and
// a time limit. Counters (per iteration, so per batch of kSeeds problems):
//   solved, limited      problems solved; problems stopped by a limit (reported, not hidden)
//   expanded, generated  summed over the batch
//   exp_per_s            expansions per second of search (time spent in find_plan only)
//   plan_len             mean plan length of the solved problems
//   solve_ms             mean time per solved problem
// A problem stopped by a limit still counts in expanded and exp_per_s.

#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <iostream>

namespace catplan {
namespace {

using namespace plan;
using namespace plan::testing;

constexpr int kSeeds = 3;
constexpr std::uint64_t kMaxNodes = 200'000;
constexpr double kMaxSeconds = 10.0;

// kSeeds problems of n blocks; the seed depends on n only, so every configuration sees the same
// problems.
std::vector<ProblemPtr> problems(int n) {
    auto d = blocks_domain(true);
    std::vector<ProblemPtr> out;
    for (int s = 0; s < kSeeds; ++s) {
        std::mt19937_64 rng(1000 * static_cast<std::uint64_t>(n) + s);
        auto init = random_towers(n, rng);
        auto goal = random_towers(n, rng);
        out.push_back(blocks_problem(d, block_names(n), init, goal));
    }
    return out;
}

void run(benchmark::State& state, SearchKind search, HeuristicKind heuristic) {
    int n = static_cast<int>(state.range(0));
    auto ps = problems(n);
    SearchOptions opt;
    opt.search = search;
    opt.heuristic = heuristic;
    opt.max_nodes = kMaxNodes;
    opt.max_seconds = kMaxSeconds;
    double solved = 0, limited = 0, expanded = 0, generated = 0, length = 0, seconds = 0,
           solve_seconds = 0;
    for (auto _ : state) {
        for (const auto& p : ps) {
            auto r = find_plan(*p, opt);
            expanded += static_cast<double>(r.stats.expanded);
            generated += static_cast<double>(r.stats.generated);
            seconds += r.stats.seconds;
            if (r.status == SearchStatus::Solved) {
                // A benchmark of a planner that finds wrong plans measures nothing.
                if (!validate_plan(*p, *r.plan).valid) {
                    state.SkipWithError("the planner found an invalid plan");
                    return;
                }
                ++solved;
                length += static_cast<double>(r.plan->steps.size());
                solve_seconds += r.stats.seconds;
            } else {
                ++limited;
            }
        }
    }
    auto per_iter = [&](double v) {
        return benchmark::Counter(v, benchmark::Counter::kAvgIterations);
    };
    state.counters["solved"] = per_iter(solved);
    state.counters["limited"] = per_iter(limited);
    state.counters["expanded"] = per_iter(expanded);
    state.counters["generated"] = per_iter(generated);
    state.counters["exp_per_s"] = seconds > 0 ? expanded / seconds : 0;
    state.counters["plan_len"] = solved > 0 ? length / solved : 0;
    state.counters["solve_ms"] = solved > 0 ? 1000 * solve_seconds / solved : 0;
}

void BM_Bfs(benchmark::State& state) {
    run(state, SearchKind::BreadthFirst, HeuristicKind::Blind);
}

void BM_AStarHff(benchmark::State& state) {
    run(state, SearchKind::AStar, HeuristicKind::HFF);
}

void BM_GbfsHff(benchmark::State& state) {
    run(state, SearchKind::GreedyBestFirst, HeuristicKind::HFF);
}

void BM_GbfsHadd(benchmark::State& state) {
    run(state, SearchKind::GreedyBestFirst, HeuristicKind::HAdd);
}

// Breadth-first search only where the state space is small enough to finish.
BENCHMARK(BM_Bfs)->DenseRange(4, 6, 1)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_AStarHff)->DenseRange(4, 10, 2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_GbfsHff)->DenseRange(4, 20, 4)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_GbfsHadd)->DenseRange(4, 20, 4)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
} // namespace catplan

BENCHMARK_MAIN();
