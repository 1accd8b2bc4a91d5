#pragma once
// Programmer errors: a broken invariant or a misused API. Always on, in every build, because the
// cost is negligible next to the search and a silent corruption of a state is far worse.

#include <cstdio>
#include <cstdlib>

namespace catplan::detail {

/// Prints the failed condition with its location and aborts; never returns.
[[noreturn]] inline void assertion_failed(const char* cond, const char* msg, const char* file,
                                          int line) {
    std::fprintf(stderr, "%s:%d: internal error: assertion '%s' failed: %s\n", file, line, cond,
                 msg);
    std::abort();
}

} // namespace catplan::detail

#define CATPLAN_ASSERT(cond, msg)                                                                  \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            ::catplan::detail::assertion_failed(#cond, msg, __FILE__, __LINE__);                   \
        }                                                                                          \
    } while (false)

#define CATPLAN_UNREACHABLE(msg)                                                                   \
    ::catplan::detail::assertion_failed("unreachable", msg, __FILE__, __LINE__)
