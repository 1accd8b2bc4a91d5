// The heap's layout at start-up: new blocks come from the aligned range marked for huge pages.
// Each test runs in a child process (a death test), since the layout is the process's.

#include "catplan/base/heap.hpp"
#include "catplan/base/sanitizers.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <sys/resource.h>
#include <vector>

namespace catplan {
namespace {

// The exit code of the child: 0 when new blocks land in the returned range (or, where malloc is
// replaced, when the range is empty); else which check failed.
int layout_check() {
    HeapRange r = back_heap_with_huge_pages();
    if (kMallocReplaced) {
        return r.empty() ? 0 : 1;
    }
    if (r.empty() || r.begin % (2u << 20) != 0 || r.end % (2u << 20) != 0) {
        return 2;
    }
    // Blocks freed before lie below the range; the first block cut from the top after the gap
    // starts the range.
    std::vector<std::unique_ptr<char[]>> blocks;
    std::uintptr_t at = 0;
    while (at < r.begin && blocks.size() < 64) {
        blocks.push_back(std::make_unique_for_overwrite<char[]>(std::size_t{100} << 10));
        at = reinterpret_cast<std::uintptr_t>(blocks.back().get());
    }
    if (at != r.begin) {
        return 3;
    }
    // Small blocks come from blocks freed before (below the range) or from the range: a
    // megabyte of them fits in it.
    for (int i = 0; i < 1000; ++i) {
        blocks.push_back(std::make_unique_for_overwrite<char[]>(1000));
        at = reinterpret_cast<std::uintptr_t>(blocks.back().get());
        if (at >= r.begin && at + 1000 > r.end) {
            return 4;
        }
    }
    return back_heap_with_huge_pages().empty() ? 0 : 5; // once per process
}

TEST(Heap, NewBlocksComeFromTheAlignedRangeMarkedForHugePages) {
    EXPECT_EXIT(std::exit(layout_check()), ::testing::ExitedWithCode(0), "");
}

// With a limit on the data segment (ulimit -d), however large, the heap is left as it is. (Not
// set under a sanitizer, whose shadow memory needs more than any such limit.)
int limited_check() {
    if (kMallocReplaced) {
        return back_heap_with_huge_pages().empty() ? 0 : 2;
    }
    rlimit data{};
    data.rlim_cur = data.rlim_max = rlim_t{1} << 40;
    if (::setrlimit(RLIMIT_DATA, &data) != 0) {
        return 1;
    }
    return back_heap_with_huge_pages().empty() ? 0 : 2;
}

TEST(Heap, LeftAloneUnderAMemoryLimit) {
    EXPECT_EXIT(std::exit(limited_check()), ::testing::ExitedWithCode(0), "");
}

} // namespace
} // namespace catplan
