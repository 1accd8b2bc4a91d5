#include "catplan/base/symbol.hpp"
#include "catplan/transfer/name_index.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <unordered_map>
#include <vector>

namespace catplan::transfer {
namespace {

// Every operation of a seeded random sequence (adds, changes, removals, many of them colliding
// in a small table) answers as std::unordered_map does, and so does every look-up after it,
// of the names present and of names removed.
TEST(NameIndex, AnswersAsAHashMapThroughAddsAndRemovals) {
    // Interned, as a NamedState's keys are: the views stay valid.
    std::vector<std::string_view> names;
    for (int k = 0; k < 200; ++k) {
        names.push_back(Symbol::intern("n" + std::to_string(k)).str());
    }
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937_64 rng(seed);
        NameIndex index;
        std::unordered_map<std::string_view, Part> expected;
        std::size_t removed = 0;
        for (int op = 0; op < 1000; ++op) {
            std::string_view name = names[rng() % names.size()];
            Part p = static_cast<Part>(rng() % 1000);
            if (rng() % 3 == 0) {
                removed += expected.erase(name);
                index.erase(name);
            } else {
                auto [e, fresh] = index.emplace(name, p);
                auto [it, added] = expected.emplace(name, p);
                ASSERT_EQ(fresh, added);
                ASSERT_EQ(*e, it->second);
                if (!fresh && p % 2 == 0) {
                    *e = p; // changed in place, as NamedState marks a shared name
                    it->second = p;
                }
            }
            for (std::string_view n : names) {
                auto it = expected.find(n);
                const Part* got = index.find(n);
                ASSERT_EQ(got != nullptr, it != expected.end()) << n;
                if (got != nullptr) {
                    ASSERT_EQ(*got, it->second) << n;
                }
            }
        }
        EXPECT_GT(removed, 100U);
        EXPECT_GT(expected.size(), 20U);
    }
}

TEST(NameIndex, FindsNothingForAnEmptyNameOrInAnEmptyIndex) {
    NameIndex index;
    EXPECT_EQ(index.find("a"), nullptr);
    index.emplace(Symbol::intern("a").str(), 3);
    EXPECT_EQ(index.find(""), nullptr);
    ASSERT_NE(index.find("a"), nullptr);
    EXPECT_EQ(*index.find("a"), 3U);
    NameIndex copy = index;
    index.erase("a");
    EXPECT_EQ(index.find("a"), nullptr);
    ASSERT_NE(copy.find("a"), nullptr); // a copy holds its own entries
}

} // namespace
} // namespace catplan::transfer
