#include "common.hpp"

namespace catplan::python {

namespace {

constexpr auto kPollInterval = std::chrono::milliseconds(50);

} // namespace

Interruptible::Interruptible() : next_(std::chrono::steady_clock::now() + kPollInterval) {
    release_.emplace();
}

Interruptible::~Interruptible() {
    release_.reset();
}

bool Interruptible::poll() {
    if (error_) {
        return true;
    }
    // Reading the clock costs tens of nanoseconds: look at it only every 256 calls.
    if ((++calls_ & 0xffU) != 0) {
        return false;
    }
    return check();
}

bool Interruptible::check() {
    if (error_) {
        return true;
    }
    auto now = std::chrono::steady_clock::now();
    if (now < next_) {
        return false;
    }
    next_ = now + kPollInterval;
    return with_gil([] {
        if (PyErr_CheckSignals() != 0) {
            throw py::error_already_set();
        }
    });
}

bool Interruptible::with_gil(const std::function<void()>& fn) {
    if (error_) {
        return true;
    }
    py::gil_scoped_acquire gil;
    try {
        fn();
    } catch (py::error_already_set& e) {
        error_.emplace(std::move(e));
    }
    return error_.has_value();
}

void Interruptible::finish() {
    release_.reset();
    if (error_) {
        auto e = std::move(*error_);
        error_.reset();
        throw e;
    }
}

} // namespace catplan::python
