#include "catplan/base/keep.hpp"

#include <atomic>
#include <mutex>
#include <vector>

namespace catplan {
namespace {

std::atomic<bool> ends{false};

// Reachable through a static pointer to the end, so leak checkers do not count it as lost.
struct Kept {
    std::mutex mutex;
    std::vector<std::shared_ptr<void>> objects;
};

Kept& kept() {
    static auto* k = new Kept;
    return *k;
}

} // namespace

void set_process_ends_after_command(bool e) {
    ends.store(e, std::memory_order_relaxed);
}

bool process_ends_after_command() {
    return ends.load(std::memory_order_relaxed);
}

namespace detail {

void keep_forever(std::shared_ptr<void> x) {
    auto& k = kept();
    std::lock_guard lock(k.mutex);
    k.objects.push_back(std::move(x));
}

} // namespace detail
} // namespace catplan
