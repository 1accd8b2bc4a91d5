#include "catplan/hom/detail/test_instances.hpp"
#include "catplan/hom/forced.hpp"

#include <gtest/gtest.h>

namespace catplan::hom {
namespace {

using namespace catplan::hom::testing;

// The pattern u -e-> v with u bound: e and v follow when u has one out-edge.
TEST(ForcedHomomorphism, PlacesTheOnlyEdgeOutOfABoundVertexAndWhereItGoes) {
    ACSet x = make_graph(2, {{0, 1}});
    ACSet y = make_graph(3, {{0, 1}, {1, 2}});
    HomSearchOptions opt;
    opt.monic_all = true;
    opt.bind(kV, 0, 1);
    Forced f = forced_homomorphism(x, y, opt);
    ASSERT_EQ(f.kind, Forced::Kind::One);
    EXPECT_EQ(f.morphism.components[kV.index()], (std::vector<Part>{1, 2}));
    EXPECT_EQ(f.morphism.components[kE.index()], (std::vector<Part>{1}));
}

TEST(ForcedHomomorphism, LeavesTwoCandidatesToTheSearch) {
    ACSet x = make_graph(2, {{0, 1}});
    ACSet y = make_graph(3, {{0, 1}, {0, 2}});
    HomSearchOptions opt;
    opt.bind(kV, 0, 0);
    EXPECT_EQ(forced_homomorphism(x, y, opt).kind, Forced::Kind::Undecided);
}

TEST(ForcedHomomorphism, FindsNoneWhereTheBindingsContradictEachOther) {
    ACSet x = make_graph(2, {{0, 1}});
    ACSet y = make_graph(3, {{0, 1}, {1, 2}});
    HomSearchOptions opt;
    opt.bind(kV, 0, 0).bind(kV, 1, 2); // the only edge out of 0 ends at 1
    EXPECT_EQ(forced_homomorphism(x, y, opt).kind, Forced::Kind::None);
    HomSearchOptions monic;
    monic.monic_all = true;
    monic.bind(kV, 0, 1).bind(kV, 1, 1); // two vertices, one image
    EXPECT_EQ(forced_homomorphism(x, y, monic).kind, Forced::Kind::None);
}

TEST(ForcedHomomorphism, LeavesWhatItDoesNotReadToTheSearch) {
    ACSet x = make_graph(2, {{0, 1}});
    ACSet y = make_graph(3, {{0, 1}, {1, 2}});
    HomSearchOptions unbound;
    EXPECT_EQ(forced_homomorphism(x, y, unbound).kind, Forced::Kind::Undecided);
    HomSearchOptions cand;
    cand.bind(kV, 0, 0).restrict(kV, 1, {1});
    EXPECT_EQ(forced_homomorphism(x, y, cand).kind, Forced::Kind::Undecided);
    HomSearchOptions out_of_range;
    out_of_range.bind(kV, 0, 7); // the search asserts on it
    EXPECT_EQ(forced_homomorphism(x, y, out_of_range).kind, Forced::Kind::Undecided);
    ACSet loop = make_graph(1, {{0, 0}});
    HomSearchOptions none_bound;
    none_bound.bind(kE, 0, 0); // the loop's vertex would go to both ends of 0 -> 1
    EXPECT_EQ(forced_homomorphism(loop, y, none_bound).kind, Forced::Kind::None);
}

// The bound edge's target is unset in Y, set in X: no morphism, decided when the edge is placed
// (agrees() reads every hom of a part before the part is placed, so propagation never follows
// an unset value of Y).
TEST(ForcedHomomorphism, FindsNoneWhereYLeavesAHomUnsetThatXSets) {
    ACSet x = make_graph(2, {{0, 1}});
    ACSet y = make_graph(2, {{0, 1}});
    y.set_subpart(kTgt, 0, kNoPart);
    HomSearchOptions opt;
    opt.monic_all = true;
    opt.bind(kE, 0, 0);
    opt.accept = [&](ObId ob, Part, Part codom) { return codom < y.num_parts(ob); };
    EXPECT_EQ(forced_homomorphism(x, y, opt).kind, Forced::Kind::None);
    EXPECT_TRUE(find_homomorphisms(x, y, opt).morphisms.empty());
}

// A part of an object without homs (a fact of no arguments) goes to the only part of Y left for
// it; with two left, the search decides.
TEST(ForcedHomomorphism, PlacesAPartWithoutHomsWhereOnlyOnePartIsLeft) {
    ACSet x = make_graph(2, {});
    ACSet y = make_graph(2, {});
    HomSearchOptions monic;
    monic.monic_all = true;
    monic.bind(kV, 0, 0);
    Forced f = forced_homomorphism(x, y, monic);
    ASSERT_EQ(f.kind, Forced::Kind::One);
    EXPECT_EQ(f.morphism.components[kV.index()], (std::vector<Part>{0, 1}));
    HomSearchOptions any;
    any.bind(kV, 0, 0);
    EXPECT_EQ(forced_homomorphism(x, y, any).kind, Forced::Kind::Undecided);
}

// States on schemas of different shapes are a misuse, asserted as the search asserts it.
TEST(ForcedHomomorphism, AssertsThatBothStatesShareASchema) {
    ACSet x = make_graph(1, {});
    ACSet other(std::make_shared<schema::Schema>("Empty"));
    HomSearchOptions opt;
    opt.bind(kV, 0, 0);
    EXPECT_EXIT(forced_homomorphism(x, other, opt), ::testing::ExitedWithCode(70),
                "different schemas");
}

} // namespace
} // namespace catplan::hom
