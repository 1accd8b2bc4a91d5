#pragma once
// Independent pieces of work spread over threads: a worker takes the next index until none is
// left, so slow pieces do not hold up the others. Each worker keeps its own data (a loaded copy of
// the inputs): catplan's values share lazily built indexes, which are not meant to be read from
// two threads at once.

#include <cstddef>
#include <functional>

namespace catplan {

/// One worker per core (at least one).
std::size_t default_jobs();

/// Runs body(worker, index) for every index in [0, n) on min(jobs, n) threads (the calling thread
/// when that is one), worker in [0, min(jobs, n)); after an exception no worker takes a new index,
/// and the first exception is rethrown once all have stopped.
void parallel_for(std::size_t n, std::size_t jobs,
                  const std::function<void(std::size_t worker, std::size_t index)>& body);

} // namespace catplan
