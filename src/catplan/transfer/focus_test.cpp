#include "catplan/rewrite/rule.hpp"
#include "catplan/transfer/focus.hpp"
#include "catplan/transfer/repair_memo.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using schema::Schema;

// Blocks (named) and the facts On(top, below) and Clear(block): what PDDL's blocks worlds become.
struct Blocks {
    std::shared_ptr<Schema> schema = std::make_shared<Schema>("Blocks");
    ObId block = schema->add_ob("Block"), on = schema->add_ob("On"),
         clear = schema->add_ob("Clear");
    HomId top = schema->add_hom("top", on, block), below = schema->add_hom("below", on, block),
          clear_of = schema->add_hom("clear_of", clear, block);
    schema::SchemaPtr s = schema;

    // Blocks A.. (n of them), towers bottom to top by index, the top of each clear.
    ACSet state(int n, const std::vector<std::vector<int>>& towers) const {
        ACSet x(s);
        for (int i = 0; i < n; ++i) {
            x.add_part(block, std::string(1, static_cast<char>('A' + i)));
        }
        for (const auto& t : towers) {
            for (std::size_t i = 1; i < t.size(); ++i) {
                add_on(x, t[i], t[i - 1]);
            }
            Part c = x.add_part(clear, "clear" + std::to_string(t.back()));
            x.set_subpart(clear_of, c, static_cast<Part>(t.back()));
        }
        return x;
    }

    void add_on(ACSet& x, int top_block, int below_block) const {
        Part o = x.add_part(on, "on" + std::to_string(x.num_parts(on)));
        x.set_subpart(top, o, static_cast<Part>(top_block));
        x.set_subpart(below, o, static_cast<Part>(below_block));
    }
};

std::vector<std::string> block_names(const ACSet& x, ObId block) {
    std::vector<std::string> out;
    for (Part p = 0; p < x.num_parts(block); ++p) {
        out.emplace_back(x.part_name(block, p));
    }
    return out;
}

TEST(Focus, KeepsThePartsNearWhatTheSubgoalChanges) {
    Blocks b;
    // A on B on C, D on E, F alone; the subgoal moves A from B onto D (the facts are named
    // otherwise than in y: a fact is found by its arguments).
    NamedState y(b.state(6, {{2, 1, 0}, {4, 3}, {5}}));
    ACSet goal = b.state(6, {{2, 1}, {4, 3, 0}, {5}});
    ASSERT_FALSE(embeds_by_names(y, goal));
    auto f = Focus::of(y, goal);
    ASSERT_TRUE(f) << f.error();
    // On(A, D) is missing (A, D), Clear(B) is missing (B).
    EXPECT_EQ(f->seeds(), 3u);
    auto p1 = f->problem(1);
    EXPECT_FALSE(p1.whole);
    // Radius 1 adds C (On(B, C)) and E (On(D, E)); F is nowhere near.
    EXPECT_EQ(block_names(p1.initial, b.block),
              (std::vector<std::string>{"A", "B", "C", "D", "E"}));
    EXPECT_EQ(p1.parts, 5u);
    EXPECT_EQ(p1.initial.num_parts(b.on), 3u);    // On(A, B), On(B, C), On(D, E)
    EXPECT_EQ(p1.initial.num_parts(b.clear), 2u); // Clear(A), Clear(D); Clear(F) is not kept
    EXPECT_EQ(p1.goal.num_parts(b.on), 3u);       // On(B, C), On(D, E), On(A, D)
    EXPECT_EQ(p1.goal.num_parts(b.clear), 2u);    // Clear(B), Clear(A)
    // Every hom of the focused states lands in the focus.
    for (const ACSet* x : {&p1.initial, &p1.goal}) {
        for (Part o = 0; o < x->num_parts(b.on); ++o) {
            EXPECT_NE(x->subpart(b.top, o), kNoPart);
            EXPECT_NE(x->subpart(b.below, o), kNoPart);
        }
    }
    // Radius 0 is the seeds alone, and a radius that reaches F is the whole state.
    EXPECT_EQ(f->problem(0).parts, 3u);
    ACSet far = b.state(6, {{2, 1, 0}, {4, 3}, {5}});
    b.add_on(far, 5, 4); // F on E: F is now near D
    NamedState y2(far);
    ACSet goal2 = b.state(6, {{2, 1}, {4, 3, 0}});
    b.add_on(goal2, 5, 4);
    auto f2 = Focus::of(y2, goal2);
    ASSERT_TRUE(f2) << f2.error();
    EXPECT_TRUE(f2->problem(4).whole);
}

TEST(Focus, ComparesByNamesAndSaysWhenItCannot) {
    Blocks b;
    NamedState y(b.state(3, {{0, 1}, {2}}));
    // The same state, its facts named otherwise: it holds by names, and nothing differs.
    ACSet same = b.state(3, {{0, 1}, {2}});
    for (Part o = 0; o < same.num_parts(b.on); ++o) {
        same.set_part_name(b.on, o, "other" + std::to_string(o));
    }
    EXPECT_TRUE(embeds_by_names(y, same));
    auto f = Focus::of(y, same);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->seeds(), 0u);
    // Less than y holds too (an embedding, not an isomorphism).
    ACSet less = b.state(3, {{2}});
    EXPECT_TRUE(embeds_by_names(y, less));
    // Two equal facts cannot go to y's one: not monic.
    ACSet twice = b.state(3, {{0, 1}, {2}});
    b.add_on(twice, 1, 0);
    EXPECT_FALSE(embeds_by_names(y, twice));
    // A block y has no namesake for cannot be compared.
    ACSet stranger = b.state(4, {{0, 1}, {2}, {3}});
    EXPECT_FALSE(embeds_by_names(y, stranger));
    auto g = Focus::of(y, stranger);
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error(), "the subgoal's Block D has no namesake in the target state");
}

// A fact of no arguments (a blocks world's HandEmpty) that y lacks differs though it seeds no
// part.
TEST(Focus, AMissingFactOfNoArgumentsDiffers) {
    Blocks b;
    ObId hand_empty = b.schema->add_ob("HandEmpty");
    NamedState y(b.state(2, {{0}, {1}}));
    ACSet goal = b.state(2, {{0}, {1}});
    goal.add_part(hand_empty, "handempty");
    EXPECT_FALSE(embeds_by_names(y, goal));
    ACSet held = y.state();
    held.add_part(hand_empty, "handempty");
    EXPECT_TRUE(embeds_by_names(NamedState(held), goal));
}

TEST(Focus, NamesOutOfOrderOrSharedAreLookedUp) {
    Blocks b;
    NamedState y(b.state(3, {{0, 1}, {2}})); // B on A; C
    // A subgoal without A: its blocks are not Y's first blocks, so each is looked up by name.
    ACSet g(b.s);
    g.add_part(b.block, "B");
    g.add_part(b.block, "C");
    b.add_on(g, 0, 1);
    auto f = Focus::of(y, g);
    ASSERT_TRUE(f) << f.error();
    EXPECT_EQ(f->seeds(), 2u); // B and C, the arguments of on(B, C), which Y lacks
    // The same move in a subgoal that lists Y's blocks in Y's order: A is clear there too.
    auto in_order = Focus::of(y, b.state(3, {{0}, {2, 1}}));
    ASSERT_TRUE(in_order) << in_order.error();
    EXPECT_EQ(in_order->seeds(), 3u);
    // A name two blocks of Y share has no namesake, though the subgoal lists the names in order.
    ACSet twice = b.state(3, {{0, 1}, {2}});
    twice.set_part_name(b.block, 2, "A");
    NamedState z(twice);
    auto shared = Focus::of(z, twice);
    ASSERT_FALSE(shared);
    EXPECT_NE(shared.error().find("has no namesake"), std::string::npos) << shared.error();
}

TEST(RepairMemo, ProblemsEqualUpToNamesShareAPlanRenamed) {
    Blocks b;
    // B on A, goal B on C; and, renamed by A->D, B->C, C->A, D->B: C on D, goal C on A.
    ACSet i1 = b.state(4, {{0, 1}, {2}, {3}}), g1 = b.state(4, {{0}, {2, 1}, {3}});
    ACSet i2 = b.state(4, {{3, 2}, {0}, {1}}), g2 = b.state(4, {{3}, {0, 2}, {1}});
    auto s1 = repair_shape(i1, g1), s2 = repair_shape(i2, g2);
    ASSERT_TRUE(s1 && s2);
    EXPECT_EQ(s1->key, s2->key);
    RepairMemo memo;
    EXPECT_EQ(memo.find(*s2), nullptr);
    memo.remember(*s1, {plan::Step{"move", {"B", "A", "C"}, {}}}, 4);
    const auto* e = memo.find(*s2);
    ASSERT_NE(e, nullptr);
    EXPECT_TRUE(e->solved);
    EXPECT_EQ(e->origin, 4u);
    auto renamed = RepairMemo::renamed(*e, *s2);
    ASSERT_EQ(renamed.size(), 1u);
    EXPECT_EQ(renamed[0].to_string(), "move(C, D, A)");
}

TEST(RepairMemo, OtherShapesHaveOtherKeys) {
    Blocks b;
    ACSet i1 = b.state(4, {{0, 1}, {2}, {3}}), g1 = b.state(4, {{0}, {2, 1}, {3}});
    // The same initial state, B to go on the table instead; then a tower of three.
    ACSet g2 = b.state(4, {{0}, {1}, {2}, {3}});
    ACSet i3 = b.state(4, {{0, 1, 2}, {3}}), g3 = b.state(4, {{0, 1}, {3, 2}});
    auto s1 = repair_shape(i1, g1), s2 = repair_shape(i1, g2), s3 = repair_shape(i3, g3);
    ASSERT_TRUE(s1 && s2 && s3);
    EXPECT_NE(s1->key, s2->key);
    EXPECT_NE(s1->key, s3->key);
    RepairMemo memo;
    memo.remember_failure(*s2, 1);
    ASSERT_NE(memo.find(*s2), nullptr);
    EXPECT_FALSE(memo.find(*s2)->solved);
    EXPECT_EQ(memo.find(*s1), nullptr);
    // A plan naming a block the problem does not have is not remembered.
    memo.remember(*s3, {plan::Step{"move", {"C", "Z", "D"}, {}}}, 2);
    EXPECT_EQ(memo.find(*s3), nullptr);
}

TEST(RepairMemo, TheSameChangeInAnotherFrameHasTheSameChangeShape) {
    Blocks b;
    // B from A onto C, D alone; and D from C onto A, on a tower B-C, A alone (B->D, A->C, C->A).
    ACSet i1 = b.state(4, {{0, 1}, {2}, {3}}), g1 = b.state(4, {{0}, {2, 1}, {3}});
    ACSet i2 = b.state(4, {{1, 2, 3}, {0}}), g2 = b.state(4, {{1, 2}, {0, 3}});
    auto s1 = repair_shape(i1, g1), s2 = repair_shape(i2, g2);
    ASSERT_TRUE(s1 && s2);
    EXPECT_NE(s1->key, s2->key); // the frames differ: D clear; B under C
    auto c1 = change_shape(i1, g1), c2 = change_shape(i2, g2);
    ASSERT_TRUE(c1 && c2);
    EXPECT_EQ(c1->key, c2->key);
    EXPECT_EQ(c1->names.size(), 3u); // D is frame only
    RepairMemo memo;
    memo.remember(*c1, {plan::Step{"move", {"B", "A", "C"}, {}}}, 0);
    const auto* e = memo.find(*c2);
    ASSERT_NE(e, nullptr);
    auto renamed = RepairMemo::renamed(*e, *c2);
    ASSERT_EQ(renamed.size(), 1u);
    EXPECT_EQ(renamed[0].to_string(), "move(D, C, A)");
    // B from A to the table is another change.
    auto c3 = change_shape(i1, b.state(4, {{0}, {1}, {2}, {3}}));
    ASSERT_TRUE(c3);
    EXPECT_NE(c1->key, c3->key);
}

// Random towers of blocks first..first+n-1 (seeded), bottom to top.
std::vector<std::vector<int>> random_towers(std::mt19937& rng, int first, int n) {
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        order[static_cast<std::size_t>(i)] = first + i;
    }
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::vector<int>> towers;
    for (int b : order) {
        if (towers.empty() || rng() % 3 == 0) {
            towers.emplace_back();
        }
        towers.back().push_back(b);
    }
    return towers;
}

// The same towers, the top of one moved onto another (or onto the table).
std::vector<std::vector<int>> move_one(std::mt19937& rng, std::vector<std::vector<int>> towers) {
    auto from = rng() % towers.size();
    int b = towers[from].back();
    towers[from].pop_back();
    auto to = rng() % (towers.size() + 1);
    if (to == from || to == towers.size()) {
        towers.push_back({b}); // to the table
    } else {
        towers[to].push_back(b);
    }
    std::erase_if(towers, [](const auto& t) { return t.empty(); });
    return towers;
}

// x with its blocks renamed by `name`, each part keeping its place.
ACSet renamed_blocks(const Blocks& b, ACSet x, const std::vector<std::string>& name) {
    for (Part p = 0; p < x.num_parts(b.block); ++p) {
        x.set_part_name(b.block, p, name[p]);
    }
    return x;
}

TEST(RepairMemo, ShapesOfRandomMovesAreKeptByRenamingAndChangesByAddingAFrame) {
    Blocks b;
    for (unsigned seed = 0; seed < 40; ++seed) {
        std::mt19937 rng(seed);
        int n = 2 + static_cast<int>(rng() % 5), extra = 1 + static_cast<int>(rng() % 3);
        auto towers = random_towers(rng, 0, n);
        auto moved = move_one(rng, towers);
        ACSet i = b.state(n, towers), g = b.state(n, moved);
        // Renamed, every part in its place: the same keys, and names that correspond.
        std::vector<std::string> names;
        for (int k = 0; k < n; ++k) {
            names.push_back("x" + std::to_string((k * 7 + static_cast<int>(seed)) % 97));
        }
        std::sort(names.begin(), names.end());
        names.erase(std::unique(names.begin(), names.end()), names.end());
        ASSERT_EQ(names.size(), static_cast<std::size_t>(n));
        std::shuffle(names.begin(), names.end(), rng);
        ACSet ri = renamed_blocks(b, i, names), rg = renamed_blocks(b, g, names);
        auto s = repair_shape(i, g), rs = repair_shape(ri, rg);
        auto c = change_shape(i, g), rc = change_shape(ri, rg);
        ASSERT_TRUE(s && rs && c && rc) << "seed " << seed;
        EXPECT_EQ(s->key, rs->key) << "seed " << seed;
        EXPECT_EQ(c->key, rc->key) << "seed " << seed;
        ASSERT_EQ(c->names.size(), rc->names.size());
        for (std::size_t k = 0; k < c->names.size(); ++k) {
            auto block = static_cast<std::size_t>(c->names[k][0] - 'A');
            EXPECT_EQ(rc->names[k], names[block]) << "seed " << seed;
        }
        // More blocks that stay where they are: another problem, the same change.
        auto framed = towers, framed_moved = moved;
        for (const auto& t : random_towers(rng, n, extra)) {
            framed.push_back(t);
            framed_moved.push_back(t);
        }
        ACSet fi = b.state(n + extra, framed), fg = b.state(n + extra, framed_moved);
        auto fs = repair_shape(fi, fg);
        auto fc = change_shape(fi, fg);
        ASSERT_TRUE(fs && fc);
        EXPECT_NE(fs->key, s->key) << "seed " << seed;
        EXPECT_EQ(fc->key, c->key) << "seed " << seed;
        EXPECT_EQ(fc->names, c->names) << "seed " << seed;
    }
}

// A domain whose one rule costs weight(its first parameter) + toll("Z", its first parameter).
plan::Domain weighed(const Blocks& b) {
    auto rule = std::make_shared<rewrite::Rule>(b.s);
    rule->cost = rewrite::Cost{0, {{"weight", {{0, {}}}}, {"toll", {{-1, "Z"}, {0, {}}}}}};
    plan::Domain d;
    d.rules = {rule};
    return d;
}

TEST(RepairMemo, ShapesHoldTheValuesTheStepsCanRead) {
    Blocks b;
    plan::Domain d = weighed(b);
    // B from A onto C; renamed by A->D, B->C, C->A, D->B: C from D onto A.
    ACSet i1 = b.state(4, {{0, 1}, {2}, {3}}), g1 = b.state(4, {{0}, {2, 1}, {3}});
    ACSet i2 = b.state(4, {{3, 2}, {0}, {1}}), g2 = b.state(4, {{3}, {0, 2}, {1}});
    std::vector<plan::FunctionValue> weights{{"weight", {"A"}, 1, {}},
                                             {"weight", {"B"}, 2, {}},
                                             {"weight", {"C"}, 3, {}},
                                             {"weight", {"D"}, 4, {}}};
    std::vector<plan::FunctionValue> renamed_weights{{"weight", {"D"}, 1, {}},
                                                     {"weight", {"C"}, 2, {}},
                                                     {"weight", {"A"}, 3, {}},
                                                     {"weight", {"B"}, 4, {}}};
    ValueIndex v(weights, d), rv(renamed_weights, d);
    auto key = [&](const ACSet& i, const ACSet& g, const ValueIndex& values) {
        auto shape = repair_shape(i, g, &values);
        EXPECT_TRUE(shape);
        return shape ? shape->key : std::vector<std::uint32_t>{};
    };
    // The same problem up to names, values and all.
    EXPECT_EQ(key(i1, g1, v), key(i2, g2, rv));
    // The same states with the values not renamed: C, the block that moves, weighs 3, not 2.
    EXPECT_NE(key(i1, g1, v), key(i2, g2, v));
    EXPECT_NE(key(i1, g1, v), key(i1, g1, ValueIndex({}, d)));
    // A value of a part outside the problem is one no step here reads: left out.
    auto outside = weights;
    outside.push_back({"weight", {"E"}, 9, {}});
    outside.push_back({"pair", {"A", "E"}, 9, {}});
    EXPECT_EQ(key(i1, g1, v), key(i1, g1, ValueIndex(outside, d)));
    // Z, which the cost reads by name wherever the step is, is held as itself.
    auto tolls = weights, other_tolls = renamed_weights;
    tolls.push_back({"toll", {"Z", "B"}, 5, {}});
    other_tolls.push_back({"toll", {"Z", "C"}, 5, {}});
    EXPECT_EQ(key(i1, g1, ValueIndex(tolls, d)), key(i2, g2, ValueIndex(other_tolls, d)));
    EXPECT_NE(key(i1, g1, ValueIndex(tolls, d)), key(i1, g1, v));
    auto y_tolls = other_tolls;
    y_tolls.back().args[0] = "Y"; // no cost reads Y by name, and Y is no block here
    EXPECT_NE(key(i1, g1, ValueIndex(tolls, d)), key(i2, g2, ValueIndex(y_tolls, d)));
}

TEST(RepairMemo, APartWithoutANameHasNoShape) {
    Blocks b;
    ACSet i = b.state(2, {{0, 1}});
    i.add_part(b.block);
    EXPECT_FALSE(repair_shape(i, b.state(2, {{0}, {1}})));
}

} // namespace
} // namespace catplan::transfer
