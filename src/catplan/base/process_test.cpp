// What ends the process: a failed assertion exits with the internal-error code, and a failed
// allocation becomes std::bad_alloc carrying the note of the work under way.

#include "catplan/base/assert.hpp"
#include "catplan/base/out_of_memory.hpp"
#include "catplan/base/sanitizers.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <sys/resource.h>

namespace catplan {
namespace {

TEST(Assert, FailureExitsWithTheInternalErrorCodeAndItsMessage) {
    int answer = 41;
    EXPECT_EXIT(CATPLAN_ASSERT(answer == 42, "the answer is 42"), ::testing::ExitedWithCode(70),
                "^catplan: internal error: assertion 'answer == 42' failed at .*process_test.cpp:"
                "[0-9]+: the answer is 42");
    EXPECT_EXIT(CATPLAN_UNREACHABLE("never here"), ::testing::ExitedWithCode(70), "never here");
    CATPLAN_ASSERT(answer == 41, "a true assertion does nothing");
}

TEST(OutOfMemory, HandlerThrowsBadAllocWithTheInnermostNote) {
    install_out_of_memory_handler(1 << 20);
    EXPECT_EQ(std::get_new_handler(), &handle_out_of_memory);
    {
        OutOfMemoryNote outer([] { return std::string("outer"); });
        {
            OutOfMemoryNote inner([] { return std::string("expanded 7"); });
            EXPECT_THROW(std::get_new_handler()(), std::bad_alloc);
            EXPECT_EQ(out_of_memory_note(), "expanded 7");
        }
        EXPECT_THROW(handle_out_of_memory(), std::bad_alloc);
        EXPECT_EQ(out_of_memory_note(), "outer");
    }
    EXPECT_THROW(handle_out_of_memory(), std::bad_alloc);
    EXPECT_EQ(out_of_memory_note(), ""); // no work under way
}

TEST(OutOfMemory, NoteThatCannotAllocateSaysNothing) {
    install_out_of_memory_handler(1 << 20);
    OutOfMemoryNote note([]() -> std::string { throw std::bad_alloc(); });
    EXPECT_THROW(handle_out_of_memory(), std::bad_alloc);
    EXPECT_EQ(out_of_memory_note(), "");
}

// In a child: the address space limited to what the process maps now plus 8 MiB (ulimit -v), a
// 64 MiB reserve must still install (a smaller one), and a 32 MiB allocation then throws
// std::bad_alloc. Exit 0 when both hold.
int limited_reserve_check() {
    long pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld", &pages) != 1) {
            pages = 0;
        }
        std::fclose(f);
    }
    if (pages == 0) {
        return 1;
    }
    rlimit limit{};
    limit.rlim_cur = limit.rlim_max = static_cast<rlim_t>(pages) * 4096 + (std::size_t{8} << 20);
    if (::setrlimit(RLIMIT_AS, &limit) != 0) {
        return 2;
    }
    try {
        install_out_of_memory_handler(std::size_t{64} << 20);
    } catch (...) {
        return 3;
    }
    try {
        auto big = std::make_unique_for_overwrite<char[]>(std::size_t{32} << 20);
        char* volatile kept = big.get(); // else the allocation may be left out
        return kept != nullptr ? 4 : 5;
    } catch (const std::bad_alloc&) {
        return 0;
    }
}

TEST(OutOfMemory, ReserveFitsALimitedAddressSpace) {
    if (kAddressSanitizer) {
        GTEST_SKIP() << "AddressSanitizer maps terabytes of shadow memory: no address space limit";
    }
    EXPECT_EXIT(std::exit(limited_reserve_check()), ::testing::ExitedWithCode(0), "");
}

} // namespace
} // namespace catplan
