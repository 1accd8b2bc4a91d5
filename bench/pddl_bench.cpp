// `catplan plan` on PDDL: seeded 4-operator blocksworld instances of 4..20 blocks, written as PDDL
// text (the domain of tests/pddl/blocksworld-domain.pddl, problems from
// plan/detail/test_domains.hpp's random towers), read, imported (rule variants, import.hpp) and
// solved with the planner.
//
// Per size, each iteration solves the same kSeeds instances (GBFS with hff, a node and a time
// limit). Counters, per iteration:
//   solved, limited   problems solved; problems stopped by a limit
//   plan_len          median plan length of the solved problems (each plan is checked with
//                     validate_ipc_plan)
//   solve_ms          median wall time per problem of parse + import + search
//   expanded          expansions summed over the batch

#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/search.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <fmt/format.h>

namespace catplan {
namespace {

constexpr int kSeeds = 5;

/// tests/pddl/blocksworld-domain.pddl.
const char* const kDomain = R"pddl(; The 4-operator blocks world (IPC 2000, typed).
(define (domain blocksworld)
  (:requirements :strips :typing)
  (:types block)
  (:predicates (on ?x - block ?y - block)
               (ontable ?x - block)
               (clear ?x - block)
               (handempty)
               (holding ?x - block))
  (:action pick-up
    :parameters (?x - block)
    :precondition (and (clear ?x) (ontable ?x) (handempty))
    :effect (and (not (ontable ?x)) (not (clear ?x)) (not (handempty)) (holding ?x)))
  (:action put-down
    :parameters (?x - block)
    :precondition (holding ?x)
    :effect (and (not (holding ?x)) (clear ?x) (handempty) (ontable ?x)))
  (:action stack
    :parameters (?x - block ?y - block)
    :precondition (and (holding ?x) (clear ?y))
    :effect (and (not (holding ?x)) (not (clear ?y)) (clear ?x) (handempty) (on ?x ?y)))
  (:action unstack
    :parameters (?x - block ?y - block)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (holding ?x) (clear ?y) (not (clear ?x)) (not (handempty)) (not (on ?x ?y)))))
)pddl";

/// A blocksworld problem in PDDL: random initial and goal towers of n blocks (seeded).
std::string problem_text(int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto init = plan::testing::random_towers(n, rng);
    auto goal = plan::testing::random_towers(n, rng);
    std::string objects, facts = "(handempty)", goals;
    for (int i = 0; i < n; ++i) {
        objects += fmt::format(" b{}", i);
    }
    for (const auto& t : init) {
        facts += fmt::format(" (ontable b{}) (clear b{})", t.front(), t.back());
        for (std::size_t i = 1; i < t.size(); ++i) {
            facts += fmt::format(" (on b{} b{})", t[i], t[i - 1]);
        }
    }
    for (const auto& t : goal) {
        for (std::size_t i = 1; i < t.size(); ++i) {
            goals += fmt::format(" (on b{} b{})", t[i], t[i - 1]);
        }
    }
    return fmt::format("(define (problem bw-{}-{}) (:domain blocksworld)\n (:objects{} - block)\n"
                       " (:init {})\n (:goal (and{})))\n",
                       n, seed, objects, facts, goals);
}

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0;
    }
    std::sort(v.begin(), v.end());
    return v.size() % 2 == 1 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

void BM_PddlBlocksworld(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const std::string dtext = kDomain;
    std::vector<std::string> problems;
    for (int s = 0; s < kSeeds; ++s) {
        problems.push_back(problem_text(n, 1000 + static_cast<std::uint64_t>(s)));
    }
    double solved = 0, limited = 0, expanded = 0;
    std::vector<double> ms, len;
    for (auto _ : state) {
        for (const auto& ptext : problems) {
            auto t0 = std::chrono::steady_clock::now();
            SourceManager sm;
            DiagnosticSink sink(sm);
            auto d = pddl::parse_domain(sm.add_buffer("domain.pddl", dtext), sm, sink);
            auto p = pddl::parse_problem(sm.add_buffer("problem.pddl", ptext), *d, sm, sink);
            auto im = pddl::import_pddl(*d, &*p, sink);
            plan::SearchOptions opt;
            opt.search = plan::SearchKind::GreedyBestFirst;
            opt.heuristic = plan::HeuristicKind::HFF;
            opt.max_nodes = 200000;
            opt.max_seconds = 30;
            auto r = plan::find_plan(*im->problem, opt);
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count());
            expanded += static_cast<double>(r.stats.expanded);
            if (r.status != plan::SearchStatus::Solved) {
                ++limited;
                continue;
            }
            auto ipc = pddl::to_ipc_plan(*im, *r.plan);
            if (!pddl::validate_ipc_plan(*im, *ipc).valid) {
                state.SkipWithError("the planner's plan does not validate");
                return;
            }
            ++solved;
            len.push_back(static_cast<double>(ipc->size()));
        }
    }
    double it = static_cast<double>(state.iterations());
    state.counters["solved"] = solved / it;
    state.counters["limited"] = limited / it;
    state.counters["plan_len"] = median(len);
    state.counters["solve_ms"] = median(ms);
    state.counters["expanded"] = expanded / it;
}

BENCHMARK(BM_PddlBlocksworld)->DenseRange(4, 20, 4)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
} // namespace catplan

BENCHMARK_MAIN();
