// Rules, domains and problems in the language, and the case study end to end: the paper's plan
// replays step by step on both forms of the ColorBlocksworld example (the appendix form with
// attributes on Block, and the authors' slide form with predicate objects).

#include "catplan/acset/acset.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/plan/actions.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

namespace catplan::lang {
namespace {

using acset::ACSet;
using acset::Value;

struct Loaded {
    SourceManager sources;
    DiagnosticSink sink{sources};
    Module module;
};

std::unique_ptr<Loaded> load(const std::string& relative) {
    auto out = std::make_unique<Loaded>();
    out->module =
        load_file(std::string(CATPLAN_SOURCE_DIR) + "/" + relative, out->sources, out->sink);
    return out;
}

std::unique_ptr<Loaded> load_text(const std::string& text) {
    auto out = std::make_unique<Loaded>();
    out->module = load_source("test.cp", text, out->sources, out->sink);
    return out;
}

plan::Plan paper_plan(SourceManager& sources, DiagnosticSink& sink) {
    auto file =
        sources.add_file(std::string(CATPLAN_SOURCE_DIR) + "/examples/colorblocksworld/paper.plan");
    EXPECT_TRUE(file.has_value());
    auto p = plan::parse_plan(*file, sources, sink);
    EXPECT_TRUE(p.has_value()) << sink.render();
    return p ? *p : plan::Plan{};
}

// The match of a step: its arguments bind the rule's parameters by name; the rest is found by
// search and must be unique.
hom::ACSetMorphism step_match(const rewrite::Rule& rule, const ACSet& x, const plan::Step& step) {
    rewrite::MatchOptions opt;
    EXPECT_EQ(rule.parameters.size(), step.args.size()) << step.to_string();
    for (std::size_t i = 0; i < rule.parameters.size() && i < step.args.size(); ++i) {
        const auto& p = rule.parameters[i];
        auto part = x.find_part(p.ob, step.args[i]);
        EXPECT_TRUE(part.has_value()) << step.args[i];
        if (part) {
            opt.initial.push_back({p.ob, p.part, *part});
        }
    }
    auto matches = rewrite::find_matches(rule, x, opt);
    EXPECT_EQ(matches.size(), 1u) << step.to_string();
    return matches.empty() ? hom::ACSetMorphism{} : matches[0];
}

// Replays the paper's plan on the problem's initial state and returns the states after each step.
std::vector<ACSet> replay(const plan::Problem& problem, const plan::Plan& plan) {
    std::vector<ACSet> states;
    ACSet x = *problem.initial;
    for (const auto& step : plan.steps) {
        const rewrite::Rule* rule = problem.domain->find_rule(step.action);
        EXPECT_NE(rule, nullptr) << step.action;
        if (rule == nullptr) {
            break;
        }
        auto m = step_match(*rule, x, step);
        if (m.components.empty()) {
            break;
        }
        auto applied = rewrite::rewrite_in_place(*rule, x, m);
        EXPECT_TRUE(applied.has_value()) << step.to_string();
        if (!applied.has_value()) {
            break;
        }
        states.push_back(x);
    }
    return states;
}

bool goal_embeds(const plan::Problem& problem, const ACSet& x) {
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    return hom::is_homomorphic(*problem.goal, x, opt);
}

ObId ob(const ACSet& x, const char* name) {
    return *x.schema().find_ob(name);
}

TEST(CaseStudy, AppendixFormLoadsWithItsDomainAndProblem) {
    auto l = load("examples/colorblocksworld/colorblocksworld.cp");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const Declaration* d = l->module.find("Blocksworld");
    ASSERT_NE(d, nullptr);
    ASSERT_EQ(d->kind, DeclKind::Domain);
    EXPECT_EQ(summarize(*d), "domain Blocksworld (ColorBlocksworld): 4 rules: unstack, stack, "
                             "pickup, putdown");
    const rewrite::Rule* unstack = d->domain->find_rule("unstack");
    ASSERT_NE(unstack, nullptr);
    // The paper's unstack: L holds gripper, empty, block, underblock, the held marker block
    // and o; K the gripper and the two blocks; R the same three with new values.
    EXPECT_EQ(summarize_rule(*unstack), "rule unstack(block, underblock) on ColorBlocksworld: L "
                                        "6 parts, K 3, R 3, deletes 3, creates 0");
    ASSERT_EQ(unstack->parameters.size(), 2u);
    EXPECT_EQ(unstack->parameters[0].name, "block");
    EXPECT_EQ(unstack->parameters[1].name, "underblock");
    const Declaration* p = l->module.find("CaseStudy");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(summarize(*p), "problem CaseStudy (Blocksworld): initial Initial, goal Goal");
}

TEST(CaseStudy, PaperPlanReplaysOnTheAppendixForm) {
    auto l = load("examples/colorblocksworld/colorblocksworld.cp");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto& problem = *l->module.find("CaseStudy")->problem;
    auto plan = paper_plan(l->sources, l->sink);
    ASSERT_EQ(plan.steps.size(), 8u);
    EXPECT_FALSE(goal_embeds(problem, *problem.initial));
    auto states = replay(problem, plan);
    ASSERT_EQ(states.size(), 8u);

    // After unstack(E, D): the gripper holds E, the Empty part and its marker block are gone,
    // On(E, D) is gone and D is clear (reference §1.11, in the appendix form).
    const ACSet& x1 = states[0];
    const auto& s = x1.schema();
    Part e = *x1.find_part(ob(x1, "Block"), "E");
    Part dd = *x1.find_part(ob(x1, "Block"), "D");
    Part c = *x1.find_part(ob(x1, "Block"), "C");
    EXPECT_EQ(x1.num_parts(ob(x1, "Gripper")), 1u);
    EXPECT_EQ(x1.subpart(*s.find_hom("isHolding"), 0), e);
    EXPECT_EQ(x1.num_parts(ob(x1, "Empty")), 0u);
    EXPECT_EQ(x1.num_parts(ob(x1, "Block")), 6u);
    ASSERT_EQ(x1.num_parts(ob(x1, "On")), 1u);
    EXPECT_EQ(x1.subpart(*s.find_hom("on_l"), 0), dd);
    EXPECT_EQ(x1.subpart(*s.find_hom("on_r"), 0), c);
    EXPECT_EQ(x1.subpart(*s.find_attr("isClear"), dd), Value::boolean(true));
    EXPECT_EQ(x1.subpart(*s.find_attr("isClear"), e), Value::boolean(true));
    EXPECT_EQ(x1.subpart(*s.find_attr("isOnTable"), e), Value::boolean(false));
    EXPECT_EQ(x1.subpart(*s.find_attr("hasColor"), e), Value::string("purple"));

    // After putdown(E) the hand is empty again, with a new Empty part and marker block.
    EXPECT_EQ(states[1].num_parts(ob(x1, "Empty")), 1u);
    EXPECT_EQ(states[1].num_parts(ob(x1, "Block")), 7u);

    const ACSet& last = states.back();
    EXPECT_EQ(last.num_parts(ob(last, "On")), 4u);
    EXPECT_TRUE(goal_embeds(problem, last));
    for (std::size_t i = 0; i + 1 < states.size(); ++i) {
        EXPECT_FALSE(goal_embeds(problem, states[i])) << "after step " << i + 1;
    }
}

TEST(CaseStudy, PaperPlanReplaysOnTheSlideForm) {
    auto l = load("examples/colorblocksworld/slides.cp");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const Declaration* pd = l->module.find("SlidesCaseStudy");
    ASSERT_NE(pd, nullptr);
    const auto& problem = *pd->problem;
    const rewrite::Rule* unstack = problem.domain->find_rule("unstack");
    ASSERT_NE(unstack, nullptr);
    ASSERT_EQ(unstack->parameters.size(), 2u);
    EXPECT_EQ(unstack->parameters[0].name, "block");
    EXPECT_EQ(unstack->parameters[1].name, "underblock");
    auto plan = paper_plan(l->sources, l->sink);
    auto states = replay(problem, plan);
    ASSERT_EQ(states.size(), 8u);

    // After unstack(E, D): reference §1.11 without the stale fact: D has one IsClear part, true.
    const ACSet& x1 = states[0];
    const auto& s = x1.schema();
    ObId block = ob(x1, "Block"), is_clear = ob(x1, "IsClear");
    Part e = *x1.find_part(block, "E");
    Part dd = *x1.find_part(block, "D");
    EXPECT_EQ(x1.num_parts(block), 7u);
    EXPECT_EQ(x1.subpart(*s.find_hom("isHolding"), 0), e);
    EXPECT_EQ(x1.num_parts(ob(x1, "On")), 1u);
    EXPECT_EQ(x1.num_parts(is_clear), 5u);
    int d_clear = 0, e_clear = 0;
    for (Part p = 0; p < x1.num_parts(is_clear); ++p) {
        Part dom = x1.subpart(*s.find_hom("isClearDom"), p);
        if (dom == dd) {
            ++d_clear;
            EXPECT_EQ(x1.subpart(*s.find_attr("isClear"), p), Value::boolean(true));
        }
        e_clear += dom == e ? 1 : 0;
    }
    EXPECT_EQ(d_clear, 1);
    EXPECT_EQ(e_clear, 0);
    EXPECT_TRUE(goal_embeds(problem, states.back()));
    EXPECT_FALSE(goal_embeds(problem, *problem.initial));
}

TEST(Rules, NamedVariablesFlowFromPreToEffAndExpressionsAreTyped) {
    auto l = load_text(R"(
@present W(FreeSchema) begin
  Thing::Ob
  Weight::AttrType(Float)
  Name::AttrType(String)
  weight::Attr(Thing, Weight)
  name::Attr(Thing, Name)
end
@rule merge(a, b) on W begin
  Pre => begin
    (a, b)::Thing
    n::Name
    name(a) == n
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    a::Thing
    n::Name
    c::Thing
    name(c) == n
    weight(c) == weight(a) + weight(b) * 2.0
    name(a) == name(a) * "!"
  end
  NAC => begin
    weight(b) == 0.0
  end
end
)");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto& rule = *l->module.find("merge")->rule;
    EXPECT_EQ(summarize_rule(rule), "rule merge(a, b) on W: L 2 parts, K 1, R 2, deletes 1, "
                                    "creates 1, 1 NAC, 2 expressions");
    // K has the named variable n, so r sends it to R's n and c's name takes a's name.
    EXPECT_EQ(rule.K.num_vars(*rule.K.schema().find_attr_type("Name")), 1u);
    std::size_t exprs = 0;
    for (const auto& per_type : rule.exprs) {
        for (const auto& e : per_type) {
            exprs += e ? 1 : 0;
        }
    }
    EXPECT_EQ(exprs, 2u);
    EXPECT_TRUE(rewrite::check_rule(rule).empty());
}

TEST(Rules, NacRejectsAMatchAndAnExpressionUpdatesAKeptPart) {
    auto l = load_text(R"(
@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
@acset_colim Start(S) begin
  (t, u)::Thing
  h::Holder
  holds(h) == u
  flag(t) == false; size(t) == 2
  flag(u) == false; size(u) == 5
end
@rule mark(a) on S begin
  Pre => begin
    a::Thing
    flag(a) == false
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    a::Thing
    flag(a) == true
    size(a) == size(a) + 1
  end
  NAC => begin
    h::Holder
    holds(h) == a
  end
end
)");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto& rule = *l->module.find("mark")->rule;
    ACSet x = *l->module.find("Start")->instance;
    auto matches = rewrite::find_matches(rule, x);
    ASSERT_EQ(matches.size(), 1u); // u is held, so only t matches
    ObId thing = ob(x, "Thing");
    Part t = *x.find_part(thing, "t");
    EXPECT_EQ(matches[0](thing, 0), t);
    auto applied = rewrite::rewrite_in_place(rule, x, matches[0]);
    ASSERT_TRUE(applied.has_value());
    const auto& s = x.schema();
    EXPECT_EQ(x.subpart(*s.find_attr("flag"), t), Value::boolean(true));
    EXPECT_EQ(x.subpart(*s.find_attr("size"), t), Value::integer(3));
    EXPECT_TRUE(rewrite::find_matches(rule, x).empty());
}

TEST(Rules, LiteralsInRulesGiveKindsAndConditionsMayBePositive) {
    auto l = load_text(R"(
@present S(FreeSchema) begin
  Thing::Ob
  Flag::AttrType
  flag::Attr(Thing, Flag)
end
@rule raise(a) on S begin
  Pre => begin a::Thing; flag(a) == false end
  Keep => begin a::Thing end
  Eff => begin a::Thing; flag(a) == true end
  PAC => begin b::Thing; flag(b) == true end
end
)");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto& rule = *l->module.find("raise")->rule;
    const auto& s = rule.L.schema();
    EXPECT_EQ(s.attr_type(*s.find_attr_type("Flag")).kind, schema::ValueKind::Bool);
    EXPECT_EQ(summarize_rule(rule), "rule raise(a) on S: L 1 part, K 1, R 1, deletes 0, creates "
                                    "0, 1 PAC");
    ASSERT_EQ(rule.conditions.size(), 1u);
    EXPECT_FALSE(rule.conditions[0].negative);
    EXPECT_EQ(rule.conditions[0].n_state.total_parts(), 2u);
}

const char* kCounter = R"(
@present Counter(FreeSchema) begin
  Thing::Ob
  N::AttrType(Int)
  R::AttrType(Float)
  B::AttrType(Bool)
  n::Attr(Thing, N)
  r::Attr(Thing, R)
  b::Attr(Thing, B)
end
@acset_colim Start(Counter) begin
  t::Thing
  n(t) == 9223372036854775806
  r(t) == 0.0
  b(t) == false
end
@rule inc(a) on Counter begin
  Pre => begin a::Thing end
  Keep => begin a::Thing end
  Eff => begin n(a) == n(a) + 1 end
end
@rule flip(a) on Counter begin
  Pre => begin a::Thing end
  Keep => begin a::Thing end
  Eff => begin n(a) == -n(a) - 1 end
end
@rule square(a) on Counter begin
  Pre => begin a::Thing end
  Keep => begin a::Thing end
  Eff => begin n(a) == n(a) * n(a) end
end
@rule halve(a) on Counter begin
  Pre => begin a::Thing end
  Keep => begin a::Thing end
  Eff => begin
    r(a) == n(a) / 2
    b(a) == (n(a) < 9007199254740993)
  end
end
)";

// Applies the rule named `name` to x at its one match, in place; the failure reason or "".
std::string apply(const Module& m, std::string_view name, ACSet& x) {
    const auto& rule = *m.find(name)->rule;
    auto matches = rewrite::find_matches(rule, x);
    EXPECT_EQ(matches.size(), 1u) << name;
    ACSet before = x;
    auto functional = rewrite::rewrite(rule, x, matches.at(0));
    auto applied = rewrite::rewrite_in_place(rule, x, matches.at(0));
    EXPECT_EQ(functional.has_value(), applied.has_value()) << name;
    if (applied.has_value()) {
        return "";
    }
    EXPECT_TRUE(x == before) << "a failing application leaves the state as it was";
    return applied.error();
}

Value cell(const ACSet& x, std::string_view attr) {
    return x.subpart(*x.schema().find_attr(attr), 0);
}

TEST(Rules, IntArithmeticIsCheckedWhenTheRuleIsApplied) {
    auto l = load_text(kCounter);
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    ACSet x = *l->module.find("Start")->instance;
    constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
    EXPECT_EQ(apply(l->module, "inc", x), "");
    EXPECT_EQ(cell(x, "n"), Value::integer(kMax));
    EXPECT_NE(apply(l->module, "inc", x)
                  .find("Int overflow: 9223372036854775807 + 1 is outside "
                        "the range of Int"),
              std::string::npos);
    EXPECT_EQ(apply(l->module, "flip", x), ""); // -max - 1 is the least Int
    EXPECT_EQ(cell(x, "n"), Value::integer(std::numeric_limits<std::int64_t>::min()));
    EXPECT_NE(apply(l->module, "flip", x).find("Int overflow: -(-9223372036854775808)"),
              std::string::npos);
    EXPECT_NE(apply(l->module, "square", x)
                  .find("Int overflow: -9223372036854775808 * "
                        "-9223372036854775808"),
              std::string::npos);
}

TEST(Rules, DivisionGivesAFloatAndIntComparisonsAreExact) {
    auto l = load_text(kCounter);
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    ACSet x = *l->module.find("Start")->instance;
    // 2^53 - 1 squared overflows, 3037000499 squared does not.
    ACSet y = x;
    y.set_subpart(*y.schema().find_attr("n"), 0, Value::integer(3037000499));
    EXPECT_EQ(apply(l->module, "square", y), "");
    EXPECT_EQ(cell(y, "n"), Value::integer(9223372030926249001));
    x.set_subpart(*x.schema().find_attr("n"), 0, Value::integer(9007199254740992));
    EXPECT_EQ(apply(l->module, "halve", x), "");
    EXPECT_EQ(cell(x, "r"), Value::real(4503599627370496.0));
    // As doubles, 2^53 and 2^53 + 1 are equal; as Ints 2^53 < 2^53 + 1.
    EXPECT_EQ(cell(x, "b"), Value::boolean(true));
    x.set_subpart(*x.schema().find_attr("n"), 0, Value::integer(7));
    EXPECT_EQ(apply(l->module, "halve", x), "");
    EXPECT_EQ(cell(x, "r"), Value::real(3.5));
}

TEST(Rules, ErrorsAreLocated) {
    auto l = load_text(R"(
@present S(FreeSchema) begin
  Thing::Ob
  Flag::AttrType(Bool)
  flag::Attr(Thing, Flag)
end
@rule r1 on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    b::Thing
  end
end
@rule r2 on S begin
  Pre => begin
    a::Thing
  end
  Eff => begin
    a::Thing
    flag(a) == flag(a) + 1
  end
end
)");
    ASSERT_TRUE(l->sink.has_errors());
    std::string out = l->sink.render();
    EXPECT_NE(out.find("Keep part 'b' is not in Pre"), std::string::npos) << out;
    EXPECT_NE(out.find("type error"), std::string::npos) << out;
}

TEST(Rules, FactsAreHeldOnceAndACostIsWhatAStepCosts) {
    auto l = load_text(R"(
@present S(FreeSchema) begin
  (Thing, Mark)::Ob
  marks::Hom(Mark, Thing)
end
@acset_colim Start(S) begin
  t::Thing
end
@domain D(S) begin
  facts = Mark
  @rule tag(a) begin
    cost = 3
    Pre => begin
      a::Thing
    end
    Keep => begin
      a::Thing
    end
    Eff => begin
      m::Mark
      marks(m) == a
    end
  end
end
)");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto& rule = *l->module.find("D")->domain->rules.at(0);
    ASSERT_TRUE(rule.cost.has_value());
    EXPECT_EQ(rule.cost->constant, 3);
    ACSet x = *l->module.find("Start")->instance;
    ObId mark = ob(x, "Mark");
    EXPECT_EQ(rule.relations, std::vector<ObId>{mark});
    // A fact added where it holds is not added again: tagging twice leaves one mark.
    for (int i = 0; i < 2; ++i) {
        auto matches = rewrite::find_matches(rule, x);
        ASSERT_EQ(matches.size(), 1u);
        ASSERT_TRUE(rewrite::rewrite_in_place(rule, x, matches[0]).has_value());
        EXPECT_EQ(x.num_parts(mark), 1u);
    }
}

TEST(Rules, BadCostsAndFactsAreLocated) {
    auto l = load_text(R"(
@present S(FreeSchema) begin
  Thing::Ob
end
@domain D(S) begin
  facts = (Thing, Nothing, Thing)
  facts = Thing
  @rule a(x) begin
    cost = -1
    Pre => begin
      x::Thing
    end
  end
  @rule b(x) begin
    cost = 1
    cost = 2
    Pre => begin
      x::Thing
    end
  end
end
)");
    std::string out = l->sink.render();
    EXPECT_NE(out.find("test.cp:6:19: error: expected an object of schema 'S' as a fact, found "
                       "'Nothing'"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("test.cp:6:28: error: 'Thing' is given twice"), std::string::npos) << out;
    EXPECT_NE(out.find("test.cp:7:3: error: the facts are given twice"), std::string::npos) << out;
    EXPECT_NE(out.find("test.cp:9:12: error: expected the cost as a non-negative integer, a "
                       "function of the parameters such as 'length(from, to)', or a sum of them, "
                       "found '-1'"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("test.cp:16:5: error: the cost is given twice"), std::string::npos) << out;
}

// A rule's cost may read functions of its parameters, whose values a problem gives; a step
// whose value the problem does not give has no cost and is not valid.
const char* kRoads = R"(
@present Roads(FreeSchema) begin
  (City, Road, At)::Ob
  (from, to)::Hom(Road, City)
  at::Hom(At, City)
end
@acset_colim Map(Roads) begin
  (a, b, c)::City
  (ab, bc, ac)::Road
  from(ab) == a
  to(ab) == b
  from(bc) == b
  to(bc) == c
  from(ac) == a
  to(ac) == c
  here::At
  at(here) == a
end
@acset_colim Nothing(Roads) begin
end
@domain Driving(Roads) begin
  @rule drive(x, y) begin
    cost = 1 + length(x, y) + toll("c")
    Pre => begin
      (x, y)::City
      r::Road
      from(r) == x
      to(r) == y
      h::At
      at(h) == x
    end
    Keep => begin
      (x, y)::City
      r::Road
      from(r) == x
      to(r) == y
    end
    Eff => begin
      h2::At
      at(h2) == y
    end
  end
end
)";

TEST(Rules, CostsReadTheProblemsFunctionValues) {
    auto l = load_text(std::string(kRoads) + R"(
@problem Trip(Driving) begin
  initial = Map
  goal = Nothing
  length(a, b) = 3
  length(b, c) = 4
  toll(c) = 10
end
@problem Steps(Driving) begin
  initial = Map
  goal = Nothing
  metric = steps
end
)");
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto& trip = *l->module.find("Trip")->problem;
    const auto& rule = *trip.domain->rules.at(0);
    ASSERT_TRUE(rule.cost.has_value());
    EXPECT_EQ(rule.cost->to_string({"x", "y"}), "1 + length(x, y) + toll(\"c\")");
    ASSERT_TRUE(trip.step_cost);
    EXPECT_EQ(trip.step_cost(rule, {"a", "b"}), 14);
    EXPECT_EQ(trip.step_cost(rule, {"a", "c"}), std::nullopt);
    auto drives = [](std::vector<std::vector<std::string>> steps) {
        plan::Plan p;
        for (auto& args : steps) {
            p.steps.push_back(plan::Step{"drive", std::move(args), {}});
        }
        return p;
    };
    auto v = plan::validate_plan(trip, drives({{"a", "b"}, {"b", "c"}}));
    ASSERT_TRUE(v.valid) << v.reason;
    EXPECT_EQ(v.cost, 29);
    auto direct = plan::validate_plan(trip, drives({{"a", "c"}}));
    EXPECT_FALSE(direct.valid);
    EXPECT_EQ(direct.reason, "step 1 drive(a, c): its cost 1 + length(a, c) + toll(\"c\") has no "
                             "value in the problem");
    const auto& steps = *l->module.find("Steps")->problem;
    EXPECT_TRUE(steps.counts_steps);
    EXPECT_FALSE(steps.step_cost);
    EXPECT_EQ(plan::validate_plan(steps, drives({{"a", "c"}})).cost, std::nullopt);
}

TEST(Rules, BadFunctionCostsAndValuesAreLocated) {
    auto l = load_text(std::string(kRoads) + R"(
@domain Flying(Roads) begin
  @rule fly(x) begin
    cost = distance(x, z) + 2.5
    Pre => begin
      x::City
    end
    Keep => begin
      x::City
    end
  end
end
@problem Trip(Driving) begin
  initial = Map
  goal = Nothing
  length(a, q) = 3
  length(a, b) = -3
  length(b, c) = 4
  length(b, c) = 5
  length(a) = 1
  width(a, b) = 1
  metric = fastest
end
)");
    std::string out = l->sink.render();
    for (const char* e :
         {"test.cp:47:24: error: expected a parameter of rule 'fly' or a part name in quotes, "
          "found 'z'",
          "test.cp:47:29: error: expected the cost as a non-negative integer, a function of the "
          "parameters such as 'length(from, to)', or a sum of them, found '2.5'",
          "test.cp:59:13: error: 'q' is no part of the initial state",
          "test.cp:60:18: error: expected the value of length as a non-negative integer, found "
          "'-3'",
          "test.cp:62:3: error: length(b, c) is given twice",
          "test.cp:63:3: error: rule 'drive' reads length with 2 arguments, not 1",
          "test.cp:64:3: warning: no rule's cost reads 'width'",
          "test.cp:65:12: error: expected 'metric = cost' or 'metric = steps', found 'metric = "
          "fastest'"}) {
        EXPECT_NE(out.find(e), std::string::npos) << e << "\n" << out;
    }
}

// Two rules carrying out one action (the domain of docs/language.md): `move(hall, hall)` is the
// rule `stay`, which identifies the action's two arguments; `move(hall, kitchen)` is `move`.
const char* kWalking = R"(
@present Rooms(FreeSchema) begin
  (Room, At)::Ob
  at::Hom(At, Room)
end
@acset_colim Start(Rooms) begin
  (hall, kitchen)::Room
  a::At
  at(a) == hall
end
@acset_colim There(Rooms) begin
  kitchen::Room
  a::At
  at(a) == kitchen
end
@domain Walking(Rooms) begin
  facts = At
  @rule move(from, to) begin
    Pre => begin
      (from, to)::Room
      here::At
      at(here) == from
    end
    Keep => begin
      (from, to)::Room
    end
    Eff => begin
      there::At
      at(there) == to
    end
  end
  @rule stay(r) begin
    action = move(r, r)
    Pre => begin
      r::Room
      here::At
      at(here) == r
    end
    Keep => begin
      r::Room
      here::At
      at(here) == r
    end
    Eff => begin
    end
  end
end
@problem Go(Walking) begin
  initial = Start
  goal = There
end
)";

plan::Plan parsed_plan(Loaded& l, const std::string& text) {
    auto file = l.sources.add_buffer("test.plan", text);
    auto p = plan::parse_plan(file, l.sources, l.sink);
    EXPECT_TRUE(p.has_value()) << l.sink.render();
    return p ? *p : plan::Plan{};
}

TEST(Rules, AStepOfAnActionIsTheRuleOfItThatApplies) {
    auto l = load_text(kWalking);
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto& problem = *l->module.find("Go")->problem;
    const auto& domain = *problem.domain;
    const auto& stay = *domain.find_rule("stay");
    ASSERT_TRUE(stay.action.has_value());
    EXPECT_EQ(stay.action_name(), "move");
    EXPECT_EQ(stay.action->arguments, (std::vector<rewrite::ActionOf::Argument>{{0, ""}, {0, ""}}));
    EXPECT_EQ(plan::action_rules(domain, "move").size(), 2u);
    EXPECT_TRUE(plan::action_rules(domain, "stay").empty());

    // The rule steps of a written plan, which validate.
    auto rule_steps = [&](const plan::Plan& written) {
        auto rules = plan::rule_plan(domain, *problem.initial, written);
        auto v = plan::validate_plan(problem, rules);
        EXPECT_TRUE(v.valid) << v.reason;
        EXPECT_EQ(plan::action_plan(domain, rules).to_string(), written.to_string());
        std::vector<std::string> out;
        for (const auto& step : rules.steps) {
            out.push_back(step.to_string());
        }
        return out;
    };
    auto written = parsed_plan(*l, "move(hall, hall)\nmove(hall, kitchen)\n");
    ASSERT_TRUE(plan::check_plan(written, domain, *problem.initial, l->sink)) << l->sink.render();
    EXPECT_EQ(rule_steps(written), (std::vector<std::string>{"stay(hall)", "move(hall, kitchen)"}));
    // A step only `move` fits is not replayed until a step both rules fit needs the state it
    // leaves: `stay(kitchen)` applies only once the walker is in the kitchen.
    EXPECT_EQ(rule_steps(parsed_plan(*l, "move(hall, kitchen)\nmove(kitchen, kitchen)\n")),
              (std::vector<std::string>{"move(hall, kitchen)", "stay(kitchen)"}));

    // Arguments that fit no rule, or no rule that applies, fail where the written plan does.
    auto wrong = parsed_plan(*l, "move(kitchen, kitchen)\nmove(hall, kitchen)\n");
    auto unapplied = plan::rule_plan(domain, *problem.initial, wrong);
    EXPECT_EQ(unapplied.steps[0].to_string(), "move(kitchen, kitchen)");
    auto failed = plan::validate_plan(problem, unapplied);
    EXPECT_FALSE(failed.valid);
    EXPECT_EQ(failed.failed_step, std::optional<std::size_t>(0));
    // A plan naming the rule itself still reads.
    auto by_rule = parsed_plan(*l, "stay(hall)\n");
    EXPECT_TRUE(plan::check_plan(by_rule, domain, *problem.initial, l->sink)) << l->sink.render();
    EXPECT_EQ(plan::rule_plan(domain, *problem.initial, by_rule).steps[0].to_string(),
              "stay(hall)");
}

TEST(Rules, BadActionsAndActionStepsAreLocated) {
    auto l = load_text(R"(
@present S(FreeSchema) begin
  Thing::Ob
end
@domain D(S) begin
  @rule a(x, y) begin
    action = go(x, y, "c")
    Pre => begin
      (x, y)::Thing
    end
  end
  @rule b(x) begin
    action = go(x, x)
    Pre => begin
      x::Thing
    end
  end
  @rule c(x, y) begin
    action = go(x, z, "c")
    action = go(x)
    Pre => begin
      (x, y)::Thing
    end
  end
end
)");
    std::string out = l->sink.render();
    // A domain that gives a rule of an action other parameters keeps the action's arguments.
    auto renamed = load_text(std::string(kWalking) + R"(
@rule stay_put(r) on Rooms begin
  action = move(r, r)
  Pre => begin
    (r, s)::Room
  end
end
@domain Kept(Rooms) begin
  stay_put(r)
end
@domain Lost(Rooms) begin
  stay_put(s)
end
)");
    const auto* kept = renamed->module.find("Kept");
    ASSERT_TRUE(kept != nullptr && kept->domain != nullptr) << renamed->sink.render();
    EXPECT_EQ(kept->domain->rules.at(0)->action->arguments,
              (std::vector<rewrite::ActionOf::Argument>{{0, ""}, {0, ""}}));
    EXPECT_NE(renamed->sink.render().find("error: the parameters leave out 'r', an argument of "
                                          "the action 'move' of rule 'stay_put'"),
              std::string::npos)
        << renamed->sink.render();
    EXPECT_NE(out.find("test.cp:12:9: error: rule 'b' carries out the action 'go' with 2 "
                       "arguments, but rule 'a' does with 3"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("test.cp:19:20: error: expected a parameter of rule 'c' or a part name in "
                       "quotes, found 'z'"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("test.cp:20:5: error: the action is given twice"), std::string::npos) << out;
    EXPECT_NE(out.find("test.cp:19:14: error: the action does not give the parameter 'y' of "
                       "rule 'c'"),
              std::string::npos)
        << out;

    auto w = load_text(kWalking);
    ASSERT_FALSE(w->sink.has_errors()) << w->sink.render();
    const auto& problem = *w->module.find("Go")->problem;
    auto p = parsed_plan(*w, "move(hall)\nstay(hall, hall)\nwalk(hall)\nmove(hall, cellar)\n");
    EXPECT_FALSE(plan::check_plan(p, *problem.domain, *problem.initial, w->sink));
    out = w->sink.render();
    EXPECT_NE(out.find("test.plan:1:1: error: move takes 2 arguments, got 1"), std::string::npos)
        << out;
    EXPECT_NE(out.find("test.plan:2:1: error: stay takes 1 argument (r), got 2"), std::string::npos)
        << out;
    EXPECT_NE(out.find("test.plan:3:1: error: unknown action 'walk' (domain Walking has: move)"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("test.plan:4:12: error: argument 2 (to): no Room named 'cellar'"),
              std::string::npos)
        << out;
}

} // namespace
} // namespace catplan::lang
