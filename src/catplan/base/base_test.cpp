#include "catplan/base/ascii.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/keep.hpp"
#include "catplan/base/lazy.hpp"
#include "catplan/base/parallel.hpp"
#include "catplan/base/process.hpp"
#include "catplan/base/result.hpp"
#include "catplan/base/symbol.hpp"
#include "catplan/base/union_find.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace catplan {
namespace {

TEST(Ascii, LowercaseChangesOnlyCapitalLetters) {
    EXPECT_EQ(ascii_lowercase("Pick-UP b_1 (:Domain)"), "pick-up b_1 (:domain)");
    // UTF-8's bytes (É is C3 89) and the characters around A-Z in ASCII ('@', '[') are kept.
    EXPECT_EQ(ascii_lowercase("\xC3\x89t@[Z]"), "\xC3\x89t@[z]");
    EXPECT_EQ(ascii_lowercase(""), "");
    static_assert(ascii_lower('A') == 'a' && ascii_lower('Z') == 'z' && ascii_lower('a') == 'a');
}

TEST(Keep, AnObjectIsKeptOnlyWhenTheProcessEndsAfterTheCommand) {
    auto p = std::make_shared<int>(7);
    std::weak_ptr<int> w = p;
    keep_until_exit(p);
    EXPECT_NE(p, nullptr); // left to its owner
    set_process_ends_after_command(true);
    keep_until_exit(p);
    set_process_ends_after_command(false);
    EXPECT_EQ(p, nullptr);
    EXPECT_FALSE(w.expired()); // alive in the kept storage, with nothing else owning it
    EXPECT_EQ(w.use_count(), 1);
}

TEST(Process, ResidentMemoryFollowsTouchedPages) {
    std::size_t before = resident_bytes();
    ASSERT_GT(before, 0u);
    constexpr std::size_t kBytes = 64u << 20;
    auto block = std::make_unique<char[]>(kBytes);
    std::memset(block.get(), 1, kBytes);
    std::size_t after = resident_bytes();
    EXPECT_GE(after, before + kBytes / 4 * 3) << "64 MiB touched";
    EXPECT_GE(static_cast<std::size_t>(peak_rss_kib()) * 1024, after / 2);
    EXPECT_EQ(block[kBytes - 1], 1);
}

TEST(Process, DefaultMemoryLimitIsThreeQuartersOfPhysicalMemory) {
    std::size_t phys = physical_memory_bytes();
    ASSERT_GT(phys, std::size_t{1} << 26);
    EXPECT_EQ(default_memory_limit_bytes(), phys / 4 * 3);
}

TEST(Symbol, TextsStayReadableAcrossManyChunksAndThreads) {
    // Two threads intern 20,000 texts each (several chunks of the table) while reading back
    // what they interned; then every text is read again.
    auto work = [](int thread, std::vector<Symbol>& out) {
        for (int i = 0; i < 20000; ++i) {
            std::string text = "t" + std::to_string(thread) + "_" + std::to_string(i);
            out.push_back(Symbol::intern(text));
            ASSERT_EQ(out.back().str(), text);
        }
    };
    std::vector<Symbol> a, b;
    std::thread t0(work, 0, std::ref(a));
    std::thread t1(work, 1, std::ref(b));
    t0.join();
    t1.join();
    for (int i = 0; i < 20000; ++i) {
        EXPECT_EQ(a[i].str(), "t0_" + std::to_string(i));
        EXPECT_EQ(b[i].str(), "t1_" + std::to_string(i));
        EXPECT_EQ(Symbol::intern("t1_" + std::to_string(i)), b[i]);
    }
}

TEST(Parallel, EveryIndexRunsOnceOnAWorkerOfItsOwn) {
    // 1,000 pieces on three workers: each index once, each worker id below three (per_worker is
    // written without a lock: a worker id is one thread, as the callers' per-worker data needs).
    std::vector<std::atomic<int>> runs(1000);
    std::vector<int> per_worker(3, 0);
    parallel_for(runs.size(), 3, [&](std::size_t w, std::size_t i) {
        ASSERT_LT(w, 3U);
        ++runs[i];
        ++per_worker[w];
    });
    for (const auto& r : runs) {
        EXPECT_EQ(r.load(), 1);
    }
    EXPECT_EQ(per_worker[0] + per_worker[1] + per_worker[2], 1000);
}

TEST(Parallel, MoreJobsThanPiecesUsesOneWorkerPerPiece) {
    std::atomic<std::size_t> highest{0};
    parallel_for(2, 8, [&](std::size_t w, std::size_t) {
        std::size_t h = highest;
        while (w > h && !highest.compare_exchange_weak(h, w)) {
        }
    });
    EXPECT_LE(highest.load(), 1U);
    int ran = 0;
    parallel_for(0, 4, [&](std::size_t, std::size_t) { ++ran; });
    EXPECT_EQ(ran, 0);
}

TEST(Parallel, AnExceptionStopsTheWorkAndReachesTheCaller) {
    auto run = [](std::size_t jobs, std::atomic<int>& ran) {
        parallel_for(10000, jobs, [&](std::size_t, std::size_t i) {
            ++ran;
            if (i == 3) {
                throw std::runtime_error("piece 3");
            }
        });
    };
    // On one worker the pieces run in order: nothing after the one that threw.
    std::atomic<int> ran{0};
    EXPECT_THROW(run(1, ran), std::runtime_error);
    EXPECT_EQ(ran.load(), 4);
    // On two, the other worker may run ahead (how far depends on the machine), but the exception
    // still reaches the caller, once both have stopped.
    std::atomic<int> ran2{0};
    EXPECT_THROW(run(2, ran2), std::runtime_error);
    EXPECT_GE(ran2.load(), 4);
    EXPECT_GE(default_jobs(), 1U);
}

TEST(Symbol, InterningGivesEqualHandlesForEqualText) {
    EXPECT_EQ(Symbol::intern("red"), Symbol::intern("red"));
    EXPECT_NE(Symbol::intern("red"), Symbol::intern("green"));
    EXPECT_EQ(Symbol::intern("purple").str(), "purple");
    EXPECT_EQ(Symbol().str(), "");
}

TEST(UnionFind, SmallestIdRepresentsTheSet) {
    UnionFind uf(5);
    EXPECT_TRUE(uf.union_sets(3, 1));
    EXPECT_TRUE(uf.union_sets(4, 3));
    EXPECT_FALSE(uf.union_sets(1, 4));
    EXPECT_EQ(uf.find(4), 1u);
    EXPECT_EQ(uf.find(0), 0u);
}

// An owner of a lazily computed value that refers back to it, as a rule's shape does.
struct Owner {
    int id = 0;
    Lazy<const Owner*> self;
    std::atomic<int>* computed = nullptr;

    const Owner* get() const {
        return self.get([&] {
            computed->fetch_add(1);
            return this;
        });
    }
};

TEST(Lazy, EveryThreadSeesTheOneValuePublishedAndACopyComputesItsOwn) {
    std::atomic<int> computed{0};
    Owner a{1, {}, &computed};
    EXPECT_EQ(a.self.peek(), nullptr);
    std::vector<const Owner*> seen(8, nullptr);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < seen.size(); ++t) {
        threads.emplace_back([&, t] { seen[t] = a.get(); });
    }
    for (auto& t : threads) {
        t.join();
    }
    for (const Owner* p : seen) {
        EXPECT_EQ(p, &a);
    }
    ASSERT_NE(a.self.peek(), nullptr);
    EXPECT_EQ(*a.self.peek(), &a);
    int after_threads = computed.load();
    EXPECT_GE(after_threads, 1);
    EXPECT_EQ(a.get(), &a);
    EXPECT_EQ(computed.load(), after_threads) << "computed once published";

    Owner b = a; // refers to a until it computes its own
    EXPECT_EQ(b.self.peek(), nullptr);
    EXPECT_EQ(b.get(), &b);
    a = b;
    EXPECT_EQ(a.self.peek(), nullptr) << "assignment forgets the old value";
    EXPECT_EQ(a.get(), &a);
}

TEST(Result, CarriesValueOrReason) {
    Result<int> ok = 3;
    Result<int> no = fail("no match");
    ASSERT_TRUE(ok);
    EXPECT_EQ(*ok, 3);
    ASSERT_FALSE(no);
    EXPECT_EQ(no.error(), "no match");
}

TEST(Diagnostic, RendersGnuStyleWithCaretAndSortsByLocation) {
    SourceManager sm;
    auto f = sm.add_buffer("w.cp", "line one\n  x → Bad\n");
    DiagnosticSink sink(sm);
    sink.error({f, 17, 20}, "unknown object 'Bad'");
    sink.error({f, 0, 4}, "first");
    EXPECT_EQ(sink.num_errors(), 2u);
    EXPECT_EQ(sink.render(), "w.cp:1:1: error: first\n"
                             "    1 | line one\n"
                             "      | ^~~~\n"
                             "w.cp:2:7: error: unknown object 'Bad'\n"
                             "    2 |   x → Bad\n"
                             "      |       ^~~\n");
}

TEST(Diagnostic, ALongLineIsShownAsAWindowAroundTheColumn) {
    // A one-line file of a megabyte: the message shows 160 columns around the error, not the line.
    std::string line(1'000'000, 'a');
    line.replace(500'000, 3, "Bad");
    SourceManager sm;
    auto f = sm.add_buffer("big.json", line);
    DiagnosticSink sink(sm);
    sink.error({f, 500'000, 500'003}, "here");
    sink.error({f, 2, 3}, "near the start");
    sink.error({f, 999'999, 1'000'000}, "at the end");
    std::string a60(60, 'a'), a97(97, 'a'), a160(160, 'a');
    EXPECT_EQ(sink.render(), "big.json:1:3: error: near the start\n"
                             "    1 | " +
                                 a160 +
                                 "...\n"
                                 "      |   ^\n"
                                 "big.json:1:500001: error: here\n"
                                 "    1 | ..." +
                                 a60 + "Bad" + a97 +
                                 "...\n"
                                 "      | " +
                                 std::string(63, ' ') +
                                 "^~~\n"
                                 "big.json:1:1000000: error: at the end\n"
                                 "    1 | ..." +
                                 a60 + "a" +
                                 "\n"
                                 "      | " +
                                 std::string(63, ' ') + "^\n");
}

TEST(Diagnostic, WindowCountsCodePointsAndCapsTheCaretAtTheWindow) {
    std::string line;
    for (int i = 0; i < 300; ++i) {
        line += "→";
    }
    SourceManager sm;
    auto f = sm.add_buffer("u.cp", line);
    DiagnosticSink sink(sm);
    // From column 101 (byte 300) to the end: the caret stops where the window does.
    sink.error({f, 300, static_cast<std::uint32_t>(line.size())}, "long");
    std::string shown;
    for (int i = 0; i < 160; ++i) {
        shown += "→";
    }
    EXPECT_EQ(sink.render(), "u.cp:1:101: error: long\n"
                             "    1 | ..." +
                                 shown +
                                 "...\n"
                                 "      | " +
                                 std::string(63, ' ') + "^" + std::string(99, '~') + "\n");
}

} // namespace
} // namespace catplan

#include "catplan/base/output_file.hpp"

#include <filesystem>
#include <fstream>

namespace catplan {
namespace {

TEST(OutputFile, WritesWholeFileAndFailsCleanly) {
    auto dir = std::filesystem::temp_directory_path() / "catplan_output_file_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::string error;
    auto path = (dir / "out.txt").string();
    ASSERT_TRUE(write_file_atomically(path, "hello\n", error)) << error;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "hello");
    EXPECT_FALSE(write_file_atomically((dir / "missing" / "x.txt").string(), "x", error));
    EXPECT_NE(error.find("missing"), std::string::npos);
    // Only the target remains: no temporary files left behind.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace catplan
