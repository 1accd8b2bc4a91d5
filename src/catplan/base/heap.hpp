#pragma once
// The heap's layout at start-up. A short command (a transfer takes milliseconds) touches a few
// hundred KiB of fresh heap, and the first touch of each 4 KiB page is a page fault: about 14 µs
// on a virtual machine (bench/RESULTS.md), more than the command's work on that page. Backed by
// one transparent huge page, that heap takes one fault. glibc's main heap starts at an address
// that no 2 MiB page fits around, so its next allocations are moved to an aligned range that the
// kernel is asked (madvise) to back with huge pages, in either of Linux's THP modes (always,
// madvise). Memory only counts where it is touched: the aligned range and the skipped gap below it
// are address space, not resident memory, until used.

#include <cstdint>

namespace catplan {

/// An address range of the heap [begin, end).
struct HeapRange {
    std::uintptr_t begin = 0, end = 0;

    bool empty() const { return begin == end; }
};

/// Lays out glibc's main heap so that its next allocations come from a 2 MiB-aligned range marked
/// for transparent huge pages, and returns that range; an empty range where that cannot be done
/// or should not: not Linux with glibc, under a sanitizer that replaces malloc, or with the address
/// space or data segment limited (ulimit -v, -d), when nothing is changed; or refused by the
/// kernel or the allocator, when the allocator keeps the top pad and threshold it was given.
HeapRange back_heap_with_huge_pages();

} // namespace catplan
