// The PDDL people write: action costs, union and repeated types, negative goals, names written
// against variables, and what catplan refuses as unsupported (exit 3) rather than malformed.

#include "catplan/pddl/costs.hpp"
#include "catplan/pddl/detail/test_load.hpp"
#include "catplan/pddl/export.hpp"
#include "catplan/pddl/steps.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"

#include <gtest/gtest.h>

namespace catplan::pddl {
namespace {

using namespace testing;

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// ---- tokens -------------------------------------------------------------------------------------

TEST(PddlTokens, ANameAndAVariableWrittenTogetherAreTwoTokens) {
    auto l = load("shuttle-domain.pddl", "shuttle-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    const Action* board = l->domain->find_action("board");
    ASSERT_NE(board, nullptr);
    // (person?p) (shuttle?s) (city?c) (at ?p?c) (at ?s ?c)
    ASSERT_EQ(board->precondition.size(), 5U);
    EXPECT_EQ(board->precondition[0].to_string(), "(person ?p)");
    EXPECT_EQ(board->precondition[3].to_string(), "(at ?p ?c)");
    auto v = validate_ipc_plan(*l->import, plan_text("(fly sh1 oslo rome)\n(board ann sh1 rome)\n"
                                                     "(fly sh1 rome oslo)\n(debark ann sh1 oslo)"));
    EXPECT_TRUE(v.valid) << v.reason;
}

// ---- action costs -------------------------------------------------------------------------------

TEST(PddlCosts, StepsCostWhatTheProblemsTableSays) {
    auto l = load("lift-domain.pddl", "lift-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    ASSERT_TRUE(l->problem->metric);
    EXPECT_EQ(l->problem->values.size(), 5U);
    auto v = validate_ipc_plan(*l->import, plan_text(read(data("lift-p01.plan"))));
    ASSERT_TRUE(v.valid) << v.reason;
    EXPECT_EQ(v.cost.steps, (std::vector<std::int64_t>{0, 6, 0, 0, 13, 0}));
    EXPECT_EQ(v.cost.total, 19);
    EXPECT_FALSE(v.cost.unit);
    EXPECT_EQ(cost_line(v.cost), "; cost = 19 (general cost)\n");
    // The same steps in another order cost the same; fast-up reads (travel-fast f0 f2).
    auto c = plan_cost(*l->domain, *l->problem, plan_text("(fast-up fast0 f0 f2)"));
    EXPECT_EQ(c.total, 13);
}

TEST(PddlCosts, AValueTheProblemDoesNotGiveLeavesTheStepWithoutACost) {
    auto l = load("lift-domain.pddl", "lift-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    // (travel-slow f1 f2) has no value: the slow lift does not serve f2 anyway, but the fast one
    // going up from f1 reads (travel-fast f1 f2), which is given, and down reads it too.
    auto c = plan_cost(*l->domain, *l->problem, plan_text("(slow-up slow0 f1 f2)"));
    EXPECT_EQ(c.undefined, "step 1 (slow-up slow0 f1 f2): its cost (travel-slow f1 f2) has no "
                           "value in the problem");
    EXPECT_TRUE(has(cost_line(c), "; cost undefined: step 1"));
}

TEST(PddlCosts, WithoutTheMetricEveryStepCostsOne) {
    std::string domain = read(data("lift-domain.pddl"));
    std::string problem = read(data("lift-p01.pddl"));
    problem.replace(problem.find("(:metric minimize (total-cost))"), 31, "");
    auto l = load_text(domain, problem);
    ASSERT_TRUE(l->import) << l->errors();
    auto v = validate_ipc_plan(*l->import, plan_text(read(data("lift-p01.plan"))));
    ASSERT_TRUE(v.valid) << v.reason;
    EXPECT_EQ(v.cost.total, 6);
    EXPECT_TRUE(v.cost.unit);
}

TEST(PddlCosts, ConstantCostsAreGeneralUnlessEveryActionCostsOne) {
    auto l = load("shuttle-domain.pddl", "shuttle-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    EXPECT_FALSE(unit_cost(*l->domain, *l->problem));
    auto c = plan_cost(*l->domain, *l->problem,
                       plan_text("(fly sh1 oslo rome)\n(board ann sh1 rome)\n"));
    EXPECT_EQ(c.total, 4);
    auto ones = load_text(R"((define (domain d) (:requirements :action-costs)
        (:predicates (p)) (:functions (total-cost))
        (:action a :parameters () :precondition () :effect (and (p) (increase (total-cost) 1)))))",
                          R"((define (problem q) (:domain d) (:init (= (total-cost) 0))
        (:goal (p)) (:metric minimize (total-cost))))");
    ASSERT_TRUE(ones->import) << ones->errors();
    EXPECT_TRUE(unit_cost(*ones->domain, *ones->problem));
}

TEST(PddlCosts, RulesCarryTheirActionsCost) {
    auto l = load("lift-domain.pddl", "");
    ASSERT_TRUE(l->import) << l->errors();
    const auto* up = l->import->domain->find_rule("slow-up");
    ASSERT_NE(up, nullptr);
    ASSERT_TRUE(up->cost.has_value());
    std::vector<std::string> names;
    for (const auto& p : up->parameters) {
        names.push_back(p.name);
    }
    EXPECT_EQ(up->cost->to_string(names), "travel-slow(f1, f2)");
    const auto* leave = l->import->domain->find_rule("leave");
    ASSERT_TRUE(leave->cost.has_value());
    EXPECT_EQ(leave->cost->constant, 0);
    EXPECT_TRUE(leave->cost->terms.empty());
    auto plain = load("blocksworld-domain.pddl", "");
    EXPECT_FALSE(plain->import->domain->rules[0]->cost.has_value());
}

/// The cost of the plan A* finds on the import's problem, checked by validating it as an IPC
/// plan; -1 (with the failure recorded) when there is none or it is not valid.
std::int64_t astar_cost(const Import& im) {
    plan::SearchOptions astar;
    astar.search = plan::SearchKind::AStar;
    auto r = plan::find_plan(*im.problem, astar);
    if (!r.plan || !r.costs) {
        ADD_FAILURE() << "A* found no costed plan";
        return -1;
    }
    auto ipc = to_ipc_plan(im, *r.plan);
    if (!ipc) {
        ADD_FAILURE() << ipc.error();
        return -1;
    }
    auto v = validate_ipc_plan(im, *ipc);
    if (!v.valid) {
        ADD_FAILURE() << v.reason;
        return -1;
    }
    return v.cost.total;
}

TEST(PddlCosts, ConstantCostsSurviveExport) {
    auto l = load("shuttle-domain.pddl", "shuttle-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    auto dom = export_domain(*l->import->domain);
    auto prob = export_problem(*l->import->problem);
    ASSERT_TRUE(dom && prob) << (dom ? prob.error() : dom.error());
    EXPECT_TRUE(has(*dom, ":action-costs")) << *dom;
    EXPECT_TRUE(has(*dom, "(increase (total-cost) 3)")) << *dom;
    EXPECT_TRUE(has(*prob, "(:metric minimize (total-cost))")) << *prob;
    auto back = load_text(*dom, *prob);
    ASSERT_TRUE(back->import) << back->errors() << *dom << *prob;
    auto plan = plan_text("(fly sh1 oslo rome)\n(board ann sh1 rome)\n(fly sh1 rome oslo)\n"
                          "(debark ann sh1 oslo)");
    auto before = validate_ipc_plan(*l->import, plan);
    auto after = validate_ipc_plan(*back->import, plan);
    ASSERT_TRUE(before.valid && after.valid) << before.reason << after.reason;
    EXPECT_EQ(before.cost.total, 8);
    EXPECT_EQ(after.cost.total, 8);
}

TEST(PddlCosts, FunctionCostsSurviveExport) {
    auto l = load("lift-domain.pddl", "lift-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    auto dom = export_domain(*l->import->domain);
    auto prob = export_problem(*l->import->problem);
    ASSERT_TRUE(dom && prob) << (dom ? prob.error() : dom.error());
    EXPECT_TRUE(has(*dom, "(travel-slow ?x1 - level ?x2 - level) - number")) << *dom;
    EXPECT_TRUE(has(*dom, "(increase (total-cost) (travel-slow ?f1 ?f2))")) << *dom;
    EXPECT_TRUE(has(*prob, "(= (travel-slow f0 f1) ")) << *prob;
    auto back = load_text(*dom, *prob);
    ASSERT_TRUE(back->import) << back->errors() << *dom << *prob;
    // A* finds a plan of the same least cost on the files read back.
    EXPECT_EQ(astar_cost(*l->import), 19);
    EXPECT_EQ(astar_cost(*back->import), 19);
}

TEST(PddlCosts, ACostThatReadsADomainConstantSurvivesExportWithItsProblem) {
    auto l = load("refuel-domain.pddl", "refuel-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    // depot's type is the problem's: the domain alone cannot declare the constant.
    auto alone = export_domain(*l->import->domain);
    ASSERT_FALSE(alone.has_value());
    EXPECT_TRUE(has(alone.error(), "reads refuel of depot, which no parameter names"))
        << alone.error();
    auto ex = export_pddl(*l->import->domain, l->import->problem.get());
    ASSERT_TRUE(ex.has_value()) << ex.error();
    EXPECT_TRUE(has(ex->domain, "(:constants depot - place)")) << ex->domain;
    EXPECT_TRUE(has(ex->domain, " depot))")) << ex->domain;
    EXPECT_FALSE(has(ex->problem, "depot - place")) << ex->problem;
    auto back = load_text(ex->domain, ex->problem);
    ASSERT_TRUE(back->import) << back->errors() << ex->domain << ex->problem;
    // The same plans cost the same on the files read back; A* finds the cheaper road on both.
    auto plan = plan_text("(drive t1 a b)\n(drive t1 b depot)");
    for (const auto* im : {&*l->import, &*back->import}) {
        auto v = validate_ipc_plan(*im, plan);
        ASSERT_TRUE(v.valid) << v.reason;
        EXPECT_EQ(v.cost.total, 3);
        EXPECT_EQ(astar_cost(*im), 1);
    }
}

TEST(PddlCosts, MalformedCostsAreBadInputAndFractionsUnsupported) {
    auto cost = [](const std::string& amount) {
        return load_text("(define (domain d) (:requirements :action-costs) (:predicates (p))\n"
                         "(:functions (total-cost) - number)\n"
                         "(:action a :parameters () :precondition () :effect (and (p) "
                         "(increase (total-cost) " +
                             amount + "))))",
                         "");
    };
    auto negative = cost("-2");
    EXPECT_FALSE(negative->domain);
    EXPECT_TRUE(has(negative->errors(), "error: an action's cost must not be negative"))
        << negative->errors();
    EXPECT_FALSE(negative->sink.only_unsupported());
    auto half = cost("2.5");
    EXPECT_FALSE(half->domain);
    EXPECT_TRUE(has(half->errors(), "unsupported number '2.5'")) << half->errors();
    EXPECT_TRUE(half->sink.only_unsupported());
    auto unknown = cost("(speed)");
    EXPECT_TRUE(has(unknown->errors(), "unknown function 'speed'")) << unknown->errors();
    auto twice = load_text(read(data("lift-domain.pddl")),
                           "(define (problem q) (:domain lift) (:objects f0 f1 - level)\n"
                           "(:init (= (travel-slow f0 f1) 2) (= (travel-slow f0 f1) 3))\n"
                           "(:goal (and)))");
    EXPECT_TRUE(has(twice->errors(), "problem.pddl:2:34: error: the value of (travel-slow f0 f1) "
                                     "is given twice"))
        << twice->errors();
    auto other = load_text(read(data("lift-domain.pddl")),
                           "(define (problem q) (:domain lift) (:init) (:goal (and))\n"
                           "(:metric maximize (total-cost)))");
    EXPECT_TRUE(has(other->errors(), "unsupported metric")) << other->errors();
    EXPECT_TRUE(other->sink.only_unsupported());
}

TEST(PddlCosts, ThePlannerCountsStepsAndThePlanIsCosted) {
    auto l = load("lift-domain.pddl", "lift-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    auto r = plan::find_plan(*l->import->problem, {});
    ASSERT_EQ(r.status, plan::SearchStatus::Solved);
    auto ipc = to_ipc_plan(*l->import, *r.plan);
    ASSERT_TRUE(ipc.has_value());
    auto v = validate_ipc_plan(*l->import, *ipc);
    ASSERT_TRUE(v.valid) << v.reason;
    auto c = plan_cost(*l->domain, *l->problem, *ipc);
    EXPECT_EQ(c.total, v.cost.total);
    EXPECT_TRUE(has(write_ipc_plan(*ipc, c), "(general cost)"));
}

TEST(PddlCosts, AStarSumsTheCostsAndFindsTheCheapestPlan) {
    auto l = load("roads-domain.pddl", "roads-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    auto costed = [&](const plan::SearchResult& r) {
        auto ipc = to_ipc_plan(*l->import, *r.plan);
        EXPECT_TRUE(ipc.has_value());
        return plan_cost(*l->domain, *l->problem, *ipc);
    };
    plan::SearchOptions astar;
    astar.search = plan::SearchKind::AStar;
    auto r = plan::find_plan(*l->import->problem, astar);
    ASSERT_EQ(r.status, plan::SearchStatus::Solved);
    EXPECT_EQ(r.path, "grounded");
    EXPECT_TRUE(r.costs);
    EXPECT_TRUE(r.optimal);
    EXPECT_TRUE(has(r.config, "summing action costs")) << r.config;
    // a-b-c-d (3 + 4 + 5), not the road a-d (20), nor a-e-d: a-e has no length, so no cost.
    EXPECT_EQ(r.plan->to_string(), "drive(t1, a, b)\ndrive(t1, b, c)\ndrive(t1, c, d)\n");
    EXPECT_EQ(costed(r).total, 12);
    EXPECT_EQ(r.uncosted, 1U);
    for (auto h : {plan::HeuristicKind::HMax, plan::HeuristicKind::Blind}) {
        astar.heuristic = h;
        auto again = plan::find_plan(*l->import->problem, astar);
        ASSERT_TRUE(again.plan);
        EXPECT_EQ(costed(again).total, 12) << again.config;
    }
    // Breadth-first search counts steps: the shortest plan, which is not the cheapest.
    plan::SearchOptions bfs;
    bfs.search = plan::SearchKind::BreadthFirst;
    auto shortest = plan::find_plan(*l->import->problem, bfs);
    ASSERT_TRUE(shortest.plan);
    EXPECT_EQ(costed(shortest).total, 20);
    EXPECT_FALSE(shortest.costs);
    EXPECT_FALSE(shortest.optimal);
    // The greedy default never takes the road without a cost.
    auto lama = plan::find_plan(*l->import->problem, {});
    ASSERT_TRUE(lama.plan);
    EXPECT_TRUE(costed(lama).undefined.empty());
}

TEST(PddlCosts, AnytimeSearchKeepsTheCheapestPlan) {
    auto l = load("roads-domain.pddl", "roads-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    plan::SearchOptions anytime;
    anytime.search = plan::SearchKind::Lama;
    anytime.anytime = true;
    auto first = plan::find_plan(*l->import->problem, {});
    ASSERT_TRUE(first.plan);
    EXPECT_EQ(first.plan->steps.size(), 1U); // lama counts steps: the road a-d, cost 20
    auto r = plan::find_plan(*l->import->problem, anytime);
    ASSERT_TRUE(r.plan);
    EXPECT_TRUE(r.costs);
    EXPECT_FALSE(r.optimal);
    EXPECT_GE(r.stats.plans, 2U);
    EXPECT_TRUE(has(r.config, "anytime")) << r.config;
    EXPECT_EQ(r.plan->to_string(), "drive(t1, a, b)\ndrive(t1, b, c)\ndrive(t1, c, d)\n");
}

TEST(PddlCosts, AStarOnTheLiftTableIsCheapest) {
    auto l = load("lift-domain.pddl", "lift-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    plan::SearchOptions astar;
    astar.search = plan::SearchKind::AStar;
    auto r = plan::find_plan(*l->import->problem, astar);
    ASSERT_TRUE(r.plan);
    EXPECT_TRUE(r.optimal && r.costs);
    auto ipc = to_ipc_plan(*l->import, *r.plan);
    ASSERT_TRUE(ipc.has_value());
    auto v = validate_ipc_plan(*l->import, *ipc);
    ASSERT_TRUE(v.valid) << v.reason;
    // lift-p01.plan costs 19 (slow0 carries ann up for 6, fast0 brings bob down for 13).
    EXPECT_EQ(v.cost.total, 19);
}

// ---- types --------------------------------------------------------------------------------------

TEST(PddlTypes, ATypeListedTwiceHasBothParentsAndAnEitherIsAType) {
    auto l = load("shelving-domain.pddl", "shelving-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    const Domain& d = *l->domain;
    // zone - object and zone - surface: object is implied by surface.
    EXPECT_EQ(d.find_type("zone")->parents, (std::vector<std::string>{"surface"}));
    EXPECT_EQ(d.predicates[1].params[0].type, "(either box rack)");
    EXPECT_TRUE(d.is_subtype("rack", "(either box rack)"));
    EXPECT_TRUE(d.is_subtype("box", "(either box rack)"));
    EXPECT_FALSE(d.is_subtype("aisle", "(either box rack)"));
    EXPECT_TRUE(d.may_share("zone", "(either box rack)")); // a rack is both
    EXPECT_FALSE(d.may_share("aisle", "box"));
    const auto& s = *l->import->domain->schema;
    EXPECT_TRUE(s.find_hom("zone_is_surface").has_value());
    EXPECT_FALSE(s.find_hom("zone_is_object").has_value());
    EXPECT_TRUE(s.find_hom("rack_is_either_box_rack").has_value());
    EXPECT_TRUE(s.find_hom("box_is_either_box_rack").has_value());
    // r1, r2, r3 and b1 are of the union; arm1 and bay1 are not.
    auto x = *l->import->problem->initial;
    EXPECT_EQ(x.num_parts(l->import->type_ob.at("(either box rack)")), 4U);
    auto v = validate_ipc_plan(*l->import, plan_text(read(data("shelving-p01.plan"))));
    EXPECT_TRUE(v.valid) << v.reason;
}

TEST(PddlTypes, AnArgumentOutsideTheUnionIsATypeMismatch) {
    std::string domain = read(data("shelving-domain.pddl"));
    domain.replace(domain.find("(in ?r ?p))"), 11, "(in ?a ?p))");
    auto l = load_text(domain, "");
    EXPECT_FALSE(l->domain);
    EXPECT_TRUE(has(l->errors(), "type mismatch: argument 1 of 'in' must be a (either box rack), "
                                 "and '?a' is a arm"))
        << l->errors();
}

TEST(PddlTypes, ObjectsOfAUnionTypeFitItsParametersOnly) {
    auto l = load_text(R"((define (domain u) (:requirements :typing) (:types a b c)
        (:predicates (p ?x - (either a b)) (q ?x - a))
        (:action mark :parameters (?x - (either b a)) :precondition () :effect (p ?x))
        (:action only-a :parameters (?x - a) :precondition () :effect (q ?x))))",
                       R"((define (problem v) (:domain u)
        (:objects x - a y - (either a b) z - c) (:init) (:goal (and (p x) (p y)))))");
    ASSERT_TRUE(l->import) << l->errors();
    // (either b a) is (either a b): one type.
    EXPECT_EQ(l->domain->types.size(), 5U);
    auto v = validate_ipc_plan(*l->import, plan_text("(mark x)\n(mark y)"));
    EXPECT_TRUE(v.valid) << v.reason;
    DiagnosticSink sink(l->sources);
    EXPECT_FALSE(check_ipc_plan(*l->import, plan_text("(only-a y)\n(mark z)"), sink));
    EXPECT_TRUE(has(sink.render(), "argument 1 (?x) must be a a, and 'y' is a (either a b)"))
        << sink.render();
    EXPECT_TRUE(has(sink.render(), "must be a (either a b), and 'z' is a c")) << sink.render();
    // A union the domain does not use cannot type a problem's object.
    auto other = load_text(R"((define (domain u) (:requirements :typing) (:types a b c)
        (:predicates (p ?x - a))))",
                           "(define (problem v) (:domain u) (:objects y - (either b c)) (:init) "
                           "(:goal (and)))");
    EXPECT_TRUE(has(other->errors(), "an object of type (either b c), a union of types the "
                                     "domain does not use"))
        << other->errors();
}

// ---- negative goals -----------------------------------------------------------------------------

TEST(PddlGoals, ANegativeGoalIsAConditionTheFinalStateMustNotMeet) {
    auto l = load("stacker-domain.pddl", "stacker-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    const auto& p = *l->import->problem;
    ASSERT_EQ(p.goal_conditions.size(), 1U);
    EXPECT_EQ(p.goal_conditions[0].name, "(not (holding))");
    auto good = validate_ipc_plan(*l->import, plan_text(read(data("stacker-p01.plan"))));
    EXPECT_TRUE(good.valid) << good.reason;
    auto bad = validate_ipc_plan(*l->import, plan_text(read(data("stacker-p01-invalid.plan"))));
    EXPECT_FALSE(bad.valid);
    EXPECT_EQ(bad.reason, "goal not reached: (not (holding)) does not hold");
    // The rule-level validation agrees: the goal embeds, but the condition holds.
    auto rules = plan::validate_plan(p, bad.plan);
    EXPECT_FALSE(rules.goal_reached);
    EXPECT_TRUE(has(rules.reason, "the negative condition '(not (holding))' holds"))
        << rules.reason;
}

TEST(PddlGoals, EverySearchMeetsANegativeGoal) {
    auto l = load("stacker-domain.pddl", "stacker-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    for (auto kind : {plan::SearchKind::BreadthFirst, plan::SearchKind::AStar,
                      plan::SearchKind::GreedyBestFirst, plan::SearchKind::Lama}) {
        for (bool ground : {true, false}) {
            SCOPED_TRACE(::testing::Message() << static_cast<int>(kind) << " ground " << ground);
            plan::SearchOptions opt;
            opt.search = kind;
            opt.ground = ground;
            auto r = plan::find_plan(*l->import->problem, opt);
            ASSERT_EQ(r.status, plan::SearchStatus::Solved);
            EXPECT_EQ(r.path, ground ? "grounded" : "C-set");
            auto ipc = to_ipc_plan(*l->import, *r.plan);
            ASSERT_TRUE(ipc.has_value());
            auto v = validate_ipc_plan(*l->import, *ipc);
            EXPECT_TRUE(v.valid) << v.reason << "\n" << write_ipc_plan(*ipc);
            // Walking to s2 with the block is shorter, and not a plan.
            EXPECT_EQ(ipc->size(), 2U);
            EXPECT_EQ((*ipc)[0].action, "give-back");
        }
    }
}

TEST(PddlGoals, AGoalThatAsksForAFactAndItsAbsenceHasNoPlan) {
    std::string problem = read(data("stacker-p01.pddl"));
    problem.replace(problem.find("(not (holding))"), 15, "(holding) (not (holding))");
    auto l = load_text(read(data("stacker-domain.pddl")), problem);
    ASSERT_TRUE(l->import) << l->errors();
    for (bool ground : {true, false}) {
        plan::SearchOptions opt;
        opt.ground = ground;
        auto r = plan::find_plan(*l->import->problem, opt);
        EXPECT_EQ(r.status, plan::SearchStatus::Unsolvable) << ground;
    }
}

TEST(PddlGoals, ProblemsWrittenFromStatesKeepTheirNegativeGoals) {
    auto l = load("stacker-domain.pddl", "stacker-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    const auto& p = *l->import->problem;
    auto written = problem_of(*l->import, "again", *p.initial, *p.goal, p.goal_conditions);
    EXPECT_EQ(written.unwritten_goal_conditions, 0U);
    std::string text = write_problem(written);
    EXPECT_TRUE(has(text, "(not (holding))")) << text;
    auto back = load_text(read(data("stacker-domain.pddl")), text);
    ASSERT_TRUE(back->import) << back->errors() << text;
    EXPECT_FALSE(validate_ipc_plan(*back->import, plan_text("(move s1 s2 t0)")).valid);
    // The export does not write goal conditions yet, and says so.
    auto exported = export_problem(p);
    ASSERT_FALSE(exported.has_value());
    EXPECT_TRUE(has(exported.error(), "(not (holding))")) << exported.error();
}

// ---- what catplan does not read -----------------------------------------------------------------

TEST(PddlUnsupported, EveryRequirementAndConstructIsNamedAndLocated) {
    auto l = load("unsupported-domain.pddl", "");
    EXPECT_FALSE(l->domain);
    std::string e = l->errors();
    for (const char* expected :
         {"4:26: warning: requirement ':conditional-effects' is read only as far as catplan goes",
          "4:47: warning: requirement ':derived-predicates'",
          "5:18: warning: requirement ':durative-actions'",
          "10:4: error: unsupported domain section ':derived' (:derived-predicates)",
          "13:36: error: unsupported construct 'or'", "13:67: error: unsupported construct '>='",
          "14:47: error: unsupported construct 'decrease'",
          "15:19: error: unsupported construct 'forall'",
          "16:4: error: unsupported domain section ':durative-action'"}) {
        EXPECT_TRUE(has(e, expected)) << expected << "\n" << e;
    }
    EXPECT_TRUE(l->sink.only_unsupported()) << e;
}

TEST(PddlUnsupported, ARequirementWhoseConstructsAreNotUsedIsNamedAndRead) {
    // :adl allows much catplan does not read; this domain uses only what it does.
    auto l = load_text("(define (domain d) (:requirements :adl :typing) (:types room)\n"
                       "(:predicates (lit ?r - room) (near ?a ?b - room))\n"
                       "(:action light :parameters (?a ?b - room)\n"
                       "  :precondition (and (near ?a ?b) (not (lit ?b)) (not (= ?a ?b)))\n"
                       "  :effect (lit ?b)))",
                       "(define (problem p) (:domain d) (:objects k h - room)\n"
                       "(:init (near k h)) (:goal (lit h)))");
    ASSERT_TRUE(l->import) << l->errors();
    EXPECT_FALSE(l->sink.has_errors()) << l->errors();
    EXPECT_TRUE(has(l->errors(), "1:35: warning: requirement ':adl'")) << l->errors();
    EXPECT_TRUE(validate_ipc_plan(*l->import, plan_text("(light k h)")).valid);
    EXPECT_FALSE(validate_ipc_plan(*l->import, plan_text("(light h k)")).valid);
}

TEST(PddlUnsupported, MalformedInputIsNotUnsupported) {
    auto typo = load_text("(define (domain d) (:requirements :typin) (:predicates (p)))", "");
    EXPECT_TRUE(has(typo->errors(), "error: unknown requirement ':typin'")) << typo->errors();
    EXPECT_FALSE(typo->sink.only_unsupported());
    auto section = load_text("(define (domain d) (:predicate (p)))", "");
    EXPECT_TRUE(has(section->errors(), "unknown domain section ':predicate'")) << section->errors();
    EXPECT_FALSE(section->sink.only_unsupported());
    // A construct catplan does not read beside a malformed one: bad input (exit 2).
    auto both = load_text("(define (domain d) (:requirements :adl) (:predicates (p))\n"
                          "(:action a :parameters () :precondition (or (p) (p)) :effect (q)))",
                          "");
    EXPECT_TRUE(has(both->errors(), "unsupported construct 'or'")) << both->errors();
    EXPECT_TRUE(has(both->errors(), "unknown predicate 'q'")) << both->errors();
    EXPECT_FALSE(both->sink.only_unsupported());
}

TEST(PddlUnsupported, TimedLiteralsAndConstraintsInProblems) {
    auto l = load_text(read(data("stacker-domain.pddl")),
                       "(define (problem q) (:domain stacker) (:objects s0 - spot)\n"
                       "(:init (at 10 (holding)) (robot-at s0)) (:goal (robot-at s0))\n"
                       "(:constraints (always (robot-at s0))))");
    EXPECT_TRUE(has(l->errors(), "2:9: error: unsupported timed initial literal")) << l->errors();
    EXPECT_TRUE(has(l->errors(), "3:2: error: unsupported problem section ':constraints'"))
        << l->errors();
    EXPECT_TRUE(l->sink.only_unsupported());
}

} // namespace
} // namespace catplan::pddl
