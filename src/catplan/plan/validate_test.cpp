#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"

#include <gtest/gtest.h>

namespace catplan::plan {
namespace {

using namespace testing;

const std::vector<std::string> kABC{"A", "B", "C"};

Plan plan_of(std::vector<Step> steps) {
    return Plan{std::move(steps)};
}

Step st(std::string action, std::vector<std::string> args) {
    return Step{std::move(action), std::move(args), {}};
}

// B on A, C on the table; the goal is A on B.
ProblemPtr swap_problem() {
    return blocks_problem(blocks_domain(true), kABC, {{0, 1}, {2}}, {{1, 0}});
}

TEST(Validate, ValidPlanReachesTheGoal) {
    auto p = swap_problem();
    auto plan = plan_of({st("unstack", {"B", "A"}), st("putdown", {"B"}), st("pickup", {"A"}),
                         st("stack", {"A", "B"})});
    ValidateOptions opt;
    opt.keep_states = true;
    auto v = validate_plan(*p, plan, opt);
    EXPECT_TRUE(v.valid) << v.reason;
    EXPECT_TRUE(v.goal_reached);
    EXPECT_FALSE(v.failed_step);
    ASSERT_EQ(v.matches.size(), 4u);
    ASSERT_EQ(v.states.size(), 5u);
    // After unstack(B, A) the hand holds B and A is clear.
    const ACSet& x1 = v.states[1];
    ASSERT_EQ(x1.num_parts(kB.holding), 1u);
    EXPECT_EQ(x1.part_label(kB.block, x1.subpart(kB.held, 0)), "B");
    EXPECT_EQ(x1.num_parts(kB.on), 0u);
    EXPECT_EQ(x1.num_parts(kB.hand), 0u);
    // The match of stack(A, B) sends the parameters to A and B.
    const Rule& stack = *p->domain->find_rule("stack");
    EXPECT_EQ(v.states[3].part_label(kB.block, v.matches[3](kB.block, stack.parameters[0].part)),
              "A");
    EXPECT_EQ(
        describe_match(v.matches[0], p->domain->find_rule("unstack")->L, v.states[0]).substr(0, 7),
        "b ↦ B");
    ASSERT_TRUE(v.final_state);
    EXPECT_EQ(v.final_state->num_parts(kB.on), 1u);
}

TEST(Validate, StepWithoutMatchNamesTheMissingPart) {
    auto p = swap_problem();
    auto v = validate_plan(*p, plan_of({st("pickup", {"A"})}));
    EXPECT_FALSE(v.valid);
    ASSERT_TRUE(v.failed_step);
    EXPECT_EQ(*v.failed_step, 0u);
    EXPECT_EQ(v.reason, "step 1 pickup(A): no match: Clear cb (clearOf(cb) == b)");
}

TEST(Validate, MissingPartWithoutHomsIsNamed) {
    auto p = swap_problem();
    // After unstack the hand is full: pickup(C) misses the HandEmpty part.
    auto v = validate_plan(*p, plan_of({st("unstack", {"B", "A"}), st("pickup", {"C"})}));
    EXPECT_EQ(v.reason, "step 2 pickup(C): no match: HandEmpty he");
    EXPECT_EQ(v.matches.size(), 1u);
}

TEST(Validate, BadArguments) {
    auto p = swap_problem();
    EXPECT_EQ(validate_plan(*p, plan_of({st("fly", {"A"})})).reason,
              "step 1 fly(A): unknown action 'fly' (domain Blocks has: pickup, putdown, unstack, "
              "stack)");
    EXPECT_EQ(validate_plan(*p, plan_of({st("pickup", {"Z"})})).reason,
              "step 1 pickup(Z): argument 1 (b): no Block named 'Z' in the state");
    EXPECT_EQ(validate_plan(*p, plan_of({st("pickup", {"A", "B"})})).reason,
              "step 1 pickup(A, B): pickup takes 1 argument (b), got 2");
    EXPECT_EQ(validate_plan(*p, plan_of({st("unstack", {"B", "B"})})).reason,
              "step 1 unstack(B, B): arguments 1 (b) and 2 (u) name the same part 'B', but a "
              "match is injective");
    // `#k` names the k-th block: #3 is C, which is clear and on the table.
    auto v = validate_plan(*p, plan_of({st("pickup", {"#3"})}));
    EXPECT_EQ(v.matches.size(), 1u) << v.reason;
    EXPECT_EQ(validate_plan(*p, plan_of({st("pickup", {"#9"})})).reason,
              "step 1 pickup(#9): argument 1 (b): no Block named '#9' in the state");
}

TEST(Validate, AmbiguousStepListsTwoMatches) {
    auto p = swap_problem();
    auto d = std::make_shared<Domain>(*p->domain);
    // touch: keeps one block and names no parameter, so any block matches.
    ACSet l(d->schema);
    add_block(l, "b", true);
    auto touch = std::make_shared<Rule>(d->schema);
    touch->name = "touch";
    touch->L = l;
    touch->K = l;
    touch->R = l;
    touch->l = hom::identity(l);
    touch->r = hom::identity(l);
    d->rules.push_back(touch);
    auto q = std::make_shared<Problem>(*p);
    q->domain = d;
    auto v = validate_plan(*q, plan_of({st("touch", {})}));
    EXPECT_EQ(v.reason, "step 1 touch(): ambiguous: the arguments leave several matches, e.g. "
                        "{b ↦ A, ?1 ↦ \"A\"} and {b ↦ B, ?1 ↦ \"B\"}");
}

TEST(Validate, GoalNotReached) {
    auto p = swap_problem();
    auto v = validate_plan(*p, plan_of({st("unstack", {"B", "A"}), st("putdown", {"B"})}));
    EXPECT_FALSE(v.valid);
    EXPECT_FALSE(v.goal_reached);
    EXPECT_FALSE(v.failed_step);
    EXPECT_EQ(v.reason, "goal not reached: nothing satisfies On #1 (onL(#1) == A)");
}

// A on B, and B not on the table: a negative goal condition (PDDL's (not (ontable b))).
ProblemPtr a_on_b_not_on_table() {
    auto p = std::make_shared<Problem>(
        *blocks_problem(blocks_domain(true), kABC, {{0}, {1}, {2}}, {{1, 0}}));
    ACSet n = *p->goal;
    add_fact(n, kB.table, kB.table_of, *n.find_part(kB.block, "B"), "");
    hom::ACSetMorphism g_to_n;
    for (std::uint32_t o = 0; o < n.schema().num_obs(); ++o) {
        g_to_n.components.emplace_back();
        for (Part q = 0; q < p->goal->num_parts(ObId(o)); ++q) {
            g_to_n.components.back().push_back(q); // the goal's parts come first in N
        }
    }
    g_to_n.var_components.resize(n.schema().num_attr_types());
    p->goal_conditions.push_back({"B not on the table", true, std::move(n), g_to_n, {}});
    return p;
}

TEST(Validate, AGoalConditionMustNotExtendTheGoalsEmbedding) {
    auto p = a_on_b_not_on_table();
    auto short_plan = plan_of({st("pickup", {"A"}), st("stack", {"A", "B"})});
    auto v = validate_plan(*p, short_plan);
    EXPECT_FALSE(v.goal_reached);
    EXPECT_EQ(v.reason, "goal not reached: the negative condition 'B not on the table' holds");
    // Without the condition the same plan reaches the goal.
    auto q = std::make_shared<Problem>(*p);
    q->goal_conditions.clear();
    EXPECT_TRUE(validate_plan(*q, short_plan).valid);
    auto longer = plan_of({st("pickup", {"B"}), st("stack", {"B", "C"}), st("pickup", {"A"}),
                           st("stack", {"A", "B"})});
    EXPECT_TRUE(validate_plan(*p, longer).valid);
}

TEST(Validate, BothSearchesPlanForAGoalCondition) {
    auto p = a_on_b_not_on_table();
    for (bool ground : {true, false}) {
        SearchOptions opt;
        opt.ground = ground;
        auto r = find_plan(*p, opt);
        ASSERT_EQ(r.status, SearchStatus::Solved) << ground;
        EXPECT_EQ(r.path, ground ? "grounded" : "C-set") << r.path_reason;
        EXPECT_EQ(r.plan->steps.size(), 4U) << r.plan->to_string();
        EXPECT_TRUE(validate_plan(*p, *r.plan).valid) << r.plan->to_string();
    }
}

TEST(Validate, EmptyPlanOnSatisfiedGoal) {
    auto p = blocks_problem(blocks_domain(true), kABC, {{0, 1}, {2}}, {{0, 1}});
    auto v = validate_plan(*p, Plan{});
    EXPECT_TRUE(v.valid);
    EXPECT_TRUE(v.goal_reached);
}

TEST(Validate, ExplainNoEmbeddingFollowsBindings) {
    auto d = blocks_domain(false);
    ACSet x = blocks_state(d->schema, kABC, {{0, 1}, {2}});
    const Rule& unstack = *d->find_rule("unstack");
    // unstack(C, A): nothing is on A... as seen from C: no On with onL == C.
    std::vector<hom::PartBinding> bind{{kB.block, 0, 2}, {kB.block, 1, 0}};
    auto why = explain_no_embedding(unstack.L, x, bind);
    ASSERT_TRUE(why);
    EXPECT_EQ(*why, "On o (onL(o) == b, onR(o) == u)");
    std::vector<hom::PartBinding> ok{{kB.block, 0, 1}, {kB.block, 1, 0}};
    EXPECT_FALSE(explain_no_embedding(unstack.L, x, ok));
}

} // namespace
} // namespace catplan::plan
