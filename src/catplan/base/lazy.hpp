#pragma once
// A value derived from its owner, computed at its first use and kept: what a rule deletes and
// creates, and what matching and application need to know about it (rewrite/rule.hpp). Several
// threads may ask at once: each may compute it, and the first to finish publishes it (the others'
// copies are dropped), so readers never wait and never see a half-built value. A copy or a move of
// the owner starts empty and computes its own, since the value may refer to its owner.

#include <atomic>
#include <utility>

namespace catplan {

template <class T>
class Lazy {
public:
    Lazy() = default;

    Lazy(const Lazy&) noexcept {}

    Lazy& operator=(const Lazy& other) noexcept {
        if (this != &other) {
            reset();
        }
        return *this;
    }

    ~Lazy() { reset(); }

    /// The value, computed by `make()` (which returns a T) if no thread has published one yet.
    template <class Make>
    const T& get(Make&& make) const {
        if (const T* p = value_.load(std::memory_order_acquire)) {
            return *p;
        }
        const T* made = new T(std::forward<Make>(make)());
        const T* expected = nullptr;
        // Set where T is complete; every thread stores the same function.
        destroy_.store([](const T* p) { delete p; }, std::memory_order_relaxed);
        if (value_.compare_exchange_strong(expected, made, std::memory_order_acq_rel)) {
            return *made;
        }
        delete made;
        return *expected;
    }

    /// The value if one was published, else null.
    const T* peek() const { return value_.load(std::memory_order_acquire); }

private:
    void reset() noexcept {
        if (const T* p = value_.exchange(nullptr, std::memory_order_acq_rel)) {
            destroy_.load(std::memory_order_relaxed)(p);
        }
    }

    mutable std::atomic<const T*> value_{nullptr};
    // How to delete the value: T may be incomplete where the owner is destroyed.
    mutable std::atomic<void (*)(const T*)> destroy_{nullptr};
};

} // namespace catplan
