#include "catplan/db/detail/test_databases.hpp"
#include "catplan/db/detail/test_states.hpp"
#include "catplan/db/library.hpp"

#include <gtest/gtest.h>

namespace catplan::db {
namespace {

using testing::FreshDatabase;
using testing::same_state;

TEST(Library, StoredStatesKeepNamesAndVariables) {
    SourceManager sources;
    lang::Module m =
        testing::load_example("examples/colorblocksworld/colorblocksworld.cp", sources);
    std::mt19937_64 rng(3);
    std::vector<acset::ACSet> states{*m.find("Initial")->instance};
    for (int i = 0; i < 8; ++i) {
        states.push_back(testing::random_state(m.find("ColorBlocksworld")->schema, rng, 6,
                                               /*partial=*/false));
    }
    for (const auto& x : states) {
        auto back = state_from_text(x.schema_ptr(), state_to_text(x));
        ASSERT_TRUE(back) << back.error();
        std::string why;
        EXPECT_TRUE(same_state(x, *back, &why)) << why;
    }
    EXPECT_FALSE(state_from_text(states[0].schema_ptr(), "{\"acset\": 3}"));
    EXPECT_FALSE(state_from_text(states[0].schema_ptr(), "not json"));
}

class LibraryTest : public ::testing::TestWithParam<Engine> {};

TEST_P(LibraryTest, TransfersInBatchesAndResumes) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    SourceManager sources;
    lang::Module m =
        testing::load_example("examples/colorblocksworld/colorblocksworld.cp", sources);
    const auto& problem = *m.find("CaseStudy")->problem;
    plan::Plan good, empty;
    for (auto [a, b] : {std::pair{"unstack", "E,D"},
                        {"putdown", "E"},
                        {"pickup", "B"},
                        {"stack", "B,D"},
                        {"pickup", "A"},
                        {"stack", "A,B"},
                        {"pickup", "E"},
                        {"stack", "E,A"}}) {
        plan::Step s{a, {}, {}};
        std::string args = b;
        for (std::size_t start = 0; start <= args.size();) {
            std::size_t comma = std::min(args.find(',', start), args.size());
            s.args.push_back(args.substr(start, comma - start));
            start = comma + 1;
        }
        good.steps.push_back(s);
    }
    std::vector<std::pair<std::string, plan::Plan>> plans;
    for (int i = 0; i < 7; ++i) {
        plans.emplace_back("plan" + std::to_string(i), i == 3 ? empty : good);
    }
    auto c = connect(db.url());
    ASSERT_TRUE(c) << c.error();
    ASSERT_TRUE(open_library(**c));
    auto stored = add_plans(**c, *problem.domain, "", problem, plans);
    ASSERT_TRUE(stored) << stored.error();
    ASSERT_EQ(stored->size(), 7U);

    std::string map =
        std::string(CATPLAN_SOURCE_DIR) + "/examples/colorblocks_to_kitchen/appendix_map.cp";
    std::vector<StoredTransfer> seen;
    auto collect = [&](const StoredTransfer& t) { seen.push_back(t); };
    auto first = transfer_library(**c, map, "ColorToKitchen", {2, 2, 3}, collect);
    ASSERT_TRUE(first) << first.error();
    EXPECT_EQ(first->transferred, 3U);
    auto rest = transfer_library(**c, map, "ColorToKitchen", {2, 3, 0}, collect);
    ASSERT_TRUE(rest) << rest.error();
    EXPECT_EQ(rest->transferred, 4U);
    EXPECT_EQ(rest->already_done, 3U);
    ASSERT_EQ(seen.size(), 7U);
    for (std::size_t i = 0; i < seen.size(); ++i) {
        EXPECT_EQ(seen[i].plan, (*stored)[i].id); // in plan order, each once
        EXPECT_EQ(seen[i].valid, i != 3) << to_json_line(seen[i]);
    }
    EXPECT_EQ(seen[0].goal_satisfied, seen[0].goal_total);
    EXPECT_EQ(seen[0].target_plan.size(), 8U);
    EXPECT_FALSE(seen[3].reason.empty());

    std::vector<StoredTransfer> failed;
    LibraryQuery q;
    q.valid = false;
    ASSERT_TRUE(query_transfers(**c, q, [&](const StoredTransfer& t) { failed.push_back(t); }));
    ASSERT_EQ(failed.size(), 1U);
    EXPECT_EQ(failed[0].label, "plan3");
    EXPECT_EQ(failed[0].reason, seen[3].reason);
    EXPECT_EQ(to_json_line(failed[0]), to_json_line(seen[3]));
}

TEST_P(LibraryTest, AProblemStoredWithOtherStatesIsRefused) {
    FreshDatabase db(GetParam());
    CATPLAN_REQUIRE_DATABASE(db);
    SourceManager sources;
    lang::Module m =
        testing::load_example("examples/colorblocksworld/colorblocksworld.cp", sources);
    plan::Problem p = *m.find("CaseStudy")->problem;
    auto c = connect(db.url());
    ASSERT_TRUE(c);
    ASSERT_TRUE(open_library(**c));
    ASSERT_TRUE(add_plans(**c, *p.domain, "", p, {}));
    p.initial = p.goal;
    auto again = add_plans(**c, *p.domain, "", p, {});
    ASSERT_FALSE(again);
    EXPECT_EQ(again.error(),
              "the library holds a problem CaseStudy of domain Blocksworld with other states");
}

INSTANTIATE_TEST_SUITE_P(Engines, LibraryTest,
                         ::testing::Values(Engine::SQLite, Engine::PostgreSQL),
                         testing::engine_name);

} // namespace
} // namespace catplan::db
