#pragma once
// Programmer errors: a broken invariant or a misused API. Always on, in every build, because the
// cost is negligible next to the search and a silent corruption of a state is far worse.
//
// A failed assertion prints one line and ends the process with exit code 70 (docs/exit-codes.md),
// not with abort()'s signal, so that scripts see a documented code. It does not unwind: the state
// is broken, and no destructor or output file should run on it. A unit test checks an assertion
// with `EXPECT_EXIT(stmt, testing::ExitedWithCode(70), "assertion 'cond' failed")`.
// The fuzz build (CATPLAN_ASSERT_ABORTS) aborts instead: libFuzzer keeps the input of a crash, not
// of an exit.

#include <cstdio>
#include <cstdlib>

namespace catplan::detail {

/// The exit code of an internal error (kInternal of the command line; docs/exit-codes.md).
inline constexpr int kInternalErrorExit = 70;

/// Prints the failed condition with its location and exits with kInternalErrorExit; never
/// returns.
[[noreturn]] inline void assertion_failed(const char* cond, const char* msg, const char* file,
                                          int line) {
    std::fflush(stdout); // what was printed so far comes before the error, as it happened
    std::fprintf(stderr,
                 "catplan: internal error: assertion '%s' failed at %s:%d: %s (please report it "
                 "with the input)\n",
                 cond, file, line, msg);
    std::fflush(stderr);
#ifdef CATPLAN_ASSERT_ABORTS
    std::abort();
#else
    std::_Exit(kInternalErrorExit);
#endif
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
