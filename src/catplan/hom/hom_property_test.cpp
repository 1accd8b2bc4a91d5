// Seeded property tests: the search against a brute-force enumerator of all candidate
// morphisms, on small random states with attribute variables and unset cells.

#include "catplan/hom/detail/test_instances.hpp"
#include "catplan/hom/forced.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"
#include "catplan/hom/morphism.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace catplan::hom {
namespace {

using namespace catplan::hom::testing;
using schema::ValueKind;

// V, E, src, tgt : E -> V, Label::AttrType (Int), label : V -> Label, weight : E -> Label.
SchemaPtr schema_with_attrs() {
    static SchemaPtr s = [] {
        auto g = std::make_shared<Schema>("LabelledGraph");
        ObId v = g->add_ob("V"), e = g->add_ob("E");
        g->add_hom("src", e, v);
        g->add_hom("tgt", e, v);
        AttrTypeId l = g->add_attr_type("Label", ValueKind::Int);
        g->add_attr("label", v, l);
        g->add_attr("weight", e, l);
        return SchemaPtr(g);
    }();
    return s;
}

constexpr AttrTypeId kLabel{0};
constexpr std::size_t kSeeds = 100;

struct Gen {
    std::mt19937_64 rng;

    explicit Gen(std::uint64_t seed) : rng(seed) {}

    std::size_t below(std::size_t n) { return n == 0 ? 0 : rng() % n; }

    bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }

    // A random state; `unset` allows unset hom values and cells.
    ACSet state(std::size_t max_v, std::size_t max_e, std::size_t max_vars, bool unset) {
        ACSet a(schema_with_attrs());
        std::size_t nv = below(max_v + 1), ne = nv == 0 ? 0 : below(max_e + 1);
        std::size_t nvars = below(max_vars + 1);
        a.add_parts(kV, nv);
        a.add_parts(kE, ne);
        for (std::size_t j = 0; j < nvars; ++j) {
            a.add_var(kLabel);
        }
        for (Part e = 0; e < ne; ++e) {
            for (HomId f : {kSrc, kTgt}) {
                a.set_subpart(f, e, unset && chance(0.1) ? kNoPart : static_cast<Part>(below(nv)));
            }
        }
        auto cell = [&] {
            if (unset && chance(0.1)) {
                return Value();
            }
            if (nvars > 0 && chance(0.5)) {
                return Value::var(static_cast<std::uint32_t>(below(nvars)));
            }
            return Value::integer(static_cast<std::int64_t>(below(2)));
        };
        for (Part p = 0; p < nv; ++p) {
            a.set_subpart(AttrId(0), p, cell());
        }
        for (Part p = 0; p < ne; ++p) {
            a.set_subpart(AttrId(1), p, cell());
        }
        return a;
    }
};

// Whether some variable of x is used by no cell and not bound by the options.
bool has_floating_var(const ACSet& x, const HomSearchOptions& opt) {
    std::vector<bool> used(x.num_vars(kLabel), false);
    for (const VarBinding& b : opt.initial_vars) {
        used[b.var] = true;
    }
    for (std::uint32_t a = 0; a < 2; ++a) {
        for (const Value& v : x.column(AttrId(a))) {
            if (v.is_var()) {
                used[v.var_index()] = true;
            }
        }
    }
    return std::find(used.begin(), used.end(), false) != used.end();
}

// Counts morphisms by trying every map on parts and every variable binding (over the codomain's
// variables and the concrete values it holds; free-floating variables over variables only, as
// no_bind says), keeping those that are natural and satisfy the options.
std::uint64_t brute_force_count(const ACSet& x, const ACSet& y, const HomSearchOptions& opt) {
    std::vector<Value> values;
    for (std::uint32_t k = 0; k < y.num_vars(kLabel); ++k) {
        values.push_back(Value::var(k));
    }
    bool monic_t = opt.iso || !opt.monic_attr_types.empty();
    if (!monic_t) {
        for (std::uint32_t a = 0; a < 2; ++a) {
            for (const Value& v : y.column(AttrId(a))) {
                if (v.is_concrete() && std::find(values.begin(), values.end(), v) == values.end()) {
                    values.push_back(v);
                }
            }
        }
    }
    // A variable bound by the options may take a value the codomain does not hold.
    for (const VarBinding& b : opt.initial_vars) {
        if (std::find(values.begin(), values.end(), b.value) == values.end()) {
            values.push_back(b.value);
        }
    }
    std::size_t nvv = y.num_vars(kLabel);
    std::vector<bool> floating(x.num_vars(kLabel), true);
    for (const VarBinding& b : opt.initial_vars) {
        floating[b.var] = false;
    }
    for (std::uint32_t a = 0; a < 2; ++a) {
        for (const Value& v : x.column(AttrId(a))) {
            if (v.is_var()) {
                floating[v.var_index()] = false;
            }
        }
    }
    ACSetMorphism m;
    m.components = {std::vector<Part>(x.num_parts(kV)), std::vector<Part>(x.num_parts(kE))};
    m.var_components = {std::vector<Value>(x.num_vars(kLabel))};
    std::size_t nx_v = x.num_parts(kV), nx_e = x.num_parts(kE), nx_vars = x.num_vars(kLabel);
    std::size_t total = nx_v + nx_e + nx_vars;
    std::vector<std::size_t> digit(total, 0);
    auto radix = [&](std::size_t i) -> std::size_t {
        if (i < nx_v) {
            return y.num_parts(kV);
        }
        if (i < nx_v + nx_e) {
            return y.num_parts(kE);
        }
        return floating[i - nx_v - nx_e] ? nvv : values.size();
    };
    for (std::size_t i = 0; i < total; ++i) {
        if (radix(i) == 0) {
            return 0;
        }
    }
    std::uint64_t count = 0;
    while (true) {
        for (std::size_t i = 0; i < nx_v; ++i) {
            m.components[0][i] = static_cast<Part>(digit[i]);
        }
        for (std::size_t i = 0; i < nx_e; ++i) {
            m.components[1][i] = static_cast<Part>(digit[nx_v + i]);
        }
        for (std::size_t i = 0; i < nx_vars; ++i) {
            std::size_t d = digit[nx_v + nx_e + i];
            m.var_components[0][i] =
                floating[i] ? Value::var(static_cast<std::uint32_t>(d)) : values[d];
        }
        bool ok = is_natural(m, x, y);
        auto injective = [](const auto& c) {
            auto s = c;
            std::sort(s.begin(), s.end(), [](const auto& a, const auto& b) {
                if constexpr (std::is_same_v<std::decay_t<decltype(a)>, Value>) {
                    return a.var_index() < b.var_index();
                } else {
                    return a < b;
                }
            });
            return std::adjacent_find(s.begin(), s.end()) == s.end();
        };
        if (ok && (opt.monic_all || opt.iso)) {
            ok = injective(m.components[0]) && injective(m.components[1]);
        }
        for (ObId ob : opt.monic) {
            ok = ok && injective(m.components[ob.index()]);
        }
        if (ok && monic_t) {
            ok = injective(m.var_components[0]);
        }
        if (ok && opt.iso) {
            ok = is_iso(m, x, y);
            // Unset cells must meet unset cells.
            for (HomId f : {kSrc, kTgt}) {
                for (Part e = 0; ok && e < nx_e; ++e) {
                    if (x.subpart(f, e) == kNoPart) {
                        ok = y.subpart(f, m.components[1][e]) == kNoPart;
                    }
                }
            }
            for (std::uint32_t a = 0; a < 2; ++a) {
                ObId ob = a == 0 ? kV : kE;
                for (Part p = 0; ok && p < x.num_parts(ob); ++p) {
                    if (x.subpart(AttrId(a), p).is_unset()) {
                        ok = y.subpart(AttrId(a), m.components[ob.index()][p]).is_unset();
                    }
                }
            }
        }
        for (const PartBinding& b : opt.initial) {
            ok = ok && m.components[b.ob.index()][b.dom] == b.codom;
        }
        for (const VarBinding& b : opt.initial_vars) {
            ok = ok && m.var_components[0][b.var] == b.value;
        }
        for (const CandidateSet& c : opt.candidates) {
            ok = ok && std::find(c.allowed.begin(), c.allowed.end(),
                                 m.components[c.ob.index()][c.dom]) != c.allowed.end();
        }
        if (ok) {
            ++count;
        }
        std::size_t i = 0;
        while (i < total && ++digit[i] == radix(i)) {
            digit[i] = 0;
            ++i;
        }
        if (i == total) {
            break;
        }
    }
    return count;
}

// Returns the number of morphisms found, so callers can check that the seeds are not trivial.
std::uint64_t check_against_brute_force(const ACSet& x, const ACSet& y, HomSearchOptions opt) {
    if (has_floating_var(x, opt) && opt.monic_attr_types.empty() && !opt.iso) {
        auto err = find_homomorphisms(x, y, opt);
        EXPECT_FALSE(err.error.empty());
        EXPECT_EQ(err.count, 0u);
        opt.no_bind = {kLabel};
    }
    auto r = find_homomorphisms(x, y, opt);
    EXPECT_TRUE(r.error.empty()) << r.error;
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.count, brute_force_count(x, y, opt));
    EXPECT_EQ(r.count, r.morphisms.size());
    EXPECT_EQ(count_homomorphisms(x, y, opt).count, r.count);
    EXPECT_EQ(is_homomorphic(x, y, opt), r.count > 0);
    for (const auto& m : r.morphisms) {
        auto fails = naturality_failures(m, x, y);
        EXPECT_TRUE(fails.empty()) << (fails.empty() ? "" : describe(fails[0], x, y));
        if (opt.monic_all) {
            EXPECT_TRUE(is_monic(m, x, y));
        }
    }
    // No morphism is found twice.
    auto sorted = r.morphisms;
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
        return a.components < b.components ||
               (a.components == b.components &&
                std::lexicographical_compare(
                    a.var_components[0].begin(), a.var_components[0].end(),
                    b.var_components[0].begin(), b.var_components[0].end(),
                    [](const Value& u, const Value& v) { return u.hash() < v.hash(); }));
    });
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
    return r.count;
}

TEST(HomSearchProperty, PlainMatchesBruteForce) {
    std::size_t nonempty = 0;
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen g(seed);
        ACSet x = g.state(3, 3, 2, seed % 2 == 0);
        ACSet y = g.state(3, 3, 2, seed % 3 == 0);
        nonempty += check_against_brute_force(x, y, {}) > 0 ? 1 : 0;
    }
    EXPECT_GE(nonempty, kSeeds / 4); // the instances are not all trivially empty
}

TEST(HomSearchProperty, MonicMatchesBruteForce) {
    std::size_t nonempty = 0;
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen g(1000 + seed);
        ACSet x = g.state(3, 2, 2, seed % 2 == 0);
        ACSet y = g.state(3, 3, 2, false);
        HomSearchOptions all;
        all.monic_all = true;
        nonempty += check_against_brute_force(x, y, all) > 0 ? 1 : 0;
        HomSearchOptions v_only;
        v_only.monic = {kV};
        check_against_brute_force(x, y, v_only);
        HomSearchOptions vars;
        vars.monic_attr_types = {kLabel};
        check_against_brute_force(x, y, vars);
    }
    EXPECT_GE(nonempty, kSeeds / 10);
}

TEST(HomSearchProperty, InitialAndCandidatesMatchBruteForce) {
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen g(2000 + seed);
        ACSet x = g.state(3, 2, 2, seed % 2 == 0);
        ACSet y = g.state(3, 3, 2, false);
        if (x.num_parts(kV) == 0 || y.num_parts(kV) == 0) {
            continue;
        }
        HomSearchOptions init;
        init.bind(kV, static_cast<Part>(g.below(x.num_parts(kV))),
                  static_cast<Part>(g.below(y.num_parts(kV))));
        if (x.num_vars(kLabel) > 0) {
            init.bind_var(kLabel, 0, g.chance(0.5) ? Value::integer(1) : Value::var(0));
            if (y.num_vars(kLabel) == 0 && init.initial_vars[0].value.is_var()) {
                init.initial_vars[0].value = Value::integer(0);
            }
        }
        check_against_brute_force(x, y, init);

        HomSearchOptions cand;
        for (Part p = 0; p < x.num_parts(kV); ++p) {
            if (g.chance(0.5)) {
                std::vector<Part> allowed;
                for (Part q = 0; q < y.num_parts(kV); ++q) {
                    if (g.chance(0.6)) {
                        allowed.push_back(q);
                    }
                }
                cand.restrict(kV, p, allowed);
            }
        }
        if (x.num_parts(kE) > 0 && y.num_parts(kE) > 0) {
            cand.restrict(kE, 0, {static_cast<Part>(g.below(y.num_parts(kE)))});
        }
        check_against_brute_force(x, y, cand);
    }
}

// What forced_homomorphism decides is what the search finds: no morphism, or exactly its one.
// The bindings place most vertices, so that most instances are decided; the dangling-like
// `accept` and monic choices vary with the seed.
TEST(HomSearchProperty, ForcedMorphismsAreTheSearchsOnly) {
    std::size_t none = 0, one = 0;
    for (std::uint64_t seed = 0; seed < 4 * kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen g(5000 + seed);
        ACSet x = g.state(3, 3, 0, seed % 2 == 0);
        // Half the time Y contains X (its first parts), and the bindings mostly follow it.
        bool contains = seed % 2 == 1;
        ACSet y = contains ? x : g.state(4, 3, 2, seed % 3 == 0);
        if (contains) {
            Part v = y.add_part(kV);
            y.set_subpart(AttrId(0), v, Value::integer(0));
            for (std::size_t k = g.below(3); k > 0; --k) {
                Part e = y.add_part(kE);
                y.set_subpart(kSrc, e, static_cast<Part>(g.below(y.num_parts(kV))));
                y.set_subpart(kTgt, e, static_cast<Part>(g.below(y.num_parts(kV))));
                y.set_subpart(AttrId(1), e, Value::integer(static_cast<std::int64_t>(g.below(2))));
            }
        }
        if (x.num_parts(kV) == 0) {
            continue;
        }
        HomSearchOptions opt;
        opt.monic_all = seed % 4 != 0;
        for (Part p = 0; p < x.num_parts(kV); ++p) {
            if (g.chance(0.8)) {
                Part q =
                    contains && g.chance(0.8) ? p : static_cast<Part>(g.below(y.num_parts(kV)));
                opt.bind(kV, p, q);
            }
        }
        if (seed % 5 == 0) {
            opt.accept = [](ObId ob, Part dom, Part codom) {
                return (ob.index() + dom + 2 * codom) % 4 != 1;
            };
        }
        Forced f = forced_homomorphism(x, y, opt);
        if (f.kind == Forced::Kind::Undecided) {
            continue;
        }
        HomSearchResult all = find_homomorphisms(x, y, opt);
        ASSERT_TRUE(all.error.empty());
        if (f.kind == Forced::Kind::None) {
            EXPECT_TRUE(all.morphisms.empty());
            ++none;
        } else {
            ASSERT_EQ(all.morphisms.size(), 1U);
            EXPECT_EQ(all.morphisms[0], f.morphism);
            ++one;
        }
    }
    EXPECT_GE(none, kSeeds / 4); // both answers occur often: the comparison is not vacuous
    EXPECT_GE(one, kSeeds / 4);
}

TEST(HomSearchProperty, IsoMatchesBruteForce) {
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen g(3000 + seed);
        ACSet x = g.state(3, 2, 2, seed % 2 == 0);
        ACSet y = g.chance(0.5) ? x : g.state(3, 2, 2, seed % 2 == 0);
        HomSearchOptions iso;
        iso.iso = true;
        check_against_brute_force(x, y, iso);
        EXPECT_EQ(is_isomorphic(x, y), brute_force_count(x, y, iso) > 0);
    }
}

TEST(HomSearchProperty, CompositesOfFoundMorphismsAreNatural) {
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        SCOPED_TRACE(seed);
        Gen g(4000 + seed);
        ACSet x = g.state(3, 2, 2, true);
        ACSet y = g.state(3, 3, 2, false);
        ACSet z = g.state(3, 3, 2, false);
        HomSearchOptions nb;
        nb.no_bind = {kLabel};
        nb.max_results = 5;
        auto fs = find_homomorphisms(x, y, nb);
        auto gs = find_homomorphisms(y, z, nb);
        for (const auto& f : fs.morphisms) {
            for (const auto& h : gs.morphisms) {
                ACSetMorphism c = compose(f, h);
                auto fails = naturality_failures(c, x, z);
                EXPECT_TRUE(fails.empty()) << (fails.empty() ? "" : describe(fails[0], x, z));
            }
            EXPECT_EQ(compose(identity(x), f), f);
            EXPECT_EQ(compose(f, identity(y)), f);
        }
    }
}

} // namespace
} // namespace catplan::hom
