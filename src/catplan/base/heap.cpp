#include "catplan/base/heap.hpp"

#include "catplan/base/sanitizers.hpp"

#if defined(__linux__) && defined(__GLIBC__) && !defined(CATPLAN_MALLOC_REPLACED)
#define CATPLAN_HUGE_HEAP 1
#include <array>
#include <cstddef>
#include <cstdlib>
#include <malloc.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace catplan {

#ifdef CATPLAN_HUGE_HEAP
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// Each growth of the heap reserves this much beyond the request (address space): the aligned
// range lies inside it.
constexpr int kTopPad = 8 << 20;
// Blocks below this size come from the heap (the gap below the aligned range is one block);
// larger ones are mapped on their own, so that a large block taken early (the out-of-memory
// reserve, 16 MiB and never touched) does not take the aligned range. Set, it no longer moves by
// itself as glibc's does (from 128 KiB up to the largest block freed, at most 32 MiB).
constexpr int kMmapThreshold = 4 << 20;

std::uintptr_t heap_end() {
    return reinterpret_cast<std::uintptr_t>(::sbrk(0));
}

// Where the heap's top chunk (the free end the next new blocks are cut from) starts.
std::uintptr_t top_start() {
    return heap_end() - mallinfo2().keepcost;
}

void* gap_block = nullptr; // held for the process's life, never touched

// Whether the process's address space or data segment is limited (ulimit -v, -d): the top pad
// would then take a share of the limit.
bool limited() {
    rlimit as{}, data{};
    return ::getrlimit(RLIMIT_AS, &as) != 0 || ::getrlimit(RLIMIT_DATA, &data) != 0 ||
           as.rlim_cur != RLIM_INFINITY || data.rlim_cur != RLIM_INFINITY;
}

// A block of `bytes` cut from the top chunk that starts at `top`, or null (nothing is then
// held). A free block of that size elsewhere may serve the request first: it is held while the
// request is made again.
void* cut_from_top(std::uintptr_t top, std::size_t bytes) {
    std::array<void*, 8> elsewhere{};
    std::size_t held = 0;
    void* block = nullptr;
    for (;;) {
        block = std::malloc(bytes);
        if (reinterpret_cast<std::uintptr_t>(block) == top + 16) {
            break;
        }
        if (block == nullptr || held == elsewhere.size()) {
            std::free(block);
            block = nullptr;
            break;
        }
        elsewhere[held++] = block;
    }
    for (std::size_t i = 0; i < held; ++i) {
        std::free(elsewhere[i]);
    }
    return block;
}

} // namespace

HeapRange back_heap_with_huge_pages() {
    if (gap_block != nullptr || limited() || mallopt(M_TOP_PAD, kTopPad) == 0 ||
        mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 0) {
        return {};
    }
    // Grows the heap now, by more than its top holds, so that the pad is added now (volatile:
    // an allocation freed unused may be left out by the compiler).
    if (std::size_t keep = mallinfo2().keepcost; keep < kHugePage) {
        void* volatile grown = std::malloc(keep + (64 << 10));
        std::free(grown);
    }
    std::uintptr_t top = top_start();
    HeapRange r{(top + kHugePage - 1) & ~(kHugePage - 1), heap_end() & ~(kHugePage - 1)};
    if (r.end <= r.begin || r.begin - top < 64 ||
        ::madvise(reinterpret_cast<void*>(r.begin), r.end - r.begin, MADV_HUGEPAGE) != 0) {
        return {};
    }
    // A block from the top's start to just below r.begin: the blocks after it start in r. A
    // chunk of a request of n bytes takes n plus 8, rounded up to 16, and its header is 16 bytes.
    gap_block = cut_from_top(top, r.begin - top - 32);
    return gap_block != nullptr ? r : HeapRange{};
}
#else
HeapRange back_heap_with_huge_pages() {
    return {};
}
#endif

} // namespace catplan
