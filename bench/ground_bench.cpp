// The grounded planner's parts on PDDL problems given on the command line (a blocksworld of 30
// blocks by default): compiling, one heuristic evaluation (per heuristic) and the successor
// generator, each on the initial state and on the states of a random walk.
//
//   ground_bench [--benchmark_filter=...] -- DOMAIN.pddl PROBLEM.pddl
//
// (Figures in bench/RESULTS.md, "Planner".)

#include "catplan/pddl/import.hpp"
#include "catplan/plan/ground/compile.hpp"
#include "catplan/plan/ground/heuristics.hpp"
#include "catplan/plan/ground/successors.hpp"

#include <benchmark/benchmark.h>

#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace catplan {
namespace {

using namespace plan::ground;

std::string g_domain = CATPLAN_SOURCE_DIR "/bench/pddl/domains/blocksworld.pddl";
std::string g_problem;

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Loaded {
    std::optional<pddl::Import> im;
    std::optional<Task> task;
};

Loaded& loaded() {
    static Loaded l = [] {
        Loaded out;
        SourceManager sm;
        DiagnosticSink sink(sm);
        auto d = pddl::parse_domain(sm.add_buffer("domain.pddl", read(g_domain)), sm, sink);
        auto p = pddl::parse_problem(sm.add_buffer("problem.pddl", read(g_problem)), *d, sm, sink);
        out.im = pddl::import_pddl(*d, &*p, sink);
        plan::Budget budget({}, plan::Clock::now());
        auto task = compile(out.im->problem, budget);
        out.task.emplace(std::move(*task));
        return out;
    }();
    return l;
}

// The states of a seeded random walk from the initial state (a value per variable).
std::vector<std::vector<std::uint32_t>> walk(const Task& t, int steps) {
    StatePacker packer(t);
    SuccessorGenerator gen(t, packer);
    std::vector<Word> s(packer.words()), next(packer.words());
    packer.pack(t.initial, s.data());
    std::mt19937_64 rng(1);
    std::vector<std::vector<std::uint32_t>> out;
    std::vector<ActionId> ops;
    for (int i = 0; i < steps; ++i) {
        out.emplace_back();
        packer.unpack(s.data(), out.back());
        gen.applicable(s.data(), ops);
        std::shuffle(ops.begin(), ops.end(), rng);
        for (ActionId a : ops) {
            if (apply(t, packer, s.data(), a, next.data())) {
                s.swap(next);
                break;
            }
        }
    }
    return out;
}

void BM_Compile(benchmark::State& state) {
    auto& l = loaded();
    for (auto _ : state) {
        plan::Budget budget({}, plan::Clock::now());
        auto t = compile(l.im->problem, budget);
        benchmark::DoNotOptimize(t);
    }
    state.counters["actions"] = static_cast<double>(l.task->actions.size());
    state.counters["variables"] = static_cast<double>(l.task->vars.size());
}

void BM_Evaluate(benchmark::State& state, plan::HeuristicKind kind) {
    auto& l = loaded();
    RelaxedTask relaxed(*l.task);
    plan::Budget budget({}, plan::Clock::now());
    auto h = make_evaluator(kind, *l.task, relaxed, budget);
    auto states = walk(*l.task, 64);
    std::size_t i = 0;
    std::vector<ActionId> preferred;
    for (auto _ : state) {
        preferred.clear();
        const auto& s = states[i++ % states.size()];
        if (h->path_dependent()) {
            h->reach(kNone, kNone, 0, s, true);
        }
        benchmark::DoNotOptimize(h->evaluate(0, s, nullptr, &preferred));
    }
    state.counters["relaxed_actions"] = static_cast<double>(relaxed.num_actions());
}

void BM_Successors(benchmark::State& state) {
    auto& l = loaded();
    StatePacker packer(*l.task);
    SuccessorGenerator gen(*l.task, packer);
    auto states = walk(*l.task, 64);
    std::vector<std::vector<Word>> packed;
    for (const auto& s : states) {
        packed.emplace_back(packer.words());
        packer.pack(s, packed.back().data());
    }
    std::vector<ActionId> ops;
    std::size_t i = 0;
    for (auto _ : state) {
        gen.applicable(packed[i++ % packed.size()].data(), ops);
        benchmark::DoNotOptimize(ops.data());
    }
    state.counters["nodes"] = static_cast<double>(gen.nodes());
}

BENCHMARK(BM_Compile)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Evaluate, hff, plan::HeuristicKind::HFF)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Evaluate, hadd, plan::HeuristicKind::HAdd)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Evaluate, hmax, plan::HeuristicKind::HMax)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Evaluate, lmcut, plan::HeuristicKind::LmCut)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Evaluate, lmcount, plan::HeuristicKind::LmCount)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Successors)->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace catplan

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (argc >= 3) {
        catplan::g_domain = argv[argc - 2];
        catplan::g_problem = argv[argc - 1];
    } else {
        catplan::g_problem = CATPLAN_SOURCE_DIR "/bench/pddl/blocks30.pddl";
    }
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
