#pragma once
// What the operating system says about this process and this machine: resident memory now and at
// its peak, and the physical memory a limit can be a share of (Linux: /proc and sysconf; other
// systems report 0, "unknown").
//
// resident_bytes reads /proc/self/statm, a few microseconds: callers that watch memory in a loop
// sample it (the planner's limits read it at most once a millisecond).

#include <cstddef>

namespace catplan {

/// The process's resident memory now, in bytes (0 when unknown).
std::size_t resident_bytes();

/// The process's peak resident memory so far, in KiB (0 when unknown).
long peak_rss_kib();

/// The memory this process may use on this machine, in bytes: the physical memory, or the
/// control group's limit when that is lower (0 when unknown); read at the first call.
std::size_t physical_memory_bytes();

/// The memory limit a planner applies by default: 75% of physical_memory_bytes (0 when unknown).
std::size_t default_memory_limit_bytes();

} // namespace catplan
