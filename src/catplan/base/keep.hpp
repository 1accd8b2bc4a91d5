#pragma once
// What a command is done with when the process ends right after it. Destroying a transfer's
// states, domains and plans visits every block they hold (0.07 ms of a 30-block transfer's 3.5,
// bench/RESULTS.md); the process's exit returns all its memory at once. As compilers do
// at exit, the catplan command keeps such objects instead of destroying them. Only the command's
// main says that the process ends after the command: under the tests, and in any other program
// that runs commands, everything is destroyed as usual.

#include <memory>
#include <utility>

namespace catplan {

/// Says whether the process ends when the command it runs returns (the catplan command's main).
void set_process_ends_after_command(bool ends);

/// Whether set_process_ends_after_command(true) was called.
bool process_ends_after_command();

namespace detail {
/// Holds x (owned) until the process ends, never destroyed.
void keep_forever(std::shared_ptr<void> x);
} // namespace detail

/// When the process ends after this command, moves x into storage that is never destroyed (its
/// memory goes with the process); otherwise leaves x to its owner.
template <class T>
void keep_until_exit(T& x) {
    if (process_ends_after_command()) {
        detail::keep_forever(std::make_shared<T>(std::move(x)));
    }
}

} // namespace catplan
