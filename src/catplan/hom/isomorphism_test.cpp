#include "catplan/hom/detail/test_instances.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace catplan::hom {
namespace {

using namespace catplan::hom::testing;
using schema::ValueKind;

SchemaPtr coloured_schema() {
    static SchemaPtr s = [] {
        auto g = std::make_shared<Schema>("ColouredGraph");
        ObId v = g->add_ob("V"), e = g->add_ob("E");
        g->add_hom("src", e, v);
        g->add_hom("tgt", e, v);
        AttrTypeId c = g->add_attr_type("Colour", ValueKind::String);
        g->add_attr("colour", v, c);
        return SchemaPtr(g);
    }();
    return s;
}

constexpr AttrTypeId kColour{0};
constexpr AttrId kColourAttr{0};

// A random coloured graph: colours from {red, blue}, variables, unset cells and hom values.
ACSet random_coloured(std::mt19937_64& rng, std::size_t max_v, std::size_t max_e) {
    ACSet a(coloured_schema());
    std::size_t nv = 1 + rng() % max_v, ne = rng() % (max_e + 1), nvars = rng() % 3;
    a.add_parts(kV, nv);
    for (std::size_t j = 0; j < nvars; ++j) {
        a.add_var(kColour);
    }
    for (Part e = 0; e < ne; ++e) {
        a.add_part(kE);
        a.set_subpart(kSrc, e, static_cast<Part>(rng() % nv));
        a.set_subpart(kTgt, e, rng() % 10 == 0 ? kNoPart : static_cast<Part>(rng() % nv));
    }
    for (Part p = 0; p < nv; ++p) {
        std::size_t r = rng() % 10;
        Value v = r < 3 ? Value::string("red") : r < 6 ? Value::string("blue") : Value();
        if (r >= 6 && r < 9 && nvars > 0) {
            v = Value::var(static_cast<std::uint32_t>(rng() % nvars));
        }
        a.set_subpart(kColourAttr, p, v);
    }
    return a;
}

// The same state with parts and variables renumbered by random permutations (and names added,
// which isomorphism ignores).
ACSet relabel(const ACSet& a, std::mt19937_64& rng) {
    auto perm = [&](std::size_t n) {
        std::vector<Part> p(n);
        std::iota(p.begin(), p.end(), 0);
        std::shuffle(p.begin(), p.end(), rng);
        return p;
    };
    auto pv = perm(a.num_parts(kV)), pe = perm(a.num_parts(kE)), pvar = perm(a.num_vars(kColour));
    ACSet b(a.schema_ptr());
    b.add_parts(kV, pv.size());
    b.add_parts(kE, pe.size());
    for (std::size_t j = 0; j < pvar.size(); ++j) {
        b.add_var(kColour);
    }
    for (Part e = 0; e < pe.size(); ++e) {
        for (HomId f : {kSrc, kTgt}) {
            Part q = a.subpart(f, e);
            b.set_subpart(f, pe[e], q == kNoPart ? kNoPart : pv[q]);
        }
    }
    for (Part p = 0; p < pv.size(); ++p) {
        Value v = a.subpart(kColourAttr, p);
        b.set_subpart(kColourAttr, pv[p], v.is_var() ? Value::var(pvar[v.var_index()]) : v);
        b.set_part_name(kV, pv[p], "v" + std::to_string(p));
    }
    return b;
}

TEST(Isomorphism, RelabelledStatesAreIsomorphicWithEqualHashes) {
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937_64 rng(seed);
        ACSet a = random_coloured(rng, 6, 8);
        ACSet b = relabel(a, rng);
        EXPECT_EQ(canonical_hash(a), canonical_hash(b));
        auto iso = find_isomorphism(a, b);
        ASSERT_TRUE(iso.has_value());
        EXPECT_TRUE(is_natural(*iso, a, b));
        EXPECT_TRUE(is_iso(*iso, a, b));
        EXPECT_TRUE(is_isomorphic(b, a));
    }
}

TEST(Isomorphism, DifferentCountsMeanNotIsomorphic) {
    ACSet probe = path_graph(2);
    std::size_t distinguished = 0;
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937_64 rng(500 + seed);
        ACSet a = random_coloured(rng, 4, 5);
        ACSet b = random_coloured(rng, 4, 5);
        // Probe with the uncoloured shape of each: a different number of edges-in-paths
        // (homs from a probe) is an isomorphism invariant.
        ACSet probe_c(coloured_schema());
        probe_c.add_parts(kV, 3);
        for (Part e = 0; e < 2; ++e) {
            probe_c.add_part(kE);
            probe_c.set_subpart(kSrc, e, e);
            probe_c.set_subpart(kTgt, e, e + 1);
        }
        auto ca = count_homomorphisms(probe_c, a).count;
        auto cb = count_homomorphisms(probe_c, b).count;
        if (ca != cb) {
            ++distinguished;
            EXPECT_FALSE(is_isomorphic(a, b));
            EXPECT_FALSE(find_isomorphism(a, b).has_value());
            EXPECT_NE(canonical_hash(a), canonical_hash(b));
        }
        if (is_isomorphic(a, b)) {
            EXPECT_EQ(canonical_hash(a), canonical_hash(b));
        }
    }
    EXPECT_GT(distinguished, 50u);
}

TEST(Isomorphism, VariablesAreAnonymousButTheirSharingMatters) {
    auto two_vertices = [](bool shared) {
        ACSet a(coloured_schema());
        a.add_parts(kV, 2);
        Value v0 = a.add_var(kColour);
        Value v1 = a.add_var(kColour);
        a.set_subpart(kColourAttr, 0, v0);
        a.set_subpart(kColourAttr, 1, shared ? v0 : v1);
        return a;
    };
    ACSet distinct = two_vertices(false), shared = two_vertices(true);
    EXPECT_NE(canonical_hash(distinct), canonical_hash(shared));
    EXPECT_FALSE(is_isomorphic(distinct, shared));

    // Swapping which variable sits where gives an isomorphic state.
    ACSet swapped(coloured_schema());
    swapped.add_parts(kV, 2);
    Value w0 = swapped.add_var(kColour, "x");
    Value w1 = swapped.add_var(kColour, "y");
    swapped.set_subpart(kColourAttr, 0, w1);
    swapped.set_subpart(kColourAttr, 1, w0);
    EXPECT_EQ(canonical_hash(distinct), canonical_hash(swapped));
    EXPECT_TRUE(is_isomorphic(distinct, swapped));

    // A variable is not a constant.
    ACSet red(coloured_schema());
    red.add_parts(kV, 2);
    red.add_var(kColour);
    red.add_var(kColour);
    red.set_subpart(kColourAttr, 0, Value::string("red"));
    red.set_subpart(kColourAttr, 1, Value::var(1));
    EXPECT_FALSE(is_isomorphic(distinct, red));
    EXPECT_NE(canonical_hash(distinct), canonical_hash(red));
}

TEST(Isomorphism, NamesAreIgnoredAndStructureIsNot) {
    ACSet a = cycle_graph(4);
    ACSet b = cycle_graph(4);
    b.set_part_name(kV, 0, "A");
    EXPECT_EQ(canonical_hash(a), canonical_hash(b));
    EXPECT_TRUE(is_isomorphic(a, b));
    // Two 2-cycles have the same degrees as one 4-cycle; refinement plus search tell them apart.
    ACSet two = make_graph(4, {{0, 1}, {1, 0}, {2, 3}, {3, 2}});
    EXPECT_FALSE(is_isomorphic(a, two));
    EXPECT_FALSE(is_isomorphic(cycle_graph(3), path_graph(3)));
    EXPECT_NE(canonical_hash(cycle_graph(3)), canonical_hash(cycle_graph(4)));
    // Unset hom values are part of the structure.
    ACSet unset = cycle_graph(4);
    unset.set_subpart(kTgt, 3, kNoPart);
    EXPECT_FALSE(is_isomorphic(a, unset));
    EXPECT_NE(canonical_hash(a), canonical_hash(unset));
}

TEST(Isomorphism, RegularGraphsNeedTheSearch) {
    // Colour refinement cannot split a vertex-transitive graph; the search still finds the iso.
    ACSet k = complete_graph(5);
    std::mt19937_64 rng(7);
    std::vector<Part> perm(5);
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<std::pair<Part, Part>> edges;
    for (Part e = 0; e < k.num_parts(kE); ++e) {
        edges.emplace_back(perm[k.subpart(kSrc, e)], perm[k.subpart(kTgt, e)]);
    }
    std::shuffle(edges.begin(), edges.end(), rng);
    ACSet k2 = make_graph(5, edges);
    auto iso = find_isomorphism(k, k2);
    ASSERT_TRUE(iso.has_value());
    EXPECT_TRUE(is_natural(*iso, k, k2));
    EXPECT_TRUE(is_iso(*iso, k, k2));
}

} // namespace
} // namespace catplan::hom
