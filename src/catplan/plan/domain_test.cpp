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

} // namespace
} // namespace catplan::plan
