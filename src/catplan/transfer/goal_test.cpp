#include "catplan/transfer/goal.hpp"
#include "catplan/transfer/terms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using acset::Value;
using schema::Schema;
using schema::SchemaPtr;
using schema::ValueKind;

struct Towers {
    SchemaPtr s;
    ObId block, on;
    HomId on_l, on_r;
    AttrId color;
};

Towers towers() {
    auto s = std::make_shared<Schema>("Towers");
    Towers t;
    t.block = s->add_ob("Block");
    t.on = s->add_ob("On");
    t.on_l = s->add_hom("on_l", t.on, t.block);
    t.on_r = s->add_hom("on_r", t.on, t.block);
    t.color = s->add_attr("hasColor", t.block, s->add_attr_type("Color", ValueKind::String));
    t.s = s;
    return t;
}

// Blocks with these names and colours, and On facts (top, below) by index.
ACSet tower(const Towers& t, const std::vector<std::pair<std::string, std::string>>& blocks,
            const std::vector<std::pair<Part, Part>>& ons) {
    ACSet x(t.s);
    for (const auto& [name, color] : blocks) {
        Part p = x.add_part(t.block, name);
        x.set_subpart(t.color, p, Value::string(color));
    }
    int i = 0;
    for (auto [top, below] : ons) {
        Part o = x.add_part(t.on, "o" + std::to_string(++i));
        x.set_subpart(t.on_l, o, top);
        x.set_subpart(t.on_r, o, below);
    }
    return x;
}

TEST(Terms, AFactNoPersonNamedIsCalledByItsTuple) {
    // On has homs, no attribute, and nothing points at it: a part of it is its tuple. Named by a
    // person it keeps its statements; unnamed (or named as PDDL facts are in rules) it is on(a, b).
    Towers t = towers();
    ACSet x = tower(t, {{"a", "red"}, {"b", "green"}}, {{0, 1}});
    Part unnamed = x.add_part(t.on);
    x.set_subpart(t.on_l, unnamed, 1);
    x.set_subpart(t.on_r, unnamed, 0);
    Part fact = x.add_part(t.on, "(on x y)");
    x.set_subpart(t.on_l, fact, 0);
    x.set_subpart(t.on_r, fact, 0);
    EXPECT_EQ(part_statements(x, t.on, 0),
              (std::vector<std::string>{"On o1", "on_l(o1) == a", "on_r(o1) == b"}));
    EXPECT_EQ(part_statements(x, t.on, unnamed), (std::vector<std::string>{"On(b, a)"}));
    EXPECT_EQ(part_statements(x, t.on, fact), (std::vector<std::string>{"On(a, a)"}));
    EXPECT_EQ(part_word(x, t.on, unnamed), "On(b, a)");
    EXPECT_FALSE(is_user_name("(on x y)"));
    EXPECT_FALSE(is_user_name("clear@2"));
    // A Block has a hom pointing at it and an attribute: no tuple.
    EXPECT_FALSE(tuple_term(x, t.block, 0).has_value());
    // A tuple with a hom unset is not a whole fact.
    Part half = x.add_part(t.on);
    x.set_subpart(t.on_l, half, 0);
    EXPECT_FALSE(tuple_term(x, t.on, half).has_value());
    EXPECT_EQ(part_statements(x, t.on, half).front(), "On #4");
}

TEST(GoalSatisfaction, StatementsInWords) {
    Towers t = towers();
    ACSet g = tower(t, {{"a", "red"}, {"b", "green"}}, {{0, 1}});
    EXPECT_EQ(goal_statements(g),
              (std::vector<std::string>{"Block a", "hasColor(a) == \"red\"", "Block b",
                                        "hasColor(b) == \"green\"", "On o1", "on_l(o1) == a",
                                        "on_r(o1) == b"}));
    EXPECT_EQ(count_goal_statements(g), 7U); // the same statements, not put in words
}

TEST(GoalSatisfaction, UnnamedPartsAreNamedByATermThatReachesThem) {
    Towers t = towers();
    ACSet g(t.s);
    Part a = g.add_part(t.block, "a");
    Part below = g.add_part(t.block); // unnamed: reached as on_r(o1)
    Part o = g.add_part(t.on, "o1");
    g.set_subpart(t.on_l, o, a);
    g.set_subpart(t.on_r, o, below);
    g.set_subpart(t.color, below, Value::string("red"));
    // The term is not used for the statement that defines it, which keeps the label.
    EXPECT_EQ(goal_statements(g), (std::vector<std::string>{
                                      "Block a", "Block on_r(o1)", "hasColor(on_r(o1)) == \"red\"",
                                      "On o1", "on_l(o1) == a", "on_r(o1) == #2"}));
}

TEST(GoalSatisfaction, EmbeddedGoalIsFullySatisfied) {
    Towers t = towers();
    ACSet g = tower(t, {{"a", "red"}, {"b", "green"}}, {{0, 1}});
    ACSet x = tower(t, {{"G", "green"}, {"B", "blue"}, {"R", "red"}}, {{2, 0}, {0, 1}});
    auto sat = goal_satisfaction(g, x);
    EXPECT_EQ(sat.satisfied, 7u);
    EXPECT_EQ(sat.total, 7u);
    EXPECT_TRUE(sat.unsatisfied.empty());
    EXPECT_TRUE(sat.exact);
    EXPECT_DOUBLE_EQ(sat.fraction(), 1.0);
}

TEST(GoalSatisfaction, WrongFactListsItsStatements) {
    Towers t = towers();
    // Goal: a on b on c. State: R on G, and B on G (not G on B).
    ACSet g = tower(t, {{"a", "red"}, {"b", "green"}, {"c", "blue"}}, {{0, 1}, {1, 2}});
    ACSet x = tower(t, {{"R", "red"}, {"G", "green"}, {"B", "blue"}}, {{0, 1}, {2, 1}});
    auto sat = goal_satisfaction(g, x);
    EXPECT_EQ(sat.total, 12u);
    EXPECT_EQ(sat.satisfied, 10u);
    EXPECT_EQ(sat.unsatisfied, (std::vector<std::string>{"on_l(o2) == b", "on_r(o2) == c"}));
}

TEST(GoalSatisfaction, MissingPartsAndWrongColours) {
    Towers t = towers();
    ACSet g = tower(t, {{"a", "red"}, {"b", "red"}}, {});
    ACSet x = tower(t, {{"R", "red"}}, {});
    auto sat = goal_satisfaction(g, x);
    EXPECT_EQ(sat.total, 4u);
    EXPECT_EQ(sat.satisfied, 2u);
    EXPECT_EQ(sat.unsatisfied, (std::vector<std::string>{"Block b", "hasColor(b) == \"red\""}));
    ACSet empty(t.s);
    EXPECT_DOUBLE_EQ(goal_satisfaction(empty, x).fraction(), 1.0);
}

// The best score by brute force: every partial injective assignment.
std::size_t brute_force(const ACSet& g, const ACSet& x, const Towers& t) {
    std::size_t nb = g.num_parts(t.block), no = g.num_parts(t.on);
    std::size_t xb = x.num_parts(t.block), xo = x.num_parts(t.on);
    std::size_t best = 0;
    std::vector<Part> ab(nb), ao(no);
    auto score = [&] {
        std::size_t s = 0;
        for (std::size_t i = 0; i < nb; ++i) {
            if (ab[i] != kNoPart) {
                s += 1 + (x.subpart(t.color, ab[i]) == g.subpart(t.color, i) ? 1 : 0);
            }
        }
        for (std::size_t i = 0; i < no; ++i) {
            if (ao[i] == kNoPart) {
                continue;
            }
            ++s;
            for (HomId f : {t.on_l, t.on_r}) {
                Part want = ab[g.subpart(f, i)];
                s += want != kNoPart && x.subpart(f, ao[i]) == want ? 1 : 0;
            }
        }
        return s;
    };
    auto injective = [](const std::vector<Part>& a) {
        for (std::size_t i = 0; i < a.size(); ++i) {
            for (std::size_t j = i + 1; j < a.size(); ++j) {
                if (a[i] != kNoPart && a[i] == a[j]) {
                    return false;
                }
            }
        }
        return true;
    };
    // Odometer over (xb + 1)^nb * (xo + 1)^no assignments; value xb / xo means unassigned.
    std::vector<std::size_t> digit(nb + no, 0);
    while (true) {
        for (std::size_t i = 0; i < nb; ++i) {
            ab[i] = digit[i] == xb ? kNoPart : static_cast<Part>(digit[i]);
        }
        for (std::size_t i = 0; i < no; ++i) {
            ao[i] = digit[nb + i] == xo ? kNoPart : static_cast<Part>(digit[nb + i]);
        }
        if (injective(ab) && injective(ao)) {
            best = std::max(best, score());
        }
        std::size_t k = 0;
        for (; k < digit.size(); ++k) {
            std::size_t base = (k < nb ? xb : xo) + 1;
            if (++digit[k] < base) {
                break;
            }
            digit[k] = 0;
        }
        if (k == digit.size()) {
            return best;
        }
    }
}

ACSet random_tower_state(const Towers& t, std::mt19937& rng, std::size_t blocks, std::size_t ons) {
    const char* colors[] = {"red", "green", "blue"};
    std::vector<std::pair<std::string, std::string>> bs;
    for (std::size_t i = 0; i < blocks; ++i) {
        bs.emplace_back("b" + std::to_string(i), colors[rng() % 3]);
    }
    std::vector<std::pair<Part, Part>> os;
    for (std::size_t i = 0; blocks > 0 && i < ons; ++i) {
        os.emplace_back(static_cast<Part>(rng() % blocks), static_cast<Part>(rng() % blocks));
    }
    return tower(t, bs, os);
}

TEST(GoalSatisfaction, MatchesBruteForceOnRandomInstances) {
    Towers t = towers();
    std::mt19937 rng(20261123);
    for (int round = 0; round < 60; ++round) {
        ACSet g = random_tower_state(t, rng, 1 + rng() % 3, rng() % 3);
        ACSet x = random_tower_state(t, rng, rng() % 4, rng() % 3);
        auto sat = goal_satisfaction(g, x, 0);
        EXPECT_EQ(sat.satisfied, brute_force(g, x, t)) << "round " << round;
        EXPECT_EQ(sat.unsatisfied.size(), sat.total - sat.satisfied);
        EXPECT_TRUE(sat.exact);
    }
}

} // namespace
} // namespace catplan::transfer
