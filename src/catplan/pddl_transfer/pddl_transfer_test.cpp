#include "catplan/pddl_transfer/pddl_transfer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace catplan::pddl_transfer {
namespace {

const std::string kExamples = std::string(CATPLAN_SOURCE_DIR) + "/examples/pddl/";

/// A map's file loaded, with the sources its diagnostics point into.
struct Loaded {
    SourceManager sources;
    DiagnosticSink sink{sources};
    lang::Module module;

    explicit Loaded(const std::string& file) {
        module = lang::load_file(kExamples + file, sources, sink);
        EXPECT_FALSE(sink.has_errors()) << sink.render();
    }

    std::optional<Setting> setting(const std::string& map, const std::string& problem,
                                   const std::string& target_problem = "") {
        std::optional<std::uint32_t> t;
        if (!target_problem.empty()) {
            t = *sources.add_file(kExamples + target_problem);
        }
        return load_setting(module, *module.find(map), *sources.add_file(kExamples + problem), t,
                            sources, sink);
    }

    pddl::IpcPlan plan(const Setting& s, const std::string& file) {
        auto p = read_plan(s, *sources.add_file(kExamples + file), sources, sink);
        EXPECT_TRUE(p.has_value()) << sink.render();
        return p.value_or(pddl::IpcPlan{});
    }
};

/// The transfer of `plan` in the setting, with its PDDL checks.
std::pair<transfer::TransferResult, Checks> run(const Setting& s, const pddl::IpcPlan& plan) {
    auto t = transfer::transfer_plan(*s.map, *s.source->problem, source_plan(s, plan),
                                     transfer_options(s, plan));
    auto c = check(s, plan, t);
    return {std::move(t), std::move(c)};
}

/// The target plan's actions.
std::vector<std::string> actions_of(const Checks& c) {
    std::vector<std::string> out;
    for (const auto& st : c.target_plan.value_or(pddl::IpcPlan{})) {
        out.push_back(st.action);
    }
    return out;
}

/// Each step's repair cost, checking that every step was repaired at its least cost.
std::vector<std::int64_t> least_repair_costs(const transfer::TransferResult& t) {
    std::vector<std::int64_t> costs;
    for (const auto& st : t.steps) {
        EXPECT_EQ(st.kind, transfer::StepTransfer::Kind::Repaired);
        EXPECT_TRUE(st.repair_least_cost);
        costs.push_back(st.repair_cost.value_or(-1));
    }
    return costs;
}

TEST(PddlTransfer, ThreeOperatorMovesAreRepairedIntoFourOperatorSteps) {
    Loaded l("blocks/three_to_four.cp");
    auto s = l.setting("ThreeToFour", "blocks/p01-3.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    ASSERT_NE(s->target, nullptr);
    auto plan = l.plan(*s, "blocks/p01-3.plan");
    ASSERT_EQ(plan.size(), 3U);
    auto [t, c] = run(*s, plan);
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    // No 4-operator action is a migrated move: every source step becomes two target steps.
    ASSERT_EQ(t.steps.size(), 3U);
    for (const auto& st : t.steps) {
        EXPECT_EQ(st.kind, transfer::StepTransfer::Kind::Repaired);
        EXPECT_EQ(st.target_steps.size(), 2U);
    }
    ASSERT_TRUE(c.target_plan.has_value());
    ASSERT_EQ(c.target_plan->size(), 6U);
    EXPECT_EQ((*c.target_plan)[0].to_string(), "(unstack a b)");
    EXPECT_EQ(ipc_text(*s, t.steps[0].target_steps[1]), (*c.target_plan)[1].to_string());
    ASSERT_TRUE(c.validation.has_value());
    EXPECT_TRUE(c.validation->valid) << c.validation->reason;
    EXPECT_NE(c.plan_text.find("; cost = 6 (unit cost)"), std::string::npos) << c.plan_text;
    EXPECT_FALSE(c.source_cost.has_value()); // blocks3 declares no action costs
    ASSERT_TRUE(c.migrated.has_value());
    EXPECT_EQ(c.migrated->objects.size(), 3U);
    EXPECT_FALSE(c.comparison.has_value());
    EXPECT_TRUE(c.ok(t));
}

TEST(PddlTransfer, AnActionsFirstRepairIsSearchedOnItsMigratedActionsOwnSides) {
    // Each of the three moves is its action's first step: a breadth-first search from the
    // migrated action's left side (the blocks it names, with their names) to its right side
    // finds the two 4-operator steps; no focus of the state is built.
    Loaded l("blocks/three_to_four.cp");
    auto s = l.setting("ThreeToFour", "blocks/p01-3.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    auto [t, c] = run(*s, l.plan(*s, "blocks/p01-3.plan"));
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    ASSERT_EQ(t.steps.size(), 3U);
    for (const auto& st : t.steps) {
        EXPECT_TRUE(st.repair_from_action);
        EXPECT_EQ(st.repair_focus, 0U);
        EXPECT_FALSE(st.repair_reused_from.has_value());
        EXPECT_GE(st.repair_stats.expanded, 1U);
    }
    EXPECT_EQ(actions_of(c), (std::vector<std::string>{"unstack", "put-down", "unstack", "stack",
                                                       "pick-up", "stack"}));
    EXPECT_TRUE(c.validation.has_value() && c.validation->valid);

    // The other way, Δ_F(stack b a) takes the block from the gripper, which the 3-operator world
    // does not see: from its sides alone nothing reaches its effect, and the focus of the state
    // (where b is on the table) gives move-from-table.
    Loaded back("blocks/four_to_three.cp");
    auto s4 = back.setting("FourToThree", "blocks/p01-4.pddl");
    ASSERT_TRUE(s4.has_value()) << back.sink.render();
    auto [t4, c4] = run(*s4, back.plan(*s4, "blocks/p01-4.plan"));
    ASSERT_TRUE(t4.verdict.valid()) << t4.verdict.reason();
    ASSERT_GE(t4.steps.size(), 4U);
    EXPECT_EQ(t4.steps[3].source.action, "stack");
    EXPECT_FALSE(t4.steps[3].repair_from_action);
    EXPECT_GT(t4.steps[3].repair_focus, 0U);
    ASSERT_EQ(t4.steps[3].target_steps.size(), 1U);
    EXPECT_EQ(t4.steps[3].target_steps[0].action, "move-from-table");
}

TEST(PddlTransfer, ActionsOfADeltaMapCorrespondAndTheUsersProblemIsCompared) {
    Loaded l("warehouse/hospital_to_warehouse.cp");
    auto s =
        l.setting("HospitalToWarehouse", "warehouse/warehouse-3.pddl", "warehouse/hospital-3.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    auto plan = l.plan(*s, "warehouse/warehouse-3.plan");
    auto [t, c] = run(*s, plan);
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    for (const auto& st : t.steps) {
        EXPECT_EQ(st.kind, transfer::StepTransfer::Kind::Corresponds);
    }
    ASSERT_TRUE(c.target_plan.has_value());
    EXPECT_EQ(c.target_plan->size(), plan.size());
    EXPECT_EQ((*c.target_plan)[0].action, "collect");
    EXPECT_TRUE(c.validation && c.validation->valid);
    ASSERT_TRUE(c.comparison.has_value());
    EXPECT_EQ(c.comparison->name, s->target_problem->name);
    EXPECT_TRUE(c.comparison->same());
    EXPECT_TRUE(c.ok(t));
}

TEST(PddlTransfer, ATargetProblemThatIsNotTheMigratedInitialStateSaysWhatDiffers) {
    Loaded l("warehouse/hospital_to_warehouse.cp");
    auto s =
        l.setting("HospitalToWarehouse", "warehouse/warehouse-3.pddl", "warehouse/hospital-3.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    // The user's problem with one fact more than Δ_F(I).
    auto& init = s->target_problem->init;
    auto fact =
        *std::find_if(init.begin(), init.end(), [](const auto& a) { return !a.args.empty(); });
    fact.args[0].name = "nowhere";
    init.push_back(fact);
    auto [t, c] = run(*s, l.plan(*s, "warehouse/warehouse-3.plan"));
    ASSERT_TRUE(c.comparison.has_value());
    EXPECT_FALSE(c.comparison->same());
    EXPECT_TRUE(c.comparison->only_in_migrated.empty());
    ASSERT_EQ(c.comparison->only_in_target_problem.size(), 1U);
    EXPECT_NE(c.comparison->only_in_target_problem[0].find("nowhere"), std::string::npos);
    EXPECT_FALSE(c.ok(t));
}

TEST(PddlTransfer, APlanStepNoStateCouldTakeIsBadInput) {
    Loaded l("blocks/three_to_four.cp");
    auto s = l.setting("ThreeToFour", "blocks/p01-3.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    auto file = l.sources.add_buffer("bad.plan", "(move a b)\n(fly a)\n");
    EXPECT_FALSE(read_plan(*s, file, l.sources, l.sink).has_value());
    EXPECT_NE(l.sink.render().find("bad.plan:2:"), std::string::npos) << l.sink.render();
}

TEST(PddlTransfer, AnInvalidSourcePlanIsCalledSoInTheWordsOfThePddlValidator) {
    Loaded l("blocks/three_to_four.cp");
    auto s = l.setting("ThreeToFour", "blocks/p02-3.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    // A step that cannot be taken, and a plan that stops short of the goal: the transfer's
    // fault is the validator's (what `catplan validate` prints), not the rules' "no match".
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"(move-to-table a b)\n(move e f d)\n",
         "step 2 (move e f d): precondition (clear e) does not hold"},
        {"(move-to-table a b)\n", "goal not reached: (on c b) does not hold"},
    };
    for (const auto& [text, reason] : cases) {
        auto plan = read_plan(*s, l.sources.add_buffer("p.plan", text), l.sources, l.sink);
        ASSERT_TRUE(plan.has_value()) << l.sink.render();
        auto [t, c] = run(*s, *plan);
        const auto* fault = t.verdict.find(transfer::Fault::Kind::SourcePlan);
        ASSERT_NE(fault, nullptr) << text;
        EXPECT_EQ(fault->to_string(), reason);
        auto v = pddl::simulate_ipc_plan(s->source->pddl_domain, *s->source->pddl_problem, *plan);
        EXPECT_EQ(v.reason, reason);
        EXPECT_EQ(fault->step, v.failed_step);
    }
}

TEST(PddlTransfer, AMapFromADomainNotReadFromPddlIsRefused) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto module = lang::load_source("m.cp", R"(
@present A(FreeSchema) begin
  X::Ob
end
@present B(FreeSchema) begin
  Y::Ob
end
@migration F(B, A) begin
  Y => X
end
)",
                                    sources, sink);
    ASSERT_FALSE(sink.has_errors()) << sink.render();
    auto problem = sources.add_buffer("p.pddl", "(define (problem p) (:domain a))");
    EXPECT_FALSE(
        load_setting(module, *module.find("F"), problem, std::nullopt, sources, sink).has_value());
    EXPECT_NE(sink.render().find("map 'F' migrates from A, which is no PDDL domain"),
              std::string::npos)
        << sink.render();
}

TEST(PddlTransfer, TheFunctionsSectionCarriesTheSourceValuesToTheTargetFunctions) {
    Loaded l("../../tests/pddl/roads_to_transit.cp");
    auto s = l.setting("ToTransit", "../../tests/pddl/roads-p01.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    ASSERT_EQ(s->functions.size(), 1U);
    auto plan = l.plan(*s, "../../tests/pddl/roads-p01.plan");
    auto [t, c] = run(*s, plan);
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    ASSERT_TRUE(c.migrated.has_value() && c.target_cost.has_value());
    // The five lengths the source problem gives, as travel times; total-cost is not carried.
    ASSERT_EQ(c.migrated->values.size(), 5U);
    EXPECT_EQ(c.migrated->values[0].term.to_string(), "(travel-time a d)");
    EXPECT_EQ(c.migrated->values[0].value, 20);
    EXPECT_EQ(c.target_cost->total, 12);
    EXPECT_TRUE(s->uncarried_values.empty());
    ASSERT_TRUE(c.validation.has_value());
    EXPECT_TRUE(c.validation->valid) << c.validation->reason;

    // Without the section the target's travel times have no values: the plan has no cost.
    auto without = l.setting("ToTransitWithoutTimes", "../../tests/pddl/roads-p01.pddl");
    ASSERT_TRUE(without.has_value()) << l.sink.render();
    auto [t3, c3] = run(*without, plan);
    ASSERT_TRUE(c3.target_cost.has_value());
    EXPECT_NE(c3.target_cost->undefined, "");
    EXPECT_FALSE(c3.validation->valid);
}

TEST(PddlTransfer, AValueWhoseArgumentsTheTargetFunctionCannotTakeIsLeftOutAndNamed) {
    Loaded l("../../tests/pddl/roads_to_transit.cp");
    // A fare is per bus and stop; a road's length is between two stops of Δ_F(I).
    auto s = l.setting("ToFares", "../../tests/pddl/roads-p01.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    EXPECT_TRUE(s->carried_values.empty());
    EXPECT_EQ(
        s->uncarried_values,
        (std::vector<std::string>{"(road-length a d)", "(road-length a b)", "(road-length b c)",
                                  "(road-length c d)", "(road-length e d)"}));
    auto [t, c] = run(*s, l.plan(*s, "../../tests/pddl/roads-p01.plan"));
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    ASSERT_TRUE(c.target_cost.has_value());
    EXPECT_NE(c.target_cost->undefined.find("fare"), std::string::npos) << c.target_cost->undefined;
}

TEST(PddlTransfer, RepairsTakeNoStepWithoutACostWhereTheTargetsValuesAreKnown) {
    Loaded l("../../tests/pddl/roads_to_transit.cp");
    auto s = l.setting("ToHops", "../../tests/pddl/roads-p01.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    ASSERT_TRUE(s->target_values.has_value());
    auto plan = l.plan(*s, "../../tests/pddl/roads-p01.plan");
    auto [t, c] = run(*s, plan);
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    // Each drive is a departure and an arrival; a shuttle's fare has no value.
    EXPECT_EQ(actions_of(c), (std::vector<std::string>{"depart", "arrive", "depart", "arrive",
                                                       "depart", "arrive"}));
    ASSERT_TRUE(c.target_cost.has_value());
    EXPECT_EQ(c.target_cost->total, 12);
    ASSERT_TRUE(c.validation.has_value());
    EXPECT_TRUE(c.validation->valid) << c.validation->reason;

    // Repairs that count steps, and search the drive's own sides first, still take no shuttle.
    auto o = transfer_options(*s, plan);
    o.repair.least_cost = false;
    auto by_steps = transfer::transfer_plan(*s->map, *s->source->problem, source_plan(*s, plan), o);
    ASSERT_TRUE(by_steps.verdict.valid()) << by_steps.verdict.reason();
    EXPECT_EQ(
        actions_of(check(*s, plan, by_steps)),
        (std::vector<std::string>{"depart", "arrive", "depart", "arrive", "depart", "arrive"}));

    // Nor where the sides' search stops at its first state and each drive is searched on a focus.
    o.repair.generated_max_nodes = 1;
    auto focused = transfer::transfer_plan(*s->map, *s->source->problem, source_plan(*s, plan), o);
    ASSERT_TRUE(focused.verdict.valid()) << focused.verdict.reason();
    for (const auto& st : focused.steps) {
        EXPECT_FALSE(st.repair_from_action);
    }
    EXPECT_EQ(
        actions_of(check(*s, plan, focused)),
        (std::vector<std::string>{"depart", "arrive", "depart", "arrive", "depart", "arrive"}));

    // Repairs that read no costs take the shuttle, which the target problem cannot price.
    s->target_values.reset();
    auto [t2, c2] = run(*s, plan);
    ASSERT_TRUE(t2.verdict.valid()) << t2.verdict.reason();
    ASSERT_TRUE(c2.validation.has_value());
    EXPECT_FALSE(c2.validation->valid);
}

TEST(PddlTransfer, RepairsSumTheTargetsCostsAndTakeTheCheapestSteps) {
    Loaded l("../../tests/pddl/roads_to_transit.cp");
    auto s = l.setting("ToCharters", "../../tests/pddl/roads-p01.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    auto plan = l.plan(*s, "../../tests/pddl/roads-p01.plan");
    auto [t, c] = run(*s, plan);
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    // A departure and an arrival cost the road's length (3, 4, 5); a charter costs 50.
    EXPECT_EQ(actions_of(c), (std::vector<std::string>{"depart", "arrive", "depart", "arrive",
                                                       "depart", "arrive"}));
    EXPECT_EQ(least_repair_costs(t), (std::vector<std::int64_t>{3, 4, 5}));
    ASSERT_TRUE(c.target_cost.has_value());
    EXPECT_EQ(c.target_cost->total, 12);
    ASSERT_TRUE(c.validation.has_value());
    EXPECT_TRUE(c.validation->valid) << c.validation->reason;

    // Repairs that count steps take the one-step charter: a valid plan that costs 150.
    auto o = transfer_options(*s, plan);
    o.repair.least_cost = false;
    auto t2 = transfer::transfer_plan(*s->map, *s->source->problem, source_plan(*s, plan), o);
    ASSERT_TRUE(t2.verdict.valid()) << t2.verdict.reason();
    auto c2 = check(*s, plan, t2);
    EXPECT_EQ(actions_of(c2), (std::vector<std::string>{"charter", "charter", "charter"}));
    ASSERT_TRUE(c2.target_cost.has_value());
    EXPECT_EQ(c2.target_cost->total, 150);
    EXPECT_FALSE(t2.steps[0].repair_least_cost);

    // Where A* stops at its limit on the whole state, the greedy search still finds a repair.
    auto o3 = transfer_options(*s, plan);
    o3.repair.radii.clear();
    o3.repair.search.max_nodes = 1;
    auto t3 = transfer::transfer_plan(*s->map, *s->source->problem, source_plan(*s, plan), o3);
    ASSERT_TRUE(t3.verdict.valid()) << t3.verdict.reason();
    EXPECT_EQ(actions_of(check(*s, plan, t3)),
              (std::vector<std::string>{"charter", "charter", "charter"}));
    EXPECT_FALSE(t3.steps[0].repair_least_cost);
    EXPECT_EQ(t3.steps[0].repair_cost, 50);
}

// The shapes that costed repairs are reused by hold the values: a repair of the 60-long road is
// searched on its own and takes the charter, the 2-long roads' repairs are reused, and each is
// the least. Without the values in the shape the 60-long drive would reuse depart and arrive.
TEST(PddlTransfer, CostedRepairsAreReusedWhereTheValuesAgree) {
    Loaded l("../../tests/pddl/roads_to_transit.cp");
    auto s = l.setting("ToCharters", "../../tests/pddl/roads-chain.pddl");
    ASSERT_TRUE(s.has_value()) << l.sink.render();
    auto plan = l.plan(*s, "../../tests/pddl/roads-chain.plan");
    auto [t, c] = run(*s, plan);
    ASSERT_TRUE(t.verdict.valid()) << t.verdict.reason();
    EXPECT_EQ(least_repair_costs(t), (std::vector<std::int64_t>{2, 2, 2, 50, 2, 2, 2}));
    std::size_t reused = 0;
    for (const auto& st : t.steps) {
        if (st.repair_reused_from) {
            ++reused;
            EXPECT_EQ(t.steps[*st.repair_reused_from].repair_cost, st.repair_cost);
        }
    }
    EXPECT_GE(reused, 2U);
    EXPECT_FALSE(t.steps[3].repair_reused_from.has_value());
    ASSERT_TRUE(c.target_cost.has_value());
    EXPECT_EQ(c.target_cost->total, 62);
    ASSERT_TRUE(c.validation.has_value());
    EXPECT_TRUE(c.validation->valid) << c.validation->reason;
}

} // namespace
} // namespace catplan::pddl_transfer
