// Rules and domains written back in the language (print_rule, print_domain) load again to the same
// rules: every PDDL domain of the tests and examples, imported, printed, loaded and printed again.

#include "catplan/lang/module.hpp"

#include <gtest/gtest.h>

#include <string>

namespace catplan::lang {
namespace {

struct Loaded {
    SourceManager sources;
    DiagnosticSink sink{sources};
    Module module;
};

std::unique_ptr<Loaded> load(const std::string& path, const std::string* text = nullptr) {
    auto out = std::make_unique<Loaded>();
    out->module = text == nullptr ? load_file(path, out->sources, out->sink)
                                  : load_source(path, *text, out->sources, out->sink);
    return out;
}

const plan::Domain* only_domain(const Module& m) {
    for (const auto& d : m.declarations()) {
        if (d.kind == DeclKind::Domain) {
            return d.domain.get();
        }
    }
    return nullptr;
}

std::vector<std::size_t> part_counts(const acset::ACSet& x) {
    std::vector<std::size_t> out;
    for (std::uint32_t o = 0; o < x.schema().num_obs(); ++o) {
        out.push_back(x.num_parts(ObId(o)));
    }
    return out;
}

// The arguments of the action a rule carries out (its parameters when it is the action itself).
std::vector<rewrite::ActionOf::Argument> action_arguments(const rewrite::Rule& r) {
    if (r.action) {
        return r.action->arguments;
    }
    std::vector<rewrite::ActionOf::Argument> out;
    for (std::size_t i = 0; i < r.parameters.size(); ++i) {
        out.push_back({static_cast<int>(i), ""});
    }
    return out;
}

void expect_same_rule(const rewrite::Rule& a, const rewrite::Rule& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.action_name(), b.action_name());
    EXPECT_EQ(action_arguments(a), action_arguments(b)) << a.name;
    ASSERT_EQ(a.parameters.size(), b.parameters.size()) << a.name;
    for (std::size_t i = 0; i < a.parameters.size(); ++i) {
        EXPECT_EQ(a.parameters[i].name, b.parameters[i].name) << a.name;
        EXPECT_EQ(a.parameters[i].ob, b.parameters[i].ob) << a.name;
    }
    EXPECT_EQ(a.relations, b.relations) << a.name;
    EXPECT_EQ(a.cost.has_value(), b.cost.has_value()) << a.name;
    if (a.cost && b.cost) {
        EXPECT_EQ(a.cost->constant, b.cost->constant) << a.name;
        EXPECT_EQ(a.cost->terms, b.cost->terms) << a.name;
    }
    EXPECT_EQ(part_counts(a.L), part_counts(b.L)) << a.name;
    EXPECT_EQ(part_counts(a.K), part_counts(b.K)) << a.name;
    EXPECT_EQ(part_counts(a.R), part_counts(b.R)) << a.name;
    ASSERT_EQ(a.conditions.size(), b.conditions.size()) << a.name;
    for (std::size_t i = 0; i < a.conditions.size(); ++i) {
        EXPECT_EQ(a.conditions[i].negative, b.conditions[i].negative) << a.name;
        EXPECT_EQ(part_counts(a.conditions[i].n_state), part_counts(b.conditions[i].n_state));
    }
    // The text names every part and cell and gives the legs by names, so equal texts are equal
    // rules up to the order of parts.
    auto ta = print_rule(a), tb = print_rule(b);
    ASSERT_TRUE(ta && tb) << a.name;
    EXPECT_EQ(*ta, *tb);
}

TEST(PrintRule, ImportedPddlDomainsLoadBackToTheSameRules) {
    const std::string root = CATPLAN_SOURCE_DIR;
    for (const char* file :
         {"tests/pddl/adl-rooms-domain.pddl", "tests/pddl/blocksworld-domain.pddl",
          "tests/pddl/dup-domain.pddl", "tests/pddl/gripper-domain.pddl",
          "tests/pddl/lift-domain.pddl", "tests/pddl/lift-flat-domain.pddl",
          "tests/pddl/logistics-domain.pddl", "tests/pddl/shelving-domain.pddl",
          "tests/pddl/shuttle-domain.pddl", "tests/pddl/stacker-domain.pddl",
          "examples/pddl/blocks/blocks3.pddl", "examples/pddl/blocks/blocks4.pddl",
          "examples/pddl/kitchen/kitchen.pddl", "examples/pddl/kitchen/colorblocks.pddl",
          "examples/pddl/warehouse/hospital.pddl", "examples/pddl/warehouse/warehouse.pddl"}) {
        SCOPED_TRACE(file);
        auto l = load(root + "/" + file);
        ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
        const plan::Domain* imported = only_domain(l->module);
        ASSERT_NE(imported, nullptr);
        plan::Domain d = *imported;
        d.name += "_domain";
        auto text = print_domain(d);
        ASSERT_TRUE(text) << text.error();
        std::string source = print_schema(*d.schema) + *text;
        auto back = load("printed.cp", &source);
        ASSERT_FALSE(back->sink.has_errors()) << back->sink.render() << source;
        const Declaration* bd = back->module.find(d.name);
        ASSERT_TRUE(bd != nullptr && bd->domain != nullptr);
        ASSERT_EQ(bd->domain->rules.size(), d.rules.size());
        for (std::size_t i = 0; i < d.rules.size(); ++i) {
            expect_same_rule(*d.rules[i], *bd->domain->rules[i]);
        }
    }
}

TEST(PrintProblem, ANegativeGoalLoadsBackAsAGoalCondition) {
    const std::string root = CATPLAN_SOURCE_DIR;
    const std::string source = "@import \"" + root +
                               "/tests/pddl/stacker-domain.pddl\"\n@import \"" + root +
                               "/tests/pddl/stacker-p01.pddl\"\n";
    auto l = load("imports.cp", &source);
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    const plan::Problem& p = *l->module.find("stacker-p01")->problem;
    ASSERT_EQ(p.goal_conditions.size(), 1u); // (not (holding))
    auto text = print_problem(p, "stacker_domain", "Initial", "Goal");
    ASSERT_TRUE(text) << text.error();
    // The problem with its states, on a domain of no rules.
    std::string printed =
        print_schema(p.goal->schema()) + "@domain stacker_domain(stacker) begin\nend\n" +
        print_instance(*p.initial, "Initial") + print_instance(*p.goal, "Goal") + *text;
    auto back = load("printed.cp", &printed);
    ASSERT_FALSE(back->sink.has_errors()) << back->sink.render() << printed;
    const plan::Problem& q = *back->module.find("stacker-p01")->problem;
    ASSERT_EQ(q.goal_conditions.size(), 1u);
    EXPECT_TRUE(q.goal_conditions[0].negative);
    EXPECT_EQ(part_counts(q.goal_conditions[0].n_state), part_counts(p.goal_conditions[0].n_state));
    EXPECT_EQ(*print_problem(q, "stacker_domain", "Initial", "Goal"),
              *print_problem(p, "stacker_domain", "Initial", "Goal"));
}

TEST(PrintRule, WhatTheLanguageCannotWriteIsRefusedWithWhy) {
    const std::string source = R"(
@present S(FreeSchema) begin
  Thing::Ob
  Size::AttrType(Int)
  size::Attr(Thing, Size)
end
@rule grow(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    size(a) == size(a) + 1
  end
end
)";
    auto l = load("test.cp", &source);
    ASSERT_FALSE(l->sink.has_errors()) << l->sink.render();
    auto text = print_rule(*l->module.find("grow")->rule);
    ASSERT_FALSE(text);
    EXPECT_EQ(text.error(), "rule 'grow' cannot be written: it computes an attribute");
}

} // namespace
} // namespace catplan::lang
