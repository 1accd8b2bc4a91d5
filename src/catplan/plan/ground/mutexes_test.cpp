#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/ground/compile.hpp"
#include "catplan/plan/ground/mutexes.hpp"
#include "catplan/plan/ground/successors.hpp"

#include <gtest/gtest.h>

#include <set>

namespace catplan::plan::ground {
namespace {

using namespace plan::testing;

Task compiled(const ProblemPtr& p) {
    Budget budget({}, Clock::now());
    auto t = compile(p, budget);
    EXPECT_TRUE(t.has_value()) << (t ? "" : t.error());
    return t ? std::move(*t) : Task{};
}

std::set<std::set<std::string>> described_groups(const Task& t) {
    std::set<std::set<std::string>> out;
    for (const auto& g : t.mutex_groups) {
        std::set<std::string> names;
        for (VarId v : g) {
            names.insert(t.describe(v));
        }
        out.insert(names);
    }
    return out;
}

TEST(MutexGroups, BlocksworldHasTheTranslatorsGroups) {
    auto p = blocks_problem(blocks_domain(true), {"A", "B", "C"}, {{0, 2}, {1}}, {{2, 1, 0}});
    Task t = compiled(p);
    // The three kinds of invariant: where a block is (on another, on the table, held), what is
    // on a block (a block, nothing, or it is held), and the hand (empty or holding one block).
    std::set<std::set<std::string>> expected = {
        {"HandEmpty()", "Holding(A)", "Holding(B)", "Holding(C)"}};
    for (std::string x : {"A", "B", "C"}) {
        std::set<std::string> where = {"Holding(" + x + ")", "OnTable(" + x + ")"};
        std::set<std::string> top = {"Holding(" + x + ")", "Clear(" + x + ")"};
        for (std::string y : {"A", "B", "C"}) {
            if (y != x) {
                where.insert("On(" + x + ", " + y + ")");
                top.insert("On(" + y + ", " + x + ")");
            }
        }
        expected.insert(where);
        expected.insert(top);
    }
    EXPECT_EQ(described_groups(t), expected);
    // The packer's groups are disjoint and cover every On and Holding atom.
    auto packed = disjoint_groups(t.mutex_groups);
    std::set<VarId> seen;
    std::size_t atoms = 0;
    for (const auto& g : packed) {
        EXPECT_GE(g.size(), 2u);
        for (VarId v : g) {
            EXPECT_TRUE(seen.insert(v).second) << t.describe(v) << " is in two groups";
        }
        atoms += g.size();
    }
    EXPECT_GE(atoms, 6u + 3u);
}

// Replays random walks twice: on a value per variable, and packed; the groups hold in every
// state reached and the packed states unpack to the same values.
void expect_groups_hold_on_walks(const Task& t, std::uint64_t seed) {
    StatePacker packer(t);
    SuccessorGenerator gen(t, packer);
    std::mt19937_64 rng(seed);
    std::vector<Word> s(packer.words()), next(packer.words());
    std::vector<std::uint32_t> plain, unpacked;
    std::vector<ActionId> ops;
    for (int walk = 0; walk < 30; ++walk) {
        plain = t.initial;
        packer.pack(plain, s.data());
        for (int step = 0; step < 40; ++step) {
            gen.applicable(s.data(), ops);
            std::erase_if(ops,
                          [&](ActionId a) { return !apply(t, packer, s.data(), a, next.data()); });
            if (ops.empty()) {
                break;
            }
            ActionId a = ops[rng() % ops.size()];
            ASSERT_TRUE(apply(t, packer, s.data(), a, next.data()));
            s.swap(next);
            for (const Fact& f : t.actions[a].eff) {
                plain[f.var] = f.value;
            }
            for (const auto& g : t.mutex_groups) {
                auto present =
                    std::count_if(g.begin(), g.end(), [&](VarId v) { return plain[v] == 1; });
                ASSERT_LE(present, 1)
                    << "walk " << walk << " step " << step << " after " << t.describe_action(a);
            }
            packer.unpack(s.data(), unpacked);
            ASSERT_EQ(unpacked, plain) << "walk " << walk << " step " << step;
        }
    }
}

TEST(MutexGroups, HoldOnRandomWalksAndPackedStatesMatch) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(seed);
        std::mt19937_64 rng(seed);
        auto init = random_towers(6, rng);
        auto goal = random_towers(6, rng);
        Task t = compiled(blocks_problem(blocks_domain(true), block_names(6), init, goal));
        EXPECT_FALSE(t.mutex_groups.empty());
        expect_groups_hold_on_walks(t, seed);
    }
    Task paper = compiled(paper_case_study());
    expect_groups_hold_on_walks(paper, 7);
}

TEST(MutexGroups, ThirtyBlocksPackIntoFourWords) {
    std::mt19937_64 rng(30);
    auto init = random_towers(30, rng);
    auto goal = random_towers(30, rng);
    Task t = compiled(blocks_problem(blocks_domain(true), block_names(30), init, goal));
    // 961 atoms: one bit each would take 16 words; 30 fields of 5 bits (31 atoms and none)
    // for the blocks' positions or tops, the rest 1 or 5 bits.
    StatePacker packer(t);
    EXPECT_LE(packer.words(), 4u);
    Task plain = t;
    plain.mutex_groups.clear();
    EXPECT_EQ(StatePacker(plain).words(), 16u);
}

} // namespace
} // namespace catplan::plan::ground
