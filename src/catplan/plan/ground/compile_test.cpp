#include "catplan/plan/detail/test_domains.hpp"
#include "catplan/plan/ground/compile.hpp"
#include "catplan/plan/ground/heuristics.hpp"
#include "catplan/plan/ground/mutexes.hpp"
#include "catplan/plan/ground/successors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fmt/format.h>
#include <functional>
#include <limits>
#include <set>

namespace catplan::plan::ground {
namespace {

using namespace plan::testing;

Task compiled(const ProblemPtr& p) {
    Budget budget({}, Clock::now());
    auto t = compile(p, budget);
    EXPECT_TRUE(t.has_value()) << (t ? "" : t.error());
    return t ? std::move(*t) : Task{};
}

// Visits the states of seeded random walks from the initial state: each state as a value per
// variable, with the action that led to it (kNone for the initial state); a walk ends early where
// no action applies.
void for_each_walk_state(
    const Task& t, std::uint64_t seed, int walks, int steps,
    const std::function<void(const std::vector<std::uint32_t>&, ActionId)>& visit) {
    StatePacker packer(t);
    SuccessorGenerator gen(t, packer);
    std::mt19937_64 rng(seed);
    std::vector<Word> s(packer.words()), next(packer.words());
    std::vector<std::uint32_t> values;
    std::vector<ActionId> ops;
    for (int walk = 0; walk < walks; ++walk) {
        packer.pack(t.initial, s.data());
        ActionId via = kNone;
        for (int step = 0;; ++step) {
            packer.unpack(s.data(), values);
            visit(values, via);
            gen.applicable(s.data(), ops);
            std::erase_if(ops,
                          [&](ActionId a) { return !apply(t, packer, s.data(), a, next.data()); });
            if (step == steps || ops.empty()) {
                break;
            }
            via = ops[rng() % ops.size()];
            (void)apply(t, packer, s.data(), via, next.data());
            s.swap(next);
        }
    }
}

std::vector<std::string> action_names(const Task& t) {
    std::vector<std::string> out;
    for (ActionId a = 0; a < t.actions.size(); ++a) {
        out.push_back(t.describe_action(a) + (t.actions[a].exit.empty() ? "" : " [exit]"));
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(Compile, StripsBlocksworldGroundsEveryMoveOfThreeBlocks) {
    auto p = blocks_problem(blocks_domain(true), {"A", "B", "C"}, {{0, 2}, {1}}, {{2, 1, 0}});
    Task t = compiled(p);
    // pickup and putdown of each block, stack and unstack of each ordered pair.
    EXPECT_EQ(t.actions.size(), 3u + 3u + 6u + 6u);
    for (const auto& a : t.actions) {
        EXPECT_TRUE(a.exit.empty());
        EXPECT_FALSE(a.pre.empty());
        EXPECT_FALSE(a.eff.empty());
    }
    ASSERT_EQ(t.goal.size(), 1u);
    EXPECT_EQ(t.goal[0].size(), 2u); // On(C, B), On(B, A)
    // Only atoms (the predicates) have variables: Block is an entity object.
    for (const auto& v : t.vars) {
        EXPECT_EQ(v.kind, Variable::Kind::Atom);
    }
}

// pickup(b) with a second kept block w that nothing in L or R touches: every image of w gives the
// same transition, so w is loose and grounds to one representative, unless an attribute (the
// label's variable) ties it to the state.
DomainPtr blocks_with_witness(bool labelled) {
    auto d = std::make_shared<Domain>(*blocks_domain(labelled));
    const auto& s = d->schema;
    ACSet l(s), r(s);
    Part b = add_block(l, "b", true);
    add_block(l, "w", true);
    add_fact(l, kB.clear, kB.clear_of, b, "cb");
    add_fact(l, kB.table, kB.table_of, b, "tb");
    l.add_part(kB.hand, "he");
    Part rb = add_block(r, "b", true);
    add_block(r, "w", true);
    add_fact(r, kB.holding, kB.held, rb, "h");
    d->rules = {make_rule("pickup_beside", l, r, {"b", "w"})};
    return d;
}

TEST(Compile, ALooseKeptPartGroundsToOneRepresentative) {
    auto p = blocks_problem(blocks_with_witness(false), {"A", "B", "C"}, {{0}, {1}, {2}}, {{0}});
    Task t = compiled(p);
    // One action per picked block (three are clear on the table), not one per (b, w) pair.
    ASSERT_EQ(t.actions.size(), 3u);
    for (ActionId a = 0; a < t.actions.size(); ++a) {
        EXPECT_EQ(t.actions[a].pre.size(), 3u) << t.describe_action(a); // clear, on table, hand
    }
    auto labelled =
        blocks_problem(blocks_with_witness(true), {"A", "B", "C"}, {{0}, {1}, {2}}, {{0}});
    EXPECT_EQ(compiled(labelled).actions.size(), 6u); // w's label variable is a cell it reads
}

TEST(Compile, ThePapersCaseStudyHasOneMarkerSlot) {
    auto p = paper_case_study();
    Task t = compiled(p);
    std::size_t slots = 0;
    for (const auto& o : t.objects) {
        slots += o.is_slot() ? 1 : 0;
    }
    EXPECT_EQ(slots, 1u); // the marker block
    auto names = action_names(t);
    for (const auto& n : names) {
        SCOPED_TRACE(n);
    }
    EXPECT_FALSE(names.empty());
    // putdown of the marker itself would change the marker, which the Empty part refers to.
    bool exit_seen = std::any_of(t.actions.begin(), t.actions.end(),
                                 [](const Action& a) { return !a.exit.empty(); });
    EXPECT_TRUE(exit_seen);
    EXPECT_EQ(t.goal.size(), 2u); // two purple blocks: D and E can be the top or the fourth
}

TEST(GroundHeuristics, LmCutIsAtLeastHMaxOnRandomWalks) {
    auto p = random_blocks_problem(6, 5);
    Budget budget({}, Clock::now());
    Task t = compiled(p);
    RelaxedTask r(t);
    auto hmax = make_evaluator(HeuristicKind::HMax, t, r, budget);
    auto lmcut = make_evaluator(HeuristicKind::LmCut, t, r, budget);
    int states = 0;
    for_each_walk_state(t, 5, 20, 15, [&](const std::vector<std::uint32_t>& values, ActionId) {
        int a = hmax->evaluate(0, values, nullptr, nullptr);
        int b = lmcut->evaluate(0, values, nullptr, nullptr);
        ASSERT_GE(b, a) << "state " << states;
        ++states;
    });
    EXPECT_GT(states, 100);
}

// Each index of the flat relaxation agrees with the actions' own lists: pre_of and achievers
// invert pre and add, every ground action but an exit has its relaxed action, and the goal
// actions (the case study's goal has two terms) come last and add the one goal proposition.
TEST(RelaxedTask, IndexesInvertEachActionsLists) {
    for (const auto& p : {paper_case_study(), random_blocks_problem(6, 7)}) {
        Task t = compiled(p);
        RelaxedTask r(t);
        std::size_t pres = 0, adds = 0, goal_actions = 0;
        std::vector<std::uint32_t> unconditional;
        for (std::uint32_t a = 0; a < r.num_actions(); ++a) {
            auto pre = r.pre(a);
            EXPECT_TRUE(std::is_sorted(pre.begin(), pre.end()));
            EXPECT_EQ(std::adjacent_find(pre.begin(), pre.end()), pre.end());
            EXPECT_EQ(r.num_pres()[a], pre.size());
            for (Prop q : pre) {
                auto users = r.pre_of(q);
                EXPECT_EQ(std::count(users.begin(), users.end(), a), 1);
                EXPECT_TRUE(r.needed(q));
            }
            for (Prop q : r.add(a)) {
                auto ach = r.achievers(q);
                EXPECT_TRUE(std::find(ach.begin(), ach.end(), a) != ach.end());
            }
            pres += pre.size();
            adds += r.add(a).size();
            if (pre.empty()) {
                unconditional.push_back(a);
            }
            if (r.action(a) == kNone) {
                ++goal_actions;
                EXPECT_EQ(r.cost(a), 0);
                EXPECT_EQ(std::vector<Prop>(r.add(a).begin(), r.add(a).end()), r.goal());
                continue;
            }
            EXPECT_EQ(goal_actions, 0u) << "a ground action after a goal action";
            EXPECT_EQ(r.relaxed_of(r.action(a)), a);
            for (ActionId b : r.also(a)) {
                EXPECT_EQ(r.relaxed_of(b), a);
            }
        }
        std::size_t in_pre_of = 0, in_achievers = 0;
        for (Prop q = 0; q < r.num_props(); ++q) {
            in_pre_of += r.pre_of(q).size();
            in_achievers += r.achievers(q).size();
            EXPECT_EQ(r.needed(q), r.is_goal(q) || !r.pre_of(q).empty());
        }
        EXPECT_EQ(in_pre_of, pres);
        EXPECT_EQ(in_achievers, adds);
        EXPECT_EQ(r.unconditional(), unconditional);
        EXPECT_EQ(goal_actions, t.goal.size() == 1 ? 0u : t.goal.size());
        for (ActionId a = 0; a < t.actions.size(); ++a) {
            EXPECT_EQ(r.relaxed_of(a) == kNone, !t.actions[a].exit.empty()) << t.describe_action(a);
        }
    }
}

std::set<std::set<std::string>> described_groups(const Task& t) {
    std::set<std::set<std::string>> out;
    for (const auto& g : t.mutex_groups) {
        std::set<std::string> names;
        for (VarId v : g) {
            names.insert(t.describe(v));
        }
        out.insert(names);
    }
    return out;
}

TEST(MutexGroups, BlocksworldHasTheTranslatorsGroups) {
    auto p = blocks_problem(blocks_domain(true), {"A", "B", "C"}, {{0, 2}, {1}}, {{2, 1, 0}});
    Task t = compiled(p);
    // The three kinds of invariant: where a block is (on another, on the table, held), what is
    // on a block (a block, nothing, or it is held), and the hand (empty or holding one block).
    std::set<std::set<std::string>> expected = {
        {"HandEmpty()", "Holding(A)", "Holding(B)", "Holding(C)"}};
    for (std::string x : {"A", "B", "C"}) {
        std::set<std::string> where = {"Holding(" + x + ")", "OnTable(" + x + ")"};
        std::set<std::string> top = {"Holding(" + x + ")", "Clear(" + x + ")"};
        for (std::string y : {"A", "B", "C"}) {
            if (y != x) {
                where.insert(fmt::format("On({}, {})", x, y));
                top.insert(fmt::format("On({}, {})", y, x));
            }
        }
        expected.insert(where);
        expected.insert(top);
    }
    EXPECT_EQ(described_groups(t), expected);
    // The packer's groups are disjoint and cover every On and Holding atom.
    auto packed = disjoint_groups(t.mutex_groups);
    std::set<VarId> seen;
    std::size_t atoms = 0;
    for (const auto& g : packed) {
        EXPECT_GE(g.size(), 2u);
        for (VarId v : g) {
            EXPECT_TRUE(seen.insert(v).second) << t.describe(v) << " is in two groups";
        }
        atoms += g.size();
    }
    EXPECT_GE(atoms, 6u + 3u);
}

// Replays random walks twice: on a value per variable, and packed; the groups hold in every
// state reached and the packed states unpack to the same values.
void expect_groups_hold_on_walks(const Task& t, std::uint64_t seed) {
    std::vector<std::uint32_t> plain;
    for_each_walk_state(t, seed, 30, 40, [&](const std::vector<std::uint32_t>& values, ActionId a) {
        if (a == kNone) {
            plain = t.initial;
        } else {
            for (const Fact& f : t.actions[a].eff) {
                plain[f.var] = f.value;
            }
        }
        for (const auto& g : t.mutex_groups) {
            auto present =
                std::count_if(g.begin(), g.end(), [&](VarId v) { return plain[v] == 1; });
            ASSERT_LE(present, 1) << (a == kNone ? "initially" : "after " + t.describe_action(a));
        }
        ASSERT_EQ(values, plain);
    });
}

TEST(MutexGroups, HoldOnRandomWalksAndPackedStatesMatch) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(seed);
        Task t = compiled(random_blocks_problem(6, seed));
        EXPECT_FALSE(t.mutex_groups.empty());
        expect_groups_hold_on_walks(t, seed);
    }
    Task paper = compiled(paper_case_study());
    expect_groups_hold_on_walks(paper, 7);
}

// A repair's focus is compiled without the analysis: the same actions, each variable packed alone.
TEST(MutexGroups, ATaskCompiledWithoutThemHasTheSameActionsAndPacksEachVariableAlone) {
    auto p = random_blocks_problem(6, 4);
    Budget budget({}, Clock::now());
    CompileOptions options;
    options.mutexes = false;
    auto t = compile(p, budget, options);
    ASSERT_TRUE(t.has_value()) << t.error();
    EXPECT_TRUE(t->mutex_groups.empty());
    Task with = compiled(p);
    EXPECT_FALSE(with.mutex_groups.empty());
    EXPECT_EQ(t->actions.size(), with.actions.size());
    EXPECT_EQ(t->vars.size(), with.vars.size());
    expect_groups_hold_on_walks(*t, 4);
}

TEST(MutexGroups, ThirtyBlocksPackIntoFourWords) {
    Task t = compiled(random_blocks_problem(30, 30));
    // 961 atoms: one bit each would take 16 words; 30 fields of 5 bits (31 atoms and none)
    // for the blocks' positions or tops, the rest 1 or 5 bits.
    StatePacker packer(t);
    EXPECT_LE(packer.words(), 4u);
    Task plain = t;
    plain.mutex_groups.clear();
    EXPECT_EQ(StatePacker(plain).words(), 16u);
}

constexpr int kInf = std::numeric_limits<int>::max();

// h_add or h_max by the textbook fixpoint (Bellman-Ford over the relaxed actions until nothing
// changes), without a queue and without stopping early.
int reference(const RelaxedTask& r, const std::vector<std::uint32_t>& state, bool max) {
    std::vector<int> cost(r.num_props(), kInf);
    std::vector<Prop> init;
    r.props_of(state, init);
    for (Prop p : init) {
        cost[p] = 0;
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (std::uint32_t a = 0; a < r.num_actions(); ++a) {
            int c = 0;
            for (Prop q : r.pre(a)) {
                if (cost[q] == kInf) {
                    c = kInf;
                    break;
                }
                c = max ? std::max(c, cost[q]) : c + cost[q];
            }
            if (c == kInf) {
                continue;
            }
            for (Prop q : r.add(a)) {
                if (c + r.cost(a) < cost[q]) {
                    cost[q] = c + r.cost(a);
                    changed = true;
                }
            }
        }
    }
    int h = 0;
    for (Prop g : r.goal()) {
        if (cost[g] == kInf) {
            return kDeadEnd;
        }
        h = max ? std::max(h, cost[g]) : h + cost[g];
    }
    return h;
}

// The Dijkstra of h_add and h_max stops when every goal proposition has popped; its values are
// the fixpoint's, on every state of random walks (blocks of two problems and the paper's case
// study, whose goal has two terms).
TEST(GroundHeuristics, HAddAndHMaxStopEarlyWithTheFixpointsValues) {
    std::vector<ProblemPtr> problems = {paper_case_study()};
    for (std::uint64_t seed : {11u, 12u}) {
        problems.push_back(random_blocks_problem(7, seed));
    }
    for (const auto& p : problems) {
        Budget budget({}, Clock::now());
        Task t = compiled(p);
        RelaxedTask r(t);
        auto hadd = make_evaluator(HeuristicKind::HAdd, t, r, budget);
        auto hmax = make_evaluator(HeuristicKind::HMax, t, r, budget);
        for_each_walk_state(t, 3, 10, 20, [&](const std::vector<std::uint32_t>& values, ActionId) {
            ASSERT_EQ(hadd->evaluate(0, values, nullptr, nullptr), reference(r, values, false));
            ASSERT_EQ(hmax->evaluate(0, values, nullptr, nullptr), reference(r, values, true));
        });
    }
}

} // namespace
} // namespace catplan::plan::ground
