// Libraries loaded at their first use: what is found works, what is missing is a reason.

#include "catplan/base/dynamic_library.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace catplan {
namespace {

// The C library, under its Debian soname: a library every process has.
struct LibC {
    decltype(&std::strlen) strlen = nullptr;
    std::FILE** out = nullptr; // the variable `stdout`
};

void bind_libc(SymbolBinder& b, LibC& c) {
    b.function(c.strlen, "strlen");
    b.data(c.out, "stdout");
}

struct Missing {
    decltype(&std::strlen) strlen = nullptr;
    decltype(&std::strlen) nonexistent = nullptr;
};

void bind_missing(SymbolBinder& b, Missing& m) {
    b.function(m.strlen, "strlen");
    b.function(m.nonexistent, "catplan_no_such_function");
}

TEST(SymbolBinder, BindsFunctionsAndData) {
    SymbolBinder b("libc.so.6", "the C library");
    ASSERT_TRUE(b.ok()) << b.why();
    LibC c;
    bind_libc(b, c);
    EXPECT_TRUE(b.ok()) << b.why();
    ASSERT_NE(c.strlen, nullptr);
    EXPECT_EQ(c.strlen("four"), 4u);
    ASSERT_NE(c.out, nullptr);
    EXPECT_EQ(*c.out, stdout); // the stream the process writes to
}

TEST(SymbolBinder, AMissingLibraryIsAReason) {
    SymbolBinder b("libcatplan-no-such-library.so.1", "the missing library (no package)");
    EXPECT_FALSE(b.ok());
    EXPECT_NE(b.why().find("cannot load the missing library (no package): "), std::string::npos)
        << b.why();
    EXPECT_NE(b.why().find("libcatplan-no-such-library.so.1"), std::string::npos) << b.why();
    // Asking it for symbols afterwards is harmless and keeps the first reason.
    void (*f)() = nullptr;
    b.function(f, "strlen");
    EXPECT_EQ(f, nullptr);
    EXPECT_EQ(b.why().rfind("cannot load", 0), 0u) << b.why();
}

TEST(SymbolBinder, AMissingSymbolIsAReasonThatNamesIt) {
    SymbolBinder b("libc.so.6", "the C library");
    Missing m;
    bind_missing(b, m);
    EXPECT_FALSE(b.ok());
    EXPECT_EQ(b.why(), "the C library has no symbol catplan_no_such_function");
    EXPECT_NE(m.strlen, nullptr);
    EXPECT_EQ(m.nonexistent, nullptr);
}

TEST(LazyLibrary, LoadsOnceAndGivesTheSameSymbolsToEveryThread) {
    LazyLibrary<LibC> lib("libc.so.6", "the C library", bind_libc);
    std::vector<const LibC*> seen(4, nullptr);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < seen.size(); ++t) {
        threads.emplace_back([&, t] {
            std::string why;
            seen[t] = lib.load(why);
        });
    }
    for (auto& t : threads) {
        t.join();
    }
    ASSERT_NE(seen[0], nullptr);
    for (const LibC* s : seen) {
        EXPECT_EQ(s, seen[0]);
    }
    EXPECT_EQ(lib.get().strlen("abc"), 3u);
}

TEST(LazyLibrary, AMissingLibraryOrSymbolIsAReasonEveryTime) {
    LazyLibrary<LibC> absent("libcatplan-no-such-library.so.1", "libnothing", bind_libc);
    LazyLibrary<Missing> partial("libc.so.6", "the C library", bind_missing);
    for (int round = 0; round < 2; ++round) {
        std::string why;
        EXPECT_EQ(absent.load(why), nullptr);
        EXPECT_EQ(why.rfind("cannot load libnothing: ", 0), 0u) << why;
        why.clear();
        EXPECT_EQ(partial.load(why), nullptr);
        EXPECT_EQ(why, "the C library has no symbol catplan_no_such_function");
    }
}

TEST(LazyLibrary, UsingSymbolsThatDidNotLoadIsAProgrammingError) {
    LazyLibrary<LibC> absent("libcatplan-no-such-library.so.1", "libnothing", bind_libc);
    EXPECT_EXIT(absent.get(), ::testing::ExitedWithCode(70), "used before it loaded");
}

} // namespace
} // namespace catplan
