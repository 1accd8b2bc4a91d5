#pragma once
// The limits of one planner run, and how the planner watches them.
//
// Every phase counts: reading the input (when the caller passes its start time), compiling the
// problem, setting up the heuristics and the search. Time is wall time since the start; memory is
// the process's resident memory (base/process.hpp), sampled at most once a millisecond, and every
// large allocation the planner makes (a hash table growing, a segment of states) is checked
// against the limit before it is made, so the process stays within the limit to a few percent.
// Nodes are expansions, counted by the search.
//
// The set-up phases have deep loops without a natural place to return a status from; they call
// Budget::poll(), which throws LimitReached, and find_plan turns it into the status. That
// exception never leaves the plan layer.

#include "catplan/base/process.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace catplan::plan {

using Clock = std::chrono::steady_clock;

enum class SearchStatus {
    Solved,
    Unsolvable, // every reachable state was expanded
    NodeLimit,
    TimeLimit,
    MemoryLimit,
};

/// "solved", "unsolvable", "node limit", "time limit", "memory limit".
std::string_view to_string(SearchStatus status);

struct Limits {
    std::uint64_t max_nodes = 0; // expansions (0 = none)
    double max_seconds = 0;      // wall seconds since the start (0 = none)
    std::size_t max_bytes = 0;   // resident bytes of the whole process (0 = none)
};

/// Thrown by Budget::poll inside the planner's set-up; caught by find_plan.
struct LimitReached {
    SearchStatus status;
};

/// Watches the time and memory limits of one run (nodes are the search's to count).
class Budget {
public:
    Budget(const Limits& limits, Clock::time_point start);

    /// The time or memory limit reached now, if any: reads the clock every call and the resident
    /// memory at most once a millisecond.
    std::optional<SearchStatus> check();

    /// check() every 64th call (for the innermost loops); throws LimitReached.
    void poll() {
        if ((++polls_ & 63) == 0) {
            if (auto s = check()) {
                throw LimitReached{*s};
            }
        }
    }

    /// Whether `bytes` more memory now would pass the memory limit (reads the resident memory).
    bool would_exceed(std::size_t bytes);

    /// CPU seconds this process has used (all its threads, since it began).
    static double cpu_seconds();

    /// Seconds since the start.
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    /// The largest resident memory seen so far (bytes).
    std::size_t peak_bytes() const { return peak_; }

    /// The resident memory at the last sample (bytes).
    std::size_t resident() const { return resident_; }

    const Limits& limits() const { return limits_; }

    Clock::time_point start() const { return start_; }

private:
    void sample();

    Limits limits_;
    Clock::time_point start_, last_sample_;
    std::size_t resident_ = 0, peak_ = 0;
    std::uint64_t polls_ = 0;
};

} // namespace catplan::plan
