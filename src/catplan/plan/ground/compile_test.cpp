#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/ground/compile.hpp"

#include <gtest/gtest.h>

namespace catplan::plan::ground {
namespace {

using namespace plan::testing;

Task compiled(const ProblemPtr& p) {
    Budget budget({}, Clock::now());
    auto t = compile(p, budget);
    EXPECT_TRUE(t.has_value()) << (t ? "" : t.error());
    return t ? std::move(*t) : Task{};
}

std::vector<std::string> action_names(const Task& t) {
    std::vector<std::string> out;
    for (ActionId a = 0; a < t.actions.size(); ++a) {
        out.push_back(t.describe_action(a) + (t.actions[a].exit.empty() ? "" : " [exit]"));
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(Compile, StripsBlocksworldGroundsEveryMoveOfThreeBlocks) {
    auto p = blocks_problem(blocks_domain(true), {"A", "B", "C"}, {{0, 2}, {1}}, {{2, 1, 0}});
    Task t = compiled(p);
    // pickup and putdown of each block, stack and unstack of each ordered pair.
    EXPECT_EQ(t.actions.size(), 3u + 3u + 6u + 6u);
    for (const auto& a : t.actions) {
        EXPECT_TRUE(a.exit.empty());
        EXPECT_FALSE(a.pre.empty());
        EXPECT_FALSE(a.eff.empty());
    }
    ASSERT_EQ(t.goal.size(), 1u);
    EXPECT_EQ(t.goal[0].size(), 2u); // On(C, B), On(B, A)
    // Only atoms (the predicates) have variables: Block is an entity object.
    for (const auto& v : t.vars) {
        EXPECT_EQ(v.kind, Variable::Kind::Atom);
    }
}

TEST(Compile, ThePapersCaseStudyHasOneMarkerSlot) {
    auto p = paper_case_study();
    Task t = compiled(p);
    std::size_t slots = 0;
    for (const auto& o : t.objects) {
        slots += o.is_slot() ? 1 : 0;
    }
    EXPECT_EQ(slots, 1u); // the marker block
    auto names = action_names(t);
    for (const auto& n : names) {
        SCOPED_TRACE(n);
    }
    EXPECT_FALSE(names.empty());
    // putdown of the marker itself would change the marker, which the Empty part refers to.
    bool exit_seen = std::any_of(t.actions.begin(), t.actions.end(),
                                 [](const Action& a) { return !a.exit.empty(); });
    EXPECT_TRUE(exit_seen);
    EXPECT_EQ(t.goal.size(), 2u); // two purple blocks: D and E can be the top or the fourth
}

} // namespace
} // namespace catplan::plan::ground

#include "catplan/plan/ground/heuristics.hpp"
#include "catplan/plan/ground/successors.hpp"

namespace catplan::plan::ground {
namespace {
TEST(GroundHeuristics, LmCutIsAtLeastHMaxOnRandomWalks) {
    std::mt19937_64 rng(5);
    auto init = random_towers(6, rng);
    auto goal = random_towers(6, rng);
    auto p = blocks_problem(blocks_domain(true), block_names(6), init, goal);
    Budget budget({}, Clock::now());
    Task t = compiled(p);
    RelaxedTask r(t);
    auto hmax = make_evaluator(HeuristicKind::HMax, t, r, budget);
    auto lmcut = make_evaluator(HeuristicKind::LmCut, t, r, budget);
    StatePacker packer(t);
    SuccessorGenerator gen(t, packer);
    std::vector<Word> s(packer.words()), next(packer.words());
    std::vector<std::uint32_t> values;
    for (int walk = 0; walk < 20; ++walk) {
        packer.pack(t.initial, s.data());
        for (int step = 0; step < 15; ++step) {
            packer.unpack(s.data(), values);
            int a = hmax->evaluate(0, values, nullptr, nullptr);
            int b = lmcut->evaluate(0, values, nullptr, nullptr);
            ASSERT_GE(b, a) << "walk " << walk << " step " << step;
            std::vector<ActionId> ops;
            gen.applicable(s.data(), ops);
            ASSERT_FALSE(ops.empty());
            ActionId op = ops[rng() % ops.size()];
            ASSERT_TRUE(apply(t, packer, s.data(), op, next.data()));
            s.swap(next);
        }
    }
}
} // namespace
} // namespace catplan::plan::ground
