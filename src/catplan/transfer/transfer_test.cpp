#include "catplan/hom/isomorphism.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/transfer/correspond.hpp"
#include "catplan/transfer/rename.hpp"
#include "catplan/transfer/transfer.hpp"

#include <gtest/gtest.h>

namespace catplan::transfer {
namespace {

using acset::Value;
using migrate::Query;
using migrate::Term;
using schema::Schema;
using schema::SchemaPtr;
using schema::ValueKind;

// Source domain: blocks stacked by On facts, each with a colour; move(b, from, to) moves block b
// from on top of `from` to on top of `to` (no clear conditions: enough to exercise transfer).
struct Stacks {
    SchemaPtr s;
    ObId block, on;
    HomId on_l, on_r;
    AttrTypeId color_type;
    AttrId color;
};

Stacks stacks() {
    auto s = std::make_shared<Schema>("Stacks");
    Stacks t;
    t.block = s->add_ob("Block");
    t.on = s->add_ob("On");
    t.on_l = s->add_hom("on_l", t.on, t.block);
    t.on_r = s->add_hom("on_r", t.on, t.block);
    t.color_type = s->add_attr_type("Color", ValueKind::String);
    t.color = s->add_attr("hasColor", t.block, t.color_type);
    t.s = s;
    return t;
}

rewrite::RulePtr move_rule(const Stacks& t) {
    auto rule = std::make_shared<rewrite::Rule>(t.s);
    rule->name = "move";
    for (ACSet* x : {&rule->L, &rule->K, &rule->R}) {
        for (const char* n : {"b", "from", "to"}) {
            x->add_part(t.block, n);
        }
    }
    Part o = rule->L.add_part(t.on, "o");
    rule->L.set_subpart(t.on_l, o, 0);
    rule->L.set_subpart(t.on_r, o, 1);
    Part o2 = rule->R.add_part(t.on, "o2");
    rule->R.set_subpart(t.on_l, o2, 0);
    rule->R.set_subpart(t.on_r, o2, 2);
    rule->l = hom::identity(rule->K);
    rule->r = hom::identity(rule->K);
    rule->parameters = {{"b", t.block, 0}, {"from", t.block, 1}, {"to", t.block, 2}};
    EXPECT_TRUE(rewrite::check_rule(*rule).empty());
    return rule;
}

ACSet blocks_state(const Stacks& t, const std::vector<std::pair<Part, Part>>& ons) {
    ACSet x(t.s);
    const char* names[] = {"A", "B", "C", "D"};
    const char* colors[] = {"purple", "red", "purple", "green"};
    for (int i = 0; i < 4; ++i) {
        Part p = x.add_part(t.block, names[i]);
        x.set_subpart(t.color, p, Value::string(colors[i]));
    }
    for (auto [top, below] : ons) {
        Part o = x.add_part(t.on);
        x.set_subpart(t.on_l, o, top);
        x.set_subpart(t.on_r, o, below);
    }
    return x;
}

// A on B, then move A onto C, then B onto D.
struct Fixture {
    Stacks t = stacks();
    plan::ProblemPtr problem;
    plan::Plan plan;

    Fixture() {
        auto domain = std::make_shared<plan::Domain>();
        domain->name = "Moves";
        domain->schema = t.s;
        domain->rules = {move_rule(t)};
        auto p = std::make_shared<plan::Problem>();
        p->name = "P";
        p->domain = domain;
        p->initial = std::make_shared<ACSet>(blocks_state(t, {{0, 1}, {1, 3}}));
        ACSet goal(t.s);
        Part a = goal.add_part(t.block, "a");
        Part c = goal.add_part(t.block, "c");
        goal.set_subpart(t.color, a, Value::string("purple"));
        goal.set_subpart(t.color, c, Value::string("purple"));
        Part o = goal.add_part(t.on, "o");
        goal.set_subpart(t.on_l, o, a);
        goal.set_subpart(t.on_r, o, c);
        p->goal = std::make_shared<ACSet>(std::move(goal));
        problem = p;
        plan.steps = {{"move", {"A", "B", "C"}, {}}, {"move", {"B", "D", "A"}, {}}};
    }
};

// Target: Things and Rels, a renaming of the source (a delta map).
SchemaMap renaming_map(const Stacks& t, bool swap) {
    auto s = std::make_shared<Schema>("Things");
    ObId thing = s->add_ob("Thing");
    ObId rel = s->add_ob("Rel");
    HomId top = s->add_hom("top", rel, thing);
    HomId below = s->add_hom("below", rel, thing);
    AttrTypeId paint = s->add_attr_type("Paint", ValueKind::String);
    AttrId painted = s->add_attr("painted", thing, paint);
    SchemaMap f(s, t.s);
    f.map_ob(thing, Query::representable(t.s, t.block, "x"));
    f.map_ob(rel, t.on);
    f.map_hom_path(top, {swap ? t.on_r : t.on_l});
    f.map_hom_path(below, {swap ? t.on_l : t.on_r});
    f.map_attr_type(paint, t.color_type);
    f.map_attr(painted, Term::path("x", {}, t.color));
    for (const auto& p : f.finish()) {
        ADD_FAILURE() << p.message;
    }
    return f;
}

// Target: Items on Items, with the purple blocks also Bread (a conjunctive map).
struct Kitchen {
    SchemaPtr s;
    ObId item, bread, in;
    HomId in_l, in_r, bread_is_item;
};

Kitchen kitchen() {
    auto s = std::make_shared<Schema>("Kitchen");
    Kitchen k;
    k.item = s->add_ob("Item");
    k.bread = s->add_ob("BreadSliced");
    k.in = s->add_ob("InReceptacle");
    k.in_l = s->add_hom("in_l", k.in, k.item);
    k.in_r = s->add_hom("in_r", k.in, k.item);
    k.bread_is_item = s->add_hom("breadIsItem", k.bread, k.item);
    k.s = s;
    return k;
}

SchemaMap kitchen_map(const Stacks& t, const Kitchen& k) {
    SchemaMap f(k.s, t.s);
    f.map_ob(k.item, t.block);
    f.map_ob(k.in, t.on);
    f.map_hom_path(k.in_l, {t.on_l});
    f.map_hom_path(k.in_r, {t.on_r});
    Query q(t.s);
    q.add_variable("block", t.block);
    q.add_equation(Term::path("block", {}, t.color), Term::constant(Value::string("purple")));
    f.map_ob(k.bread, std::move(q));
    f.map_hom(k.bread_is_item, {Term::path("block")});
    EXPECT_TRUE(f.finish().empty());
    return f;
}

std::vector<std::string> target_plan(const TransferResult& r) {
    std::vector<std::string> out;
    for (const auto& s : r.steps) {
        out.push_back(s.target.to_string());
    }
    return out;
}

TEST(Transfer, DeltaMapGivesTheMigratedStates) {
    Fixture fx;
    SchemaMap f = renaming_map(fx.t, false);
    TransferOptions opt;
    opt.keep_states = true;
    auto r = transfer_plan(f, *fx.problem, fx.plan, opt);
    EXPECT_EQ(r.migration, MigrationKind::Delta);
    EXPECT_TRUE(r.verdict.source_valid());
    ASSERT_TRUE(r.verdict.valid()) << r.verdict.reason();
    EXPECT_EQ(target_plan(r), (std::vector<std::string>{"move(A, B, C)", "move(B, D, A)"}));
    ASSERT_EQ(r.target_states.size(), 3u);
    ASSERT_EQ(r.source_states.size(), 3u);
    // Y_i = Δ_F(X_i) at every step (paper Appendix A).
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(hom::is_isomorphic(r.target_states[i], migrate::migrate(f, r.source_states[i])))
            << "step " << i;
    }
    EXPECT_EQ(r.verdict.goal.satisfied, r.verdict.goal.total);
    EXPECT_EQ(r.verdict.goal.total, 7u); // 2 blocks, 2 colours, 1 fact with 2 homs
}

TEST(Transfer, SwappedHomsTransferConsistently) {
    // Swapping top and below is a functor too: the plan still transfers (both the actions and the
    // goal are read through the same map).
    Fixture fx;
    auto r = transfer_plan(renaming_map(fx.t, true), *fx.problem, fx.plan);
    EXPECT_TRUE(r.verdict.valid()) << r.verdict.reason();
}

TEST(Transfer, ConjunctiveMapCarriesMatchesByName) {
    Fixture fx;
    Kitchen k = kitchen();
    SchemaMap f = kitchen_map(fx.t, k);
    auto r = transfer_plan(f, *fx.problem, fx.plan);
    EXPECT_EQ(r.migration, MigrationKind::Conjunctive);
    ASSERT_TRUE(r.verdict.valid()) << r.verdict.reason();
    EXPECT_EQ(target_plan(r), (std::vector<std::string>{"move(A, B, C)", "move(B, D, A)"}));
    EXPECT_EQ(r.steps[0].target_bindings.find("b ↦ A"), 0u) << r.steps[0].target_bindings;
    // The purple blocks A and C are bread in the target.
    ASSERT_TRUE(r.final_state);
    EXPECT_EQ(r.final_state->num_parts(k.bread), 2u);
    EXPECT_DOUBLE_EQ(r.verdict.goal.fraction(), 1.0);
}

TEST(Transfer, BindingsAreDescribedOnlyWhenAskedFor) {
    Fixture fx;
    Kitchen k = kitchen();
    SchemaMap f = kitchen_map(fx.t, k);
    TransferOptions opt;
    opt.describe_bindings = false;
    auto r = transfer_plan(f, *fx.problem, fx.plan, opt);
    ASSERT_TRUE(r.verdict.valid()) << r.verdict.reason();
    ASSERT_EQ(r.steps.size(), 2u);
    for (const auto& st : r.steps) {
        EXPECT_EQ(st.source_bindings, "");
        EXPECT_EQ(st.target_bindings, "");
    }
    // The same plan, the same verdict, as with the bindings described (the default).
    auto described = transfer_plan(f, *fx.problem, fx.plan);
    EXPECT_EQ(target_plan(r), target_plan(described));
    EXPECT_NE(described.steps[0].source_bindings, "");
}

TEST(Transfer, RenameByTypeNamesPartsAfterTheirMostSpecificType) {
    Fixture fx;
    Kitchen k = kitchen();
    SchemaMap f = kitchen_map(fx.t, k);
    TransferOptions opt;
    opt.rename_by_type = true;
    auto r = transfer_plan(f, *fx.problem, fx.plan, opt);
    ASSERT_TRUE(r.verdict.valid()) << r.verdict.reason();
    // A and C are bread (is-a Item); B and D only items.
    EXPECT_EQ(target_plan(r), (std::vector<std::string>{"move(bread1, item1, bread2)",
                                                        "move(item1, item2, bread1)"}));
    ACSet y0 = migrate::migrate(f, *fx.problem->initial);
    auto names = names_by_type(y0);
    EXPECT_EQ(names.at("A"), "bread1");
    EXPECT_EQ(names.at("D"), "item2");
}

// The fixture's problem with move costing 1 + dist(from, to), and the values of dist its plan
// reads (B to C 5, D to A 7), but D to A only when `complete`.
plan::ProblemPtr with_distances(const Fixture& fx, bool complete) {
    auto rule = std::make_shared<rewrite::Rule>(*fx.problem->domain->rules[0]);
    rule->cost = rewrite::Cost{1, {{"dist", {{1, {}}, {2, {}}}}}};
    auto domain = std::make_shared<plan::Domain>(*fx.problem->domain);
    domain->rules = {rule};
    auto p = std::make_shared<plan::Problem>(*fx.problem);
    p->domain = domain;
    p->values = {{"dist", {"B", "C"}, 5, {}}, {"dist", {"A", "D"}, 100, {}}};
    if (complete) {
        p->values.push_back({"dist", {"D", "A"}, 7, {}});
    }
    plan::set_step_cost(*p);
    return p;
}

TEST(Transfer, CostsAreCarriedByNameIntoTheGeneratedActions) {
    Fixture fx;
    auto p = with_distances(fx, true);
    for (bool rename : {false, true}) {
        Kitchen k = kitchen();
        TransferOptions opt;
        opt.rename_by_type = rename;
        for (const SchemaMap& f : {renaming_map(fx.t, false), kitchen_map(fx.t, k)}) {
            auto r = transfer_plan(f, *p, fx.plan, opt);
            ASSERT_TRUE(r.verdict.valid()) << r.verdict.reason();
            auto costs = plan_costs(r, *p, fx.plan);
            ASSERT_TRUE(costs.has_value());
            ASSERT_TRUE(costs->source.has_value()) << costs->source.error();
            EXPECT_EQ(*costs->source, 14); // (1 + 5) + (1 + 7)
            ASSERT_TRUE(costs->target.has_value()) << costs->target.error();
            EXPECT_EQ(*costs->target, 14) << "renamed: " << rename;
            // Replanning in the generated actions sums the same costs.
            plan::Problem target = target_problem(r);
            ASSERT_NE(target.step_cost, nullptr);
        }
    }
    // Measured by steps, the problem sums no costs, and neither does its transfer.
    auto steps = std::make_shared<plan::Problem>(*p);
    steps->counts_steps = true;
    plan::set_step_cost(*steps);
    auto r = transfer_plan(renaming_map(fx.t, false), *steps, fx.plan);
    EXPECT_FALSE(plan_costs(r, *steps, fx.plan).has_value());
    EXPECT_EQ(target_problem(r).step_cost, nullptr);
}

TEST(Transfer, AStepWithoutAValueCannotBeTakenInTheSourcePlan) {
    Fixture fx;
    auto p = with_distances(fx, false);
    auto r = transfer_plan(renaming_map(fx.t, false), *p, fx.plan);
    // As validate_plan says: the step cannot be taken, so the source plan is invalid there.
    EXPECT_FALSE(r.verdict.source_valid());
    auto v = plan::validate_plan(*p, fx.plan);
    ASSERT_FALSE(v.valid);
    EXPECT_EQ(v.reason,
              "step 2 move(B, D, A): its cost 1 + dist(D, A) has no value in the problem");
    ASSERT_EQ(r.verdict.faults.size(), 1U);
    const Fault& f = r.verdict.faults.front();
    EXPECT_EQ(f.kind, Fault::Kind::SourcePlan);
    EXPECT_EQ(f.step, std::optional<std::size_t>(1));
    EXPECT_EQ(f.where + ": " + f.why, v.reason);
    EXPECT_FALSE(plan_costs(r, *p, fx.plan).has_value());
}

TEST(Transfer, SourceFaultsTakeTheWordsOfTheUsersOwnValidator) {
    Fixture fx;
    plan::Plan bad;
    bad.steps = {{"move", {"A", "C", "D"}, {}}};
    auto own = [](std::optional<std::size_t> step) {
        return [step]() -> std::optional<Fault> {
            return Fault{Fault::Kind::Step, step, "step 1 (move a c d)", "(clear a) is false"};
        };
    };
    // Where the validator finds the step the replay stopped at, the verdict says what it says.
    TransferOptions o;
    o.source_fault = own(0);
    auto r = transfer_plan(renaming_map(fx.t, false), *fx.problem, bad, o);
    ASSERT_FALSE(r.verdict.faults.empty());
    const Fault& f = r.verdict.faults.front();
    EXPECT_EQ(f.kind, Fault::Kind::SourcePlan);
    EXPECT_EQ(f.step, std::optional<std::size_t>(0));
    EXPECT_EQ(r.verdict.reason(),
              "the source plan is invalid: step 1 (move a c d): (clear a) is false");
    // Where it finds another (or none), the replay's own words stay.
    o.source_fault = own(1);
    auto r2 = transfer_plan(renaming_map(fx.t, false), *fx.problem, bad, o);
    auto plain = transfer_plan(renaming_map(fx.t, false), *fx.problem, bad);
    EXPECT_EQ(r2.verdict.reason(), plain.verdict.reason());
    EXPECT_EQ(plain.verdict.reason().rfind("the source plan is invalid: step 1 move(A, C, D): ", 0),
              0U)
        << plain.verdict.reason();
}

TEST(Transfer, AFaultIsSplitWhereItsReasonNamesTheStep) {
    auto f = Fault::from_reason(Fault::Kind::SourcePlan, 2, "step 3 (stack a b)",
                                "step 3 (stack a b): precondition (holding a) does not hold");
    EXPECT_EQ(f.where, "step 3 (stack a b)");
    EXPECT_EQ(f.why, "precondition (holding a) does not hold");
    auto g = Fault::from_reason(Fault::Kind::SourcePlan, 2, "step 3 stack(a, b)",
                                "goal not reached: (on a b) does not hold");
    EXPECT_EQ(g.where, "");
    EXPECT_EQ(g.to_string(), "goal not reached: (on a b) does not hold");
}

TEST(Transfer, ParametersTheMapCannotSeeAreReported) {
    Fixture fx;
    // Only purple blocks are items here, and move's blocks have no colour in its precondition:
    // the migrated action keeps none of its parameters, which the transfer reports.
    auto s = std::make_shared<Schema>("Purple");
    ObId item = s->add_ob("Item");
    SchemaMap f(s, fx.t.s);
    Query q(fx.t.s);
    q.add_variable("block", fx.t.block);
    q.add_equation(Term::path("block", {}, fx.t.color), Term::constant(Value::string("purple")));
    f.map_ob(item, std::move(q));
    ASSERT_TRUE(f.finish().empty());
    auto r = transfer_plan(f, *fx.problem, fx.plan);
    ASSERT_EQ(r.steps.size(), 2u);
    EXPECT_EQ(r.steps[0].target.to_string(), "move()");
    EXPECT_EQ(r.steps[0].lost_parameters, (std::vector<std::string>{"b", "from", "to"}));
}

TEST(Transfer, InvalidSourcePlanIsReported) {
    Fixture fx;
    plan::Plan bad;
    bad.steps = {{"move", {"A", "C", "D"}, {}}};
    auto r = transfer_plan(renaming_map(fx.t, false), *fx.problem, bad);
    EXPECT_FALSE(r.verdict.source_valid());
    EXPECT_FALSE(r.verdict.valid());
    EXPECT_NE(r.verdict.reason().find("the source plan is invalid"), std::string::npos)
        << r.verdict.reason();
}

// A goal in the Kitchen schema: n bread slices, each with the item it is.
std::shared_ptr<const ACSet> bread_goal(const Kitchen& k, int n) {
    auto g = std::make_shared<ACSet>(k.s);
    for (int i = 0; i < n; ++i) {
        Part item = g->add_part(k.item);
        Part b = g->add_part(k.bread);
        g->set_subpart(k.bread_is_item, b, item);
    }
    return g;
}

TEST(Transfer, TheIntendedGoalJudgesTheVerdict) {
    Fixture fx;
    Kitchen k = kitchen();
    SchemaMap f = kitchen_map(fx.t, k);
    TransferOptions opt;
    opt.goal = bread_goal(k, 2); // A and C are purple: two slices
    opt.goal_name = "TwoSlices";
    auto met = transfer_plan(f, *fx.problem, fx.plan, opt);
    ASSERT_TRUE(met.verdict.valid()) << met.verdict.reason();
    EXPECT_EQ(met.verdict.goal_name, "TwoSlices");
    EXPECT_EQ(met.verdict.goal.total, 6u); // 4 parts, 2 hom values
    EXPECT_EQ(met.verdict.goal.satisfied, 6u);

    opt.goal = bread_goal(k, 3);
    opt.goal_name = "ThreeSlices";
    auto unmet = transfer_plan(f, *fx.problem, fx.plan, opt);
    const Verdict& v = unmet.verdict;
    EXPECT_FALSE(v.valid());
    EXPECT_EQ(v.status, Verdict::Status::Invalid);
    // Every step applies and Δ_F(G) embeds: the intended goal is the only fault.
    ASSERT_EQ(v.faults.size(), 1u);
    EXPECT_EQ(v.faults[0].kind, Fault::Kind::IntendedGoal);
    EXPECT_EQ(v.reason(), "the intended goal ThreeSlices is not satisfied");
    EXPECT_TRUE(v.source_valid());
    EXPECT_EQ(v.failed_step(), nullptr);
    EXPECT_EQ(v.goal.total, 9u);
    EXPECT_EQ(v.goal.satisfied, 7u); // the third slice and its hom value have no purple block
    EXPECT_EQ(v.goal.unsatisfied.size(), 2u);
}

TEST(Transfer, FaultsComeInTheOrderTheTransferMeetsThem) {
    // The empty plan leaves A on B (purple on red): neither Δ_F(G) nor G is reached; the target
    // goal's fault decides, the source plan's follows.
    Fixture fx;
    auto r = transfer_plan(renaming_map(fx.t, false), *fx.problem, plan::Plan{});
    const Verdict& v = r.verdict;
    ASSERT_EQ(v.faults.size(), 2u);
    EXPECT_EQ(v.faults[0].kind, Fault::Kind::Goal);
    EXPECT_EQ(v.faults[1].kind, Fault::Kind::SourcePlan);
    EXPECT_EQ(v.reason().rfind("goal not reached: ", 0), 0u) << v.reason();
    EXPECT_FALSE(v.source_valid());
    EXPECT_EQ(v.failed_step(), nullptr);

    // A source step that does not apply stops the replay: that fault comes first.
    plan::Plan bad;
    bad.steps = {{"move", {"A", "C", "D"}, {}}};
    auto s = transfer_plan(renaming_map(fx.t, false), *fx.problem, bad);
    const Fault* failed = s.verdict.failed_step();
    ASSERT_NE(failed, nullptr);
    EXPECT_EQ(failed->kind, Fault::Kind::SourcePlan);
    EXPECT_EQ(failed->step, 0u);
    EXPECT_EQ(failed->where, "step 1 move(A, C, D)");
    EXPECT_EQ(s.verdict.reason(), "the source plan is invalid: " + failed->to_string());
    EXPECT_TRUE(s.steps.empty());
}

TEST(Transfer, ValidByConstructionIsClaimedOnlyForADeltaMap) {
    Fixture fx;
    auto delta = transfer_plan(renaming_map(fx.t, false), *fx.problem, fx.plan);
    EXPECT_TRUE(delta.verdict.claim(Claim::Kind::ValidByConstruction).holds());
    Kitchen k = kitchen();
    auto conjunctive = transfer_plan(kitchen_map(fx.t, k), *fx.problem, fx.plan);
    const Claim& c = conjunctive.verdict.claim(Claim::Kind::ValidByConstruction);
    EXPECT_FALSE(c.holds());
    ASSERT_NE(c.failing(), nullptr);
    EXPECT_EQ(c.failing()->statement, "F is a delta map (Δ_F preserves pushouts)");
    EXPECT_EQ(c.failing()->why_not, "it sends BreadSliced to a query");
    // The claim is about the method, not the outcome: the conjunctive transfer is still valid.
    EXPECT_TRUE(conjunctive.verdict.valid());
}

// paint_red(b) makes block b red; with `test_purple` its Pre requires b to be purple.
std::shared_ptr<rewrite::Rule> paint_red_rule(const Stacks& t, bool test_purple) {
    auto rule = std::make_shared<rewrite::Rule>(t.s);
    rule->name = "paint_red";
    for (ACSet* x : {&rule->L, &rule->K, &rule->R}) {
        x->add_part(t.block, "b");
    }
    rule->K.set_subpart(t.color, 0, rule->K.add_var(t.color_type));
    rule->L.set_subpart(t.color, 0,
                        test_purple ? Value::string("purple") : rule->L.add_var(t.color_type));
    rule->R.set_subpart(t.color, 0, Value::string("red"));
    rule->l = hom::identity(rule->K);
    rule->l.var_components[t.color_type.index()] = {rule->L.subpart(t.color, 0)};
    rule->r = hom::identity(rule->K);
    rule->r.var_components[t.color_type.index()] = {Value::string("red")};
    rule->parameters = {{"b", t.block, 0}};
    EXPECT_TRUE(rewrite::check_rule(*rule).empty());
    return rule;
}

// The fixture's problem with paint_red as its only action and no goal to speak of.
plan::ProblemPtr painting(const Fixture& fx, rewrite::RulePtr rule) {
    auto domain = std::make_shared<plan::Domain>();
    domain->name = "Painting";
    domain->schema = fx.t.s;
    domain->rules = {std::move(rule)};
    auto p = std::make_shared<plan::Problem>(*fx.problem);
    p->domain = domain;
    p->goal = std::make_shared<ACSet>(fx.t.s);
    return p;
}

TEST(Transfer, ADivergentTrajectoryIsReportedWithWhatDiffers) {
    // The purple blocks are bread. paint_red(A) does not test A's colour, so its migration
    // cannot see that A stops being bread: the target keeps A's slice, Δ_F(X1) has none.
    Fixture fx;
    Kitchen k = kitchen();
    SchemaMap f = kitchen_map(fx.t, k);
    plan::Plan plan;
    plan.steps = {{"paint_red", {"A"}, {}}, {"paint_red", {"C"}, {}}};
    auto r = transfer_plan(f, *painting(fx, paint_red_rule(fx.t, false)), plan);
    const Verdict& v = r.verdict;
    ASSERT_EQ(r.steps.size(), 2u);
    ASSERT_NE(v.diverged(), nullptr);
    EXPECT_EQ(v.divergences.size(), 1u); // the later states are not compared
    EXPECT_EQ(v.diverged()->step, 0u);
    EXPECT_EQ(v.diverged()->where, "step 1 paint_red(A)");
    EXPECT_EQ(v.diverged()->only_in_target,
              (std::vector<std::string>{"BreadSliced A", "breadIsItem(A) == A"}));
    EXPECT_TRUE(v.diverged()->only_in_migrated.empty());
    // Not a fault by default, but never called valid without saying so.
    EXPECT_TRUE(v.valid()) << v.reason();
    EXPECT_NE(v.summary().find("not the migration of the source plan"), std::string::npos)
        << v.summary();
    EXPECT_NE(v.summary().find("after step 1 paint_red(A)"), std::string::npos) << v.summary();

    TransferOptions strict;
    strict.strict = true;
    auto s = transfer_plan(f, *painting(fx, paint_red_rule(fx.t, false)), plan, strict);
    EXPECT_FALSE(s.verdict.valid());
    ASSERT_FALSE(s.verdict.faults.empty());
    EXPECT_EQ(s.verdict.faults[0].kind, Fault::Kind::Divergence);
    EXPECT_EQ(s.verdict.failed_step(), nullptr);
    EXPECT_EQ(s.verdict.reason(), "step 1 paint_red(A): the target state is not Δ_F(X1): it has "
                                  "BreadSliced A and breadIsItem(A) == A, which Δ_F(X1) has not");
}

TEST(Transfer, FollowingTheSourceTakesTheMigratedStatesAndChecksEachStep) {
    Fixture fx;
    Kitchen k = kitchen();
    SchemaMap f = kitchen_map(fx.t, k);
    plan::Plan plan;
    plan.steps = {{"paint_red", {"A"}, {}}, {"paint_red", {"C"}, {}}};
    TransferOptions opt;
    opt.follow_source = true;
    opt.keep_states = true;
    auto r = transfer_plan(f, *painting(fx, paint_red_rule(fx.t, false)), plan, opt);
    const Verdict& v = r.verdict;
    EXPECT_EQ(v.trajectory, Trajectory::FollowSource);
    // Both steps leave a stale slice behind; each target state is then Δ_F(X_i).
    ASSERT_EQ(v.divergences.size(), 2u);
    EXPECT_EQ(v.divergences[1].where, "step 2 paint_red(C)");
    ASSERT_TRUE(r.final_state);
    EXPECT_EQ(r.final_state->num_parts(k.bread), 0u);
    EXPECT_TRUE(hom::is_isomorphic(*r.final_state, migrate::migrate(f, r.source_states.back())));
    EXPECT_NE(v.summary().find("2 target step(s) do not reach"), std::string::npos) << v.summary();
}

TEST(Transfer, ARuleThatTestsWhatItChangesDoesNotDiverge) {
    // With Pre testing purple, the migrated step deletes A's slice: Y_i = Δ_F(X_i), and the
    // local check decides it without comparing the whole states.
    Fixture fx;
    Kitchen k = kitchen();
    plan::Plan plan;
    plan.steps = {{"paint_red", {"A"}, {}}, {"paint_red", {"C"}, {}}};
    auto r = transfer_plan(kitchen_map(fx.t, k), *painting(fx, paint_red_rule(fx.t, true)), plan);
    ASSERT_TRUE(r.verdict.valid()) << r.verdict.reason();
    EXPECT_EQ(r.verdict.diverged(), nullptr);
    EXPECT_EQ(r.whole_comparisons, 0u);
    EXPECT_EQ(r.final_state->num_parts(k.bread), 0u);
    EXPECT_EQ(r.verdict.summary(), "valid: every step applies and the goal embeds monically");
}

TEST(Transfer, ADeltaMapNeverDiverges) {
    Fixture fx;
    auto r = transfer_plan(renaming_map(fx.t, true), *fx.problem, fx.plan);
    ASSERT_TRUE(r.verdict.valid()) << r.verdict.reason();
    EXPECT_EQ(r.verdict.diverged(), nullptr);
    EXPECT_EQ(r.whole_comparisons, 0u);
}

TEST(Transfer, ANegativeConditionTheMapCannotSeeBreaksTheClaim) {
    // A delta map that forgets On, and paint_red(b) unless b stands on something: the migrated
    // NAC is Δ_F(N) = Δ_F(L), which rejects every match.
    Fixture fx;
    auto s = std::make_shared<Schema>("Colors");
    ObId thing = s->add_ob("Thing");
    AttrTypeId paint = s->add_attr_type("Paint", ValueKind::String);
    AttrId painted = s->add_attr("painted", thing, paint);
    SchemaMap f(s, fx.t.s);
    f.map_ob(thing, Query::representable(fx.t.s, fx.t.block, "x"));
    f.map_attr_type(paint, fx.t.color_type);
    f.map_attr(painted, Term::path("x", {}, fx.t.color));
    ASSERT_TRUE(f.finish().empty());
    ASSERT_TRUE(f.is_delta());
    auto rule = paint_red_rule(fx.t, false);
    rewrite::ApplicationCondition nac{"NAC 1", true, rule->L, hom::identity(rule->L), {}};
    Part o = nac.n_state.add_part(fx.t.on, "o");
    nac.n_state.set_subpart(fx.t.on_l, o, 0);
    nac.n_state.add_part(fx.t.block, "below");
    nac.n_state.set_subpart(fx.t.on_r, o, 1);
    rule->conditions.push_back(std::move(nac));
    ASSERT_TRUE(rewrite::check_rule(*rule).empty());
    plan::Plan plan;
    plan.steps = {{"paint_red", {"C"}, {}}}; // C stands on nothing
    auto r = transfer_plan(f, *painting(fx, rule), plan);
    EXPECT_TRUE(r.verdict.source_valid());
    EXPECT_FALSE(r.verdict.valid());
    ASSERT_NE(r.verdict.failed_step(), nullptr);
    const Claim& c = r.verdict.claim(Claim::Kind::ValidByConstruction);
    EXPECT_FALSE(c.holds());
    ASSERT_NE(c.failing(), nullptr);
    EXPECT_EQ(c.failing()->why_not, "rule paint_red has a negative application condition");
}

// The Things domain's own actions: lift(b, from) takes b off `from`; put(b, to) puts b on `to`
// when b stands on nothing (a NAC). No Things action is a migrated move, so every step of a
// move plan is repaired.
plan::DomainPtr lift_and_put(const SchemaPtr& s) {
    ObId thing(0), rel(1);
    HomId top(0), below(1);
    auto domain = std::make_shared<plan::Domain>();
    domain->name = "LiftAndPut";
    domain->schema = s;
    for (bool lift : {true, false}) {
        auto rule = std::make_shared<rewrite::Rule>(s);
        rule->name = lift ? "lift" : "put";
        for (ACSet* x : {&rule->L, &rule->K, &rule->R}) {
            x->add_part(thing, "b");
            x->add_part(thing, "o");
        }
        ACSet& with = lift ? rule->L : rule->R;
        Part r = with.add_part(rel, "r");
        with.set_subpart(top, r, 0);
        with.set_subpart(below, r, 1);
        rule->l = hom::identity(rule->K);
        rule->r = hom::identity(rule->K);
        rule->parameters = {{"b", thing, 0}, {lift ? "from" : "to", thing, 1}};
        if (!lift) {
            rewrite::ApplicationCondition nac{"NAC 1", true, rule->L, hom::identity(rule->L), {}};
            Part u = nac.n_state.add_part(thing, "under");
            Part on = nac.n_state.add_part(rel, "on");
            nac.n_state.set_subpart(top, on, 0);
            nac.n_state.set_subpart(below, on, u);
            rule->conditions.push_back(std::move(nac));
        }
        EXPECT_TRUE(rewrite::check_rule(*rule).empty());
        domain->rules.push_back(std::move(rule));
    }
    return domain;
}

TEST(Transfer, ARepairIsFoundOnAFocusOfTheStateOrOnTheWholeStateAlike) {
    // move(b, from, to) becomes lift(b, from), put(b, to): put cannot come first (its NAC).
    Fixture fx;
    auto f = renaming_map(fx.t, false);
    auto own = lift_and_put(f.target());
    auto generated = migrate_domain(f, *fx.problem->domain);
    std::vector<std::vector<std::string>> plans;
    for (bool focus : {true, false}) {
        SCOPED_TRACE(focus ? "on a focus" : "on the whole state");
        TransferOptions o;
        o.target_actions =
            std::make_shared<TargetActions>(correspond_domain(*generated.domain, own, {}));
        if (!focus) {
            o.repair.radii.clear();
        }
        auto t = transfer_plan(f, *fx.problem, fx.plan, o);
        EXPECT_TRUE(t.verdict.valid()) << t.verdict.reason();
        ASSERT_EQ(t.steps.size(), 2u);
        std::vector<std::string> steps;
        // The first repair needs A, B and C (A is on B, and goes on C): a focus of 3 of the 4
        // blocks. The second is a move too: the first's plan, on its own arguments, replays on
        // the whole state, so it is searched on no focus (its own would be all four blocks).
        EXPECT_EQ(t.steps[0].repair_focus, focus ? 3u : 0u);
        EXPECT_FALSE(t.steps[0].repair_reused_from.has_value());
        EXPECT_EQ(t.steps[1].repair_focus, 0u);
        EXPECT_EQ(t.steps[1].repair_reused_from, std::optional<std::size_t>(0));
        EXPECT_EQ(t.steps[1].repair_stats.expanded, 0u);
        for (const auto& st : t.steps) {
            EXPECT_EQ(st.kind, StepTransfer::Kind::Repaired);
            EXPECT_GE(st.target_steps.size(), 2u); // a lift before the put
            for (const auto& step : st.target_steps) {
                steps.push_back(step.to_string());
            }
        }
        // Each repair ends by putting the moved block where the source put it.
        EXPECT_EQ(t.steps[0].target_steps.back().to_string(), "put(A, C)");
        EXPECT_EQ(t.steps[1].target_steps.back().to_string(), "put(B, A)");
        plans.push_back(std::move(steps));
    }
    EXPECT_EQ(plans[0], plans[1]);
}

TEST(Transfer, ReplanFindsAPlanAndMeasuresTheEditDistance) {
    Fixture fx;
    auto r = transfer_plan(renaming_map(fx.t, false), *fx.problem, fx.plan);
    ASSERT_TRUE(r.verdict.valid());
    plan::SearchOptions opt;
    auto rp = replan(r, opt);
    ASSERT_EQ(rp.search.status, plan::SearchStatus::Solved);
    // One move suffices (A onto C); the transferred plan has one step more.
    EXPECT_EQ(rp.steps.size(), 1u);
    EXPECT_EQ(rp.steps[0].to_string(), "move(A, B, C)");
    EXPECT_EQ(rp.edit_distance, 1u);
}

TEST(Transfer, CollapsedArgumentsShowPartsThatDisagree) {
    Stacks t = stacks();
    rewrite::Rule rule(t.s);
    rule.parameters = {
        {"block", t.block, 0}, {"block", t.on, 0}, {"under", t.block, 1}, {"under", t.on, 1}};
    plan::Step agree{"stack", {"B", "B", "D", "D"}, {}};
    EXPECT_EQ(collapse_arguments(rule, agree).to_string(), "stack(B, D)");
    plan::Step mixed{"stack", {"B", "A", "A", "D"}, {}};
    EXPECT_EQ(collapse_arguments(rule, mixed).to_string(), "stack(B|A, A|D)");
}

TEST(Transfer, ASpeedupAgainstACutOffSearchIsALowerBound) {
    Replan r;
    r.ms = 1000;
    r.search.status = plan::SearchStatus::Solved;
    EXPECT_FALSE(hit_limit(r));
    EXPECT_EQ(speedup_text(r, 10), "100x");
    r.search.status = plan::SearchStatus::TimeLimit;
    EXPECT_TRUE(hit_limit(r));
    EXPECT_EQ(speedup_text(r, 10), "> 100x (replanning hit its time limit)");
}

TEST(Transfer, EditDistanceCountsWholeSteps) {
    using S = plan::Step;
    std::vector<S> a = {{"pickup", {"A"}, {}}, {"stack", {"A", "B"}, {}}};
    std::vector<S> b = {{"pickup", {"A"}, {}}, {"stack", {"A", "C"}, {}}, {"noop", {}, {}}};
    EXPECT_EQ(edit_distance(a, b), 2u);
    EXPECT_EQ(edit_distance(a, a), 0u);
    EXPECT_EQ(edit_distance({}, b), 3u);
}

} // namespace
} // namespace catplan::transfer
