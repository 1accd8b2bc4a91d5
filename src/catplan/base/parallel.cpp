#include "catplan/base/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace catplan {

std::size_t default_jobs() {
    return std::max(1U, std::thread::hardware_concurrency());
}

void parallel_for(std::size_t n, std::size_t jobs,
                  const std::function<void(std::size_t worker, std::size_t index)>& body) {
    std::size_t workers = std::min(std::max<std::size_t>(jobs, 1), n);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first;
    std::mutex first_mutex;
    auto work = [&](std::size_t w) {
        for (std::size_t i = next++; i < n && !failed; i = next++) {
            try {
                body(w, i);
            } catch (...) {
                // An exception must not leave a thread (that would terminate the process).
                std::lock_guard<std::mutex> lock(first_mutex);
                if (!first) {
                    first = std::current_exception();
                }
                failed = true;
            }
        }
    };
    if (workers <= 1) {
        work(0);
    } else {
        std::vector<std::thread> threads;
        threads.reserve(workers);
        for (std::size_t w = 0; w < workers; ++w) {
            threads.emplace_back(work, w);
        }
        for (auto& t : threads) {
            t.join();
        }
    }
    if (first) {
        std::rethrow_exception(first);
    }
}

} // namespace catplan
