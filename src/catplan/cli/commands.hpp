#pragma once
// The command-line front end: one function per subcommand, each loading its inputs, calling the
// library, printing the result and returning an exit code from docs/exit-codes.md.

#include <functional>
#include <iosfwd>

namespace catplan::cli {

/// Exit codes (docs/exit-codes.md).
enum ExitCode : int {
    kOk = 0,          ///< success; for a question, "yes"
    kNo = 1,          ///< a well-formed question whose answer is "no" (no homomorphism)
    kBadInput = 2,    ///< bad input or usage: diagnostics on stderr, nothing written
    kUnsupported = 3, ///< valid input that uses something catplan does not support
    kLimit = 4,       ///< a node, time or memory limit stopped the work
    kInternal = 70,   ///< a bug in catplan
};

/// Runs the catplan command line and returns its exit code.
int run(int argc, char** argv, std::ostream& out, std::ostream& err);

/// Sets up the process for the command line (guard.cpp): the out-of-memory handler with its
/// reserve, std::terminate and (without AddressSanitizer) crash signals as internal errors.
void install_process_guards();

/// Runs `body` (the whole command) so that nothing escapes as a signal: std::bad_alloc becomes
/// `catplan: error: out of memory` with what the work under way had done (base/out_of_memory.hpp)
/// and kLimit; any other exception `catplan: internal error: ...` and kInternal (guard.cpp).
int run_protected(const std::function<int()>& body, std::ostream& out, std::ostream& err);

} // namespace catplan::cli
