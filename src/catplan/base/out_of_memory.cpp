#include "catplan/base/out_of_memory.hpp"

#include <memory>
#include <new>

namespace catplan {
namespace {

constexpr std::size_t kLeastReserve = std::size_t{64} << 10;

std::unique_ptr<char[]>& reserve() {
    static std::unique_ptr<char[]> r;
    return r;
}

std::string& last_note() {
    static std::string n;
    return n;
}

thread_local OutOfMemoryNote* innermost = nullptr;
thread_local bool handling = false; // a note that cannot allocate must not call it again

} // namespace

void install_out_of_memory_handler(std::size_t reserve_bytes) {
    reserve().reset(); // first, so that renewing does not hold two reserves at once
    // Not zeroed: the pages are never touched, so the reserve costs nothing at start-up. Where the
    // address space is limited below it (ulimit -v), a smaller one, or none: the process must
    // still start, and report running out of memory as it would with a reserve.
    for (std::size_t n = reserve_bytes; n >= kLeastReserve && !reserve(); n /= 2) {
        reserve().reset(new (std::nothrow) char[n]);
    }
    std::set_new_handler(&handle_out_of_memory);
}

OutOfMemoryNote::OutOfMemoryNote(std::function<std::string()> describe)
    : describe_(std::move(describe)), outer_(innermost) {
    innermost = this;
}

OutOfMemoryNote::~OutOfMemoryNote() {
    innermost = outer_;
}

std::string out_of_memory_note() {
    return last_note();
}

void handle_out_of_memory() {
    if (handling) {
        throw std::bad_alloc();
    }
    reserve().reset();
    handling = true;
    // Without the reserve the note may not be able to allocate: then it says nothing.
    std::string note;
    try {
        if (innermost != nullptr && innermost->describe_) {
            note = innermost->describe_();
        }
        last_note() = std::move(note);
    } catch (...) {
        last_note().clear();
    }
    handling = false;
    throw std::bad_alloc();
}

} // namespace catplan
