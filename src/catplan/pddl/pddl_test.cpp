#include "catplan/pddl/analysis.hpp"
#include "catplan/pddl/detail/test_load.hpp"
#include "catplan/pddl/export.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/search.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

namespace catplan::pddl {
namespace {

using testing::data;
using testing::load;
using testing::load_text;
using testing::plan_text;
using testing::read;

std::string domain_error(const std::string& file) {
    auto l = load(file, "");
    EXPECT_FALSE(l->domain.has_value());
    return l->errors();
}

TEST(PddlParse, ReadsTheThreeDomains) {
    for (auto [d, p] : {std::pair{"blocksworld-domain.pddl", "blocksworld-p01.pddl"},
                        {"gripper-domain.pddl", "gripper-p01.pddl"},
                        {"logistics-domain.pddl", "logistics-p01.pddl"}}) {
        auto l = load(d, p);
        ASSERT_TRUE(l->import.has_value()) << d << "\n" << l->errors();
        for (const auto& r : l->import->domain->rules) {
            EXPECT_TRUE(rewrite::check_rule(*r).empty()) << r->name;
        }
    }
}

TEST(PddlParse, LogisticsTypesFormATree) {
    auto l = load("logistics-domain.pddl", "");
    ASSERT_TRUE(l->domain);
    EXPECT_TRUE(l->domain->is_subtype("truck", "physobj"));
    EXPECT_TRUE(l->domain->is_subtype("airport", "place"));
    EXPECT_FALSE(l->domain->is_subtype("place", "airport"));
    const auto& s = *l->import->domain->schema;
    EXPECT_TRUE(s.find_hom("truck_is_vehicle").has_value());
    EXPECT_TRUE(s.find_hom("at_2").has_value());
}

TEST(PddlErrors, NameTheConstruct) {
    EXPECT_NE(domain_error("bad-parens.pddl")
                  .find("domain.pddl:1:1: error: unbalanced "
                        "parentheses"),
              std::string::npos)
        << domain_error("bad-parens.pddl");
    EXPECT_NE(domain_error("bad-predicate.pddl").find("4:46: error: unknown predicate 'q'"),
              std::string::npos)
        << domain_error("bad-predicate.pddl");
    EXPECT_NE(domain_error("bad-arity.pddl").find("wrong arity: 'p' takes 1 argument, not 2"),
              std::string::npos);
    EXPECT_NE(domain_error("bad-type.pddl").find("unknown type 'table'"), std::string::npos);
    // A requirement is named in a warning; what it allows is refused where it is used.
    std::string req = domain_error("bad-requirement.pddl");
    EXPECT_NE(req.find("2:26: warning: requirement ':conditional-effects'"), std::string::npos)
        << req;
    EXPECT_NE(req.find("4:61: error: unsupported construct 'when'"), std::string::npos) << req;
}

TEST(PddlPlans, HandWrittenPlansValidate) {
    for (auto [d, p, plan] :
         {std::tuple{"blocksworld-domain.pddl", "blocksworld-p01.pddl", "blocksworld-p01.plan"},
          {"gripper-domain.pddl", "gripper-p01.pddl", "gripper-p01.plan"},
          {"logistics-domain.pddl", "logistics-p01.pddl", "logistics-p01.plan"}}) {
        auto l = load(d, p);
        ASSERT_TRUE(l->import) << l->errors();
        auto v = validate_ipc_plan(*l->import, plan_text(read(data(plan))));
        EXPECT_TRUE(v.valid) << plan << ": " << v.reason;
    }
}

TEST(PddlPlans, InvalidPlanFailsAtTheRightStepNamingThePrecondition) {
    auto l = load("blocksworld-domain.pddl", "blocksworld-p01.pddl");
    auto v = validate_ipc_plan(*l->import, plan_text(read(data("blocksworld-p01-invalid.plan"))));
    EXPECT_FALSE(v.valid);
    ASSERT_EQ(v.failed_step, 2u);
    EXPECT_EQ(v.reason, "step 3 (unstack c d): precondition (on c d) does not hold");
}

TEST(PddlPlans, GoalNotReachedNamesTheGoal) {
    auto l = load("blocksworld-domain.pddl", "blocksworld-p01.pddl");
    auto v = validate_ipc_plan(*l->import, plan_text("(unstack e d)\n(put-down e)\n"));
    EXPECT_FALSE(v.valid);
    EXPECT_TRUE(v.goal_reached == false && !v.failed_step);
    EXPECT_EQ(v.reason, "goal not reached: (on d e) does not hold");
}

TEST(PddlPlans, IpcPlanRoundTrip) {
    auto p = plan_text("0.000: (Unstack E D) [1]\n; comment\n(put-down e)\n");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].to_string(), "(unstack e d)");
    EXPECT_EQ(write_ipc_plan(p), "(unstack e d)\n(put-down e)\n; cost = 2 (unit cost)\n");
}

std::size_t facts(const Import& im, const acset::ACSet& x, const std::string& predicate) {
    return x.num_parts(im.predicate_ob.at(predicate));
}

TEST(PddlAnalysis, BlocksworldsInvariantLeavesOneRulePerAction) {
    auto l = load("blocksworld-domain.pddl", "blocksworld-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    // Found only by growing a candidate that two adds of one instance would break: unstack(x, x)
    // adds (holding x) and (clear x), but needs (on x x) and (clear x), which the invariant
    // forbids together.
    std::vector<std::string> found;
    for (const auto& inv : find_invariants(*l->domain)) {
        found.push_back(inv.to_string());
    }
    EXPECT_NE(
        std::find(found.begin(), found.end(), "at most one of (clear ?1), (holding ?1), (on * ?1)"),
        found.end())
        << ::testing::PrintToString(found);
    // So stack(x, x) and unstack(x, x) can never apply, and each action is one rule.
    for (const auto& a : l->import->actions) {
        EXPECT_EQ(a.variants.size(), 1u) << a.action;
    }
    // A step that identifies two parameters where that may apply keeps its rule: gripper's
    // (move rooma rooma) is a step that changes nothing.
    auto g = load("gripper-domain.pddl", "gripper-p01.pddl");
    ASSERT_TRUE(g->import) << g->errors();
    EXPECT_EQ(g->import->find_action("move")->variants.size(), 2u);
}

TEST(PddlAnalysis, AnInvariantHoldsWhereEachInstanceHasAtMostOneFact) {
    auto l = load("blocksworld-domain.pddl", "blocksworld-p01.pddl");
    ASSERT_TRUE(l->domain) << l->errors();
    auto invariants = find_invariants(*l->domain);
    auto it = std::find_if(invariants.begin(), invariants.end(), [](const Invariant& inv) {
        return inv.to_string() == "at most one of (clear ?1), (holding ?1), (on * ?1)";
    });
    ASSERT_NE(it, invariants.end());
    auto atom = [](std::string predicate, std::vector<std::string> args) {
        Atom a;
        a.predicate = std::move(predicate);
        for (auto& name : args) {
            a.args.push_back({std::move(name), false, {}});
        }
        return a;
    };
    // b is clear and holds nothing; the same fact twice is one fact.
    EXPECT_TRUE(holds_in(*it, {atom("clear", {"b"}), atom("on", {"a", "c"}), atom("clear", {"b"}),
                               atom("on", {"c", "ab"})}));
    // Two facts of one instance: b is clear and a is on it.
    EXPECT_FALSE(
        holds_in(*it, {atom("clear", {"b"}), atom("on", {"c", "d"}), atom("on", {"a", "b"})}));
    // An instance is its argument: a and ab are two.
    EXPECT_TRUE(holds_in(*it, {atom("clear", {"ab"}), atom("holding", {"a"})}));
    EXPECT_FALSE(holds_in(*it, {atom("clear", {"a"}), atom("holding", {"a"})}));
}

TEST(PddlParse, AnObjectIndexFindsConstantsFirstAndFollowsAGrowingProblem) {
    auto l = load("blocksworld-domain.pddl", "blocksworld-p01.pddl");
    ASSERT_TRUE(l->problem) << l->errors();
    Domain d = *l->domain;
    Problem p = *l->problem;
    ObjectIndex objects(d, p);
    ASSERT_FALSE(p.objects.empty());
    const std::string first = p.objects.front().name;
    ASSERT_NE(objects.find(first), nullptr);
    EXPECT_EQ(objects.find(first)->name, first);
    EXPECT_EQ(objects.find("no-such-object"), nullptr);
    // Objects added (the list moves) are found; a constant of a name comes before an object.
    for (int i = 0; i < 100; ++i) {
        p.objects.push_back({"extra" + std::to_string(i), "object", {}});
    }
    ASSERT_NE(objects.find("extra99"), nullptr);
    EXPECT_EQ(objects.find("extra99")->type, "object");
    d.constants.push_back({first, "table", {}});
    ASSERT_NE(objects.find(first), nullptr);
    EXPECT_EQ(objects.find(first)->type, "table");
}

TEST(PddlSemantics, AddingATrueFactKeepsOneFact) {
    auto l = load("dup-domain.pddl", "dup-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    auto v = validate_ipc_plan(*l->import, plan_text("(set-mark a)\n(set-mark a)\n(set-mark b)"));
    ASSERT_FALSE(v.failed_step) << v.reason;
    EXPECT_EQ(facts(*l->import, *v.final_state, "mark"), 2u);
    // One clear-mark makes (mark a) false: no second copy survives.
    v = validate_ipc_plan(*l->import, plan_text("(set-mark a)\n(clear-mark a)\n(clear-mark a)"));
    EXPECT_EQ(v.failed_step, 2u);
    EXPECT_EQ(v.reason, "step 3 (clear-mark a): precondition (mark a) does not hold");
}

TEST(PddlSemantics, ParametersMayBindTheSameObjectUnlessForbidden) {
    auto l = load("dup-domain.pddl", "dup-p01.pddl");
    auto v = validate_ipc_plan(*l->import, plan_text("(connect a a)\n(connect-other a b)"));
    EXPECT_TRUE(v.valid) << v.reason;
    v = validate_ipc_plan(*l->import, plan_text("(connect-other a a)"));
    EXPECT_EQ(v.reason, "step 1 (connect-other a a): precondition (not (= a a)) does not hold");
    // A negative precondition: (link a a) is now true.
    v = validate_ipc_plan(*l->import, plan_text("(connect a a)\n(connect a a)"));
    EXPECT_EQ(v.reason, "step 2 (connect a a): precondition (not (link a a)) does not hold");
}

TEST(PddlSemantics, SimulationGivesValidationsVerdictWithoutTheRules) {
    struct Case {
        const char *domain, *problem, *plan;
    };

    for (auto c : {Case{"blocksworld-domain.pddl", "blocksworld-p01.pddl",
                        "(unstack e d)\n(put-down e)\n(unstack c d)\n"},
                   {"blocksworld-domain.pddl", "blocksworld-p01.pddl", "(unstack e d)\n"},
                   {"dup-domain.pddl", "dup-p01.pddl", "(connect-other a a)"},
                   {"dup-domain.pddl", "dup-p01.pddl", "(connect a a)\n(connect a a)"},
                   {"dup-domain.pddl", "dup-p01.pddl", "(connect a a)\n(connect-other a b)"}}) {
        auto l = load(c.domain, c.problem);
        ASSERT_TRUE(l->import) << l->errors();
        auto plan = plan_text(c.plan);
        auto v = validate_ipc_plan(*l->import, plan);
        auto s = simulate_ipc_plan(*l->domain, *l->problem, plan);
        EXPECT_EQ(s.valid, v.valid) << c.plan;
        EXPECT_EQ(s.failed_step, v.failed_step) << c.plan;
        EXPECT_EQ(s.reason, v.reason) << c.plan;
        EXPECT_EQ(s.cost.total, v.cost.total) << c.plan;
        EXPECT_TRUE(v.final_state.has_value());
        EXPECT_FALSE(s.final_state.has_value());
        EXPECT_TRUE(s.plan.steps.empty());
    }
    auto l = load("blocksworld-domain.pddl", "blocksworld-p01.pddl");
    auto s = simulate_ipc_plan(*l->domain, *l->problem,
                               plan_text(read(data("blocksworld-p01-invalid.plan"))));
    EXPECT_EQ(s.reason, "step 3 (unstack c d): precondition (on c d) does not hold");
    s = simulate_ipc_plan(*l->domain, *l->problem, plan_text("(fly e d)"));
    EXPECT_EQ(s.failed_step, 0u);
    EXPECT_NE(s.reason.find("unknown action 'fly'"), std::string::npos) << s.reason;
}

TEST(PddlSemantics, AnAtomAStepDeletesAndAddsHoldsAfterIt) {
    auto l = load_text("(define (domain touch) (:predicates (on) (seen))\n"
                       "  (:action touch :parameters () :precondition (on)\n"
                       "    :effect (and (not (on)) (on) (seen))))",
                       "(define (problem t1) (:domain touch) (:init (on))\n"
                       "  (:goal (and (on) (seen))))");
    ASSERT_TRUE(l->domain && l->problem) << l->errors();
    auto s = simulate_ipc_plan(*l->domain, *l->problem, plan_text("(touch)\n(touch)"));
    EXPECT_TRUE(s.valid) << s.reason;
    EXPECT_EQ(s.cost.total, 2);
}

TEST(PddlSemantics, PlannerPlansAreValidIpcPlans) {
    for (auto [d, p] : {std::pair{"blocksworld-domain.pddl", "blocksworld-p01.pddl"},
                        {"gripper-domain.pddl", "gripper-p01.pddl"},
                        {"dup-domain.pddl", "dup-p01.pddl"}}) {
        auto l = load(d, p);
        ASSERT_TRUE(l->import);
        plan::SearchOptions opt;
        opt.search = plan::SearchKind::GreedyBestFirst;
        opt.heuristic = plan::HeuristicKind::HFF;
        auto r = plan::find_plan(*l->import->problem, opt);
        ASSERT_EQ(r.status, plan::SearchStatus::Solved) << d;
        auto ipc = to_ipc_plan(*l->import, *r.plan);
        ASSERT_TRUE(ipc.has_value()) << ipc.error();
        auto v = validate_ipc_plan(*l->import, *ipc);
        EXPECT_TRUE(v.valid) << d << ": " << v.reason << "\n" << write_ipc_plan(*ipc);
    }
}

// ---- PDDL -> catplan -> PDDL keeps the valid plans ---------------------------------------------

/// Every type-correct ground action of the problem.
std::vector<IpcStep> ground_actions(const Domain& d, const Problem& p) {
    std::vector<TypedName> objects = d.constants;
    objects.insert(objects.end(), p.objects.begin(), p.objects.end());
    std::vector<IpcStep> out;
    for (const auto& a : d.actions) {
        std::function<void(IpcStep&)> fill = [&](IpcStep& s) {
            if (s.args.size() == a.params.size()) {
                out.push_back(s);
                return;
            }
            for (const auto& o : objects) {
                if (d.is_subtype(o.type, a.params[s.args.size()].type)) {
                    s.args.push_back(o.name);
                    fill(s);
                    s.args.pop_back();
                }
            }
        };
        IpcStep s{a.name, {}, {}};
        fill(s);
    }
    return out;
}

/// The plans of length <= depth whose every step applies, each with whether it reaches the goal.
std::map<std::string, bool> applicable_plans(const Import& im, std::size_t depth) {
    std::map<std::string, bool> out;
    auto actions = ground_actions(im.pddl_domain, *im.pddl_problem);
    std::function<void(IpcPlan&)> grow = [&](IpcPlan& plan) {
        auto v = validate_ipc_plan(im, plan);
        if (v.failed_step) {
            return;
        }
        out[write_ipc_plan(plan)] = v.valid;
        if (plan.size() == depth) {
            return;
        }
        for (const auto& a : actions) {
            plan.push_back(a);
            grow(plan);
            plan.pop_back();
        }
    };
    IpcPlan empty;
    grow(empty);
    return out;
}

void expect_round_trip_keeps_plans(const std::string& d, const std::string& p, std::size_t depth) {
    auto l = load(d, p);
    ASSERT_TRUE(l->import) << l->errors();
    auto dom = export_domain(*l->import->domain);
    ASSERT_TRUE(dom.has_value()) << dom.error();
    auto prob = export_problem(*l->import->problem);
    ASSERT_TRUE(prob.has_value()) << prob.error();
    auto back = load_text(*dom, *prob);
    ASSERT_TRUE(back->import) << back->errors() << *dom << *prob;
    EXPECT_EQ(back->import->domain->rules.size(), l->import->domain->rules.size()) << *dom;
    auto before = applicable_plans(*l->import, depth);
    auto after = applicable_plans(*back->import, depth);
    EXPECT_GT(before.size(), depth);
    EXPECT_EQ(before, after) << *dom;
}

TEST(PddlRoundTrip, BlocksworldKeepsItsPlans) {
    expect_round_trip_keeps_plans("blocksworld-domain.pddl", "blocksworld-p01.pddl", 3);
}

TEST(PddlRoundTrip, GripperKeepsItsPlans) {
    expect_round_trip_keeps_plans("gripper-domain.pddl", "gripper-p01.pddl", 3);
}

TEST(PddlRoundTrip, LogisticsKeepsItsPlans) {
    expect_round_trip_keeps_plans("logistics-domain.pddl", "logistics-p01.pddl", 2);
}

TEST(PddlRoundTrip, EqualityAndNegationKeepTheirPlans) {
    expect_round_trip_keeps_plans("dup-domain.pddl", "dup-p01.pddl", 3);
}

// The imported rules against PDDL's meaning, on seeded random walks: wherever PDDL lets a step
// apply, a rule variant applies (validate_ipc_plan fails the step otherwise), and after every step
// the facts of the rules' state are the atoms PDDL says hold.
void expect_rules_follow_pddl(const std::string& d, const std::string& p, std::uint64_t seed) {
    auto l = load(d, p);
    ASSERT_TRUE(l->import) << l->errors();
    auto actions = ground_actions(*l->domain, *l->problem);
    std::mt19937_64 rng(seed);
    for (int walk = 0; walk < 8; ++walk) {
        IpcPlan plan;
        for (int length = 0; length < 6; ++length) {
            std::vector<const IpcStep*> applicable;
            for (const auto& a : actions) {
                plan.push_back(a);
                if (!simulate_ipc_plan(*l->domain, *l->problem, plan).failed_step) {
                    applicable.push_back(&a);
                }
                plan.pop_back();
            }
            if (applicable.empty()) {
                break;
            }
            plan.push_back(*applicable[rng() % applicable.size()]);
            auto v = validate_ipc_plan(*l->import, plan);
            ASSERT_FALSE(v.failed_step) << d << ": " << v.reason << "\n" << write_ipc_plan(plan);
            std::vector<std::string> rule_facts;
            for (const auto& atom : l->import->facts(*v.final_state)) {
                rule_facts.push_back(atom.to_string());
            }
            std::sort(rule_facts.begin(), rule_facts.end());
            ASSERT_EQ(rule_facts, v.final_facts) << d << "\n" << write_ipc_plan(plan);
        }
    }
}

TEST(PddlSemantics, ImportedRulesFollowPddlOnRandomWalks) {
    for (auto [d, p] : {std::pair{"blocksworld-domain.pddl", "blocksworld-p01.pddl"},
                        {"gripper-domain.pddl", "gripper-p01.pddl"},
                        {"logistics-domain.pddl", "logistics-p01.pddl"},
                        {"dup-domain.pddl", "dup-p01.pddl"},
                        {"lift-domain.pddl", "lift-p01.pddl"},
                        {"shuttle-domain.pddl", "shuttle-p01.pddl"},
                        {"stacker-domain.pddl", "stacker-p01.pddl"},
                        {"shelving-domain.pddl", "shelving-p01.pddl"}}) {
        expect_rules_follow_pddl(d, p, 20261204);
    }
}

TEST(PddlSemantics, ConstantsArePinnedAndMayBeParameters) {
    auto l = load_text(R"((define (domain home)
      (:requirements :strips :typing)
      (:types room)
      (:constants home - room)
      (:predicates (at ?r - room) (rested))
      (:action go
        :parameters (?from ?to - room)
        :precondition (at ?from)
        :effect (and (not (at ?from)) (at ?to)))
      (:action rest
        :parameters ()
        :precondition (at home)
        :effect (rested))))",
                       R"((define (problem p) (:domain home) (:objects hall - room)
      (:init (at hall)) (:goal (and (rested) (at home)))))");
    ASSERT_TRUE(l->import) << l->errors();
    auto v = validate_ipc_plan(*l->import, plan_text("(rest)"));
    EXPECT_EQ(v.reason, "step 1 (rest): precondition (at home) does not hold");
    v = validate_ipc_plan(*l->import, plan_text("(go hall home)\n(rest)\n(go home home)"));
    EXPECT_TRUE(v.valid) << v.reason;
    auto dom = export_domain(*l->import->domain);
    auto prob = export_problem(*l->import->problem);
    ASSERT_TRUE(dom && prob);
    auto back = load_text(*dom, *prob);
    ASSERT_TRUE(back->import) << back->errors() << *dom;
    EXPECT_EQ(applicable_plans(*l->import, 3), applicable_plans(*back->import, 3)) << *dom;
}

// ---- hostile input ------------------------------------------------------------------------------

TEST(PddlErrors, DeepNestingIsALocatedErrorNotACrash) {
    // 30,000 levels overflowed the stack before the limit.
    std::string deep;
    for (int i = 0; i < 30000; ++i) {
        deep += "(and ";
    }
    deep += "(p)" + std::string(30000, ')');
    auto l = load_text("(define (domain d) (:predicates (p))\n(:action a :parameters () "
                       ":precondition " +
                           deep + " :effect (p)))",
                       "");
    EXPECT_FALSE(l->domain);
    EXPECT_NE(l->errors().find("domain.pddl:2:1311: error: nested deeper than 256 levels"),
              std::string::npos)
        << l->errors().substr(0, 300);
    // Within the limit the same formula reads.
    std::string ok;
    for (int i = 0; i < 250; ++i) {
        ok += "(and ";
    }
    ok += "(p)" + std::string(250, ')');
    auto fine = load_text("(define (domain d) (:predicates (p)) (:action a :parameters () "
                          ":precondition " +
                              ok + " :effect (p)))",
                          "");
    EXPECT_TRUE(fine->domain) << fine->errors().substr(0, 300);
}

// Found by fuzzing: a second ':parameters' replaced the first, so the precondition named
// variables the action no longer had.
TEST(PddlErrors, AnActionFieldGivenTwiceIsAnError) {
    auto l = load_text(R"((define (domain d) (:predicates (p ?x))
  (:action a :parameters (?x) :precondition (p ?x) :effect (not (p ?x)) :parameters (?y)
    :effect (p ?y))))",
                       "");
    EXPECT_FALSE(l->domain);
    auto text = l->errors();
    EXPECT_NE(text.find("domain.pddl:2:73: error: ':parameters' is given twice in the action 'a'"),
              std::string::npos)
        << text;
}

TEST(PddlErrors, DuplicateParametersObjectsAndConstantsAreLocated) {
    auto l = load_text(R"((define (domain d) (:types t)
  (:constants k k - t)
  (:predicates (p ?x ?x - t))
  (:action a :parameters (?x ?y ?x - t) :precondition (p ?x ?y) :effect (p ?y ?x))))",
                       "");
    EXPECT_FALSE(l->domain);
    auto text = l->errors();
    EXPECT_NE(text.find("domain.pddl:2:17: error: the constant 'k' is declared twice"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("domain.pddl:3:22: error: the parameter '?x' is declared twice"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("domain.pddl:4:33: error: the parameter '?x' is declared twice"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("domain.pddl:4:27: note: first declared here"), std::string::npos);
    auto p = load_text(R"((define (domain d) (:types t) (:constants k - t) (:predicates (p ?x - t))
  (:action a :parameters (?x - t) :precondition (p ?x) :effect (not (p ?x)))))",
                       R"((define (problem q) (:domain d)
  (:objects a b a - t k - t) (:init) (:goal (and))))");
    text = p->errors();
    EXPECT_FALSE(p->problem);
    EXPECT_NE(text.find("problem.pddl:2:17: error: the object 'a' is declared twice"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("problem.pddl:2:23: error: the object 'k' is declared twice"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("domain.pddl:1:43: note: first declared here"), std::string::npos) << text;
}

// Found by the fuzzer: a second (:types ...) section redeclared the first one's types.
TEST(PddlParse, SeveralTypesSectionsMakeOneTree) {
    auto l = load_text(R"((define (domain d) (:types a) (:types b - a c)
  (:predicates (p ?x - b))))",
                       "");
    ASSERT_TRUE(l->import) << l->errors();
    const auto& s = *l->import->domain->schema;
    EXPECT_TRUE(s.find("a") && s.find("b") && s.find("c") && s.find("b_is_a"));
    // A type listed again is the same type (storage lists one twice), and a cycle is an error.
    auto twice = load_text("(define (domain d) (:types a) (:types a))", "");
    ASSERT_TRUE(twice->domain) << twice->errors();
    EXPECT_EQ(twice->domain->types.size(), 2U);
    auto cycle = load_text("(define (domain d) (:types a - b) (:types b - a))", "");
    EXPECT_FALSE(cycle->domain);
    EXPECT_NE(cycle->errors().find("error: the type 'b' is its own ancestor"), std::string::npos)
        << cycle->errors();
}

TEST(PddlParse, SkipsAByteOrderMarkAndEndsLinesAtCr) {
    auto l = load_text("\xEF\xBB\xBF; a comment\r(define (domain d) ; another\r"
                       "(:predicates (p)) (:action a :parameters () :precondition (p)\r"
                       ":effect (not (p))))",
                       "(define (problem q) (:domain d)\r(:init (p) (r))\r(:goal (p)))");
    EXPECT_TRUE(l->domain) << l->errors();
    EXPECT_NE(l->errors().find("problem.pddl:2:13: error: unknown predicate 'r'"),
              std::string::npos)
        << l->errors();
}

TEST(PddlErrors, InvalidUtf8IsAnEncodingError) {
    auto l = load_text("(define (domain d\xFF))", "");
    EXPECT_FALSE(l->domain);
    EXPECT_NE(l->errors().find("domain.pddl:1:18: error: invalid UTF-8"), std::string::npos)
        << l->errors();
}

struct PlanRead {
    SourceManager sm;
    DiagnosticSink sink{sm};
    std::optional<IpcPlan> plan;

    explicit PlanRead(const std::string& text) {
        plan = parse_ipc_plan(sm.add_buffer("p.plan", text), sm, sink);
    }
};

TEST(IpcPlanReader, AcceptsTheFormsPlannersWrite) {
    PlanRead r("\xEF\xBB\xBF; Fast Downward\n(Unstack E D)\n0.000: (put-down e) [1]\r\n"
               "  1.5:(pick-up c)[2.0] ; comment\r(stack c d)\n\n; cost = 4 (unit cost)\n");
    ASSERT_TRUE(r.plan) << r.sink.render();
    ASSERT_EQ(r.plan->size(), 4u);
    EXPECT_EQ((*r.plan)[0].to_string(), "(unstack e d)");
    EXPECT_EQ((*r.plan)[2].to_string(), "(pick-up c)");
    EXPECT_EQ(r.sm.line_col(0, (*r.plan)[3].range.begin).line, 5u);
    ASSERT_EQ((*r.plan)[0].arg_ranges.size(), 2u);
    EXPECT_EQ(r.sm.line_col(0, (*r.plan)[0].arg_ranges[1].begin).col, 12u);
}

TEST(IpcPlanReader, RejectsEverythingElseLocated) {
    for (auto [text, message] : std::vector<std::pair<std::string, std::string>>{
             {"(stack a b) (teleport x y) (explode)",
              "p.plan:1:13: error: expected one step per line, found a second '('"},
             {"junk (stack a b)", "p.plan:1:1: error: expected a step '(action object ...)'"},
             {"(stack a b) junk", "p.plan:1:13: error: unexpected text after the step"},
             {"((stack a b))", "p.plan:1:2: error: expected an object name or ')' in a step, "
                               "found '('"},
             {"(stack a b", "p.plan:1:1: error: unbalanced parentheses"},
             {"(stack a\nb)", "p.plan:1:1: error: unbalanced parentheses"},
             {"()", "p.plan:1:1: error: expected an action name in '()'"},
             {"1e999: (stack a b)", "p.plan:1:1: error: number '1e999' is out of range"},
             {"0: (stack a b) [x]", "p.plan:1:16: error: expected a duration '[number]'"},
             {"0 (stack a b)", "p.plan:1:1: error: expected a step '(action object ...)'"},
             {"0: stack a b", "p.plan:1:4: error: expected a step '(action object ...)' after "
                              "the time stamp"},
             {"(stack a b)\xFF", "p.plan:1:12: error: invalid UTF-8"},
         }) {
        PlanRead r(text);
        EXPECT_FALSE(r.plan) << text;
        EXPECT_NE(r.sink.render().find(message), std::string::npos) << text << "\n"
                                                                    << r.sink.render();
    }
    PlanRead several("(a)\n(b c) d\n(e\n");
    EXPECT_EQ(several.sink.num_errors(), 2u) << several.sink.render();
}

TEST(IpcPlanReader, CheckReportsEveryStepThatCannotBeRightLocated) {
    auto l = load("blocksworld-domain.pddl", "blocksworld-p01.pddl");
    ASSERT_TRUE(l->import) << l->errors();
    PlanRead r("(unstack e d)\n(teleport e)\n(stack a)\n(stack a zz)\n(pick-up qq)\n");
    ASSERT_TRUE(r.plan);
    EXPECT_FALSE(check_ipc_plan(*l->import, *r.plan, r.sink));
    EXPECT_EQ(r.sink.num_errors(), 4u);
    auto text = r.sink.render();
    EXPECT_NE(text.find("p.plan:2:2: error: unknown action 'teleport' (domain blocksworld has: "
                        "pick-up, put-down, stack, unstack)"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("p.plan:3:1: error: 'stack' takes 2 arguments, got 1"), std::string::npos)
        << text;
    EXPECT_NE(text.find("p.plan:4:10: error: unknown object 'zz'"), std::string::npos) << text;
    EXPECT_NE(text.find("p.plan:5:10: error: unknown object 'qq'"), std::string::npos) << text;
    PlanRead good(read(data("blocksworld-p01.plan")));
    EXPECT_TRUE(check_ipc_plan(*l->import, *good.plan, good.sink)) << good.sink.render();
}

} // namespace
} // namespace catplan::pddl
