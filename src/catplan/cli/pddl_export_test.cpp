// `pddl export` on every example domain and problem (and each map's migrated target): the export
// reads back with catplan's own PDDL reader, catplan's plans carry over to it, and plans found on
// it carry back, valid on the problem exported. Fast Downward and VAL are checked in `make
// interop` (tools/interop.sh), not here.

#include "catplan/cli/pddl_export.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/pddl/export.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace catplan::cli {
namespace {

struct Example {
    const char* file;
    const char* problem;
    const char* map; // or ""
    // A plan of the problem (or of the source problem, whose steps a migrated rule takes too:
    // rule and parameter names are kept), or "" to let the planner find one.
    const char* plan;
};

// The examples of tools/interop.sh.
const Example kExamples[] = {
    {"examples/colorblocksworld/colorblocksworld.cp", "CaseStudy", "",
     "examples/colorblocksworld/paper.plan"},
    {"examples/colorblocksworld/slides.cp", "SlidesCaseStudy", "",
     "examples/colorblocksworld/paper.plan"},
    {"examples/hanoi/hanoi.cp", "ThreeDiscs", "", "examples/hanoi/hanoi.plan"},
    {"examples/sandwich_kitchen/sandwich_kitchen.cp", "MakeSandwich", "",
     "examples/sandwich_kitchen/sandwich.plan"},
    {"tests/pddl/lights.cp", "LightsProblem", "", ""},
    {"tests/pddl/lights.cp", "LightsProblem", "LightsToRooms", ""},
    {"examples/colorblocks_to_kitchen/appendix_map.cp", "CaseStudy", "ColorToKitchen",
     "examples/colorblocksworld/paper.plan"},
    {"examples/colorblocks_to_kitchen/slides_map.cp", "SlidesCaseStudy", "ColorToKitchen",
     "examples/colorblocksworld/paper.plan"},
    {"examples/colorblocks_to_kitchen/swapped_map.cp", "CaseStudy", "SwappedToKitchen",
     "examples/colorblocksworld/paper.plan"},
    {"examples/colorblocks_to_blocks/forget_colors.cp", "CaseStudy", "ForgetColors",
     "examples/colorblocksworld/paper.plan"},
    {"examples/hanoi_to_blocks/hanoi_to_blocks.cp", "ThreeDiscs", "HanoiToBlocks",
     "examples/hanoi/hanoi.plan"},
    {"examples/kitchen_to_colorblocks/kitchen_to_color.cp", "MakeSandwich", "KitchenToColor",
     "examples/sandwich_kitchen/sandwich.plan"},
    {"examples/kitchen_to_warehouse/kitchen_to_warehouse.cp", "CaseStudy", "ColorToWarehouse",
     "examples/colorblocksworld/paper.plan"},
};

std::string path(const std::string& relative) {
    return std::string(CATPLAN_SOURCE_DIR) + "/" + relative;
}

struct Loaded {
    SourceManager sources;
    DiagnosticSink sink{sources};
    plan::ProblemPtr problem;
};

/// The example's problem, migrated along its map when it has one.
std::unique_ptr<Loaded> load_example(const Example& e) {
    auto l = std::make_unique<Loaded>();
    auto m = lang::load_file(path(e.file), l->sources, l->sink);
    EXPECT_FALSE(l->sink.has_errors()) << l->sink.render();
    const auto* p = m.find(e.problem);
    if (p == nullptr || p->problem == nullptr) {
        ADD_FAILURE() << "no problem " << e.problem;
        return nullptr;
    }
    l->problem = p->problem;
    if (*e.map != '\0') {
        const auto* f = m.find(e.map);
        EXPECT_TRUE(f != nullptr && f->map != nullptr);
        auto migrated = migrate_along(*f->map, p->problem->domain, p->problem);
        EXPECT_TRUE(migrated.has_value()) << (migrated ? "" : migrated.error());
        if (!migrated) {
            return nullptr;
        }
        l->problem = migrated->second;
    }
    return l;
}

/// The exported files read with catplan's PDDL reader and imported.
std::optional<pddl::Import> read_back(const pddl::Exported& ex, SourceManager& sources,
                                      DiagnosticSink& sink) {
    auto df = sources.add_buffer("domain.pddl", ex.domain);
    auto pf = sources.add_buffer("problem.pddl", ex.problem);
    auto d = pddl::parse_domain(df, sources, sink);
    if (!d) {
        return std::nullopt;
    }
    auto p = pddl::parse_problem(pf, *d, sources, sink);
    if (!p) {
        return std::nullopt;
    }
    return pddl::import_pddl(*d, &*p, sink);
}

std::optional<plan::Plan> read_plan(const std::string& file, SourceManager& sources,
                                    DiagnosticSink& sink) {
    std::ifstream in(path(file));
    std::stringstream text;
    text << in.rdbuf();
    return plan::parse_plan(sources.add_buffer(file, text.str()), sources, sink);
}

plan::SearchOptions small_search() {
    plan::SearchOptions o;
    o.max_nodes = 200000;
    return o;
}

TEST(PddlExport, EveryExampleReadsBackAndItsPlansCarryOverBothWays) {
    for (const auto& e : kExamples) {
        SCOPED_TRACE(std::string(e.file) + " " + e.problem + " " + e.map);
        auto l = load_example(e);
        ASSERT_TRUE(l != nullptr);
        auto ex = pddl::export_pddl(*l->problem->domain, l->problem.get());
        ASSERT_TRUE(ex.has_value()) << ex.error();
        SourceManager sources;
        DiagnosticSink sink(sources);
        auto im = read_back(*ex, sources, sink);
        ASSERT_TRUE(im.has_value() && !sink.has_errors()) << sink.render() << ex->domain;

        // catplan's plan for the problem exported (the example's, else the planner's), carried to
        // the export: valid there, by catplan's PDDL validator.
        std::optional<plan::Plan> given;
        if (*e.plan != '\0') {
            given = read_plan(e.plan, sources, sink);
        } else {
            auto r = plan::find_plan(*l->problem, small_search());
            if (r.plan) {
                given = *r.plan;
            }
        }
        ASSERT_TRUE(given.has_value());
        auto ipc = pddl::to_exported_plan(*ex, *given);
        ASSERT_TRUE(ipc.has_value()) << ipc.error();
        auto v = pddl::validate_ipc_plan(*im, *ipc);
        EXPECT_TRUE(v.valid) << v.reason << "\n" << pddl::write_ipc_plan(*ipc) << ex->domain;

        // A plan catplan finds on the export, carried back: valid on the problem exported.
        auto found = plan::find_plan(*im->problem, small_search());
        ASSERT_TRUE(found.plan.has_value());
        auto found_ipc = pddl::to_ipc_plan(*im, *found.plan);
        ASSERT_TRUE(found_ipc.has_value());
        auto back = pddl::from_exported_plan(*ex, *found_ipc);
        ASSERT_TRUE(back.has_value()) << back.error();
        auto replayed = pddl::replay_exported(*ex, *back);
        EXPECT_TRUE(replayed.has_value()) << (replayed ? "" : replayed.error()) << "\n"
                                          << back->to_string();
    }
}

TEST(PddlExport, APatternGoalIsReachedByAnActionNotByNamingObjects) {
    // "Some room is lit" (tests/pddl/lights.cp) takes one step, not the two that lighting the
    // kitchen takes.
    auto l = load_example(kExamples[4]);
    ASSERT_TRUE(l != nullptr);
    auto ex = pddl::export_pddl(*l->problem->domain, l->problem.get());
    ASSERT_TRUE(ex.has_value()) << ex.error();
    EXPECT_EQ(ex->goal_action, "reach-goal");
    EXPECT_NE(ex->problem.find("(:goal (goal-reached))"), std::string::npos) << ex->problem;
    EXPECT_NE(ex->domain.find(":precondition (and (isLit ?kitchen) (not (goal-reached)))"),
              std::string::npos)
        << ex->domain;
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto im = read_back(*ex, sources, sink);
    ASSERT_TRUE(im.has_value()) << sink.render();
    auto found = plan::find_plan(*im->problem, small_search());
    ASSERT_TRUE(found.plan.has_value());
    auto ipc = pddl::to_ipc_plan(*im, *found.plan);
    ASSERT_TRUE(ipc.has_value());
    ASSERT_EQ(ipc->size(), 2u) << pddl::write_ipc_plan(*ipc); // switch_on, then reach-goal
    EXPECT_EQ((*ipc)[0].action, "switch_on");
    EXPECT_EQ((*ipc)[1].action, "reach-goal");
    auto back = pddl::from_exported_plan(*ex, *ipc);
    ASSERT_TRUE(back.has_value()) << back.error();
    EXPECT_EQ(back->to_string(), "switch_on(r1, hall)\n");
    // reach-goal before the end is refused: the goal must hold at the end of the plan.
    pddl::IpcPlan early{(*ipc)[1], (*ipc)[0]};
    EXPECT_FALSE(pddl::from_exported_plan(*ex, early).has_value());
}

TEST(PddlExport, TheCaseStudyTargetHasOneThingPerBlockAndTheMarkerAsFacts) {
    auto l = load_example(kExamples[6]);
    ASSERT_TRUE(l != nullptr);
    auto ex = pddl::export_pddl(*l->problem->domain, l->problem.get());
    ASSERT_TRUE(ex.has_value()) << ex.error();
    // BreadSliced has two is-a homs: one type and unary predicates.
    EXPECT_NE(ex->domain.find("(:types Object_or_Receptacle - object)"), std::string::npos);
    EXPECT_NE(ex->problem.find("(is_BreadSliced E)"), std::string::npos);
    // The knife block's Receptacle part is a thing of its own (no is-a hom joins it to F).
    EXPECT_NE(ex->problem.find("F_Receptacle - Object_or_Receptacle"), std::string::npos);
    EXPECT_NE(ex->problem.find("(Gripper_isHolding_marker)"), std::string::npos);
    // The transferred plan names each block once per target object.
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto plan =
        plan::parse_plan(sources.add_buffer("p", "unstack(E, D)\nputdown(E)"), sources, sink);
    ASSERT_TRUE(plan.has_value());
    auto r = pddl::replay_exported(*ex, *plan);
    ASSERT_FALSE(r.has_value()); // the goal is not reached after two steps
    EXPECT_NE(r.error().find("goal not reached"), std::string::npos) << r.error();
}

/// The export of problem P of a language text, or its error.
std::string export_error(const std::string& text) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto m = lang::load_source("t.cp", text, sources, sink);
    EXPECT_FALSE(sink.has_errors()) << sink.render();
    const auto* p = m.find("P");
    if (p == nullptr || p->problem == nullptr) {
        return "no problem P";
    }
    auto ex = pddl::export_pddl(*p->problem->domain, p->problem.get());
    return ex ? "exported" : ex.error();
}

const char* kSchema = R"(
@present S(FreeSchema) begin
  (Block, Hand, On)::Ob
  holds::Hom(Hand, Block)
  (on_l, on_r)::Hom(On, Block)
  Clear::AttrType(Bool)
  isClear::Attr(Block, Clear)
end
)";

TEST(PddlExport, WhatCannotBeExpressedIsRefusedWithTheReason) {
    // A rule that deletes a block that facts with other arguments may refer to: STRIPS cannot ask
    // that no (On x marker) holds.
    std::string rules = R"(
@domain D(S) begin
  @rule drop(h, base) begin
    Pre => begin
      h::Hand
      (b, base)::Block
      holds(h) == b
    end
    Keep => begin
      h::Hand
      base::Block
    end
    Eff => begin
      h::Hand
      (c, base)::Block
      holds(h) == c
      o::On
      on_l(o) == c; on_r(o) == base
    end
  end
end
)";
    std::string problem = R"(
@acset_colim I(S) begin
  h::Hand
  (A, B)::Block
  isClear(A) == true
  holds(h) == B
end
@acset_colim G(S) begin
  x::Block
  isClear(x) == true
end
@problem P(D) begin
  initial = I
  goal = G
end
)";
    EXPECT_EQ(export_error(kSchema + rules + problem),
              "not expressible: drop deletes the Block marker, which facts (On_on_l_marker ...) "
              "may refer to; STRIPS cannot ask that none does");
    // Read as false, B's unknown isClear would be false in PDDL's closed world.
    std::string negative = problem;
    negative.replace(negative.find("isClear(x) == true"), 18, "isClear(x) == false");
    std::string keep = R"(
@domain D(S) begin
  @rule wait(b) begin
    Pre => begin
      b::Block
    end
    Keep => begin
      b::Block
    end
    Eff => begin
      b::Block
    end
  end
end
)";
    std::string named = negative;
    named.replace(named.find("(A, B)::Block"), 13, "(A, B)::Block; isClear(B) == true");
    EXPECT_EQ(export_error(kSchema + keep + named), "exported");
    EXPECT_EQ(export_error(kSchema + keep + negative),
              "not expressible: isClear(B) is unknown in the initial state, and PDDL would read "
              "it as false");
}

} // namespace
} // namespace catplan::cli
