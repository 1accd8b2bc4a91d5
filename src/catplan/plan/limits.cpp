#include "catplan/plan/limits.hpp"

#include "catplan/base/assert.hpp"

#include <algorithm>
#include <ctime>

namespace catplan::plan {

std::string_view to_string(SearchStatus status) {
    switch (status) {
    case SearchStatus::Solved:
        return "solved";
    case SearchStatus::Unsolvable:
        return "unsolvable";
    case SearchStatus::NodeLimit:
        return "node limit";
    case SearchStatus::TimeLimit:
        return "time limit";
    case SearchStatus::MemoryLimit:
        return "memory limit";
    }
    CATPLAN_UNREACHABLE("search status");
}

Budget::Budget(const Limits& limits, Clock::time_point start)
    : limits_(limits), start_(start), last_sample_(Clock::now()) {
    sample();
}

void Budget::sample() {
    resident_ = resident_bytes();
    peak_ = std::max(peak_, resident_);
}

std::optional<SearchStatus> Budget::check() {
    auto now = Clock::now();
    if (limits_.max_seconds > 0 &&
        std::chrono::duration<double>(now - start_).count() >= limits_.max_seconds) {
        return SearchStatus::TimeLimit;
    }
    if (now - last_sample_ >= std::chrono::milliseconds(1)) {
        last_sample_ = now;
        sample();
    }
    if (limits_.max_bytes > 0 && resident_ >= limits_.max_bytes) {
        return SearchStatus::MemoryLimit;
    }
    return std::nullopt;
}

double Budget::cpu_seconds() {
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

bool Budget::would_exceed(std::size_t bytes) {
    last_sample_ = Clock::now();
    sample();
    return limits_.max_bytes > 0 && resident_ + bytes >= limits_.max_bytes;
}

} // namespace catplan::plan
