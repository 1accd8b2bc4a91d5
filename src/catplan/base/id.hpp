#pragma once
// Dense 32-bit ids behind strong types, so an object id cannot be passed where a hom id is meant.
// An id does not record which schema it belongs to: that is the caller's contract (as with
// Fast Downward's OperatorID).

#include <compare>
#include <cstdint>
#include <functional>

namespace catplan {

template <class Tag>
class Id {
public:
    constexpr Id() = default;

    constexpr explicit Id(std::uint32_t index) : index_(index) {}

    constexpr std::uint32_t index() const { return index_; }

    friend constexpr auto operator<=>(Id, Id) = default;

private:
    std::uint32_t index_ = UINT32_MAX;
};

using ObId = Id<struct ObTag>;
using HomId = Id<struct HomTag>;
using AttrTypeId = Id<struct AttrTypeTag>;
using AttrId = Id<struct AttrTag>;

/// A part of an object in a state: a dense index 0..n-1 (printed 1-based, as Catlab does).
using Part = std::uint32_t;
/// The value of a hom column that has not been set (Catlab's 0).
inline constexpr Part kNoPart = UINT32_MAX;

} // namespace catplan

template <class Tag>
struct std::hash<catplan::Id<Tag>> {
    std::size_t operator()(catplan::Id<Tag> id) const noexcept { return id.index(); }
};
