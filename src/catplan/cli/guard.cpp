// The last line of defence of the command line: whatever escapes a command ends with a message on
// stderr and a documented exit code (docs/exit-codes.md), never with a signal.

#include "catplan/base/out_of_memory.hpp"
#include "catplan/base/sanitizers.hpp"
#include "catplan/cli/commands.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <ostream>
#include <unistd.h>

namespace catplan::cli {
namespace {

// The output printed so far comes before the message, as it happened; a stream that fails now
// (stdout closed) must not throw again.
void flush_quietly(std::ostream& out) {
    try {
        out.flush();
    } catch (...) {
        out.clear();
    }
}

int out_of_memory(std::ostream& out, std::ostream& err) {
    flush_quietly(out);
    std::string note;
    try {
        note = out_of_memory_note();
    } catch (const std::bad_alloc&) {
        note.clear();
    }
    err << "catplan: error: out of memory: the work was stopped (exit 4, a limit)\n";
    if (!note.empty()) {
        err << "catplan: when memory ran out: " << note << "\n";
    }
    return kLimit;
}

int internal_error(std::ostream& out, std::ostream& err, const char* what) {
    flush_quietly(out);
    err << "catplan: internal error: " << what << " (please report it with the input)\n";
    return kInternal;
}

// std::terminate (an exception through a noexcept function or out of a thread): the same one line
// and code as an exception caught by run_protected.
[[noreturn]] void on_terminate() {
    const char* what = "terminate called";
    std::string text;
    if (auto e = std::current_exception()) {
        try {
            std::rethrow_exception(e);
        } catch (const std::bad_alloc&) {
            what = "out of memory where it cannot be handled";
        } catch (const std::exception& x) {
            text = x.what();
            what = text.c_str();
        } catch (...) {
            what = "an exception that is not a std::exception";
        }
    }
    std::fflush(stdout);
    std::fprintf(stderr, "catplan: internal error: %s (please report it with the input)\n", what);
    std::_Exit(kInternal);
}

// A crash (a stack overflow among others) in a build without AddressSanitizer, which reports it
// better itself: one line and the internal-error code instead of the signal. Runs on its own stack
// (an overflowed one has no room) and calls only async-signal-safe functions.
extern "C" void on_crash(int signal) {
    const char* name = signal == SIGSEGV  ? "SIGSEGV (a stack overflow or a bad memory access)"
                       : signal == SIGBUS ? "SIGBUS"
                       : signal == SIGFPE ? "SIGFPE"
                                          : "SIGILL";
    const char* head = "catplan: internal error: crashed with ";
    const char* tail = " (please report it with the input)\n";
    static_cast<void>(::write(2, head, std::strlen(head)));
    static_cast<void>(::write(2, name, std::strlen(name)));
    static_cast<void>(::write(2, tail, std::strlen(tail)));
    ::_exit(kInternal);
}

void install_crash_handlers() {
    static char stack[64 * 1024];
    stack_t ss{};
    ss.ss_sp = stack;
    ss.ss_size = sizeof stack;
    if (::sigaltstack(&ss, nullptr) != 0) {
        return;
    }

    struct sigaction sa {};

    sa.sa_handler = on_crash;
    sa.sa_flags = SA_ONSTACK | SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) {
        ::sigaction(signal, &sa, nullptr);
    }
}

} // namespace

void install_process_guards() {
    std::set_terminate(on_terminate);
    install_out_of_memory_handler();
    if (!kAddressSanitizer) {
        install_crash_handlers();
    }
}

int run_protected(const std::function<int()>& body, std::ostream& out, std::ostream& err) {
    try {
        int code = body();
        out.flush();
        if (!out) {
            err << "catplan: error: cannot write the output to stdout\n";
            return code == kOk ? kBadInput : code;
        }
        return code;
    } catch (const std::bad_alloc&) {
        return out_of_memory(out, err);
    } catch (const std::exception& e) {
        return internal_error(out, err, e.what());
    } catch (...) {
        return internal_error(out, err, "an exception that is not a std::exception");
    }
}

} // namespace catplan::cli
