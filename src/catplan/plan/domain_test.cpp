#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/domain.hpp"

#include <gtest/gtest.h>

namespace catplan::plan {
namespace {

struct Parsed {
    SourceManager sources;
    DiagnosticSink sink{sources};
    std::optional<Plan> plan;

    explicit Parsed(std::string text) {
        auto f = sources.add_buffer("test.plan", std::move(text));
        plan = parse_plan(f, sources, sink);
    }
};

TEST(ParsePlan, StepsSeparatedByNewlinesAndSemicolons) {
    Parsed p("# the paper's plan\nunstack(E, D); putdown(E)\n\n  pickup( B )  # comment\nnoop\n"
             "stack(#3,D)");
    ASSERT_TRUE(p.plan) << p.sink.render();
    ASSERT_EQ(p.plan->steps.size(), 5u);
    EXPECT_EQ(p.plan->steps[0].action, "unstack");
    EXPECT_EQ(p.plan->steps[0].args, (std::vector<std::string>{"E", "D"}));
    EXPECT_EQ(p.plan->steps[2].args, (std::vector<std::string>{"B"}));
    EXPECT_TRUE(p.plan->steps[3].args.empty());
    EXPECT_EQ(p.plan->steps[4].args, (std::vector<std::string>{"#3", "D"}));
    EXPECT_EQ(p.plan->to_string(), "unstack(E, D)\nputdown(E)\npickup(B)\nnoop()\nstack(#3, D)\n");
    auto lc = p.sources.line_col(0, p.plan->steps[2].range.begin);
    EXPECT_EQ(lc.line, 4u);
    EXPECT_EQ(lc.col, 3u);
}

TEST(ParsePlan, PrintedPlanParsesBack) {
    Parsed p("a(X, Y)\nb()\n");
    ASSERT_TRUE(p.plan);
    Parsed q(p.plan->to_string());
    ASSERT_TRUE(q.plan);
    EXPECT_EQ(q.plan->to_string(), p.plan->to_string());
}

TEST(ParsePlan, EmptyPlan) {
    Parsed p("# nothing to do\n\n");
    ASSERT_TRUE(p.plan);
    EXPECT_TRUE(p.plan->steps.empty());
}

TEST(ParsePlan, ReportsEveryErrorWithItsLocation) {
    Parsed p("unstack(E D)\npickup(B)\nstack(B,)\nputdown(E) extra\n");
    EXPECT_FALSE(p.plan);
    ASSERT_EQ(p.sink.num_errors(), 3u);
    std::string text = p.sink.render();
    EXPECT_NE(text.find("test.plan:1:11: error: expected ',' or ')' in the arguments of 'unstack'"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("test.plan:3:9: error: expected an argument of 'stack'"), std::string::npos)
        << text;
    EXPECT_NE(text.find("test.plan:4:12: error: expected a new line or ';' after step "
                        "'putdown(E)'"),
              std::string::npos)
        << text;
}

TEST(ParsePlan, MissingActionName) {
    Parsed p("(A)\n");
    EXPECT_FALSE(p.plan);
    EXPECT_NE(p.sink.render().find("1:1: error: expected an action name"), std::string::npos);
}

TEST(ParsePlan, LineEndsAreLfCrlfOrCrAndAByteOrderMarkIsSkipped) {
    Parsed p("\xEF\xBB\xBF"
             "a(X)\rb(Y) # c\rc\r\nd(#2)");
    ASSERT_TRUE(p.plan) << p.sink.render();
    ASSERT_EQ(p.plan->steps.size(), 4u);
    EXPECT_EQ(p.plan->to_string(), "a(X)\nb(Y)\nc()\nd(#2)\n");
    EXPECT_EQ(p.sources.line_col(0, p.plan->steps[3].range.begin).line, 4u);
    EXPECT_EQ(p.sources.line_col(0, p.plan->steps[0].arg_ranges[0].begin).col, 3u);
}

TEST(ParsePlan, RejectsInvalidUtf8AndPartNumbersFromZero) {
    Parsed bad("a(X\xFF)\n");
    EXPECT_FALSE(bad.plan);
    EXPECT_NE(bad.sink.render().find("test.plan:1:4: error: invalid UTF-8"), std::string::npos)
        << bad.sink.render();
    Parsed zero("a(#0)\nb(#99999999999)\n");
    EXPECT_FALSE(zero.plan);
    EXPECT_EQ(zero.sink.num_errors(), 2u) << zero.sink.render();
    EXPECT_NE(zero.sink.render().find("test.plan:1:3: error: '#0' names no part"),
              std::string::npos)
        << zero.sink.render();
}

TEST(CheckPlan, ReportsEveryStepThatCannotBeRightWhateverTheState) {
    using namespace testing;
    auto p = blocks_problem(blocks_domain(true), {"A", "B", "C"}, {{0, 1}, {2}}, {{1, 0}});
    Parsed ok("unstack(B, A)\nputdown(B)\npickup(#1)\n");
    ASSERT_TRUE(ok.plan);
    EXPECT_TRUE(check_plan(*ok.plan, *p->domain, *p->initial, ok.sink)) << ok.sink.render();
    Parsed bad("unstack(B, A)\nteleport(B)\npickup(A, B)\nstack(Z, #4)\npickup(#3)\n");
    ASSERT_TRUE(bad.plan);
    EXPECT_FALSE(check_plan(*bad.plan, *p->domain, *p->initial, bad.sink));
    auto text = bad.sink.render();
    EXPECT_EQ(bad.sink.num_errors(), 4u) << text;
    EXPECT_NE(text.find("test.plan:2:1: error: unknown action 'teleport' (domain Blocks has: "
                        "pickup, putdown, unstack, stack)\n"
                        "    2 | teleport(B)\n"
                        "      | ^~~~~~~~\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("test.plan:3:1: error: pickup takes 1 argument (b), got 2"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("test.plan:4:7: error: argument 1 (b): no Block named 'Z' in the initial "
                        "state, and no action creates one"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("test.plan:4:10: error: argument 2 (u): '#4' names no part: there are 3 "
                        "Block parts and no action creates one"),
              std::string::npos)
        << text;
}

} // namespace
} // namespace catplan::plan
