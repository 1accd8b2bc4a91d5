// What ends the process: a failed assertion exits with the internal-error code, and a failed
// allocation becomes std::bad_alloc carrying the note of the work under way.

#include "catplan/base/assert.hpp"
#include "catplan/base/out_of_memory.hpp"

#include <gtest/gtest.h>

#include <new>
#include <string>

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

} // namespace
} // namespace catplan
