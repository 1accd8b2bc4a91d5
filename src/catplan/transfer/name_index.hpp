#pragma once
// A map name -> part for one object of a NamedState: open addressing with linear probing in one
// flat array, so that copying a state (a repair replays its steps on a copy of the target state,
// once per repaired step) copies one array rather than a node per name, and a look-up reads
// adjacent slots. Keys are views of interned part names (symbol.hpp), valid for the process.

#include "catplan/base/assert.hpp"
#include "catplan/base/id.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

namespace catplan::transfer {

class NameIndex {
public:
    /// The part of this name, or nullptr when the index has no such name.
    const Part* find(std::string_view name) const {
        std::size_t i = slot_of(name);
        return i == kAbsent ? nullptr : &slots_[i].part;
    }

    /// The entry of name, added with part p if absent; whether it was added.
    std::pair<Part*, bool> emplace(std::string_view name, Part p) {
        CATPLAN_ASSERT(!name.empty(), "an unnamed part is not indexed");
        if (2 * (size_ + 1) > slots_.size()) {
            grow();
        }
        auto h = hash(name);
        std::size_t i = h & mask();
        for (; slots_[i].data != nullptr; i = (i + 1) & mask()) {
            if (slots_[i].hash == h && key(slots_[i]) == name) {
                return {&slots_[i].part, false};
            }
        }
        slots_[i] = {name.data(), static_cast<std::uint32_t>(name.size()), h, p};
        ++size_;
        return {&slots_[i].part, true};
    }

    /// Removes name's entry, if any.
    void erase(std::string_view name) {
        std::size_t i = slot_of(name);
        if (i == kAbsent) {
            return;
        }
        // Backward shift: move each later entry of the run into the hole when its home slot
        // does not lie after the hole (cyclically), so that no probe stops early.
        for (std::size_t j = (i + 1) & mask(); slots_[j].data != nullptr; j = (j + 1) & mask()) {
            std::size_t home = slots_[j].hash & mask();
            if (((j - home) & mask()) >= ((j - i) & mask())) {
                slots_[i] = slots_[j];
                i = j;
            }
        }
        slots_[i] = Slot{};
        --size_;
    }

    /// Room for n names without growing.
    void reserve(std::size_t n) {
        while (2 * n > slots_.size()) {
            grow();
        }
    }

private:
    struct Slot {
        const char* data = nullptr; // nullptr: an empty slot
        std::uint32_t size = 0;
        std::uint32_t hash = 0;
        Part part = kNoPart;
    };

    static constexpr std::size_t kAbsent = SIZE_MAX;

    static std::uint32_t hash(std::string_view name) {
        return static_cast<std::uint32_t>(std::hash<std::string_view>{}(name));
    }

    static std::string_view key(const Slot& s) { return {s.data, s.size}; }

    std::size_t mask() const { return slots_.size() - 1; }

    std::size_t slot_of(std::string_view name) const {
        if (size_ == 0 || name.empty()) {
            return kAbsent;
        }
        auto h = hash(name);
        for (std::size_t i = h & mask(); slots_[i].data != nullptr; i = (i + 1) & mask()) {
            if (slots_[i].hash == h && key(slots_[i]) == name) {
                return i;
            }
        }
        return kAbsent;
    }

    void grow() {
        std::vector<Slot> old(slots_.empty() ? 16 : 2 * slots_.size());
        old.swap(slots_);
        size_ = 0;
        for (const Slot& s : old) {
            if (s.data != nullptr) {
                emplace(key(s), s.part);
            }
        }
    }

    std::vector<Slot> slots_; // a power of two in size, at most half full
    std::size_t size_ = 0;
};

} // namespace catplan::transfer
