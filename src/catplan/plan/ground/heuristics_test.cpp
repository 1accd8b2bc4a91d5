#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/ground/compile.hpp"
#include "catplan/plan/ground/heuristics.hpp"
#include "catplan/plan/ground/successors.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace catplan::plan::ground {
namespace {

using namespace plan::testing;

constexpr int kInf = std::numeric_limits<int>::max();

// h_add or h_max by the textbook fixpoint (Bellman-Ford over the relaxed actions until nothing
// changes), without a queue and without stopping early.
int reference(const RelaxedTask& r, const std::vector<std::uint32_t>& state, bool max) {
    std::vector<int> cost(r.num_props(), kInf);
    std::vector<Prop> init;
    r.props_of(state, init);
    for (Prop p : init) {
        cost[p] = 0;
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& a : r.actions()) {
            int c = 0;
            for (Prop q : a.pre) {
                if (cost[q] == kInf) {
                    c = kInf;
                    break;
                }
                c = max ? std::max(c, cost[q]) : c + cost[q];
            }
            if (c == kInf) {
                continue;
            }
            for (Prop q : a.add) {
                if (c + a.cost < cost[q]) {
                    cost[q] = c + a.cost;
                    changed = true;
                }
            }
        }
    }
    int h = 0;
    for (Prop g : r.goal()) {
        if (cost[g] == kInf) {
            return kDeadEnd;
        }
        h = max ? std::max(h, cost[g]) : h + cost[g];
    }
    return h;
}

// The Dijkstra of h_add and h_max stops when every goal proposition has popped; its values are
// the fixpoint's, on every state of random walks (blocks of two problems and the paper's case
// study, whose goal has two terms).
TEST(GroundHeuristics, HAddAndHMaxStopEarlyWithTheFixpointsValues) {
    std::vector<ProblemPtr> problems = {paper_case_study()};
    for (std::uint64_t seed : {11u, 12u}) {
        std::mt19937_64 rng(seed);
        auto init = random_towers(7, rng);
        auto goal = random_towers(7, rng);
        problems.push_back(blocks_problem(blocks_domain(true), block_names(7), init, goal));
    }
    std::mt19937_64 rng(3);
    for (const auto& p : problems) {
        Budget budget({}, Clock::now());
        auto t = compile(p, budget);
        ASSERT_TRUE(t.has_value());
        RelaxedTask r(*t);
        auto hadd = make_evaluator(HeuristicKind::HAdd, *t, r, budget);
        auto hmax = make_evaluator(HeuristicKind::HMax, *t, r, budget);
        StatePacker packer(*t);
        SuccessorGenerator gen(*t, packer);
        std::vector<Word> s(packer.words()), next(packer.words());
        std::vector<std::uint32_t> values;
        std::vector<ActionId> ops;
        for (int walk = 0; walk < 10; ++walk) {
            packer.pack(t->initial, s.data());
            for (int step = 0; step < 20; ++step) {
                packer.unpack(s.data(), values);
                ASSERT_EQ(hadd->evaluate(0, values, nullptr, nullptr), reference(r, values, false))
                    << "walk " << walk << " step " << step;
                ASSERT_EQ(hmax->evaluate(0, values, nullptr, nullptr), reference(r, values, true))
                    << "walk " << walk << " step " << step;
                gen.applicable(s.data(), ops);
                std::erase_if(
                    ops, [&](ActionId a) { return !apply(*t, packer, s.data(), a, next.data()); });
                if (ops.empty()) {
                    break;
                }
                ASSERT_TRUE(apply(*t, packer, s.data(), ops[rng() % ops.size()], next.data()));
                s.swap(next);
            }
        }
    }
}

} // namespace
} // namespace catplan::plan::ground
