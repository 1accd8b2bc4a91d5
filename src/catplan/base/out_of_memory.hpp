#pragma once
// Running out of memory is a limit, not a crash: the process-wide new_handler installed here turns
// the first failed allocation into std::bad_alloc after releasing a reserve kept for the purpose,
// so that what follows (unwinding, the statistics of the work under way, the message of `main`)
// can still allocate. Work that can say how far it got (a search: its statistics) keeps an
// OutOfMemoryNote alive meanwhile; the note is read when memory runs out, before the stack unwinds,
// and main prints it with the error.
//
//   install_out_of_memory_handler();                 // once, in main
//   OutOfMemoryNote note([&] { return format_stats(stats); });
//   ... search ...                                    // a failed allocation throws std::bad_alloc
//   catch (const std::bad_alloc&) { print(out_of_memory_note()); }
//
// Under AddressSanitizer the sanitizer's operator new reports a failed allocation itself and never
// calls the handler (with allocator_may_return_null=1, which catplan's main sets, malloc returns
// null instead of aborting and operator new still aborts for sizes it cannot serve).

#include <cstddef>
#include <functional>
#include <string>

namespace catplan {

/// Installs the new_handler and allocates its reserve (`reserve_bytes`, or as much of it as the
/// address space allows, halving down to 64 KiB, else none); calling it again renews the reserve.
void install_out_of_memory_handler(std::size_t reserve_bytes = std::size_t{16} << 20);

/// The new_handler itself: releases the reserve, reads the innermost note and throws
/// std::bad_alloc. Exposed for tests, which cannot exhaust memory under a sanitizer.
[[noreturn]] void handle_out_of_memory();

/// While alive, says how far the work under way got, for the report of a failed allocation. Notes
/// nest (one per thread); the innermost is read.
class OutOfMemoryNote {
public:
    explicit OutOfMemoryNote(std::function<std::string()> describe);
    ~OutOfMemoryNote();
    OutOfMemoryNote(const OutOfMemoryNote&) = delete;
    OutOfMemoryNote& operator=(const OutOfMemoryNote&) = delete;

private:
    std::function<std::string()> describe_;
    OutOfMemoryNote* outer_;
    friend void handle_out_of_memory();
};

/// What the innermost note said when memory last ran out ("" when there was none).
std::string out_of_memory_note();

} // namespace catplan
