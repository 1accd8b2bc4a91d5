#pragma once
// Result<T>: a value or the reason there is none. For an algorithm's expected "no" (no match,
// gluing violated, an infinite hom set), never for bad user input (that is a Diagnostic) or a bug
// (that is CATPLAN_ASSERT). A stand-in for std::expected<T, std::string>, absent from g++ 12 in
// C++20.

#include "catplan/base/assert.hpp"

#include <string>
#include <utility>
#include <variant>

namespace catplan {

/// The reason an algorithm gives for producing no value.
struct Failure {
    std::string reason;
};

/// Makes a Failure from a reason (use: `return fail("dangling: ...")`).
inline Failure fail(std::string reason) {
    return Failure{std::move(reason)};
}

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : data_(std::move(value)) {}

    Result(Failure failure) : data_(std::move(failure)) {}

    bool has_value() const { return data_.index() == 0; }

    explicit operator bool() const { return has_value(); }

    T& value() & {
        CATPLAN_ASSERT(has_value(), "Result::value() on a failure");
        return std::get<0>(data_);
    }

    const T& value() const& {
        CATPLAN_ASSERT(has_value(), "Result::value() on a failure");
        return std::get<0>(data_);
    }

    T&& value() && {
        CATPLAN_ASSERT(has_value(), "Result::value() on a failure");
        return std::get<0>(std::move(data_));
    }

    T& operator*() & { return value(); }

    const T& operator*() const& { return value(); }

    T* operator->() { return &value(); }

    const T* operator->() const { return &value(); }

    /// The reason for the failure; only valid when !has_value().
    const std::string& error() const {
        CATPLAN_ASSERT(!has_value(), "Result::error() on a value");
        return std::get<1>(data_).reason;
    }

private:
    std::variant<T, Failure> data_;
};

} // namespace catplan
